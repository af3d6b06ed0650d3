#pragma once

#include "core/layout/grafcetlayout.h"

#include <QGraphicsItem>

namespace editor {

// A step of a nested GRAFCET: its square with its number (a double square
// for an initial step) and, to its right, its action boxes: the qualifier
// in a cell of its own when it is not N, the condition of a conditional
// action under its box.
class GrafcetStepItem : public QGraphicsItem {
public:
    enum { Type = QGraphicsItem::UserType + 10 };

    explicit GrafcetStepItem(const core::GrafcetStepLayout& layout, QGraphicsItem* parent = nullptr);

    int type() const override { return Type; }
    int number() const { return m_layout.number; }
    const core::GrafcetStepLayout& layout() const { return m_layout; }

    QRectF boundingRect() const override;
    QVariant itemChange(GraphicsItemChange change, const QVariant& value) override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    void paintActions(QPainter* painter) const;

    core::GrafcetStepLayout m_layout;
    QRectF m_bounds;
};

} // namespace editor
