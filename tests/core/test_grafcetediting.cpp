#include "core/formats/modelfiles.h"
#include "core/layout/grafcetlayout.h"
#include "core/model/branchorder.h"
#include "core/model/grafcetediting.h"
#include "core/model/model.h"
#include "grafcetlayoutchecks.h"
#include "samplemodels.h"

#include <catch2/catch.hpp>

#include <functional>
#include <random>
#include <string>
#include <vector>

namespace test_grafcetediting {

using namespace core;

namespace {

GrafcetStep makeStep(int number, bool initial = false, std::vector<GrafcetAction> actions = {})
{
    GrafcetStep step;
    step.number = number;
    step.initial = initial;
    step.actions = std::move(actions);
    return step;
}

void add(Grafcet& g, int number, std::vector<int> up, std::vector<int> down, std::string receptivity = "TRUE")
{
    REQUIRE(g.addTransition({number, std::move(up), std::move(down), std::move(receptivity)}).ok);
}

// 1 -> T1 -> 2 -> ... -> n, step 1 initial.
Grafcet sequence(int steps)
{
    Grafcet g;
    for (int n = 1; n <= steps; ++n)
        REQUIRE(g.addStep(makeStep(n, n == 1)).ok);
    for (int n = 1; n < steps; ++n)
        add(g, n, {n}, {n + 1}, "c" + std::to_string(n));
    return g;
}

// 1 -> T1 -> 2 -> T3 -> 4 and 1 -> T2 -> 3 -> T4 -> 4: a selection converging on 4.
Grafcet selection()
{
    Grafcet g;
    for (int n = 1; n <= 4; ++n)
        REQUIRE(g.addStep(makeStep(n, n == 1)).ok);
    add(g, 1, {1}, {2}, "a");
    add(g, 2, {1}, {3}, "NOT a");
    add(g, 3, {2}, {4});
    add(g, 4, {3}, {4});
    return g;
}

// 1 -> T1 -> 2 -> T2 -> (3 || 4) -> T3 -> 1
Grafcet parallelLoop()
{
    Grafcet g;
    for (int n = 1; n <= 4; ++n)
        REQUIRE(g.addStep(makeStep(n, n == 1)).ok);
    add(g, 1, {1}, {2});
    add(g, 2, {2}, {3, 4});
    add(g, 3, {3, 4}, {1});
    return g;
}

std::string join(const std::vector<int>& numbers)
{
    std::string text;
    for (int n : numbers)
        text += (text.empty() ? "" : ",") + std::to_string(n);
    return text;
}

// "T1 1>2, T2 2>3,4": every transition in list order.
std::string links(const Grafcet& g)
{
    std::string text;
    for (const GrafcetTransition& t : g.transitions())
        text += (text.empty() ? "" : ", ") + ("T" + std::to_string(t.number)) + " " + join(t.upstream) + ">"
              + join(t.downstream);
    return text;
}

// "1*,2,3": the steps in list order, initial ones starred.
std::string steps(const Grafcet& g)
{
    std::string text;
    for (const GrafcetStep& s : g.steps())
        text += (text.empty() ? "" : ",") + std::to_string(s.number) + (s.initial ? "*" : "");
    return text;
}

void checkClean(const Grafcet& g, const std::string& name)
{
    INFO(name << ": " << steps(g) << " / " << links(g));
    const std::vector<std::string> invariants = g.invariantViolations();
    for (const std::string& problem : invariants)
        UNSCOPED_INFO(problem);
    CHECK(invariants.empty());
    const std::vector<std::string> layout
        = grafcetlayoutchecks::violations(g, layoutGrafcet(g, grafcetlayoutchecks::fixedWidth));
    for (const std::string& problem : layout)
        UNSCOPED_INFO(problem);
    CHECK(layout.empty());
}

// The edit fails and leaves the GRAFCET as it was.
void checkRefused(Grafcet g, const std::function<Status(Grafcet&)>& edit)
{
    const Grafcet before = g;
    const Status status = edit(g);
    CHECK_FALSE(status.ok);
    CHECK_FALSE(status.code.empty());
    CHECK(g.sameContent(before));
}

} // namespace

TEST_CASE("Structured editing: insert a step after or before a step", "[grafcet-editing]")
{
    Grafcet g = sequence(3);
    GrafcetCreated created;
    REQUIRE(insertStepAfterStep(g, 2, &created).ok);
    CHECK(steps(g) == "1*,2,3,4");
    CHECK(links(g) == "T1 1>2, T2 4>3, T3 2>4"); // 2 -> T3 -> 4 -> T2 -> 3
    CHECK(created.steps == std::vector<int>{4});
    CHECK(created.transitions == std::vector<int>{3});
    CHECK(g.transition(3)->receptivity == "TRUE");
    checkClean(g, "after 2");

    g = sequence(3);
    REQUIRE(insertStepBeforeStep(g, 2, &created).ok);
    CHECK(links(g) == "T1 1>4, T2 2>3, T3 4>2");
    checkClean(g, "before 2");

    // Before the initial step: the new step is the new top, initial.
    g = sequence(3);
    add(g, 3, {3}, {1});
    REQUIRE(insertStepBeforeStep(g, 1, &created).ok);
    CHECK(steps(g) == "1,2,3,4*");
    CHECK(links(g) == "T1 1>2, T2 2>3, T3 3>4, T4 4>1");
    checkClean(g, "before initial");

    // After a step in a simultaneous convergence: the new step takes its place there.
    g = parallelLoop();
    REQUIRE(insertStepAfterStep(g, 3, &created).ok);
    CHECK(links(g) == "T1 1>2, T2 2>3,4, T3 5,4>1, T4 3>5");
    checkClean(g, "after a parallel branch's step");
}

TEST_CASE("Structured editing: insert a step after or before a transition", "[grafcet-editing]")
{
    Grafcet g = sequence(3);
    GrafcetCreated created;
    REQUIRE(insertStepAfterTransition(g, 1, &created).ok);
    CHECK(links(g) == "T1 1>4, T2 2>3, T3 4>2");
    CHECK(created.steps == std::vector<int>{4});
    CHECK(created.transitions == std::vector<int>{3});
    checkClean(g, "after T1");

    g = sequence(3);
    REQUIRE(insertStepBeforeTransition(g, 2, &created).ok);
    CHECK(links(g) == "T1 1>2, T2 4>3, T3 2>4");
    checkClean(g, "before T2");

    // The divergence moves to the new transition, below the new step.
    g = parallelLoop();
    REQUIRE(insertStepAfterTransition(g, 2, &created).ok);
    CHECK(links(g) == "T1 1>2, T2 2>5, T3 3,4>1, T4 5>3,4");
    checkClean(g, "after a divergence");
    g = parallelLoop();
    REQUIRE(insertStepBeforeTransition(g, 3, &created).ok);
    CHECK(links(g) == "T1 1>2, T2 2>3,4, T3 5>1, T4 3,4>5");
    checkClean(g, "before a convergence");
}

TEST_CASE("Structured editing: selection branches", "[grafcet-editing]")
{
    CHECK(selectionJoin(selection(), 1) == 4);
    CHECK(selectionJoin(sequence(3), 1) == 2);
    CHECK(selectionJoin(sequence(3), 3) == 0);

    // On a step of a sequence: an alternative to its transition, rejoining the next step.
    Grafcet g = sequence(3);
    GrafcetCreated created;
    REQUIRE(addSelectionBranchAtStep(g, 1, &created).ok);
    CHECK(links(g) == "T1 1>2, T2 2>3, T3 1>4, T4 4>2");
    CHECK(created.steps == std::vector<int>{4});
    CHECK(created.transitions == (std::vector<int>{3, 4}));
    checkClean(g, "selection on a sequence");

    // A third branch, to the right, converging where the two others do.
    g = selection();
    REQUIRE(addSelectionBranchAtStep(g, 1, &created).ok);
    CHECK(links(g) == "T1 1>2, T2 1>3, T3 2>4, T4 3>4, T5 1>5, T6 5>4");
    checkClean(g, "third branch");

    // Beside a transition: right after it in the branch order.
    g = selection();
    REQUIRE(addSelectionBranchAtTransition(g, 1, &created).ok);
    CHECK(links(g) == "T1 1>2, T5 1>5, T6 5>4, T2 1>3, T3 2>4, T4 3>4");
    checkClean(g, "branch beside T1");
    const GrafcetLayout layout = layoutGrafcet(g, grafcetlayoutchecks::fixedWidth);
    CHECK(layout.transition(1)->barCenter.x < layout.transition(5)->barCenter.x);
    CHECK(layout.transition(5)->barCenter.x < layout.transition(2)->barCenter.x);

    checkRefused(sequence(3), [](Grafcet& e) { return addSelectionBranchAtStep(e, 3); }); // no outgoing transition
}

TEST_CASE("Structured editing: a branch ending on a step", "[grafcet-editing]")
{
    // At a step with branches: a new rightmost branch to a step with no transition after it.
    Grafcet g = selection();
    GrafcetCreated created;
    REQUIRE(addBranchEndingOnStep(g, 1, &created).ok);
    CHECK(links(g) == "T1 1>2, T2 1>3, T3 2>4, T4 3>4, T5 1>5");
    CHECK(created.steps == std::vector<int>{5});
    CHECK(created.transitions == std::vector<int>{5});
    CHECK(g.transitionsFrom(5).empty());
    checkClean(g, "exit branch");
    const GrafcetLayout layout = layoutGrafcet(g, grafcetlayoutchecks::fixedWidth);
    CHECK(layout.step(5)->box.x > layout.step(3)->box.x); // the rightmost branch

    // At the last step of a sequence: the sequence goes on with the new step.
    g = sequence(2);
    REQUIRE(addBranchEndingOnStep(g, 2).ok);
    CHECK(links(g) == "T1 1>2, T2 2>3");
    checkRefused(sequence(2), [](Grafcet& e) { return addBranchEndingOnStep(e, 9); });
    checkRefused(parallelLoop(), [](Grafcet& e) { return addSelectionBranchAtTransition(e, 3); }); // two upstream
}

TEST_CASE("Structured editing: parallel branches", "[grafcet-editing]")
{
    // A transition of a sequence becomes a divergence, its next transition the convergence.
    Grafcet g = sequence(3);
    GrafcetCreated created;
    REQUIRE(addParallelBranch(g, 1, &created).ok);
    CHECK(links(g) == "T1 1>2,4, T2 2,4>3");
    CHECK(created.steps == std::vector<int>{4});
    CHECK(created.transitions.empty());
    checkClean(g, "new parallel section");

    g = parallelLoop();
    REQUIRE(addParallelBranch(g, 2, &created).ok);
    CHECK(links(g) == "T1 1>2, T2 2>3,4,5, T3 3,4,5>1");
    checkClean(g, "third parallel branch");

    // Longer branches: the convergence is found below them.
    g = parallelLoop();
    REQUIRE(insertStepAfterStep(g, 3).ok); // 3 -> T4 -> 5 -> T3
    REQUIRE(addParallelBranch(g, 2, &created).ok);
    CHECK(links(g) == "T1 1>2, T2 2>3,4,6, T3 5,4,6>1, T4 3>5");
    checkClean(g, "parallel branch beside a longer one");

    // The last transition of a sequence has no convergence below: the branch ends on its step.
    g = sequence(3);
    REQUIRE(addParallelBranch(g, 2, &created).ok);
    CHECK(links(g) == "T1 1>2, T2 2>3,4");
    checkClean(g, "open parallel branch");
}

TEST_CASE("Structured editing: loops and jumps", "[grafcet-editing]")
{
    Grafcet g = sequence(3);
    GrafcetCreated created;
    REQUIRE(addJump(g, 3, 1, &created).ok);
    CHECK(links(g) == "T1 1>2, T2 2>3, T3 3>1");
    CHECK(created.transitions == std::vector<int>{3});
    checkClean(g, "loop back to 1");
    const GrafcetLayout loop = layoutGrafcet(g, grafcetlayoutchecks::fixedWidth);
    bool drawnAsLoop = false;
    for (const GrafcetLinkLayout& link : loop.links)
        drawnAsLoop |= link.transition == 3 && link.ending == GrafcetLinkLayout::Ending::Loop;
    CHECK(drawnAsLoop);

    // From the second branch of a selection back to the top: a jump arrow.
    g = selection();
    REQUIRE(addJump(g, 3, 1).ok);
    checkClean(g, "jump from a second branch");
    bool drawnAsJump = false;
    for (const GrafcetLinkLayout& link : layoutGrafcet(g, grafcetlayoutchecks::fixedWidth).links)
        drawnAsJump |= link.transition == 5 && link.ending == GrafcetLinkLayout::Ending::Jump;
    CHECK(drawnAsJump);

    Grafcet looped = sequence(3);
    REQUIRE(addJump(looped, 3, 1).ok);
    checkRefused(looped, [](Grafcet& e) { return addJump(e, 3, 1); }); // it exists already
    checkRefused(sequence(3), [](Grafcet& e) { return addJump(e, 3, 9); });
}

TEST_CASE("Structured editing: removing a step repairs the sequence", "[grafcet-editing]")
{
    // In a sequence: its transition goes with it, the one before it reaches the next step.
    Grafcet g = sequence(4);
    g.setReceptivity(2, "lost");
    REQUIRE(removeStepWithRepair(g, 2).ok);
    CHECK(steps(g) == "1*,3,4");
    CHECK(links(g) == "T1 1>3, T3 3>4");
    CHECK(g.transition(1)->receptivity == "c1");
    checkClean(g, "removed 2");

    // The initial step passes its flag to the next one; the loop back follows.
    g = sequence(3);
    add(g, 3, {3}, {1});
    REQUIRE(removeStepWithRepair(g, 1).ok);
    CHECK(steps(g) == "2*,3");
    CHECK(links(g) == "T2 2>3, T3 3>2");
    checkClean(g, "removed the initial step");

    // The last step: the transition that reached it goes too.
    g = sequence(3);
    REQUIRE(removeStepWithRepair(g, 3).ok);
    CHECK(links(g) == "T1 1>2");
    checkClean(g, "removed the last step");

    // A one-step parallel branch: the divergence and the convergence lose it.
    g = parallelLoop();
    REQUIRE(removeStepWithRepair(g, 3).ok);
    CHECK(links(g) == "T1 1>2, T2 2>4, T3 4>1");
    checkClean(g, "removed a parallel step");

    // A step with a selection below it and one transition above: that
    // transition goes, the branches leave the step above.
    g = selection();
    add(g, 5, {4}, {1});
    REQUIRE(insertStepBeforeStep(g, 1).ok); // 4 -> T5 -> 5 -> T6 -> 1
    REQUIRE(removeStepWithRepair(g, 1).ok);
    CHECK(steps(g) == "2,3,4,5*");
    CHECK(links(g) == "T1 5>2, T2 5>3, T3 2>4, T4 3>4, T5 4>5");
    checkClean(g, "removed a divergence step");

    checkRefused(sequence(3), [](Grafcet& e) { return removeStepWithRepair(e, 7); });
}

TEST_CASE("Structured editing: removing a branch", "[grafcet-editing]")
{
    Grafcet g = selection();
    REQUIRE(removeSelectionBranch(g, 2).ok);
    CHECK(steps(g) == "1*,2,4");
    CHECK(links(g) == "T1 1>2, T3 2>4");
    checkClean(g, "removed the second selection branch");

    // A longer branch goes whole; the join and what follows stay, as does a loop back.
    g = selection();
    add(g, 5, {4}, {1});
    REQUIRE(insertStepAfterStep(g, 3).ok); // 3 -> T6 -> 5 -> T4 -> 4
    REQUIRE(removeSelectionBranch(g, 2).ok);
    CHECK(steps(g) == "1*,2,4");
    CHECK(links(g) == "T1 1>2, T3 2>4, T5 4>1");
    checkClean(g, "removed a longer branch");

    // A jump branch: only its transition.
    g = sequence(3);
    REQUIRE(addJump(g, 2, 1).ok);
    REQUIRE(removeSelectionBranch(g, 3).ok);
    CHECK(g.sameContent(sequence(3)));

    g = parallelLoop();
    REQUIRE(insertStepAfterStep(g, 4).ok); // 4 -> T4 -> 5 -> T3
    REQUIRE(removeParallelBranch(g, 4).ok);
    CHECK(steps(g) == "1*,2,3");
    CHECK(links(g) == "T1 1>2, T2 2>3, T3 3>1");
    checkClean(g, "removed a parallel branch");

    checkRefused(sequence(3), [](Grafcet& e) { return removeSelectionBranch(e, 1); }); // no other branch
    checkRefused(sequence(3), [](Grafcet& e) { return removeSelectionBranch(e, 5); });
    checkRefused(parallelLoop(), [](Grafcet& e) { return removeParallelBranch(e, 2); }); // not in a divergence
}

TEST_CASE("Structured editing: renumbering in drawing order", "[grafcet-editing]")
{
    Grafcet g;
    REQUIRE(g.addStep(makeStep(10, true, {{ActionTiming::Continuous, "Lamp IF X20"}})).ok);
    REQUIRE(g.addStep(makeStep(20)).ok);
    REQUIRE(g.addStep(makeStep(7)).ok);
    REQUIRE(g.addStep(makeStep(5)).ok);
    add(g, 9, {10}, {20}, "a");
    add(g, 4, {10}, {7}, "NOT a");
    add(g, 2, {20}, {5}, "X20 AND 2s/X10");
    add(g, 8, {7}, {5});
    add(g, 3, {5}, {10}, "X7");
    const GrafcetLayout before = layoutGrafcet(g, grafcetlayoutchecks::fixedWidth);
    REQUIRE(renumberAll(g).ok);
    // Top to bottom, each row left to right: 10; 20 and 7 side by side; 5.
    CHECK(steps(g) == "1*,2,3,4");
    CHECK(links(g) == "T1 1>2, T2 1>3, T3 2>4, T4 3>4, T5 4>1");
    CHECK(g.step(1)->actions[0].text == "Lamp IF X2");
    CHECK(g.transition(3)->receptivity == "X2 AND 2s/X1");
    CHECK(g.transition(5)->receptivity == "X3");
    // The drawing stays as it was.
    const GrafcetLayout after = layoutGrafcet(g, grafcetlayoutchecks::fixedWidth);
    REQUIRE(after.steps.size() == before.steps.size());
    // The same rows and, in each row, the same left-to-right order (the
    // shorter texts X2, X1 make the columns narrower).
    for (std::size_t i = 0; i < after.steps.size(); ++i) {
        for (std::size_t j = 0; j < after.steps.size(); ++j) {
            CHECK(after.steps[i].box.y == before.steps[i].box.y);
            CHECK((after.steps[i].box.x < after.steps[j].box.x) == (before.steps[i].box.x < before.steps[j].box.x));
        }
    }
    checkClean(g, "renumbered");

    // Already numbered: nothing changes.
    Grafcet numbered = sequence(4);
    REQUIRE(renumberAll(numbered).ok);
    CHECK(numbered.sameContent(sequence(4)));
}

TEST_CASE("Structured editing: connecting a transition directly", "[grafcet-editing]")
{
    Grafcet g = sequence(4);
    REQUIRE(connectDirectly(g, 2, {2}, {3, 4}).ok);
    CHECK(links(g) == "T1 1>2, T2 2>3,4, T3 3>4");
    checkRefused(sequence(3), [](Grafcet& e) { return connectDirectly(e, 1, {1}, {}); });
    checkRefused(sequence(3), [](Grafcet& e) { return connectDirectly(e, 1, {1}, {2, 9}); });
    checkRefused(sequence(3), [](Grafcet& e) { return connectDirectly(e, 1, {2}, {3, 3}); });
    checkRefused(sequence(3), [](Grafcet& e) { return connectDirectly(e, 8, {1}, {2}); });
}

TEST_CASE("Structured editing: copy and paste renumber and rewrite references", "[grafcet-editing]")
{
    Grafcet g = sequence(4);
    REQUIRE(g.addAction(3, {ActionTiming::Continuous, "N Lamp IF X2"}).ok);
    REQUIRE(g.setReceptivity(2, "X2 AND 3s/X3 AND X1").ok);
    const GrafcetFragment fragment = copyFragment(g, {3, 2});
    REQUIRE(fragment.steps.size() == 2);
    CHECK(fragment.steps[0].number == 2); // in the GRAFCET's order
    REQUIRE(fragment.transitions.size() == 1);
    CHECK(fragment.transitions[0].number == 2);

    GrafcetCreated created;
    REQUIRE(pasteFragment(g, fragment, 4, &created).ok);
    CHECK(created.steps == (std::vector<int>{5, 6}));
    CHECK(created.transitions == (std::vector<int>{4, 5}));
    CHECK(links(g) == "T1 1>2, T2 2>3, T3 3>4, T4 5>6, T5 4>5");
    CHECK(g.transition(4)->receptivity == "X5 AND 3s/X6 AND X1"); // X1 was not copied
    CHECK(g.step(6)->actions[0].text == "N Lamp IF X5");
    CHECK(g.transition(2)->receptivity == "X2 AND 3s/X3 AND X1"); // the original stays
    checkClean(g, "pasted after the last step");

    // In the middle of a sequence: what followed the step follows the pasted piece.
    g = sequence(3);
    REQUIRE(pasteFragment(g, copyFragment(g, {2}), 1, &created).ok);
    CHECK(links(g) == "T1 4>2, T2 2>3, T3 1>4");
    checkClean(g, "pasted in the middle");

    // The initial step is pasted as a plain one; apart from everything with 0.
    g = sequence(2);
    REQUIRE(pasteFragment(g, copyFragment(g, {1, 2}), 0, &created).ok);
    CHECK(steps(g) == "1*,2,3,4");
    CHECK(links(g) == "T1 1>2, T2 3>4");
    checkClean(g, "pasted apart");

    // Numbers above the temporary ones and references to numbers never used stay.
    g = sequence(2);
    REQUIRE(g.setReceptivity(1, "X2 OR X99").ok);
    REQUIRE(pasteFragment(g, copyFragment(g, {1, 2}), 2).ok);
    CHECK(g.transition(2)->receptivity == "X4 OR X99");

    checkRefused(parallelLoop(), [](Grafcet& e) { return pasteFragment(e, copyFragment(e, {3, 4}), 1); }); // two entries
    checkRefused(sequence(3), [](Grafcet& e) { return pasteFragment(e, copyFragment(e, {2}), 9); });
    checkRefused(sequence(3), [](Grafcet& e) { return pasteFragment(e, GrafcetFragment{}, 1); });
    GrafcetFragment broken = copyFragment(sequence(3), {1, 2});
    broken.transitions[0].downstream = {7};
    checkRefused(sequence(3), [&broken](Grafcet& e) { return pasteFragment(e, broken, 0); });
}

TEST_CASE("Structured editing: the usual shape of a new GRAFCET", "[grafcet-editing]")
{
    const Grafcet g = usualGrafcet();
    CHECK(steps(g) == "1*,2,3");
    CHECK(links(g) == "T1 1>2, T2 2>3");
    REQUIRE(g.step(3)->actions.size() == 1);
    CHECK(g.step(3)->actions[0].text == "S Complete");
    CHECK(g.step(3)->actions[0].timing == ActionTiming::OnActivation);
    checkClean(g, "usual shape");
}

namespace {

// One random structured edit on a random element; false when it was refused.
bool randomEdit(Grafcet& g, std::mt19937& random, std::string& what)
{
    const auto pick = [&random](const std::vector<int>& numbers) {
        return numbers.empty() ? 1 : numbers[std::uniform_int_distribution<std::size_t>(0, numbers.size() - 1)(random)];
    };
    std::vector<int> stepNumbers;
    for (const GrafcetStep& s : g.steps())
        stepNumbers.push_back(s.number);
    std::vector<int> transitionNumbers;
    for (const GrafcetTransition& t : g.transitions())
        transitionNumbers.push_back(t.number);
    const int s = pick(stepNumbers);
    const int t = pick(transitionNumbers);
    const Grafcet before = g;
    Status status;
    switch (std::uniform_int_distribution<int>(0, 16)(random)) {
    case 0: what = "insert after step " + std::to_string(s); status = insertStepAfterStep(g, s); break;
    case 1: what = "insert before step " + std::to_string(s); status = insertStepBeforeStep(g, s); break;
    case 2: what = "insert after T" + std::to_string(t); status = insertStepAfterTransition(g, t); break;
    case 3: what = "insert before T" + std::to_string(t); status = insertStepBeforeTransition(g, t); break;
    case 4: what = "selection at step " + std::to_string(s); status = addSelectionBranchAtStep(g, s); break;
    case 5: what = "selection at T" + std::to_string(t); status = addSelectionBranchAtTransition(g, t); break;
    case 6: what = "parallel at T" + std::to_string(t); status = addParallelBranch(g, t); break;
    case 7: {
        const int target = pick(stepNumbers);
        what = "jump " + std::to_string(s) + " to " + std::to_string(target);
        status = addJump(g, s, target);
        break;
    }
    case 8: what = "remove step " + std::to_string(s); status = removeStepWithRepair(g, s); break;
    case 9: what = "remove selection branch T" + std::to_string(t); status = removeSelectionBranch(g, t); break;
    case 10: what = "remove parallel branch " + std::to_string(s); status = removeParallelBranch(g, s); break;
    case 11: what = "renumber"; status = renumberAll(g); break;
    case 12: what = "branch ending on a step at " + std::to_string(s); status = addBranchEndingOnStep(g, s); break;
    case 13: what = "move branch of " + std::to_string(s) + " left"; status = moveBranch(g, s, -1); break;
    case 14: what = "move branch of " + std::to_string(s) + " right"; status = moveBranch(g, s, +1); break;
    case 15: what = "remove T" + std::to_string(t); status = g.removeTransition(t); break;
    default: {
        const int anchor = pick(stepNumbers);
        what = "paste " + std::to_string(s) + " after " + std::to_string(anchor);
        status = pasteFragment(g, copyFragment(g, {s}), anchor);
        break;
    }
    }
    if (!status.ok)
        CHECK(g.sameContent(before));
    return status.ok;
}

} // namespace

TEST_CASE("Structured editing: every operation on the shipped example's GRAFCETs", "[grafcet-editing][example]")
{
    const auto loaded = loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    REQUIRE(loaded.model);
    int edits = 0;
    for (const auto& [id, grafcet] : loaded.model->grafcets()) {
        using StepEdit = Status (*)(Grafcet&, int, GrafcetCreated*);
        for (const GrafcetStep& step : grafcet.steps()) {
            for (StepEdit edit : {StepEdit(insertStepAfterStep), StepEdit(insertStepBeforeStep),
                                  StepEdit(addSelectionBranchAtStep)}) {
                Grafcet g = grafcet;
                if (edit(g, step.number, nullptr).ok) {
                    ++edits;
                    checkClean(g, id + " step " + std::to_string(step.number));
                }
            }
            for (auto edit : {removeStepWithRepair, removeParallelBranch}) {
                Grafcet g = grafcet;
                if (edit(g, step.number).ok) {
                    ++edits;
                    checkClean(g, id + " removal at step " + std::to_string(step.number));
                }
            }
            Grafcet pasted = grafcet;
            if (pasteFragment(pasted, copyFragment(grafcet, {step.number}), step.number).ok)
                checkClean(pasted, id + " paste after " + std::to_string(step.number));
        }
        Grafcet renumbered = grafcet;
        REQUIRE(renumberAll(renumbered).ok);
        checkClean(renumbered, id + " renumbered");
        for (const GrafcetTransition& t : grafcet.transitions()) {
            for (StepEdit edit : {StepEdit(insertStepAfterTransition), StepEdit(insertStepBeforeTransition),
                                  StepEdit(addSelectionBranchAtTransition), StepEdit(addParallelBranch)}) {
                Grafcet g = grafcet;
                if (edit(g, t.number, nullptr).ok) {
                    ++edits;
                    checkClean(g, id + " T" + std::to_string(t.number));
                }
            }
            Grafcet g = grafcet;
            if (removeSelectionBranch(g, t.number).ok)
                checkClean(g, id + " removed branch T" + std::to_string(t.number));
        }
    }
    CHECK(edits > 100);
}

TEST_CASE("Structured editing: random sequences of operations", "[grafcet-editing][random]")
{
    int applied = 0;
    for (std::uint32_t seed = 1; seed <= 40; ++seed) {
        Model model = samples::randomModel(seed);
        std::mt19937 random(seed);
        samples::addValidRandomNestedGrafcets(model, random);
        std::vector<Grafcet> starts{usualGrafcet()};
        for (const auto& [id, grafcet] : model.grafcets())
            starts.push_back(grafcet);
        for (std::size_t i = 0; i < starts.size(); ++i) {
            Grafcet g = starts[i];
            std::string history;
            for (int edit = 0; edit < 25; ++edit) {
                std::string what;
                if (!randomEdit(g, random, what))
                    continue;
                ++applied;
                history += what + "; ";
                checkClean(g, "seed " + std::to_string(seed) + " GRAFCET " + std::to_string(i) + ": " + history);
            }
            INFO("seed " << seed << " GRAFCET " << i << ": " << history);
            for (const std::string& move : grafcetlayoutchecks::labelWidthMoves(g))
                UNSCOPED_INFO(move);
            CHECK(grafcetlayoutchecks::labelWidthMoves(g).empty());
        }
    }
    CHECK(applied > 1000);
}

} // namespace test_grafcetediting
