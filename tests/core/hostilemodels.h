#pragma once

// Models whose user text is hostile: variable names, defaults, comments,
// conditions, tokens and the model name drawn from fragments that would
// break generated code written verbatim (`;`, `(*`, `*)`, END_VAR, quotes,
// line breaks, terminal escapes, bidi overrides, non-ASCII, invalid UTF-8,
// keywords, the generator's own names), mixed with ordinary ones.

#include "core/model/model.h"

#include <cstdint>
#include <string_view>

namespace samples {

// Every hostile fragment that is code ("Injected := 13;", "END_VAR Injected")
// carries this word: it must never appear in generated code outside a comment.
inline constexpr std::string_view kInjectedMarker = "Injected";

// The same seed gives the same model. Conditions name the variables (valid
// and hostile ones alike) or are garbage themselves; the checks find errors.
core::Model hostileModel(std::uint32_t seed);

} // namespace samples
