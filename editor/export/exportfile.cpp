#include "editor/export/exportfile.h"

#include "core/formats/fileio.h"

#include <QBuffer>
#include <QFile>
#include <QImage>
#include <QPainter>
#include <QPdfWriter>
#include <QSvgGenerator>

#include <cmath>
#include <string_view>

namespace editor {

bool writeExportFile(const QString& path, const QByteArray& bytes, QString* errorMessage)
{
    const core::Status status = core::writeFileAtomically(QFile::encodeName(path).toStdString(),
                                                          std::string_view(bytes.constData(), bytes.size()));
    if (!status && errorMessage)
        *errorMessage = QString::fromStdString(status.message);
    return status.ok;
}

bool PictureFile::writeSvg(const QString& path, const QSizeF& size, const QString& title, const QString& description,
                           const Paint& paint, QString* errorMessage)
{
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    QSvgGenerator generator;
    generator.setOutputDevice(&buffer);
    generator.setTitle(title);
    generator.setDescription(description);
    generator.setSize(QSize(int(std::ceil(size.width())), int(std::ceil(size.height()))));
    generator.setViewBox(QRectF(QPointF(0, 0), size));
    {
        QPainter painter;
        if (!painter.begin(&generator)) {
            if (errorMessage)
                *errorMessage = tr("The SVG picture could not be drawn.");
            return false;
        }
        paint(painter);
    }
    return writeExportFile(path, buffer.data(), errorMessage);
}

bool PictureFile::writePng(const QString& path, const QSizeF& size, const Paint& paint, QString* errorMessage)
{
    QImage image(QSize(int(std::ceil(size.width())), int(std::ceil(size.height()))), QImage::Format_ARGB32);
    if (image.isNull()) {
        if (errorMessage)
            *errorMessage = tr("Not enough memory for a picture of %1 × %2 pixels.")
                                .arg(int(size.width()))
                                .arg(int(size.height()));
        return false;
    }
    image.fill(Qt::white);
    {
        QPainter painter(&image);
        paint(painter);
    }
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    if (!image.save(&buffer, "PNG")) {
        if (errorMessage)
            *errorMessage = tr("The PNG picture could not be encoded.");
        return false;
    }
    return writeExportFile(path, buffer.data(), errorMessage);
}

bool PictureFile::writePdf(const QString& path, const QString& title, QPageLayout::Orientation orientation,
                           const PaintPages& paint, QString* errorMessage, const std::function<bool()>& cancelled)
{
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    {
        QPdfWriter writer(&buffer);
        writer.setTitle(title);
        writer.setCreator(QStringLiteral("GG Studio"));
        writer.setPageSize(QPageSize(QPageSize::A4));
        writer.setPageOrientation(orientation);
        writer.setPageMargins(QMarginsF(10, 10, 10, 10), QPageLayout::Millimeter);
        QPainter painter;
        if (!painter.begin(&writer)) {
            if (errorMessage)
                *errorMessage = tr("The PDF document could not be drawn.");
            return false;
        }
        paint(painter, writer, QSizeF(writer.width(), writer.height()), writer.resolution() / 72.0);
    }
    if (cancelled && cancelled())
        return false;
    return writeExportFile(path, buffer.data(), errorMessage);
}

} // namespace editor
