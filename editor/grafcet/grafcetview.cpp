#include "editor/grafcet/grafcetview.h"

#include "editor/chart/pinchzoom.h"
#include "editor/chart/viewzoom.h"
#include "editor/grafcet/grafcetscene.h"

#include <QMouseEvent>
#include <QScrollBar>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <utility>

namespace editor {

namespace {

constexpr double kZoomStep = 1.25;
constexpr double kMinZoom = 0.25;
constexpr double kMaxZoom = 4.0;
constexpr double kFitMargin = 12; // scene units around the drawing

} // namespace

GrafcetView::GrafcetView(GrafcetScene* scene, QWidget* parent)
    : QGraphicsView(scene, parent)
    , m_scene(scene)
{
    setRenderHint(QPainter::Antialiasing);
    setFrameShape(QFrame::NoFrame);
    // Anchored at the top left: a drawing that grows or shrinks at the right
    // (a longer receptivity, the simulation caption from scan to scan) does
    // not shift sideways, as a centred one would.
    setAlignment(Qt::AlignLeft | Qt::AlignTop);
    setBackgroundBrush(Qt::white);
    setDragMode(QGraphicsView::RubberBandDrag);
    setTransformationAnchor(QGraphicsView::AnchorUnderMouse);
    viewport()->grabGesture(Qt::PinchGesture);
    connect(verticalScrollBar(), &QScrollBar::valueChanged, this,
            [this](int value) { m_atTop = value <= verticalScrollBar()->minimum(); });
    // Runs after the view's own handler: the scroll bar's range is the new one.
    connect(scene, &QGraphicsScene::sceneRectChanged, this, [this] {
        if (m_atTop)
            verticalScrollBar()->setValue(verticalScrollBar()->minimum());
    });
}

double GrafcetView::zoom() const
{
    return transform().m11();
}

void GrafcetView::zoomIn()
{
    zoomBy(kZoomStep, viewport()->rect().center());
}

void GrafcetView::zoomOut()
{
    zoomBy(1 / kZoomStep, viewport()->rect().center());
}

// The whole drawing in the tab, however small that makes it (down to the
// smallest zoom, then scrolled).
void GrafcetView::zoomToFit()
{
    fitInView(sceneRect().adjusted(-kFitMargin, -kFitMargin, kFitMargin, kFitMargin), Qt::KeepAspectRatio);
    const double bounded = std::clamp(zoom(), kMinZoom, kMaxZoom);
    if (bounded != zoom())
        setTransform(QTransform::fromScale(bounded, bounded));
    emit zoomChanged(zoom());
}

void GrafcetView::zoomToActualSize()
{
    setTransform(QTransform());
    emit zoomChanged(zoom());
}

void GrafcetView::zoomBy(double factor, QPointF viewPoint)
{
    if (!zoomViewAbout(*this, std::clamp(zoom() * factor, kMinZoom, kMaxZoom), viewPoint))
        return;
    emit zoomChanged(zoom());
}

void GrafcetView::showEvent(QShowEvent* event)
{
    QGraphicsView::showEvent(event);
    if (std::exchange(m_shown, true))
        return;
    // Its left too: a drawing wider than the tab would open scrolled to its
    // middle, the initial step and the way back cut off.
    horizontalScrollBar()->setValue(horizontalScrollBar()->minimum());
    verticalScrollBar()->setValue(verticalScrollBar()->minimum());
}

void GrafcetView::drawForeground(QPainter* painter, const QRectF& rect)
{
    QGraphicsView::drawForeground(painter, rect);
    for (const QPointer<GrafcetViewOverlay>& overlay : std::as_const(m_overlays))
        if (overlay)
            overlay->paintOverlay(painter);
}

void GrafcetView::wheelEvent(QWheelEvent* event)
{
    if (!(event->modifiers() & Qt::ControlModifier)) {
        QGraphicsView::wheelEvent(event);
        return;
    }
    // 120 units per notch: one notch zooms by about 20 %, a touchpad's small steps smoothly.
    zoomBy(std::pow(1.0015, event->angleDelta().y()), event->position());
    event->accept();
}

bool GrafcetView::viewportEvent(QEvent* event)
{
    if (const std::optional<PinchZoom> pinch = pinchZoom(event, *viewport())) {
        zoomBy(pinch->factor, pinch->at);
        return true;
    }
    return QGraphicsView::viewportEvent(event);
}

// The left button on the background draws the rubber band (RubberBandDrag);
// the right one leaves the selection alone, for the context menu to act on
// all the selected elements (the scene would clear it); the middle one pans.
void GrafcetView::mousePressEvent(QMouseEvent* event)
{
    if (event->button() == Qt::RightButton) {
        event->accept();
        return;
    }
    if (event->button() == Qt::MiddleButton) {
        m_panFrom = event->position().toPoint();
        viewport()->setCursor(Qt::ClosedHandCursor);
        event->accept();
        return;
    }
    QGraphicsView::mousePressEvent(event);
}

void GrafcetView::mouseMoveEvent(QMouseEvent* event)
{
    if (!m_panFrom) {
        QGraphicsView::mouseMoveEvent(event);
        return;
    }
    const QPoint moved = event->position().toPoint() - *m_panFrom;
    m_panFrom = event->position().toPoint();
    horizontalScrollBar()->setValue(horizontalScrollBar()->value() - moved.x());
    verticalScrollBar()->setValue(verticalScrollBar()->value() - moved.y());
    event->accept();
}

void GrafcetView::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() == Qt::MiddleButton && m_panFrom) {
        m_panFrom.reset();
        viewport()->unsetCursor();
        event->accept();
        return;
    }
    QGraphicsView::mouseReleaseEvent(event);
}

} // namespace editor
