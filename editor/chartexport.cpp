#include "editor/chartexport.h"

#include "editor/chart/chartscene.h"

#include "core/formats/fileio.h"

#include <QBuffer>
#include <QFile>
#include <QFileInfo>
#include <QGraphicsItem>
#include <QImage>
#include <QPainter>
#include <QPdfWriter>
#include <QPrinter>
#include <QSignalBlocker>
#include <QSvgGenerator>

#include <cmath>

namespace editor {

namespace {

// White margin around the sheet, in scene units.
constexpr double kMargin = 12;

// Unselects the scene's items for the time of a rendering, without telling
// the shared Selection (its signals are blocked), and selects them again.
class HiddenSelection {
public:
    explicit HiddenSelection(QGraphicsScene& scene)
        : m_blocker(&scene)
        , m_selected(scene.selectedItems())
    {
        for (QGraphicsItem* item : m_selected)
            item->setSelected(false);
    }
    ~HiddenSelection()
    {
        for (QGraphicsItem* item : m_selected)
            item->setSelected(true);
    }
    HiddenSelection(const HiddenSelection&) = delete;
    HiddenSelection& operator=(const HiddenSelection&) = delete;

private:
    QSignalBlocker m_blocker;
    QList<QGraphicsItem*> m_selected;
};

QRectF paperRect(const ChartScene& scene)
{
    return scene.sceneRect().adjusted(-kMargin, -kMargin, kMargin, kMargin);
}

void render(ChartScene& scene, QPainter& painter, const QRectF& target)
{
    HiddenSelection hidden(scene);
    painter.setRenderHints(QPainter::Antialiasing | QPainter::TextAntialiasing | QPainter::SmoothPixmapTransform);
    painter.fillRect(target, Qt::white);
    scene.render(&painter, target, paperRect(scene), Qt::KeepAspectRatio);
}

// Writes through core's atomic writer, so a failed export never leaves half
// a file in place of a good one.
bool writeBytes(const QString& path, const QByteArray& bytes, QString* errorMessage)
{
    const core::Status status = core::writeFileAtomically(QFile::encodeName(path).toStdString(),
                                                          std::string_view(bytes.constData(), bytes.size()));
    if (!status && errorMessage)
        *errorMessage = QString::fromStdString(status.message);
    return status.ok;
}

} // namespace

ChartExport::ChartExport(ChartScene& scene)
    : m_scene(scene)
{
}

bool ChartExport::formatForPath(const QString& path, Format* format)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("svg"))
        *format = Format::Svg;
    else if (suffix == QLatin1String("png"))
        *format = Format::Png;
    else if (suffix == QLatin1String("pdf"))
        *format = Format::Pdf;
    else
        return false;
    return true;
}

bool ChartExport::write(const QString& path, Format format, QString* errorMessage) const
{
    switch (format) {
    case Format::Svg:
        return writeSvg(path, errorMessage);
    case Format::Png:
        return writePng(path, errorMessage);
    case Format::Pdf:
        return writePdf(path, errorMessage);
    }
    return false;
}

bool ChartExport::writeSvg(const QString& path, QString* errorMessage) const
{
    const QRectF paper = paperRect(m_scene);
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    QSvgGenerator generator;
    generator.setOutputDevice(&buffer);
    generator.setTitle(m_title);
    generator.setDescription(tr("GEMMA-GRAFCET chart drawn by GG Studio"));
    generator.setSize(paper.size().toSize());
    generator.setViewBox(QRectF(QPointF(0, 0), paper.size()));
    {
        QPainter painter;
        if (!painter.begin(&generator)) {
            if (errorMessage)
                *errorMessage = tr("The SVG picture could not be drawn.");
            return false;
        }
        render(m_scene, painter, QRectF(QPointF(0, 0), paper.size()));
    }
    return writeBytes(path, buffer.data(), errorMessage);
}

bool ChartExport::writePng(const QString& path, QString* errorMessage, double scale) const
{
    const QSizeF paper = paperRect(m_scene).size() * scale;
    QImage image(QSize(int(std::ceil(paper.width())), int(std::ceil(paper.height()))), QImage::Format_ARGB32);
    if (image.isNull()) {
        if (errorMessage)
            *errorMessage = tr("Not enough memory for a picture of %1 × %2 pixels.")
                                .arg(int(paper.width()))
                                .arg(int(paper.height()));
        return false;
    }
    image.fill(Qt::white);
    {
        QPainter painter(&image);
        render(m_scene, painter, QRectF(QPointF(0, 0), paper));
    }
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    if (!image.save(&buffer, "PNG")) {
        if (errorMessage)
            *errorMessage = tr("The PNG picture could not be encoded.");
        return false;
    }
    return writeBytes(path, buffer.data(), errorMessage);
}

bool ChartExport::writePdf(const QString& path, QString* errorMessage) const
{
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    {
        QPdfWriter writer(&buffer);
        writer.setTitle(m_title);
        writer.setCreator(QStringLiteral("GG Studio"));
        writer.setPageSize(QPageSize(QPageSize::A4));
        writer.setPageOrientation(QPageLayout::Landscape);
        writer.setPageMargins(QMarginsF(10, 10, 10, 10), QPageLayout::Millimeter);
        QPainter painter;
        if (!painter.begin(&writer)) {
            if (errorMessage)
                *errorMessage = tr("The PDF document could not be drawn.");
            return false;
        }
        render(m_scene, painter, QRectF(QPointF(0, 0), QSizeF(writer.width(), writer.height())));
    }
    return writeBytes(path, buffer.data(), errorMessage);
}

bool ChartExport::print(QPrinter& printer) const
{
    printer.setDocName(m_title);
    QPainter painter;
    if (!painter.begin(&printer))
        return false;
    // The painter's origin is the top left of the printable area.
    render(m_scene, painter, QRectF(0, 0, printer.width(), printer.height()));
    return true;
}

} // namespace editor
