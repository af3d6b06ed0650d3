#pragma once

// The parts of a native model file that every template writes and reads
// alike (nativeformat.h): the common settings, the variables, the
// properties and the nested GRAFCETs. The GEMMA file (nativeformat.cpp) and
// the PackML file (core/templates/packml/packmlformat.cpp) share them.
// Readers throw JsonReadError with the JSON path; `major`.`minor` is the
// file's version, which decides which keys are known (newer minors may add
// keys, which are skipped).

#include "core/model/model.h"

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <string>
#include <string_view>

namespace core {

struct NativeVersion {
    int major = 0;
    int minor = 0;
};

// "3.0" for major 3.
std::string nativeVersionText(int major);

// How the file names an action's timing: "continuous", "activation", "deactivation".
std::string_view nativeTimingName(ActionTiming timing);

// Fails at the first key of `object` that is not in `known` (unless the
// file's minor version is newer than this build's), naming it and the known keys.
void checkNativeKeys(const nlohmann::ordered_json& object, const std::string& path, const char* what,
                     std::initializer_list<std::string_view> known, NativeVersion version);

// "cycleTimeMs", "dialect" and "evolution" of a settings object.
void readNativeCommonSettings(Model& model, const nlohmann::ordered_json& settings, const std::string& path);
void readNativeVariables(Model& model, const nlohmann::ordered_json& root, NativeVersion version);
void readNativeProperties(Model& model, const nlohmann::ordered_json& root, NativeVersion version);
Grafcet readNativeGrafcet(const nlohmann::ordered_json& value, const std::string& path, NativeVersion version);

// Variables with their kinds (format 2.0 and later).
nlohmann::ordered_json nativeVariablesJson(const Model& model);
nlohmann::ordered_json nativePropertiesJson(const Model& model);

} // namespace core
