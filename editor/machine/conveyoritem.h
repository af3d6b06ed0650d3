#pragma once

// A conveyor in the Machine tab: the belt, arrows while it runs, the part
// drawn on its way from the entry to the part-present sensor at the end,
// and how many parts it delivered.

#include "editor/machine/machinecomponentitem.h"

namespace editor {

class ConveyorItem : public MachineComponentItem {
    Q_DECLARE_TR_FUNCTIONS(ConveyorItem)

public:
    using MachineComponentItem::MachineComponentItem;

    // Where the part's box is drawn now; empty without a part.
    QRectF partRect() const;

protected:
    void paintBody(QPainter& painter, const QRectF& body, const QColor& ink) const override;
    void appendLook(std::vector<std::int64_t>& look) const override;

private:
    QRectF belt(const QRectF& body) const;
};

} // namespace editor
