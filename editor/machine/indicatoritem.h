#pragma once

// What only shows a signal in the Machine tab: a lamp, lit while its
// output is TRUE; a delayed sensor, its output and the sensor that follows
// it after the delays, each lit while TRUE.

#include "editor/machine/machinecomponentitem.h"

namespace editor {

class IndicatorItem : public MachineComponentItem {
public:
    using MachineComponentItem::MachineComponentItem;

    // The big lamp of a lamp, or the sensor of a delayed sensor.
    bool isLit() const;

protected:
    void paintBody(QPainter& painter, const QRectF& body, const QColor& ink) const override;
    void appendLook(std::vector<std::int64_t>& look) const override;
};

} // namespace editor
