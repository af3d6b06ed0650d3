// Simulator::explainNested(): why each transition of a nested GRAFCET fires
// or not in the next scan, predicted as the engine runs it (spec
// grafcet-layer.md §4).

#include "core/formats/modelfiles.h"
#include "core/model/model.h"
#include "core/simulation/simulator.h"
#include "samplemodels.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace test_nestedexplanation {

using namespace core;

namespace {

using Kind = ExplanationReason::Kind;
using NS = NestedTransitionStatus;

// F1 is the initial step. Its GRAFCET: 1 --RE Start--> 2 (N Lamp) --5s/X2--> 3 (S Complete).
Model timedModel()
{
    Model model;
    REQUIRE(model.addVariable(samples::variable("Start", IecType::Bool, VariableKind::Input)));
    REQUIRE(model.addVariable(samples::variable("Stop", IecType::Bool, VariableKind::Input)));
    REQUIRE(model.addVariable(samples::variable("Lamp", IecType::Bool, VariableKind::Output)));
    REQUIRE(model.setInitialStep("F1"));
    REQUIRE(model.setCondition("F1->A2", "TRUE"));
    REQUIRE(model.setCondition("F->D1", "Stop"));
    REQUIRE(model.setTransitionHidden("F->D1", false));
    REQUIRE(model.addGrafcetStep("F1", {1, true, "", {}}));
    REQUIRE(model.addGrafcetStep("F1", {2, false, "", {{ActionTiming::Continuous, "N Lamp"}}}));
    REQUIRE(model.addGrafcetStep("F1", {3, false, "", {{ActionTiming::OnActivation, "S Complete"}}}));
    REQUIRE(model.addGrafcetTransition("F1", {1, {1}, {2}, "RE Start"}));
    REQUIRE(model.addGrafcetTransition("F1", {2, {2}, {3}, "5s/X2"}));
    return model;
}

// Receptivities that read variables, comparisons, X<n>, Complete, an edge
// and an undeclared name; a convergence of two steps.
Model readingModel()
{
    Model model;
    REQUIRE(model.addVariable(samples::variable("A", IecType::Bool, VariableKind::Input)));
    REQUIRE(model.addVariable(samples::variable("Speed", IecType::Int, VariableKind::Input)));
    REQUIRE(model.setInitialStep("F1"));
    REQUIRE(model.setCondition("F1->A2", "TRUE"));
    REQUIRE(model.addGrafcetStep("F1", {1, true, "", {}}));
    REQUIRE(model.addGrafcetStep("F1", {2, false, "", {}}));
    REQUIRE(model.addGrafcetStep("F1", {3, false, "", {}}));
    REQUIRE(model.addGrafcetTransition("F1", {1, {1}, {2}, "a AND Speed > 10"}));
    REQUIRE(model.addGrafcetTransition("F1", {2, {1}, {3}, "NOT X1 OR Complete"}));
    REQUIRE(model.addGrafcetTransition("F1", {3, {2, 3}, {1}, "TRUE"}));
    REQUIRE(model.addGrafcetTransition("F1", {4, {1}, {1}, "FE A"}));
    REQUIRE(model.addGrafcetTransition("F1", {5, {1}, {2}, "Missing"}));
    return model;
}

const NestedTransitionExplanation& transition(const NestedExplanation& explanation, int number)
{
    const auto found = std::find_if(explanation.transitions.begin(), explanation.transitions.end(),
                                    [number](const NestedTransitionExplanation& t) { return t.number == number; });
    REQUIRE(found != explanation.transitions.end());
    return *found;
}

std::vector<std::string> texts(const NestedTransitionExplanation& explanation)
{
    std::vector<std::string> result;
    for (const ExplanationReason& reason : explanation.reasons)
        result.push_back(toText(reason));
    return result;
}

// The situation one evolution leads to from `situation` when the
// explanation's Fires transitions fire (IEC 60848 rules 2-5).
std::vector<int> predictedSituation(const NestedExplanation& explanation)
{
    std::set<int> left;
    std::set<int> entered;
    for (const NestedTransitionExplanation& t : explanation.transitions) {
        if (t.status != NS::Fires)
            continue;
        left.insert(t.upstream.begin(), t.upstream.end());
        entered.insert(t.downstream.begin(), t.downstream.end());
    }
    std::set<int> next;
    for (int step : explanation.situation) {
        if (!left.count(step) || entered.count(step))
            next.insert(step);
    }
    next.insert(entered.begin(), entered.end());
    return {next.begin(), next.end()};
}

} // namespace

TEST_CASE("Nested explanation: the entry scan re-initialises, edges, upstream steps", "[simulation][nested-explanation]")
{
    Simulator simulator(timedModel());
    REQUIRE(simulator.activeNestedSteps("F1").empty()); // power-on: no step active yet

    NestedExplanation next = simulator.explainNested("F1");
    CHECK(next.stepId == "F1");
    CHECK(next.called);
    CHECK(next.initialization); // Entry: the Initialization call comes first
    CHECK_FALSE(next.untilStable);
    CHECK(next.situation == std::vector<int>{1});
    REQUIRE(next.transitions.size() == 2);
    const NestedTransitionExplanation& edge = transition(next, 1);
    CHECK(edge.status == NS::ReceptivityFalse);
    REQUIRE(edge.reasons.size() == 1);
    CHECK(edge.reasons[0].kind == Kind::NoRisingEdge);
    CHECK(edge.reasons[0].subject == "Start");
    CHECK(edge.reasons[0].value == "FALSE");
    CHECK(edge.reasons[0].previous == "FALSE");
    CHECK(texts(edge) == std::vector<std::string>{
                             "no rising edge of Start this scan (Start = FALSE, at the end of the previous scan FALSE)"});
    const NestedTransitionExplanation& timed = transition(next, 2);
    CHECK(timed.status == NS::UpstreamInactive);
    REQUIRE(timed.reasons.size() == 1);
    CHECK(timed.reasons[0].kind == Kind::StepsInactive);
    CHECK(timed.reasons[0].steps == std::vector<int>{2});
    CHECK(texts(timed) == std::vector<std::string>{"step 2 is not active"});

    // Start TRUE before the entry scan: the edge is there (Start_PREV is FALSE).
    REQUIRE(simulator.setVariable("Start", true));
    next = simulator.explainNested("F1");
    CHECK(transition(next, 1).status == NS::Fires);
    CHECK(transition(next, 1).reasons.empty());
    CHECK(simulator.activeNestedSteps("F1").empty()); // explaining changes nothing
    simulator.step();
    CHECK(simulator.activeNestedSteps("F1") == std::vector<int>{2});

    // Start still TRUE in the next scan: no edge any more.
    next = simulator.explainNested("F1");
    CHECK_FALSE(next.initialization);
    CHECK(next.situation == std::vector<int>{2});
    CHECK(transition(next, 1).status == NS::UpstreamInactive);
}

TEST_CASE("Nested explanation: a time-dependent receptivity gives elapsed and duration", "[simulation][nested-explanation]")
{
    Simulator simulator(timedModel());
    REQUIRE(simulator.setVariable("Start", true));
    simulator.step(); // scan 1: 1 -> 2; step 2's TON called with IN := FALSE
    // Scan 2 starts the TON: ET 0.
    NestedExplanation next = simulator.explainNested("F1");
    const NestedTransitionExplanation& first = transition(next, 2);
    CHECK(first.status == NS::ReceptivityFalse);
    REQUIRE(first.reasons.size() == 1);
    CHECK(first.reasons[0].kind == Kind::TimerNotElapsed);
    CHECK(first.reasons[0].subject == "5s/X2");
    CHECK(first.reasons[0].steps == std::vector<int>{2});
    CHECK(first.reasons[0].elapsedMs == 0);
    CHECK(first.reasons[0].durationMs == 5000);
    simulator.step();
    next = simulator.explainNested("F1");
    CHECK(transition(next, 2).reasons.at(0).elapsedMs == 20);
    CHECK(texts(transition(next, 2)) == std::vector<std::string>{"5s/X2 is FALSE: step 2 active for 20 ms of 5000 ms"});

    // The TON reaches 5 s in the 251st scan after scan 1: scan 252.
    simulator.run(249); // 251 scans run
    next = simulator.explainNested("F1");
    CHECK(transition(next, 2).status == NS::Fires);
    simulator.step();
    CHECK(simulator.activeNestedSteps("F1") == std::vector<int>{3});
    CHECK(simulator.scanCount() == 252);
}

TEST_CASE("Nested explanation: a FALSE receptivity names its operands", "[simulation][nested-explanation]")
{
    Simulator simulator(readingModel());
    simulator.step(); // entry scan: the GRAFCET is in step 1
    REQUIRE(simulator.activeNestedSteps("F1") == std::vector<int>{1});
    REQUIRE(simulator.setVariable("Speed", std::int64_t{3}));

    NestedExplanation next = simulator.explainNested("F1");
    // AND FALSE: both FALSE operands, with the declared spelling of A.
    const NestedTransitionExplanation& both = transition(next, 1);
    CHECK(both.status == NS::ReceptivityFalse);
    CHECK(texts(both) == std::vector<std::string>{"A = FALSE", "Speed > 10 is FALSE (Speed = 3)"});
    REQUIRE(both.reasons.size() == 2);
    CHECK(both.reasons[0].kind == Kind::Reading);
    CHECK(both.reasons[1].kind == Kind::Expression);
    CHECK(both.reasons[1].readings == std::vector<ConditionReading>{{"Speed", "3", {}}});
    REQUIRE(simulator.setVariable("A", true));
    next = simulator.explainNested("F1");
    CHECK(texts(transition(next, 1)) == std::vector<std::string>{"Speed > 10 is FALSE (Speed = 3)"});

    // X1 and Complete read as the FB reads them.
    const NestedTransitionExplanation& activity = transition(next, 2);
    CHECK(activity.status == NS::ReceptivityFalse);
    CHECK(texts(activity) == std::vector<std::string>{"X1 = TRUE", "Complete = FALSE"});

    // A convergence names every upstream step that is not active.
    CHECK(texts(transition(next, 3)) == std::vector<std::string>{"steps 2, 3 are not active"});

    // A falling edge: A is TRUE now.
    const NestedTransitionExplanation& falling = transition(next, 4);
    REQUIRE(falling.reasons.size() == 1);
    CHECK(falling.reasons[0].kind == Kind::NoFallingEdge);
    CHECK(falling.reasons[0].value == "TRUE");
    CHECK(falling.reasons[0].previous == "FALSE");

    // An undeclared name: the receptivity is unusable, with the checks' problem.
    const NestedTransitionExplanation& unusable = transition(next, 5);
    CHECK(unusable.status == NS::Unusable);
    REQUIRE_FALSE(unusable.reasons.empty());
    CHECK(unusable.reasons[0].kind == Kind::Unusable);
    CHECK_FALSE(unusable.reasons[0].code.empty());
    CHECK(toText(unusable.reasons[0]).find("Missing") != std::string::npos);

    REQUIRE(simulator.setVariable("Speed", std::int64_t{11}));
    CHECK(transition(simulator.explainNested("F1"), 1).status == NS::Fires);
}

TEST_CASE("Nested explanation: a step that is not active does not call its GRAFCET", "[simulation][nested-explanation]")
{
    const auto loaded = loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    REQUIRE(loaded.model);
    Simulator simulator(*loaded.model);
    REQUIRE(simulator.activeStepId() != "F1");
    const NestedExplanation next = simulator.explainNested("F1");
    CHECK(next.stepId == "F1");
    CHECK_FALSE(next.called);
    CHECK_FALSE(next.initialization);
    REQUIRE_FALSE(next.transitions.empty());
    for (const NestedTransitionExplanation& t : next.transitions) {
        CHECK(t.status == NS::NotCalled);
        REQUIRE(t.reasons.size() == 1);
        CHECK(t.reasons[0].kind == Kind::NotCalled);
        CHECK(toText(t.reasons[0]) == "F1 is not the active step: its GRAFCET does not evolve in the next scan");
    }
    // A step without GRAFCET, an unknown one: nothing to explain.
    CHECK(simulator.explainNested("A1").transitions.empty());
    CHECK(simulator.explainNested("A1").stepId.empty());
    CHECK(simulator.explainNested("Z9").transitions.empty());
}

TEST_CASE("Nested explanation: until stable explains the first evolution", "[simulation][nested-explanation]")
{
    Model model;
    REQUIRE(model.addVariable(samples::variable("A", IecType::Bool, VariableKind::Input)));
    REQUIRE(model.setInitialStep("F1"));
    REQUIRE(model.addGrafcetStep("F1", {1, true, "", {}}));
    REQUIRE(model.addGrafcetStep("F1", {2, false, "", {}}));
    REQUIRE(model.addGrafcetStep("F1", {3, false, "", {}}));
    REQUIRE(model.addGrafcetTransition("F1", {1, {1}, {2}, "RE A"}));
    REQUIRE(model.addGrafcetTransition("F1", {2, {2}, {3}, "TRUE"}));
    model.setEvolutionRule(EvolutionRule::UntilStable);
    Simulator simulator(model);
    REQUIRE(simulator.setVariable("A", true));
    const NestedExplanation next = simulator.explainNested("F1");
    CHECK(next.untilStable);
    CHECK(next.situation == std::vector<int>{1});
    CHECK(transition(next, 1).status == NS::Fires); // the edge, live in the first evolution
    CHECK(transition(next, 2).status == NS::UpstreamInactive); // fires in the second evolution only
    simulator.step();
    CHECK(simulator.activeNestedSteps("F1") == std::vector<int>{3});
}

TEST_CASE("Explanations: the predictions agree with the scan on the drilling cell", "[simulation][nested-explanation][example]")
{
    const auto loaded = loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    REQUIRE(loaded.model);
    REQUIRE(loaded.model->settings().evolution == EvolutionRule::OneEvolutionPerScan);
    Simulator simulator(*loaded.model);
    std::vector<std::size_t> inputs;
    for (std::size_t i = 0; i < simulator.variableNames().size(); ++i) {
        if (simulator.variableKind(i) == VariableKind::Input && simulator.variableType(i) == IecType::Bool)
            inputs.push_back(i);
    }
    REQUIRE_FALSE(inputs.empty());
    std::mt19937 random(16);
    int explained = 0;
    int entries = 0;
    int firings = 0;
    for (int scan = 0; scan < 20000; ++scan) {
        if (random() % 4 == 0) {
            const std::size_t input = inputs[random() % inputs.size()];
            REQUIRE(simulator.setVariableAt(input, !cond::isTrue(simulator.variableValue(input))));
        }
        const std::string step = simulator.activeStepId();
        // The GEMMA transition explain() says fires is the one the scan fires.
        std::string firing;
        for (const TransitionExplanation& e : simulator.explain()) {
            if (e.status == TransitionStatus::Fires)
                firing = e.transitionId;
        }
        if (!simulator.hasGrafcet(step)) {
            CHECK(simulator.step().fired == firing);
            continue;
        }
        const NestedExplanation next = simulator.explainNested(step);
        REQUIRE(next.called);
        const std::vector<int> predicted = predictedSituation(next);
        const ScanRecord record = simulator.step();
        INFO("scan " << simulator.scanCount() << ", " << step);
        CHECK(record.fired == firing);
        CHECK(simulator.activeNestedSteps(step) == predicted);
        ++explained;
        entries += next.initialization ? 1 : 0;
        firings += predicted != next.situation ? 1 : 0;
    }
    CHECK(explained > 1000);
    CHECK(entries > 5);
    CHECK(firings > 20);
}

TEST_CASE("GEMMA explanation of a step with a GRAFCET: its Complete and its stored actions", "[simulation][nested-explanation]")
{
    // F1 -> A2 waits for the GRAFCET's Complete, set on entering step 3.
    Simulator simulator(timedModel());
    std::vector<TransitionExplanation> next = simulator.explain();
    auto find = [&](const std::string& id) -> const TransitionExplanation& {
        const auto found = std::find_if(next.begin(), next.end(),
                                        [&](const TransitionExplanation& e) { return e.transitionId == id; });
        REQUIRE(found != next.end());
        return *found;
    };
    CHECK(find("F1->A2").status == TransitionStatus::WaitingForComplete);
    REQUIRE(simulator.setVariable("Start", true));
    simulator.run(251); // 1 -> 2 in scan 1; 5s/X2 holds in scan 252
    next = simulator.explain();
    CHECK(find("F1->A2").status == TransitionStatus::Fires); // step 3 sets Complete in that very call
    CHECK(simulator.step().fired == "F1->A2");

    // F -> D1 reads Alarm, which the initial step's on-activation action sets.
    Model model;
    Variable alarm{"Alarm", IecType::Bool, "", ""};
    alarm.kind = VariableKind::Internal;
    REQUIRE(model.addVariable(alarm));
    REQUIRE(model.setInitialStep("F1"));
    REQUIRE(model.setCondition("F1->A2", "TRUE"));
    REQUIRE(model.setCondition("F->D1", "Alarm"));
    REQUIRE(model.setTransitionHidden("F->D1", false));
    REQUIRE(model.addGrafcetStep("F1", {1, true, "", {{ActionTiming::OnActivation, "S Alarm"}}}));
    REQUIRE(model.addGrafcetStep("F1", {2, false, "", {{ActionTiming::OnActivation, "S Complete"}}}));
    REQUIRE(model.addGrafcetTransition("F1", {1, {1}, {2}, "FALSE"}));
    Simulator alarmed(model);
    next = alarmed.explain();
    CHECK(find("F->D1").status == TransitionStatus::Fires);
    CHECK(alarmed.variable("Alarm") == cond::Value{false}); // explaining changes nothing
    CHECK(alarmed.step().fired == "F->D1");
}

} // namespace test_nestedexplanation
