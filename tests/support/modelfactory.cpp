#include "modelfactory.h"

#include <array>
#include <stdexcept>
#include <vector>

namespace factory {

namespace {

void require(const core::Status& status)
{
    if (!status)
        throw std::logic_error("model factory: " + status.message);
}

core::Variable variable(std::string name, core::IecType type, std::string defaultValue, std::string comment)
{
    return core::Variable{std::move(name), type, std::move(defaultValue), std::move(comment)};
}

template <typename T>
const T& pick(std::mt19937& random, const std::vector<T>& items)
{
    std::uniform_int_distribution<std::size_t> index(0, items.size() - 1);
    return items[index(random)];
}

int between(std::mt19937& random, int low, int high)
{
    return std::uniform_int_distribution<int>(low, high)(random);
}

std::string randomCondition(std::mt19937& random, const core::Model& model)
{
    static const std::vector<std::string> shapes{"{0}", "NOT {0}", "{0} AND {1}", "{0} OR NOT {1}",
                                                 "({0} OR {1}) AND {2}", "{0} XOR {1}", "TRUE", "",
                                                 "{0} AND", "{0} = {1}", "NOT NOT {0}"};
    std::string text = pick(random, shapes);
    for (char slot : {'0', '1', '2'}) {
        const std::string placeholder = std::string("{") + slot + "}";
        for (auto at = text.find(placeholder); at != std::string::npos; at = text.find(placeholder)) {
            const std::string name =
                model.variables().empty() ? "Unknown" : pick(random, model.variables()).name;
            text.replace(at, placeholder.size(), name);
        }
    }
    return text;
}

} // namespace

core::Model realisticModel()
{
    core::Model model;
    require(model.setName("Bottle filling line"));
    require(model.setCycleTimeMs(10));
    const std::array<core::Variable, 20> variables{{
        variable("EmergencyStop", core::IecType::Bool, "FALSE", "Emergency stop chain open"),
        variable("Start", core::IecType::Bool, "", "Start push button"),
        variable("Stop", core::IecType::Bool, "", "Stop push button"),
        variable("Reset", core::IecType::Bool, "", "Reset push button"),
        variable("Acknowledge", core::IecType::Bool, "", "Fault acknowledged by the operator"),
        variable("AutoMode", core::IecType::Bool, "TRUE", "Mode selector on automatic"),
        variable("VerifyMode", core::IecType::Bool, "", "Mode selector on verification"),
        variable("Fault", core::IecType::Bool, "", "Any drive fault"),
        variable("MotorOverload", core::IecType::Bool, "", "Conveyor motor thermal relay"),
        variable("DoorClosed", core::IecType::Bool, "", "Guard door closed"),
        variable("AirPressureOk", core::IecType::Bool, "", "Compressed air above 5 bar"),
        variable("HomePosition", core::IecType::Bool, "", "Filler head in home position"),
        variable("CycleEnd", core::IecType::Bool, "", "Current bottle finished"),
        variable("PreparationDone", core::IecType::Bool, "", "Tank filled and rinsed"),
        variable("BottlePresent", core::IecType::Bool, "", "Bottle under the filler"),
        variable("BottleCount", core::IecType::Int, "0", "Bottles filled in this batch"),
        variable("BatchSize", core::IecType::Int, "500", "Bottles per batch"),
        variable("Temperature", core::IecType::Real, "20.0", "Product temperature in degrees Celsius"),
        variable("MaxTemperature", core::IecType::Real, "45.5", "Alarm threshold"),
        variable("FaultCount", core::IecType::Dint, "0", "Faults since power-on"),
    }};
    for (const core::Variable& v : variables)
        require(model.addVariable(v));

    for (const char* hidden : {"A3", "F3", "F5", "F6", "D3"})
        require(model.setStepHidden(hidden, true));
    require(model.setStepType("F2", core::StepType::Simple));

    const std::array<std::pair<const char*, const char*>, 19> conditions{{
        {"F->D1", "EmergencyStop"},
        {"A6->A1", "HomePosition AND AirPressureOk"},
        {"A1->F4", "VerifyMode AND Start"},
        {"A1->F2", "Start AND NOT PreparationDone"},
        {"A1->F1", "Start AND AutoMode AND PreparationDone AND DoorClosed"},
        {"A2->A1", "CycleEnd"},
        {"A4->F1", "Start AND DoorClosed"},
        {"A5->A6", "Reset AND Acknowledge"},
        {"A5->A7", "Reset AND NOT HomePosition"},
        {"A7->A4", "HomePosition"},
        {"F1->D1", "MotorOverload OR Temperature > MaxTemperature"},
        {"F1->A2", "NOT Stop"},
        {"F1->F4", "VerifyMode AND NOT BottlePresent"},
        {"F1->D2", "Fault AND FaultCount < 3"},
        {"F2->F1", "PreparationDone"},
        {"F4->A6", "Stop OR BottleCount >= BatchSize"},
        {"D1->A5", "NOT EmergencyStop AND Acknowledge"},
        {"D1->D2", "Fault"},
        {"D2->A5", "Acknowledge AND NOT Fault"},
    }};
    for (const auto& [id, condition] : conditions)
        require(model.setCondition(id, condition));
    require(model.setTokens("F1->A2", {"Stop"}));
    require(model.setTokens("F1->F4", {"VerifyMode"}));
    require(model.setTokens("F1->D2", {"Fault"}));
    require(model.setStepComment("F1", "Fill, cap and label bottles"));
    return model;
}

core::Model stressModel()
{
    core::Model model;
    std::vector<std::string> bools;
    std::vector<std::string> ints;
    for (int i = 0; i < 500; ++i) {
        const bool isBool = i % 5 != 4;
        std::string name = (isBool ? "Sensor" : "Counter") + std::to_string(i);
        require(model.addVariable(variable(name, isBool ? core::IecType::Bool : core::IecType::Int, "", "")));
        (isBool ? bools : ints).push_back(std::move(name));
    }
    std::mt19937 random(2026);
    for (const core::Transition& t : model.transitions()) {
        std::string condition;
        for (int operand = 0; operand < 30; ++operand) {
            if (operand > 0)
                condition += operand % 3 == 0 ? " OR " : " AND ";
            if (operand % 4 == 3) {
                condition += pick(random, ints) + " > " + std::to_string(between(random, 0, 100));
            } else {
                condition += (operand % 2 ? "NOT " : "") + pick(random, bools);
            }
        }
        require(model.setCondition(t.id, condition));
    }
    return model;
}

core::Model verificationStressModel()
{
    core::Model model;
    constexpr int kVariables = 40;
    for (int i = 0; i < kVariables; ++i)
        require(model.addVariable(variable("In" + std::to_string(i), core::IecType::Bool, "", "")));
    int next = 0;
    for (const core::Transition& t : model.transitions()) {
        std::vector<std::string> names;
        for (int k = 0; k < 3; ++k)
            names.push_back("In" + std::to_string((next + k * 13) % kVariables));
        next += 3;
        require(model.setCondition(t.id, "(" + names[0] + " AND NOT " + names[1] + ") OR " + names[2]));
        const core::Step* source = model.step(t.source);
        if (source && source->type != core::StepType::Simple && !t.isFamilyTransition())
            require(model.setTokens(t.id, names));
    }
    return model;
}

core::Model comparisonVerificationModel(int operands, bool mixed)
{
    core::Model model;
    std::vector<std::string> ints;
    std::vector<std::string> bools;
    for (int i = 0; i < 8; ++i) {
        ints.push_back((i % 2 ? "Level" : "Speed") + std::to_string(i));
        require(model.addVariable(variable(ints.back(), core::IecType::Int, "", "")));
        bools.push_back("In" + std::to_string(i));
        require(model.addVariable(variable(bools.back(), core::IecType::Bool, "", "")));
    }
    require(model.addVariable(variable("Temperature", core::IecType::Real, "", "")));
    require(model.addVariable(variable("Pressure", core::IecType::Real, "", "")));
    static const std::vector<std::string> relations{">", "<=", "<", ">=", "=", "<>"};
    std::mt19937 random(static_cast<std::uint32_t>(2026 + operands + (mixed ? 1000 : 0)));
    for (const core::Transition& t : model.transitions()) {
        std::string condition;
        for (int operand = 0; operand < operands; ++operand) {
            if (operand > 0)
                condition += operand % 3 == 2 ? " OR " : " AND ";
            const int kind = mixed ? operand % 4 : 0;
            if (kind == 0)
                condition += pick(random, ints) + " " + pick(random, relations) + " "
                    + std::to_string(between(random, 0, 300));
            else if (kind == 1)
                condition += (operand % 8 == 1 ? "NOT " : "") + pick(random, bools);
            else if (kind == 2)
                condition += std::string(operand % 8 == 2 ? "Temperature" : "Pressure") + " > "
                    + std::to_string(between(random, 0, 100)) + ".5";
            else
                condition += pick(random, ints) + " + " + pick(random, ints) + " > "
                    + std::to_string(between(random, 0, 400));
        }
        require(model.setCondition(t.id, condition));
    }
    return model;
}

core::Model hugeConditionVerificationModel()
{
    core::Model model = comparisonVerificationModel(12, false);
    std::mt19937 random(15);
    for (const char* id : {"A1->F1", "F1->A2"}) {
        std::string condition;
        while (condition.size() < 5000) {
            if (!condition.empty())
                condition += " OR ";
            condition += "(In" + std::to_string(between(random, 0, 7)) + " AND Speed"
                + std::to_string(2 * between(random, 0, 3)) + " > " + std::to_string(between(random, 0, 300))
                + " AND NOT In" + std::to_string(between(random, 0, 7)) + " AND Level"
                + std::to_string(2 * between(random, 0, 3) + 1) + " <= " + std::to_string(between(random, 0, 300))
                + ")";
        }
        require(model.setCondition(id, condition));
    }
    require(model.setCondition("D2->A5", "Speed0 > 10 AND Speed0 < 5"));
    return model;
}

core::Grafcet loopedSequence(int steps)
{
    core::Grafcet grafcet;
    for (int n = 1; n <= steps; ++n) {
        core::GrafcetStep step;
        step.number = n;
        step.initial = n == 1;
        step.actions.push_back({core::ActionTiming::Continuous, "Out" + std::to_string(n)});
        require(grafcet.addStep(step));
    }
    for (int n = 1; n <= steps; ++n) {
        core::GrafcetTransition transition;
        transition.number = n;
        transition.upstream = {n};
        transition.downstream = {n < steps ? n + 1 : 1};
        transition.receptivity = "Go" + std::to_string(n);
        require(grafcet.addTransition(transition));
    }
    return grafcet;
}

int applyRandomEdits(core::Model& model, std::mt19937& random, int count)
{
    std::vector<std::string> stepIds;
    for (const core::Step& s : model.steps())
        stepIds.push_back(s.id);
    stepIds.push_back("X9"); // not a step: must be refused
    std::vector<std::string> transitionIds;
    for (const core::Transition& t : model.transitions())
        transitionIds.push_back(t.id);
    transitionIds.push_back("A1->D3");
    const std::vector<std::string> names{"Start", "stop", "Stop", "Speed", "Level", "Door_Closed", "", "X"};
    const std::vector<core::StepType> types{core::StepType::Simple, core::StepType::Macro,
                                            core::StepType::Enclosing};

    int accepted = 0;
    for (int i = 0; i < count; ++i) {
        core::Status status;
        const std::string& stepId = pick(random, stepIds);
        const std::string& transitionId = pick(random, transitionIds);
        const std::string& name = pick(random, names);
        switch (between(random, 0, 16)) {
        case 0: status = model.setStepType(stepId, pick(random, types)); break;
        case 1: status = model.setInitialStep(stepId); break;
        case 2: status = model.setStepHidden(stepId, between(random, 0, 2) == 0); break;
        case 3: status = model.setStepComment(stepId, "comment <" + std::to_string(i) + "> *) \"&"); break;
        case 4: status = model.setTransitionHidden(transitionId, between(random, 0, 3) == 0); break;
        case 5: status = model.setPriority(transitionId, between(random, 0, 10)); break;
        case 6: status = model.setOrder(transitionId, between(random, 0, 10)); break;
        case 7: status = model.setCondition(transitionId, randomCondition(random, model)); break;
        case 8: status = model.setNegated(transitionId, between(random, 0, 1) == 1); break;
        case 9: status = model.setTokens(transitionId, {name}); break;
        case 10: status = model.addVariable(variable(name, pick(random, std::vector<core::IecType>{
                                                                 core::IecType::Bool, core::IecType::Int,
                                                                 core::IecType::Real}),
                                                     "", "")); break;
        case 11: status = model.removeVariable(name); break;
        case 12: status = model.renameVariable(name, pick(random, names) + std::to_string(between(random, 0, 3)));
            break;
        case 13: status = model.setVariableType(name, core::IecType::Dint); break;
        case 14: status = model.setVariableDefault(name, std::to_string(between(random, -5, 300))); break;
        case 15: status = model.setCycleTimeMs(between(random, -1, 100)); break;
        default: status = model.moveVariable(name, between(random, -1, 5)); break;
        }
        accepted += status ? 1 : 0;
    }
    return accepted;
}

core::Model unstableGrafcetModel(int steps)
{
    core::Grafcet grafcet;
    for (int n = 1; n <= steps; ++n)
        require(grafcet.addStep({n, n == 1, "", {}}));
    for (int n = 1; n <= steps; ++n)
        require(grafcet.addTransition({n, {n}, {n < steps ? n + 1 : 1}, "TRUE"}));
    core::Model model;
    require(model.setName("Unstable GRAFCET"));
    require(model.setInitialStep("F1"));
    require(model.setGrafcet("F1", std::move(grafcet)));
    model.setEvolutionRule(core::EvolutionRule::UntilStable);
    return model;
}

core::Model longGrafcetModel(int steps)
{
    core::Model model = realisticModel();
    (void)model.setGrafcet("F1", loopedSequence(steps));
    return model;
}

} // namespace factory

namespace factory {

namespace {

// Fork 1 -> three branches of `length` steps -> join -> a Complete step -> back to 1.
void addParallelGrafcet(core::Model& model, const std::string& stepId, int index, int length,
                        std::vector<std::string>& memories)
{
    const std::string prefix = stepId + "_";
    auto input = [&](const std::string& name) { return prefix + name; };
    for (const char* name : {"Go", "Ack"})
        require(model.addVariable(variable(input(name), core::IecType::Bool, "", "")));
    for (int branch = 0; branch < 3; ++branch)
        require(model.addVariable(variable(input("In" + std::to_string(branch)), core::IecType::Bool, "", "")));
    const std::string output = prefix + "Move";
    require(model.addVariable(variable(output, core::IecType::Bool, "", "")));
    require(model.setVariableKind(output, core::VariableKind::Output));
    require(model.addGrafcetStep(stepId, {1, true, "", {}}));
    const int join = 2 + 3 * length;
    std::vector<int> firsts, lasts;
    for (int branch = 0; branch < 3; ++branch) {
        for (int k = 0; k < length; ++k) {
            const int number = 2 + branch * length + k;
            std::vector<core::GrafcetAction> actions;
            if (k == 0 && memories.size() < 18) {
                const std::string memory = "Mem" + std::to_string(memories.size());
                require(model.addVariable(variable(memory, core::IecType::Bool, "", "")));
                require(model.setVariableKind(memory, core::VariableKind::Internal));
                memories.push_back(memory);
                actions.push_back({core::ActionTiming::OnActivation, "S " + memory});
            }
            if (k == length - 1)
                actions.push_back({core::ActionTiming::Continuous, "N " + output + " IF " + input("Go")});
            require(model.addGrafcetStep(stepId, {number, false, "", actions}));
            if (k == 0)
                firsts.push_back(number);
            if (k == length - 1)
                lasts.push_back(number);
            if (k > 0)
                require(model.addGrafcetTransition(
                    stepId, {number - 1 + 100, {number - 1}, {number}, input("In" + std::to_string(branch))
                                                                             + (k % 2 ? "" : " AND NOT " + input("Go"))}));
        }
    }
    std::vector<core::GrafcetAction> joinActions{{core::ActionTiming::OnActivation, "S Complete"}};
    for (std::size_t m = memories.size() >= 3 ? memories.size() - 3 : 0; m < memories.size(); ++m)
        joinActions.push_back({core::ActionTiming::OnActivation, "R " + memories[m]});
    require(model.addGrafcetStep(stepId, {join, false, "", joinActions}));
    require(model.addGrafcetStep(stepId, {join + 1, false, "", {{core::ActionTiming::OnActivation, "R Complete"}}}));
    require(model.addGrafcetTransition(stepId, {1, {1}, firsts, input("Go")}));
    require(model.addGrafcetTransition(stepId, {2, lasts, {join}, "TRUE"}));
    require(model.addGrafcetTransition(stepId, {3, {join}, {join + 1}, input("Ack")}));
    require(model.addGrafcetTransition(stepId, {4, {join + 1}, {1}, "NOT " + input("Ack")}));
    (void)index;
}

} // namespace

core::Model bothLayersStressModel(int branchLength)
{
    core::Model model;
    for (const char* name : {"Start", "Stop", "EStop", "Fault", "Test", "Reset"})
        require(model.addVariable(variable(name, core::IecType::Bool, "", "")));
    require(model.setInitialStep("A1"));
    const std::vector<std::pair<std::string, std::string>> conditions{
        {"A1->F2", "Start"}, {"F2->F1", "NOT Start"}, {"F1->A2", "NOT Stop"}, {"F1->F3", "Fault"},
        {"F1->F5", "Test"},  {"F1->D3", "Fault AND Test"}, {"F5->F4", "NOT Test"}, {"F4->A6", "Reset"},
        {"A6->A1", "NOT Reset"}, {"A2->A1", "TRUE"}, {"F3->A1", "Reset"}, {"D3->A2", "Reset"},
        {"F->D1", "EStop"},  {"D1->A5", "NOT EStop"}, {"A5->A6", "Reset"}};
    for (const auto& [id, condition] : conditions)
        require(model.setCondition(id, condition));
    for (const core::Transition& t : model.transitions()) {
        if (t.condition.empty())
            require(model.setTransitionHidden(t.id, true));
    }
    for (const char* unused : {"A3", "A4", "A7", "F6", "D2"})
        require(model.setStepHidden(unused, true));
    require(model.setTokens("F1->A2", {"Stop"}));
    require(model.setTokens("F1->F3", {"Fault"}));
    std::vector<std::string> memories;
    int index = 0;
    for (const char* stepId : {"F1", "F2", "F3", "F4", "F5", "D3"})
        addParallelGrafcet(model, stepId, index++, branchLength, memories);
    for (const char* name : {"BatchMark", "ServiceMark"}) {
        require(model.addVariable(variable(name, core::IecType::Bool, "", "")));
        require(model.setVariableKind(name, core::VariableKind::Internal));
    }
    require(model.addGrafcetAction("F1", 1, {core::ActionTiming::OnActivation, "S BatchMark"}));
    require(model.addGrafcetAction("F2", 1, {core::ActionTiming::OnActivation, "R BatchMark"}));
    require(model.addGrafcetAction("F5", 1, {core::ActionTiming::OnActivation, "S ServiceMark"}));
    require(model.addGrafcetAction("F4", 1, {core::ActionTiming::OnActivation, "R ServiceMark"}));
    return model;
}

} // namespace factory

namespace factory {

core::Model unstableCycleModel(int steps, int inputs)
{
    core::Model model;
    require(model.addVariable(variable("Start", core::IecType::Bool, "", "")));
    for (int k = 0; k < inputs; ++k)
        require(model.addVariable(variable("In" + std::to_string(k), core::IecType::Bool, "", "")));
    require(model.setInitialStep("A1"));
    require(model.setStepType("F1", core::StepType::Macro));
    require(model.setCondition("A1->F1", "Start"));
    model.setEvolutionRule(core::EvolutionRule::UntilStable);
    core::Grafcet grafcet;
    for (int n = 1; n <= steps; ++n)
        require(grafcet.addStep({n, n == 1, "", {}}));
    for (int n = 1; n <= steps; ++n) {
        core::GrafcetTransition transition;
        transition.number = n;
        transition.upstream = {n};
        transition.downstream = {n < steps ? n + 1 : 1};
        transition.receptivity = inputs == 0 ? "TRUE" : "In" + std::to_string(n % inputs);
        require(grafcet.addTransition(transition));
    }
    require(model.setGrafcet("F1", std::move(grafcet)));
    return model;
}

} // namespace factory
