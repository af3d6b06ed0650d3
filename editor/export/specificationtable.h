#pragma once

// The tables of the Specification PDF.

#include "editor/export/specificationflow.h"

#include <QList>
#include <QString>
#include <QStringList>

#include <algorithm>
#include <optional>
#include <vector>

namespace editor::specification {

struct Column {
    QString title;
    double points = 0; // at least; 0: what the other columns leave
};

// A table whose cells wrap: it breaks between rows, repeating its header
// row on every page; a row taller than a page breaks between its lines.
// Each cell's lines are drawn together, so a text tool reads a cell whole.
class Table {
public:
    Table(const Style& style, const QList<Column>& columns, double width, bool header = true, bool boldFirst = false)
        : m_style(style)
        , m_columns(columns)
        , m_width(width)
        , m_hasHeader(header)
        , m_boldFirst(boldFirst)
    {
    }

    void addRow(const QStringList& cells)
    {
        m_cells.push_back(cells);
        m_laidOut = false;
    }
    bool isEmpty() const { return m_cells.empty(); }

    // What a heading above the table keeps with it: the header and the first row.
    double startHeight() const
    {
        layOut();
        return (m_header ? height(*m_header, 0, m_header->lines) : 0)
               + (m_rows.empty() ? 0 : height(m_rows.front(), 0, m_rows.front().lines));
    }

    void flowInto(Flow& flow) const;

private:
    struct Row {
        QList<QStringList> cells;
        qsizetype lines = 1;
        bool head = false;
    };

    TextStyle styleOf(bool head, qsizetype column) const
    {
        if (head)
            return TextStyle::TableHead;
        return m_boldFirst && column == 0 ? TextStyle::Bold : TextStyle::Body;
    }
    double lineSpacing(bool head) const
    {
        return std::max(m_style.metrics(styleOf(head, 0)).lineSpacing(),
                        m_style.metrics(styleOf(head, 1)).lineSpacing());
    }

    // The column widths, then every row wrapped to them. A column given a
    // width widens to its longest word (its header's too), up to a third
    // of the table, so that words break between their letters only when
    // nothing else will do; the columns without a width share the rest.
    void layOut() const;

    Row makeRow(const QStringList& cells, bool head) const;

    double height(const Row& row, qsizetype first, qsizetype end) const
    {
        return double(end - first) * lineSpacing(row.head) + 2 * m_style.pt(kCellPadding);
    }

    Paint paint(const Row& row, qsizetype first, qsizetype end) const;

    const Style& m_style;
    QList<Column> m_columns;
    double m_width = 0;
    bool m_hasHeader = true;
    bool m_boldFirst = false;
    std::vector<QStringList> m_cells;
    // Laid out from the above when first needed.
    mutable bool m_laidOut = false;
    mutable QList<double> m_x;
    mutable QList<double> m_widths;
    mutable double m_tableWidth = 0;
    mutable std::optional<Row> m_header;
    mutable std::vector<Row> m_rows;
};

} // namespace editor::specification
