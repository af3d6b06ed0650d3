#include "core/templates/packml/packmlchartlayout.h"

#include "core/layout/orthogonalroute.h"

#include <optional>

namespace core::packml {

const ChartStateBox& PackmlChartLayout::state(State state) const
{
    return states[static_cast<std::size_t>(state) - 1];
}

const ChartFrame* PackmlChartLayout::frame(Command command) const
{
    for (const ChartFrame& candidate : frames)
        if (candidate.command == command)
            return &candidate;
    return nullptr;
}

const ChartTransition* PackmlChartLayout::transition(State source, State target) const
{
    for (const ChartTransition& candidate : transitions)
        if (candidate.transition.source == source && candidate.transition.target == target)
            return &candidate;
    return nullptr;
}

namespace {

// The Abort frame runs kFrameGap outside the Stop frame, which runs
// kFrameGap outside the boxes; above them, each frame's title.
constexpr double kSceneMargin = 20;
constexpr double kFrameGap = 20;
constexpr double kTitleInset = 8;
constexpr double kTitleWidth = 200;
constexpr double kTitleHeight = 18;
constexpr double kTitleBand = 2 * kTitleInset + kTitleHeight; // the Abort title, above the Stop frame
constexpr double kStopFrameHeadroom = 40;                      // the Stop title, above row 0
constexpr double kBoxInsetX = (kChartCellWidth - kStateBoxWidth) / 2;
constexpr double kBoxInsetY = (kChartCellHeight - kStateBoxHeight) / 2;
constexpr double kGridLeft = kSceneMargin + 2 * kFrameGap - kBoxInsetX;
constexpr double kGridTop = kSceneMargin + kTitleBand + kStopFrameHeadroom - kBoxInsetY;
constexpr double kColumnPitch = kChartCellWidth + kChartColumnLane;
constexpr double kRowPitch = kChartCellHeight + kChartRowLane;
// How far below the last row it encloses a frame's bottom edge runs: under
// the lane of Complete → Resetting, leaving its arrow room for a label.
constexpr double kFrameBottomBelowRow = 64;

double boxLeft(int column)
{
    return kGridLeft + column * kColumnPitch + kBoxInsetX;
}

double boxRight(int column)
{
    return boxLeft(column) + kStateBoxWidth;
}

double boxTop(int row)
{
    return kGridTop + row * kRowPitch + kBoxInsetY;
}

double boxBottom(int row)
{
    return boxTop(row) + kStateBoxHeight;
}

double centerX(int column)
{
    return boxLeft(column) + kStateBoxWidth / 2;
}

// x in the lane right of a column, y in the lane below a row.
double rightOf(int column, double distance)
{
    return boxRight(column) + distance;
}

double below(int row, double distance)
{
    return boxBottom(row) + distance;
}

Rect stateBox(State state)
{
    const ChartCell cell = stateInfo(state).cell;
    return {boxLeft(cell.column), boxTop(cell.row), kStateBoxWidth, kStateBoxHeight};
}

// Where a label goes, as a compass direction from its bar, centred on it:
// N and S of a vertical bar (on a horizontal stretch), W and E of a
// horizontal one.
enum class LabelPlace { N, S, W, E };

Rect labelRect(Point bar, LabelPlace place, double width)
{
    constexpr double h = kChartLabelHeight;
    constexpr double clearance = kChartBarLength / 2 + 2;
    constexpr double beside = kChartBarLength / 2 + 4;
    switch (place) {
    case LabelPlace::N: return {bar.x - width / 2, bar.y - clearance - h, width, h};
    case LabelPlace::S: return {bar.x - width / 2, bar.y + clearance, width, h};
    case LabelPlace::W: return {bar.x - beside - width, bar.y - h / 2, width, h};
    case LabelPlace::E: return {bar.x + beside, bar.y - h / 2, width, h};
    }
    return {};
}

// A transition's route (orthogonalRoute), its bar on stretch barSegment,
// in the middle or at coordinate barAt along it, and where its label goes.
struct RouteSpec {
    State source;
    State target;
    Anchor exit;
    std::vector<double> turns;
    Anchor entry;
    int barSegment;
    std::optional<double> barAt;
    LabelPlace label;
};

// The drawing of spec §2.4 (docs/packml.md, "The chart").
std::vector<RouteSpec> routeSpecs()
{
    using enum Side;
    using enum LabelPlace;
    using St = State;
    const double loopLane0 = below(0, 40);  // the Hold loop, between rows 0 and 1
    const double loopLane1 = below(1, 76);  // the Suspend loop, between rows 1 and 2
    const double resetLane = below(2, 44);  // Complete → Resetting, between rows 2 and 3
    const double middleOfRow3 = centerX(2); // the long rows 3 and 5
    return {
        // Column 0, the way back up.
        {St::Clearing, St::Stopped, {Top}, {}, {Bottom}, 0, {}, E},
        {St::Stopped, St::Resetting, {Top}, {}, {Bottom}, 0, below(2, 90), E},
        {St::Resetting, St::Idle, {Top}, {}, {Bottom}, 0, {}, E},
        {St::Aborted, St::Clearing, {Top}, {}, {Bottom}, 0, below(4, 90), E},
        // Row 1, the main line.
        {St::Idle, St::Starting, {Right}, {}, {Left}, 0, {}, N},
        {St::Starting, St::Execute, {Right}, {}, {Left}, 0, {}, N},
        {St::Execute, St::Completing, {Right}, {}, {Left}, 0, {}, N},
        {St::Completing, St::Complete, {Right}, {}, {Left}, 0, rightOf(3, 70), N},
        {St::Complete, St::Resetting, {Bottom, -30}, {resetLane, rightOf(0, 40)}, {Right}, 1, rightOf(1, 60), N},
        // The Hold loop above row 1.
        {St::Execute, St::Holding, {Top, 40}, {loopLane0}, {Bottom, -40}, 1, {}, N},
        {St::Holding, St::Held, {Left}, {}, {Right}, 0, {}, N},
        {St::Held, St::Unholding, {Left}, {}, {Right}, 0, {}, N},
        {St::Unholding, St::Execute, {Bottom, 40}, {loopLane0}, {Top, -40}, 1, {}, N},
        // The Suspend loop below it.
        {St::Execute, St::Suspending, {Bottom, 40}, {loopLane1}, {Top, -40}, 1, {}, S},
        {St::Suspending, St::Suspended, {Left}, {}, {Right}, 0, {}, S},
        {St::Suspended, St::Unsuspending, {Left}, {}, {Right}, 0, {}, S},
        {St::Unsuspending, St::Execute, {Top, 40}, {loopLane1}, {Bottom, -40}, 1, {}, S},
        // Stopping and Aborting back to column 0.
        {St::Stopping, St::Stopped, {Left}, {}, {Right}, 0, middleOfRow3, N},
        {St::Aborting, St::Aborted, {Left}, {}, {Right}, 0, middleOfRow3, N},
        // The optional transitions: Complete from Held and Suspended run down,
        // resp. up, the lane between Execute and Completing; Hold from
        // Suspended goes round Completing on its right.
        {St::Held, St::Completing, {Right, 14}, {rightOf(2, 12), below(0, 80)}, {Top, -20}, 2, {}, N},
        {St::Suspended, St::Completing, {Right, -14}, {rightOf(2, 12), below(1, 36)}, {Bottom, -20}, 2, {}, S},
        {St::Suspended, St::Holding, {Bottom, 30}, {below(2, 14), rightOf(3, 16)}, {Right}, 2, below(0, 58), E},
    };
}

ChartArrow buildArrow(const RouteSpec& spec)
{
    ChartArrow arrow;
    arrow.route = orthogonalRoute(stateBox(spec.source), spec.exit, spec.turns, stateBox(spec.target), spec.entry);
    const Point from = arrow.route[static_cast<std::size_t>(spec.barSegment)];
    const Point to = arrow.route[static_cast<std::size_t>(spec.barSegment) + 1];
    const bool vertical = from.x == to.x;
    arrow.barCenter = {(from.x + to.x) / 2, (from.y + to.y) / 2};
    if (spec.barAt)
        (vertical ? arrow.barCenter.y : arrow.barCenter.x) = *spec.barAt;
    arrow.barHorizontal = vertical;
    arrow.labelRect = labelRect(arrow.barCenter, spec.label, kChartLabelWidth);
    return arrow;
}

const RouteSpec* findSpec(const std::vector<RouteSpec>& specs, State source, State target)
{
    for (const RouteSpec& spec : specs)
        if (spec.source == source && spec.target == target)
            return &spec;
    return nullptr;
}

// A frame encloses the rows up to lastRow; its arrow leaves its bottom edge
// at column 4, straight down to the target's top.
ChartFrame buildFrame(Command command, State target, int lastRow, double outset, double headroom)
{
    ChartFrame frame;
    frame.command = command;
    frame.target = target;
    const double top = boxTop(0) - headroom;
    const double bottom = below(lastRow, kFrameBottomBelowRow);
    const double left = boxLeft(0) - outset;
    const double right = boxRight(kChartColumns - 1) + outset;
    frame.rect = {left, top, right - left, bottom - top};
    frame.titleRect = {frame.rect.x + kTitleInset, top + kTitleInset, kTitleWidth, kTitleHeight};
    const Rect targetBox = stateBox(target);
    const double x = targetBox.center().x;
    frame.arrow.route = {{x, bottom}, {x, targetBox.top()}};
    frame.arrow.barCenter = {x, (bottom + targetBox.top()) / 2};
    frame.arrow.barHorizontal = true;
    frame.arrow.labelRect = labelRect(frame.arrow.barCenter, LabelPlace::W, kFrameArrowLabelWidth);
    return frame;
}

} // namespace

PackmlChartLayout chartLayout(const Options& options)
{
    PackmlChartLayout layout;
    const double sceneRight = boxRight(kChartColumns - 1) + 2 * kFrameGap + kSceneMargin;
    const double sceneBottom = boxBottom(kChartRows - 1) + kSceneMargin;
    layout.sceneRect = {0, 0, sceneRight, sceneBottom};
    for (const StateInfo& info : states())
        layout.states.push_back({info.state, stateBox(info.state)});
    layout.frames.push_back(
        buildFrame(Command::Abort, State::Aborting, 4, 2 * kFrameGap, kStopFrameHeadroom + kTitleBand));
    layout.frames.push_back(buildFrame(Command::Stop, State::Stopping, 2, kFrameGap, kStopFrameHeadroom));
    const std::vector<RouteSpec> specs = routeSpecs();
    for (const StateInfo& info : states()) {
        for (const TemplateTransition& t : transitionsFrom(info.state, options)) {
            if (t.trigger == Trigger::Command && (t.command == Command::Abort || t.command == Command::Stop))
                continue; // the frames' arrows
            if (const RouteSpec* spec = findSpec(specs, t.source, t.target))
                layout.transitions.push_back({t, buildArrow(*spec)});
        }
    }
    return layout;
}

} // namespace core::packml
