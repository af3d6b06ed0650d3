#pragma once

// Text that says less than the main text (hints, notes, defaults, what is
// not effective) but must still be read, on a projector too. Qt's disabled
// and placeholder colours are for what cannot be used: Fusion's disabled
// text is #bebebe on #efefef, a contrast of 1.5:1. This colour keeps the
// contrast WCAG 2 asks of body text.

#include <QColor>
#include <QPalette>

class QWidget;

namespace editor {

inline constexpr double kMinimumTextContrast = 4.5;

// WCAG 2 contrast ratio of two opaque colours, 1 … 21.
double contrastRatio(const QColor& first, const QColor& second);

// Between the palette's text colour and `background`, as light as the
// contrast of kMinimumTextContrast allows (the text colour itself when
// even that is short). Text and WindowText go with Window; Text with Base.
QColor secondaryTextColor(const QPalette& palette, QPalette::ColorRole background = QPalette::Window);

// Draws the label (or any widget whose text is WindowText) in that colour.
void useSecondaryText(QWidget* widget);

} // namespace editor
