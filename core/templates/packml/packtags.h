#pragma once

// The PackTags interface every generated PackML program declares (spec
// packml.md §5.2): the command and mode requests an HMI or a line controller
// writes, and the state and mode it reads back. Conditions may read them;
// no action writes them. The checks, the generator and the simulator take
// the list from here, so they declare, type and initialise them alike.

#include "core/model/model.h"

#include <span>
#include <string_view>
#include <vector>

namespace core::packml {

struct PackTag {
    std::string_view name; // PackTags Command.* / Status.* leaf name
    IecType type;
    bool input; // written from outside the program (true), or by it (false)
    std::string_view meaning;
};

// CntrlCmd, CmdChangeRequest, UnitMode, UnitModeChangeRequest, StateCurrent,
// UnitModeCurrent, in that order.
std::span<const PackTag> packTags();

// The six as variables of the model's configuration: inputs and outputs with
// their initial values (UnitMode and UnitModeCurrent the initial mode,
// StateCurrent the initial state's number, the others 0 / FALSE).
std::vector<Variable> packTagVariables(const Configuration& configuration);

// Is `name` one of the six (ignoring case, as IEC names compare)?
bool isPackTagName(std::string_view name);

} // namespace core::packml
