#include "core/verification/closedloopreplay.h"

#include "core/machine/machineloop.h"
#include "core/simulation/simulator.h"

namespace core {

ScenarioRunResult replayClosedLoop(const Scenario& scenario, machine::MachineLoop& loop, std::int64_t scans)
{
    Simulator& simulator = loop.simulator();
    for (const std::string& step : simulator.nestedSteps()) {
        simulator.setCompleteMode(step, CompleteMode::Automatic);
        simulator.setComplete(step, false);
    }
    loop.reset();
    // In closed loop: the runner applies the fault lines and runs the
    // machine's cycles, but none after the last scan.
    ScenarioRunner runner(scenario, loop);
    ScenarioRunResult result;
    for (std::int64_t i = 0; i < scans && !simulator.fault(); ++i) {
        if (i + 1 == scans)
            runner.skipNextMachineCycle();
        result.records.push_back(runner.step());
    }
    result.failures = runner.failures();
    result.fault = simulator.fault();
    return result;
}

} // namespace core
