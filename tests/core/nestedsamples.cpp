// The small models of the verification of both layers (samplemodels.h):
// the machine, the sound GRAFCET and each defect seeded on its own.

#include "samplemodels.h"

#include "core/machine/machine.h"

#include <stdexcept>
#include <utility>

namespace samples {

using core::ActionTiming;

core::Model nestedMachine()
{
    core::Model model;
    for (const char* name : {"Start", "Done", "EStop", "A", "B", "C"})
        requireBuilt(model.addVariable(variable(name, core::IecType::Bool, core::VariableKind::Input)));
    requireBuilt(model.addVariable(variable("Lamp", core::IecType::Bool, core::VariableKind::Output)));
    requireBuilt(model.addVariable(variable("Flag", core::IecType::Bool, core::VariableKind::Internal)));
    requireBuilt(model.setInitialStep("A1"));
    requireBuilt(model.setStepType("F1", core::StepType::Macro));
    requireBuilt(model.setCondition("A1->F1", "Start"));
    requireBuilt(model.setCondition("F1->A2", "Done"));
    requireBuilt(model.setCondition("A2->A1", "TRUE"));
    requireBuilt(model.setCondition("F->D1", "EStop"));
    requireBuilt(model.setCondition("D1->A5", "NOT EStop"));
    return model;
}

void addMachineStep(core::Model& model, int number, bool initial, std::vector<core::GrafcetAction> actions)
{
    requireBuilt(model.addGrafcetStep("F1", {number, initial, "", std::move(actions)}));
}

void addMachineTransition(core::Model& model, int number, std::vector<int> up, std::vector<int> down,
                          std::string receptivity)
{
    requireBuilt(model.addGrafcetTransition("F1", {number, std::move(up), std::move(down), std::move(receptivity)}));
}

core::Model soundMachine()
{
    core::Model model = nestedMachine();
    addMachineStep(model, 1, true);
    addMachineStep(model, 2, false, {{ActionTiming::Continuous, "N Lamp"}, {ActionTiming::OnActivation, "S Complete"}});
    addMachineTransition(model, 1, {1}, {2}, "A");
    addMachineTransition(model, 2, {2}, {1}, "NOT A");
    return model;
}

core::Model cylinderCell()
{
    core::Model model = nestedMachine();
    addMachineStep(model, 1, true);
    addMachineStep(model, 2, false, {{ActionTiming::Continuous, "N Lamp"}});
    addMachineTransition(model, 1, {1}, {2}, "A");
    addMachineTransition(model, 2, {2}, {1}, "B");
    core::machine::Component cylinder = core::machine::makeComponent(core::machine::ComponentKind::SingleActingCylinder, "Pusher");
    cylinder.wires = {"Lamp", "A", "B"};
    cylinder.parameters = {60, 40};
    requireBuilt(model.setMachine(core::machine::Machine{{cylinder}}));
    return model;
}

core::Model longTimerMachine()
{
    core::Model model = nestedMachine();
    requireBuilt(model.addVariable(variable("Out1", core::IecType::Bool, core::VariableKind::Output)));
    addMachineStep(model, 1, true);
    addMachineStep(model, 2, false, {{ActionTiming::Continuous, "N Out1"}, {ActionTiming::OnActivation, "S Complete"}});
    addMachineTransition(model, 1, {1}, {2}, "25m/X1 AND NOT 30m/X1");
    addMachineTransition(model, 2, {2}, {1}, "A");
    return model;
}

core::Model overlapMachine()
{
    core::Model model = soundMachine();
    requireBuilt(model.setCondition("F1->A3", "B"));
    requireBuilt(model.setCondition("A3->A4", "TRUE"));
    requireBuilt(model.setCondition("A4->F1", "Start"));
    return model;
}

// The overlap machine with F1->A2 waiting for NOT Flag, which F1 sets as it starts.
core::Model alwaysTrueMachine()
{
    core::Model model = overlapMachine();
    requireBuilt(model.addGrafcetAction("F1", 1, {ActionTiming::OnActivation, "S Flag"}));
    requireBuilt(model.setNegated("F1->A2", true));
    requireBuilt(model.setCondition("F1->A2", "Flag"));
    return model;
}

core::Model exclusiveByMemoryMachine()
{
    core::Model model = soundMachine();
    requireBuilt(model.addVariable(variable("Flag2", core::IecType::Bool, core::VariableKind::Internal)));
    requireBuilt(model.addGrafcetAction("F1", 1, {ActionTiming::OnActivation, "S Flag"}));
    requireBuilt(model.addGrafcetAction("F1", 1, {ActionTiming::OnActivation, "R Flag2"}));
    requireBuilt(model.addGrafcetAction("F1", 2, {ActionTiming::OnActivation, "R Flag"}));
    requireBuilt(model.addGrafcetAction("F1", 2, {ActionTiming::OnActivation, "S Flag2"}));
    requireBuilt(model.setNegated("F1->A2", true));
    requireBuilt(model.setCondition("F1->A2", "Flag AND B"));
    requireBuilt(model.setNegated("F1->A3", true));
    requireBuilt(model.setCondition("F1->A3", "Flag2 AND B"));
    requireBuilt(model.setCondition("A3->A4", "TRUE"));
    requireBuilt(model.setCondition("A4->F1", "Start"));
    return model;
}

std::vector<SeededModel> seededDefectModels()
{
    std::vector<SeededModel> out;
    out.push_back({"sound", soundMachine(), {"never Lamp AND in A2", "always in F1 -> NOT F1.X2 OR Lamp"}});
    {
        core::Model model = soundMachine(); // step 3 never active, transition 3 never fires
        addMachineStep(model, 3, false);
        addMachineTransition(model, 3, {1}, {3}, "B AND NOT B");
        out.push_back({"never-active", std::move(model), {}});
    }
    {
        core::Model model = nestedMachine(); // 2 and 3 each lead to 4 without synchronising
        addMachineStep(model, 1, true);
        addMachineStep(model, 2, false);
        addMachineStep(model, 3, false);
        addMachineStep(model, 4, false, {{ActionTiming::OnActivation, "S Complete"}});
        addMachineTransition(model, 1, {1}, {2, 3}, "A");
        addMachineTransition(model, 2, {2}, {4}, "B");
        addMachineTransition(model, 3, {3}, {4}, "C");
        out.push_back({"unsafe", std::move(model), {}});
    }
    {
        core::Model model = soundMachine(); // 3 and 4 fire each other for ever
        addMachineStep(model, 3, false);
        addMachineStep(model, 4, false);
        addMachineTransition(model, 3, {1}, {3}, "B");
        addMachineTransition(model, 4, {3}, {4}, "TRUE");
        addMachineTransition(model, 5, {4}, {3}, "TRUE");
        model.setEvolutionRule(core::EvolutionRule::UntilStable);
        out.push_back({"unstable", std::move(model), {}});
    }
    {
        core::Model model = nestedMachine(); // a selection whose branches are not exclusive
        addMachineStep(model, 1, true);
        addMachineStep(model, 2, false, {{ActionTiming::OnActivation, "S Complete"}});
        addMachineStep(model, 3, false);
        addMachineTransition(model, 1, {1}, {2}, "A");
        addMachineTransition(model, 2, {1}, {3}, "B");
        out.push_back({"branches-together", std::move(model), {}});
    }
    {
        core::Model model = soundMachine(); // a dead end where Complete is never set
        addMachineStep(model, 3, false);
        addMachineTransition(model, 3, {1}, {3}, "B AND NOT A");
        out.push_back({"stuck-without-complete", std::move(model), {"never F1.X3"}});
    }
    {
        core::Model model = nestedMachine(); // parallel steps set and reset Flag in one scan
        addMachineStep(model, 1, true);
        addMachineStep(model, 2, false, {{ActionTiming::OnActivation, "S Flag"}});
        addMachineStep(model, 3, false, {{ActionTiming::OnActivation, "R Flag"}});
        addMachineStep(model, 4, false, {{ActionTiming::OnActivation, "S Complete"}});
        addMachineTransition(model, 1, {1}, {2, 3}, "A");
        addMachineTransition(model, 2, {2, 3}, {4}, "B");
        out.push_back({"race", std::move(model), {"never Flag AND in A2"}});
    }
    {
        core::Model model = soundMachine(); // a stored output is still TRUE when D1 is entered
        requireBuilt(model.addVariable(variable("Horn", core::IecType::Bool, core::VariableKind::Output)));
        requireBuilt(model.addGrafcetAction("F1", 2, {ActionTiming::OnActivation, "S Horn"}));
        out.push_back({"stored-output-on-d1", std::move(model), {"always in D1 -> NOT Horn", "never Lamp AND Horn"}});
    }
    {
        core::Model model = soundMachine(); // edges, a numeric input and an assigned value
        requireBuilt(model.addVariable(variable("Speed", core::IecType::Int, core::VariableKind::Input)));
        addMachineStep(model, 3, false, {{ActionTiming::OnActivation, "Flag := B OR Speed > 10"}});
        addMachineTransition(model, 3, {1}, {3}, "RE C AND Speed > 5");
        addMachineTransition(model, 4, {3}, {1}, "FE C OR Speed >= 100");
        out.push_back({"edges-numbers", std::move(model), {"never F1.X3 AND Flag", "never Flag AND in A2"}});
    }
    {
        core::Model model = nestedMachine(); // a timer: abstracted, or counted in scans
        addMachineStep(model, 1, true);
        addMachineStep(model, 2, false, {{ActionTiming::Continuous, "N Lamp"}});
        addMachineStep(model, 3, false, {{ActionTiming::OnActivation, "S Complete"}});
        addMachineTransition(model, 1, {1}, {2}, "A");
        addMachineTransition(model, 2, {2}, {3}, "100ms/X2");
        addMachineTransition(model, 3, {3}, {1}, "NOT A");
        out.push_back({"timer", std::move(model), {"never F1.X3", "never Lamp AND in A2"}});
    }
    out.push_back({"always-true", alwaysTrueMachine(), {}});
    out.push_back({"overlap", overlapMachine(), {}});
    out.push_back({"exclusive-by-memory", exclusiveByMemoryMachine(), {"never Flag AND Flag2"}});
    return out;
}

} // namespace samples
