#pragma once

// GG Studio's own model file (spec §8, README "File formats"): JSON with a
// format name and a major.minor version, storing only what the user can change.

#include "core/formats/loaderror.h"
#include "core/model/model.h"

#include <memory>
#include <string>
#include <string_view>
#include <variant>

namespace core {

inline constexpr std::string_view kNativeFormatName = "ggstudio-model";
inline constexpr int kNativeFormatMajor = 1;
inline constexpr int kNativeFormatMinor = 0;

// Deterministic: the same model gives the same bytes (2-space indent, fixed key order, trailing newline).
std::string saveNativeJson(const Model& model);

// Either a whole model or an error naming the place (JSON path or line/column).
std::variant<std::unique_ptr<Model>, LoadError> loadNativeJson(std::string_view text, const std::string& displayName);

// True when the text looks like a native file (for format detection).
bool looksLikeNativeJson(std::string_view text);

} // namespace core
