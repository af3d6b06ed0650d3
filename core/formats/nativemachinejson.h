#pragma once

// The native file's "machine" key (docs/file-formats.md): the model's
// virtual machine, format 2.0. Readers throw JsonReadError with the JSON path.

#include "core/formats/nativemodelparts.h"
#include "core/machine/machine.h"

#include <nlohmann/json.hpp>

#include <string>

namespace core {

// {"components": [{"name": ..., "kind": ..., <roles>, <parameters>, ...}]}:
// wired roles only, every parameter (a part source's "parts" only when
// limited), "contact" for operator inputs, "conveyor" for part sources.
nlohmann::ordered_json nativeMachineJson(const machine::Machine& machine);

// Strict: unknown keys (unless the file's minor version is newer), a
// missing or repeated name, an unknown kind or contact, a value of the wrong
// JSON type or out of range, each at its path. Wiring is not checked against
// the variables here: the checks report it (GG6xx), as for conditions.
machine::Machine readNativeMachine(const nlohmann::ordered_json& value, const std::string& path,
                                   NativeVersion version);

} // namespace core
