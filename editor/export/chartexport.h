#pragma once

#include <QCoreApplication>
#include <QSizeF>
#include <QString>

#include <memory>

class QPainter;
class QPrinter;

namespace editor {

class ChartScene;

// Pictures of the chart as the window shows it (hidden elements included
// when they are shown), on white paper, without the selection highlight.
// No condition is cut short: one that does not fit its label ends there in a
// note marker, "[1]", and a "Conditions" list under the chart gives it in
// full (editor/export/conditionnotes.h); the picture grows downwards to hold it.
// Each writer returns false with a message for the user when the file
// cannot be written; a failed write leaves no partial file behind.
class ChartExport {
    Q_DECLARE_TR_FUNCTIONS(ChartExport)

public:
    enum class Format { Svg, Png, Pdf };

    explicit ChartExport(ChartScene& scene);

    // From the file name's extension (".svg", ".png", ".pdf"); false when
    // it is none of those.
    static bool formatForPath(const QString& path, Format* format);

    bool write(const QString& path, Format format, QString* errorMessage) const;
    bool writeSvg(const QString& path, QString* errorMessage) const;
    // Rendered at `scale` device pixels per scene unit (2 gives a sharp A4 print).
    bool writePng(const QString& path, QString* errorMessage, double scale = 2.0) const;
    bool writePdf(const QString& path, QString* errorMessage) const;

    // Fitted to the printable area of the printer's page (the caller sets
    // the orientation: landscape suits the chart), the Conditions list
    // under the chart or on the following pages, as the PDF. False when the
    // printer cannot start.
    bool print(QPrinter& printer) const;

    // The title written into SVG and PDF metadata.
    void setTitle(const QString& title) { m_title = title; }

    // The pages a PDF or a print (or the specification, editor/
    // specificationexport.h) puts the chart on, `page` device units each:
    // the chart fitted to the first, its Conditions list under it or on the
    // following pages (planPages). While it exists, the labels of the
    // conditions that do not fit end in their note markers.
    class Pages {
    public:
        Pages(ChartScene& scene, const QSizeF& page);
        ~Pages();
        Pages(const Pages&) = delete;
        Pages& operator=(const Pages&) = delete;

        qsizetype count() const;
        // Page `index` (from 0), its top left at the painter's origin.
        void paint(QPainter& painter, qsizetype index) const;

    private:
        struct Plan;
        std::unique_ptr<Plan> m_plan;
    };

private:
    ChartScene& m_scene;
    QString m_title;
};

} // namespace editor
