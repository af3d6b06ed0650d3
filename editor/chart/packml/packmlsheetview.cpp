#include "editor/chart/packml/packmlsheetview.h"

#include "editor/chart/packml/packmlchartscene.h"
#include "editor/chart/pinchzoom.h"
#include "editor/chart/viewzoom.h"

#include "editor/selection.h"

#include <QContextMenuEvent>
#include <QGraphicsItem>
#include <QKeyEvent>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace editor {

namespace {

// As the GEMMA chart's view.
constexpr double kMinZoom = 0.1;
constexpr double kMaxZoom = 8.0;
constexpr double kZoomStep = 1.25;
constexpr double kFitMargin = 12; // scene units around the sheet

} // namespace

PackmlSheetView::PackmlSheetView(PackmlChartScene* scene, QWidget* parent)
    : QGraphicsView(scene, parent)
    , m_scene(scene)
{
    setFrameShape(QFrame::NoFrame);
    setRenderHints(QPainter::Antialiasing | QPainter::TextAntialiasing | QPainter::SmoothPixmapTransform);
    viewport()->setAttribute(Qt::WA_OpaquePaintEvent); // drawBackground paints every pixel
    setFocusPolicy(Qt::StrongFocus);
    setTransformationAnchor(AnchorViewCenter);
    setResizeAnchor(AnchorViewCenter);
    setDragMode(ScrollHandDrag);
    viewport()->grabGesture(Qt::PinchGesture);
}

double PackmlSheetView::zoom() const
{
    return transform().m11();
}

void PackmlSheetView::zoomIn()
{
    zoomBy(kZoomStep, viewport()->rect().center());
}

void PackmlSheetView::zoomOut()
{
    zoomBy(1 / kZoomStep, viewport()->rect().center());
}

void PackmlSheetView::zoomToFit()
{
    m_fitted = true;
    fitInView(sceneRect().adjusted(-kFitMargin, -kFitMargin, kFitMargin, kFitMargin), Qt::KeepAspectRatio);
    emit zoomChanged(zoom());
}

void PackmlSheetView::zoomToActualSize()
{
    m_fitted = false;
    resetTransform();
    emit zoomChanged(zoom());
}

void PackmlSheetView::zoomBy(double factor, QPointF viewPoint)
{
    const double target = std::clamp(zoom() * factor, kMinZoom, kMaxZoom);
    if (qFuzzyCompare(target, zoom()))
        return;
    m_fitted = false;
    zoomViewAbout(*this, target, viewPoint);
    emit zoomChanged(zoom());
}

void PackmlSheetView::wheelEvent(QWheelEvent* event)
{
    if (!(event->modifiers() & Qt::ControlModifier)) {
        QGraphicsView::wheelEvent(event);
        return;
    }
    // 120 units per notch: one notch zooms by about 20 %, as on the GEMMA chart.
    zoomBy(std::pow(1.0015, event->angleDelta().y()), event->position());
    event->accept();
}

void PackmlSheetView::resizeEvent(QResizeEvent* event)
{
    QGraphicsView::resizeEvent(event);
    if (m_fitted)
        zoomToFit();
}

bool PackmlSheetView::viewportEvent(QEvent* event)
{
    if (const std::optional<PinchZoom> pinch = pinchZoom(event, *viewport())) {
        zoomBy(pinch->factor, pinch->at);
        return true;
    }
    return QGraphicsView::viewportEvent(event);
}

void PackmlSheetView::contextMenuEvent(QContextMenuEvent* event)
{
    ElementRef element;
    if (event->reason() == QContextMenuEvent::Mouse) {
        for (QGraphicsItem* item = itemAt(event->pos()); item && element.isNull(); item = item->parentItem())
            element = m_scene->elementOf(item);
        if (!element.isNull())
            m_scene->selection()->select(element);
    } else {
        element = m_scene->selection()->current(); // the menu key: the selected element
    }
    emit contextMenuRequested(element, event->globalPos());
    event->accept();
}

void PackmlSheetView::keyPressEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_Escape && !m_scene->selectedItems().isEmpty()) {
        m_scene->clearSelection();
        event->accept();
        return;
    }
    QGraphicsView::keyPressEvent(event);
}

// White paper on the window's colour, as the GEMMA chart.
void PackmlSheetView::drawBackground(QPainter* painter, const QRectF& rect)
{
    painter->save();
    painter->setRenderHint(QPainter::Antialiasing, false);
    painter->fillRect(rect, palette().color(QPalette::Window));
    painter->fillRect(sceneRect() & rect, Qt::white);
    painter->setPen(QPen(palette().color(QPalette::Mid), 0));
    painter->setBrush(Qt::NoBrush);
    painter->drawRect(sceneRect());
    painter->restore();
}

} // namespace editor
