#pragma once

// The checks of a model's virtual machine (docs/diagnostics.md, GG601 to
// GG608), each on the component (Diagnostic::Target::MachineComponent, the
// role or parameter as field) with its values as arguments:
//   GG601 error   a role names no variable of the model
//   GG602 error   a variable of the wrong kind: an actuator role needs an
//                 output, a sensor or operator role an input
//   GG603 error   a variable that is not BOOL
//   GG604 error   an input wired to two roles (sensors or operator inputs):
//                 two writers of one input
//   GG605 warning an actuator output that no action of the program drives
//   GG606 error   a travel time that is not positive, a negative delay or
//                 part count, or one above the limits (componentkind.h)
//   GG607 error   a required role left unwired
//   GG608 error   a part source naming no conveyor of the machine

#include "core/checks/diagnostic.h"

#include <vector>

namespace core {
class Model;
}

namespace core::machine {

std::vector<Diagnostic> checkMachine(const Model& model);

} // namespace core::machine
