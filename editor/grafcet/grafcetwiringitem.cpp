#include "editor/grafcet/grafcetwiringitem.h"

#include "editor/chart/chartstyle.h"
#include "editor/chart/layoutconversion.h"

#include <QPainter>

namespace editor {

namespace {

// A downward arrowhead with its tip at `tip`.
QPolygonF arrowDownAt(QPointF tip)
{
    const double length = chartstyle::kArrowLength;
    const double half = chartstyle::kArrowHalfWidth;
    return QPolygonF({tip, tip + QPointF(-half, -length), tip + QPointF(half, -length)});
}

} // namespace

GrafcetWiringItem::GrafcetWiringItem(const core::GrafcetLayout& layout, QGraphicsItem* parent)
    : QGraphicsItem(parent)
    , m_links(layout.links)
    , m_lines(layout.lines)
    , m_bounds(toQRectF(layout.boundingRect))
{
    setZValue(chartstyle::kFrameZ);
}

QRectF GrafcetWiringItem::boundingRect() const
{
    return m_bounds;
}

void GrafcetWiringItem::setFiredTransitions(const QList<int>& transitions)
{
    if (m_fired == transitions)
        return;
    m_fired = transitions;
    update();
}

void GrafcetWiringItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*)
{
    painter->setRenderHint(QPainter::Antialiasing);
    for (const core::GrafcetLinkLayout& link : m_links)
        paintLink(painter, link, false);
    for (const core::GrafcetBranchLineLayout& line : m_lines)
        paintLine(painter, line);
    // Over the lines: a fired divergence's route shows along its line.
    for (const core::GrafcetLinkLayout& link : m_links) {
        if (m_fired.contains(link.transition))
            paintLink(painter, link, true);
    }
}

void GrafcetWiringItem::paintLink(QPainter* painter, const core::GrafcetLinkLayout& link, bool fired) const
{
    QPolygonF route;
    for (const core::Point& point : link.route)
        route << toQPointF(point);
    if (route.size() < 2)
        return;
    const QColor colour = fired ? chartstyle::firedColor() : chartstyle::inkColor();
    const QPen pen(colour, fired ? chartstyle::kFiredWidth : chartstyle::kRouteWidth, Qt::SolidLine, Qt::FlatCap,
                   Qt::MiterJoin);
    painter->setPen(pen);
    painter->setBrush(Qt::NoBrush);
    const bool arrow = link.ending != core::GrafcetLinkLayout::Ending::Plain;
    if (arrow) // the line stops where the arrowhead starts
        route.last().ry() -= chartstyle::kArrowLength;
    painter->drawPolyline(route);
    if (arrow) {
        painter->setPen(QPen(colour, chartstyle::kRouteWidth));
        painter->setBrush(colour);
        painter->drawPolygon(arrowDownAt(toQPointF(link.route.back())));
    }
    if (fired)
        return; // the texts are drawn once, in ink
    painter->setPen(chartstyle::labelColor());
    if (link.ending == core::GrafcetLinkLayout::Ending::Jump)
        chartstyle::drawCentredText(painter, toQRectF(link.labelRect), QString::number(link.step));
    if (link.fromReference)
        chartstyle::drawCentredText(painter, toQRectF(link.referenceRect), QString::number(link.step));
}

void GrafcetWiringItem::paintLine(QPainter* painter, const core::GrafcetBranchLineLayout& line) const
{
    using Kind = core::GrafcetBranchLineLayout::Kind;
    painter->setPen(QPen(chartstyle::inkColor(), chartstyle::kRouteWidth, Qt::SolidLine, Qt::FlatCap));
    painter->drawLine(QLineF(line.left, line.y, line.right, line.y));
    if (line.kind == Kind::SimultaneousDivergence || line.kind == Kind::SimultaneousConvergence)
        painter->drawLine(QLineF(line.left, line.y + core::kDoubleLineGap, line.right, line.y + core::kDoubleLineGap));
}

} // namespace editor
