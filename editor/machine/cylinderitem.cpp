#include "editor/machine/cylinderitem.h"

#include "editor/machine/machinescene.h"

#include "core/machine/machine.h"

#include <QPainter>
#include <QPainterPath>

#include <cmath>

namespace editor {

double CylinderItem::position() const
{
    return machineScene().state().position(component());
}

double CylinderItem::rodTipX() const
{
    return geometry(bodyRect()).rodTip;
}

void CylinderItem::appendLook(std::vector<std::int64_t>& look) const
{
    look.push_back(std::llround(position() * kLookPositionSteps));
}

CylinderItem::Geometry CylinderItem::geometry(const QRectF& body) const
{
    const double barrelWidth = (body.width() - 8) / 2;
    const QRectF barrel(body.left() + 2, body.center().y() - 14, barrelWidth, 20);
    const double piston = barrel.left() + 3 + position() * (barrel.width() - 9);
    return {barrel, piston, piston + 3 + barrelWidth};
}

void CylinderItem::paintBody(QPainter& painter, const QRectF& body, const QColor& ink) const
{
    const Geometry g = geometry(body);
    const bool doubleActing = componentDescription().kind == core::machine::ComponentKind::DoubleActingCylinder;
    const std::size_t retracted = doubleActing ? core::machine::role::kDoubleRetracted
                                               : core::machine::role::kSingleRetracted;
    const std::size_t extended = doubleActing ? core::machine::role::kDoubleExtended
                                              : core::machine::role::kSingleExtended;
    // Rod first, so the barrel's wall covers its root.
    painter.setPen(QPen(ink, 1));
    painter.setBrush(unlitColour().lighter(150));
    painter.drawRect(QRectF(g.piston + 3, g.barrel.center().y() - 3, g.rodTip - g.piston - 3, 6));
    painter.setBrush(ink);
    painter.drawRect(QRectF(g.rodTip - 3, g.barrel.center().y() - 8, 4, 16));
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(ink, 1.5));
    painter.drawRect(g.barrel);
    painter.fillRect(QRectF(g.piston, g.barrel.top() + 1.5, 4, g.barrel.height() - 3), ink);
    if (!doubleActing) { // the return spring, between the piston and the barrel's end
        QPainterPath spring;
        const double from = g.piston + 5;
        const double to = g.barrel.right() - 1;
        const int turns = 6;
        spring.moveTo(from, g.barrel.center().y());
        for (int i = 1; i <= turns; ++i)
            spring.lineTo(from + (to - from) * i / turns, g.barrel.center().y() + ((i % 2) ? -6 : 6));
        painter.setPen(QPen(ink, 1));
        painter.drawPath(spring);
    }
    // The limit switches where the rod's end stands at either end of the stroke.
    const double y = g.barrel.bottom() + 8;
    const double tipRetracted = g.barrel.left() + 6 + g.barrel.width();
    const double tipExtended = g.barrel.left() + g.barrel.width() - 3 + g.barrel.width();
    paintLamp(painter, QPointF(tipRetracted, y), 4.5, signal(retracted));
    paintLamp(painter, QPointF(tipExtended, y), 4.5, signal(extended));
}

} // namespace editor
