#pragma once

#include "core/layout/grafcetlayout.h"

#include <QGraphicsItem>
#include <QString>

namespace editor {

// A transition of a nested GRAFCET: its bar across the link and its
// receptivity to the right, edges written ↑ and ↓ as IEC 60848 draws them.
class GrafcetTransitionItem : public QGraphicsItem {
public:
    enum { Type = QGraphicsItem::UserType + 11 };

    GrafcetTransitionItem(const core::GrafcetTransitionLayout& layout, const std::string& receptivity,
                          QGraphicsItem* parent = nullptr);

    int type() const override { return Type; }
    // Its receptivity edited: the new text and the layout made for it (the
    // label's width); the bar must stay where it is (GrafcetScene).
    void setReceptivity(const core::GrafcetTransitionLayout& layout, const std::string& receptivity);
    int number() const { return m_layout.number; }
    // The receptivity as drawn: "↑PartPresent AND NOT X3".
    const QString& labelText() const { return m_label; }
    // "RE a" and "FE a" as ↑a and ↓a; the rest as written.
    static QString drawnReceptivity(const QString& receptivity);

    // Simulation (set by GrafcetSimulationMarks): fired in the last scan,
    // its bar drawn in the chart's fired colour.
    bool isFired() const { return m_fired; }
    void setFired(bool fired);
    const core::GrafcetTransitionLayout& layout() const { return m_layout; }
    // A problem (set by GrafcetScene from the document's checks): the bar
    // and the receptivity drawn in the chart's problem colour.
    bool hasProblemMark() const { return m_problem; }
    void setProblemMark(bool problem);

    QRectF boundingRect() const override;
    QVariant itemChange(GraphicsItemChange change, const QVariant& value) override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    static QRectF boundsOf(const core::GrafcetTransitionLayout& layout);

    core::GrafcetTransitionLayout m_layout;
    QString m_label;
    QRectF m_bounds;
    bool m_fired = false;
    bool m_problem = false;
};

} // namespace editor
