#include "editor/export/specificationtable.h"

#include <QRegularExpression>

#include <algorithm>
#include <cmath>

namespace editor::specification {

namespace {

constexpr qsizetype kLongestMeasuredWord = 1000; // characters: wider than a page

} // namespace

void Table::flowInto(Flow& flow) const
{
    layOut();
    const auto placeHeader = [&] {
        if (m_header)
            flow.place(height(*m_header, 0, m_header->lines), paint(*m_header, 0, m_header->lines));
    };
    // The current page holds nothing of the table but its header.
    bool fresh = flow.atPageTop();
    if (m_header) {
        const double first = m_rows.empty() ? 0 : height(m_rows.front(), 0, m_rows.front().lines);
        const double head = height(*m_header, 0, m_header->lines);
        flow.add(head, paint(*m_header, 0, m_header->lines), std::min(first, flow.body().height() / 3));
        fresh = flow.room() + head >= flow.body().height();
    }
    for (const Row& row : m_rows) {
        const double whole = height(row, 0, row.lines);
        if (whole > flow.room() && !fresh) {
            flow.continuePage();
            placeHeader();
        }
        fresh = false;
        if (whole <= flow.room()) {
            flow.place(whole, paint(row, 0, row.lines));
            continue;
        }
        // Taller than what a page holds: broken between its lines.
        const double spacing = lineSpacing(false);
        for (qsizetype first = 0; first < row.lines;) {
            const double room = flow.room() - 2 * m_style.pt(kCellPadding);
            const qsizetype fitting = std::max<qsizetype>(1, qsizetype(std::floor(room / spacing)));
            const qsizetype end = std::min(row.lines, first + fitting);
            flow.place(height(row, first, end), paint(row, first, end));
            first = end;
            if (first < row.lines) {
                flow.continuePage();
                placeHeader();
            }
        }
    }
}

void Table::layOut() const
{
    if (m_laidOut)
        return;
    m_laidOut = true;
    const double padding = 2 * m_style.pt(kCellPadding);
    // A word of more characters than a third of the table could hold
    // is not measured (a font's metrics overflow on a hundred thousand).
    const double widestWanted = m_width / 3;
    const auto widestWord = [this, widestWanted](TextStyle style, const QString& text) {
        const QFontMetricsF metrics = m_style.metrics(style);
        double widest = 0;
        for (const QString& word : text.split(QRegularExpression(QStringLiteral("\\s+")), Qt::SkipEmptyParts)) {
            widest = std::max(widest, word.size() > kLongestMeasuredWord ? widestWanted
                                                                         : metrics.horizontalAdvance(word));
        }
        return widest;
    };
    QList<double> widths;
    double fixed = 0;
    int rest = 0;
    for (qsizetype c = 0; c < m_columns.size(); ++c) {
        if (m_columns[c].points <= 0) {
            widths << 0;
            ++rest;
            continue;
        }
        double need = widestWord(styleOf(true, c), m_columns[c].title);
        for (const QStringList& cells : m_cells)
            need = std::max(need, widestWord(styleOf(false, c), cells.value(c)));
        const double w =
            std::max(m_style.pt(m_columns[c].points), std::min(need + padding + m_style.pt(1), m_width / 3));
        widths << w;
        fixed += w;
    }
    const double free = rest > 0 ? std::max(m_style.pt(60), (m_width - fixed) / rest) : 0;
    m_x.clear();
    m_widths.clear();
    double x = 0;
    for (qsizetype c = 0; c < m_columns.size(); ++c) {
        const double w = m_columns[c].points > 0 ? widths[c] : free;
        m_x << x;
        m_widths << w;
        x += w;
    }
    m_tableWidth = x;
    m_header.reset();
    if (m_hasHeader) {
        QStringList titles;
        for (const Column& column : m_columns)
            titles << column.title;
        m_header = makeRow(titles, true);
    }
    m_rows.clear();
    for (const QStringList& cells : m_cells)
        m_rows.push_back(makeRow(cells, false));
}

Table::Row Table::makeRow(const QStringList& cells, bool head) const
{
    Row row;
    row.head = head;
    for (qsizetype c = 0; c < m_widths.size(); ++c) {
        const QString text = c < cells.size() ? cells[c] : QString();
        row.cells << m_style.wrap(styleOf(head, c), text, m_widths[c] - 2 * m_style.pt(kCellPadding));
        row.lines = std::max(row.lines, row.cells.back().size());
    }
    return row;
}

Paint Table::paint(const Row& row, qsizetype first, qsizetype end) const
{
    struct Cell {
        QFont font;
        double ascent;
        double x;
        QStringList lines;
    };
    QList<Cell> cells;
    for (qsizetype c = 0; c < row.cells.size(); ++c) {
        const TextStyle style = styleOf(row.head, c);
        cells.append({m_style.font(style), m_style.metrics(style).ascent(), m_x[c],
                      row.cells[c].mid(first, end - first)});
    }
    const double rowHeight = height(row, first, end);
    const double spacing = lineSpacing(row.head);
    const double padding = m_style.pt(kCellPadding);
    const double rule = m_style.pt(0.5);
    const double width = m_tableWidth;
    const bool head = row.head;
    return [=](QPainter& painter, const QPointF& at) {
        if (head)
            painter.fillRect(QRectF(at, QSizeF(width, rowHeight)), headFillColor());
        painter.setPen(inkColor());
        for (const Cell& cell : cells) {
            painter.setFont(cell.font);
            for (qsizetype i = 0; i < cell.lines.size(); ++i) {
                const double baseline = at.y() + padding + double(i) * spacing + cell.ascent;
                painter.drawText(QPointF(at.x() + cell.x + padding, baseline), cell.lines[i]);
            }
        }
        painter.setPen(QPen(ruleColor(), rule));
        painter.drawLine(QPointF(at.x(), at.y() + rowHeight), QPointF(at.x() + width, at.y() + rowHeight));
    };
}

} // namespace editor::specification
