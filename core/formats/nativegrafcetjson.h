#pragma once

// One nested GRAFCET as the native model file writes and reads it
// ({"steps": [...], "transitions": [...]}, nativeformat.h), for the other
// JSON formats that carry steps and transitions (the clipboard's fragments).

#include "core/model/grafcet.h"

#include <nlohmann/json.hpp>

#include <string>

namespace core {

nlohmann::ordered_json nativeGrafcetJson(const Grafcet& grafcet);

// As the newest native format reads it (unknown keys are errors); throws
// JsonReadError with paths under `path`.
Grafcet readNativeGrafcet(const nlohmann::ordered_json& value, const std::string& path);

} // namespace core
