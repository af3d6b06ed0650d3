#include <catch2/catch.hpp>

#include "core/checks/checks.h"
#include "core/condition/conditionparser.h"
#include "core/model/model.h"
#include "core/simulation/simulator.h"
#include "modelfactory.h"

#include <algorithm>
#include <initializer_list>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace test_simulator {

using namespace core;

// Every expected trace below is computed by hand from the generated code of
// spec §6 (CASE branch, entry block, ELSIF chain, token updates after
// END_CASE); the comment above each scan says which lines decide it.

namespace {

// The template with only `visible` steps shown and `initial` as initial step.
Model onlyVisible(std::initializer_list<const char*> visible, const char* initial)
{
    Model model;
    REQUIRE(model.setInitialStep(initial));
    for (const Step& step : std::vector<Step>(model.steps())) {
        const bool keep = std::any_of(visible.begin(), visible.end(), [&](const char* id) { return step.id == id; });
        if (!keep)
            REQUIRE(model.setStepHidden(step.id, true));
    }
    return model;
}

void addVariable(Model& model, const std::string& name, IecType type = IecType::Bool, const std::string& value = "")
{
    REQUIRE(model.addVariable(Variable{name, type, value, ""}));
}

void condition(Model& model, const char* transition, const char* text)
{
    REQUIRE(model.setCondition(transition, text));
}

void set(Simulator& simulator, const char* name, cond::Value value)
{
    const Status status = simulator.setVariable(name, value);
    INFO(status.message);
    REQUIRE(status);
}

// The English text of each reason.
std::vector<std::string> texts(const std::vector<ExplanationReason>& reasons)
{
    std::vector<std::string> result;
    for (const ExplanationReason& reason : reasons)
        result.push_back(toText(reason));
    return result;
}

// "before>after fired E tokens": e.g. "A1>F1 A1->F1 E 01".
std::string describe(const ScanRecord& record)
{
    std::string text = record.stepBefore + ">" + record.stepAfter + " " + (record.fired.empty() ? "-" : record.fired)
                       + (record.entry ? " E" : " .");
    if (!record.tokens.empty()) {
        text += " ";
        for (bool token : record.tokens)
            text += token ? '1' : '0';
    }
    return text;
}

std::string scan(Simulator& simulator)
{
    return describe(simulator.step());
}

} // namespace

TEST_CASE("Simulator: simple steps do not touch Entry and fire one transition per scan", "[simulation]")
{
    Model model = onlyVisible({"A6", "A1", "F2"}, "A6");
    REQUIRE(model.setStepType("F2", StepType::Simple));
    addVariable(model, "Go");
    addVariable(model, "Start");
    condition(model, "A6->A1", "Go");
    condition(model, "A1->F2", "Start");
    Simulator sim(model);
    CHECK(sim.activeStepId() == "A6");
    CHECK(sim.activeStepNumber() == 6);
    CHECK(sim.entry());

    // 6: IF Go THEN ... : Go is FALSE, nothing; a simple branch leaves Entry alone.
    CHECK(scan(sim) == "A6>A6 - E");
    set(sim, "Go", true);
    set(sim, "Start", true); // A1's condition is already TRUE, but only one transition fires per scan
    CHECK(scan(sim) == "A6>A1 A6->A1 E");
    // 1: IF Start THEN State := 9; Entry := TRUE;
    CHECK(scan(sim) == "A1>F2 A1->F2 E");
    // 9: F2 has no effective transition: State := 9;
    CHECK(scan(sim) == "F2>F2 - E");
    CHECK(sim.scanCount() == 4);
    CHECK(sim.simulatedTimeMs() == 4 * model.settings().cycleTimeMs);
    CHECK(sim.lastFired().empty());
}

TEST_CASE("Simulator: a macro-step waits for Complete, given by hand", "[simulation]")
{
    Model model = onlyVisible({"A5", "A7", "A4"}, "A5");
    addVariable(model, "Go");
    addVariable(model, "Done");
    condition(model, "A5->A7", "Go");
    condition(model, "A7->A4", "Done");
    Simulator sim(model);
    REQUIRE(sim.nestedSteps() == std::vector<std::string>{"A7"});
    REQUIRE(sim.setCompleteMode("A7", CompleteMode::Manual));
    REQUIRE(sim.setComplete("A7", false));
    set(sim, "Go", true);
    set(sim, "Done", true);

    CHECK(scan(sim) == "A5>A7 A5->A7 E");
    // 7: IF Entry THEN A7(...); Entry := FALSE; END_IF; A7(...); IF Done AND A7.Complete: Complete FALSE.
    CHECK(scan(sim) == "A7>A7 - .");
    CHECK_FALSE(sim.complete("A7"));
    CHECK(scan(sim) == "A7>A7 - .");
    REQUIRE(sim.setComplete("A7", true));
    CHECK(scan(sim) == "A7>A4 A7->A4 E");
    CHECK(sim.complete("A7"));

    SECTION("automatic Complete is TRUE from the entry scan on, as the skeleton FB")
    {
        REQUIRE(sim.setCompleteMode("A7", CompleteMode::Automatic));
        sim.reset();
        CHECK(sim.activeStepId() == "A5");
        CHECK_FALSE(sim.complete("A7"));
        CHECK(sim.variable("Go") == cond::Value{false}); // reset: the defaults again
        set(sim, "Go", true);
        set(sim, "Done", true);
        CHECK(scan(sim) == "A5>A7 A5->A7 E");
        CHECK(scan(sim) == "A7>A4 A7->A4 E");
    }
    SECTION("a manual TRUE held while entering applies in the entry scan: the FB body runs after Initialization")
    {
        REQUIRE(sim.setComplete("A7", true));
        sim.reset();
        CHECK(sim.completeMode("A7") == CompleteMode::Manual); // reset keeps the modes
        set(sim, "Go", true);
        set(sim, "Done", true);
        CHECK(scan(sim) == "A5>A7 A5->A7 E");
        CHECK(scan(sim) == "A7>A4 A7->A4 E");
    }
}

TEST_CASE("Simulator: an enclosing step does not wait; negation flips both", "[simulation]")
{
    Model model = onlyVisible({"A1", "F4", "A6", "A5", "A7", "A4"}, "A1");
    for (const char* name : {"Verify", "Leave", "Go", "Done"})
        addVariable(model, name);
    condition(model, "A1->F4", "Verify");
    condition(model, "F4->A6", "Leave");
    condition(model, "A6->A1", "FALSE");
    condition(model, "A5->A7", "Go");
    condition(model, "A7->A4", "Done");
    condition(model, "A5->A6", "FALSE");
    condition(model, "A4->F1", "FALSE");

    SECTION("enclosing, not negated: fires while Complete is FALSE")
    {
        Simulator sim(model);
        REQUIRE(sim.setCompleteMode("F4", CompleteMode::Manual));
        set(sim, "Verify", true);
        set(sim, "Leave", true);
        CHECK(scan(sim) == "A1>F4 A1->F4 E");
        CHECK(scan(sim) == "F4>A6 F4->A6 E");
    }
    SECTION("enclosing, negated: waits for Complete")
    {
        REQUIRE(model.setNegated("F4->A6", true));
        Simulator sim(model);
        REQUIRE(sim.setCompleteMode("F4", CompleteMode::Manual));
        set(sim, "Verify", true);
        set(sim, "Leave", true);
        CHECK(scan(sim) == "A1>F4 A1->F4 E");
        CHECK(scan(sim) == "F4>F4 - .");
        REQUIRE(sim.setComplete("F4", true));
        CHECK(scan(sim) == "F4>A6 F4->A6 E");
    }
    SECTION("macro, negated: ignores Complete")
    {
        REQUIRE(model.setInitialStep("A5"));
        REQUIRE(model.setNegated("A7->A4", true));
        Simulator sim(model);
        REQUIRE(sim.setCompleteMode("A7", CompleteMode::Manual));
        set(sim, "Go", true);
        set(sim, "Done", true);
        CHECK(scan(sim) == "A5>A7 A5->A7 E");
        CHECK(scan(sim) == "A7>A4 A7->A4 E");
        CHECK_FALSE(sim.complete("A7"));
    }
}

TEST_CASE("Simulator: the family transition comes first and never waits", "[simulation]")
{
    Model model = onlyVisible({"A1", "F1", "D1", "A2"}, "A1");
    for (const char* name : {"Start", "Emergency", "Overload", "Stop"})
        addVariable(model, name);
    condition(model, "A1->F1", "Start");
    condition(model, "F->D1", "Emergency");
    condition(model, "F1->D1", "Overload"); // negated by default: ignores Complete
    condition(model, "F1->A2", "Stop");
    Simulator sim(model);
    REQUIRE(sim.setCompleteMode("F1", CompleteMode::Manual));
    set(sim, "Start", true);
    CHECK(scan(sim) == "A1>F1 A1->F1 E");
    CHECK(scan(sim) == "F1>F1 - .");

    SECTION("family before the state's own transitions")
    {
        set(sim, "Overload", true);
        set(sim, "Emergency", true);
        set(sim, "Stop", true);
        CHECK(scan(sim) == "F1>D1 F->D1 E");
    }
    SECTION("the state's own negated transition when the family one is FALSE")
    {
        set(sim, "Overload", true);
        CHECK(scan(sim) == "F1>D1 F1->D1 E");
    }
    SECTION("a not negated transition out of the macro-step waits")
    {
        set(sim, "Stop", true);
        CHECK(scan(sim) == "F1>F1 - .");
        REQUIRE(sim.setComplete("F1", true));
        CHECK(scan(sim) == "F1>A2 F1->A2 E");
    }
}

TEST_CASE("Simulator: priorities decide among transitions that hold", "[simulation]")
{
    Model model = onlyVisible({"A1", "F4", "F2", "F1", "F5"}, "A1");
    for (const char* id : {"A1->F4", "A1->F2", "A1->F1", "A1->F5"})
        condition(model, id, "TRUE");
    REQUIRE(model.setPriority("A1->F1", 1));
    REQUIRE(model.setTransitionHidden("A1->F4", true));
    Simulator sim(model);

    const std::vector<TransitionExplanation> explanations = sim.explain();
    REQUIRE(explanations.size() == 3); // the hidden one does not exist for the simulator
    CHECK(explanations[0].transitionId == "A1->F1");
    CHECK(explanations[0].status == TransitionStatus::Fires);
    CHECK(explanations[1].transitionId == "A1->F2");
    CHECK(explanations[1].status == TransitionStatus::PreemptedByHigherPriority);
    CHECK(explanations[1].preemptedBy == "A1->F1");
    REQUIRE(explanations[1].reasons.size() == 1);
    CHECK(explanations[1].reasons[0].kind == ExplanationReason::Kind::FiresFirst);
    CHECK(explanations[1].reasons[0].subject == "A1->F1");
    CHECK(texts(explanations[1].reasons) == std::vector<std::string>{"A1->F1 fires first"});
    CHECK(explanations[2].transitionId == "A1->F5");
    CHECK(explanations[2].status == TransitionStatus::PreemptedByHigherPriority);
    CHECK(scan(sim) == "A1>F1 A1->F1 E");
}

TEST_CASE("Simulator: tokens remember pulses while Complete is FALSE", "[simulation]")
{
    // F1's effective transitions: F1->A2 (priority 1, NOT Stop, token: NC) and
    // F1->F3 (priority 2, EmptyMachine, token: NO).
    Model model = onlyVisible({"A1", "F1", "A2", "F3"}, "A1");
    addVariable(model, "Start");
    addVariable(model, "Stop", IecType::Bool, "TRUE"); // normally closed push button
    addVariable(model, "EmptyMachine");
    condition(model, "A1->F1", "Start");
    condition(model, "F1->A2", "NOT Stop");
    condition(model, "F1->F3", "EmptyMachine");
    REQUIRE(model.setTokens("F1->A2", {"Stop"}));
    REQUIRE(model.setTokens("F1->F3", {"EmptyMachine"}));
    Simulator sim(model);
    REQUIRE(sim.tokenNames() == std::vector<std::string>{"Stop_F1_1_MEM", "EmptyMachine_F1_2_MEM"});
    REQUIRE(sim.setCompleteMode("F1", CompleteMode::Manual));
    set(sim, "Start", true);

    SECTION("NC pulse in the entry scan: tokens are reset in the entry block, set after END_CASE")
    {
        CHECK(scan(sim) == "A1>F1 A1->F1 E 00");
        set(sim, "Stop", false);
        // Entry block: Stop_F1_1_MEM := FALSE; no transition; after END_CASE: State = 8 AND NOT Stop.
        CHECK(scan(sim) == "F1>F1 - . 10");
        set(sim, "Stop", true);
        CHECK(scan(sim) == "F1>F1 - . 10"); // remembered while Complete is FALSE
        REQUIRE(sim.setComplete("F1", true));
        // ELSIF Stop_F1_1_MEM AND F1.Complete; the token keeps its value until F1 is entered again.
        CHECK(scan(sim) == "F1>A2 F1->A2 E 10");
        CHECK(sim.token("stop_f1_1_mem"));
    }
    SECTION("a pulse in the scan that enters the source is captured, then reset by the entry block")
    {
        set(sim, "EmptyMachine", true);
        CHECK(scan(sim) == "A1>F1 A1->F1 E 01");
        set(sim, "EmptyMachine", false);
        CHECK(scan(sim) == "F1>F1 - . 00");
    }
    SECTION("NO pulse while Complete is FALSE fires once Complete")
    {
        CHECK(scan(sim) == "A1>F1 A1->F1 E 00");
        CHECK(scan(sim) == "F1>F1 - . 00");
        set(sim, "EmptyMachine", true);
        CHECK(scan(sim) == "F1>F1 - . 01");
        set(sim, "EmptyMachine", false);
        CHECK(scan(sim) == "F1>F1 - . 01");
        REQUIRE(sim.setComplete("F1", true));
        CHECK(scan(sim) == "F1>F3 F1->F3 E 01");
    }
}

TEST_CASE("Simulator: hidden steps and transitions do not exist", "[simulation]")
{
    Model model = onlyVisible({"A1", "F4", "F2"}, "A1");
    REQUIRE(model.setStepType("F2", StepType::Simple));
    addVariable(model, "X");
    condition(model, "A1->F4", "TRUE");
    condition(model, "A1->F2", "X");
    condition(model, "A1->F1", "TRUE"); // F1 is hidden
    REQUIRE(model.setTransitionHidden("A1->F4", true));
    Simulator sim(model);
    CHECK(sim.nestedSteps() == std::vector<std::string>{"F4"}); // visible, though only a hidden transition leads there
    CHECK(scan(sim) == "A1>A1 - E");
    set(sim, "X", true);
    CHECK(scan(sim) == "A1>F2 A1->F2 E");

    SECTION("a hidden initial step: State names no branch, nothing ever happens")
    {
        REQUIRE(model.setInitialStep("A6")); // hidden
        Simulator hiddenStart(model);
        CHECK(hiddenStart.activeStepId().empty());
        CHECK(hiddenStart.activeStepNumber() == 6);
        const ScanRecord record = hiddenStart.step();
        CHECK(record.stepBefore.empty());
        CHECK(record.stepAfter.empty());
        CHECK(record.fired.empty());
        CHECK(hiddenStart.explain().empty());
    }
}

TEST_CASE("Simulator: unusable conditions are FALSE and explained", "[simulation]")
{
    Model model = onlyVisible({"A1", "F2", "F1"}, "A1");
    addVariable(model, "Speed", IecType::Int, "3");
    addVariable(model, "Start");
    condition(model, "A1->F2", "Start AND");
    condition(model, "A1->F1", "Start OR Speed > 10");
    Simulator sim(model);
    std::vector<TransitionExplanation> explanations = sim.explain();
    REQUIRE(explanations.size() == 2);
    CHECK(explanations[0].status == TransitionStatus::Unusable);
    REQUIRE(explanations[0].reasons.size() == 1);
    const ExplanationReason& unusable = explanations[0].reasons[0];
    CHECK(unusable.kind == ExplanationReason::Kind::Unusable);
    CHECK_THAT(toText(unusable), Catch::StartsWith("syntax error in the condition of A1->F2: "));
    // What the checks report for the same condition, so the editor words both alike.
    CHECK(unusable.code == "GG201");
    REQUIRE(unusable.arguments.size() == 7);
    CHECK(unusable.arguments[0] == "A1->F2");
    CHECK(unusable.message == "syntax error in the condition of A1->F2: " + unusable.arguments[2]);
    CHECK(unusable.arguments[3] == "operand-after");
    CHECK(unusable.arguments[5] == "AND");
    CHECK(explanations[1].status == TransitionStatus::ConditionFalse);
    CHECK(texts(explanations[1].reasons) == std::vector<std::string>{"Start = FALSE", "Speed > 10 is FALSE (Speed = 3)"});
    CHECK(scan(sim) == "A1>A1 - E");
    set(sim, "Speed", std::int64_t{11});
    explanations = sim.explain();
    CHECK(explanations[1].status == TransitionStatus::Fires);
    CHECK(scan(sim) == "A1>F1 A1->F1 E");
}

TEST_CASE("Simulator: explain names the operands that make a condition FALSE", "[simulation]")
{
    Model model = onlyVisible({"A1", "F1", "A2"}, "A1");
    addVariable(model, "Start");
    addVariable(model, "Auto", IecType::Bool, "TRUE");
    addVariable(model, "Door");
    addVariable(model, "Stop", IecType::Bool, "TRUE");
    addVariable(model, "Level", IecType::Real, "2.5");
    condition(model, "A1->F1", "Start AND Auto AND NOT (Door OR Level < 3.0)");
    condition(model, "F1->A2", "NOT Stop");
    REQUIRE(model.setTokens("F1->A2", {"Stop"}));
    Simulator sim(model);
    std::vector<TransitionExplanation> explanations = sim.explain();
    REQUIRE(explanations.size() == 1);
    // AND: only its FALSE operands; NOT (OR) is FALSE because an operand of the OR is TRUE.
    CHECK(texts(explanations[0].reasons) == std::vector<std::string>{"Start = FALSE", "Level < 3.0 is TRUE (Level = 2.5)"});

    set(sim, "Start", true);
    set(sim, "Level", 4.0);
    CHECK(scan(sim) == "A1>F1 A1->F1 E 0");
    REQUIRE(sim.setCompleteMode("F1", CompleteMode::Manual));
    set(sim, "Stop", false);
    // Predicts the entry scan: the token reads FALSE there (the entry block resets it).
    explanations = sim.explain();
    REQUIRE(explanations.size() == 1);
    CHECK(explanations[0].status == TransitionStatus::ConditionFalse);
    CHECK(texts(explanations[0].reasons)
          == std::vector<std::string>{"Stop_F1_1_MEM = FALSE (token of NOT Stop)", "F1.Complete = FALSE"});
    CHECK(scan(sim) == "F1>F1 - . 1");
    explanations = sim.explain();
    CHECK(explanations[0].status == TransitionStatus::WaitingForComplete);
    CHECK(texts(explanations[0].reasons) == std::vector<std::string>{"F1.Complete = FALSE"});
    REQUIRE(sim.setComplete("F1", true));
    CHECK(sim.explain()[0].status == TransitionStatus::Fires);
}

TEST_CASE("Simulator: explanation reasons are data the UI can word", "[simulation]")
{
    using Kind = ExplanationReason::Kind;
    Model model = onlyVisible({"A1", "F1", "A2", "F2", "F3"}, "A1");
    addVariable(model, "Start");
    addVariable(model, "Stop", IecType::Bool, "TRUE");
    addVariable(model, "Speed", IecType::Int, "3");
    addVariable(model, "Limit", IecType::Int, "10");
    condition(model, "A1->F1", "Start AND FALSE AND Speed + Speed > Limit");
    condition(model, "A1->F2", "Speed = 7");
    condition(model, "F1->A2", "NOT Stop");
    condition(model, "F1->F3", "Nothing");
    REQUIRE(model.setTokens("F1->A2", {"Stop"}));
    Simulator sim(model);

    std::vector<TransitionExplanation> explanations = sim.explain();
    REQUIRE(explanations.size() == 2);
    REQUIRE(explanations[1].transitionId == "A1->F1");
    const std::vector<ExplanationReason>& reasons = explanations[1].reasons;
    REQUIRE(reasons.size() == 3);
    CHECK(reasons[0].kind == Kind::Reading);
    CHECK(reasons[0].readings == std::vector<ConditionReading>{{"Start", "FALSE", ""}});
    CHECK(reasons[1].kind == Kind::Literal);
    CHECK(reasons[1].value == "FALSE");
    CHECK(reasons[2].kind == Kind::Expression);
    CHECK(reasons[2].subject == "Speed + Speed > Limit");
    CHECK(reasons[2].value == "FALSE");
    // Each operand once, in the order the expression reads them.
    CHECK(reasons[2].readings == std::vector<ConditionReading>{{"Speed", "3", ""}, {"Limit", "10", ""}});
    CHECK(texts(reasons)
          == std::vector<std::string>{"Start = FALSE", "FALSE", "Speed + Speed > Limit is FALSE (Speed = 3, Limit = 10)"});

    REQUIRE(model.setInitialStep("F1"));
    Simulator fromF1(model);
    REQUIRE(fromF1.setCompleteMode("F1", CompleteMode::Manual));
    set(fromF1, "Stop", false);
    CHECK(scan(fromF1) == "F1>F1 - . 1");
    explanations = fromF1.explain();
    REQUIRE(explanations.size() == 2);
    // The token reads TRUE: only Complete holds the transition back.
    CHECK(explanations[0].status == TransitionStatus::WaitingForComplete);
    REQUIRE(explanations[0].reasons.size() == 1);
    CHECK(explanations[0].reasons[0].kind == Kind::CompleteFalse);
    CHECK(explanations[0].reasons[0].subject == "F1");
    // An undeclared variable: the error as the checks give it (GG203).
    CHECK(explanations[1].status == TransitionStatus::Unusable);
    REQUIRE(explanations[1].reasons.size() == 1);
    const ExplanationReason& unusable = explanations[1].reasons[0];
    CHECK(unusable.kind == Kind::Unusable);
    CHECK(unusable.code == "GG203");
    CHECK(unusable.arguments == std::vector<std::string>{"F1->F3", "Nothing", "'Nothing' is not a declared variable"});
    CHECK(toText(unusable) == "in the condition of F1->F3: 'Nothing' is not a declared variable");
    const std::vector<Diagnostic> diagnostics = checkModel(model);
    const auto checked = std::find_if(diagnostics.begin(), diagnostics.end(),
                                      [](const Diagnostic& d) { return d.element == "F1->F3" && d.code == "GG203"; });
    REQUIRE(checked != diagnostics.end());
    CHECK(checked->arguments == unusable.arguments);
    CHECK(checked->message == unusable.message);
}

TEST_CASE("Explanation reasons: English text of each kind", "[simulation]")
{
    using Kind = ExplanationReason::Kind;
    const ConditionReading token{"Stop_F1_1_MEM", "FALSE", "NOT Stop"};
    CHECK(token.isToken());
    CHECK(toText(token) == "Stop_F1_1_MEM = FALSE (token of NOT Stop)");
    CHECK(toText(ConditionReading{"Level", "2.5", ""}) == "Level = 2.5");

    ExplanationReason reason;
    reason.kind = Kind::Expression;
    reason.subject = "Level < 3.0";
    reason.value = "TRUE";
    CHECK(toText(reason) == "Level < 3.0 is TRUE"); // a constant comparison reads nothing
    reason.readings = {{"Level", "2.5", ""}, token};
    CHECK(toText(reason) == "Level < 3.0 is TRUE (Level = 2.5, Stop_F1_1_MEM = FALSE (token of NOT Stop))");

    ExplanationReason complete;
    complete.kind = Kind::CompleteFalse;
    complete.subject = "F1";
    CHECK(toText(complete) == "F1.Complete = FALSE");
    ExplanationReason first;
    first.kind = Kind::FiresFirst;
    first.subject = "F->D1";
    CHECK(toText(first) == "F->D1 fires first");
    ExplanationReason unusable;
    unusable.kind = Kind::Unusable;
    CHECK(toText(unusable) == "the condition cannot be used: it is FALSE");
}

TEST_CASE("Simulator: inputs are checked against their IEC type", "[simulation]")
{
    Model model;
    addVariable(model, "Flag");
    addVariable(model, "Small", IecType::Sint, "-5");
    addVariable(model, "Count", IecType::Uint);
    addVariable(model, "Level", IecType::Real, "1.5");
    Simulator sim(model);
    CHECK(sim.variable("small") == cond::Value{std::int64_t{-5}});
    CHECK(sim.variable("Level") == cond::Value{1.5});
    CHECK(sim.variable("Count") == cond::Value{std::int64_t{0}});
    CHECK(sim.setVariable("SMALL", std::int64_t{127}));
    const Status tooBig = sim.setVariable("Small", std::int64_t{128});
    CHECK_FALSE(tooBig);
    CHECK_THAT(tooBig.message, Catch::Contains("out of range for SINT"));
    CHECK(sim.variable("Small") == cond::Value{std::int64_t{127}});
    CHECK_FALSE(sim.setVariable("Count", std::int64_t{-1}));
    CHECK_FALSE(sim.setVariable("Flag", std::int64_t{1}));
    CHECK_FALSE(sim.setVariable("Nope", true));
    CHECK(sim.setVariable("Level", std::int64_t{2})); // an integer is a fine REAL
    CHECK(sim.variable("Level") == cond::Value{2.0});
    CHECK(sim.setVariableText("flag", "true"));
    CHECK(sim.variable("Flag") == cond::Value{true});
    CHECK_FALSE(sim.setVariableText("Count", "abc"));
    CHECK_FALSE(sim.setCompleteMode("A1", CompleteMode::Manual)); // simple step
    CHECK_FALSE(sim.setComplete("Z9", true));

    const ScanRecord record = sim.step();
    REQUIRE(record.changedInputs.size() == 3); // changed since reset (Count did not), in declaration order
    CHECK(record.changedInputs[0].variable == "Flag");
    CHECK(record.changedInputs[1].variable == "Small");
    CHECK(record.changedInputs[2].variable == "Level");
    set(sim, "Flag", false);
    set(sim, "Flag", true); // back to the previous scan's value: no change
    CHECK(sim.step().changedInputs.empty());
}

TEST_CASE("Simulator: compiled conditions agree with cond::evaluate", "[simulation]")
{
    // Each condition guards A6->A1: the scan fires it exactly when cond::evaluate says TRUE.
    const std::vector<std::string> conditions = {
        "Count / (Count + 11) = 0 AND Count MOD (Count + 11) = Count", // divisors never 0 here
        "Count MOD -1 = 0",
        "-Count < 1",
        "Level * 2 > Count + 0.5",
        "Count / 3 = -2",
        "Count MOD 3 = -1",
        "Big + 1 < Big",
        "-9223372036854775808 < Big",
        "Level / (Level - Level) > 0.0 OR Level / (Level - Level) <> Level / (Level - Level)", // INF, NaN
        "Count MOD -4 = Count - (Count / -4) * -4",
        "(A XOR B) = (Count > 0)",
        "NOT (NOT A) AND B OR Count >= 5",
        "A = FALSE",
        "2 * 3 + Count = 10 - 1",
        "1.5 + 1 = 2.5 AND Count <> 4",
    };
    std::mt19937 random(7);
    for (const std::string& text : conditions) {
        Model model = onlyVisible({"A6", "A1"}, "A6");
        addVariable(model, "A");
        addVariable(model, "B");
        addVariable(model, "Count", IecType::Dint);
        addVariable(model, "Big", IecType::Lint, "9223372036854775807");
        addVariable(model, "Level", IecType::Lreal);
        condition(model, "A6->A1", text.c_str());
        const cond::ParseResult parsed = cond::parse(text);
        REQUIRE(parsed.ok());
        Simulator sim(model);
        const GemmaStep* a6 = sim.program().step("A6");
        REQUIRE(a6);
        REQUIRE(a6->transitions.size() == 1);
        INFO(text);
        REQUIRE(a6->transitions.front().conditionUsable);
        for (int round = 0; round < 40; ++round) {
            sim.reset();
            const bool a = random() % 2;
            const bool b = random() % 2;
            const std::int64_t count = static_cast<std::int64_t>(random() % 21) - 10;
            const double level = static_cast<double>(random() % 13) / 2.0 - 3.0;
            set(sim, "A", a);
            set(sim, "B", b);
            set(sim, "Count", count);
            set(sim, "Level", level);
            const cond::Value expected = cond::evaluate(parsed.expression, [&](int node) -> cond::Value {
                const std::string name = toUpperAscii(parsed.expression.at(node).text);
                if (name == "A")
                    return a;
                if (name == "B")
                    return b;
                if (name == "COUNT")
                    return count;
                if (name == "BIG")
                    return std::int64_t{9223372036854775807};
                return level;
            });
            INFO(text << " with A=" << a << " B=" << b << " Count=" << count << " Level=" << level);
            CHECK(sim.step().fired.empty() != cond::isTrue(expected));
        }
    }
}

TEST_CASE("Simulator: trace, callback and copies", "[simulation]")
{
    const Model model = factory::realisticModel();
    Simulator sim(model);
    std::vector<std::int64_t> called;
    sim.setScanCallback([&](const ScanRecord& record) { called.push_back(record.scan); });
    sim.setTraceEnabled(true);
    sim.run(3);
    CHECK(called == std::vector<std::int64_t>{1, 2, 3});
    REQUIRE(sim.trace().size() == 3);
    CHECK(sim.trace()[2].scan == 3);
    CHECK(sim.trace()[0].stepBefore == "A6");
    CHECK(sim.trace()[0].complete.size() == sim.nestedSteps().size());
    CHECK(sim.trace()[0].tokens.size() == sim.tokenNames().size());

    set(sim, "HomePosition", true);
    set(sim, "AirPressureOk", true);
    Simulator copy(sim);
    copy.setScanCallback({});
    CHECK(copy.step().fired == "A6->A1");
    CHECK(copy.lastFired() == "A6->A1");
    CHECK(sim.activeStepId() == "A6"); // the original did not move
    Simulator assigned = copy;
    CHECK(assigned.lastFired() == "A6->A1");
    // Copies share the compiled program: a copy outlives the simulator it came from.
    std::optional<Simulator> survivor;
    {
        Simulator original(copy);
        survivor.emplace(original);
    }
    CHECK(survivor->lastFired() == "A6->A1");
    CHECK(survivor->activeStepId() == "A1");
    survivor->run(2);
    CHECK(survivor->scanCount() == copy.scanCount() + 2);
    sim.reset();
    CHECK(sim.trace().empty());
    CHECK(sim.scanCount() == 0);
    CHECK(sim.variable("HomePosition") == cond::Value{false});
}

} // namespace test_simulator
