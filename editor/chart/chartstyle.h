#pragma once

#include "core/templates/gemma/gemmatemplate.h"
#include "core/templates/packml/packmltemplate.h"

#include <QColor>
#include <QFont>
#include <QRectF>

class QPainter;

// Colours, pen widths and fonts of the chart, in one place so the items
// agree. Sizes are in scene units: the template sheet is 1500 x 960, fitted
// at about 60 % on a 1366 x 768 screen (the docks beside it, none below), so
// the 14-unit labels read at 8 px or more there.
namespace editor::chartstyle {

inline constexpr double kStrokeWidth = 1.6;
inline constexpr double kRouteWidth = 1.3;
inline constexpr double kBarWidth = 4;
inline constexpr double kHaloWidth = 7;
inline constexpr double kHiddenOpacity = 0.25;
inline constexpr double kArrowLength = 9;
inline constexpr double kArrowHalfWidth = 4;
inline constexpr double kInitialInset = 4;  // gap between the two squares of an initial step
inline constexpr double kMacroInset = 5;    // distance of a macro-step's inner lines
inline constexpr double kEnclosingMark = 8; // leg length of an enclosing step's corner marks
inline constexpr double kBadgeRadius = 7;
inline constexpr double kOverlineWidth = 1.4; // the overline on a negated transition's priority
inline constexpr double kOverlineGap = 1.6;
inline constexpr double kNegatedBadgePadding = 3; // around a negated transition's priority and its overline
inline constexpr double kFiredWidth = 3.2;     // the route of the transition that fired last (simulation)
inline constexpr double kTokenRadius = 3.6;    // a token's dot on its transition bar (simulation)
inline constexpr double kCompleteBadgeSize = 14; // the "C" badge of a nested step (simulation)
inline constexpr double kNestedMarkSize = 15;    // the GRAFCET mark of a step with a nested GRAFCET

// Stacking: frames at the bottom, then transitions, then steps. A selected
// element goes below every other transition and step, so that its halo
// never covers their marks (an arrowhead, the green route of the transition
// that fired, a token).
inline constexpr double kFrameZ = 0;
inline constexpr double kSelectedZ = 0.5;
inline constexpr double kTransitionZ = 1;
inline constexpr double kStepZ = 2;

inline QColor inkColor() { return QColor(0x20, 0x24, 0x2a); }
inline QColor stepFillColor() { return QColor(0xff, 0xff, 0xff); }
inline QColor activeFillColor() { return QColor(0xff, 0xd8, 0x4d); }
inline QColor problemColor() { return QColor(0xd3, 0x1f, 0x1f); }
inline QColor haloColor() { return QColor(0x25, 0x74, 0xe8, 120); }
inline QColor labelColor() { return QColor(0x1d, 0x2f, 0x4a); }
// Simulation marks: the transition that fired last, a TRUE token or Complete,
// and a FALSE one.
inline QColor firedColor() { return QColor(0x1e, 0x9e, 0x3e); }
inline QColor trueMarkColor() { return QColor(0x1e, 0x9e, 0x3e); }
inline QColor falseMarkColor() { return QColor(0x9a, 0xa1, 0xab); }
// The GRAFCET mark of a step with a nested GRAFCET: the label colour, so it
// reads as part of the drawing rather than as a warning; in the fired
// colour while that GRAFCET runs (simulation).
inline QColor nestedMarkColor() { return labelColor(); }
inline QColor nestedRunningColor() { return firedColor(); }

// Simulation marks of a nested GRAFCET (editor/simulation/grafcetsimulationmarks.h):
// an active step is filled as the chart's active state with the IEC 60848
// token in it; a step active when its GRAFCET stopped running is greyed; a
// continuous action whose output the last call emitted is lit.
inline constexpr double kGrafcetTokenRadius = 4.5;
inline QColor tokenColor() { return inkColor(); }
inline QColor frozenFillColor() { return QColor(0xe4, 0xe7, 0xeb); }
inline QColor frozenTokenColor() { return falseMarkColor(); }
inline QColor litActionFillColor() { return QColor(0xc9, 0xef, 0xd3); }
inline QColor litActionBorderColor() { return firedColor(); }

// Soft tints after the classic GEMMA sheet: stops blue, operation green,
// failures red-orange.
QColor frameFillColor(core::Family family);
QColor frameBorderColor(core::Family family);

// The PackML chart (spec packml.md §2.4, after seed 002's Figure 1): wait
// states cyan, acting states green, Execute (dual) white, each pale enough to
// print and to carry ink text; a state the shown mode disables is grey with
// a dashed outline, an arrow that skips a state grey.
QColor packmlStateFillColor(core::packml::StateKind kind);
inline QColor packmlDisabledFillColor() { return QColor(0xec, 0xee, 0xf0); }
inline QColor packmlGreyedInkColor() { return QColor(0x98, 0x9f, 0xa8); }
// The Stop frame pale amber inside the Abort frame pale red: a controlled
// stop inside the region a fault can reach.
QColor packmlFrameFillColor(core::packml::Command command);
QColor packmlFrameBorderColor(core::packml::Command command);

// All the chart's text is one font, the window's own face at kFontSize units:
// the transition labels at that size, step ids, badges and family titles
// drawn larger (or smaller) by scaling. Another size or weight would be a
// font engine of its own, and a bold one another face too: fontconfig
// matching, FreeType and HarfBuzz set-up and glyphs of its own, 3.4 M
// instructions of the first frame, its largest single cost (measured with
// callgrind). The chart is drawn scaled anyway, so scaled text looks as a
// bigger font would; emphasis comes from size and colour, and step numbers
// are regular, as in the figures of IEC 60848.
inline constexpr int kFontSize = 14;
const QFont& font();
// Scales of font() for a step's id (larger in the big hub steps), a badge's
// letter and a family frame's title.
double stepIdScale(double boxSize);
inline constexpr double kBadgeScale = 11.0 / kFontSize;
inline constexpr double kTitleScale = 15.0 / kFontSize;
// The advance of `text` in font(). The short texts every label repeats
// ("2", "2: ") are measured once: each measurement shapes its text anew,
// and the template's 34 labels are mostly a priority alone.
double advance(const QString& text);

// `text` in `rect` with `flags` (Qt::AlignmentFlag, Qt::TextFlag), in
// font() enlarged by `scale`.
void drawText(QPainter* painter, const QRectF& rect, int flags, const QString& text, double scale = 1.0);
// `text` centred in `rect`.
void drawCentredText(QPainter* painter, const QRectF& rect, const QString& text, double scale = 1.0);

} // namespace editor::chartstyle
