#include "editor/export/packmlchartexport.h"

#include "editor/chart/packml/packmlchartscene.h"
#include "editor/export/exportfile.h"
#include "editor/export/hiddenselection.h"

#include <QPagedPaintDevice>
#include <QPainter>
#include <QPrinter>

namespace editor {

namespace {

// White margin around the sheet, in scene units.
constexpr double kMargin = 12;

} // namespace

PackmlChartExport::PackmlChartExport(PackmlChartScene& scene)
    : m_scene(scene)
{
}

QRectF PackmlChartExport::paper() const
{
    return m_scene.sceneRect().adjusted(-kMargin, -kMargin, kMargin, kMargin);
}

void PackmlChartExport::paintSheet(QPainter& painter, const QRectF& target) const
{
    HiddenSelection hidden(m_scene);
    painter.setRenderHints(QPainter::Antialiasing | QPainter::TextAntialiasing | QPainter::SmoothPixmapTransform);
    painter.fillRect(target, Qt::white);
    m_scene.render(&painter, target, paper(), Qt::KeepAspectRatio);
}

bool PackmlChartExport::write(const QString& path, ChartExport::Format format, QString* errorMessage) const
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

bool PackmlChartExport::writeSvg(const QString& path, QString* errorMessage) const
{
    const QRectF sheet = paper();
    return PictureFile::writeSvg(
        path, sheet.size(), m_title, tr("PackML chart drawn by GG Studio"),
        [&](QPainter& painter) { paintSheet(painter, QRectF(QPointF(0, 0), sheet.size())); }, errorMessage);
}

bool PackmlChartExport::writePng(const QString& path, QString* errorMessage, double scale) const
{
    const QSizeF size = paper().size() * scale;
    return PictureFile::writePng(
        path, size, [&](QPainter& painter) { paintSheet(painter, QRectF(QPointF(0, 0), size)); }, errorMessage);
}

void PackmlChartExport::paintPage(QPainter& painter, const QSizeF& page) const
{
    const QString modeTitle = m_scene.modeTitle();
    double top = 0;
    if (!modeTitle.isEmpty()) {
        QFont font = painter.font();
        font.setPixelSize(std::max(1, int(page.height() / 40)));
        font.setBold(true);
        painter.setFont(font);
        const double height = QFontMetricsF(font).height() * 1.5;
        painter.setPen(Qt::black);
        painter.drawText(QRectF(0, 0, page.width(), height), Qt::AlignLeft | Qt::AlignTop,
                         tr("Unit mode %1").arg(modeTitle));
        top = height;
    }
    const QRectF sheet = paper();
    const double scale = std::min(page.width() / sheet.width(), (page.height() - top) / sheet.height());
    const QSizeF size = sheet.size() * scale;
    paintSheet(painter, QRectF(QPointF((page.width() - size.width()) / 2, top), size));
}

bool PackmlChartExport::writePdf(const QString& path, QString* errorMessage) const
{
    return PictureFile::writePdf(
        path, m_title, QPageLayout::Landscape,
        [this](QPainter& painter, QPagedPaintDevice&, const QSizeF& page, double) { paintPage(painter, page); },
        errorMessage);
}

bool PackmlChartExport::print(QPrinter& printer) const
{
    printer.setDocName(m_title);
    QPainter painter;
    if (!painter.begin(&printer))
        return false;
    paintPage(painter, QSizeF(printer.width(), printer.height()));
    return true;
}

} // namespace editor
