#include "core/model/branchorder.h"
#include "core/model/grafcetediting.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace test_branchorder {

using namespace core;

namespace {

void addSteps(Grafcet& g, std::vector<int> numbers)
{
    for (int n : numbers)
        REQUIRE(g.addStep({n, n == 1, "", {}}).ok);
}

void add(Grafcet& g, int number, std::vector<int> up, std::vector<int> down)
{
    REQUIRE(g.addTransition({number, std::move(up), std::move(down), "c" + std::to_string(number)}).ok);
}

std::vector<int> leaving(const Grafcet& g, int step)
{
    std::vector<int> numbers;
    for (const GrafcetTransition* t : g.transitionsFrom(step))
        numbers.push_back(t->number);
    return numbers;
}

// 1 -> T1 -> 2, then a selection at 2: T2 -> 3 -> T3 -> 1, T4 -> 4 -> T5 -> 1, T6 -> 5 (exit step).
Grafcet threeBranches()
{
    Grafcet g;
    addSteps(g, {1, 2, 3, 4, 5});
    add(g, 1, {1}, {2});
    add(g, 2, {2}, {3});
    add(g, 3, {3}, {1});
    add(g, 4, {2}, {4});
    add(g, 5, {4}, {1});
    add(g, 6, {2}, {5});
    return g;
}

} // namespace

TEST_CASE("moveBranch moves a selection branch one place left or right", "[branchorder]")
{
    Grafcet g = threeBranches();
    CHECK(canMoveBranch(g, 4, -1));
    CHECK(canMoveBranch(g, 4, +1));
    CHECK_FALSE(canMoveBranch(g, 3, -1)); // the leftmost branch
    CHECK_FALSE(canMoveBranch(g, 5, +1)); // the rightmost branch
    CHECK_FALSE(canMoveBranch(g, 1, -1)); // on no branch
    CHECK_FALSE(canMoveBranch(g, 2, +1)); // the divergence step itself
    CHECK_FALSE(canMoveBranch(g, 99, +1));

    REQUIRE(moveBranch(g, 4, -1).ok);
    CHECK(leaving(g, 2) == std::vector<int>{4, 2, 6});
    REQUIRE(moveBranch(g, 3, +1).ok);
    CHECK(leaving(g, 2) == std::vector<int>{4, 6, 2});
    CHECK(g.invariantViolations().empty());

    const Grafcet before = g;
    CHECK_FALSE(moveBranch(g, 3, +1).ok);
    CHECK_FALSE(moveBranch(g, 1, -1).ok);
    CHECK(g.sameContent(before));
}

TEST_CASE("moveBranch keeps the order of other steps' transitions", "[branchorder]")
{
    Grafcet g = threeBranches();
    REQUIRE(moveBranch(g, 5, -2).ok);
    CHECK(leaving(g, 2) == std::vector<int>{6, 2, 4});
    CHECK(leaving(g, 1) == std::vector<int>{1});
    CHECK(g.transitions().size() == 6);
    CHECK(g.transition(5)->upstream == std::vector<int>{4});
}

TEST_CASE("moveBranch moves a parallel branch and keeps the convergence in the same order", "[branchorder]")
{
    // 1 -> T1 -> {2, 4, 6}; 2 -> T2 -> 3, 4 -> T3 -> 5, 6 -> T4 -> 7; {3, 5, 7} -> T5 -> 8 -> T6 -> 1
    Grafcet g;
    addSteps(g, {1, 2, 3, 4, 5, 6, 7, 8});
    add(g, 1, {1}, {2, 4, 6});
    add(g, 2, {2}, {3});
    add(g, 3, {4}, {5});
    add(g, 4, {6}, {7});
    add(g, 5, {3, 5, 7}, {8});
    add(g, 6, {8}, {1});
    BranchPlace place;
    REQUIRE(findBranch(g, 5, place));
    CHECK(place.kind == BranchPlace::Kind::Parallel);
    CHECK(place.divergence == 1);
    CHECK(place.index == 1);
    CHECK(place.steps == std::vector<int>{4, 5});
    CHECK_FALSE(canMoveBranch(g, 8, 1));

    REQUIRE(moveBranch(g, 3, +1).ok);
    CHECK(g.transition(1)->downstream == std::vector<int>{4, 2, 6});
    CHECK(g.transition(5)->upstream == std::vector<int>{5, 3, 7});
    REQUIRE(moveBranch(g, 6, -2).ok);
    CHECK(g.transition(1)->downstream == std::vector<int>{6, 4, 2});
    CHECK(g.transition(5)->upstream == std::vector<int>{7, 5, 3});
}

TEST_CASE("moveBranch moves the innermost branch holding the step", "[branchorder]")
{
    // Selection at 2: T2 -> parallel {3, 4} joined by T4 into 5 -> T5 -> 1; T6 -> 6 (exit).
    Grafcet g;
    addSteps(g, {1, 2, 3, 4, 5, 6});
    add(g, 1, {1}, {2});
    add(g, 2, {2}, {3, 4});
    add(g, 4, {3, 4}, {5});
    add(g, 5, {5}, {1});
    add(g, 6, {2}, {6});
    BranchPlace place;
    REQUIRE(findBranch(g, 3, place));
    CHECK(place.kind == BranchPlace::Kind::Parallel);
    REQUIRE(findBranch(g, 5, place));
    CHECK(place.kind == BranchPlace::Kind::Selection);
    CHECK(place.divergence == 2);

    REQUIRE(moveBranch(g, 4, -1).ok); // the parallel branch, not the selection one
    CHECK(g.transition(2)->downstream == std::vector<int>{4, 3});
    CHECK(g.transition(4)->upstream == std::vector<int>{4, 3});
    CHECK(leaving(g, 2) == std::vector<int>{2, 6});
    REQUIRE(moveBranch(g, 5, +1).ok); // the selection branch
    CHECK(leaving(g, 2) == std::vector<int>{6, 2});
}

TEST_CASE("moveSelectionBranch moves a branch named by its first transition, a jump included", "[branchorder]")
{
    Grafcet g = threeBranches();
    add(g, 7, {2}, {1}); // a fourth branch without steps: a jump back to 1
    CHECK(canMoveSelectionBranch(g, 7, -1));
    CHECK_FALSE(canMoveSelectionBranch(g, 7, +1));
    CHECK_FALSE(canMoveSelectionBranch(g, 1, -1)); // leaves a step with one branch
    CHECK_FALSE(canMoveSelectionBranch(g, 99, -1));
    REQUIRE(moveSelectionBranch(g, 7, -2).ok);
    CHECK(leaving(g, 2) == std::vector<int>{2, 7, 4, 6});
    const Grafcet before = g;
    CHECK_FALSE(moveSelectionBranch(g, 2, -1).ok);
    CHECK(g.sameContent(before));
}

TEST_CASE("moveBranch moves the branches of a selection that never converges either way", "[branchorder]")
{
    // 1 -> T1 -> 2 and 1 -> T2 -> 3: two dead ends, no join.
    Grafcet g;
    addSteps(g, {1, 2, 3});
    add(g, 1, {1}, {2});
    add(g, 2, {1}, {3});
    REQUIRE(moveBranch(g, 3, -1).ok);
    CHECK(leaving(g, 1) == std::vector<int>{2, 1});
    CHECK(canMoveBranch(g, 3, +1));
    CHECK(canMoveBranch(g, 2, -1));
    REQUIRE(moveBranch(g, 3, +1).ok);
    CHECK(leaving(g, 1) == std::vector<int>{1, 2});
}

} // namespace test_branchorder
