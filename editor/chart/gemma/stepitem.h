#pragma once

#include "core/templates/gemma/gemmachartlayout.h"

#include <QCoreApplication>
#include <QGraphicsItem>

#include <optional>
#include <string>

namespace core {
struct Step;
}

namespace editor {

class Document;

// A GEMMA state drawn as its GRAFCET symbol: a square with the id (simple
// step), a double square (initial step), double lines at top and bottom
// (macro-step) or corner marks (enclosing step). Holds only the id and
// reads the model when it paints; the box comes from core::templateLayout().
class StepItem : public QGraphicsItem {
    Q_DECLARE_TR_FUNCTIONS(editor::StepItem)

public:
    enum { Type = QGraphicsItem::UserType + 1 };

    StepItem(const Document& document, const core::StepLayout& layout, QGraphicsItem* parent = nullptr);

    int type() const override { return Type; }
    const QString& id() const { return m_id; }

    // Repaints with the model as it is now (its type, its nested GRAFCET).
    void refresh();
    bool isHiddenInModel() const;
    // The official GEMMA name in the UI language, the type, how many
    // problems its nested GRAFCET's elements have, and the user's comment;
    // built when the tooltip shows (ChartScene::helpEvent).
    QString toolTipText() const;

    // Set by the scene from Document::hasProblems and
    // Document::nestedProblemCount, so the check runs once per change of the
    // diagnostics rather than on every paint.
    bool hasProblemMark() const { return m_problem; }
    void setProblemMark(bool problem);

    // The active state during simulation: drawn filled.
    bool isActive() const { return m_active; }
    void setActive(bool active);

    // The Complete output of a nested step's function block during
    // simulation, drawn as a "C" badge (green TRUE, grey FALSE); nullopt
    // draws none.
    std::optional<bool> completeMark() const { return m_complete; }
    void setCompleteMark(std::optional<bool> complete);

    // A macro-step or an enclosing step whose model has a nested GRAFCET
    // with steps carries a small GRAFCET mark on its top-left corner (clear
    // of the problem badge, top right, and the Complete badge, bottom
    // right); the number of its steps, nullopt for no mark. Read from the
    // model by refresh().
    std::optional<int> nestedMark() const { return m_nestedSteps; }
    // While that GRAFCET runs (simulation): the mark drawn in the running
    // colour with a ring, and the tooltip names its active steps ("3, 5");
    // nullopt otherwise.
    const std::optional<QString>& nestedRunning() const { return m_nestedRunning; }
    void setNestedRunning(const std::optional<QString>& activeSteps);

    QRectF boundingRect() const override;
    QPainterPath shape() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

protected:
    // A selected step goes below the others (chartstyle::kSelectedZ).
    QVariant itemChange(GraphicsItemChange change, const QVariant& value) override;

private:
    const core::Step* step() const;
    void paintSymbol(QPainter* painter, const core::Step& step) const;
    void paintBadge(QPainter* painter) const;
    void paintCompleteBadge(QPainter* painter) const;
    void paintNestedMark(QPainter* painter) const;
    std::optional<int> readNestedMark() const;

    const Document& m_document;
    QString m_id;
    std::string m_modelId;
    QRectF m_box; // item coordinates: the item sits at the box's top-left corner
    bool m_problem = false;
    bool m_active = false;
    std::optional<bool> m_complete;
    std::optional<int> m_nestedSteps;
    std::optional<QString> m_nestedRunning;
};

} // namespace editor
