#include "editor/export/conditionnotes.h"

#include "editor/chart/chartstyle.h"
#include "editor/chart/gemma/chartscene.h"
#include "editor/chart/gemma/transitionitem.h"
#include "editor/text/elementlabels.h"

#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>

namespace editor {

namespace {

// The heading is drawn as large as a family frame's title, with this much
// room under it before the first note.
constexpr double kHeadingGap = 4;

// How many characters of `word` from the start fit in `width`: at least one
// (a line holds something), never half of a surrogate pair. Measures no
// more than twice what fits: a font's metrics overflow on a text of a
// hundred thousand characters, and measuring all of a long word for each of
// its lines would take quadratic time.
qsizetype fittingPrefix(QStringView word, double width, const std::function<double(const QString&)>& advance)
{
    qsizetype low = 1; // fits, or must anyway
    qsizetype high = std::min<qsizetype>(word.size(), 16);
    while (high < word.size() && advance(word.left(high).toString()) <= width) {
        low = high;
        high = std::min(word.size(), 2 * high);
    }
    if (high == word.size() && advance(word.toString()) <= width)
        return high;
    while (low < high) {
        const qsizetype middle = (low + high + 1) / 2;
        if (advance(word.left(middle).toString()) <= width)
            low = middle;
        else
            high = middle - 1;
    }
    if (low < word.size() && low > 1 && word[low - 1].isHighSurrogate())
        --low;
    else if (low == 1 && word.size() > 1 && word[0].isHighSurrogate())
        low = 2;
    return low;
}

} // namespace

QList<ConditionNote> numberConditionNotes(const QList<LabelFit>& labels)
{
    QList<ConditionNote> notes;
    for (const LabelFit& label : labels) {
        if (!label.drawn || label.fits || label.condition.isEmpty())
            continue;
        notes.append({int(notes.size()) + 1, label.transitionId, label.condition});
    }
    return notes;
}

QList<ConditionNote> conditionNotes(const ChartScene& scene)
{
    QList<LabelFit> labels;
    for (const TransitionItem* item : scene.transitions())
        labels.append({item->id(), item->conditionText(), item->isVisible(), !item->conditionCut()});
    return numberConditionNotes(labels);
}

QString conditionNoteText(const ConditionNote& note)
{
    //: an entry of the Conditions list under an exported chart: note number, transition, its condition in full
    return ConditionList::tr("[%1] %2: %3")
        .arg(QString::number(note.number), transitionLabel(note.transitionId), note.condition);
}

QStringList wrapText(const QString& text, double firstWidth, double restWidth,
                     const std::function<double(const QString&)>& advance)
{
    QStringList lines;
    QString current;
    double width = firstWidth;
    const auto newLine = [&] {
        lines.append(current);
        current.clear();
        width = restWidth;
    };
    const auto fits = [&](QStringView part) { return fittingPrefix(part, width, advance) >= part.size(); };
    for (QStringView word : QStringView(text).split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        if (!current.isEmpty()) {
            const QString longer = current + QLatin1Char(' ') + word.toString();
            if (fits(longer)) {
                current = longer;
                continue;
            }
            newLine();
        }
        QStringView rest = word;
        for (qsizetype fitting = fittingPrefix(rest, width, advance); fitting < rest.size();
             fitting = fittingPrefix(rest, width, advance)) {
            current = rest.left(fitting).toString();
            rest = rest.mid(fitting);
            newLine();
        }
        current = rest.toString();
    }
    if (!current.isEmpty())
        lines.append(current);
    return lines;
}

QList<int> pageBreaks(const QList<double>& lineHeights, double pageRoom)
{
    QList<int> starts;
    double used = 0;
    for (qsizetype i = 0; i < lineHeights.size(); ++i) {
        if (i == 0 || (used > 0 && used + lineHeights[i] > pageRoom)) {
            starts.append(int(i));
            used = 0;
        }
        used += lineHeights[i];
    }
    return starts;
}

PagePlan planPages(QSizeF chart, double listHeight, QSizeF page)
{
    if (chart.isEmpty() || page.isEmpty())
        return {};
    const double alone = std::min(page.width() / chart.width(), page.height() / chart.height());
    if (listHeight <= 0)
        return {alone, true};
    const double together = std::min(page.width() / chart.width(), page.height() / (chart.height() + listHeight));
    if (together >= alone * (1 - kMaxShrinkForList))
        return {together, true};
    return {alone, false};
}

ConditionList::ConditionList(const QList<ConditionNote>& notes, double width)
{
    if (notes.isEmpty())
        return;
    const QFontMetricsF metrics(chartstyle::font());
    const double lineSpacing = metrics.lineSpacing();
    m_lines.append({tr("Conditions"), 0, lineSpacing * chartstyle::kTitleScale + kHeadingGap, true});
    const auto advance = [&metrics](const QString& text) { return metrics.horizontalAdvance(text); };
    for (const ConditionNote& note : notes) {
        // Further lines start under the transition's name, past "[1] ".
        const double indent = std::min(width / 2, advance(QStringLiteral("[%1] ").arg(note.number)));
        const QStringList lines = wrapText(conditionNoteText(note), width, width - indent, advance);
        for (qsizetype i = 0; i < lines.size(); ++i)
            m_lines.append({lines[i], i == 0 ? 0.0 : indent, lineSpacing, false});
    }
}

double ConditionList::height() const
{
    if (m_lines.isEmpty())
        return 0;
    double height = kTopGap + kBottomGap;
    for (const Line& line : m_lines)
        height += line.height;
    return height;
}

QList<double> ConditionList::lineHeights() const
{
    QList<double> heights;
    for (const Line& line : m_lines)
        heights.append(line.height);
    return heights;
}

QStringList ConditionList::lineTexts() const
{
    QStringList texts;
    for (const Line& line : m_lines)
        texts.append(line.text);
    return texts;
}

void ConditionList::paint(QPainter& painter, QPointF topLeft, qsizetype first, qsizetype end) const
{
    const QFontMetricsF metrics(chartstyle::font());
    painter.save();
    painter.setPen(chartstyle::labelColor());
    double y = topLeft.y();
    for (qsizetype i = std::max<qsizetype>(0, first); i < std::min(end, m_lines.size()); ++i) {
        const Line& line = m_lines[i];
        if (line.heading) {
            const double height = metrics.lineSpacing() * chartstyle::kTitleScale;
            const double width = (metrics.horizontalAdvance(line.text) + 2) * chartstyle::kTitleScale;
            chartstyle::drawText(&painter, QRectF(topLeft.x(), y, width, height), Qt::AlignLeft | Qt::AlignVCenter,
                                 line.text, chartstyle::kTitleScale);
        } else {
            painter.setFont(chartstyle::font());
            painter.drawText(QPointF(topLeft.x() + line.indent, y + metrics.ascent()), line.text);
        }
        y += line.height;
    }
    painter.restore();
}

} // namespace editor
