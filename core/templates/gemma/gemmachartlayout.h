#pragma once

#include "core/layout/geometry.h"
#include "core/templates/gemma/gemmatemplate.h"

#include <string>
#include <string_view>
#include <vector>

namespace core {

// Geometry of the GEMMA chart, in scene units (y grows downwards), shared by
// the Qt chart and any chart export so both draw the same sheet.

struct FrameLayout {
    Family family = Family::A;
    Rect rect;
    Rect titleRect; // where the GUI writes the translated "A  Stop procedures"
};

// The box is square; the drawn symbol (double square of the initial step,
// double lines of a macro-step, ...) stays inside it.
struct StepLayout {
    std::string_view id;
    Rect box;
};

struct TransitionLayout {
    std::string id;           // "A1->F4", "F->D1"
    std::string_view source;  // step id, or kFamilySource
    std::string_view target;
    // Orthogonal polyline: first point on the source box border (on the F
    // frame border for the family transition), last point on the target box
    // border, where the arrowhead goes.
    std::vector<Point> route;
    Point barCenter;          // GRAFCET transition bar, on a straight segment of the route
    bool barHorizontal = true; // horizontal bar across a vertical segment
    // Where the GUI writes "p: condition", elided to fit. Its width is
    // chosen per transition, as wide as the sheet allows around the bar.
    Rect labelRect;
};

struct ChartLayout {
    Rect sceneRect;
    std::vector<FrameLayout> frames;          // A, F, D
    std::vector<StepLayout> steps;            // in state-number order
    std::vector<TransitionLayout> transitions; // in template order

    const FrameLayout* frame(Family family) const;
    const StepLayout* step(std::string_view id) const;
    const TransitionLayout* transition(std::string_view id) const;
};

inline constexpr double kTransitionBarLength = 20;
inline constexpr double kMinTransitionLabelWidth = 160;
inline constexpr double kMaxTransitionLabelWidth = 240;
inline constexpr double kTransitionLabelHeight = 18;

// The layout of the fixed template, built on first use.
const ChartLayout& templateLayout();

} // namespace core
