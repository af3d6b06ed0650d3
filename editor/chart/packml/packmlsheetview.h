#pragma once

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

protected:
    void keyPressEvent(QKeyEvent* event) override;
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
