#include "editor/machine/indicatoritem.h"

#include "editor/machine/machinescene.h"

#include "core/machine/machine.h"

#include <QPainter>

namespace editor {

bool IndicatorItem::isLit() const
{
    if (componentDescription().kind == core::machine::ComponentKind::Lamp)
        return signal(core::machine::role::kLamp);
    return machineScene().state().sensorOn(component());
}

void IndicatorItem::appendLook(std::vector<std::int64_t>& look) const
{
    look.push_back(isLit() ? 1 : 0);
}

void IndicatorItem::paintBody(QPainter& painter, const QRectF& body, const QColor& ink) const
{
    const double radius = body.height() / 2 - 3;
    if (componentDescription().kind == core::machine::ComponentKind::Lamp) {
        const QPointF centre(body.left() + radius + 4, body.center().y());
        // A lit lamp glows: a halo around it.
        if (isLit()) {
            painter.setPen(Qt::NoPen);
            QColor halo = litColour();
            halo.setAlpha(90);
            painter.setBrush(halo);
            painter.drawEllipse(centre, radius + 3, radius + 3);
        }
        paintLamp(painter, centre, radius, isLit());
        return;
    }
    // A delayed sensor: the output, a delay, the sensor.
    const double small = radius * 0.6;
    const QPointF output(body.left() + small + 4, body.center().y());
    const QPointF sensor(body.right() - radius - 4, body.center().y());
    paintLamp(painter, output, small, signal(core::machine::role::kDelayedOutput));
    painter.setPen(QPen(ink, 1.2, Qt::DashLine));
    painter.drawLine(QPointF(output.x() + small + 3, output.y()), QPointF(sensor.x() - radius - 5, sensor.y()));
    painter.setPen(QPen(ink, 1.2));
    painter.drawLine(QPointF(sensor.x() - radius - 10, sensor.y() - 4), QPointF(sensor.x() - radius - 5, sensor.y()));
    painter.drawLine(QPointF(sensor.x() - radius - 10, sensor.y() + 4), QPointF(sensor.x() - radius - 5, sensor.y()));
    paintLamp(painter, sensor, radius, isLit());
}

} // namespace editor
