#pragma once

#include <QGraphicsView>
#include <QList>
#include <QPointer>

#include <optional>

namespace editor {

class GrafcetScene;

// What a mouse gesture draws over the drawing while it lasts (a rubber
// line, a highlighted target), in scene coordinates: no scene item, which
// the scene's rebuild after every edit would delete.
class GrafcetViewOverlay : public QObject {
    Q_OBJECT

public:
    using QObject::QObject;
    virtual void paintOverlay(QPainter* painter) const = 0;
};

// A nested GRAFCET in a tab beside the GEMMA chart, at its actual size (its
// text at the chart's label size) and scrolled when taller than the tab:
// fitted, a long sequence would shrink to unreadable, so fitting is the
// user's choice (View > Fit). Ctrl+wheel and a pinch zoom about the point
// under the fingers. A drag on the background selects the steps and
// transitions the band touches (Ctrl adds to the selection); the middle
// button pans.
class GrafcetView : public QGraphicsView {
    Q_OBJECT

public:
    explicit GrafcetView(GrafcetScene* scene, QWidget* parent = nullptr);

    GrafcetScene* grafcetScene() const { return m_scene; }
    double zoom() const; // 1.0 is 100 %

public slots:
    void zoomIn();
    void zoomOut();
    void zoomToFit();
    void zoomToActualSize();

signals:
    void zoomChanged(double zoom);

public:
    // Painted over the drawing, in the order added, for as long as it lives.
    void addOverlay(GrafcetViewOverlay* overlay) { m_overlays.append(overlay); }

protected:
    void drawForeground(QPainter* painter, const QRectF& rect) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    bool viewportEvent(QEvent* event) override;
    // The first time: at the top left of the drawing, where its initial step is.
    void showEvent(QShowEvent* event) override;

private:
    // Scales to zoom() * factor (within bounds) keeping viewPoint on the same scene point.
    void zoomBy(double factor, QPointF viewPoint);

    GrafcetScene* m_scene;
    bool m_shown = false;
    // Scrolled to the top: stays there when the scene grows upwards (the
    // simulation's caption above the drawing).
    bool m_atTop = true;
    // Where the middle button was last seen while it pans; null otherwise.
    std::optional<QPoint> m_panFrom;
    QList<QPointer<GrafcetViewOverlay>> m_overlays;
};

} // namespace editor
