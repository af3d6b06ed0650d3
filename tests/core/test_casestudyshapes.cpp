// The case study's nested GRAFCETs (spec grafcet-layer.md §6) drawn with the
// structured editing operations only, as a user draws them, each compared
// with its figure: structure, branch order, and the drawing's shape (F2 as
// the case study's Figure 3, "Nested behaviour of the starting procedure F2
// mode", draws it: Castillo, Barbieri et al., Machines 2021).

#include "core/layout/grafcetlayout.h"
#include "core/model/branchorder.h"
#include "core/model/grafcetediting.h"
#include "grafcetlayoutchecks.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace test_casestudyshapes {

using namespace core;

namespace {

void require(const Status& status)
{
    INFO(status.message);
    REQUIRE(status.ok);
}

int created(Status status, const GrafcetCreated& made, bool step)
{
    require(status);
    const std::vector<int>& numbers = step ? made.steps : made.transitions;
    REQUIRE(numbers.size() == 1);
    return numbers.front();
}

// The transition fromStep -> toStep.
int transitionBetween(const Grafcet& g, int from, int to)
{
    for (const GrafcetTransition* t : g.transitionsFrom(from))
        if (std::find(t->downstream.begin(), t->downstream.end(), to) != t->downstream.end())
            return t->number;
    FAIL("no transition from " << from << " to " << to);
    return 0;
}

std::vector<int> leaving(const Grafcet& g, int step)
{
    std::vector<int> numbers;
    for (const GrafcetTransition* t : g.transitionsFrom(step))
        numbers.push_back(t->number);
    return numbers;
}

void checkLayoutClean(const Grafcet& g)
{
    const GrafcetLayout layout = layoutGrafcet(g, grafcetlayoutchecks::fixedWidth);
    for (const std::string& problem : grafcetlayoutchecks::violations(g, layout))
        UNSCOPED_INFO(problem);
    CHECK(grafcetlayoutchecks::violations(g, layout).empty());
    for (const std::string& move : grafcetlayoutchecks::labelWidthMoves(g))
        UNSCOPED_INFO(move);
    CHECK(grafcetlayoutchecks::labelWidthMoves(g).empty());
}

const GrafcetBranchLineLayout* line(const GrafcetLayout& layout, GrafcetBranchLineLayout::Kind kind, int step,
                                    int transition = 0)
{
    for (const GrafcetBranchLineLayout& l : layout.lines)
        if (l.kind == kind && l.step == step && l.transition == transition)
            return &l;
    return nullptr;
}

// F2 of the case study, drawn as a user would: the usual shape, then the
// selection at step 3 branch by branch, the exit step first and moved to
// the right afterwards.
Grafcet drawF2()
{
    Grafcet g = usualGrafcet(); // 1 -> T1 -> 2 -> T2 -> 3 (S Complete)
    require(g.removeAction(3, 0));
    require(g.setReceptivity(1, "h1 AND b1"));
    require(g.setReceptivity(2, "h0 AND b0"));
    GrafcetCreated made;
    // 4-5, back to 1.
    const int four = created(addBranchEndingOnStep(g, 3, &made), made, true);
    require(g.setReceptivity(made.transitions.front(), "CP1 AND NOT CP2"));
    const int five = created(insertStepAfterStep(g, four, &made), made, true);
    require(g.setReceptivity(made.transitions.front(), "a1"));
    require(g.setReceptivity(created(addJump(g, five, 1, &made), made, false), "a0"));
    // The exit step, drawn too early: moved right at the end.
    const int exit = created(addBranchEndingOnStep(g, 3, &made), made, true);
    require(g.setReceptivity(made.transitions.front(), "CP1 AND CP2 AND CP3"));
    require(g.addAction(exit, {ActionTiming::OnActivation, "S Complete"}));
    // The parallel section 7-8 || 9-10, joined by a0*c0 back to 1.
    const int seven = created(addBranchEndingOnStep(g, 3, &made), made, true);
    const int opening = made.transitions.front();
    require(g.setReceptivity(opening, "CP1 AND CP2 AND NOT CP3"));
    const int nine = created(addParallelBranch(g, opening, &made), made, true);
    const int eight = created(insertStepAfterStep(g, seven, &made), made, true);
    require(g.setReceptivity(made.transitions.front(), "a1"));
    const int ten = created(insertStepAfterStep(g, nine, &made), made, true);
    require(g.setReceptivity(made.transitions.front(), "c1"));
    const int closing = created(addJump(g, eight, 1, &made), made, false);
    require(connectDirectly(g, closing, {eight, ten}, {1}));
    require(g.setReceptivity(closing, "a0 AND c0"));
    // NOT CP1, back to 1.
    require(g.setReceptivity(created(addJump(g, 3, 1, &made), made, false), "NOT CP1"));
    // The figure's order: 4-5, the parallel section, NOT CP1, 11.
    require(moveBranch(g, exit, +1));
    require(moveBranch(g, exit, +1));
    // The figure's numbers.
    const std::vector<std::pair<int, int>> numbers{{exit, 11}, {ten, 10}, {nine, 9}, {eight, 8}, {seven, 7}};
    for (const auto& [from, to] : numbers)
        require(g.renumberStep(from, 100 + to));
    for (const auto& [from, to] : numbers)
        require(g.renumberStep(100 + to, to));
    return g;
}

} // namespace

TEST_CASE("Case study: F2 drawn with the editing operations is the figure", "[casestudy][grafcet-layout]")
{
    const Grafcet g = drawF2();
    REQUIRE(g.invariantViolations().empty());
    // Structure and branch order: the selection at 3 is 4-5, the parallel section, NOT CP1, 11.
    const std::vector<int> branches = leaving(g, 3);
    REQUIRE(branches.size() == 4);
    CHECK(g.transition(branches[0])->downstream == std::vector<int>{4});
    CHECK(g.transition(branches[1])->downstream == (std::vector<int>{7, 9}));
    CHECK(g.transition(branches[2])->downstream == std::vector<int>{1});
    CHECK(g.transition(branches[2])->receptivity == "NOT CP1");
    CHECK(g.transition(branches[3])->downstream == std::vector<int>{11});
    CHECK(g.transitionsFrom(11).empty()); // the exit step
    CHECK(g.step(11)->actions.front().text == "S Complete");
    const int closing = transitionBetween(g, 8, 1);
    CHECK(g.transition(closing)->upstream == (std::vector<int>{8, 10}));
    CHECK(g.transition(closing)->receptivity == "a0 AND c0");
    CHECK(transitionBetween(g, 5, 1) != 0);

    const GrafcetLayout layout = layoutGrafcet(g, grafcetlayoutchecks::fixedWidth);
    checkLayoutClean(g);
    // Drawn in branch order, left to right.
    CHECK(layout.step(4)->box.x < layout.step(7)->box.x);
    CHECK(layout.step(7)->box.x < layout.step(9)->box.x);
    CHECK(layout.transition(branches[1])->barCenter.x < layout.transition(branches[2])->barCenter.x);
    CHECK(layout.transition(branches[2])->barCenter.x < layout.step(11)->box.x);
    // One convergence under 4-5, the parallel section and NOT CP1, then one link back to 1.
    const GrafcetBranchLineLayout* convergence = line(layout, GrafcetBranchLineLayout::Kind::SelectionConvergence, 1);
    REQUIRE(convergence);
    CHECK(convergence->branches
          == (std::vector<int>{transitionBetween(g, 5, 1), closing, branches[2]}));
    CHECK(convergence->right < layout.step(11)->box.x); // the exit step stands beside it
    // The three links run down to the convergence line, then along one and the same way back.
    std::vector<std::vector<Point>> ways;
    for (const GrafcetLinkLayout& link : layout.links) {
        if (link.kind != GrafcetLinkLayout::Kind::TransitionToStep || link.step != 1)
            continue;
        CHECK(link.ending != GrafcetLinkLayout::Ending::Plain);
        const auto below = std::find_if(link.route.begin(), link.route.end(),
                                        [&](Point p) { return p.y > convergence->y; });
        REQUIRE(below != link.route.begin());
        CHECK((below - 1)->y <= convergence->y);
        std::vector<Point> way;
        for (auto p = below; p != link.route.end(); ++p)
            way.push_back(*p);
        ways.push_back(std::move(way));
    }
    REQUIRE(ways.size() == 3);
    for (const std::vector<Point>& way : ways) {
        REQUIRE(way.size() == ways.front().size());
        for (std::size_t i = 0; i < way.size(); ++i)
            CHECK((way[i].x == ways.front()[i].x && way[i].y == ways.front()[i].y));
    }
}

TEST_CASE("Case study: F1's three stations in one parallel section", "[casestudy][grafcet-layout]")
{
    // 1 -> T1 -> 2 -> (3-4 || 5-6 || 7-8) -> 9 -> back to 1.
    Grafcet g = usualGrafcet();
    GrafcetCreated made;
    const int opening = 2; // 2 -> T2 -> 3
    const int second = created(addParallelBranch(g, opening, &made), made, true);
    const int third = created(addParallelBranch(g, opening, &made), made, true);
    for (int station : {3, second, third})
        require(insertStepAfterStep(g, station, &made));
    std::vector<int> ends;
    for (int station : g.transition(opening)->downstream)
        ends.push_back(g.transitionsFrom(station).front()->downstream.front());
    const int closing = created(addJump(g, ends.front(), 1, &made), made, false);
    require(connectDirectly(g, closing, ends, {1}));
    require(insertStepBeforeTransition(g, closing, &made)); // the convergence, then a last step
    REQUIRE(g.invariantViolations().empty());
    CHECK(g.transition(opening)->downstream.size() == 3);
    checkLayoutClean(g);
    const GrafcetLayout layout = layoutGrafcet(g, grafcetlayoutchecks::fixedWidth);
    const GrafcetBranchLineLayout* join = line(layout, GrafcetBranchLineLayout::Kind::SimultaneousConvergence, 0,
                                               g.transitionsTo(made.steps.front()).front()->number);
    REQUIRE(join);
    CHECK(join->branches == ends);

    // The user puts the third station first: the convergence follows.
    require(moveBranch(g, third, -2));
    CHECK(g.transition(opening)->downstream.front() == third);
    CHECK(g.transitionsTo(made.steps.front()).front()->upstream.front() == ends.back());
    checkLayoutClean(g);
    const GrafcetLayout moved = layoutGrafcet(g, grafcetlayoutchecks::fixedWidth);
    CHECK(moved.step(third)->box.x < moved.step(3)->box.x);
}

TEST_CASE("Case study: a four-branch selection looping back to step 3 (F3 to F5)", "[casestudy][grafcet-layout]")
{
    // 1 -> 2 -> 3, then at 3 four branches each of one step, three going back to 3, the last an exit.
    Grafcet g = usualGrafcet();
    require(g.removeAction(3, 0));
    GrafcetCreated made;
    std::vector<int> firsts;
    for (int b = 0; b < 3; ++b) {
        const int step = created(addBranchEndingOnStep(g, 3, &made), made, true);
        firsts.push_back(made.transitions.front());
        require(addJump(g, step, 3, &made));
    }
    const int exit = created(addBranchEndingOnStep(g, 3, &made), made, true);
    firsts.push_back(made.transitions.front());
    CHECK(leaving(g, 3) == firsts);
    checkLayoutClean(g);
    const GrafcetLayout layout = layoutGrafcet(g, grafcetlayoutchecks::fixedWidth);
    const GrafcetBranchLineLayout* divergence = line(layout, GrafcetBranchLineLayout::Kind::SelectionDivergence, 3);
    REQUIRE(divergence);
    CHECK(divergence->branches == firsts);
    REQUIRE(line(layout, GrafcetBranchLineLayout::Kind::SelectionConvergence, 3));

    // The exit branch moved to the far left: drawn there.
    require(moveBranch(g, exit, -3));
    CHECK(leaving(g, 3).front() == firsts.back());
    checkLayoutClean(g);
    const GrafcetLayout moved = layoutGrafcet(g, grafcetlayoutchecks::fixedWidth);
    CHECK(moved.step(exit)->box.x < moved.step(4)->box.x);
}

TEST_CASE("Stable drawing: a receptivity growing within its room moves nothing", "[grafcet-layout]")
{
    Grafcet g = drawF2();
    const GrafcetLayout before = layoutGrafcet(g, grafcetlayoutchecks::fixedWidth);
    const int branch = leaving(g, 3).front(); // 3 -> 4, the leftmost branch: everything else is at its right
    require(g.setReceptivity(branch, "CP1 * NOT CP2")); // narrower, within the same room
    const GrafcetLayout after = layoutGrafcet(g, grafcetlayoutchecks::fixedWidth);
    for (const GrafcetStepLayout& step : before.steps)
        CHECK(after.step(step.number)->box.x == step.box.x);
    CHECK(grafcetlayoutchecks::labelWidthMoves(g).empty());
}

// The exit step added in one action stands to the right of the sequence it
// leaves: the step's column goes on straight down its first branch, as the
// sheet draws it (it used to go on with the last branch, the new exit step,
// and push the sequence to its left).
TEST_CASE("An exit step added beside a sequence stands to its right", "[casestudy][grafcet-layout]")
{
    for (int exits = 1; exits <= 6; ++exits) {
        Grafcet g = usualGrafcet(); // 1 -> T1 -> 2 -> T2 -> 3
        for (int i = 0; i < exits; ++i)
            require(addBranchEndingOnStep(g, 1));
        checkLayoutClean(g);
        const GrafcetLayout layout = layoutGrafcet(g, grafcetlayoutchecks::fixedWidth);
        INFO("exit branches: " << exits);
        CHECK(layout.step(1)->box.center().x == layout.step(2)->box.center().x);
        CHECK(layout.step(2)->box.center().x == layout.step(3)->box.center().x);
        for (int exit = 4; exit < 4 + exits; ++exit)
            CHECK(layout.step(exit)->box.left() > layout.step(2)->box.right());
        // The initial step is the leftmost box: a tab opened at its left shows it.
        for (const GrafcetStepLayout& step : layout.steps)
            CHECK(step.box.left() >= layout.step(1)->box.left());
    }
}

} // namespace test_casestudyshapes
