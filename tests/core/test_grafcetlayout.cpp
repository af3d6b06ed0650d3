#include "core/formats/modelfiles.h"
#include "core/layout/grafcetlayout.h"
#include "core/model/grafcet.h"
#include "core/model/model.h"
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

using namespace core;

namespace {

// 7 units per character (UTF-8 continuation bytes do not count).
double fixedWidth(std::string_view text)
{
    return 7.0 * static_cast<double>(std::count_if(text.begin(), text.end(), [](char c) {
        return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    }));
}
const TextMeasure kMeasure = fixedWidth;

struct Segment {
    Point a;
    Point b;
    std::string owner; // "link T3->5", "line ..."

    bool vertical() const { return a.x == b.x; }
};

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

// Does an axis-aligned segment touch the interior of the rectangle?
bool segmentEnters(const Segment& s, const Rect& r)
{
    const double xMin = std::min(s.a.x, s.b.x);
    const double xMax = std::max(s.a.x, s.b.x);
    const double yMin = std::min(s.a.y, s.b.y);
    const double yMax = std::max(s.a.y, s.b.y);
    if (s.vertical())
        return xMin > r.left() && xMin < r.right() && yMin < r.bottom() && yMax > r.top();
    return yMin > r.top() && yMin < r.bottom() && xMin < r.right() && xMax > r.left();
}

// Proper crossing of a horizontal and a vertical segment (not at an end).
bool crosses(const Segment& s, const Segment& t)
{
    if (s.vertical() == t.vertical())
        return false;
    const Segment& v = s.vertical() ? s : t;
    const Segment& h = s.vertical() ? t : s;
    const auto inside = [](double value, double p, double q) {
        return value > std::min(p, q) && value < std::max(p, q);
    };
    return inside(v.a.x, h.a.x, h.b.x) && inside(h.a.y, v.a.y, v.b.y);
}

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

struct Obstacle {
    Rect rect;
    std::string owner;
};

// Every invariant of a GRAFCET layout; one line per violation.
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
    for (const GrafcetLinkLayout& link : layout.links) {
        if (link.ending == GrafcetLinkLayout::Ending::Jump)
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
            if (line.y >= layout.step(line.step)->box.top())
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
