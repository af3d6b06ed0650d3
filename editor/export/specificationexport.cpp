#include "editor/export/specificationexport.h"

#include "editor/chart/gemma/chartscene.h"
#include "editor/docks/variablestablemodel.h"
#include "editor/document.h"
#include "editor/export/chartexport.h"
#include "editor/export/conditionnotes.h"
#include "editor/export/exportfile.h"
#include "editor/export/exportoptionsdialog.h"
#include "editor/grafcet/grafcetexport.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/selection.h"
#include "editor/stdstring.h"
#include "editor/text/displaytext.h"
#include "editor/text/elementlabels.h"
#include "editor/text/gemmastatenames.h"

#include "core/checks/diagnostic.h"
#include "core/codegen/stgenerator.h"
#include "core/model/model.h"

#include <QFileInfo>
#include <QFont>
#include <QFontMetricsF>
#include <QLocale>
#include <QPagedPaintDevice>
#include <QPainter>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace editor {

namespace {

// Sizes in points.
constexpr double kHeaderBand = 22;      // the running header of one line, its rule and the gap under it
constexpr double kFooterBand = 18;      // the gap above the page number and the number
constexpr double kCellPadding = 3;      // around a table cell's text
constexpr double kSectionGap = 14;      // above a heading that does not start its page
constexpr double kMaxGrafcetText = 10;  // a small GRAFCET grows to fill its page no further
constexpr double kMeasureSlack = 0.5;   // kept free at a line's end, against rounding
constexpr qsizetype kLongestMeasuredWord = 1000; // characters: wider than a page

QColor inkColor() { return QColor(0x20, 0x24, 0x2a); }
QColor mutedColor() { return QColor(0x5b, 0x64, 0x70); }
QColor headFillColor() { return QColor(0xe9, 0xed, 0xf2); }
QColor ruleColor() { return QColor(0xb8, 0xbe, 0xc7); }

enum class TextStyle { Body, Bold, Small, TableHead, Title, Subtitle, Heading, Subheading };
constexpr int kTextStyles = int(TextStyle::Subheading) + 1;

// The document's fonts and lengths in device units: the painter draws
// unscaled on the PDF writer, so metrics are those of its resolution.
class Style {
public:
    Style(const QPaintDevice& device, double dotsPerPoint)
        : m_dotsPerPoint(dotsPerPoint)
    {
        for (int i = 0; i < kTextStyles; ++i) {
            m_fonts.push_back(makeFont(TextStyle(i)));
            m_metrics.emplace_back(m_fonts.back(), &device);
        }
    }

    double pt(double points) const { return points * m_dotsPerPoint; }
    double dotsPerPoint() const { return m_dotsPerPoint; }

    const QFont& font(TextStyle style) const { return m_fonts[std::size_t(style)]; }
    const QFontMetricsF& metrics(TextStyle style) const { return m_metrics[std::size_t(style)]; }

    // `text` in lines no wider than `width`: its own line breaks kept, the
    // rest broken at spaces, a word wider than a line between its
    // characters (wrapText). No line for an empty text. Every text of the
    // document comes through here: control and bidirectional formatting
    // characters are written out (withVisibleControls), so that none
    // reorders or hides what the reader sees.
    QStringList wrap(TextStyle style, const QString& text, double width) const
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

private:
    static QFont makeFont(TextStyle style)
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

    double m_dotsPerPoint;
    std::vector<QFont> m_fonts;           // by TextStyle
    std::vector<QFontMetricsF> m_metrics; // by TextStyle, on the PDF writer
};

// Draws a block with its top left at `topLeft` (device units).
using Paint = std::function<void(QPainter& painter, const QPointF& topLeft)>;

struct Block {
    double y = 0; // from the body's top
    Paint paint;
};

struct Page {
    QPageLayout::Orientation orientation = QPageLayout::Portrait;
    QString section; // in the running header
    std::vector<Block> blocks;
};

// The pages as they fill: blocks go down the current page's body and on to
// a new page when they do not fit. Planned before anything is painted, so
// that every page knows the page count and the contents their numbers.
class Flow {
public:
    // `printable`: a portrait page's printable area; the body is what the
    // running header and foot leave of it, in either orientation.
    Flow(const QSizeF& printable, double bands)
        : m_printable(printable)
        , m_bands(bands)
    {
    }

    void newPage(QPageLayout::Orientation orientation, const QString& section)
    {
        m_pages.push_back({orientation, section, {}});
        m_y = 0;
    }
    // A new page of the same section and orientation.
    void continuePage() { newPage(m_pages.back().orientation, m_pages.back().section); }

    QSizeF body() const
    {
        const bool landscape = !m_pages.empty() && m_pages.back().orientation == QPageLayout::Landscape;
        const QSizeF page = landscape ? m_printable.transposed() : m_printable;
        return QSizeF(page.width(), page.height() - m_bands);
    }
    double room() const { return body().height() - m_y; }
    bool atPageTop() const { return m_y <= 0; }
    int pageNumber() const { return int(m_pages.size()); }

    // Here, whether it fits or not.
    void place(double height, Paint paint)
    {
        m_pages.back().blocks.push_back({m_y, std::move(paint)});
        m_y += height;
    }
    // Here when it fits with `keepWithNext` more under it, else on a new page.
    void add(double height, Paint paint, double keepWithNext = 0)
    {
        if (!atPageTop() && height + keepWithNext > room())
            continuePage();
        place(height, std::move(paint));
    }
    // Blank room, none at a page's top.
    void space(double height)
    {
        if (!atPageTop())
            m_y += std::min(height, room());
    }

    const std::vector<Page>& pages() const { return m_pages; }

private:
    QSizeF m_printable;
    double m_bands;
    std::vector<Page> m_pages;
    double m_y = 0;
};

// `text` wrapped to the body's width, one block a line so that a paragraph
// breaks between its lines; `keepWithNext` more room wanted under its last line.
void addText(Flow& flow, const Style& style, TextStyle textStyle, const QString& text, double keepWithNext = 0,
             const QColor& color = inkColor())
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

// A fixed-height band of one line at a page's top: the first page of a
// drawing has its heading there, the following ones a line saying whose
// pages they continue, so that every page of it has the same room left.
void placeBand(Flow& flow, double height, const QFont& font, double ascent, const QColor& color, const QString& text)
{
    flow.place(height, [font, ascent, color, text](QPainter& painter, const QPointF& at) {
        painter.setFont(font);
        painter.setPen(color);
        painter.drawText(QPointF(at.x(), at.y() + ascent), text);
    });
}

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

    void flowInto(Flow& flow) const
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
    void layOut() const
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

    Row makeRow(const QStringList& cells, bool head) const
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

    double height(const Row& row, qsizetype first, qsizetype end) const
    {
        return double(end - first) * lineSpacing(row.head) + 2 * m_style.pt(kCellPadding);
    }

    Paint paint(const Row& row, qsizetype first, qsizetype end) const
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

// An entry of the title page's contents; its page is known once the
// section is planned, before anything is painted.
struct ContentsEntry {
    QString text;
    bool sub = false;
    int page = 0;
};

QString orDash(const QString& text)
{
    return text.trimmed().isEmpty() ? QStringLiteral("—") : text;
}

QString stateLabel(const QString& id)
{
    return id + QLatin1Char(' ') + officialStateName(id);
}

// The specification of one model on the pages of one PDF: planned section
// by section into a Flow, then painted page by page with the running
// header and the foot, which know the page count.
class SpecificationPages {
    Q_DECLARE_TR_FUNCTIONS(SpecificationExport)

public:
    SpecificationPages(Document& document, const QDateTime& date, QPagedPaintDevice& device, const QSizeF& printable,
                       double dotsPerPoint);

    // Lays the sections out, then draws every page, telling `progress`
    // after each; false when it cancelled.
    bool write(QPainter& painter, const SpecificationExport::Progress& progress);

private:
    // Every page; false when `pageDone` returned false after one.
    bool paint(QPainter& painter, const std::function<bool()>& pageDone) const;

    // The contents' entries, in order; then one per GRAFCET and the code's.
    enum Entry { ChartEntry, StatesEntry, TransitionsEntry, VariablesEntry, GrafcetsEntry };

    void planTitlePage();
    void planChart();
    void planStates();
    void planTransitions();
    void planVariables();
    // A section of the tables: its heading, what it lists, the table (or
    // `empty` when it has no row).
    void planTable(Entry entry, const QString& heading, const QString& intro, const Table& table,
                   const QString& empty);
    void planGrafcet(qsizetype index);
    void planCode();

    void startsHere(std::size_t entry) { (*m_contents)[entry].page = m_flow->pageNumber(); }
    double bodyLine() const { return m_style.metrics(TextStyle::Body).lineSpacing(); }
    int errorCount() const;

    Document& m_document;
    const core::Model& m_model;
    QDateTime m_date;
    QPagedPaintDevice& m_device;
    QSizeF m_printable;
    Style m_style;
    double m_width; // of a portrait page's body
    QString m_modelName;
    // The sections, as the running header names them.
    QString m_titleSection;
    QString m_chartSection;
    QString m_tablesSection;
    QString m_grafcetSection;
    QString m_codeSection;
    QStringList m_headerLines; // the model's name, wrapped clear of the section
    double m_bodyTop = 0;
    QStringList m_grafcetSteps; // the GRAFCETs that generate code, in state order
    std::map<QString, int> m_grafcetPages;
    std::shared_ptr<std::vector<ContentsEntry>> m_contents;
    std::size_t m_codeEntry = 0;

    // The scenes the pages draw, alive until the pages are painted
    // (declared before the flow, whose blocks refer to them).
    Selection m_selection;
    ChartScene m_chartScene;
    std::vector<std::unique_ptr<GrafcetScene>> m_grafcetScenes;
    std::optional<Flow> m_flow;
};

SpecificationPages::SpecificationPages(Document& document, const QDateTime& date, QPagedPaintDevice& device,
                                       const QSizeF& printable, double dotsPerPoint)
    : m_document(document)
    , m_model(document.model())
    , m_date(date)
    , m_device(device)
    , m_printable(printable)
    , m_style(device, dotsPerPoint)
    , m_width(printable.width())
    , m_modelName(fromStd(m_model.settings().name))
    , m_titleSection(tr("Specification"))
    , m_chartSection(tr("GEMMA chart"))
    , m_tablesSection(tr("States, transitions and variables"))
    , m_grafcetSection(tr("Nested GRAFCETs"))
    , m_codeSection(tr("Generated code"))
    , m_contents(std::make_shared<std::vector<ContentsEntry>>())
    , m_chartScene(&document, &m_selection)
{
    const QFontMetricsF small = m_style.metrics(TextStyle::Small);
    double sectionWidth = 0;
    for (const QString& section : {m_titleSection, m_chartSection, m_tablesSection, m_grafcetSection, m_codeSection})
        sectionWidth = std::max(sectionWidth, small.horizontalAdvance(section));
    m_headerLines = m_style.wrap(TextStyle::Small, m_modelName, m_width - sectionWidth - m_style.pt(12));
    if (m_headerLines.isEmpty())
        m_headerLines << QString();
    m_bodyTop = m_style.pt(kHeaderBand) + double(m_headerLines.size() - 1) * small.lineSpacing();
    m_flow.emplace(printable, m_bodyTop + m_style.pt(kFooterBand));

    for (const core::Step& step : m_model.steps()) {
        if (m_model.effectiveGrafcet(step.id))
            m_grafcetSteps << fromStd(step.id);
    }
    // The contents, whose pages the sections fill in.
    m_contents->push_back({tr("GEMMA chart")});
    m_contents->push_back({tr("States")});
    m_contents->push_back({tr("Transitions")});
    m_contents->push_back({tr("Variables")});
    if (!m_grafcetSteps.isEmpty()) {
        m_contents->push_back({tr("Nested GRAFCETs")});
        for (const QString& id : std::as_const(m_grafcetSteps))
            m_contents->push_back({SpecificationExport::grafcetTitle(id), true});
    }
    m_codeEntry = m_contents->size();
    m_contents->push_back({tr("Generated code")});
}

bool SpecificationPages::write(QPainter& painter, const SpecificationExport::Progress& progress)
{
    std::vector<std::function<void()>> sections{[this] { planTitlePage(); }, [this] { planChart(); },
                                                [this] { planStates(); },    [this] { planTransitions(); },
                                                [this] { planVariables(); }};
    for (qsizetype i = 0; i < m_grafcetSteps.size(); ++i)
        sections.push_back([this, i] { planGrafcet(i); });
    sections.push_back([this] { planCode(); });
    const int planned = int(sections.size());
    int done = 0;
    const auto tell = [&](int total) { return !progress || progress(++done, total); };
    for (const std::function<void()>& section : sections) {
        section();
        if (!tell(planned + 1)) // the pages are one more part until counted
            return false;
    }
    const int pages = int(m_flow->pages().size());
    return paint(painter, [&] { return tell(planned + pages); });
}

int SpecificationPages::errorCount() const
{
    int errors = 0;
    for (const core::Diagnostic& diagnostic : m_document.diagnostics())
        errors += diagnostic.severity == core::Severity::Error ? 1 : 0;
    return errors;
}

void SpecificationPages::planTitlePage()
{
    Flow& flow = *m_flow;
    flow.newPage(QPageLayout::Portrait, m_titleSection);
    flow.place(m_style.pt(70), [](QPainter&, const QPointF&) {});
    addText(flow, m_style, TextStyle::Title, m_modelName);
    flow.space(m_style.pt(4));
    addText(flow, m_style, TextStyle::Subtitle, tr("GEMMA-GRAFCET specification"), 0, mutedColor());
    flow.space(m_style.pt(28));

    int warnings = 0;
    for (const core::Diagnostic& diagnostic : m_document.diagnostics())
        warnings += diagnostic.severity == core::Severity::Warning ? 1 : 0;
    QStringList checks;
    if (const int errors = errorCount(); errors > 0)
        checks << tr("%n error(s)", nullptr, errors);
    if (warnings > 0)
        checks << tr("%n warning(s)", nullptr, warnings);
    const QString file = QFileInfo(m_document.filePath()).fileName();
    const core::ModelSettings& settings = m_model.settings();
    Table facts(m_style, {{QString(), 150}, {QString(), 0}}, m_width, false, true);
    facts.addRow({tr("File"), file.isEmpty() ? tr("not saved yet") : file});
    facts.addRow({tr("Date"), QLocale().toString(m_date.date(), QLocale::LongFormat) + QStringLiteral(", ")
                                  + QLocale().toString(m_date.time(), QLocale::ShortFormat)});
    facts.addRow({tr("Initial state"), stateLabel(fromStd(m_model.initialStep().id))});
    facts.addRow({tr("PLC task cycle"), tr("%1 ms").arg(settings.cycleTimeMs)});
    facts.addRow({tr("Code dialect"), ExportOptionsDialog::dialectText(settings.dialect)});
    facts.addRow({tr("Nested GRAFCET evolution"), settings.evolution == core::EvolutionRule::UntilStable
                                                      ? tr("Until stable, in one call of its function block")
                                                      : tr("One evolution per PLC scan")});
    facts.addRow({tr("Checks"), checks.isEmpty() ? tr("No problems found") : checks.join(QStringLiteral(", "))});
    facts.addRow({tr("Written by"), tr("GG Studio %1").arg(QStringLiteral(GGSTUDIO_VERSION))});
    facts.flowInto(flow);

    addHeading(flow, m_style, TextStyle::Subheading, tr("Contents"), bodyLine());
    const QFont font = m_style.font(TextStyle::Body);
    const double spacing = bodyLine() * 1.15;
    const double indent = m_style.pt(16);
    const double width = m_width;
    for (std::size_t i = 0; i < m_contents->size(); ++i) {
        flow.add(spacing, [contents = m_contents, i, font, spacing, indent, width](QPainter& painter,
                                                                                  const QPointF& at) {
            const ContentsEntry& entry = (*contents)[i];
            painter.setFont(font);
            painter.setPen(inkColor());
            const double left = entry.sub ? indent : 0;
            const QRectF line(at.x() + left, at.y(), width - left, spacing);
            painter.drawText(line, Qt::AlignLeft | Qt::AlignVCenter, entry.text);
            painter.drawText(line, Qt::AlignRight | Qt::AlignVCenter, QString::number(entry.page));
        });
    }
}

// The GEMMA chart on a landscape page, its Conditions list on the next
// pages when it does not fit under it.
void SpecificationPages::planChart()
{
    Flow& flow = *m_flow;
    flow.newPage(QPageLayout::Landscape, m_chartSection);
    startsHere(ChartEntry);
    const QFontMetricsF heading = m_style.metrics(TextStyle::Heading);
    const double band = heading.lineSpacing() + m_style.pt(6);
    placeBand(flow, band, m_style.font(TextStyle::Heading), heading.ascent(), inkColor(), tr("GEMMA chart"));
    const QSizeF area(flow.body().width(), flow.room());
    auto pages = std::make_shared<ChartExport::Pages>(m_chartScene, area);
    for (qsizetype i = 0; i < pages->count(); ++i) {
        if (i > 0) {
            flow.continuePage();
            placeBand(flow, band, m_style.font(TextStyle::Small), m_style.metrics(TextStyle::Small).ascent(),
                      mutedColor(), tr("GEMMA chart, continued"));
        }
        flow.place(area.height(), [pages, i](QPainter& painter, const QPointF& at) {
            painter.translate(at);
            pages->paint(painter, i);
        });
    }
}

void SpecificationPages::planStates()
{
    m_flow->newPage(QPageLayout::Portrait, m_tablesSection);
    Table states(m_style,
                 {{tr("State"), 38}, {tr("Name"), 118}, {tr("Type"), 84}, {tr("GRAFCET"), 52}, {tr("Comment"), 0}},
                 m_width);
    for (const core::Step& step : m_model.steps()) {
        if (step.hidden)
            continue;
        const QString id = fromStd(step.id);
        QString type = stepTypeText(step.type);
        if (step.initial)
            type = tr("%1, initial").arg(type);
        QString grafcet;
        if (const core::Grafcet* nested = m_model.effectiveGrafcet(step.id))
            grafcet = tr("%n step(s)", nullptr, int(nested->steps().size()));
        states.addRow({id, officialStateName(id), type, orDash(grafcet), orDash(fromStd(step.comment))});
    }
    planTable(StatesEntry, tr("States"),
              tr("The visible states of the GEMMA chart, in state order. A macro-step or an enclosing "
                 "step runs its nested GRAFCET while it is active."),
              states, QString());
}

void SpecificationPages::planTable(Entry entry, const QString& heading, const QString& intro, const Table& table,
                                   const QString& empty)
{
    Flow& flow = *m_flow;
    addHeading(flow, m_style, TextStyle::Heading, heading, 0);
    startsHere(entry);
    addText(flow, m_style, TextStyle::Body, intro, table.startHeight() + m_style.pt(6));
    flow.space(m_style.pt(6));
    if (table.isEmpty())
        addText(flow, m_style, TextStyle::Body, empty);
    else
        table.flowInto(flow);
}

// The transitions that take part, by source and priority.
void SpecificationPages::planTransitions()
{
    Table transitions(m_style,
                      {{tr("Transition"), 92}, {tr("Priority"), 58}, {tr("Condition"), 0}, {tr("Tokens"), 96}},
                      m_width);
    for (const core::Transition& transition : m_model.transitions()) {
        if (!m_model.isEffective(transition))
            continue;
        QString priority = QString::number(m_model.priority(transition.id));
        if (transition.negated)
            priority = tr("%1, negated").arg(priority);
        QStringList tokens;
        for (const std::string& token : transition.tokens)
            tokens << fromStd(token);
        transitions.addRow({transitionLabel(transition), priority, orDash(fromStd(transition.condition)),
                            orDash(tokens.join(QStringLiteral(", ")))});
    }
    planTable(TransitionsEntry, tr("Transitions"),
              tr("The transitions that take part: visible, between visible states. A state evaluates "
                 "its transitions by priority, 1 first; a negated transition fires when its condition "
                 "is FALSE."),
              transitions, tr("No transition takes part."));
}

void SpecificationPages::planVariables()
{
    Table variables(
        m_style,
        {{tr("Name"), 104}, {tr("Kind"), 54}, {tr("Type"), 44}, {tr("Default"), 58}, {tr("Comment"), 0}},
        m_width);
    for (const core::Variable& variable : m_model.variables()) {
        variables.addRow({fromStd(variable.name), VariablesTableModel::kindText(variable.kind),
                          fromStd(std::string(core::iecTypeName(variable.type))),
                          orDash(fromStd(variable.defaultValue)), orDash(fromStd(variable.comment))});
    }
    planTable(VariablesEntry, tr("Variables"),
              tr("The declared variables, in declaration order. Inputs are read from the machine, "
                 "outputs written by the actions of the nested GRAFCETs, internal variables are the "
                 "program's memory. A variable without a default starts at its type's (FALSE, 0)."),
              variables, tr("No variables are declared."));
}

// A nested GRAFCET from a new page: its heading, its drawing (over as many
// pages as it needs), its steps' comments.
void SpecificationPages::planGrafcet(qsizetype index)
{
    Flow& flow = *m_flow;
    const QString id = m_grafcetSteps[index];
    const core::Step* step = m_model.step(id.toStdString());
    const core::Grafcet* grafcet = m_model.effectiveGrafcet(id.toStdString());
    flow.newPage(QPageLayout::Portrait, m_grafcetSection);
    if (index == 0)
        startsHere(GrafcetsEntry);
    startsHere(GrafcetsEntry + 1 + std::size_t(index));
    m_grafcetPages[id] = flow.pageNumber();

    // The heading band: as high on the following pages, which say whose
    // drawing they continue.
    const QStringList facts{stepTypeText(step->type), tr("%n step(s)", nullptr, int(grafcet->steps().size())),
                            tr("%n transition(s)", nullptr, int(grafcet->transitions().size())),
                            tr("function block %1").arg(id + QStringLiteral("_FB"))};
    const QStringList titleLines = m_style.wrap(TextStyle::Heading, SpecificationExport::grafcetTitle(id), m_width);
    const QStringList factLines = m_style.wrap(TextStyle::Small, facts.join(QStringLiteral(" · ")), m_width);
    const QFontMetricsF heading = m_style.metrics(TextStyle::Heading);
    const QFontMetricsF small = m_style.metrics(TextStyle::Small);
    const double band = double(titleLines.size()) * heading.lineSpacing()
                        + double(factLines.size()) * small.lineSpacing() + m_style.pt(10);
    flow.place(band, [=, headingFont = m_style.font(TextStyle::Heading),
                      smallFont = m_style.font(TextStyle::Small)](QPainter& painter, const QPointF& at) {
        painter.setFont(headingFont);
        painter.setPen(inkColor());
        double y = at.y();
        for (const QString& line : titleLines) {
            painter.drawText(QPointF(at.x(), y + heading.ascent()), line);
            y += heading.lineSpacing();
        }
        painter.setFont(smallFont);
        painter.setPen(mutedColor());
        for (const QString& line : factLines) {
            painter.drawText(QPointF(at.x(), y + small.ascent()), line);
            y += small.lineSpacing();
        }
    });

    if (grafcet->steps().empty()) {
        addText(flow, m_style, TextStyle::Body, tr("This GRAFCET has no steps yet."));
    } else {
        GrafcetScene& scene = *m_grafcetScenes.emplace_back(std::make_unique<GrafcetScene>(&m_document, id));
        const QSizeF area(flow.body().width(), flow.room());
        auto pages = std::make_shared<GrafcetExport::Pages>(scene, area, m_style.dotsPerPoint(), kMaxGrafcetText);
        for (qsizetype i = 0; i < pages->count(); ++i) {
            if (i > 0) {
                flow.continuePage();
                placeBand(flow, band, m_style.font(TextStyle::Small), small.ascent(), mutedColor(),
                          tr("Nested GRAFCET of %1, continued").arg(id));
            }
            flow.place(pages->height(i), [pages, i](QPainter& painter, const QPointF& at) {
                painter.translate(at);
                pages->paint(painter, i);
            });
        }
    }

    std::vector<core::GrafcetStep> steps = grafcet->steps();
    std::sort(steps.begin(), steps.end(),
              [](const core::GrafcetStep& a, const core::GrafcetStep& b) { return a.number < b.number; });
    if (std::none_of(steps.begin(), steps.end(), [](const core::GrafcetStep& s) { return !s.comment.empty(); }))
        return;
    Table comments(m_style, {{tr("Step"), 70}, {tr("Comment"), 0}}, m_width);
    for (const core::GrafcetStep& nested : steps) {
        const QString number = QString::number(nested.number);
        comments.addRow({nested.initial ? tr("%1, initial").arg(number) : number, orDash(fromStd(nested.comment))});
    }
    addHeading(flow, m_style, TextStyle::Subheading, tr("Steps of %1").arg(id), comments.startHeight());
    comments.flowInto(flow);
}

// The outline of the generated code: the task, each POU with its interface,
// the globals the generator adds.
void SpecificationPages::planCode()
{
    Flow& flow = *m_flow;
    flow.newPage(QPageLayout::Portrait, m_codeSection);
    startsHere(m_codeEntry);
    const core::Dialect dialect = m_model.settings().dialect;
    const core::PlcProject project = core::buildPlcProject(m_model, dialect);
    const QString program = project.pous.empty() ? QStringLiteral("GEMMA") : fromStd(project.pous.front().name);
    addHeading(flow, m_style, TextStyle::Heading, tr("Generated code"), 0);
    addText(flow, m_style, TextStyle::Body,
            tr("GG Studio generates the PLC program as IEC 61131-3 Structured Text by the "
               "Hierarchical Design Pattern: the program %1 holds the active GEMMA state and evaluates "
               "its transitions by priority, and each visible macro-step or enclosing step is a "
               "function block that %1 calls while that state is active. This outline gives the "
               "program organisation units and their interfaces; File > Export Structured Text and "
               "Export PLCopen XML write the code itself.")
                .arg(program));
    if (const int errors = errorCount(); errors > 0) {
        flow.space(m_style.pt(4));
        addText(flow, m_style, TextStyle::Body,
                tr("The model has %n error(s): the generated code marks each one with a comment.", nullptr, errors));
    }

    Table task(m_style, {{QString(), 150}, {QString(), 0}}, m_width, false, true);
    task.addRow({tr("Code dialect"), ExportOptionsDialog::dialectText(dialect)});
    task.addRow({tr("Configuration"), fromStd(project.configurationName)});
    task.addRow({tr("Resource"), fromStd(project.resourceName)});
    task.addRow({tr("Task"), tr("%1: cyclic, every %2, priority %3")
                                 .arg(fromStd(project.taskName), fromStd(core::formatDuration(project.cycleTimeMs)))
                                 .arg(project.taskPriority)});
    task.addRow({tr("Program instance"), fromStd(project.programInstanceName) + QStringLiteral(" : ") + program});
    if (!project.globalListName.empty())
        task.addRow({tr("Global variable list"), fromStd(project.globalListName)});
    addHeading(flow, m_style, TextStyle::Subheading, tr("Task"), task.startHeight());
    task.flowInto(flow);

    QStringList pouNames;
    for (const core::PlcPou& pou : project.pous)
        pouNames << fromStd(pou.name);
    for (const core::PlcPou& pou : project.pous) {
        const QString name = fromStd(pou.name);
        const bool isProgram = pou.kind == core::PouKind::Program;
        QString description;
        if (isProgram) {
            description = tr("The GEMMA layer: it holds the active state in State, evaluates that "
                             "state's transitions by priority and calls the function block of a state "
                             "with nested behaviour while that state is active.");
        } else {
            QString stepId = name;
            stepId.chop(3); // "_FB"
            const auto page = m_grafcetPages.find(stepId);
            if (page != m_grafcetPages.end()) {
                description = tr("The nested GRAFCET of %1 (page %2). %3 calls it through its "
                                 "instance %4 while %4 is active.")
                                  .arg(stateLabel(stepId), QString::number(page->second), program, stepId);
            } else {
                description = tr("The nested behaviour of %1, not written yet: until it is, the "
                                 "function block completes at once. %2 calls it through its instance "
                                 "%3.")
                                  .arg(stateLabel(stepId), program, stepId);
            }
        }

        // Its interface (inputs, outputs, the instances it calls); the
        // globals it reads and its other variables by name.
        Table declarations(m_style,
                           {{tr("Declaration"), 76}, {tr("Name"), 104}, {tr("Type"), 64}, {tr("Initial value"), 58},
                            {tr("Comment"), 0}},
                           m_width);
        const auto declare = [&](const char* block, const std::vector<core::PlcVariable>& variables) {
            for (const core::PlcVariable& variable : variables) {
                declarations.addRow({QString::fromLatin1(block), fromStd(variable.name), fromStd(variable.typeName),
                                     orDash(fromStd(variable.initialValue)), orDash(fromStd(variable.comment))});
            }
        };
        declare("VAR_INPUT", pou.inputs);
        declare("VAR_OUTPUT", pou.outputs);
        std::vector<core::PlcVariable> instances;
        QStringList others;
        for (const core::PlcVariable& local : pou.locals) {
            if (pouNames.contains(fromStd(local.typeName)))
                instances.push_back(local);
            else
                others << fromStd(local.name);
        }
        declare("VAR", instances);
        QStringList externals;
        for (const core::PlcVariable& external : pou.externals)
            externals << fromStd(external.name);

        const QString keyword = isProgram ? QStringLiteral("PROGRAM ") : QStringLiteral("FUNCTION_BLOCK ");
        addHeading(flow, m_style, TextStyle::Subheading, keyword + name, 3 * bodyLine());
        addText(flow, m_style, TextStyle::Body, description);
        flow.space(m_style.pt(4));
        if (!declarations.isEmpty())
            declarations.flowInto(flow);
        if (!externals.isEmpty()) {
            flow.space(m_style.pt(4));
            addText(flow, m_style, TextStyle::Body,
                    tr("Global variables it reads (VAR_EXTERNAL): %1.").arg(externals.join(QStringLiteral(", "))));
        }
        if (!others.isEmpty()) {
            flow.space(m_style.pt(4));
            addText(flow, m_style, TextStyle::Body,
                    tr("Its own variables (VAR): %1.").arg(others.join(QStringLiteral(", "))));
        }
    }

    Table added(m_style, {{tr("Name"), 130}, {tr("Type"), 50}, {tr("Initial value"), 64}, {tr("Comment"), 0}},
                m_width);
    for (const core::PlcVariable& global : project.globals) {
        if (!m_model.variable(global.name)) {
            added.addRow({fromStd(global.name), fromStd(global.typeName), orDash(fromStd(global.initialValue)),
                          orDash(fromStd(global.comment))});
        }
    }
    addHeading(flow, m_style, TextStyle::Subheading, tr("Global variables"), 2 * bodyLine());
    const QString where = project.globalListName.empty()
                              ? tr("in the VAR_GLOBAL of the configuration %1").arg(fromStd(project.configurationName))
                              : tr("in the global variable list %1").arg(fromStd(project.globalListName));
    addText(flow, m_style, TextStyle::Body,
            tr("The declared variables (page %1) are the program's global variables, %2.")
                .arg(QString::number((*m_contents)[VariablesEntry].page), where));
    if (!added.isEmpty()) {
        flow.space(m_style.pt(4));
        addText(flow, m_style, TextStyle::Body, tr("The generator adds these:"), added.startHeight());
        flow.space(m_style.pt(4));
        added.flowInto(flow);
    }
}

// Every page with its running header and foot, then its blocks.
bool SpecificationPages::paint(QPainter& painter, const std::function<bool()>& pageDone) const
{
    const std::vector<Page>& pages = m_flow->pages();
    const QFont font = m_style.font(TextStyle::Small);
    const QFontMetricsF metrics = m_style.metrics(TextStyle::Small);
    const QString date = QLocale().toString(m_date.date(), QLocale::ShortFormat);
    for (std::size_t i = 0; i < pages.size(); ++i) {
        const Page& page = pages[i];
        if (i > 0) {
            m_device.setPageOrientation(page.orientation);
            m_device.newPage();
        }
        const QSizeF size = page.orientation == QPageLayout::Landscape ? m_printable.transposed() : m_printable;
        painter.save();
        painter.setFont(font);
        painter.setPen(mutedColor());
        for (qsizetype line = 0; line < m_headerLines.size(); ++line)
            painter.drawText(QPointF(0, double(line) * metrics.lineSpacing() + metrics.ascent()), m_headerLines[line]);
        painter.drawText(QRectF(0, 0, size.width(), metrics.lineSpacing()), Qt::AlignRight | Qt::AlignTop,
                         page.section);
        painter.setPen(QPen(ruleColor(), m_style.pt(0.5)));
        const double rule = double(m_headerLines.size() - 1) * metrics.lineSpacing() + metrics.ascent()
                            + metrics.descent() + m_style.pt(4);
        painter.drawLine(QPointF(0, rule), QPointF(size.width(), rule));
        painter.setPen(mutedColor());
        const QRectF foot(0, size.height() - metrics.lineSpacing(), size.width(), metrics.lineSpacing());
        painter.drawText(foot, Qt::AlignLeft | Qt::AlignBottom, date);
        painter.drawText(foot, Qt::AlignRight | Qt::AlignBottom, tr("Page %1 of %2").arg(i + 1).arg(pages.size()));
        painter.restore();
        for (const Block& block : page.blocks) {
            painter.save();
            block.paint(painter, QPointF(0, m_bodyTop + block.y));
            painter.restore();
        }
        if (!pageDone())
            return false;
    }
    return true;
}

} // namespace

SpecificationExport::SpecificationExport(Document& document)
    : m_document(document)
{
}

QString SpecificationExport::grafcetTitle(const QString& stepId)
{
    return stateLabel(stepId);
}

QString SpecificationExport::suggestedFileName(const QString& baseName)
{
    //: the specification's title and the file name it is saved under; %1 is the model's name
    return tr("%1 specification").arg(baseName) + QStringLiteral(".pdf");
}

bool SpecificationExport::writePdf(const QString& path, QString* errorMessage, bool* cancelled) const
{
    bool stopped = false;
    const QString title
        = tr("%1 specification").arg(withVisibleControls(QString::fromStdString(m_document.model().settings().name)));
    const QDateTime date = m_date.isValid() ? m_date : QDateTime::currentDateTime();
    const bool ok = PictureFile::writePdf(
        path, title, QPageLayout::Portrait,
        [&](QPainter& painter, QPagedPaintDevice& device, const QSizeF& printable, double dotsPerPoint) {
            SpecificationPages pages(m_document, date, device, printable, dotsPerPoint);
            stopped = !pages.write(painter, m_progress);
        },
        errorMessage, [&stopped] { return stopped; });
    if (cancelled)
        *cancelled = stopped;
    return ok;
}

} // namespace editor
