#include "core/machine/closedloopscenario.h"

namespace core::machine {

namespace {

ScenarioError errorAt(const Scenario& scenario, const ScenarioAction& action, ScenarioError::Kind kind,
                      std::string subject, std::string detail)
{
    ScenarioError error;
    error.fileName = scenario.fileName;
    error.line = action.line;
    error.column = action.column;
    error.kind = kind;
    error.subject = std::move(subject);
    error.detail = std::move(detail);
    error.message = toText(error);
    return error;
}

} // namespace

ScenarioError::Kind scenarioErrorKind(FaultRefusal::Kind kind)
{
    using Kind = ScenarioError::Kind;
    switch (kind) {
    case FaultRefusal::Kind::UnknownVariable: return Kind::UnknownVariable;
    case FaultRefusal::Kind::OperatorInput: return Kind::FaultOnOperatorInput;
    case FaultRefusal::Kind::NotMachineSensor: return Kind::FaultNotMachineSensor;
    case FaultRefusal::Kind::UnknownComponent: return Kind::FaultUnknownComponent;
    case FaultRefusal::Kind::CannotJam: return Kind::FaultCannotJam;
    case FaultRefusal::Kind::UnknownTarget: return Kind::FaultUnknownTarget;
    }
    return Kind::FaultUnknownTarget;
}

std::vector<ScenarioError> validateClosedLoopScenario(const Scenario& scenario, const MachineLoop& loop)
{
    std::vector<ScenarioError> errors;
    const Simulator& simulator = loop.simulator();
    for (const ScenarioAction& action : scenario.actions) {
        if (const std::optional<Fault> fault = scenarioFault(action)) {
            if (const std::optional<FaultRefusal> refusal = loop.checkFault(*fault))
                errors.push_back(errorAt(scenario, action, scenarioErrorKind(refusal->kind), refusal->subject, refusal->detail));
            continue;
        }
        if (action.kind != ScenarioAction::Kind::SetVariable)
            continue;
        const Component* owner = loop.sensorOwner(action.name);
        if (!owner)
            continue;
        const std::string& declared =
            simulator.variableNames()[static_cast<std::size_t>(simulator.variableIndex(action.name))];
        errors.push_back(errorAt(scenario, action, ScenarioError::Kind::MachineSensor, declared, owner->name));
    }
    return errors;
}

} // namespace core::machine
