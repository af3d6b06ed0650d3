#pragma once

#include "core/layout/grafcetlayout.h"

#include <QGraphicsItem>
#include <QList>

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

    // Simulation (set by GrafcetSimulationMarks): Active, filled with the
    // IEC 60848 token in it, while its GRAFCET runs; Frozen, greyed with a
    // grey token, for a step its GRAFCET was left in.
    enum class SimulationMark { None, Active, Frozen };
    SimulationMark simulationMark() const { return m_mark; }
    void setSimulationMark(SimulationMark mark);
    // Where the token is drawn, under the number (scene coordinates).
    QRectF tokenRect() const;
    // The continuous actions drawn lit (their output emitted in the last
    // call), by index in the step's list of actions; empty for none.
    const QList<int>& litActions() const { return m_litActions; }
    void setLitActions(const QList<int>& actions);

    // Problems (set by GrafcetScene from the document's checks): the step's
    // own, drawn on its square, and those of its actions by index, drawn on
    // their boxes, in the chart's problem colour.
    bool hasProblemMark() const { return m_problem; }
    const QList<int>& problemActions() const { return m_problemActions; }
    void setProblemMarks(bool problem, const QList<int>& actions);

    QRectF boundingRect() const override;
    QVariant itemChange(GraphicsItemChange change, const QVariant& value) override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    void paintActions(QPainter* painter) const;

    core::GrafcetStepLayout m_layout;
    QRectF m_bounds;
    SimulationMark m_mark = SimulationMark::None;
    QList<int> m_litActions;
    bool m_problem = false;
    QList<int> m_problemActions;
};

} // namespace editor
