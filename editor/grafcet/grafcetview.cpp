#include "editor/grafcet/grafcetview.h"

#include "editor/grafcet/grafcetscene.h"

#include <QScrollBar>
#include <QWheelEvent>

#include <algorithm>
#include <utility>

namespace editor {

namespace {

constexpr double kZoomStep = 1.25;
constexpr double kMinZoom = 0.25;
constexpr double kMaxZoom = 4.0;

} // namespace

GrafcetView::GrafcetView(GrafcetScene* scene, QWidget* parent)
    : QGraphicsView(scene, parent)
    , m_scene(scene)
{
    setRenderHint(QPainter::Antialiasing);
    setFrameShape(QFrame::NoFrame);
    setAlignment(Qt::AlignHCenter | Qt::AlignTop);
    setBackgroundBrush(Qt::white);
    setDragMode(QGraphicsView::ScrollHandDrag);
    setTransformationAnchor(QGraphicsView::AnchorUnderMouse);
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

void GrafcetView::showEvent(QShowEvent* event)
{
    QGraphicsView::showEvent(event);
    if (std::exchange(m_shown, true))
        return;
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
    const double factor = event->angleDelta().y() > 0 ? kZoomStep : 1 / kZoomStep;
    const double target = std::clamp(zoom() * factor, kMinZoom, kMaxZoom);
    scale(target / zoom(), target / zoom());
    event->accept();
}

} // namespace editor
