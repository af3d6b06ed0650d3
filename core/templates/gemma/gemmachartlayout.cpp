#include "core/templates/gemma/gemmachartlayout.h"

#include "core/layout/orthogonalroute.h"

#include <algorithm>

namespace core {

const FrameLayout* ChartLayout::frame(Family family) const
{
    for (const FrameLayout& candidate : frames) {
        if (candidate.family == family)
            return &candidate;
    }
    return nullptr;
}

const StepLayout* ChartLayout::step(std::string_view id) const
{
    for (const StepLayout& candidate : steps) {
        if (candidate.id == id)
            return &candidate;
    }
    return nullptr;
}

const TransitionLayout* ChartLayout::transition(std::string_view id) const
{
    for (const TransitionLayout& candidate : transitions) {
        if (candidate.id == id)
            return &candidate;
    }
    return nullptr;
}

namespace {

// The sheet follows the paper GEMMA chart: stop procedures (A) top left,
// failure procedures (D) bottom left, operation procedures (F) on the right
// over the full height. docs/chart-layout.md explains the choices.

constexpr Rect kSceneRect{0, 0, 1500, 960};
constexpr double kTitleWidth = 360; // room for the longest translated family title
constexpr double kTitleHeight = 20;
constexpr double kTitleInset = 8;

struct FrameSpec {
    Family family;
    Rect rect;
};

constexpr FrameSpec kFrames[] = {
    {Family::A, {20, 20, 670, 500}},
    {Family::F, {710, 20, 780, 920}},
    {Family::D, {20, 540, 670, 400}},
};

struct StepSpec {
    std::string_view id;
    double x; // top-left corner
    double y;
    double size;
};

constexpr double kStep = 40;
constexpr double kHubStep = 60; // A1: seven transitions meet there
constexpr double kBigStep = 100; // F1: fourteen transitions, the heart of the sheet

constexpr StepSpec kSteps[] = {
    {"A1", 480, 110, kHubStep},
    {"A2", 480, 240, kStep},
    {"A3", 480, 390, kStep},
    {"A4", 400, 390, kStep},
    {"A5", 40, 390, kStep},
    {"A6", 40, 120, kStep},
    {"A7", 300, 390, kStep},
    {"F1", 990, 360, kBigStep},
    {"F2", 750, 260, kStep},
    {"F3", 1020, 220, kStep},
    {"F4", 1430, 102, kStep},
    {"F5", 1230, 102, kStep},
    {"F6", 1260, 700, kStep},
    {"D1", 40, 840, kStep},
    {"D2", 300, 700, kStep},
    {"D3", 480, 700, kStep},
};

// Where a label goes, as a compass direction from its bar. E and W: beside a
// horizontal bar. NE, NW, SE, SW: above or below a horizontal segment, close
// to it, starting right of the vertical bar or ending left of it. N, S and the
// Far variants: 24 units off the segment, clear of the 40-unit step boxes it
// joins.
enum class LabelPlace { E, W, NE, NW, SE, SW, N, S, NEFar, NWFar, SEFar, SWFar };

// A route as orthogonalRoute() builds it, with its bar and label.
struct RouteSpec {
    std::string_view source;
    std::string_view target;
    Anchor exit;
    std::vector<double> turns;
    Anchor entry;
    int barSegment;
    double barAt; // distance from the segment start; negative: from its end
    LabelPlace label;
    double labelWidth; // kMinTransitionLabelWidth to kMaxTransitionLabelWidth
};

std::vector<RouteSpec> routeSpecs()
{
    using enum Side;
    using enum LabelPlace;
    return {
        {"F", "D1", {Left, 390}, {}, {Right, 10}, 0, 50, NW, 240},
        {"A1", "F4", {Top, 15}, {84}, {Top, -10}, 1, 435, SE, 240},
        {"A1", "F2", {Bottom, 15}, {210}, {Top, 0}, 1, 205, NE, 240},
        {"A1", "F1", {Right, 18}, {1005}, {Top, -35}, 1, 92, W, 216},
        {"A1", "F5", {Right, -18}, {}, {Left, 0}, 0, 175, NE, 240},
        {"A2", "A1", {Top, 0}, {}, {Bottom, -10}, 0, 40, W, 240},
        {"A3", "A4", {Left, 0}, {}, {Right, 0}, 0, 20, NEFar, 180},
        {"A4", "F1", {Bottom, 0}, {470, 950}, {Left, 18}, 1, 310, SE, 210},
        {"A5", "A6", {Top, 0}, {}, {Bottom, 0}, 0, 120, E, 240},
        {"A5", "A7", {Right, 0}, {}, {Left, 0}, 0, 20, NE, 190},
        {"A6", "A1", {Right, 0}, {}, {Left, 0}, 0, 80, NE, 240},
        {"A7", "A4", {Right, 0}, {}, {Left, 0}, 0, 20, NWFar, 220},
        {"F1", "D1", {Bottom, -4}, {900, 70}, {Bottom, 10}, 0, 400, E, 220},
        {"F1", "D3", {Bottom, -40}, {720}, {Right, 0}, 1, 270, NE, 240},
        {"F1", "A2", {Left, -18}, {650, 248}, {Right, -12}, 1, 72, W, 240},
        {"F1", "F4", {Right, 0}, {1460}, {Bottom, 10}, 1, 80, W, 180},
        {"F1", "F5", {Right, -40}, {1240}, {Bottom, -10}, 1, 100, W, 180},
        {"F1", "F3", {Top, 0}, {}, {Bottom, 0}, 0, 50, E, 180},
        {"F1", "A3", {Left, 0}, {}, {Right, 0}, 0, 260, SE, 210},
        {"F1", "F6", {Bottom, 35}, {720}, {Left, 0}, 0, 120, E, 186},
        {"F1", "D2", {Bottom, -22}, {780}, {Bottom, 10}, 1, 288, NE, 240},
        {"F2", "F1", {Bottom, 0}, {374}, {Left, -36}, 0, 37, E, 216},
        {"F3", "A1", {Top, 0}, {140}, {Right, 0}, 0, 50, E, 180},
        {"F4", "A6", {Top, 10}, {60, 60}, {Top, 0}, 1, 1060, SE, 240},
        {"F5", "F4", {Right, 0}, {}, {Left, 0}, 0, 90, S, 196},
        {"F5", "F1", {Bottom, 10}, {390}, {Right, -20}, 0, 158, E, 180},
        {"F6", "D1", {Bottom, 0}, {920, 50}, {Bottom, -10}, 0, 110, E, 190},
        {"F6", "F1", {Top, 0}, {445}, {Right, 35}, 0, 140, E, 190},
        {"D1", "A5", {Top, -10}, {}, {Bottom, -10}, 0, 80, E, 240},
        {"D1", "D2", {Right, -10}, {310}, {Bottom, -10}, 1, 50, E, 240},
        {"D2", "A5", {Top, 0}, {580, 70}, {Bottom, 10}, 0, 60, W, 240},
        {"D3", "A2", {Top, -14}, {620, 376, 260}, {Left, 0}, 2, 120, W, 240},
        {"D3", "A3", {Top, 0}, {}, {Bottom, 0}, 0, 120, E, 176},
        {"D3", "D2", {Left, 0}, {}, {Right, 0}, 0, 60, S, 176},
    };
}

Rect labelRect(Point bar, LabelPlace place, double w)
{
    constexpr double h = kTransitionLabelHeight;
    constexpr double gap = 4;
    constexpr double beside = kTransitionBarLength / 2 + gap;
    constexpr double far = 24;
    double x = bar.x + gap;
    double y = bar.y + gap;
    switch (place) {
    case LabelPlace::E: x = bar.x + beside; y = bar.y - h / 2; break;
    case LabelPlace::W: x = bar.x - beside - w; y = bar.y - h / 2; break;
    case LabelPlace::NE: y = bar.y - gap - h; break;
    case LabelPlace::NW: x = bar.x - gap - w; y = bar.y - gap - h; break;
    case LabelPlace::SE: break;
    case LabelPlace::SW: x = bar.x - gap - w; break;
    case LabelPlace::N: x = bar.x - w / 2; y = bar.y - far - h; break;
    case LabelPlace::S: x = bar.x - w / 2; y = bar.y + far; break;
    case LabelPlace::NEFar: y = bar.y - far - h; break;
    case LabelPlace::NWFar: x = bar.x - gap - w; y = bar.y - far - h; break;
    case LabelPlace::SEFar: y = bar.y + far; break;
    case LabelPlace::SWFar: x = bar.x - gap - w; y = bar.y + far; break;
    }
    return {x, y, w, h};
}

Rect endRect(const ChartLayout& layout, std::string_view id)
{
    if (id == kFamilySource)
        return layout.frame(Family::F)->rect;
    const StepLayout* step = layout.step(id);
    return step ? step->box : Rect{};
}

TransitionLayout buildTransition(const ChartLayout& layout, const RouteSpec& spec)
{
    TransitionLayout transition;
    transition.id = makeTransitionId(spec.source, spec.target);
    transition.source = spec.source;
    transition.target = spec.target;
    transition.route = orthogonalRoute(endRect(layout, spec.source), spec.exit, spec.turns,
                                       endRect(layout, spec.target), spec.entry);
    const std::size_t segment = std::min<std::size_t>(spec.barSegment, transition.route.size() - 2);
    const Point from = transition.route[segment];
    const Point to = transition.route[segment + 1];
    transition.barCenter = pointAlong(from, to, spec.barAt);
    transition.barHorizontal = from.x == to.x; // a vertical segment gets a horizontal bar
    transition.labelRect = labelRect(transition.barCenter, spec.label, spec.labelWidth);
    return transition;
}

ChartLayout buildTemplateLayout()
{
    ChartLayout layout;
    layout.sceneRect = kSceneRect;
    for (const FrameSpec& spec : kFrames) {
        const Rect title{spec.rect.x + kTitleInset, spec.rect.y + kTitleInset, kTitleWidth, kTitleHeight};
        layout.frames.push_back({spec.family, spec.rect, title});
    }
    for (const TemplateState& state : templateStates()) {
        for (const StepSpec& spec : kSteps) {
            if (spec.id == state.id)
                layout.steps.push_back({state.id, {spec.x, spec.y, spec.size, spec.size}});
        }
    }
    const std::vector<RouteSpec> specs = routeSpecs();
    for (const TemplateTransition& t : templateTransitions()) {
        for (const RouteSpec& spec : specs) {
            if (spec.source == t.source && spec.target == t.target)
                layout.transitions.push_back(buildTransition(layout, spec));
        }
    }
    return layout;
}

} // namespace

const ChartLayout& templateLayout()
{
    static const ChartLayout layout = buildTemplateLayout();
    return layout;
}

} // namespace core
