#pragma once

// Replays a closed-loop counterexample (docs/verification.md, "Closed loop
// (--machine)"): the scenario is run as runScenario runs it with a
// machine::MachineLoop, except that no machine cycle follows the last scan,
// so that the simulator still holds the sensors that scan read and a
// property evaluated on it sees what the verifier's last scan saw. Its
// `fault` lines (a counterexample of --faults single) are applied as
// runScenario applies them.

#include "core/simulation/scenario.h"

#include <cstdint>

namespace core {

namespace machine {
class MachineLoop;
}

// Resets the loop, every Complete automatic until the scenario sets it, and
// runs `scans` scans. The scenario must pass validateScenario and
// validateClosedLoopScenario.
ScenarioRunResult replayClosedLoop(const Scenario& scenario, machine::MachineLoop& loop, std::int64_t scans);

} // namespace core
