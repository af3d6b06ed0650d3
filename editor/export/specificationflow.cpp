#include "editor/export/specificationflow.h"

#include "editor/export/conditionnotes.h"
#include "editor/text/displaytext.h"

#include <algorithm>

namespace editor::specification {

Style::Style(const QPaintDevice& device, double dotsPerPoint)
    : m_dotsPerPoint(dotsPerPoint)
{
    for (int i = 0; i < kTextStyles; ++i) {
        m_fonts.push_back(makeFont(TextStyle(i)));
        m_metrics.emplace_back(m_fonts.back(), &device);
    }
}

QStringList Style::wrap(TextStyle style, const QString& text, double width) const
{
    const QFontMetricsF& metrics = this->metrics(style);
    const auto advance = [&metrics](const QString& part) { return metrics.horizontalAdvance(part); };
    const double room = std::max(width - pt(kMeasureSlack), pt(4));
    QString normalised = text;
    normalised.replace(QStringLiteral("\r\n"), QStringLiteral("\n"));
    normalised.replace(QLatin1Char('\r'), QLatin1Char('\n'));
    normalised.replace(QLatin1Char('\t'), QLatin1Char(' '));
    normalised = withVisibleControls(normalised);
    QStringList lines;
    for (const QString& paragraph : normalised.split(QLatin1Char('\n'))) {
        const QStringList wrapped = wrapText(paragraph, room, room, advance);
        if (wrapped.isEmpty())
            lines << QString();
        else
            lines << wrapped;
    }
    while (!lines.isEmpty() && lines.back().isEmpty())
        lines.removeLast();
    return lines;
}

QFont Style::makeFont(TextStyle style)
{
    double points = 9.5;
    bool bold = false;
    switch (style) {
    case TextStyle::Body: break;
    case TextStyle::Bold: bold = true; break;
    case TextStyle::Small: points = 8; break;
    case TextStyle::TableHead: points = 8.5; bold = true; break;
    case TextStyle::Title: points = 26; bold = true; break;
    case TextStyle::Subtitle: points = 15; break;
    case TextStyle::Heading: points = 17; bold = true; break;
    case TextStyle::Subheading: points = 12; bold = true; break;
    }
    QFont font;
    font.setPointSizeF(points);
    font.setBold(bold);
    font.setHintingPreference(QFont::PreferNoHinting);
    // No ligatures: "fi" stays two letters for text search and copy.
    font.setStyleStrategy(QFont::PreferNoShaping);
    return font;
}

void addText(Flow& flow, const Style& style, TextStyle textStyle, const QString& text, double keepWithNext,
             const QColor& color)
{
    const QStringList lines = style.wrap(textStyle, text, flow.body().width());
    const QFont font = style.font(textStyle);
    const QFontMetricsF metrics = style.metrics(textStyle);
    const double spacing = metrics.lineSpacing();
    const double ascent = metrics.ascent();
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const QString line = lines[i];
        const double after = double(lines.size() - 1 - i) * spacing + keepWithNext;
        flow.add(
            spacing,
            [font, color, line, ascent](QPainter& painter, const QPointF& at) {
                painter.setFont(font);
                painter.setPen(color);
                painter.drawText(QPointF(at.x(), at.y() + ascent), line);
            },
            i == 0 ? std::min(after, flow.body().height() / 3) : 0);
    }
}

void addHeading(Flow& flow, const Style& style, TextStyle textStyle, const QString& text, double keepWithNext)
{
    flow.space(style.pt(kSectionGap));
    addText(flow, style, textStyle, text, keepWithNext + style.pt(4));
    flow.space(style.pt(4));
}

void placeBand(Flow& flow, double height, const QFont& font, double ascent, const QColor& color, const QString& text)
{
    flow.place(height, [font, ascent, color, text](QPainter& painter, const QPointF& at) {
        painter.setFont(font);
        painter.setPen(color);
        painter.drawText(QPointF(at.x(), at.y() + ascent), text);
    });
}

QString orDash(const QString& text)
{
    return text.trimmed().isEmpty() ? QStringLiteral("—") : text;
}

} // namespace editor::specification
