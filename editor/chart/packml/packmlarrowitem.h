#pragma once

#include "core/templates/packml/packmlchartlayout.h"

#include <QGraphicsItem>
#include <QPolygonF>
#include <QStringList>

namespace editor {

// An arrow of the PackML chart: a transition of a state, or the one arrow of
// the Stop or Abort frame. Its orthogonal route from the layout with an
// arrowhead at the target, its bar, and its label ("Reset", "SC", "Reset →
// Idle" when it skips a state). Dashed when optional, grey when it skips a
// state in the mode shown. The scene sets what depends on the model.
class PackmlArrowItem : public QGraphicsItem {
public:
    enum { Type = QGraphicsItem::UserType + 22 };

    explicit PackmlArrowItem(const core::packml::ChartArrow& arrow, QGraphicsItem* parent = nullptr);

    int type() const override { return Type; }

    // The label, as the first of `candidates` that fits the layout's label
    // rectangle, if need be a little smaller (down to kMinLabelScale), or
    // else the last one elided at that smallest size: a long text can give way to a shorter one
    // that says the main thing ("→ Idle").
    void setLabelCandidates(const QStringList& candidates);
    const QStringList& labelCandidates() const { return m_candidates; }
    // The text drawn.
    const QString& displayedLabel() const { return m_shown; }
    // How much smaller than the chart's font it is drawn (1: not at all).
    double labelScale() const { return m_scale; }
    static constexpr double kMinLabelScale = 0.8;
    QRectF labelRect() const { return m_labelRect; }

    bool isDashed() const { return m_dashed; }
    void setDashed(bool dashed);
    // Skips a state in the mode shown: drawn in grey.
    bool isGreyed() const { return m_greyed; }
    void setGreyed(bool greyed);
    // The transition that fired last in the simulation (PackmlSimulationMarks):
    // drawn green and thicker.
    bool isFired() const { return m_fired; }
    void setFired(bool fired);
    QColor inkColor() const;

    QRectF boundingRect() const override;
    QPainterPath shape() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

protected:
    QVariant itemChange(GraphicsItemChange change, const QVariant& value) override;

private:
    QLineF barLine() const;
    QRectF shownLabelRect() const;

    QPolygonF m_line;  // the route, stopping where the arrowhead starts
    QPolygonF m_arrow; // filled triangle at the target end
    QPointF m_barCenter;
    bool m_barHorizontal = true;
    QRectF m_labelRect;
    Qt::Alignment m_labelAlignment = Qt::AlignHCenter; // towards the bar
    QRectF m_bounds;
    QPainterPath m_shape;
    QStringList m_candidates;
    QString m_shown;
    double m_shownWidth = 0; // scaled
    double m_scale = 1;
    bool m_dashed = false;
    bool m_greyed = false;
    bool m_fired = false;
};

} // namespace editor
