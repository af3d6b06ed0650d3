#include "core/model/model.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace test_model {

using namespace core;

namespace {

std::vector<std::string> effectiveIds(const Model& model, std::string_view source)
{
    std::vector<std::string> ids;
    for (const Transition* t : model.effectiveOutgoing(source))
        ids.push_back(t->id);
    return ids;
}

Variable boolVariable(std::string name)
{
    Variable v;
    v.name = std::move(name);
    return v;
}

} // namespace

TEST_CASE("A new model is the template with its defaults", "[model]")
{
    Model model;
    CHECK(model.steps().size() == 16);
    CHECK(model.transitions().size() == 34);
    CHECK(model.initialStep().id == "A6");
    CHECK(model.step("F1")->type == StepType::Macro);
    CHECK(model.transition("F1->D1")->negated);
    CHECK(model.transition("F->D1")->isFamilyTransition());
    CHECK(model.priority("F1->A2") == 3);
    CHECK(model.priority("F->D1") == 1);
    CHECK(model.invariantViolations().empty());
    CHECK(model.settings().cycleTimeMs == 20);
    CHECK(effectiveIds(model, "A1") == std::vector<std::string>{"A1->F4", "A1->F2", "A1->F1", "A1->F5"});
}

TEST_CASE("Setting the initial step clears the previous one", "[model]")
{
    Model model;
    REQUIRE(model.setInitialStep("A1"));
    CHECK(model.initialStep().id == "A1");
    CHECK_FALSE(model.step("A6")->initial);
    CHECK(model.invariantViolations().empty());
    CHECK_FALSE(model.setInitialStep("Z9"));
    CHECK(model.initialStep().id == "A1");
}

TEST_CASE("Step operations refuse unknown ids and leave the model untouched", "[model]")
{
    Model model;
    const auto revision = model.revision();
    Status status = model.setStepType("X1", StepType::Macro);
    CHECK_FALSE(status);
    CHECK(status.code == "unknown-step");
    CHECK(status.message.find("X1") != std::string::npos);
    CHECK_FALSE(model.setCondition("A1->A2", "TRUE"));
    CHECK_FALSE(model.setStepHidden("", true));
    CHECK(model.revision() == revision);
    CHECK(model.sameContent(Model()));
}

TEST_CASE("A transition is effective only when it and both ends are visible", "[model]")
{
    Model model;
    CHECK(model.isEffective("A1->F2"));
    REQUIRE(model.setStepHidden("F2", true));
    CHECK_FALSE(model.isEffective("A1->F2"));
    CHECK_FALSE(model.isEffective("F2->F1"));
    CHECK(model.priority("A1->F2") == 0);
    CHECK(model.priority("A1->F1") == 2);
    CHECK(model.priority("A1->F5") == 3);
    REQUIRE(model.setStepHidden("F2", false));
    REQUIRE(model.setTransitionHidden("A1->F4", true));
    CHECK(model.priority("A1->F2") == 1);
    REQUIRE(model.setStepHidden("D1", true));
    CHECK_FALSE(model.isEffective("F->D1"));
}

TEST_CASE("Setting a priority reorders like a list and hidden transitions keep their place", "[model]")
{
    Model model;
    REQUIRE(model.setPriority("A1->F5", 1));
    CHECK(effectiveIds(model, "A1") == std::vector<std::string>{"A1->F5", "A1->F4", "A1->F2", "A1->F1"});
    REQUIRE(model.setPriority("A1->F5", 4));
    CHECK(effectiveIds(model, "A1") == std::vector<std::string>{"A1->F4", "A1->F2", "A1->F1", "A1->F5"});

    // Hide F2: A1->F2 keeps its slot between F4 and F1.
    REQUIRE(model.setTransitionHidden("A1->F2", true));
    CHECK(effectiveIds(model, "A1") == std::vector<std::string>{"A1->F4", "A1->F1", "A1->F5"});
    REQUIRE(model.setPriority("A1->F5", 2));
    CHECK(effectiveIds(model, "A1") == std::vector<std::string>{"A1->F4", "A1->F5", "A1->F1"});
    REQUIRE(model.setTransitionHidden("A1->F2", false));
    // F5 went before F1, which was right after the hidden F2: F2 stays second in the full order.
    CHECK(effectiveIds(model, "A1") == std::vector<std::string>{"A1->F4", "A1->F2", "A1->F5", "A1->F1"});
    CHECK(model.invariantViolations().empty());

    CHECK_FALSE(model.setPriority("A1->F5", 0));
    CHECK_FALSE(model.setPriority("A1->F5", 5));
    REQUIRE(model.setTransitionHidden("A1->F2", true));
    Status status = model.setPriority("A1->F2", 1);
    CHECK_FALSE(status);
    CHECK(status.code == "not-effective");
}

TEST_CASE("Setting the order moves a transition among all outgoing ones", "[model]")
{
    Model model;
    REQUIRE(model.setOrder("F1->D2", 1));
    CHECK(model.transition("F1->D2")->order == 1);
    CHECK(model.transition("F1->D1")->order == 2);
    CHECK(model.priority("F1->D2") == 1);
    CHECK_FALSE(model.setOrder("F1->D2", 10));
    CHECK(model.invariantViolations().empty());
}

TEST_CASE("Conditions, negation and tokens are stored as given", "[model]")
{
    Model model;
    REQUIRE(model.setCondition("F1->A2", "NOT Stop"));
    REQUIRE(model.setNegated("F1->A2", true));
    REQUIRE(model.setTokens("F1->A2", {"Stop"}));
    const Transition* t = model.transition("F1->A2");
    CHECK(t->condition == "NOT Stop");
    CHECK(t->negated);
    CHECK(t->tokens == std::vector<std::string>{"Stop"});
    Status duplicate = model.setTokens("F1->A2", {"Stop", "STOP"});
    CHECK_FALSE(duplicate);
    CHECK(duplicate.code == "duplicate-token");
    CHECK(model.transition("F1->A2")->tokens == std::vector<std::string>{"Stop"});
    CHECK_FALSE(model.setTokens("F1->A2", {""}));
}

TEST_CASE("Variable names are unique ignoring case and never empty", "[model]")
{
    Model model;
    REQUIRE(model.addVariable(boolVariable("Start")));
    Status duplicate = model.addVariable(boolVariable("START"));
    CHECK_FALSE(duplicate);
    CHECK(duplicate.code == "duplicate-name");
    CHECK_FALSE(model.addVariable(boolVariable("")));
    REQUIRE(model.addVariable(boolVariable("Stop"), 0));
    CHECK(model.variables().front().name == "Stop");
    CHECK(model.variable("start")->name == "Start");
    CHECK_FALSE(model.renameVariable("Stop", "start"));
    REQUIRE(model.renameVariable("Stop", "STOP")); // a change of case only
    CHECK(model.variables().front().name == "STOP");
    REQUIRE(model.moveVariable("STOP", 1));
    CHECK(model.variables().back().name == "STOP");
    REQUIRE(model.removeVariable("stop"));
    CHECK(model.variables().size() == 1);
    CHECK_FALSE(model.removeVariable("Stop"));
    CHECK(model.invariantViolations().empty());
}

TEST_CASE("Renaming a variable rewrites every condition and token that uses it", "[model]")
{
    Model model;
    REQUIRE(model.addVariable(boolVariable("Stop")));
    REQUIRE(model.addVariable(boolVariable("StopButton")));
    REQUIRE(model.setCondition("F1->A2", "NOT stop AND StopButton"));
    REQUIRE(model.setTokens("F1->A2", {"Stop"}));
    REQUIRE(model.setCondition("A2->A1", "STOP OR (Stop AND NOT StopButton)"));
    REQUIRE(model.renameVariable("Stop", "Halt"));
    CHECK(model.transition("F1->A2")->condition == "NOT Halt AND StopButton");
    CHECK(model.transition("F1->A2")->tokens == std::vector<std::string>{"Halt"});
    CHECK(model.transition("A2->A1")->condition == "Halt OR (Halt AND NOT StopButton)");
    CHECK(model.variable("Halt") != nullptr);
    CHECK(model.variable("Stop") == nullptr);
}

TEST_CASE("A variable is renamed only to a valid identifier, so its conditions still parse", "[model]")
{
    Model model;
    REQUIRE(model.addVariable(boolVariable("Stop")));
    REQUIRE(model.setCondition("F1->A2", "NOT Stop"));
    const Model before(model);
    for (const char* invalid : {"Stop 2", "AND", "Int", "2Stop", "Stop__2", "Stop_", "GEMMA"}) {
        const Status status = model.renameVariable("Stop", invalid);
        CHECK_FALSE(status);
        CHECK(status.code == "invalid-name");
        CHECK(status.message.find(invalid) != std::string::npos);
    }
    CHECK(model.sameContent(before));
    REQUIRE(model.renameVariable("Stop", "Stop2"));
    CHECK(model.transition("F1->A2")->condition == "NOT Stop2");
}

TEST_CASE("Variable type, default and comment can be changed by name", "[model]")
{
    Model model;
    REQUIRE(model.addVariable(boolVariable("Speed")));
    REQUIRE(model.setVariableType("speed", IecType::Int));
    REQUIRE(model.setVariableDefault("Speed", "42"));
    REQUIRE(model.setVariableComment("Speed", "rpm"));
    const Variable* v = model.variable("Speed");
    CHECK(v->type == IecType::Int);
    CHECK(v->defaultValue == "42");
    CHECK(v->comment == "rpm");
    CHECK_FALSE(model.setVariableType("Nope", IecType::Int));
}

TEST_CASE("Settings keep the cycle time in range", "[model]")
{
    Model model;
    REQUIRE(model.setCycleTimeMs(10));
    CHECK(model.settings().cycleTimeMs == 10);
    Status status = model.setCycleTimeMs(0);
    CHECK_FALSE(status);
    CHECK(status.message.find("between") != std::string::npos);
    CHECK(model.settings().cycleTimeMs == 10);
    model.setDialect(Dialect::Codesys);
    CHECK(model.settings().dialect == Dialect::Codesys);
    REQUIRE(model.setName("Bottling line"));
    CHECK(model.settings().name == "Bottling line");
}

TEST_CASE("Observers hear of every change, with what changed", "[model]")
{
    Model model;
    std::vector<ModelChange> changes;
    const int handle = model.addObserver([&](const ModelChange& change) { changes.push_back(change); });
    const auto revision = model.revision();

    REQUIRE(model.setStepType("F2", StepType::Enclosing));
    REQUIRE(changes.size() == 1);
    CHECK(changes[0].kind == ModelChange::Kind::Step);
    CHECK(changes[0].id == "F2");

    changes.clear();
    REQUIRE(model.setStepType("F2", StepType::Enclosing)); // no change, no event
    CHECK(changes.empty());

    REQUIRE(model.setPriority("A1->F5", 1));
    CHECK(changes.size() == 4); // all four orders moved

    changes.clear();
    model.resetToTemplate();
    REQUIRE(changes.size() == 1);
    CHECK(changes[0].kind == ModelChange::Kind::Reset);
    CHECK(model.revision() > revision);
    CHECK(model.sameContent(Model()));

    model.removeObserver(handle);
    changes.clear();
    REQUIRE(model.setStepHidden("A2", true));
    CHECK(changes.empty());
}

TEST_CASE("A copy holds the same content and no observers", "[model]")
{
    Model model;
    int calls = 0;
    model.addObserver([&](const ModelChange&) { ++calls; });
    REQUIRE(model.setStepHidden("A3", true));
    Model copy(model);
    CHECK(copy.sameContent(model));
    REQUIRE(copy.setStepHidden("A4", true));
    CHECK(calls == 1);
    CHECK_FALSE(copy.sameContent(model));
    model.assign(copy);
    CHECK(calls == 2);
    CHECK(model.sameContent(copy));
}

TEST_CASE("Observers always see exactly one initial step", "[model]")
{
    Model model;
    std::vector<std::string> initialSeen;
    model.addObserver([&](const ModelChange&) {
        REQUIRE(model.invariantViolations().empty());
        initialSeen.push_back(model.initialStep().id);
    });
    REQUIRE(model.setInitialStep("F1"));
    CHECK(initialSeen == std::vector<std::string>{"F1", "F1"});
}

// ---- nested GRAFCETs, variable kinds, evolution rule ---------------------------

namespace {

GrafcetStep nestedStep(int number, bool initial = false)
{
    GrafcetStep step;
    step.number = number;
    step.initial = initial;
    return step;
}

GrafcetTransition nestedTransition(int number, int from, int to, std::string receptivity)
{
    GrafcetTransition transition;
    transition.number = number;
    transition.upstream = {from};
    transition.downstream = {to};
    transition.receptivity = std::move(receptivity);
    return transition;
}

} // namespace

TEST_CASE("A macro-step gets its nested GRAFCET by id, a simple step none", "[model][grafcet]")
{
    Model model;
    CHECK(model.grafcet("F1") == nullptr);
    const Status simple = model.addGrafcetStep("A1", nestedStep(1, true));
    CHECK_FALSE(simple.ok);
    CHECK(simple.code == "simple-step");
    CHECK(model.addGrafcetStep("Z9", nestedStep(1)).code == "unknown-step");
    CHECK(model.removeGrafcetStep("F1", 1).code == "no-grafcet");

    REQUIRE(model.addGrafcetStep("F1", nestedStep(1, true)));
    REQUIRE(model.addGrafcetStep("F1", nestedStep(2)));
    REQUIRE(model.addGrafcetTransition("F1", nestedTransition(1, 1, 2, "Start")));
    REQUIRE(model.grafcet("F1") != nullptr);
    CHECK(model.grafcet("F1")->steps().size() == 2);
    CHECK(model.effectiveGrafcet("F1") == model.grafcet("F1"));
    // The GRAFCET's own invariants are kept through the model.
    CHECK_FALSE(model.addGrafcetTransition("F1", nestedTransition(2, 1, 7, "TRUE")));
    CHECK(model.invariantViolations().empty());
}

TEST_CASE("Hiding a step or making it simple keeps its GRAFCET, not effective", "[model][grafcet]")
{
    Model model;
    REQUIRE(model.addGrafcetStep("F2", nestedStep(1, true)));
    REQUIRE(model.setStepHidden("F2", true));
    CHECK(model.grafcet("F2") != nullptr);
    CHECK(model.effectiveGrafcet("F2") == nullptr);
    REQUIRE(model.setStepHidden("F2", false));
    REQUIRE(model.setStepType("F2", StepType::Simple));
    CHECK(model.effectiveGrafcet("F2") == nullptr);
    // What it kept can still be edited, and comes back with the type.
    REQUIRE(model.addGrafcetStep("F2", nestedStep(2)));
    REQUIRE(model.setStepType("F2", StepType::Enclosing));
    REQUIRE(model.effectiveGrafcet("F2") != nullptr);
    CHECK(model.effectiveGrafcet("F2")->steps().size() == 2);
}

TEST_CASE("Nested GRAFCET operations notify observers with what changed", "[model][grafcet]")
{
    Model model;
    std::vector<ModelChange> changes;
    model.addObserver([&](const ModelChange& change) { changes.push_back(change); });

    REQUIRE(model.addGrafcetStep("F1", nestedStep(1, true)));
    REQUIRE(changes.size() == 1);
    CHECK(changes[0].kind == ModelChange::Kind::Grafcet);
    CHECK(changes[0].id == "F1");
    CHECK(changes[0].grafcetChanges.empty()); // created as a whole

    changes.clear();
    REQUIRE(model.addGrafcetStep("F1", nestedStep(2)));
    REQUIRE(model.addGrafcetTransition("F1", nestedTransition(1, 1, 2, "A")));
    REQUIRE(model.setReceptivity("F1", 1, "B"));
    REQUIRE(changes.size() == 3);
    CHECK(changes[2].grafcetChanges == std::vector<GrafcetChange>{{GrafcetChange::Kind::Transition, 1}});

    changes.clear();
    REQUIRE(model.setReceptivity("F1", 1, "B")); // no change, no event
    CHECK(changes.empty());
    CHECK_FALSE(model.setReceptivity("F1", 9, "B"));
    CHECK(changes.empty());

    REQUIRE(model.removeGrafcet("F1"));
    REQUIRE(changes.size() == 1);
    CHECK(changes[0].kind == ModelChange::Kind::Grafcet);
    CHECK(model.grafcet("F1") == nullptr);
}

TEST_CASE("Renaming a variable rewrites receptivities and actions", "[model][grafcet]")
{
    Model model;
    REQUIRE(model.addVariable(boolVariable("Valve")));
    REQUIRE(model.addGrafcetStep("F1", nestedStep(1, true)));
    REQUIRE(model.addGrafcetStep("F1", nestedStep(2)));
    REQUIRE(model.addGrafcetAction("F1", 2, {ActionTiming::Continuous, "N Valve IF NOT valve_open"}));
    REQUIRE(model.addGrafcetAction("F1", 1, {ActionTiming::OnActivation, "R VALVE"}));
    REQUIRE(model.addGrafcetTransition("F1", nestedTransition(1, 1, 2, "Valve AND X1")));

    std::vector<ModelChange> changes;
    model.addObserver([&](const ModelChange& change) { changes.push_back(change); });
    REQUIRE(model.renameVariable("Valve", "Inlet"));
    const Grafcet& nested = *model.grafcet("F1");
    CHECK(nested.step(2)->actions[0].text == "N Inlet IF NOT valve_open");
    CHECK(nested.step(1)->actions[0].text == "R Inlet");
    CHECK(nested.transition(1)->receptivity == "Inlet AND X1");
    const bool heard = std::any_of(changes.begin(), changes.end(), [](const ModelChange& c) {
        return c.kind == ModelChange::Kind::Grafcet && c.id == "F1" && !c.grafcetChanges.empty();
    });
    CHECK(heard);
}

TEST_CASE("Copies, assignment and sameContent include GRAFCETs, kinds and the rule", "[model][grafcet]")
{
    Model model;
    REQUIRE(model.addGrafcetStep("D3", nestedStep(1, true)));
    Model copy(model);
    CHECK(copy.sameContent(model));
    REQUIRE(copy.setGrafcetStepComment("D3", 1, "wait"));
    CHECK_FALSE(copy.sameContent(model));
    model.assign(copy);
    CHECK(model.sameContent(copy));

    REQUIRE(model.addVariable(boolVariable("Lamp")));
    CHECK(model.variable("Lamp")->kind == VariableKind::Input);
    Model before(model);
    REQUIRE(model.setVariableKind("Lamp", VariableKind::Output));
    CHECK_FALSE(model.sameContent(before));
    CHECK(model.setVariableKind("Nope", VariableKind::Output).code == "unknown-variable");

    Model ruled(model);
    CHECK(ruled.settings().evolution == EvolutionRule::OneEvolutionPerScan);
    ruled.setEvolutionRule(EvolutionRule::UntilStable);
    CHECK_FALSE(ruled.sameContent(model));

    Grafcet broken;
    CHECK(model.setGrafcet("F3", broken));          // an empty GRAFCET is valid structure
    CHECK(model.setGrafcet("Z1", broken).code == "unknown-step");
}

TEST_CASE("Variable kinds and evolution rules have stable names", "[model]")
{
    for (VariableKind kind : {VariableKind::Input, VariableKind::Output, VariableKind::Internal}) {
        VariableKind parsed = VariableKind::Input;
        REQUIRE(parseVariableKind(variableKindName(kind), parsed));
        CHECK(parsed == kind);
    }
    VariableKind unused = VariableKind::Input;
    CHECK_FALSE(parseVariableKind("Output", unused));
    for (EvolutionRule rule : {EvolutionRule::OneEvolutionPerScan, EvolutionRule::UntilStable}) {
        EvolutionRule parsed = EvolutionRule::OneEvolutionPerScan;
        REQUIRE(parseEvolutionRule(evolutionRuleName(rule), parsed));
        CHECK(parsed == rule);
    }
}

} // namespace test_model
