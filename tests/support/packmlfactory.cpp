#include "packmlfactory.h"

#include "core/templates/packml/packmlconfiguration.h"
#include "core/templates/packml/packmlmodel.h"

#include <stdexcept>
#include <string>

namespace factory {

namespace {

void require(const core::Status& status)
{
    if (!status)
        throw std::logic_error("packmlStressModel: " + status.message);
}

void declare(core::Model& model, const std::string& name, core::IecType type, core::VariableKind kind)
{
    core::Variable variable;
    variable.name = name;
    variable.type = type;
    variable.kind = kind;
    require(model.addVariable(variable));
}

// Step n drives Out<n>; transition n (In<n>) leads to n + 1; the last step
// sets Complete, or loops back to step 1 in Execute (which waits, spec §4).
core::Grafcet stateGrafcet(int steps, bool loops)
{
    core::Grafcet grafcet;
    for (int n = 1; n <= steps; ++n) {
        core::GrafcetStep step;
        step.number = n;
        step.initial = n == 1;
        step.actions.push_back({core::ActionTiming::Continuous, "N Out" + std::to_string(n)});
        if (n == steps && !loops)
            step.actions.push_back({core::ActionTiming::OnActivation, "S Complete"});
        require(grafcet.addStep(step));
    }
    for (int n = 1; n < steps || (loops && n == steps); ++n) {
        core::GrafcetTransition transition;
        transition.number = n;
        transition.upstream = {n};
        transition.downstream = {n < steps ? n + 1 : 1};
        transition.receptivity = "In" + std::to_string(n);
        require(grafcet.addTransition(transition));
    }
    return grafcet;
}

} // namespace

core::Model packmlStressModel(int steps)
{
    using core::packml::State;
    core::Model model = core::packml::newModel();
    require(model.setName("StressLine"));
    declare(model, "ModeKey", core::IecType::Int, core::VariableKind::Input);
    for (int n = 1; n <= steps; ++n) {
        declare(model, "In" + std::to_string(n), core::IecType::Bool, core::VariableKind::Input);
        declare(model, "Out" + std::to_string(n), core::IecType::Bool, core::VariableKind::Output);
    }
    for (int mode = core::packml::kFirstUserMode; mode <= core::packml::kMaxModeNumber; ++mode)
        require(model.addMode(mode, "User" + std::to_string(mode)));
    for (int mode = 1; mode <= core::packml::kMaxModeNumber; ++mode)
        require(model.setModeRequest(mode, "ModeKey = " + std::to_string(mode)));
    for (const core::packml::StateInfo& info : core::packml::states()) {
        if (!core::packml::holdsGrafcet(info.state))
            continue;
        require(model.setGrafcet(core::packml::grafcetKey(1, info.state),
                                 stateGrafcet(steps, info.state == State::Execute)));
        for (int mode = 2; mode <= core::packml::kMaxModeNumber; ++mode)
            require(model.setGrafcetChoice(mode, info.state, core::packml::GrafcetChoice::sameAs(1)));
    }
    return model;
}

} // namespace factory
