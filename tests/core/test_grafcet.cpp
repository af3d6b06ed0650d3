#include "core/model/grafcet.h"
#include "core/model/grafcetadjacency.h"

#include <catch2/catch.hpp>

#include <random>
#include <string>
#include <vector>

namespace test_grafcet {

using namespace core;

namespace {

GrafcetStep makeStep(int number, bool initial = false)
{
    GrafcetStep step;
    step.number = number;
    step.initial = initial;
    return step;
}

GrafcetTransition makeTransition(int number, std::vector<int> upstream, std::vector<int> downstream,
                                 std::string receptivity = "TRUE")
{
    GrafcetTransition transition;
    transition.number = number;
    transition.upstream = std::move(upstream);
    transition.downstream = std::move(downstream);
    transition.receptivity = std::move(receptivity);
    return transition;
}

// 1 -> T1 -> 2 -> T2 -> (3 || 4) -> T3 -> 1
Grafcet parallelLoop()
{
    Grafcet g;
    for (int n = 1; n <= 4; ++n)
        REQUIRE(g.addStep(makeStep(n, n == 1)));
    REQUIRE(g.addTransition(makeTransition(1, {1}, {2}, "Start")));
    REQUIRE(g.addTransition(makeTransition(2, {2}, {3, 4}, "5s/X2")));
    REQUIRE(g.addTransition(makeTransition(3, {3, 4}, {1}, "X3 AND X4 AND Done")));
    return g;
}

std::vector<int> numbers(const std::vector<const GrafcetTransition*>& transitions)
{
    std::vector<int> result;
    for (const GrafcetTransition* t : transitions)
        result.push_back(t->number);
    return result;
}

} // namespace

TEST_CASE("A GRAFCET keeps its steps and transitions and answers queries", "[grafcet]")
{
    const Grafcet g = parallelLoop();
    CHECK(g.steps().size() == 4);
    CHECK(g.initialSteps() == std::vector<int>{1});
    CHECK(numbers(g.transitionsFrom(2)) == std::vector<int>{2});
    CHECK(numbers(g.transitionsTo(1)) == std::vector<int>{3});
    CHECK(numbers(g.transitionsFrom(4)) == std::vector<int>{3});
    CHECK(g.nextStepNumber() == 5);
    CHECK(g.nextTransitionNumber() == 4);
    CHECK(g.invariantViolations().empty());
    CHECK(Grafcet().nextStepNumber() == 1);
}

TEST_CASE("Adding steps and transitions refuses what breaks the invariants", "[grafcet]")
{
    Grafcet g = parallelLoop();
    const Grafcet before = g;

    Status status = g.addStep(makeStep(2));
    CHECK_FALSE(status);
    CHECK(status.code == "duplicate-step");
    CHECK(g.addStep(makeStep(0)).code == "invalid-number");
    CHECK(g.addTransition(makeTransition(1, {1}, {2})).code == "duplicate-transition");
    CHECK(g.addTransition(makeTransition(9, {}, {2})).code == "empty-upstream");
    CHECK(g.addTransition(makeTransition(9, {1}, {})).code == "empty-downstream");
    status = g.addTransition(makeTransition(9, {1}, {7}));
    CHECK(status.code == "unknown-step");
    CHECK(status.message == "the GRAFCET has no step 7");
    CHECK(g.addTransition(makeTransition(9, {1, 1}, {2})).code == "repeated-step");
    CHECK(g.addTransition(makeTransition(-1, {1}, {2})).code == "invalid-number");
    CHECK(g.setUpstream(1, {}).code == "empty-upstream");
    CHECK(g.setDownstream(1, {8}).code == "unknown-step");
    CHECK(g.setReceptivity(42, "A").code == "unknown-transition");
    CHECK(g.sameContent(before));

    REQUIRE(g.addStep(makeStep(10)));
    REQUIRE(g.addTransition(makeTransition(4, {2}, {10})));
    CHECK(numbers(g.transitionsFrom(2)) == std::vector<int>{2, 4});
    CHECK(g.invariantViolations().empty());
}

TEST_CASE("Removing a step removes it from transitions and drops those left dangling", "[grafcet]")
{
    Grafcet g = parallelLoop();
    REQUIRE(g.removeStep(4));
    // T2 still has step 3 downstream, T3 still step 3 upstream.
    REQUIRE(g.transition(2));
    CHECK(g.transition(2)->downstream == std::vector<int>{3});
    CHECK(g.transition(3)->upstream == std::vector<int>{3});
    CHECK(g.lastChanges() == std::vector<GrafcetChange>{{GrafcetChange::Kind::Transition, 2},
                                                        {GrafcetChange::Kind::Transition, 3},
                                                        {GrafcetChange::Kind::StepList, 0}});

    REQUIRE(g.removeStep(1));
    // T1 lost its only upstream step, T3 its only downstream step.
    CHECK_FALSE(g.transition(1));
    CHECK_FALSE(g.transition(3));
    CHECK(g.transition(2));
    CHECK(g.invariantViolations().empty());
    CHECK(g.removeStep(1).code == "unknown-step");
}

TEST_CASE("Renumbering a step rewrites the transitions and the X and t/X references", "[grafcet]")
{
    Grafcet g = parallelLoop();
    GrafcetAction action;
    action.timing = ActionTiming::Continuous;
    action.text = "Lamp IF NOT X3";
    REQUIRE(g.addAction(1, action));

    REQUIRE(g.renumberStep(3, 30));
    CHECK_FALSE(g.step(3));
    REQUIRE(g.step(30));
    CHECK(g.transition(2)->downstream == std::vector<int>{30, 4});
    CHECK(g.transition(3)->upstream == std::vector<int>{30, 4});
    CHECK(g.transition(3)->receptivity == "X30 AND X4 AND Done");
    CHECK(g.step(1)->actions[0].text == "Lamp IF NOT X30");

    REQUIRE(g.renumberStep(2, 20));
    CHECK(g.transition(2)->receptivity == "5s/X20");
    CHECK(g.transition(2)->upstream == std::vector<int>{20});

    const Grafcet before = g;
    CHECK(g.renumberStep(20, 4).code == "duplicate-step");
    CHECK(g.renumberStep(20, 0).code == "invalid-number");
    CHECK(g.renumberStep(99, 100).code == "unknown-step");
    CHECK(g.sameContent(before));
    CHECK(g.invariantViolations().empty());
}

TEST_CASE("Renumbering leaves identifiers that only look alike", "[grafcet]")
{
    Grafcet g = parallelLoop();
    REQUIRE(g.setReceptivity(1, "X30 OR XX3 OR X3A OR x3"));
    REQUIRE(g.renumberStep(3, 7));
    // IEC identifiers ignore case: x3 is X3.
    CHECK(g.transition(1)->receptivity == "X30 OR XX3 OR X3A OR X7");
}

TEST_CASE("Initial steps are set one by one or as a set", "[grafcet]")
{
    Grafcet g = parallelLoop();
    REQUIRE(g.setStepInitial(3, true));
    CHECK(g.initialSteps() == std::vector<int>{1, 3});
    REQUIRE(g.setInitialSteps({2, 4}));
    CHECK(g.initialSteps() == std::vector<int>{2, 4});
    CHECK(g.lastChanges().size() == 4); // 1, 2, 3 and 4 changed
    CHECK(g.setInitialSteps({2, 9}).code == "unknown-step");
    CHECK(g.initialSteps() == std::vector<int>{2, 4});
    CHECK(g.setStepInitial(9, true).code == "unknown-step");
}

TEST_CASE("Actions are added, edited, moved and removed by index", "[grafcet]")
{
    Grafcet g = parallelLoop();
    const auto text = [&](std::size_t i) { return g.step(2)->actions.at(i).text; };
    REQUIRE(g.addAction(2, {ActionTiming::Continuous, "A_Plus"}));
    REQUIRE(g.addAction(2, {ActionTiming::OnActivation, "S Alarm"}));
    REQUIRE(g.addAction(2, {ActionTiming::OnDeactivation, "Count := Count + 1"}, 0));
    CHECK(text(0) == "Count := Count + 1");
    CHECK(text(1) == "A_Plus");
    CHECK(text(2) == "S Alarm");

    REQUIRE(g.moveAction(2, 0, 2));
    CHECK(text(0) == "A_Plus");
    CHECK(text(2) == "Count := Count + 1");
    REQUIRE(g.setAction(2, 1, {ActionTiming::OnActivation, "R Alarm"}));
    CHECK(text(1) == "R Alarm");
    CHECK(g.lastChanges() == std::vector<GrafcetChange>{{GrafcetChange::Kind::Step, 2}});
    REQUIRE(g.setAction(2, 1, {ActionTiming::OnActivation, "R Alarm"}));
    CHECK(g.lastChanges().empty()); // nothing changed
    REQUIRE(g.removeAction(2, 0));
    CHECK(g.step(2)->actions.size() == 2);

    CHECK(g.addAction(2, {}, 5).code == "invalid-action");
    CHECK(g.setAction(2, 2, {}).code == "invalid-action");
    CHECK(g.removeAction(2, -1).code == "invalid-action");
    CHECK(g.moveAction(2, 0, 7).code == "invalid-action");
    CHECK(g.addAction(8, {}).code == "unknown-step");
}

TEST_CASE("Renaming an identifier rewrites receptivities and actions and says where", "[grafcet]")
{
    Grafcet g = parallelLoop();
    REQUIRE(g.addAction(3, {ActionTiming::Continuous, "Motor IF Done"}));
    REQUIRE(g.addAction(4, {ActionTiming::OnActivation, "Done := FALSE"}));
    REQUIRE(g.addAction(2, {ActionTiming::Continuous, "Lamp"}));
    std::vector<int> steps;
    std::vector<int> transitions;
    g.renameIdentifier("done", "Finished", steps, transitions);
    CHECK(steps == std::vector<int>{3, 4});
    CHECK(transitions == std::vector<int>{3});
    CHECK(g.transition(3)->receptivity == "X3 AND X4 AND Finished");
    CHECK(g.step(3)->actions[0].text == "Motor IF Finished");
    CHECK(g.step(4)->actions[0].text == "Finished := FALSE");
    CHECK(g.step(2)->actions[0].text == "Lamp");
}

TEST_CASE("Random operations keep the invariants, refused ones change nothing, the adjacency follows", "[grafcet]")
{
    std::mt19937 random(20261202);
    const auto pick = [&](int low, int high) { return std::uniform_int_distribution<int>(low, high)(random); };
    const auto someSteps = [&] {
        std::vector<int> steps;
        for (int n = pick(0, 3); n > 0; --n)
            steps.push_back(pick(0, 12));
        return steps;
    };
    for (int run = 0; run < 50; ++run) {
        Grafcet g;
        for (int i = 0; i < 200; ++i) {
            const Grafcet before = g;
            Status status;
            switch (pick(0, 7)) {
            case 0: status = g.addStep(makeStep(pick(0, 12), pick(0, 1) == 1)); break;
            case 1: status = g.removeStep(pick(0, 12)); break;
            case 2: status = g.renumberStep(pick(0, 12), pick(0, 12)); break;
            case 3: status = g.addTransition(makeTransition(pick(0, 8), someSteps(), someSteps(), "X3 OR X5")); break;
            case 4: status = g.removeTransition(pick(0, 8)); break;
            case 5: status = g.setUpstream(pick(0, 8), someSteps()); break;
            case 6: status = g.setDownstream(pick(0, 8), someSteps()); break;
            default: status = g.setInitialSteps(someSteps()); break;
            }
            INFO("run " << run << ", operation " << i << ": " << status.message);
            REQUIRE(g.invariantViolations().empty());
            const GrafcetAdjacency adjacency(g);
            for (int step = 0; step <= 12; ++step) {
                REQUIRE(adjacency.leaving(step) == g.transitionsFrom(step));
                REQUIRE(adjacency.entering(step) == g.transitionsTo(step));
            }
            if (!status)
                REQUIRE(g.sameContent(before));
        }
    }
}

} // namespace test_grafcet
