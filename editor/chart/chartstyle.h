#pragma once

#include "core/gemmatemplate.h"

#include <QColor>
#include <QFont>
#include <QRectF>

class QPainter;

// Colours, pen widths and fonts of the chart, in one place so the items
// agree. Sizes are in scene units: the template sheet is 1500 x 960, so a
// 12-unit font still reads at about 9 px when the sheet is fitted on a
// 1366 x 768 screen.
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
inline constexpr double kFiredWidth = 3.2;     // the route of the transition that fired last (simulation)
inline constexpr double kTokenRadius = 3.6;    // a token's dot on its transition bar (simulation)
inline constexpr double kCompleteBadgeSize = 14; // the "C" badge of a nested step (simulation)

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

// Soft tints after the classic GEMMA sheet: stops blue, operation green,
// failures red-orange.
QColor frameFillColor(core::Family family);
QColor frameBorderColor(core::Family family);

// The chart's text uses two fonts: a regular one for the transition labels
// and a bold one for everything else, drawn larger or smaller by scaling.
// Each size of a font is a font engine of its own (fontconfig matching,
// FreeType sizing, shaping tables: 0.3 to 1 ms each, paid by the first frame),
// and the chart is drawn scaled anyway, so a scaled bold font looks the same.
const QFont& labelFont();
const QFont& boldFont();
// The scale of boldFont() for a step's id (larger in the big hub steps) and
// for a badge's letter; family frame titles use it as it is.
double stepIdScale(double boxSize);
inline constexpr double kBadgeScale = 11.0 / 15.0;

// `text` centred in `rect`, in `font` enlarged by `scale`.
void drawCentredText(QPainter* painter, const QRectF& rect, const QString& text, const QFont& font,
                     double scale = 1.0);

} // namespace editor::chartstyle
