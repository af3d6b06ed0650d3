#pragma once

#include <QByteArray>
#include <QCoreApplication>
#include <QPageLayout>
#include <QSizeF>
#include <QString>

#include <functional>

class QPagedPaintDevice;
class QPainter;

namespace editor {

// Writes an exported picture or document through core's atomic writer, so a
// failed export never leaves half a file in place of a good one. False with
// the reason in *errorMessage.
bool writeExportFile(const QString& path, const QByteArray& bytes, QString* errorMessage);

// The picture formats the GEMMA chart and a nested GRAFCET share: each
// writer sets up its device, lets `paint` draw (the top left at the
// painter's origin) and writes the file. False with a message for the user.
class PictureFile {
    Q_DECLARE_TR_FUNCTIONS(PictureFile)

public:
    using Paint = std::function<void(QPainter& painter)>;
    // The page size in device units and the device units per point.
    using PaintPages =
        std::function<void(QPainter& painter, QPagedPaintDevice& device, const QSizeF& page, double dotsPerPoint)>;

    // `size` in the picture's units (the scene's).
    static bool writeSvg(const QString& path, const QSizeF& size, const QString& title, const QString& description,
                         const Paint& paint, QString* errorMessage);
    // `size` in pixels, on white.
    static bool writePng(const QString& path, const QSizeF& size, const Paint& paint, QString* errorMessage);
    // A4 pages with 10 mm margins. When `cancelled` (if given) is TRUE after
    // `paint`, nothing is written and the file on disk stays as it was.
    static bool writePdf(const QString& path, const QString& title, QPageLayout::Orientation orientation,
                         const PaintPages& paint, QString* errorMessage,
                         const std::function<bool()>& cancelled = {});
};

} // namespace editor
