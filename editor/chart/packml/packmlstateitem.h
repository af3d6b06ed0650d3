#pragma once

#include "core/templates/packml/packmlchartlayout.h"

#include <QGraphicsItem>
#include <QString>

namespace editor {

// A PackML state: its box filled by its kind (wait, acting, dual) with its
// PackTags name; grey with a dashed outline when the mode shown disables it.
// The scene sets what depends on the model (the name the edition shows, the
// mode, the tooltip).
class PackmlStateItem : public QGraphicsItem {
public:
    enum { Type = QGraphicsItem::UserType + 21 };

    explicit PackmlStateItem(const core::packml::ChartStateBox& layout, QGraphicsItem* parent = nullptr);

    int type() const override { return Type; }
    core::packml::State state() const { return m_state; }
    core::packml::StateKind kind() const;

    // "Complete", or "Completed" in the 2022 edition (spec §2.1).
    const QString& displayName() const { return m_name; }
    void setDisplayName(const QString& name);

    // Disabled in the mode shown: drawn grey and dashed.
    bool isDisabledInMode() const { return m_disabled; }
    void setDisabledInMode(bool disabled);

    // The state the simulation is in (PackmlSimulationMarks): filled as the
    // GEMMA chart fills its active step.
    bool isActiveInSimulation() const { return m_active; }
    void setActiveInSimulation(bool active);

    // The colour the box is filled with now.
    QColor fillColor() const;

    QRectF boundingRect() const override;
    QPainterPath shape() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

protected:
    // A selected state goes below the others (chartstyle::kSelectedZ), as on the GEMMA chart.
    QVariant itemChange(GraphicsItemChange change, const QVariant& value) override;

private:
    core::packml::State m_state;
    QRectF m_box; // item coordinates: the item sits at the box's top-left corner
    QString m_name;
    bool m_disabled = false;
    bool m_active = false;
};

} // namespace editor
