#pragma once

// `ggstudio-cli simulate` on a PackML model: runs core::packml's simulator
// (spec packml.md §6.5), with an optional scenario, and prints per scan the
// state, the mode, what fired, Execute's resume and every dropped event with
// its reason.

#include "commands.h"

#include <cstdint>
#include <string>
#include <vector>

namespace core {
class Model;
}

namespace cli {

// files: the model, then the optional scenario. scans: 0 for the scenario's
// last scan (or the default). trace: also the called instance's steps and
// Complete, and the continuous outputs.
int simulatePackml(const core::Model& model, const std::vector<std::string>& files, std::int64_t scans, bool trace,
                   Streams streams);

} // namespace cli
