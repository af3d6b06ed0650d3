#pragma once

#include "editor/export/chartexport.h"

#include <QCoreApplication>
#include <QString>

class QPainter;
class QPrinter;

namespace editor {

class PackmlChartScene;

// Pictures of the PackML chart in the unit mode it shows (its disabled
// states greyed, its skipped transitions re-labelled, as on screen), on
// white paper without the selection: SVG and PNG at the sheet's size, PDF
// and print fitted to one landscape page.
class PackmlChartExport {
    Q_DECLARE_TR_FUNCTIONS(PackmlChartExport)

public:
    explicit PackmlChartExport(PackmlChartScene& scene);

    void setTitle(const QString& title) { m_title = title; }

    bool write(const QString& path, ChartExport::Format format, QString* errorMessage) const;
    bool writeSvg(const QString& path, QString* errorMessage) const;
    bool writePng(const QString& path, QString* errorMessage, double scale = 2.0) const;
    bool writePdf(const QString& path, QString* errorMessage) const;
    bool print(QPrinter& printer) const;

    // The sheet fitted to `page` (device units), centred, with the mode's
    // title above it; the painter's origin at the page's top left. Also a
    // page of the specification.
    void paintPage(QPainter& painter, const QSizeF& page) const;

private:
    QRectF paper() const;
    void paintSheet(QPainter& painter, const QRectF& target) const;

    PackmlChartScene& m_scene;
    QString m_title;
};

} // namespace editor
