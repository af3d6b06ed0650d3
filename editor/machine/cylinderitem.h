#pragma once

// A cylinder in the Machine tab: its barrel, the piston and rod drawn at
// the current stroke, and its limit switches lit at either end; a
// single-acting one shows its return spring.

#include "editor/machine/machinecomponentitem.h"

namespace editor {

class CylinderItem : public MachineComponentItem {
public:
    using MachineComponentItem::MachineComponentItem;

    // 0 retracted .. 1 extended, as drawn.
    double position() const;
    // The rod's end, where the drawing puts it now.
    double rodTipX() const;

protected:
    void paintBody(QPainter& painter, const QRectF& body, const QColor& ink) const override;
    void appendLook(std::vector<std::int64_t>& look) const override;

private:
    struct Geometry {
        QRectF barrel;
        double piston;
        double rodTip;
    };
    Geometry geometry(const QRectF& body) const;
};

} // namespace editor
