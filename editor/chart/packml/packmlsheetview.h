#pragma once

#include "editor/elementref.h"

#include <QGraphicsView>

namespace editor {

class PackmlChartScene;

// The PackML chart's sheet, zoomed as the GEMMA chart: fitted to the view
// until the user zooms, Ctrl+wheel or a pinch about the point under the
// mouse, the zoom slots; dragging the background pans; Ctrl+click adds to
// the selection; Esc clears it.
class PackmlSheetView : public QGraphicsView {
    Q_OBJECT

public:
    explicit PackmlSheetView(PackmlChartScene* scene, QWidget* parent = nullptr);

    PackmlChartScene* chartScene() const { return m_scene; }
    double zoom() const; // 1.0 is 100 %

public slots:
    void zoomIn();
    void zoomOut();
    void zoomToFit();
    void zoomToActualSize();

signals:
    void zoomChanged(double zoom);
    // A right click (or the menu key) on a state, a transition, a frame's
    // arrow (its command), or the sheet (a null element).
    void contextMenuRequested(const editor::ElementRef& element, const QPoint& globalPos);

protected:
    void keyPressEvent(QKeyEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    bool viewportEvent(QEvent* event) override;
    void drawBackground(QPainter* painter, const QRectF& rect) override;

private:
    void zoomBy(double factor, QPointF viewPoint);

    PackmlChartScene* m_scene;
    bool m_fitted = true;
};

} // namespace editor
