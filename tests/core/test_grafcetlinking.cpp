// Linking two elements of a nested GRAFCET (core/model/grafcetlinking.h):
// each direction's meaning, every refusal with its code and the GRAFCET
// left as it was, and the drawings of linked GRAFCETs still clean.

#include "core/layout/grafcetlayout.h"
#include "core/model/grafcetlinking.h"
#include "grafcetlayoutchecks.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace test_grafcetlinking {

using namespace core;

namespace {

// 1 -> T1 -> 2 -> T2 -> 3 -> T3 -> 1, step 1 initial, and 4 -> T4 -> 5 apart.
Grafcet cycleAndPair()
{
    Grafcet g;
    for (int n = 1; n <= 5; ++n) {
        GrafcetStep step;
        step.number = n;
        step.initial = n == 1 || n == 4;
        REQUIRE(g.addStep(step).ok);
    }
    REQUIRE(g.addTransition({1, {1}, {2}, "a"}).ok);
    REQUIRE(g.addTransition({2, {2}, {3}, "b"}).ok);
    REQUIRE(g.addTransition({3, {3}, {1}, "c"}).ok);
    REQUIRE(g.addTransition({4, {4}, {5}, "d"}).ok);
    return g;
}

void requireCleanLayout(const Grafcet& g)
{
    REQUIRE(g.invariantViolations().empty());
    const GrafcetLayout layout = layoutGrafcet(g, grafcetlayoutchecks::fixedWidth);
    CHECK(grafcetlayoutchecks::violations(g, layout).empty());
}

void requireRefused(GrafcetLinkEnd from, GrafcetLinkEnd to, std::string_view code)
{
    Grafcet g = cycleAndPair();
    const Grafcet before = g;
    CHECK(checkLink(g, from, to).code == code);
    const Status status = link(g, from, to);
    CHECK_FALSE(status.ok);
    CHECK(status.code == code);
    CHECK(g.sameContent(before));
}

} // namespace

TEST_CASE("a step dropped on a transition joins its upstream steps", "[linking]")
{
    Grafcet g = cycleAndPair();
    REQUIRE(link(g, GrafcetLinkEnd::step(5), GrafcetLinkEnd::transition(2)).ok);
    CHECK(g.transition(2)->upstream == std::vector<int>{2, 5});
    CHECK(g.transition(2)->downstream == std::vector<int>{3});
    requireCleanLayout(g);
}

TEST_CASE("a transition dropped on a step gains it as a downstream step", "[linking]")
{
    Grafcet g = cycleAndPair();
    REQUIRE(link(g, GrafcetLinkEnd::transition(1), GrafcetLinkEnd::step(4)).ok);
    CHECK(g.transition(1)->upstream == std::vector<int>{1});
    CHECK(g.transition(1)->downstream == std::vector<int>{2, 4});
    requireCleanLayout(g);
}

TEST_CASE("a step dropped on a step gets a new TRUE transition to it", "[linking]")
{
    Grafcet g = cycleAndPair();
    GrafcetCreated created;
    REQUIRE(link(g, GrafcetLinkEnd::step(3), GrafcetLinkEnd::step(2), &created).ok);
    REQUIRE(created.transitions == std::vector<int>{5});
    const GrafcetTransition* jump = g.transition(5);
    CHECK(jump->upstream == std::vector<int>{3});
    CHECK(jump->downstream == std::vector<int>{2});
    CHECK(jump->receptivity == kNewTransitionReceptivity);
    requireCleanLayout(g);
}

TEST_CASE("links IEC 60848 does not allow are refused with their reason", "[linking]")
{
    requireRefused(GrafcetLinkEnd::transition(1), GrafcetLinkEnd::transition(2), kLinkTransitionToTransition);
    requireRefused(GrafcetLinkEnd::step(1), GrafcetLinkEnd::transition(1), kLinkExists);
    requireRefused(GrafcetLinkEnd::transition(1), GrafcetLinkEnd::step(2), kLinkExists);
    requireRefused(GrafcetLinkEnd::step(1), GrafcetLinkEnd::step(2), kLinkExists);
    requireRefused(GrafcetLinkEnd::step(2), GrafcetLinkEnd::transition(1), kLinkStepToItself);
    requireRefused(GrafcetLinkEnd::transition(1), GrafcetLinkEnd::step(1), kLinkStepToItself);
    requireRefused(GrafcetLinkEnd::step(3), GrafcetLinkEnd::step(3), kLinkStepToItself);
    requireRefused(GrafcetLinkEnd::step(9), GrafcetLinkEnd::transition(1), kLinkUnknownElement);
}

} // namespace test_grafcetlinking
