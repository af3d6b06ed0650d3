#include "core/formats/modelfiles.h"
#include "core/layout/grafcetlayout.h"
#include "core/model/grafcet.h"
#include "core/model/model.h"
#include "grafcetlayoutchecks.h"
#include "samplemodels.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace test_grafcetlayout {

using namespace core;

namespace {

using grafcetlayoutchecks::fixedWidth;
using grafcetlayoutchecks::violations;
const TextMeasure kMeasure = fixedWidth;

// GGSTUDIO_GRAFCET_SVG=<dir>: each checked layout is also written there, to look at.
void dumpSvg(const GrafcetLayout& layout, const std::string& name)
{
    const char* dir = std::getenv("GGSTUDIO_GRAFCET_SVG");
    if (!dir)
        return;
    std::ofstream out(std::string(dir) + "/" + name + ".svg");
    const Rect& b = layout.boundingRect;
    out << "<svg xmlns='http://www.w3.org/2000/svg' viewBox='" << b.x << " " << b.y << " " << b.width << " " << b.height
        << "' width='" << b.width << "' height='" << b.height << "' font-family='monospace' font-size='11'>\n"
        << "<rect x='" << b.x << "' y='" << b.y << "' width='" << b.width << "' height='" << b.height << "' fill='white'/>\n";
    const auto rect = [&](const Rect& r, const char* style) {
        out << "<rect x='" << r.x << "' y='" << r.y << "' width='" << r.width << "' height='" << r.height << "' " << style << "/>\n";
    };
    const auto text = [&](double x, double y, const std::string& s) {
        std::string escaped;
        for (char c : s)
            escaped += c == '<' ? std::string("&lt;") : c == '&' ? std::string("&amp;") : std::string(1, c);
        out << "<text x='" << x << "' y='" << y << "'>" << escaped << "</text>\n";
    };
    for (const GrafcetStepLayout& step : layout.steps) {
        rect(step.box, "fill='none' stroke='black'");
        if (step.initial)
            rect(step.box.adjusted(-4), "fill='none' stroke='black'");
        text(step.box.x + 6, step.box.center().y + 4, std::to_string(step.number));
        if (step.actionLink.size() == 2)
            out << "<line x1='" << step.actionLink[0].x << "' y1='" << step.actionLink[0].y << "' x2='" << step.actionLink[1].x
                << "' y2='" << step.actionLink[1].y << "' stroke='black'/>\n";
        for (const GrafcetActionLayout& action : step.actions) {
            rect(action.box, "fill='none' stroke='black'");
            if (action.qualifierCell.width > 0) {
                rect(action.qualifierCell, "fill='none' stroke='black'");
                text(action.qualifierCell.x + 4, action.box.center().y + 4, action.qualifier);
            }
            text(action.textCell.x + 6, action.box.center().y + 4, action.text);
            if (!action.condition.empty())
                text(action.conditionRect.x + 4, action.conditionRect.bottom() - 4, action.condition);
        }
    }
    const auto& grafcetTexts = layout.transitions;
    for (const GrafcetTransitionLayout& t : grafcetTexts) {
        out << "<line x1='" << t.barCenter.x - kGrafcetBarLength / 2 << "' y1='" << t.barCenter.y << "' x2='"
            << t.barCenter.x + kGrafcetBarLength / 2 << "' y2='" << t.barCenter.y << "' stroke='black' stroke-width='3'/>\n";
        rect(t.labelRect, "fill='none' stroke='#ccc'");
        text(t.labelRect.x + 4, t.labelRect.bottom() - 5, "T" + std::to_string(t.number));
    }
    for (const GrafcetLinkLayout& link : layout.links) {
        out << "<polyline fill='none' stroke='" << (link.ending == GrafcetLinkLayout::Ending::Loop ? "blue" : "black")
            << "' points='";
        for (const Point& p : link.route)
            out << p.x << "," << p.y << " ";
        out << "'/>\n";
        if (link.ending == GrafcetLinkLayout::Ending::Jump)
            text(link.labelRect.x + 4, link.labelRect.bottom() - 5, "->" + std::to_string(link.step));
        if (link.fromReference)
            text(link.referenceRect.x + 4, link.referenceRect.bottom() - 5, std::to_string(link.step));
    }
    for (const GrafcetBranchLineLayout& line : layout.lines) {
        const bool simultaneous = line.kind == GrafcetBranchLineLayout::Kind::SimultaneousDivergence
                               || line.kind == GrafcetBranchLineLayout::Kind::SimultaneousConvergence;
        for (int k = 0; k < (simultaneous ? 2 : 1); ++k)
            out << "<line x1='" << line.left << "' y1='" << line.y + k * kDoubleLineGap << "' x2='" << line.right
                << "' y2='" << line.y + k * kDoubleLineGap << "' stroke='" << (simultaneous ? "green" : "red") << "'/>\n";
    }
    out << "</svg>\n";
}

void checkLayout(const Grafcet& grafcet, const std::string& name)
{
    const GrafcetLayout layout = layoutGrafcet(grafcet, kMeasure);
    dumpSvg(layout, name);
    INFO(name);
    const std::vector<std::string> problems = violations(grafcet, layout);
    for (const std::string& problem : problems)
        UNSCOPED_INFO(problem);
    CHECK(problems.empty());
}

GrafcetStep makeStep(int number, std::vector<std::string> actions = {}, bool initial = false)
{
    GrafcetStep step;
    step.number = number;
    step.initial = initial;
    for (std::string& text : actions)
        step.actions.push_back({ActionTiming::Continuous, std::move(text)});
    return step;
}

void add(Grafcet& grafcet, GrafcetStep step) { REQUIRE(grafcet.addStep(std::move(step)).ok); }
void add(Grafcet& grafcet, int number, std::vector<int> up, std::vector<int> down, std::string receptivity)
{
    REQUIRE(grafcet.addTransition({number, std::move(up), std::move(down), std::move(receptivity)}).ok);
}

// The shape of the case study's F2 figure (spec grafcet-layer.md §6): a
// sequence 1-2-3, a selection of four branches, the second a parallel
// section of two sequences, the fourth ending on step 11; the first three
// converge on step 12, which loops back to 1.
Grafcet referenceFigure()
{
    Grafcet g;
    add(g, makeStep(1, {"h+", "b+"}, true));
    add(g, makeStep(2, {"h-", "b-"}));
    add(g, makeStep(3));
    add(g, makeStep(4, {"a+"}));
    add(g, makeStep(5, {"a-"}));
    add(g, makeStep(7, {"a+"}));
    add(g, makeStep(8, {"a-"}));
    add(g, makeStep(9, {"c+", "d+"}));
    add(g, makeStep(10, {"c-"}));
    add(g, makeStep(11, {"Complete"}));
    add(g, makeStep(12));
    add(g, 1, {1}, {2}, "h1 AND b1");
    add(g, 2, {2}, {3}, "h0 AND b0");
    add(g, 3, {3}, {4}, "CP1 AND NOT CP2");
    add(g, 4, {3}, {7, 9}, "CP1 AND CP2 AND NOT CP3");
    add(g, 5, {3}, {12}, "NOT CP1");
    add(g, 6, {3}, {11}, "CP1 AND CP2 AND CP3");
    add(g, 7, {4}, {5}, "a1");
    add(g, 8, {5}, {12}, "a0");
    add(g, 9, {7}, {8}, "a1");
    add(g, 10, {9}, {10}, "c1");
    add(g, 11, {8, 10}, {12}, "a0 AND c0");
    add(g, 12, {12}, {1}, "TRUE");
    return g;
}

} // namespace

TEST_CASE("GRAFCET layout: the reference figure's shape", "[layout][grafcet-layout]")
{
    const Grafcet g = referenceFigure();
    checkLayout(g, "reference-figure");
    const GrafcetLayout layout = layoutGrafcet(g, kMeasure);
    const auto box = [&](int n) { return layout.step(n)->box; };
    const auto bar = [&](int t) { return layout.transition(t)->barCenter; };

    // The sequence 1-2-3 goes straight down; 1 is drawn as initial.
    CHECK(layout.step(1)->initial);
    CHECK_FALSE(layout.step(2)->initial);
    CHECK(box(1).center().x == box(2).center().x);
    CHECK(box(2).center().x == box(3).center().x);
    CHECK(box(1).bottom() < bar(1).y);
    CHECK(bar(1).y < box(2).top());
    CHECK(box(2).bottom() < bar(2).y);
    CHECK(bar(2).y < box(3).top());

    // The four branches of the selection stand left to right, below 3, the
    // first straight under it.
    CHECK(bar(3).x == box(3).center().x);
    CHECK(bar(3).x < bar(4).x);
    CHECK(bar(4).x < bar(5).x);
    CHECK(bar(5).x < bar(6).x);
    for (int t : {3, 4, 5, 6})
        CHECK(bar(t).y == bar(3).y);
    CHECK(bar(3).y > box(3).bottom());
    const auto selection = std::find_if(layout.lines.begin(), layout.lines.end(), [](const GrafcetBranchLineLayout& l) {
        return l.kind == GrafcetBranchLineLayout::Kind::SelectionDivergence;
    });
    REQUIRE(selection != layout.lines.end());
    CHECK(selection->step == 3);
    CHECK(selection->branches == std::vector<int>{3, 4, 5, 6});
    CHECK(selection->left == bar(3).x);
    CHECK(selection->right == bar(6).x);
    CHECK(selection->y > box(3).bottom());
    CHECK(selection->y < bar(3).y);

    // Branch 1: 4 above 5; the parallel section: 7 and 9 side by side under
    // the double line, 8 under 7, 10 under 9, all between branch 1 and branch 3.
    CHECK(box(4).center().x == bar(3).x);
    CHECK(box(4).bottom() < box(5).top());
    CHECK(box(7).top() == box(9).top());
    CHECK(box(7).center().x < box(9).center().x);
    CHECK(box(8).center().x == box(7).center().x);
    CHECK(box(10).center().x == box(9).center().x);
    CHECK(box(7).bottom() < box(8).top());
    CHECK(box(9).bottom() < box(10).top());
    CHECK(box(7).center().x == bar(4).x);
    CHECK(layout.step(9)->actions.back().box.right() < bar(5).x);
    CHECK(layout.step(5)->actions.back().box.right() < box(7).left());
    const auto parallel = std::find_if(layout.lines.begin(), layout.lines.end(), [](const GrafcetBranchLineLayout& l) {
        return l.kind == GrafcetBranchLineLayout::Kind::SimultaneousDivergence;
    });
    REQUIRE(parallel != layout.lines.end());
    CHECK(parallel->transition == 4);
    CHECK(parallel->y > bar(4).y);
    CHECK(parallel->y + kDoubleLineGap < box(7).top());
    CHECK(parallel->left < box(7).center().x);
    CHECK(parallel->right > box(9).center().x);
    const auto closing = std::find_if(layout.lines.begin(), layout.lines.end(), [](const GrafcetBranchLineLayout& l) {
        return l.kind == GrafcetBranchLineLayout::Kind::SimultaneousConvergence;
    });
    REQUIRE(closing != layout.lines.end());
    CHECK(closing->transition == 11);
    CHECK(closing->branches == std::vector<int>{8, 10});
    CHECK(closing->y > box(10).bottom());
    CHECK(bar(11).y > closing->y + kDoubleLineGap);
    CHECK(bar(11).x == box(7).center().x);

    // Branch 4 ends on 11; the first three converge on 12, under everything.
    CHECK(box(11).center().x == bar(6).x);
    const auto convergence = std::find_if(layout.lines.begin(), layout.lines.end(), [](const GrafcetBranchLineLayout& l) {
        return l.kind == GrafcetBranchLineLayout::Kind::SelectionConvergence;
    });
    REQUIRE(convergence != layout.lines.end());
    CHECK(convergence->step == 12);
    CHECK(convergence->branches == std::vector<int>{8, 11, 5});
    CHECK(convergence->y > bar(11).y);
    CHECK(convergence->y > bar(8).y);
    CHECK(box(12).top() > convergence->y);
    CHECK(box(12).center().x == box(3).center().x);

    // The loop back to 1 goes up on the left, arrowhead on 1.
    const auto loop = std::find_if(layout.links.begin(), layout.links.end(), [](const GrafcetLinkLayout& l) {
        return l.kind == GrafcetLinkLayout::Kind::TransitionToStep && l.transition == 12;
    });
    REQUIRE(loop != layout.links.end());
    CHECK(loop->ending == GrafcetLinkLayout::Ending::Loop);
    CHECK(loop->route.back() == Point{box(1).center().x, box(1).top()});
    int upwards = 0;
    for (std::size_t i = 0; i + 1 < loop->route.size(); ++i) {
        if (loop->route[i + 1].y >= loop->route[i].y)
            continue;
        ++upwards;
        for (const GrafcetStepLayout& step : layout.steps)
            CHECK(loop->route[i].x < step.box.left());
    }
    CHECK(upwards == 1);

    // Actions: one cell each, to the right, in order; widths from the measure.
    const GrafcetStepLayout& one = *layout.step(1);
    REQUIRE(one.actions.size() == 2);
    CHECK(one.actions[0].text == "h+");
    CHECK(one.actions[0].qualifier.empty());
    CHECK(one.actions[0].box.left() > one.box.right());
    CHECK(one.actions[1].box.left() == one.actions[0].box.right());
    CHECK(layout.transition(1)->labelRect.width == fixedWidth("h1 AND b1") + 8);
}

TEST_CASE("GRAFCET layout: action boxes, qualifiers and conditions", "[layout][grafcet-layout]")
{
    Grafcet g;
    GrafcetStep step = makeStep(1, {"N Valve IF Level < 10 AND NOT Full", "Lamp", "N Motor"}, true);
    step.actions.push_back({ActionTiming::OnActivation, "S Alarm"});
    step.actions.push_back({ActionTiming::OnActivation, "Count := Count + 1"});
    step.actions.push_back({ActionTiming::OnDeactivation, "R Alarm"});
    step.actions.push_back({ActionTiming::OnActivation, "S := 3"});
    add(g, step);
    add(g, makeStep(2, {"Fan if Hot"}));
    add(g, 1, {1}, {2}, "Start");
    add(g, 2, {2}, {1}, "Stop");
    checkLayout(g, "actions");
    const GrafcetLayout layout = layoutGrafcet(g, kMeasure);
    const auto& actions = layout.step(1)->actions;
    REQUIRE(actions.size() == 7);
    CHECK(actions[0].qualifier.empty());
    CHECK(actions[0].text == "Valve");
    CHECK(actions[0].condition == "Level < 10 AND NOT Full");
    CHECK(actions[0].conditionRect.top() >= actions[0].box.bottom());
    CHECK(actions[0].textCell.width >= fixedWidth("Level < 10 AND NOT Full"));
    CHECK(actions[1].text == "Lamp");
    CHECK(actions[1].condition.empty());
    CHECK(actions[2].qualifier.empty());
    CHECK(actions[2].text == "Motor");
    CHECK(actions[3].qualifier == "\xE2\x86\x91S");
    CHECK(actions[3].text == "Alarm");
    CHECK(actions[3].qualifierCell.width > 0);
    CHECK(actions[4].qualifier == "\xE2\x86\x91");
    CHECK(actions[4].text == "Count := Count + 1");
    CHECK(actions[4].textCell.width >= fixedWidth("Count := Count + 1"));
    CHECK(actions[5].qualifier == "\xE2\x86\x93R");
    CHECK(actions[6].qualifier == "\xE2\x86\x91");
    CHECK(actions[6].text == "S := 3");
    for (std::size_t i = 1; i < actions.size(); ++i)
        CHECK(actions[i].box.left() == actions[i - 1].box.right());
    CHECK(layout.step(2)->actions[0].condition == "Hot");
    // The transition under step 1 is below its conditions.
    CHECK(layout.transition(1)->labelRect.top() > actions[0].conditionRect.bottom());
}

TEST_CASE("GRAFCET layout: the shipped example's GRAFCETs", "[layout][grafcet-layout][example]")
{
    const auto loaded = loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    REQUIRE(loaded.model);
    REQUIRE(loaded.model->grafcets().size() == 4);
    int loops = 0;
    int parallel = 0;
    int selections = 0;
    for (const auto& [id, grafcet] : loaded.model->grafcets()) {
        checkLayout(grafcet, "drilling-cell-" + id);
        const GrafcetLayout layout = layoutGrafcet(grafcet, kMeasure);
        for (const GrafcetLinkLayout& link : layout.links)
            loops += link.ending == GrafcetLinkLayout::Ending::Loop ? 1 : 0;
        for (const GrafcetBranchLineLayout& line : layout.lines) {
            parallel += line.kind == GrafcetBranchLineLayout::Kind::SimultaneousDivergence ? 1 : 0;
            selections += line.kind == GrafcetBranchLineLayout::Kind::SelectionDivergence ? 1 : 0;
        }
        for (const GrafcetTransitionLayout& t : layout.transitions)
            CHECK_FALSE(t.detached); // the example is structured: everything joins
    }
    CHECK(loops >= 1);
    CHECK(parallel >= 1);
    CHECK(selections >= 1);
}

TEST_CASE("GRAFCET layout: random valid GRAFCETs", "[layout][grafcet-layout][random]")
{
    int grafcets = 0;
    int loops = 0;
    int jumps = 0;
    int parallelInSelection = 0;
    int detached = 0;
    for (std::uint32_t seed = 1; seed <= 80; ++seed) {
        Model model = samples::randomModel(seed);
        std::mt19937 random(seed);
        samples::addValidRandomNestedGrafcets(model, random);
        for (const auto& [id, grafcet] : model.grafcets()) {
            ++grafcets;
            checkLayout(grafcet, "valid-" + std::to_string(seed) + "-" + id);
            const GrafcetLayout layout = layoutGrafcet(grafcet, kMeasure);
            for (const GrafcetLinkLayout& link : layout.links) {
                loops += link.ending == GrafcetLinkLayout::Ending::Loop ? 1 : 0;
                jumps += link.ending == GrafcetLinkLayout::Ending::Jump ? 1 : 0;
            }
            for (const GrafcetTransitionLayout& t : layout.transitions)
                detached += t.detached ? 1 : 0;
            // A double line between the divergence and convergence of a selection.
            for (const GrafcetBranchLineLayout& s : layout.lines) {
                if (s.kind != GrafcetBranchLineLayout::Kind::SelectionDivergence)
                    continue;
                for (const GrafcetBranchLineLayout& p : layout.lines) {
                    if (p.kind == GrafcetBranchLineLayout::Kind::SimultaneousDivergence && p.y > s.y)
                        ++parallelInSelection;
                }
            }
        }
    }
    INFO(grafcets << " GRAFCETs, " << loops << " loops, " << jumps << " jumps, " << detached << " detached");
    CHECK(grafcets >= 200);
    CHECK(loops >= 50);
    CHECK(jumps >= 20);
    CHECK(parallelInSelection >= 10);
}

// Found by structured editing's random edits: 6 opens a selection inside the
// first branch of 3's; its first branch loops back to 1, its main branch to 3.
// Both lines come out of the same block of the column, so which leaves lower
// is unknown when channels are given: one of them is a jump.
TEST_CASE("GRAFCET layout: two loops out of one selection of a column", "[layout][grafcet-layout]")
{
    Grafcet g;
    for (int n : {1, 3, 6, 7, 9, 8, 10, 13, 12, 2, 4, 14})
        add(g, makeStep(n, {}, n == 1));
    add(g, 4, {3}, {6}, "a");
    add(g, 19, {13}, {3}, "b");
    add(g, 8, {14}, {7}, "c");
    add(g, 12, {8}, {9}, "d");
    add(g, 10, {7}, {8}, "e");
    add(g, 14, {9}, {10}, "f");
    add(g, 15, {10}, {1}, "g");
    add(g, 18, {12}, {13}, "h");
    add(g, 2, {1}, {2}, "i");
    add(g, 3, {2}, {3}, "j");
    add(g, 5, {3}, {4}, "k");
    add(g, 20, {6}, {14}, "l");
    add(g, 23, {6}, {12}, "m");
    checkLayout(g, "two-loops-one-selection");
    int loops = 0;
    for (const GrafcetLinkLayout& link : layoutGrafcet(g, kMeasure).links)
        loops += link.ending == GrafcetLinkLayout::Ending::Loop ? 1 : 0;
    CHECK(loops == 1);
}

TEST_CASE("GRAFCET layout: random GRAFCETs with errors, and odd shapes", "[layout][grafcet-layout][random]")
{
    for (std::uint32_t seed = 1; seed <= 40; ++seed) {
        Model model = samples::randomModel(seed);
        samples::addRandomNestedGrafcets(model, seed);
        for (const auto& [id, grafcet] : model.grafcets())
            checkLayout(grafcet, "any-" + std::to_string(seed) + "-" + id);
    }

    // No initial step, an unreachable step, a convergence from unrelated
    // steps, a parallel section whose branches never join, a jump into a
    // branch, two initial steps, a step number of six digits.
    Grafcet g;
    add(g, makeStep(1, {"A"}));
    add(g, makeStep(2));
    add(g, makeStep(3, {"B IF C"}));
    add(g, makeStep(4));
    add(g, makeStep(5));
    add(g, makeStep(6));
    add(g, makeStep(123456));
    add(g, 1, {1}, {2, 3}, "go");
    add(g, 2, {2}, {4}, "x");
    add(g, 3, {4, 5}, {1, 3}, "y");
    add(g, 4, {3}, {4}, "z");
    add(g, 5, {123456}, {2}, "w");
    add(g, 6, {6}, {6}, "self");
    checkLayout(g, "odd");
    const GrafcetLayout odd = layoutGrafcet(g, kMeasure);
    CHECK(odd.transition(3)->detached);
    CHECK(odd.step(123456)->box.width > kGrafcetStepSize);
    REQUIRE(g.setInitialSteps({1, 6}).ok);
    checkLayout(g, "odd-initial");

    const Grafcet none;
    const GrafcetLayout emptyLayout = layoutGrafcet(none, kMeasure);
    CHECK(emptyLayout.steps.empty());
    CHECK(emptyLayout.boundingRect.width > 0);
}

TEST_CASE("GRAFCET layout: a large structured GRAFCET", "[layout][grafcet-layout]")
{
    // Blocks from the initial step: a three-way selection whose second branch
    // is a parallel section (one of its sequences holding a selection with a
    // loop), converging on a step; then a step that repeats (a loop) or goes
    // on. The end loops back to step 1.
    Grafcet g;
    int transition = 1;
    const auto step = [&](int number) {
        GrafcetStep s = makeStep(number, {"Out" + std::to_string(number % 5) + (number % 4 == 0 ? " IF In1" : "")}, number == 1);
        REQUIRE(g.addStep(std::move(s)).ok);
        return number;
    };
    const auto link = [&](std::vector<int> up, std::vector<int> down) {
        add(g, transition, std::move(up), std::move(down), "In" + std::to_string(transition % 9));
        ++transition;
    };
    int at = step(1);
    int next = 2;
    for (int block = 0; block < 12; ++block) {
        const int a1 = step(next++), a2 = step(next++);
        const int b1 = step(next++), b2 = step(next++), b3 = step(next++), c1 = step(next++);
        const int d1 = step(next++), join = step(next++), body = step(next++), after = step(next++);
        link({at}, {a1});
        link({a1}, {a2});
        link({a2}, {join});
        link({at}, {b1, c1});
        link({b1}, {b2}); // b2 repeats back to b1 or goes on to b3
        link({b2}, {b1});
        link({b2}, {b3});
        link({b3, c1}, {join});
        link({at}, {d1});
        link({d1}, {join});
        link({join}, {body});
        link({body}, {join});
        link({body}, {after});
        at = after;
    }
    link({at}, {1});
    REQUIRE(g.steps().size() == 121);
    checkLayout(g, "large");
    const GrafcetLayout layout = layoutGrafcet(g, kMeasure);
    int loops = 0;
    int jumps = 0;
    for (const GrafcetTransitionLayout& t : layout.transitions)
        CHECK_FALSE(t.detached);
    for (const GrafcetLinkLayout& link : layout.links) {
        loops += link.ending == GrafcetLinkLayout::Ending::Loop ? 1 : 0;
        jumps += link.ending == GrafcetLinkLayout::Ending::Jump ? 1 : 0;
    }
    // Every way back is a loop line: the repeating steps, the loops in the
    // parallel branches, the end around all of them.
    CHECK(loops == 25);
    CHECK(jumps == 0);
    // The main path goes straight down: every join under the initial step.
    for (const GrafcetStepLayout& s : layout.steps) {
        if (s.number % 10 == 9) // the joins
            CHECK(s.box.center().x == layout.step(1)->box.center().x);
    }
}

} // namespace test_grafcetlayout
