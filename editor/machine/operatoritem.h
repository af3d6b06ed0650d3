#pragma once

// An operator input in the Machine tab: a push button, a selector or an
// emergency stop, drawn actuated or at rest, clickable while simulating.
// A push button is held while the mouse button is; a selector or an
// emergency stop changes at each click. The item only passes the click to
// MachineScene, which plays it through the simulation session.

#include "editor/machine/machinecomponentitem.h"

namespace editor {

class OperatorItem : public MachineComponentItem {
    Q_DECLARE_TR_FUNCTIONS(OperatorItem)

public:
    OperatorItem(MachineScene& scene, std::size_t component, const QRectF& cell);

    // Pressed, turned or struck: the input differs from its rest value.
    bool isActuated() const;
    // The clickable part of the drawing, in scene coordinates.
    QRectF controlRect() const;

protected:
    void paintBody(QPainter& painter, const QRectF& body, const QColor& ink) const override;
    void mousePressEvent(QGraphicsSceneMouseEvent* event) override;
    void mouseReleaseEvent(QGraphicsSceneMouseEvent* event) override;
};

} // namespace editor
