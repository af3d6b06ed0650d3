#pragma once

// A PackML model as a native model file, format 3.0 with "template":
// "packml" (spec packml.md §9). nativeformat.h's saveNativeJson and
// loadNativeJson dispatch here; GEMMA models stay 1.0/2.0.

#include "core/formats/nativemodelparts.h"
#include "core/model/model.h"

#include <nlohmann/json.hpp>

#include <memory>
#include <string>
#include <string_view>

namespace core::packml {

inline constexpr int kFormatMajor = 3;
inline constexpr int kFormatMinor = 0;
inline constexpr std::string_view kTemplateName = "packml";

// Deterministic, keys in the order of spec §9; the model must be a PackML model.
std::string saveJson(const Model& model);

// The model of a file whose "format", "version" (3.x) and "template" the
// caller has read; throws JsonReadError naming the JSON path of what is wrong.
std::unique_ptr<Model> buildModel(const nlohmann::ordered_json& root, NativeVersion version);

} // namespace core::packml
