#pragma once

// Geometry of the fixed PackML chart (spec packml.md §2.4), in scene units
// (y grows downwards), shared by the Qt chart and any chart export so both
// draw the same sheet, as core/templates/gemma/gemmachartlayout.h does for GEMMA. It
// depends on the edition and options only: a unit mode greys or hides what
// is drawn here, it never moves anything. docs/packml.md ("The chart")
// explains the choices.

#include "core/layout/geometry.h"
#include "core/templates/packml/packmltemplate.h"

#include <vector>

namespace core::packml {

// The grid of spec §2.4, with lanes between the cells where the routes and
// their labels run.
inline constexpr double kChartCellWidth = 160;
inline constexpr double kChartCellHeight = 90;
inline constexpr double kChartColumnLane = 80;
inline constexpr double kChartRowLane = 70;
inline constexpr double kStateBoxWidth = 120;
inline constexpr double kStateBoxHeight = 44;

inline constexpr double kChartBarLength = 20;
// Room for a command name in the label font ("Unsuspend"); the GUI writes
// "SC" in the label of a State Complete transition.
inline constexpr double kChartLabelWidth = 76;
inline constexpr double kChartLabelHeight = 16;
// A frame's arrow names the command and its condition when not the default.
inline constexpr double kFrameArrowLabelWidth = 200;

// An arrow: an orthogonal polyline from its source (a state box border, or
// the bottom edge of a frame) to the border of its target box, where the
// arrowhead goes, with its transition bar and where its text goes.
struct ChartArrow {
    std::vector<Point> route;
    Point barCenter;           // on a straight stretch of the route
    bool barHorizontal = true; // a horizontal bar across a vertical stretch
    Rect labelRect;
};

struct ChartStateBox {
    State state;
    Rect box;
};

// The Stop or the Abort frame: it encloses exactly the states that accept
// its command, and its one arrow leaves its bottom edge for the command's
// target.
struct ChartFrame {
    Command command; // Stop or Abort
    Rect rect;
    Rect titleRect;
    State target; // Stopping or Aborting
    ChartArrow arrow;
};

// Every transition but Stop and Abort, which are the frames' arrows.
struct ChartTransition {
    TemplateTransition transition;
    ChartArrow arrow; // drawn dashed when transition.optional
};

struct PackmlChartLayout {
    Rect sceneRect;
    std::vector<ChartStateBox> states;        // in state-number order
    std::vector<ChartFrame> frames;           // Abort (the outer one), Stop
    std::vector<ChartTransition> transitions; // by source state number, then in priority order

    const ChartStateBox& state(State state) const;
    const ChartFrame* frame(Command command) const;
    const ChartTransition* transition(State source, State target) const;
};

PackmlChartLayout chartLayout(const Options& options);

} // namespace core::packml
