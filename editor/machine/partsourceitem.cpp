#include "editor/machine/partsourceitem.h"

#include "editor/machine/machinescene.h"

#include "core/machine/machine.h"

#include <QPainter>

#include <algorithm>

namespace editor {

void PartSourceItem::appendLook(std::vector<std::int64_t>& look) const
{
    look.push_back(machineScene().state().partsLeft(component()));
}

QString PartSourceItem::partsText() const
{
    const std::int64_t left = machineScene().state().partsLeft(component());
    if (left == core::machine::kUnlimitedParts)
        return tr("Unlimited parts");
    return tr("Parts left: %1").arg(left);
}

void PartSourceItem::paintBody(QPainter& painter, const QRectF& body, const QColor& ink) const
{
    // A stack of up to four boxes: a full magazine at a glance, empty when none is left.
    const std::int64_t left = machineScene().state().partsLeft(component());
    const int shown = left == core::machine::kUnlimitedParts ? 4 : static_cast<int>(std::min<std::int64_t>(left, 4));
    const QRectF magazine(body.left() + 2, body.top() + 2, 24, body.height() - 4);
    painter.setPen(QPen(ink, 1.5));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(magazine);
    painter.setPen(QPen(ink, 1));
    painter.setBrush(QColor(0xd9, 0x8c, 0x1f));
    const double box = (magazine.height() - 4) / 4;
    for (int i = 0; i < shown; ++i)
        painter.drawRect(QRectF(magazine.left() + 3, magazine.bottom() - 2 - (i + 1) * box, magazine.width() - 6, box - 1));
    painter.setPen(ink);
    const QRectF text = body.adjusted(34, 0, 0, 0);
    const QString conveyor = QString::fromStdString(componentDescription().conveyor);
    painter.drawText(text, Qt::AlignLeft | Qt::AlignVCenter,
                     partsText() + QLatin1Char('\n')
                         + (conveyor.isEmpty() ? tr("feeds no conveyor") : tr("feeds %1").arg(conveyor)));
}

} // namespace editor
