#pragma once

// The steps Copy puts on the system clipboard, as JSON (docs/file-formats.md):
//   {"format": "ggstudio-grafcet-fragment", "version": "1.0",
//    "grafcet": {"steps": [...], "transitions": [...]}}
// the steps and transitions written as the native model file writes a nested
// GRAFCET. Any program can put anything there, so the text is read as
// strictly as a model file and its size bounded before it is parsed.

#include "core/formats/jsonreader.h"
#include "core/model/grafcetediting.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <variant>

namespace core {

inline constexpr std::string_view kGrafcetFragmentFormatName = "ggstudio-grafcet-fragment";
inline constexpr std::string_view kGrafcetFragmentVersion = "1.0";
// Far above what a user copies (a whole production GRAFCET is a few kB).
inline constexpr std::size_t kMaxGrafcetFragmentBytes = 1024 * 1024;
inline constexpr std::size_t kMaxGrafcetFragmentSteps = 1000;
inline constexpr std::size_t kMaxGrafcetFragmentTransitions = 1000;

// Deterministic, 2-space indent, trailing newline.
std::string saveGrafcetFragmentJson(const GrafcetFragment& fragment);

// The fragment (at least one step, its transitions between its own steps),
// or what is wrong and where. Pasted steps are never initial, whatever the text says.
std::variant<GrafcetFragment, JsonReadError> loadGrafcetFragmentJson(std::string_view text);

} // namespace core
