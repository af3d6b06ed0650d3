#pragma once

// Geometry of one nested GRAFCET (spec grafcet-layer.md §2), computed from
// its structure: sequences go down, the branches of a divergence stand side
// by side in branch order, nothing overlaps. Plain data in scene units
// (y downwards), like the GEMMA chart's layout (chartlayout.h), so the
// GRAFCET view and the SVG/PDF exports draw the same picture.
// docs/grafcet-layout.md says how it is computed.

#include "core/templates/gemma/gemmachartlayout.h"
#include "core/model/grafcet.h"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace core {

// The width of a text in scene units, in the font the drawing uses for it
// (the GUI passes QFontMetricsF::horizontalAdvance; tests a fixed width per
// character). Texts are UTF-8.
using TextMeasure = std::function<double(std::string_view text)>;

struct GrafcetActionLayout {
    int index = 0;          // in the step's action list
    ActionTiming timing = ActionTiming::Continuous;
    Rect box;               // the whole action box (qualifier cell and text cell)
    // What the qualifier cell shows: "S", "R", an event mark for stored
    // actions ("↑" on activation, "↓" on deactivation, before S or R:
    // "↓S"); empty for a continuous action (N is not drawn).
    std::string qualifier;
    Rect qualifierCell;     // empty (zero width) when qualifier is empty
    std::string text;       // the action without qualifier and condition: "A_Plus", "Count := Count + 1"
    Rect textCell;
    std::string condition;  // of a conditional action (after IF); empty otherwise
    Rect conditionRect;     // under the text cell; empty (zero size) when there is no condition

    friend bool operator==(const GrafcetActionLayout&, const GrafcetActionLayout&) = default;
};

struct GrafcetStepLayout {
    int number = 0;
    bool initial = false;   // the GUI draws the double square inside box
    Rect box;               // square; the number is written in it
    // The line from the box's right side to the first action box (no points
    // when the step has no action); the action boxes follow each other
    // left to right, touching, vertically centred on the step.
    std::vector<Point> actionLink;
    std::vector<GrafcetActionLayout> actions;

    friend bool operator==(const GrafcetStepLayout&, const GrafcetStepLayout&) = default;
};

struct GrafcetTransitionLayout {
    int number = 0;
    Point barCenter;        // a horizontal bar of kGrafcetBarLength on a vertical link
    Rect labelRect;         // the receptivity, to the right of the bar
    // A transition that does not fit the drawn structure (its upstream steps
    // do not end the branches of one parallel section, ...) stands in a
    // column of its own, reached from reference labels naming its upstream
    // steps (fromReference links).
    bool detached = false;

    friend bool operator==(const GrafcetTransitionLayout&, const GrafcetTransitionLayout&) = default;
};

// One link between a step and a transition, as an orthogonal polyline.
// Links of one divergence or convergence share the stretch along its line.
struct GrafcetLinkLayout {
    enum class Kind { StepToTransition, TransitionToStep };
    // How a TransitionToStep link ends: on the top of the step's box
    // (Plain, and Loop: a line going up beside the drawing, arrowhead at the
    // target's box) or on an arrow tip with the target's number (Jump).
    enum class Ending { Plain, Loop, Jump };

    Kind kind = Kind::StepToTransition;
    int step = 0;
    int transition = 0;
    Ending ending = Ending::Plain;
    // StepToTransition: the first point is the middle of the step box's
    // bottom side, or, when fromReference, of the bottom of referenceRect;
    // the last point is the bar's centre. TransitionToStep: the first point
    // is the bar's centre, the last one the middle of the target box's top
    // side (Plain, Loop; the arrowhead of a Loop points down into the box
    // there) or the tip of the jump arrow (Jump, pointing down).
    std::vector<Point> route;
    Rect labelRect;          // Jump: where the target's number is written
    bool fromReference = false;
    Rect referenceRect;      // fromReference: where the upstream step's number is written

    friend bool operator==(const GrafcetLinkLayout&, const GrafcetLinkLayout&) = default;
};

// A horizontal line of a divergence or convergence. Selection lines are
// single; simultaneous ones are double: a second segment kDoubleLineGap
// below the first (y is the upper one).
struct GrafcetBranchLineLayout {
    enum class Kind { SelectionDivergence, SelectionConvergence, SimultaneousDivergence, SimultaneousConvergence };
    Kind kind = Kind::SelectionDivergence;
    double y = 0;
    double left = 0;
    double right = 0;
    // Selection divergence: the step the branches leave, and their first
    // transitions in branch order (left to right). Selection convergence:
    // the step they join, and their last transitions. Simultaneous: the
    // transition, and the steps of the branches in branch order.
    int step = 0;
    int transition = 0;
    std::vector<int> branches;

    friend bool operator==(const GrafcetBranchLineLayout&, const GrafcetBranchLineLayout&) = default;
};

struct GrafcetLayout {
    Rect boundingRect;       // everything below, with a margin
    std::vector<GrafcetStepLayout> steps;             // in the GRAFCET's step order
    std::vector<GrafcetTransitionLayout> transitions; // in the GRAFCET's transition order
    std::vector<GrafcetLinkLayout> links;
    std::vector<GrafcetBranchLineLayout> lines;

    const GrafcetStepLayout* step(int number) const;
    const GrafcetTransitionLayout* transition(int number) const;
};

inline constexpr double kGrafcetStepSize = 40;        // step boxes (wider for long numbers)
inline constexpr double kGrafcetBarLength = 20;
inline constexpr double kGrafcetLabelHeight = 18;     // receptivity, jump and reference labels
inline constexpr double kGrafcetActionHeight = 28;
inline constexpr double kGrafcetConditionHeight = 16;
inline constexpr double kDoubleLineGap = 4;
inline constexpr double kGrafcetBranchGap = 30;       // between the branches of a divergence
inline constexpr double kGrafcetColumnGap = 60;       // between independent columns
inline constexpr double kGrafcetMargin = 20;          // around the drawing
// The room a receptivity or a step's actions take beside a column is their
// width rounded up to a multiple of this: a label that grows or shrinks
// within its room moves nothing (docs/grafcet-layout.md, "Stable drawing").
inline constexpr double kGrafcetLabelReserve = 60;

// Never fails: any GRAFCET the model can hold, valid or not, is placed
// without overlaps (see docs/grafcet-layout.md for what is drawn how).
GrafcetLayout layoutGrafcet(const Grafcet& grafcet, const TextMeasure& measure);

} // namespace core
