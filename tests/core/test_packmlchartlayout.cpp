#include "core/templates/packml/packmlchartlayout.h"
#include "core/templates/packml/packmltemplate.h"
#include "routegeometry.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace test_packmlchartlayout {

using namespace core;
using namespace core::packml;
using namespace routegeometry;

namespace {

// Both editions with every combination of the two options.
std::vector<Options> everyOptions()
{
    std::vector<Options> result;
    for (Edition edition : {Edition::Y2015, Edition::Y2022})
        for (bool holdInSuspended : {false, true})
            for (bool completeInSuspendedHeld : {false, true})
                result.push_back({edition, holdInSuspended, completeInSuspendedHeld});
    return result;
}

std::string describeOptions(const Options& options)
{
    return std::string("edition ") + std::string(editionName(options.edition)) + ", holdInSuspended "
        + (options.holdInSuspended ? "on" : "off") + ", completeInSuspendedHeld "
        + (options.completeInSuspendedHeld ? "on" : "off");
}

// An arrow of the chart, a transition's or a frame's, with what it joins.
struct NamedArrow {
    std::string name;
    const ChartArrow* arrow;
    Rect source; // the source box, or the frame for a frame's arrow
    Rect target;
    bool fromFrame;
    bool optional;
};

std::vector<NamedArrow> allArrows(const PackmlChartLayout& layout)
{
    std::vector<NamedArrow> result;
    for (const ChartTransition& t : layout.transitions) {
        const packml::TemplateTransition& tt = t.transition;
        result.push_back({std::string(stateName(tt.source)) + "->" + std::string(stateName(tt.target)), &t.arrow,
                          layout.state(tt.source).box, layout.state(tt.target).box, false, tt.optional});
    }
    for (const ChartFrame& frame : layout.frames)
        result.push_back({std::string(commandName(frame.command)) + " frame->" + std::string(stateName(frame.target)),
                          &frame.arrow, frame.rect, layout.state(frame.target).box, true, false});
    return result;
}

Rect barRect(const ChartArrow& a)
{
    const double half = kChartBarLength / 2;
    if (a.barHorizontal)
        return {a.barCenter.x - half, a.barCenter.y - 1, kChartBarLength, 2};
    return {a.barCenter.x - 1, a.barCenter.y - half, 2, kChartBarLength};
}

bool isFrameCommand(const packml::TemplateTransition& t)
{
    return t.trigger == Trigger::Command && (t.command == Command::Stop || t.command == Command::Abort);
}

bool sameTransition(const packml::TemplateTransition& a, const packml::TemplateTransition& b)
{
    return a.source == b.source && a.target == b.target && a.trigger == b.trigger
        && (a.trigger == Trigger::StateComplete || a.command == b.command) && a.optional == b.optional;
}

} // namespace

TEST_CASE("PackML chart: 17 boxes of 120 x 44 on the 5 x 6 grid, none overlapping", "[packml-chart]")
{
    for (const Options& options : everyOptions()) {
        INFO(describeOptions(options));
        const PackmlChartLayout layout = chartLayout(options);
        REQUIRE(layout.states.size() == 17);
        for (const ChartStateBox& box : layout.states) {
            INFO("state " << stateName(box.state));
            CHECK(&layout.state(box.state) == &box);
            CHECK(box.box.width == kStateBoxWidth);
            CHECK(box.box.height == kStateBoxHeight);
            const ChartCell cell = stateInfo(box.state).cell;
            for (const ChartStateBox& other : layout.states) {
                if (&other == &box)
                    continue;
                INFO("other " << stateName(other.state));
                const ChartCell otherCell = stateInfo(other.state).cell;
                // Same row, same top; same column, same centre; the grid's
                // pitch is at least the cell of spec 2.4.
                CHECK((cell.row == otherCell.row) == (box.box.top() == other.box.top()));
                CHECK((cell.column == otherCell.column) == (box.box.center().x == other.box.center().x));
                if (cell.column < otherCell.column)
                    CHECK(other.box.left() - box.box.left() >= kChartCellWidth * (otherCell.column - cell.column));
                if (cell.row < otherCell.row)
                    CHECK(other.box.top() - box.box.top() >= kChartCellHeight * (otherCell.row - cell.row));
                CHECK_FALSE(box.box.adjusted(kChartCellWidth - kStateBoxWidth).intersects(other.box));
            }
        }
    }
}

TEST_CASE("PackML chart: every transition of the template has exactly one route", "[packml-chart]")
{
    for (const Options& options : everyOptions()) {
        INFO(describeOptions(options));
        const PackmlChartLayout layout = chartLayout(options);
        std::size_t expected = 0;
        for (const StateInfo& info : states()) {
            for (const packml::TemplateTransition& t : transitionsFrom(info.state, options)) {
                if (isFrameCommand(t))
                    continue;
                ++expected;
                INFO(stateName(t.source) << " -> " << stateName(t.target));
                int routes = 0;
                for (const ChartTransition& drawn : layout.transitions)
                    routes += sameTransition(drawn.transition, t) ? 1 : 0;
                CHECK(routes == 1);
            }
        }
        CHECK(layout.transitions.size() == expected);
        for (const ChartTransition& drawn : layout.transitions)
            CHECK_FALSE(isFrameCommand(drawn.transition)); // Stop and Abort are the frames' arrows
        // Held -> Completing exists under its option only, and is then dashed.
        const ChartTransition* heldComplete = layout.transition(State::Held, State::Completing);
        CHECK((heldComplete != nullptr) == (options.edition == Edition::Y2022 && options.completeInSuspendedHeld));
        if (heldComplete)
            CHECK(heldComplete->transition.optional);
        CHECK_FALSE(layout.transition(State::Execute, State::Completing)->transition.optional);
    }
}

TEST_CASE("PackML chart: routes are orthogonal and join their source and target borders", "[packml-chart]")
{
    for (const Options& options : everyOptions()) {
        INFO(describeOptions(options));
        const PackmlChartLayout layout = chartLayout(options);
        for (const NamedArrow& a : allArrows(layout)) {
            INFO(a.name);
            const std::vector<Point>& route = a.arrow->route;
            REQUIRE(route.size() >= 2);
            const auto segs = segmentsOf(route);
            for (std::size_t i = 0; i < segs.size(); ++i) {
                INFO("segment " << i << " " << describe(segs[i].a) << "-" << describe(segs[i].b));
                CHECK((segs[i].vertical() != segs[i].horizontal())); // axis-aligned, not a point
                if (i > 0)
                    CHECK(segs[i].vertical() != segs[i - 1].vertical()); // every point is a real bend
            }
            INFO("from " << describe(route.front()) << " to " << describe(route.back()));
            CHECK(onBorder(route.front(), a.source));
            CHECK(onBorder(route.back(), a.target));
            // Leaving and entering perpendicular to the side touched.
            const Segment& first = segs.front();
            const Segment& last = segs.back();
            const bool startsOnVerticalSide = first.a.x == a.source.left() || first.a.x == a.source.right();
            const bool endsOnVerticalSide = last.b.x == a.target.left() || last.b.x == a.target.right();
            CHECK(first.horizontal() == startsOnVerticalSide);
            CHECK(last.horizontal() == endsOnVerticalSide);
        }
    }
}

TEST_CASE("PackML chart: no route passes through a box", "[packml-chart]")
{
    for (const Options& options : everyOptions()) {
        INFO(describeOptions(options));
        const PackmlChartLayout layout = chartLayout(options);
        for (const NamedArrow& a : allArrows(layout)) {
            for (const Segment& s : segmentsOf(a.arrow->route)) {
                for (const ChartStateBox& box : layout.states) {
                    // Its own ends included: a route touches them at its end points only.
                    INFO(a.name << " segment " << describe(s.a) << "-" << describe(s.b) << " box "
                                << stateName(box.state));
                    CHECK_FALSE(segmentEnters(s, box.box));
                }
            }
        }
    }
}

TEST_CASE("PackML chart: routes never run along each other; only optional ones cross, once", "[packml-chart]")
{
    for (const Options& options : everyOptions()) {
        INFO(describeOptions(options));
        const PackmlChartLayout layout = chartLayout(options);
        const std::vector<NamedArrow> arrows = allArrows(layout);
        std::vector<int> crossings(arrows.size(), 0);
        for (std::size_t i = 0; i < arrows.size(); ++i) {
            for (std::size_t j = i + 1; j < arrows.size(); ++j) {
                INFO(arrows[i].name << " and " << arrows[j].name);
                for (const Segment& s : segmentsOf(arrows[i].arrow->route)) {
                    for (const Segment& u : segmentsOf(arrows[j].arrow->route)) {
                        CHECK(sharedLength(s, u) == 0);
                        if (crosses(s, u)) {
                            ++crossings[i];
                            ++crossings[j];
                            CHECK((arrows[i].optional || arrows[j].optional));
                        }
                    }
                }
            }
        }
        // Hold from Suspended must cross the main line (Suspended is inside
        // the cycle Idle ... Complete -> Resetting -> Idle, Holding outside);
        // Complete from Held and Suspended cross the Hold, resp. Suspend, loop.
        for (std::size_t i = 0; i < arrows.size(); ++i) {
            INFO(arrows[i].name);
            if (arrows[i].optional)
                CHECK(crossings[i] <= 1);
        }
    }
}

TEST_CASE("PackML chart: route ends on one box are kept apart", "[packml-chart]")
{
    for (const Options& options : everyOptions()) {
        INFO(describeOptions(options));
        const PackmlChartLayout layout = chartLayout(options);
        std::vector<std::pair<std::string, Point>> ends;
        for (const NamedArrow& a : allArrows(layout)) {
            ends.emplace_back(a.name, a.arrow->route.front());
            ends.emplace_back(a.name, a.arrow->route.back());
        }
        for (std::size_t i = 0; i < ends.size(); ++i) {
            for (std::size_t j = i + 1; j < ends.size(); ++j) {
                INFO(ends[i].first << " and " << ends[j].first);
                const Point p = ends[i].second;
                const Point q = ends[j].second;
                CHECK(std::abs(p.x - q.x) + std::abs(p.y - q.y) >= 12);
            }
        }
    }
}

TEST_CASE("PackML chart: transition bars sit on a straight stretch of their route", "[packml-chart]")
{
    for (const Options& options : everyOptions()) {
        INFO(describeOptions(options));
        const PackmlChartLayout layout = chartLayout(options);
        const std::vector<NamedArrow> arrows = allArrows(layout);
        for (const NamedArrow& a : arrows) {
            INFO(a.name << " bar at " << describe(a.arrow->barCenter));
            bool found = false;
            for (const Segment& s : segmentsOf(a.arrow->route)) {
                if (!onSegment(a.arrow->barCenter, s))
                    continue;
                const Point c = a.arrow->barCenter;
                const double toStart = std::abs(c.x - s.a.x) + std::abs(c.y - s.a.y);
                const double toEnd = std::abs(c.x - s.b.x) + std::abs(c.y - s.b.y);
                if (a.arrow->barHorizontal == s.vertical() && toStart >= kChartBarLength && toEnd >= kChartBarLength)
                    found = true;
            }
            CHECK(found);
            const Rect bar = barRect(*a.arrow);
            for (const NamedArrow& other : arrows) {
                if (&other == &a)
                    continue;
                INFO("other " << other.name);
                CHECK_FALSE(bar.intersects(other.arrow->labelRect));
                for (const Segment& s : segmentsOf(other.arrow->route))
                    CHECK_FALSE(segmentEnters(s, bar.adjusted(8))); // not read as the other's
            }
        }
    }
}

TEST_CASE("PackML chart: labels overlap no box, no title, no other label, and no route runs through them",
          "[packml-chart]")
{
    for (const Options& options : everyOptions()) {
        INFO(describeOptions(options));
        const PackmlChartLayout layout = chartLayout(options);
        const std::vector<NamedArrow> arrows = allArrows(layout);
        for (const NamedArrow& a : arrows) {
            INFO(a.name);
            const Rect& label = a.arrow->labelRect;
            CHECK(label.height == kChartLabelHeight);
            CHECK(label.width == (a.fromFrame ? kFrameArrowLabelWidth : kChartLabelWidth));
            CHECK(distance(a.arrow->barCenter, label) <= kChartBarLength);
            CHECK_FALSE(label.intersects(barRect(*a.arrow)));
            for (const ChartStateBox& box : layout.states) {
                INFO("box " << stateName(box.state));
                CHECK_FALSE(label.intersects(box.box));
            }
            for (const ChartFrame& frame : layout.frames) {
                INFO("frame " << commandName(frame.command));
                CHECK_FALSE(label.intersects(frame.titleRect));
                // Inside the frame or out of it, never across its border.
                CHECK((frame.rect.contains(label) || !frame.rect.intersects(label)));
            }
            for (const NamedArrow& other : arrows) {
                INFO("other " << other.name);
                if (&other != &a)
                    CHECK_FALSE(label.intersects(other.arrow->labelRect));
                for (const Segment& s : segmentsOf(other.arrow->route))
                    CHECK_FALSE(segmentEnters(s, label));
            }
        }
    }
}

TEST_CASE("PackML chart: the Stop and Abort frames enclose exactly the states that accept them", "[packml-chart]")
{
    for (const Options& options : everyOptions()) {
        INFO(describeOptions(options));
        const PackmlChartLayout layout = chartLayout(options);
        REQUIRE(layout.frames.size() == 2);
        const ChartFrame* stop = layout.frame(Command::Stop);
        const ChartFrame* abort = layout.frame(Command::Abort);
        REQUIRE(stop != nullptr);
        REQUIRE(abort != nullptr);
        CHECK(layout.frame(Command::Hold) == nullptr);
        CHECK(stop->target == State::Stopping);
        CHECK(abort->target == State::Aborting);
        CHECK(abort->rect.contains(stop->rect));
        CHECK_FALSE(stop->titleRect.intersects(abort->titleRect));
        for (const ChartFrame* frame : {stop, abort}) {
            INFO("frame " << commandName(frame->command));
            int enclosed = 0;
            for (const ChartStateBox& box : layout.states) {
                INFO("state " << stateName(box.state));
                const bool accepts = frame->command == Command::Stop ? acceptsStop(box.state) : acceptsAbort(box.state);
                CHECK(frame->rect.contains(box.box) == accepts);
                if (!accepts)
                    CHECK_FALSE(frame->rect.intersects(box.box));
                CHECK_FALSE(frame->titleRect.intersects(box.box));
                enclosed += frame->rect.contains(box.box) ? 1 : 0;
            }
            CHECK(enclosed == (frame->command == Command::Stop ? 12 : 15));
            CHECK(frame->rect.contains(frame->titleRect));
            // One arrow, from the bottom edge at column 4 down to the target.
            const std::vector<Point>& route = frame->arrow.route;
            REQUIRE(route.size() == 2);
            const Rect target = layout.state(frame->target).box;
            CHECK(stateInfo(frame->target).cell.column == 4);
            CHECK(route.front().y == frame->rect.bottom());
            CHECK(route.front().x > target.left());
            CHECK(route.front().x < target.right());
            CHECK(route.back() == Point{route.front().x, target.top()});
        }
    }
}

TEST_CASE("PackML chart: the drawing follows spec 2.4", "[packml-chart]")
{
    for (const Options& options : everyOptions()) {
        INFO(describeOptions(options));
        const PackmlChartLayout layout = chartLayout(options);
        const auto box = [&](State s) { return layout.state(s).box; };
        const auto route = [&](State s, State t) {
            const ChartTransition* drawn = layout.transition(s, t);
            REQUIRE(drawn != nullptr);
            return drawn->arrow.route;
        };
        // The main line and the way back up are straight arrows.
        for (auto [s, t] : {std::pair{State::Idle, State::Starting}, {State::Starting, State::Execute},
                            {State::Execute, State::Completing}, {State::Completing, State::Complete},
                            {State::Aborted, State::Clearing}, {State::Clearing, State::Stopped},
                            {State::Stopped, State::Resetting}, {State::Resetting, State::Idle}}) {
            INFO(stateName(s) << " -> " << stateName(t));
            CHECK(route(s, t).size() == 2);
        }
        // Stopping along row 3 to Stopped, Aborting along row 5 to Aborted.
        CHECK(route(State::Stopping, State::Stopped)
              == std::vector<Point>{{box(State::Stopping).left(), box(State::Stopping).center().y},
                                    {box(State::Stopped).right(), box(State::Stopped).center().y}});
        CHECK(route(State::Aborting, State::Aborted)
              == std::vector<Point>{{box(State::Aborting).left(), box(State::Aborting).center().y},
                                    {box(State::Aborted).right(), box(State::Aborted).center().y}});
        // The Hold loop runs above row 1, the Suspend loop below it.
        for (auto [s, t] : {std::pair{State::Execute, State::Holding}, {State::Holding, State::Held},
                            {State::Held, State::Unholding}, {State::Unholding, State::Execute}}) {
            INFO(stateName(s) << " -> " << stateName(t));
            for (Point p : route(s, t))
                CHECK(p.y <= box(State::Execute).top());
        }
        for (auto [s, t] : {std::pair{State::Execute, State::Suspending}, {State::Suspending, State::Suspended},
                            {State::Suspended, State::Unsuspending}, {State::Unsuspending, State::Execute}}) {
            INFO(stateName(s) << " -> " << stateName(t));
            for (Point p : route(s, t))
                CHECK(p.y >= box(State::Execute).bottom());
        }
        // Complete -> Resetting: its horizontal stretch in the lane between
        // rows 2 and 3, inside the Stop frame.
        bool inLane = false;
        for (const Segment& s : segmentsOf(route(State::Complete, State::Resetting)))
            inLane = inLane
                || (s.horizontal() && s.a.y > box(State::Suspended).bottom() && s.a.y < box(State::Stopped).top()
                    && s.a.y < layout.frame(Command::Stop)->rect.bottom() && s.length() > 3 * kChartCellWidth);
        CHECK(inLane);
    }
}

TEST_CASE("PackML chart: everything lies inside the scene rectangle", "[packml-chart]")
{
    for (const Options& options : everyOptions()) {
        INFO(describeOptions(options));
        const PackmlChartLayout layout = chartLayout(options);
        const Rect& scene = layout.sceneRect;
        CHECK(scene.x == 0);
        CHECK(scene.y == 0);
        for (const ChartStateBox& box : layout.states)
            CHECK(scene.contains(box.box));
        for (const ChartFrame& frame : layout.frames) {
            CHECK(scene.contains(frame.rect));
            CHECK(scene.contains(frame.titleRect));
        }
        for (const NamedArrow& a : allArrows(layout)) {
            INFO(a.name);
            CHECK(scene.contains(a.arrow->labelRect));
            CHECK(scene.contains(barRect(*a.arrow)));
            for (Point p : a.arrow->route)
                CHECK(scene.contains(p));
        }
    }
}

} // namespace test_packmlchartlayout
