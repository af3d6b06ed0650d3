#pragma once

#include <QCoreApplication>
#include <QList>
#include <QPointF>
#include <QSizeF>
#include <QString>
#include <QStringList>

#include <functional>

class QPainter;

namespace editor {

class ChartScene;

// The exported chart never cuts a condition short: a condition that does not
// fit its label ends in a note marker there ("Start AND…[1]") and is given in
// full in a "Conditions" list under the chart. The on-screen chart elides it
// and its tooltip shows it whole.

// A condition the exported chart lists under itself.
struct ConditionNote {
    int number = 0;       // the "[1]" of the label and the list, from 1
    QString transitionId; // core's id, "F1->A2"
    QString condition;    // in full, on one line
};

// What the numbering needs to know of one transition label.
struct LabelFit {
    QString transitionId;
    QString condition;
    bool drawn = true; // in the picture: not hidden, or hidden elements shown
    bool fits = true;  // the whole condition is in the label
};

// One note per drawn label whose condition does not fit, numbered from 1 in
// the order given: the template's transition order, so that a number stays
// as long as the labels before it keep their fit.
QList<ConditionNote> numberConditionNotes(const QList<LabelFit>& labels);
// The same for the scene as it draws now (its transitions in template order,
// the visible ones, with their on-screen fit).
QList<ConditionNote> conditionNotes(const ChartScene& scene);

// The list entry of a note: "[1] F1 → A2: Start AND NOT Stop AND …", the
// transition named as everywhere in the editor.
QString conditionNoteText(const ConditionNote& note);

// `text` in lines no wider than `firstWidth` (the first line) and
// `restWidth` (the others), widths as `advance` measures them: broken at
// spaces, and a word wider than a line between its characters. Only the
// spaces where a line breaks are left out: nothing is cut.
QStringList wrapText(const QString& text, double firstWidth, double restWidth,
                     const std::function<double(const QString&)>& advance);

// Where pages start when lines of `lineHeights` fill pages of `pageRoom`
// height each: the index of each page's first line (the first page's is 0).
// A line taller than a page has a page of its own.
QList<int> pageBreaks(const QList<double>& lineHeights, double pageRoom);

// How a PDF or a print puts the chart (`chart`: the sheet with its margin,
// in scene units) and its list (`listHeight` scene units when as wide as the
// chart; 0 for none) on pages of `page` device units: `scale` device units
// per scene unit for the chart, and the list under the chart on its page or
// on the following pages at the same scale. The list shares the page when
// that shrinks the chart by at most kMaxShrinkForList.
struct PagePlan {
    double scale = 1;
    bool listBelowChart = true;
};
inline constexpr double kMaxShrinkForList = 0.15;
PagePlan planPages(QSizeF chart, double listHeight, QSizeF page);

// The "Conditions" list as drawn under an exported chart: a heading, then
// each note wrapped to `width`, its further lines indented past its number.
// Scene units, in the chart's label font.
class ConditionList {
    Q_DECLARE_TR_FUNCTIONS(editor::ConditionList)

public:
    ConditionList(const QList<ConditionNote>& notes, double width);

    bool isEmpty() const { return m_lines.isEmpty(); }
    // Of every line, heading included, and the gaps above and below the list.
    double height() const;
    QList<double> lineHeights() const;
    qsizetype lineCount() const { return m_lines.size(); }
    // The lines' texts, for tests.
    QStringList lineTexts() const;

    // Lines [first, end), the first's top at `topLeft`.
    void paint(QPainter& painter, QPointF topLeft, qsizetype first, qsizetype end) const;

    // The gap above the list (under the chart's sheet) and below it.
    static constexpr double kTopGap = 6;
    static constexpr double kBottomGap = 12;

private:
    struct Line {
        QString text;
        double indent = 0;
        double height = 0;
        bool heading = false;
    };
    QList<Line> m_lines;
};

} // namespace editor
