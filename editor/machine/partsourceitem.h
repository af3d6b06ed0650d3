#pragma once

// A part source in the Machine tab: a magazine with the parts it has left,
// the conveyor it feeds, its empty sensor lit when it has none.

#include "editor/machine/machinecomponentitem.h"

namespace editor {

class PartSourceItem : public MachineComponentItem {
    Q_DECLARE_TR_FUNCTIONS(PartSourceItem)

public:
    using MachineComponentItem::MachineComponentItem;

    QString partsText() const; // "Parts left: 9", "Unlimited parts"

protected:
    void paintBody(QPainter& painter, const QRectF& body, const QColor& ink) const override;
    void appendLook(std::vector<std::int64_t>& look) const override;
};

} // namespace editor
