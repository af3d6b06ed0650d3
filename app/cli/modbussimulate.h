#pragma once

#include "arguments.h"
#include "commands.h"

#include <cstdint>
#include <string>

namespace core {
class Model;
}

namespace cli {

// simulate MODEL --modbus-server HOST:PORT | --modbus-client HOST:PORT
// [--modbus-map FILE] [--unit-id N] [--scans N], and --print-modbus-map
// (docs/modbus.md): the GEMMA simulator linked to a digital twin in real time,
// until SIGINT or SIGTERM, or `scans` scans when not 0.
int simulateModbus(const Arguments& args, const std::string& path, const core::Model& model, std::int64_t scans,
                   Streams streams);

} // namespace cli
