#pragma once

// The page flow of the Specification PDF: its fonts and lengths (Style),
// the pages as they fill (Flow) and the texts placed on them. Shared by the
// GEMMA and PackML specifications.

#include <QColor>
#include <QFont>
#include <QFontMetricsF>
#include <QPageLayout>
#include <QPainter>
#include <QString>
#include <QStringList>

#include <functional>
#include <vector>

class QPaintDevice;

namespace editor::specification {

inline constexpr double kHeaderBand = 22;      // the running header of one line, its rule and the gap under it
inline constexpr double kFooterBand = 18;      // the gap above the page number and the number
inline constexpr double kCellPadding = 3;      // around a table cell's text
inline constexpr double kSectionGap = 14;      // above a heading that does not start its page
inline constexpr double kMaxGrafcetText = 10;  // a small GRAFCET grows to fill its page no further
inline constexpr double kMeasureSlack = 0.5;   // kept free at a line's end, against rounding

inline QColor inkColor() { return QColor(0x20, 0x24, 0x2a); }
inline QColor mutedColor() { return QColor(0x5b, 0x64, 0x70); }
inline QColor headFillColor() { return QColor(0xe9, 0xed, 0xf2); }
inline QColor ruleColor() { return QColor(0xb8, 0xbe, 0xc7); }

enum class TextStyle { Body, Bold, Small, TableHead, Title, Subtitle, Heading, Subheading };
inline constexpr int kTextStyles = int(TextStyle::Subheading) + 1;

// The document's fonts and lengths in device units: the painter draws
// unscaled on the PDF writer, so metrics are those of its resolution.
class Style {
public:
    Style(const QPaintDevice& device, double dotsPerPoint);

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
    QStringList wrap(TextStyle style, const QString& text, double width) const;

private:
    static QFont makeFont(TextStyle style);

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
             const QColor& color = inkColor());
void addHeading(Flow& flow, const Style& style, TextStyle textStyle, const QString& text, double keepWithNext);
// A fixed-height band of one line at a page's top: the first page of a
// drawing has its heading there, the following ones a line saying whose
// pages they continue, so that every page of it has the same room left.
void placeBand(Flow& flow, double height, const QFont& font, double ascent, const QColor& color, const QString& text);

// "—" for an empty text.
QString orDash(const QString& text);

} // namespace editor::specification
