#pragma once

#include "core/layout/grafcetlayout.h"

#include <QGraphicsItem>

namespace editor {

// The lines of a nested GRAFCET drawing: the links between steps and
// transitions (loops going up beside the drawing with an arrowhead at their
// target, jumps as an arrow with the target step's number), the single
// lines of selections and the double lines of simultaneous sequences, and
// the labels naming the upstream steps of a detached transition.
class GrafcetWiringItem : public QGraphicsItem {
public:
    explicit GrafcetWiringItem(const core::GrafcetLayout& layout, QGraphicsItem* parent = nullptr);

    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    void paintLink(QPainter* painter, const core::GrafcetLinkLayout& link) const;
    void paintLine(QPainter* painter, const core::GrafcetBranchLineLayout& line) const;

    std::vector<core::GrafcetLinkLayout> m_links;
    std::vector<core::GrafcetBranchLineLayout> m_lines;
    QRectF m_bounds;
};

} // namespace editor
