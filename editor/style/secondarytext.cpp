#include "editor/style/secondarytext.h"

#include <QWidget>

#include <algorithm>
#include <cmath>

namespace editor {

namespace {

double channel(double value)
{
    return value <= 0.04045 ? value / 12.92 : std::pow((value + 0.055) / 1.055, 2.4);
}

double relativeLuminance(const QColor& colour)
{
    return 0.2126 * channel(colour.redF()) + 0.7152 * channel(colour.greenF()) + 0.0722 * channel(colour.blueF());
}

QColor mixed(const QColor& from, const QColor& to, double share)
{
    const auto mix = [share](double a, double b) { return a + (b - a) * share; };
    return QColor::fromRgbF(float(mix(from.redF(), to.redF())), float(mix(from.greenF(), to.greenF())),
                            float(mix(from.blueF(), to.blueF())));
}

} // namespace

double contrastRatio(const QColor& first, const QColor& second)
{
    const double a = relativeLuminance(first);
    const double b = relativeLuminance(second);
    return (std::max(a, b) + 0.05) / (std::min(a, b) + 0.05);
}

QColor secondaryTextColor(const QPalette& palette, QPalette::ColorRole background)
{
    const QColor back = palette.color(QPalette::Active, background);
    const QColor text = palette.color(QPalette::Active, background == QPalette::Base ? QPalette::Text
                                                                                      : QPalette::WindowText);
    // From halfway towards the background back to the text colour, the
    // first share that reads well.
    for (int percent = 50; percent > 0; percent -= 2) {
        const QColor candidate = mixed(text, back, percent / 100.0);
        if (contrastRatio(candidate, back) >= kMinimumTextContrast)
            return candidate;
    }
    return text;
}

void useSecondaryText(QWidget* widget)
{
    QPalette palette = widget->palette();
    const QColor colour = secondaryTextColor(palette);
    for (QPalette::ColorGroup group : {QPalette::Active, QPalette::Inactive})
        palette.setColor(group, QPalette::WindowText, colour);
    widget->setPalette(palette);
}

} // namespace editor
