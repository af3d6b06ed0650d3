#pragma once

// `simulate --fault "120:Clamped stuck FALSE"` (docs/cli.md): a scenario's
// fault line given on the command line, `SCAN:TARGET KIND` for
// `at SCAN: fault TARGET KIND`, parsed by the scenario parser itself so
// that both spell faults alike.

#include "core/simulation/scenario.h"

#include <string>

namespace cli {

// The fault action the option gives; false and `error` set ("expected TRUE
// or FALSE, found 'maybe'") when it is malformed.
bool parseFaultOption(const std::string& option, core::ScenarioAction& action, std::string& error);

} // namespace cli
