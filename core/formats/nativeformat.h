#pragma once

// GG Studio's own model file (spec §8, README "File formats"): JSON with a
// format name and a major.minor version, storing only what the user can change.

#include "core/formats/loaderror.h"
#include "core/model/model.h"

#include <memory>
#include <cstddef>
#include <string>
#include <string_view>
#include <variant>

namespace core {

inline constexpr std::string_view kNativeFormatName = "ggstudio-model";
// A model that needs none of format 2.0's keys (no nested GRAFCET, only input
// variables, the default evolution rule) is written as 1.0, byte for byte as
// GG Studio wrote it before nested GRAFCETs, so older versions still read it.
// Anything else is 2.0, which those versions refuse by its major number
// instead of silently dropping the nested behaviour.
inline constexpr int kNativeFormatMajor = 2;
inline constexpr int kNativeFormatMinor = 0;
inline constexpr int kNativeFormatOldestMajor = 1;
// Limits of one nested GRAFCET in a file.
inline constexpr int kMaxGrafcetNumber = 999'999;
inline constexpr std::size_t kMaxGrafcetElements = 10'000;

// Deterministic: the same model gives the same bytes (2-space indent, fixed key order, trailing newline).
std::string saveNativeJson(const Model& model);

// Either a whole model or an error naming the place (JSON path or line/column).
std::variant<std::unique_ptr<Model>, LoadError> loadNativeJson(std::string_view text, const std::string& displayName);

// True when the text looks like a native file (for format detection).
bool looksLikeNativeJson(std::string_view text);

} // namespace core
