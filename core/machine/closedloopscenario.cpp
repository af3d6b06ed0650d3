#include "core/machine/closedloopscenario.h"

namespace core::machine {

std::vector<ScenarioError> validateClosedLoopScenario(const Scenario& scenario, const MachineLoop& loop)
{
    std::vector<ScenarioError> errors;
    const Simulator& simulator = loop.simulator();
    for (const ScenarioAction& action : scenario.actions) {
        if (action.kind != ScenarioAction::Kind::SetVariable)
            continue;
        const Component* owner = loop.sensorOwner(action.name);
        if (!owner)
            continue;
        ScenarioError error;
        error.fileName = scenario.fileName;
        error.line = action.line;
        error.column = action.column;
        error.kind = ScenarioError::Kind::MachineSensor;
        error.subject = simulator.variableNames()[static_cast<std::size_t>(simulator.variableIndex(action.name))];
        error.detail = owner->name;
        error.message = toText(error);
        errors.push_back(std::move(error));
    }
    return errors;
}

} // namespace core::machine
