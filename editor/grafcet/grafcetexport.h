#pragma once

#include "editor/export/chartexport.h"

#include <QCoreApplication>
#include <QList>
#include <QString>

class QPagedPaintDevice;
class QPainter;
class QPrinter;

namespace editor {

class GrafcetScene;

// Pictures of a nested GRAFCET on white paper: SVG and PNG at the drawing's
// size, PDF and print on A4 portrait pages. A drawing that would shrink
// below a readable size on one page (its text under 8 pt) keeps that size,
// fitted to the page's width, and goes on over as many pages as it needs,
// each page break between steps and transitions rather than through them.
class GrafcetExport {
    Q_DECLARE_TR_FUNCTIONS(GrafcetExport)

public:
    explicit GrafcetExport(GrafcetScene& scene);

    void setTitle(const QString& title) { m_title = title; }

    bool write(const QString& path, ChartExport::Format format, QString* errorMessage) const;
    bool writeSvg(const QString& path, QString* errorMessage) const;
    bool writePng(const QString& path, QString* errorMessage, double scale = 2.0) const;
    bool writePdf(const QString& path, QString* errorMessage) const;
    bool print(QPrinter& printer) const;

    // Where pages of `pageHeight` scene units start, from the drawing's top
    // (0): each break moves up above any step or transition it would cut.
    static QList<double> pageStarts(const QList<QPair<double, double>>& elements, double drawingHeight,
                                    double pageHeight);

    // The pages a PDF or a print (or the specification, editor/
    // specificationexport.h) puts the drawing on, `page` device units each
    // at `dotsPerPoint` device units a point: one page while its text stays
    // at 8 pt, else over several, as the class comment says. A positive
    // `maxTextPoints` keeps a small drawing from growing past that text size
    // to fill the page.
    class Pages {
    public:
        Pages(GrafcetScene& scene, const QSizeF& page, double dotsPerPoint, double maxTextPoints = 0);

        qsizetype count() const { return m_starts.size(); }
        // The height the drawing takes on page `index`, in device units.
        double height(qsizetype index) const;
        // Page `index` (from 0), horizontally centred, its top at the painter's origin.
        void paint(QPainter& painter, qsizetype index) const;

    private:
        // The drawing's rows on page `index`, from its top.
        QPair<double, double> slice(qsizetype index) const;

        GrafcetScene& m_scene;
        QSizeF m_page;
        double m_scale = 1;
        QList<double> m_starts;
    };

private:
    void renderPages(QPainter& painter, QPagedPaintDevice& device, const QSizeF& page, double dotsPerPoint) const;

    GrafcetScene& m_scene;
    QString m_title;
};

} // namespace editor
