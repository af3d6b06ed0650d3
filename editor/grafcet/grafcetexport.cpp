#include "editor/grafcet/grafcetexport.h"

#include "editor/chart/chartstyle.h"
#include "editor/export/exportfile.h"
#include "editor/export/hiddenselection.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetstepitem.h"
#include "editor/grafcet/grafcettransitionitem.h"

#include <QPagedPaintDevice>
#include <QPainter>
#include <QPrinter>

#include <algorithm>

namespace editor {

namespace {

constexpr double kMinimumTextPoints = 8; // the labels on paper

// The drawing's part `source` into `target`, on white.
void render(GrafcetScene& scene, QPainter& painter, const QRectF& target, const QRectF& source)
{
    painter.setRenderHints(QPainter::Antialiasing | QPainter::TextAntialiasing | QPainter::SmoothPixmapTransform);
    painter.fillRect(target, Qt::white);
    const HiddenSelection hidden(scene);
    // On paper the drawing is the clean one: the problems are the editor's.
    const bool problemMarks = scene.problemMarksShown();
    scene.setProblemMarksShown(false);
    scene.render(&painter, target, source, Qt::KeepAspectRatio);
    scene.setProblemMarksShown(problemMarks);
}

// The vertical extent of every step (with its actions) and transition (with
// its receptivity), as their items paint them, in the drawing's coordinates
// from its top: where a page must not break. An item that reaches into a
// page is drawn on it, clipped: its text would be on both pages.
QList<QPair<double, double>> elementExtents(const GrafcetScene& scene)
{
    QList<QPair<double, double>> extents;
    const double top = scene.drawingRect().top();
    for (const core::GrafcetStepLayout& step : scene.layout().steps) {
        const QRectF painted = scene.stepItem(step.number)->sceneBoundingRect();
        extents.push_back({painted.top() - top, painted.bottom() - top});
    }
    for (const core::GrafcetTransitionLayout& transition : scene.layout().transitions) {
        if (const GrafcetTransitionItem* item = scene.transitionItem(transition.number)) {
            const QRectF painted = item->sceneBoundingRect();
            extents.push_back({painted.top() - top, painted.bottom() - top});
        }
    }
    return extents;
}

} // namespace

GrafcetExport::GrafcetExport(GrafcetScene& scene)
    : m_scene(scene)
{
}

bool GrafcetExport::write(const QString& path, ChartExport::Format format, QString* errorMessage) const
{
    switch (format) {
    case ChartExport::Format::Svg:
        return writeSvg(path, errorMessage);
    case ChartExport::Format::Png:
        return writePng(path, errorMessage);
    case ChartExport::Format::Pdf:
        return writePdf(path, errorMessage);
    }
    return false;
}

bool GrafcetExport::writeSvg(const QString& path, QString* errorMessage) const
{
    const QRectF drawing = m_scene.drawingRect();
    return PictureFile::writeSvg(
        path, drawing.size(), m_title, tr("Nested GRAFCET drawn by GG Studio"),
        [&](QPainter& painter) { render(m_scene, painter, QRectF(QPointF(0, 0), drawing.size()), drawing); },
        errorMessage);
}

bool GrafcetExport::writePng(const QString& path, QString* errorMessage, double scale) const
{
    const QRectF drawing = m_scene.drawingRect();
    return PictureFile::writePng(
        path, drawing.size() * scale,
        [&](QPainter& painter) { render(m_scene, painter, QRectF(QPointF(0, 0), drawing.size() * scale), drawing); },
        errorMessage);
}

bool GrafcetExport::writePdf(const QString& path, QString* errorMessage) const
{
    return PictureFile::writePdf(
        path, m_title, QPageLayout::Portrait,
        [this](QPainter& painter, QPagedPaintDevice& device, const QSizeF& page, double dotsPerPoint) {
            renderPages(painter, device, page, dotsPerPoint);
        },
        errorMessage);
}

bool GrafcetExport::print(QPrinter& printer) const
{
    printer.setDocName(m_title);
    QPainter painter;
    if (!painter.begin(&printer))
        return false;
    renderPages(painter, printer, QSizeF(printer.width(), printer.height()), printer.resolution() / 72.0);
    return true;
}

QList<double> GrafcetExport::pageStarts(const QList<QPair<double, double>>& elements, double drawingHeight,
                                        double pageHeight)
{
    QList<double> starts{0};
    while (starts.back() + pageHeight < drawingHeight) {
        const double start = starts.back();
        double end = start + pageHeight;
        // Up above every element the break would cut, but never above half
        // the page: an element taller than that is cut rather than looped on.
        for (bool moved = true; moved;) {
            moved = false;
            for (const auto& [top, bottom] : elements) {
                if (top < end && end < bottom && top - 1 > start + pageHeight / 2) {
                    end = top - 1;
                    moved = true;
                }
            }
        }
        starts.push_back(end);
    }
    return starts;
}

GrafcetExport::Pages::Pages(GrafcetScene& scene, const QSizeF& page, double dotsPerPoint, double maxTextPoints)
    : m_scene(scene)
    , m_page(page)
    , m_starts{0}
{
    const HiddenSelection hidden(m_scene); // the page breaks come from the unselected extents
    const QRectF drawing = m_scene.drawingRect();
    if (drawing.isEmpty() || page.isEmpty())
        return;
    const double fitPage = std::min(page.width() / drawing.width(), page.height() / drawing.height());
    const double fitWidth = page.width() / drawing.width();
    const double readable = kMinimumTextPoints * dotsPerPoint / chartstyle::kFontSize;
    // One page when it stays readable; else the readable size (or the
    // page's width when even that is too wide) over several pages.
    m_scale = fitPage >= readable ? fitPage : std::min(readable, fitWidth);
    if (maxTextPoints > 0)
        m_scale = std::min(m_scale, maxTextPoints * dotsPerPoint / chartstyle::kFontSize);
    m_starts = pageStarts(elementExtents(m_scene), drawing.height(), page.height() / m_scale);
}

QPair<double, double> GrafcetExport::Pages::slice(qsizetype index) const
{
    const double top = m_starts.value(index);
    const double bottom = index + 1 < m_starts.size() ? m_starts[index + 1] : m_scene.drawingRect().height();
    return {top, std::max(top, bottom)};
}

double GrafcetExport::Pages::height(qsizetype index) const
{
    const auto [top, bottom] = slice(index);
    return (bottom - top) * m_scale;
}

void GrafcetExport::Pages::paint(QPainter& painter, qsizetype index) const
{
    const QRectF drawing = m_scene.drawingRect();
    if (drawing.isEmpty() || index < 0 || index >= m_starts.size())
        return;
    const auto [top, bottom] = slice(index);
    const QRectF source(drawing.left(), drawing.top() + top, drawing.width(), bottom - top);
    const QRectF target((m_page.width() - drawing.width() * m_scale) / 2, 0, drawing.width() * m_scale,
                        (bottom - top) * m_scale);
    render(m_scene, painter, target, source);
}

void GrafcetExport::renderPages(QPainter& painter, QPagedPaintDevice& device, const QSizeF& page,
                                double dotsPerPoint) const
{
    const Pages pages(m_scene, page, dotsPerPoint);
    for (qsizetype i = 0; i < pages.count(); ++i) {
        if (i > 0)
            device.newPage();
        pages.paint(painter, i);
    }
}

} // namespace editor
