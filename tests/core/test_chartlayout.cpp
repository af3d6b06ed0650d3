#include "core/templates/gemma/gemmachartlayout.h"
#include "core/templates/gemma/gemmatemplate.h"
#include "routegeometry.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace test_chartlayout {

using namespace core;
using namespace routegeometry;

namespace {

std::vector<Segment> segments(const TransitionLayout& t)
{
    return segmentsOf(t.route);
}

Rect endRect(const ChartLayout& layout, std::string_view id)
{
    if (id == kFamilySource)
        return layout.frame(Family::F)->rect;
    return layout.step(id)->box;
}

Rect barRect(const TransitionLayout& t)
{
    const double half = kTransitionBarLength / 2;
    if (t.barHorizontal)
        return {t.barCenter.x - half, t.barCenter.y - 1, kTransitionBarLength, 2};
    return {t.barCenter.x - 1, t.barCenter.y - half, 2, kTransitionBarLength};
}

} // namespace

TEST_CASE("Rect geometry helpers", "[layout]")
{
    const Rect r{10, 20, 30, 40};
    CHECK(r.right() == 40);
    CHECK(r.bottom() == 60);
    CHECK(r.center() == Point{25, 40});
    CHECK(r.contains(Point{10, 20}));
    CHECK(r.contains(Point{40, 60}));
    CHECK_FALSE(r.contains(Point{40.5, 30}));
    CHECK(r.intersects({39, 59, 5, 5}));
    CHECK_FALSE(r.intersects({40, 20, 5, 5})); // touching the right edge only
    CHECK_FALSE(r.intersects({0, 0, 10, 100}));
    CHECK(r.contains(Rect{15, 25, 10, 10}));
    CHECK_FALSE(r.contains(Rect{15, 25, 30, 10}));
    const Rect grown = r.adjusted(5);
    CHECK(grown.x == 5);
    CHECK(grown.width == 40);
}

TEST_CASE("The template layout has every frame, step and transition of the template", "[layout]")
{
    const ChartLayout& layout = templateLayout();
    CHECK(&layout == &templateLayout()); // built once

    REQUIRE(layout.frames.size() == 3);
    for (Family family : {Family::A, Family::F, Family::D}) {
        REQUIRE(layout.frame(family) != nullptr);
        CHECK(layout.frame(family)->family == family);
    }

    const auto states = templateStates();
    REQUIRE(layout.steps.size() == states.size());
    REQUIRE(layout.steps.size() == 16);
    for (std::size_t i = 0; i < states.size(); ++i) {
        CHECK(layout.steps[i].id == states[i].id);
        REQUIRE(layout.step(states[i].id) == &layout.steps[i]);
    }
    CHECK(layout.step("X9") == nullptr);

    const auto transitions = templateTransitions();
    REQUIRE(layout.transitions.size() == transitions.size());
    REQUIRE(layout.transitions.size() == 34);
    for (std::size_t i = 0; i < transitions.size(); ++i) {
        const TransitionLayout& t = layout.transitions[i];
        CHECK(t.id == makeTransitionId(transitions[i].source, transitions[i].target));
        CHECK(t.source == transitions[i].source);
        CHECK(t.target == transitions[i].target);
        CHECK(layout.transition(t.id) == &t);
    }
    CHECK(layout.transition("A1->A2") == nullptr);
    CHECK(layout.transition("F->D1") != nullptr);
}

TEST_CASE("Frames are laid out like the GEMMA sheet", "[layout]")
{
    const ChartLayout& layout = templateLayout();
    const Rect a = layout.frame(Family::A)->rect;
    const Rect f = layout.frame(Family::F)->rect;
    const Rect d = layout.frame(Family::D)->rect;
    CHECK(a.bottom() <= d.top());  // A above D
    CHECK(a.right() <= f.left());  // A and D left of F
    CHECK(d.right() <= f.left());
    CHECK(f.top() <= a.top());     // F over the full height
    CHECK(f.bottom() >= d.bottom());
    for (const FrameLayout& frame : layout.frames) {
        INFO("frame " << familyName(frame.family));
        CHECK(layout.sceneRect.contains(frame.rect));
        CHECK(frame.rect.contains(frame.titleRect));
        CHECK(frame.titleRect.width >= 200);
        for (const FrameLayout& other : layout.frames) {
            if (&other != &frame)
                CHECK_FALSE(frame.rect.intersects(other.rect));
        }
    }
    // Landmarks engineers look for: the initial step left, A1 at the top,
    // F1 the biggest box, D1 bottom left, D3 the D step nearest to F.
    const Rect a1 = layout.step("A1")->box;
    const Rect a6 = layout.step("A6")->box;
    const Rect f1 = layout.step("F1")->box;
    const Rect d1 = layout.step("D1")->box;
    CHECK(a6.right() < a1.left());
    for (const StepLayout& step : layout.steps) {
        INFO("step " << step.id);
        if (step.id.front() == 'A')
            CHECK(a1.top() <= step.box.top());
        if (step.id != "F1")
            CHECK(step.box.width < f1.width);
        if (step.id.front() == 'D') {
            CHECK(d1.bottom() >= step.box.bottom());
            CHECK(d1.left() <= step.box.left());
            CHECK(layout.step("D3")->box.right() >= step.box.right());
        }
    }
}

TEST_CASE("Step boxes are square, apart and inside their family frame", "[layout]")
{
    const ChartLayout& layout = templateLayout();
    constexpr double kMinGap = 20;
    constexpr double kFrameMargin = 20;
    for (const StepLayout& step : layout.steps) {
        INFO("step " << step.id);
        const TemplateState* state = findTemplateState(step.id);
        REQUIRE(state != nullptr);
        CHECK(step.box.width == step.box.height);
        CHECK(step.box.width >= 40);
        const FrameLayout* frame = layout.frame(state->family);
        CHECK(frame->rect.adjusted(-kFrameMargin).contains(step.box));
        for (const FrameLayout& other : layout.frames) {
            CHECK_FALSE(other.titleRect.adjusted(kMinGap / 2).intersects(step.box));
        }
        for (const StepLayout& other : layout.steps) {
            if (&other != &step) {
                INFO("other step " << other.id);
                CHECK_FALSE(step.box.adjusted(kMinGap / 2).intersects(other.box.adjusted(kMinGap / 2)));
            }
        }
    }
}

TEST_CASE("Routes are orthogonal and join the borders of their ends", "[layout]")
{
    const ChartLayout& layout = templateLayout();
    for (const TransitionLayout& t : layout.transitions) {
        INFO("transition " << t.id);
        REQUIRE(t.route.size() >= 2);
        const auto segs = segments(t);
        for (std::size_t i = 0; i < segs.size(); ++i) {
            INFO("segment " << i << " from " << describe(segs[i].a) << " to " << describe(segs[i].b));
            CHECK((segs[i].vertical() != segs[i].horizontal())); // axis-aligned, not a point
            if (i > 0)
                CHECK(segs[i].vertical() != segs[i - 1].vertical()); // every point is a real bend
        }
        const Rect source = endRect(layout, t.source);
        const Rect target = endRect(layout, t.target);
        INFO("first point " << describe(t.route.front()) << ", last point " << describe(t.route.back()));
        CHECK(onBorder(t.route.front(), source));
        CHECK(onBorder(t.route.back(), target));
        // The arrow leaves and enters perpendicular to the side it touches.
        const Segment& first = segs.front();
        const Segment& last = segs.back();
        const bool firstOnVerticalSide = first.a.x == source.left() || first.a.x == source.right();
        const bool lastOnVerticalSide = last.b.x == target.left() || last.b.x == target.right();
        CHECK(first.horizontal() == firstOnVerticalSide);
        CHECK(last.horizontal() == lastOnVerticalSide);
    }
}

TEST_CASE("Routes do not pass through step boxes", "[layout]")
{
    const ChartLayout& layout = templateLayout();
    for (const TransitionLayout& t : layout.transitions) {
        for (const Segment& s : segments(t)) {
            for (const StepLayout& step : layout.steps) {
                // Own ends included: a route touches its boxes only at its end points.
                INFO("transition " << t.id << " segment " << describe(s.a) << "-" << describe(s.b) << " step "
                                   << step.id);
                CHECK_FALSE(segmentEnters(s, step.box));
            }
        }
    }
}

TEST_CASE("Routes never run on top of each other and rarely cross", "[layout]")
{
    const ChartLayout& layout = templateLayout();
    int crossings = 0;
    for (std::size_t i = 0; i < layout.transitions.size(); ++i) {
        for (std::size_t j = i + 1; j < layout.transitions.size(); ++j) {
            const TransitionLayout& a = layout.transitions[i];
            const TransitionLayout& b = layout.transitions[j];
            for (const Segment& s : segments(a)) {
                for (const Segment& u : segments(b)) {
                    INFO(a.id << " and " << b.id);
                    CHECK(sharedLength(s, u) == 0);
                    crossings += crosses(s, u) ? 1 : 0;
                }
            }
        }
    }
    // A4->F1 x D3->A3 and A7->A4 x D3->A2: the cycle F1-A2-D3-A3 forces
    // them (docs/chart-layout.md).
    CHECK(crossings <= 2);
}

TEST_CASE("Route end points on one box are kept apart", "[layout]")
{
    const ChartLayout& layout = templateLayout();
    struct End {
        std::string_view box;
        Point point;
        std::string id;
    };
    std::vector<End> ends;
    for (const TransitionLayout& t : layout.transitions) {
        ends.push_back({t.source, t.route.front(), t.id});
        ends.push_back({t.target, t.route.back(), t.id});
    }
    for (std::size_t i = 0; i < ends.size(); ++i) {
        for (std::size_t j = i + 1; j < ends.size(); ++j) {
            if (ends[i].box != ends[j].box)
                continue;
            INFO(ends[i].id << " and " << ends[j].id << " on " << ends[i].box);
            const double gap = std::abs(ends[i].point.x - ends[j].point.x) + std::abs(ends[i].point.y - ends[j].point.y);
            CHECK(gap >= 12);
        }
    }
}

TEST_CASE("Transition bars sit on a straight stretch of their route", "[layout]")
{
    const ChartLayout& layout = templateLayout();
    for (const TransitionLayout& t : layout.transitions) {
        INFO("transition " << t.id << " bar at " << describe(t.barCenter));
        bool found = false;
        for (const Segment& s : segments(t)) {
            if (!onSegment(t.barCenter, s))
                continue;
            // A horizontal bar crosses a vertical segment, and the whole bar
            // is clear of the segment's bends.
            const double toStart = std::abs(t.barCenter.x - s.a.x) + std::abs(t.barCenter.y - s.a.y);
            const double toEnd = std::abs(t.barCenter.x - s.b.x) + std::abs(t.barCenter.y - s.b.y);
            if (t.barHorizontal == s.vertical() && toStart >= kTransitionBarLength && toEnd >= kTransitionBarLength)
                found = true;
        }
        CHECK(found);
        const Rect bar = barRect(t);
        for (const StepLayout& step : layout.steps)
            CHECK_FALSE(bar.intersects(step.box));
        for (const TransitionLayout& other : layout.transitions) {
            if (&other == &t)
                continue;
            INFO("other transition " << other.id);
            CHECK_FALSE(bar.intersects(other.labelRect));
            CHECK_FALSE(bar.adjusted(4).intersects(barRect(other)));
            // Kept clear of other routes, so that it is not read as theirs.
            for (const Segment& s : segments(other))
                CHECK_FALSE(segmentEnters(s, bar.adjusted(8)));
        }
    }
}

TEST_CASE("Transition labels are beside their bar and overlap nothing", "[layout]")
{
    const ChartLayout& layout = templateLayout();
    for (const TransitionLayout& t : layout.transitions) {
        INFO("transition " << t.id);
        const Rect& label = t.labelRect;
        CHECK(label.width >= kMinTransitionLabelWidth);
        CHECK(label.width <= kMaxTransitionLabelWidth);
        CHECK(label.height == kTransitionLabelHeight);
        CHECK(distance(t.barCenter, label) <= 30);
        CHECK_FALSE(label.intersects(barRect(t)));
        for (const StepLayout& step : layout.steps) {
            INFO("step " << step.id);
            CHECK_FALSE(label.intersects(step.box));
        }
        int framesHolding = 0;
        for (const FrameLayout& frame : layout.frames) {
            CHECK_FALSE(label.intersects(frame.titleRect));
            framesHolding += frame.rect.contains(label) ? 1 : 0;
        }
        CHECK(framesHolding == 1); // no label straddles a frame border
        for (const TransitionLayout& other : layout.transitions) {
            INFO("other transition " << other.id);
            if (&other != &t)
                CHECK_FALSE(label.intersects(other.labelRect));
            // No route, its own included, runs through a label.
            for (const Segment& s : segments(other))
                CHECK_FALSE(segmentEnters(s, label));
        }
    }
}

TEST_CASE("Every transition label is wide enough for a real condition", "[layout]")
{
    // 120 units cut "Stop OR BottleCount_Max" after a dozen characters; 160
    // holds about 20 characters of the 14-unit label font.
    STATIC_REQUIRE(kMinTransitionLabelWidth >= 160);
    const ChartLayout& layout = templateLayout();
    double total = 0;
    for (const TransitionLayout& t : layout.transitions) {
        INFO("transition " << t.id);
        CHECK(t.labelRect.width >= 160);
        total += t.labelRect.width;
    }
    // On average well above the minimum: labels take the room the sheet has.
    CHECK(total / static_cast<double>(layout.transitions.size()) >= 190);
}

TEST_CASE("The A5->A7 label sits next to its bar", "[layout]")
{
    // A5->A7 once had its label centred 24 units above the row, closer to
    // A5->A6 than to its own bar.
    const TransitionLayout* t = templateLayout().transition("A5->A7");
    REQUIRE(t != nullptr);
    CHECK(distance(t->barCenter, t->labelRect) <= 6);
    CHECK(t->labelRect.left() > t->barCenter.x); // starts at the bar, reads away from A5
}

TEST_CASE("Everything lies inside the scene rectangle", "[layout]")
{
    const ChartLayout& layout = templateLayout();
    const Rect& scene = layout.sceneRect;
    CHECK(scene.width <= 1500);
    CHECK(scene.height <= 1050);
    for (const FrameLayout& frame : layout.frames)
        CHECK(scene.contains(frame.titleRect));
    for (const StepLayout& step : layout.steps)
        CHECK(scene.contains(step.box));
    for (const TransitionLayout& t : layout.transitions) {
        INFO("transition " << t.id);
        CHECK(scene.contains(t.labelRect));
        CHECK(scene.contains(barRect(t)));
        for (const Point& p : t.route)
            CHECK(scene.contains(p));
    }
}

TEST_CASE("The family transition leaves the F frame from its bottom-left area", "[layout]")
{
    const ChartLayout& layout = templateLayout();
    const TransitionLayout* family = layout.transition("F->D1");
    REQUIRE(family != nullptr);
    const Rect f = layout.frame(Family::F)->rect;
    const Point start = family->route.front();
    CHECK(start.x == f.left());
    CHECK(start.y > f.center().y);
}

} // namespace test_chartlayout
