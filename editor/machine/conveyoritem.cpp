#include "editor/machine/conveyoritem.h"

#include "editor/machine/machinescene.h"

#include "core/machine/machine.h"

#include <QPainter>

#include <cmath>

namespace editor {

namespace {

constexpr double kPart = 14;

} // namespace

void ConveyorItem::appendLook(std::vector<std::int64_t>& look) const
{
    const core::machine::MachineState& state = machineScene().state();
    look.push_back(state.hasPart(component()) ? 1 : 0);
    look.push_back(std::llround(state.position(component()) * kLookPositionSteps));
    look.push_back(state.partsDelivered(component()));
}

QRectF ConveyorItem::belt(const QRectF& body) const
{
    return QRectF(body.left() + 2, body.bottom() - 16, body.width() - 20, 12);
}

QRectF ConveyorItem::partRect() const
{
    const core::machine::MachineState& state = machineScene().state();
    if (!state.hasPart(component()))
        return {};
    const QRectF b = belt(bodyRect());
    const double x = b.left() + 4 + state.position(component()) * (b.width() - kPart - 8);
    return QRectF(x, b.top() - kPart, kPart, kPart);
}

void ConveyorItem::paintBody(QPainter& painter, const QRectF& body, const QColor& ink) const
{
    const QRectF b = belt(body);
    const bool running = signal(core::machine::role::kRun);
    painter.setPen(QPen(ink, 1.5));
    painter.setBrush(Qt::NoBrush);
    painter.drawRoundedRect(b, b.height() / 2, b.height() / 2);
    // Chevrons along the belt while it runs.
    painter.setPen(QPen(running ? litColour().darker(120) : unlitColour(), 1.5));
    for (double x = b.left() + 12; x < b.right() - 10; x += 18) {
        const double y = b.center().y();
        if (running) {
            painter.drawLine(QPointF(x, y - 3), QPointF(x + 4, y));
            painter.drawLine(QPointF(x + 4, y), QPointF(x, y + 3));
        } else {
            painter.drawPoint(QPointF(x + 2, y));
        }
    }
    if (const QRectF part = partRect(); !part.isEmpty()) {
        painter.setPen(QPen(ink, 1));
        painter.setBrush(QColor(0xd9, 0x8c, 0x1f));
        painter.drawRect(part);
    }
    // The part-present sensor at the end of the belt.
    paintLamp(painter, QPointF(b.right() + 9, b.top() - 6), 5, signal(core::machine::role::kPartPresent));
    const std::int64_t delivered = machineScene().state().partsDelivered(component());
    painter.setPen(ink);
    painter.drawText(QRectF(body.left(), body.top(), body.width(), 14), Qt::AlignRight | Qt::AlignVCenter,
                     tr("Parts out: %1").arg(delivered));
}

} // namespace editor
