#include "grafcetlayoutchecks.h"

#include "routegeometry.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

using namespace core;

namespace {

using routegeometry::crosses;
using routegeometry::Segment;
using routegeometry::segmentEnters;

std::string describe(Point p)
{
    std::ostringstream out;
    out << "(" << p.x << ", " << p.y << ")";
    return out.str();
}

std::string describe(const Rect& r)
{
    std::ostringstream out;
    out << "[" << r.x << ", " << r.y << " " << r.width << "x" << r.height << "]";
    return out.str();
}

bool empty(const Rect& r) { return r.width == 0 && r.height == 0; }

Point bottomMiddle(const Rect& r) { return {r.center().x, r.bottom()}; }
Point topMiddle(const Rect& r) { return {r.center().x, r.top()}; }

double distance(Point p, const Rect& r)
{
    const double dx = std::max({r.left() - p.x, 0.0, p.x - r.right()});
    const double dy = std::max({r.top() - p.y, 0.0, p.y - r.bottom()});
    return std::hypot(dx, dy);
}

Rect barRect(const GrafcetTransitionLayout& t)
{
    return {t.barCenter.x - kGrafcetBarLength / 2, t.barCenter.y - 1, kGrafcetBarLength, 2};
}

std::string linkName(const GrafcetLinkLayout& link)
{
    return link.kind == GrafcetLinkLayout::Kind::StepToTransition
        ? "link " + std::to_string(link.step) + "->T" + std::to_string(link.transition)
        : "link T" + std::to_string(link.transition) + "->" + std::to_string(link.step);
}

// Whether the line is part of the drawing of the link (the links of a
// divergence or convergence run along its line and cross the double one).
bool lineOwns(const GrafcetBranchLineLayout& line, const GrafcetLinkLayout& link)
{
    return (line.transition != 0 && link.transition == line.transition) || (line.step != 0 && link.step == line.step);
}

// A convergence whose branches go on as one link back up (a loop or a jump) to its step.
bool goesBack(const GrafcetLayout& layout, const GrafcetBranchLineLayout& line)
{
    int back = 0;
    for (const GrafcetLinkLayout& link : layout.links) {
        const bool ofLine = link.kind == GrafcetLinkLayout::Kind::TransitionToStep && link.step == line.step
                         && std::find(line.branches.begin(), line.branches.end(), link.transition) != line.branches.end();
        if (!ofLine)
            continue;
        if (link.ending == GrafcetLinkLayout::Ending::Plain)
            return false;
        ++back;
    }
    return back > 0;
}

struct Obstacle {
    Rect rect;
    std::string owner;
};

} // namespace

namespace grafcetlayoutchecks {

double fixedWidth(std::string_view text)
{
    return 7.0 * static_cast<double>(std::count_if(text.begin(), text.end(), [](char c) {
        return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    }));
}

std::vector<std::string> violations(const Grafcet& grafcet, const GrafcetLayout& layout)
{
    std::vector<std::string> found;
    const auto fail = [&](std::string text) {
        if (found.size() < 20)
            found.push_back(std::move(text));
    };

    // Everything is drawn, once, in the model's order.
    if (layout.steps.size() != grafcet.steps().size() || layout.transitions.size() != grafcet.transitions().size()) {
        fail("not every step and transition is laid out");
        return found;
    }
    for (std::size_t i = 0; i < layout.steps.size(); ++i) {
        const GrafcetStepLayout& step = layout.steps[i];
        if (step.number != grafcet.steps()[i].number || step.initial != grafcet.steps()[i].initial)
            fail("step " + std::to_string(step.number) + " out of order or initial flag wrong");
        if (step.box.width < kGrafcetStepSize || step.box.width != step.box.height)
            fail("step " + std::to_string(step.number) + " box not a square of at least the step size");
        if (step.actions.size() != grafcet.steps()[i].actions.size())
            fail("step " + std::to_string(step.number) + ": not every action has a box");
    }
    for (std::size_t i = 0; i < layout.transitions.size(); ++i) {
        if (layout.transitions[i].number != grafcet.transitions()[i].number)
            fail("transition order");
    }

    // The rectangles: boxes and labels never overlap.
    std::vector<Obstacle> obstacles;
    for (const GrafcetStepLayout& step : layout.steps) {
        const std::string name = "step " + std::to_string(step.number);
        obstacles.push_back({step.box, name});
        double x = step.box.right();
        for (const GrafcetActionLayout& action : step.actions) {
            const std::string actionName = name + " action " + std::to_string(action.index);
            obstacles.push_back({action.box, actionName});
            if (action.box.left() < x)
                fail(actionName + " not right of the step box and of the previous action");
            if (action.box.center().y != step.box.center().y)
                fail(actionName + " not centred on the step");
            if (action.qualifier.empty() != (action.qualifierCell.width == 0))
                fail(actionName + ": a qualifier cell exactly when there is a qualifier");
            if (!action.box.contains(action.qualifierCell) && action.qualifierCell.width > 0)
                fail(actionName + ": qualifier cell outside the box");
            if (!action.box.contains(action.textCell) || action.textCell.left() != action.qualifierCell.right())
                fail(actionName + ": text cell not beside the qualifier cell in the box");
            if (action.condition.empty() != empty(action.conditionRect))
                fail(actionName + ": a condition rectangle exactly when there is a condition");
            if (!action.condition.empty()) {
                obstacles.push_back({action.conditionRect, actionName + " condition"});
                if (action.conditionRect.top() < action.box.bottom() || action.conditionRect.left() < action.textCell.left()
                    || action.conditionRect.right() > action.textCell.right())
                    fail(actionName + ": condition not under its cell");
            }
            x = action.box.right();
        }
        if (!step.actions.empty()) {
            const Point a = step.actionLink.size() == 2 ? step.actionLink[0] : Point{};
            const Point b = step.actionLink.size() == 2 ? step.actionLink[1] : Point{};
            if (step.actionLink.size() != 2 || a != Point{step.box.right(), step.box.center().y}
                || b != Point{step.actions.front().box.left(), step.box.center().y})
                fail(name + ": the action link does not join the box and the first action");
        }
    }
    for (const GrafcetTransitionLayout& t : layout.transitions) {
        const std::string name = "transition " + std::to_string(t.number);
        obstacles.push_back({t.labelRect, name + " label"});
        if (t.labelRect.left() < t.barCenter.x + kGrafcetBarLength / 2 || t.labelRect.top() > t.barCenter.y
            || t.labelRect.bottom() < t.barCenter.y)
            fail(name + ": label not to the right of the bar");
    }
    std::set<std::tuple<int, double, double>> sharedJumps; // the branches of a convergence share one arrow
    for (const GrafcetLinkLayout& link : layout.links) {
        if (link.ending == GrafcetLinkLayout::Ending::Jump
            && sharedJumps.emplace(link.step, link.labelRect.x, link.labelRect.y).second)
            obstacles.push_back({link.labelRect, linkName(link) + " jump label"});
        if (link.fromReference)
            obstacles.push_back({link.referenceRect, linkName(link) + " reference"});
    }
    for (std::size_t i = 0; i < obstacles.size(); ++i) {
        for (std::size_t j = i + 1; j < obstacles.size(); ++j) {
            if (obstacles[i].rect.intersects(obstacles[j].rect))
                fail(obstacles[i].owner + " " + describe(obstacles[i].rect) + " overlaps " + obstacles[j].owner + " "
                     + describe(obstacles[j].rect));
        }
        for (const GrafcetTransitionLayout& t : layout.transitions) {
            if (barRect(t).intersects(obstacles[i].rect))
                fail("the bar of transition " + std::to_string(t.number) + " overlaps " + obstacles[i].owner);
        }
    }

    // The links: orthogonal, joining their ends, each once.
    std::vector<Segment> segments;
    std::vector<std::size_t> linkOf; // index of the link of each segment (npos: not a link)
    std::multiset<std::string> linkNames;
    for (std::size_t l = 0; l < layout.links.size(); ++l) {
        const GrafcetLinkLayout& link = layout.links[l];
        const std::string name = linkName(link);
        linkNames.insert(name);
        const GrafcetTransition* transition = grafcet.transition(link.transition);
        const GrafcetStepLayout* step = layout.step(link.step);
        const GrafcetTransitionLayout* bar = layout.transition(link.transition);
        if (!transition || !step || !bar || link.route.size() < 2) {
            fail(name + ": unknown ends or no route");
            continue;
        }
        for (std::size_t i = 0; i + 1 < link.route.size(); ++i) {
            const Point a = link.route[i];
            const Point b = link.route[i + 1];
            if (a.x != b.x && a.y != b.y)
                fail(name + ": not orthogonal at " + describe(a));
            segments.push_back({a, b, name});
            linkOf.push_back(l);
        }
        const bool down = std::adjacent_find(link.route.begin(), link.route.end(), [](Point a, Point b) {
                              return b.y < a.y;
                          }) == link.route.end();
        if (link.kind == GrafcetLinkLayout::Kind::StepToTransition) {
            const auto& up = transition->upstream;
            if (std::find(up.begin(), up.end(), link.step) == up.end())
                fail(name + ": the step is not upstream of the transition");
            const Point start = link.fromReference ? bottomMiddle(link.referenceRect) : bottomMiddle(step->box);
            if (link.route.front() != start)
                fail(name + ": does not start at the bottom of " + (link.fromReference ? "its reference" : "the step box")
                     + ": " + describe(link.route.front()));
            if (link.route.back() != bar->barCenter)
                fail(name + ": does not end on the bar");
            if (!down)
                fail(name + ": goes up");
            if (link.ending != GrafcetLinkLayout::Ending::Plain)
                fail(name + ": a step-to-transition link ends plainly");
            if (link.fromReference != bar->detached)
                fail(name + ": reference labels exactly for detached transitions");
        } else {
            const auto& downstream = transition->downstream;
            if (std::find(downstream.begin(), downstream.end(), link.step) == downstream.end())
                fail(name + ": the step is not downstream of the transition");
            if (link.route.front() != bar->barCenter)
                fail(name + ": does not start on the bar");
            switch (link.ending) {
            case GrafcetLinkLayout::Ending::Plain:
                if (link.route.back() != topMiddle(step->box))
                    fail(name + ": does not end on the top of the step box");
                if (!down)
                    fail(name + ": goes up");
                break;
            case GrafcetLinkLayout::Ending::Loop: {
                if (link.route.back() != topMiddle(step->box))
                    fail(name + ": loop arrowhead not on the top of the target box");
                if (down)
                    fail(name + ": a loop line that does not go up");
                const Point last = link.route[link.route.size() - 2];
                if (last.x != link.route.back().x || last.y >= link.route.back().y)
                    fail(name + ": a loop line does not enter its target from above");
                break;
            }
            case GrafcetLinkLayout::Ending::Jump:
                if (!down)
                    fail(name + ": a jump arrow that goes up");
                if (empty(link.labelRect) || distance(link.route.back(), link.labelRect) > 8)
                    fail(name + ": no target number at the jump arrow");
                break;
            }
        }
    }
    for (const GrafcetTransition& t : grafcet.transitions()) {
        for (int up : t.upstream) {
            const std::string name = "link " + std::to_string(up) + "->T" + std::to_string(t.number);
            if (linkNames.count(name) != 1)
                fail(name + " drawn " + std::to_string(linkNames.count(name)) + " times");
        }
        for (int d : t.downstream) {
            const std::string name = "link T" + std::to_string(t.number) + "->" + std::to_string(d);
            if (linkNames.count(name) != 1)
                fail(name + " drawn " + std::to_string(linkNames.count(name)) + " times");
        }
    }
    const std::size_t linkSegments = segments.size();
    for (const GrafcetStepLayout& step : layout.steps) {
        if (step.actionLink.size() == 2) {
            segments.push_back({step.actionLink[0], step.actionLink[1], "action link of " + std::to_string(step.number)});
            linkOf.push_back(std::string::npos);
        }
    }
    // Segments touch no box or label; bars only their own links.
    for (std::size_t s = 0; s < segments.size(); ++s) {
        for (const Obstacle& obstacle : obstacles) {
            if (segmentEnters(segments[s], obstacle.rect))
                fail(segments[s].owner + " " + describe(segments[s].a) + "-" + describe(segments[s].b) + " enters "
                     + obstacle.owner);
        }
        for (const GrafcetTransitionLayout& t : layout.transitions) {
            const bool own = s < linkSegments && layout.links[linkOf[s]].transition == t.number;
            if (!own && segmentEnters(segments[s], barRect(t).adjusted(1)))
                fail(segments[s].owner + " touches the bar of transition " + std::to_string(t.number));
        }
    }
    // No two links cross (they may share the stretch along a branch line).
    for (std::size_t s = 0; s < segments.size(); ++s) {
        for (std::size_t u = s + 1; u < segments.size(); ++u) {
            if (crosses(segments[s], segments[u]))
                fail(segments[s].owner + " crosses " + segments[u].owner + " at " + describe(segments[s].a));
        }
    }

    // Branch lines: branches side by side in branch order; only their own links cross them.
    for (const GrafcetBranchLineLayout& line : layout.lines) {
        std::vector<Segment> drawn{{{line.left, line.y}, {line.right, line.y}, "line"}};
        const bool simultaneous = line.kind == GrafcetBranchLineLayout::Kind::SimultaneousDivergence
                               || line.kind == GrafcetBranchLineLayout::Kind::SimultaneousConvergence;
        if (simultaneous)
            drawn.push_back({{line.left, line.y + kDoubleLineGap}, {line.right, line.y + kDoubleLineGap}, "line"});
        for (const Segment& segment : drawn) {
            for (const Obstacle& obstacle : obstacles) {
                if (segmentEnters(segment, obstacle.rect))
                    fail("a branch line at y " + std::to_string(line.y) + " enters " + obstacle.owner);
            }
            for (std::size_t s = 0; s < linkSegments; ++s) {
                if (!lineOwns(line, layout.links[linkOf[s]]) && crosses(segment, segments[s]))
                    fail("a branch line at y " + std::to_string(line.y) + " crosses " + segments[s].owner);
            }
        }
        std::vector<double> xs;
        switch (line.kind) {
        case GrafcetBranchLineLayout::Kind::SelectionDivergence: {
            std::vector<int> expected;
            for (const GrafcetTransition* t : grafcet.transitionsFrom(line.step)) {
                if (t->upstream.size() == 1)
                    expected.push_back(t->number);
            }
            if (line.branches != expected)
                fail("selection divergence at " + std::to_string(line.step) + ": not every branch, or not in order");
            for (int t : line.branches) {
                const GrafcetTransitionLayout* bar = layout.transition(t);
                xs.push_back(bar->barCenter.x);
                if (bar->barCenter.y <= line.y)
                    fail("selection branch T" + std::to_string(t) + " not below its divergence");
            }
            if (line.y <= layout.step(line.step)->box.bottom())
                fail("selection divergence above its step " + std::to_string(line.step));
            break;
        }
        case GrafcetBranchLineLayout::Kind::SelectionConvergence:
            for (int t : line.branches) {
                const GrafcetTransitionLayout* bar = layout.transition(t);
                xs.push_back(bar->barCenter.x);
                if (bar->barCenter.y >= line.y)
                    fail("selection branch T" + std::to_string(t) + " not above its convergence");
            }
            if (line.y >= layout.step(line.step)->box.top() && !goesBack(layout, line))
                fail("selection convergence below its step " + std::to_string(line.step));
            break;
        case GrafcetBranchLineLayout::Kind::SimultaneousDivergence:
            if (line.branches != grafcet.transition(line.transition)->downstream)
                fail("simultaneous divergence of T" + std::to_string(line.transition) + ": not its downstream steps in order");
            for (int d : line.branches) {
                for (const GrafcetLinkLayout& link : layout.links) {
                    if (link.kind == GrafcetLinkLayout::Kind::TransitionToStep && link.transition == line.transition
                        && link.step == d) {
                        xs.push_back(link.route.back().x);
                        if (link.route.back().y <= line.y + kDoubleLineGap)
                            fail("simultaneous branch " + std::to_string(d) + " not below its double line");
                    }
                }
            }
            if (layout.transition(line.transition)->barCenter.y >= line.y)
                fail("simultaneous divergence above its bar");
            break;
        case GrafcetBranchLineLayout::Kind::SimultaneousConvergence:
            for (int up : line.branches) {
                for (const GrafcetLinkLayout& link : layout.links) {
                    if (link.kind == GrafcetLinkLayout::Kind::StepToTransition && link.transition == line.transition
                        && link.step == up) {
                        xs.push_back(link.route.front().x);
                        if (link.route.front().y >= line.y)
                            fail("simultaneous branch " + std::to_string(up) + " not above its double line");
                    }
                }
            }
            if (layout.transition(line.transition)->barCenter.y <= line.y + kDoubleLineGap)
                fail("simultaneous convergence below its bar");
            break;
        }
        if (xs.size() < line.branches.size() || !std::is_sorted(xs.begin(), xs.end())
            || std::adjacent_find(xs.begin(), xs.end()) != xs.end())
            fail("the branches of a line at y " + std::to_string(line.y) + " are not side by side left to right");
        if (line.left > line.right)
            fail("a branch line runs backwards");
        for (double x : xs) {
            if (x < line.left || x > line.right)
                fail("a branch outside its line at y " + std::to_string(line.y));
        }
    }

    // Everything lies in the bounding rectangle.
    const Rect& bounds = layout.boundingRect;
    for (const Obstacle& obstacle : obstacles) {
        if (!bounds.contains(obstacle.rect))
            fail(obstacle.owner + " outside the bounding rectangle");
    }
    for (const Segment& segment : segments) {
        if (!bounds.contains(segment.a) || !bounds.contains(segment.b))
            fail(segment.owner + " outside the bounding rectangle");
    }
    for (const GrafcetBranchLineLayout& line : layout.lines) {
        if (!bounds.contains(Point{line.left, line.y}) || !bounds.contains(Point{line.right, line.y + kDoubleLineGap}))
            fail("a branch line outside the bounding rectangle");
    }
    for (const GrafcetTransitionLayout& t : layout.transitions) {
        if (!bounds.contains(barRect(t)))
            fail("the bar of transition " + std::to_string(t.number) + " outside the bounding rectangle");
    }
    return found;
}

} // namespace grafcetlayoutchecks

namespace {

double reservedRoom(double width)
{
    return std::ceil(width / kGrafcetLabelReserve) * kGrafcetLabelReserve;
}

// The width of a step's actions, 0 without.
double actionsWidth(const GrafcetStepLayout& step)
{
    return step.actions.empty() ? 0 : step.actions.back().box.right() - step.actions.front().box.left();
}

// What moved between the two layouts: everything vertically, and sideways unless `sideways` is allowed.
void compareLayouts(const GrafcetLayout& before, const GrafcetLayout& after, bool sideways, const std::string& what,
                    std::vector<std::string>& moves)
{
    const auto report = [&](const std::string& element, bool horizontal) {
        if (moves.size() < 20)
            moves.push_back(what + " moved " + element + (horizontal ? " sideways" : " up or down"));
    };
    for (const GrafcetStepLayout& step : before.steps) {
        const GrafcetStepLayout* moved = after.step(step.number);
        if (!moved)
            continue;
        if (moved->box.y != step.box.y)
            report("step " + std::to_string(step.number), false);
        if (!sideways && moved->box.x != step.box.x)
            report("step " + std::to_string(step.number), true);
    }
    for (const GrafcetTransitionLayout& t : before.transitions) {
        const GrafcetTransitionLayout* moved = after.transition(t.number);
        if (!moved)
            continue;
        if (moved->barCenter.y != t.barCenter.y)
            report("T" + std::to_string(t.number), false);
        if (!sideways && moved->barCenter.x != t.barCenter.x)
            report("T" + std::to_string(t.number), true);
    }
    if (before.lines.size() != after.lines.size()) {
        report("the branch lines", false);
        return;
    }
    for (std::size_t i = 0; i < before.lines.size(); ++i) {
        if (before.lines[i].y != after.lines[i].y)
            report("a branch line", false);
        if (!sideways && (before.lines[i].left != after.lines[i].left || before.lines[i].right != after.lines[i].right))
            report("a branch line", true);
    }
}

} // namespace

namespace grafcetlayoutchecks {

std::vector<std::string> labelWidthMoves(const Grafcet& grafcet)
{
    std::vector<std::string> moves;
    const GrafcetLayout before = layoutGrafcet(grafcet, fixedWidth);
    for (const GrafcetTransition& t : grafcet.transitions()) {
        Grafcet wider = grafcet;
        wider.setReceptivity(t.number, t.receptivity + "x");
        const GrafcetLayout after = layoutGrafcet(wider, fixedWidth);
        const bool outgrown = reservedRoom(after.transition(t.number)->labelRect.width)
                           != reservedRoom(before.transition(t.number)->labelRect.width);
        compareLayouts(before, after, outgrown, "a longer receptivity of T" + std::to_string(t.number), moves);
    }
    for (const GrafcetStep& step : grafcet.steps()) {
        if (step.actions.empty())
            continue;
        Grafcet wider = grafcet;
        GrafcetAction action = step.actions.back();
        action.text += "x";
        wider.setAction(step.number, static_cast<int>(step.actions.size()) - 1, action);
        const GrafcetLayout after = layoutGrafcet(wider, fixedWidth);
        const bool outgrown = reservedRoom(actionsWidth(*after.step(step.number)))
                           != reservedRoom(actionsWidth(*before.step(step.number)));
        compareLayouts(before, after, outgrown, "a longer action of step " + std::to_string(step.number), moves);
    }
    return moves;
}

} // namespace grafcetlayoutchecks
