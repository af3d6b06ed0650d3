#include "editor/chart/gemma/chartview.h"

#include "editor/chart/gemma/chartscene.h"
#include "editor/chart/pinchzoom.h"
#include "editor/chart/viewzoom.h"
#include "editor/selection.h"

#include <QContextMenuEvent>
#include <QGraphicsItem>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QScrollBar>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace editor {

namespace {

constexpr double kMinZoom = 0.1;
constexpr double kMaxZoom = 8.0;
constexpr double kZoomStep = 1.25;
constexpr double kFitMargin = 12; // scene units around the sheet
constexpr int kRevealMargin = 30; // pixels kept around an element scrolled into view

} // namespace

ChartView::ChartView(ChartScene* scene, QWidget* parent)
    : QGraphicsView(scene, parent)
    , m_scene(scene)
{
    // The central view needs no frame: the sheet has its own border, and the
    // style's frame around a view this size is a long outline to draw in
    // the first frame.
    setFrameShape(QFrame::NoFrame);
    setRenderHints(QPainter::Antialiasing | QPainter::TextAntialiasing | QPainter::SmoothPixmapTransform);
    // drawBackground() paints every pixel it is given: the viewport's own
    // background fill would only paint them once more before it.
    viewport()->setAttribute(Qt::WA_OpaquePaintEvent);
    setFocusPolicy(Qt::StrongFocus);
    setTransformationAnchor(AnchorViewCenter);
    setResizeAnchor(AnchorViewCenter);
    viewport()->grabGesture(Qt::PinchGesture);
    connect(m_scene->selection(), &Selection::changed, this, &ChartView::revealSelection);
}

double ChartView::zoom() const
{
    return transform().m11();
}

void ChartView::zoomIn()
{
    zoomBy(kZoomStep, viewport()->rect().center());
}

void ChartView::zoomOut()
{
    zoomBy(1 / kZoomStep, viewport()->rect().center());
}

int ChartView::widthToFitHeight(int height) const
{
    const QRectF sheet = sceneRect().adjusted(-kFitMargin, -kFitMargin, kFitMargin, kFitMargin);
    const int frame = 2 * frameWidth(); // the view has none; a style may add one
    return static_cast<int>(std::ceil((height - frame) * sheet.width() / sheet.height())) + frame;
}

void ChartView::zoomToFit()
{
    m_fitted = true;
    const QRectF sheet = sceneRect().adjusted(-kFitMargin, -kFitMargin, kFitMargin, kFitMargin);
    fitInView(sheet, Qt::KeepAspectRatio);
    emit zoomChanged(zoom());
}

void ChartView::zoomToActualSize()
{
    m_fitted = false;
    resetTransform();
    emit zoomChanged(zoom());
}

void ChartView::zoomBy(double factor, QPointF viewPoint)
{
    const double target = std::clamp(zoom() * factor, kMinZoom, kMaxZoom);
    if (qFuzzyCompare(target, zoom()))
        return;
    m_fitted = false;
    zoomViewAbout(*this, target, viewPoint);
    emit zoomChanged(zoom());
}

void ChartView::wheelEvent(QWheelEvent* event)
{
    if (!(event->modifiers() & Qt::ControlModifier)) {
        QGraphicsView::wheelEvent(event);
        return;
    }
    // 120 units per notch: one notch zooms by about 20 %.
    const double factor = std::pow(1.0015, event->angleDelta().y());
    zoomBy(factor, event->position());
    event->accept();
}

void ChartView::resizeEvent(QResizeEvent* event)
{
    QGraphicsView::resizeEvent(event);
    if (m_fitted)
        zoomToFit();
}

// The sheet as white paper on the window's colour, each pixel filled once:
// the window's colour only around the sheet.
void ChartView::drawBackground(QPainter* painter, const QRectF& rect)
{
    // Crisp and cheap: the raster engine fills aliased rectangles and draws
    // an aliased hairline directly, while antialiasing would rasterize both
    // edge by edge over the whole window.
    painter->save();
    painter->setRenderHint(QPainter::Antialiasing, false);
    const QRectF sheet = sceneRect();
    const QColor surround = palette().color(QPalette::Window);
    for (const QRectF& margin : marginsAround(sheet, rect))
        painter->fillRect(margin, surround);
    painter->fillRect(sheet & rect, Qt::white);
    QPen border(palette().color(QPalette::Mid), 0); // cosmetic hairline
    painter->setPen(border);
    painter->setBrush(Qt::NoBrush);
    painter->drawRect(sheet);
    painter->restore();
}

// Adjacent edges are shared, so the aliased fills of these and of
// `inner & area` neither overlap nor leave a gap.
QList<QRectF> ChartView::marginsAround(const QRectF& inner, const QRectF& area)
{
    QList<QRectF> margins;
    const auto add = [&margins](double left, double top, double right, double bottom) {
        if (right > left && bottom > top)
            margins.append(QRectF(QPointF(left, top), QPointF(right, bottom)));
    };
    const double top = std::clamp(inner.top(), area.top(), area.bottom());
    const double bottom = std::clamp(inner.bottom(), area.top(), area.bottom());
    add(area.left(), area.top(), area.right(), top);
    add(area.left(), bottom, area.right(), area.bottom());
    add(area.left(), top, std::min(inner.left(), area.right()), bottom);
    add(std::max(inner.right(), area.left()), top, area.right(), bottom);
    return margins;
}

bool ChartView::focusNextPrevChild(bool next)
{
    const QList<QGraphicsItem*> order = m_scene->tabOrder();
    const QList<QGraphicsItem*> selected = m_scene->selectedItems();
    const qsizetype current = selected.size() == 1 ? order.indexOf(selected.first()) : -1;
    const qsizetype wanted = current < 0 ? (next ? 0 : order.size() - 1) : current + (next ? 1 : -1);
    if (wanted < 0 || wanted >= order.size())
        return QGraphicsView::focusNextPrevChild(next); // past either end: leave the chart
    m_scene->selection()->select(ChartScene::elementOf(order[wanted]));
    return true;
}

void ChartView::keyPressEvent(QKeyEvent* event)
{
    const bool edit = event->key() == Qt::Key_F2 || event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter;
    if (edit && event->modifiers() == Qt::NoModifier && !m_scene->selection()->current().isNull()) {
        // The docks reveal themselves and focus their main field.
        m_scene->selection()->select(m_scene->selection()->current(), QStringLiteral("main"));
        event->accept();
        return;
    }
    if (event->key() == Qt::Key_Escape && !m_scene->selectedItems().isEmpty()) {
        m_scene->clearSelection();
        event->accept();
        return;
    }
    QGraphicsView::keyPressEvent(event);
}

ElementRef ChartView::elementAt(const QPoint& viewPos) const
{
    for (QGraphicsItem* item : items(viewPos)) {
        for (QGraphicsItem* candidate = item; candidate; candidate = candidate->parentItem()) {
            const ElementRef element = ChartScene::elementOf(candidate);
            if (!element.isNull())
                return element;
        }
    }
    return {};
}

// A plain drag on the sheet pans; with Shift or Ctrl it selects what the
// rubber band covers (Ctrl adds to the selection).
void ChartView::mousePressEvent(QMouseEvent* event)
{
    const bool modifier = event->modifiers() & (Qt::ShiftModifier | Qt::ControlModifier);
    if (event->button() == Qt::LeftButton && modifier && elementAt(event->position().toPoint()).isNull())
        setDragMode(RubberBandDrag);
    QGraphicsView::mousePressEvent(event);
}

void ChartView::mouseReleaseEvent(QMouseEvent* event)
{
    QGraphicsView::mouseReleaseEvent(event);
    if (dragMode() == RubberBandDrag)
        setDragMode(m_panningSetUp ? ScrollHandDrag : NoDrag);
}

void ChartView::mouseDoubleClickEvent(QMouseEvent* event)
{
    const ElementRef element = elementAt(event->pos());
    if (element.kind == ElementRef::Kind::Step) {
        emit stepDoubleClicked(element.id);
        event->accept();
        return;
    }
    QGraphicsView::mouseDoubleClickEvent(event);
}

void ChartView::contextMenuEvent(QContextMenuEvent* event)
{
    ElementRef element;
    if (event->reason() == QContextMenuEvent::Mouse) {
        element = elementAt(event->pos());
        // On one of several selected elements the menu acts on all of them.
        if (!element.isNull() && !m_scene->selection()->elements().contains(element))
            m_scene->selection()->select(element);
    } else {
        element = m_scene->selection()->current(); // the menu key: the selected element
    }
    if (element.kind != ElementRef::Kind::Step && element.kind != ElementRef::Kind::Transition)
        element = {};
    emit contextMenuRequested(element, event->globalPos());
    event->accept();
}

void ChartView::revealSelection()
{
    if (QGraphicsItem* item = m_scene->itemFor(m_scene->selection()->current()); item && item->isVisible())
        ensureVisible(item, kRevealMargin, kRevealMargin);
}

// Dragging the background pans, under the open hand: set once the first
// frame is out. On X11 the first use of a cursor shape reads it from the
// cursor theme and uploads it to the display server (1 M instructions and
// a round trip), which the first frame need not wait for.
bool ChartView::viewportEvent(QEvent* event)
{
    if (const std::optional<PinchZoom> pinch = pinchZoom(event, *viewport())) {
        zoomBy(pinch->factor, pinch->at);
        return true;
    }
    if (event->type() == QEvent::Paint && !m_panningSetUp) {
        m_panningSetUp = true;
        QMetaObject::invokeMethod(this, [this] { setDragMode(ScrollHandDrag); }, Qt::QueuedConnection);
    }
    return QGraphicsView::viewportEvent(event);
}

// The scene is no widget: the view passes the language change on to it.
void ChartView::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        m_scene->retranslate();
    QGraphicsView::changeEvent(event);
}

} // namespace editor
