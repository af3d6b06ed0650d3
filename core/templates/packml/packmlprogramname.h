#pragma once

// The name of the PROGRAM a PackML model generates (spec packml.md §6.1):
// the checks (PM003, PM018) and the generator must choose it alike.

#include "core/model/model.h"

#include <string>
#include <vector>

namespace core::packml {

// The names the modes go by ("Production", "Manual", a user mode's), in
// mode order.
std::vector<std::string> modeNames(const Configuration& configuration);

// The model's name when it is an IEC identifier that no name of the
// generated code (§5.3, without the program's own) and no user variable
// takes, else kDefaultProgramName ("PackML").
std::string programName(const Model& model);

} // namespace core::packml
