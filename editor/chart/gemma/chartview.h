#pragma once

#include "editor/elementref.h"

#include <QGraphicsView>

namespace editor {

class ChartScene;

// Shows the chart: antialiased, panned by dragging the background (from the
// first frame on), zoomed with Ctrl+wheel or a pinch (about the point under
// the mouse) or the zoom slots.
// Tab / Shift+Tab walk through the visible elements (ChartScene::tabOrder)
// and leave the view past either end; Ctrl+click adds to the selection and
// Shift or Ctrl with a drag on the sheet draws a rubber band; Enter or F2 puts the focus in the
// selected element's main field in its dock (a step's type, a
// transition's condition), Esc clears the selection. The sheet stays fitted to the view
// when it is resized until the user picks another zoom.
class ChartView : public QGraphicsView {
    Q_OBJECT

public:
    explicit ChartView(ChartScene* scene, QWidget* parent = nullptr);

    ChartScene* chartScene() const { return m_scene; }
    double zoom() const; // 1.0 is 100 %
    // The width at which the fitted sheet fills a view `height` pixels high:
    // what the view needs beside the dock column, and no more.
    int widthToFitHeight(int height) const;

    // The parts of `area` outside `inner` (above, below, left and right),
    // which tile it together with `inner & area`.
    static QList<QRectF> marginsAround(const QRectF& inner, const QRectF& area);

public slots:
    void zoomIn();
    void zoomOut();
    void zoomToFit();
    void zoomToActualSize();

signals:
    void zoomChanged(double zoom);
    // A right click or the menu key: on `element`, already selected, or on
    // the empty sheet (a null element); `globalPos` is where the menu opens.
    void contextMenuRequested(const editor::ElementRef& element, const QPoint& globalPos);
    // A double click on a step.
    void stepDoubleClicked(const QString& stepId);

protected:
    void changeEvent(QEvent* event) override;
    bool focusNextPrevChild(bool next) override;
    void keyPressEvent(QKeyEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    bool viewportEvent(QEvent* event) override;
    void drawBackground(QPainter* painter, const QRectF& rect) override;

private:
    // Scales about viewPoint, which keeps showing the same scene point.
    void zoomBy(double factor, QPointF viewPoint);
    void revealSelection();
    // The step or transition drawn at the point, or none.
    ElementRef elementAt(const QPoint& viewPos) const;

    ChartScene* m_scene;
    bool m_fitted = true;
    bool m_panningSetUp = false;
};

} // namespace editor
