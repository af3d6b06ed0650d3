#pragma once

#include "core/layout/grafcetlayout.h"

#include <QGraphicsItem>
#include <QList>

namespace editor {

// The lines of a nested GRAFCET drawing: the links between steps and
// transitions (loops going up beside the drawing with an arrowhead at their
// target, jumps as an arrow with the target step's number), the single
// lines of selections and the double lines of simultaneous sequences, and
// the labels naming the upstream steps of a detached transition.
class GrafcetWiringItem : public QGraphicsItem {
public:
    explicit GrafcetWiringItem(const core::GrafcetLayout& layout, QGraphicsItem* parent = nullptr);

    // Simulation (set by GrafcetSimulationMarks): the links of these
    // transitions, fired in the last scan, drawn thick in the fired colour.
    const QList<int>& firedTransitions() const { return m_fired; }
    void setFiredTransitions(const QList<int>& transitions);

    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    void paintLink(QPainter* painter, const core::GrafcetLinkLayout& link, bool fired) const;
    void paintLine(QPainter* painter, const core::GrafcetBranchLineLayout& line) const;

    std::vector<core::GrafcetLinkLayout> m_links;
    std::vector<core::GrafcetBranchLineLayout> m_lines;
    QRectF m_bounds;
    QList<int> m_fired;
};

} // namespace editor
