#include "editor/machine/operatoritem.h"

#include "editor/machine/machinescene.h"

#include "core/machine/machine.h"

#include <QCursor>
#include <QGraphicsSceneMouseEvent>
#include <QPainter>
#include <QtMath>

#include <cmath>

namespace editor {

OperatorItem::OperatorItem(MachineScene& scene, std::size_t component, const QRectF& cell)
    : MachineComponentItem(scene, component, cell)
{
    setAcceptedMouseButtons(Qt::LeftButton);
    setCursor(Qt::PointingHandCursor);
}

bool OperatorItem::isActuated() const
{
    const bool restValue = componentDescription().contact == core::machine::Contact::NormallyClosed;
    return signal(core::machine::role::kOperatorInput) != restValue;
}

QRectF OperatorItem::controlRect() const
{
    const QRectF body = bodyRect();
    const double side = body.height() - 2;
    return QRectF(body.left() + 2, body.top() + 1, side, side);
}

void OperatorItem::paintBody(QPainter& painter, const QRectF& body, const QColor& ink) const
{
    using Kind = core::machine::ComponentKind;
    const QRectF control = controlRect();
    const bool actuated = isActuated();
    const Kind kind = componentDescription().kind;
    painter.setPen(QPen(ink, 1.5));
    QString state;
    if (kind == Kind::Selector) {
        // A knob whose pointer turns right when switched on.
        painter.setBrush(unlitColour().lighter(160));
        painter.drawEllipse(control);
        const double angle = qDegreesToRadians(actuated ? 45.0 : -45.0);
        const QPointF centre = control.center();
        const double reach = control.width() / 2 - 3;
        painter.setPen(QPen(ink, 4, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(centre, centre + QPointF(reach * std::sin(angle), -reach * std::cos(angle)));
        state = actuated ? tr("switched on") : tr("switched off");
    } else {
        // A push button or an emergency stop: pressed in, it is drawn smaller and darker.
        const QColor cap = kind == Kind::EmergencyStop ? QColor(0xd3, 0x2f, 0x2f) : QColor(0x1e, 0x88, 0xe5);
        if (kind == Kind::EmergencyStop) {
            painter.setBrush(QColor(0xf9, 0xc9, 0x2a)); // the yellow collar
            painter.drawEllipse(control);
        }
        const double inset = kind == Kind::EmergencyStop ? 5 : 1;
        const QRectF button = control.adjusted(inset, inset, -inset, -inset);
        painter.setBrush(actuated ? cap.darker(140) : cap);
        painter.drawEllipse(actuated ? button.adjusted(2.5, 2.5, -2.5, -2.5) : button);
        state = actuated ? tr("pressed") : tr("released");
    }
    painter.setPen(ink);
    painter.drawText(body.adjusted(control.width() + 10, 0, 0, 0), Qt::AlignLeft | Qt::AlignVCenter, state);
}

void OperatorItem::mousePressEvent(QGraphicsSceneMouseEvent* event)
{
    if (!machineScene().canOperate()) {
        event->ignore();
        return;
    }
    machineScene().pressOperator(component());
    event->accept();
}

void OperatorItem::mouseReleaseEvent(QGraphicsSceneMouseEvent* event)
{
    machineScene().releaseOperator(component());
    event->accept();
}

} // namespace editor
