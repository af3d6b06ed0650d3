#include "editor/chart/viewzoom.h"

#include <QGraphicsView>
#include <QScrollBar>

namespace editor {

bool zoomViewAbout(QGraphicsView& view, double target, QPointF viewPoint)
{
    const double zoom = view.transform().m11();
    if (qFuzzyCompare(target, zoom))
        return false;
    const QPointF anchor = view.mapToScene(viewPoint.toPoint());
    const QGraphicsView::ViewportAnchor previous = view.transformationAnchor();
    view.setTransformationAnchor(QGraphicsView::NoAnchor);
    view.scale(target / zoom, target / zoom);
    view.setTransformationAnchor(previous);
    const QPointF drift = view.mapFromScene(anchor) - viewPoint;
    view.horizontalScrollBar()->setValue(view.horizontalScrollBar()->value() + qRound(drift.x()));
    view.verticalScrollBar()->setValue(view.verticalScrollBar()->value() + qRound(drift.y()));
    return true;
}

} // namespace editor
