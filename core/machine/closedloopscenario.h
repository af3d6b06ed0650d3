#pragma once

// A scenario played in closed loop (docs/simulation.md, "The virtual
// machine"): its `set` lines are the operator's, so setting an input the
// machine writes at every cycle is an error, at the line and column of the
// name (ScenarioError::Kind::MachineSensor); its `fault` lines must name a
// sensor the machine writes or a component that moves (docs/simulation.md,
// "Faults"), else an error at the name (ScenarioError::Kind::Fault..., or
// UnknownVariable). Run validateScenario(scenario, simulator,
// FaultLines::CheckedByMachine) first.

#include "core/machine/machineloop.h"
#include "core/simulation/scenario.h"

#include <vector>

namespace core::machine {

// The scenario error a fault refusal is on a `fault` line (the editor words
// a refused fault as the scenario's message would).
ScenarioError::Kind scenarioErrorKind(FaultRefusal::Kind kind);

std::vector<ScenarioError> validateClosedLoopScenario(const Scenario& scenario, const MachineLoop& loop);

} // namespace core::machine
