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
    // A runner of the simulator alone: the machine's cycles are run here.
    ScenarioRunner runner(scenario, simulator);
    ScenarioRunResult result;
    for (std::int64_t i = 0; i < scans && !simulator.fault(); ++i) {
        result.records.push_back(runner.step());
        if (i + 1 < scans)
            loop.afterScan();
    }
    result.failures = runner.failures();
    result.fault = simulator.fault();
    return result;
}

} // namespace core
