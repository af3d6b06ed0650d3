#pragma once

// A model's virtual machine as Promela, for the SPIN cross-check of the
// closed loop (docs/verification.md, "Closed loop (--machine)"): written from
// the machine's semantics (docs/simulation.md, "The virtual machine"), not
// from the explorer's code. Counted in scans (exactTime) the statements do
// what core::machine::MachineState does; otherwise they are the abstraction
// of core/verification/abstractmachine.h, a travel under way ending or not
// by a nondeterministic `if`.

#include "core/machine/machine.h"

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace core {

struct PromelaMachine {
    std::vector<std::string> declarations; // global variables with their start values
    // By upper-case variable name: the expression an input a sensor drives reads.
    std::map<std::string, std::string> sensors;
    std::vector<std::string> cycle; // statements: one machine cycle, after the scan
};

// `wired(name, direction)`: whether the variable may take the role (as
// core::machine::MachineLoop wires: a BOOL output to an actuator role, a BOOL
// input to a sensor or operator role); `outputValue(name)`: the Promela
// expression of an actuator's output as the scan left it.
// `jammed(k)`: with single faults, the Promela condition under which
// component k (a cylinder or conveyor) is jammed and does not move; empty
// (or no function): it always moves.
PromelaMachine buildPromelaMachine(const machine::Machine& machine, int cycleTimeMs, bool exactTime,
                                   const std::function<bool(std::string_view, machine::SignalDirection)>& wired,
                                   const std::function<std::string(std::string_view)>& outputValue,
                                   const std::function<std::string(std::size_t)>& jammed = {});

} // namespace core
