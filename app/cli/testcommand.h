#pragma once

#include "arguments.h"
#include "commands.h"

namespace cli {

// ggstudio-cli test MODEL SCENARIO|FOLDER... [--junit FILE]
// ggstudio-cli test --models MODEL|FOLDER [--models ...] SCENARIO|FOLDER... [--junit FILE]
// Runs each scenario against each model (in closed loop when the model has a
// machine), prints one line per scenario and a total per model, and writes
// JUnit XML (junitreport.h). Exit 0 when every scenario passes, 1 when one
// fails, 2 when a model, a scenario or the report cannot be read or written
// (a scenario with syntax or name errors included), 64 for a usage error.
int commandTest(const Arguments& args, Streams streams);

} // namespace cli
