#pragma once

#include "core/templates/gemma/gemmachartlayout.h"

#include <QCoreApplication>
#include <QGraphicsItem>
#include <QList>
#include <QPainterPath>
#include <QPolygonF>

#include <string>

namespace editor {

class Document;

// A GRAFCET transition: the orthogonal route from core::templateLayout()
// with an arrowhead at the target, the transition bar, and the label
// "p: condition" (the priority only when the source has a choice to make,
// overlined when the transition is negated, and then drawn light on a dark
// badge so that a negated transition stands out at a glance).
class TransitionItem : public QGraphicsItem {
    Q_DECLARE_TR_FUNCTIONS(editor::TransitionItem)

public:
    enum { Type = QGraphicsItem::UserType + 2 };

    // Shows nothing of the model until refresh(), as a StepItem: the scene
    // refreshes every item once they are all built.
    TransitionItem(const Document& document, const core::TransitionLayout& layout,
                   QGraphicsItem* parent = nullptr);

    int type() const override { return Type; }
    const QString& id() const { return m_id; }
    const QString& sourceId() const { return m_sourceId; } // a step id, or "F" for the family transition
    const QString& targetId() const { return m_targetId; }

    // Re-reads the model into the label and shape, and repaints.
    // The label needs the effective priorities, which cost a scan of the
    // source's transitions: done here on change rather than on every paint.
    void refresh();
    // Hidden itself, or not effective because an end is hidden.
    bool isHiddenInModel() const;
    // Source and target, priority, negation, the full condition and the
    // tokens; built when the tooltip shows (ChartScene::helpEvent).
    QString toolTipText() const;

    // What the label says, before eliding: "3: NOT Stop".
    QString labelText() const;
    QRectF labelTextRect() const; // the part of the label rectangle the shown text covers
    // The condition in full, on one line ("NOT Stop").
    const QString& conditionText() const { return m_conditionText; }
    // The condition as drawn: elided to the label width.
    const QString& displayedCondition() const { return m_elidedCondition; }
    // Whether the condition is cut short on screen (it does not fit the label).
    bool conditionCut() const { return m_conditionCut; }
    // For the chart exports only (ChartExport): with a number above 0, a
    // condition cut short ends in its note marker ("Start AND…[1]", or
    // "3: [1]" when no part of it fits), the full text being listed under
    // the chart. 0, the default, is the on-screen label.
    int noteNumber() const { return m_noteNumber; }
    void setNoteNumber(int number);
    bool priorityShown() const { return !m_priorityText.isEmpty(); }
    bool priorityOverlined() const { return m_overlined && priorityShown(); }
    // Where the priority is drawn: its badge when the transition is negated.
    QRectF priorityRect() const;

    // Set by the scene from Document::hasProblems.
    bool hasProblemMark() const { return m_problem; }
    void setProblemMark(bool problem);

    // Simulation marks, set by the scene: the transition that fired last is
    // drawn thick and green; each of its tokens is a dot on the bar, filled
    // when TRUE (in the order of Simulator::tokenNames()).
    bool isFired() const { return m_fired; }
    void setFired(bool fired);
    const QList<bool>& tokenMarks() const { return m_tokens; }
    void setTokenMarks(const QList<bool>& tokens);

    QRectF boundingRect() const override;
    QPainterPath shape() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

protected:
    // A selected transition goes below the others (chartstyle::kSelectedZ).
    QVariant itemChange(GraphicsItemChange change, const QVariant& value) override;

private:
    void updateLabel();
    QPainterPath buildShape() const;
    QLineF barLine() const;
    void paintLabel(QPainter* painter) const;
    void paintTokens(QPainter* painter) const;

    const Document& m_document;
    QString m_id;
    QString m_sourceId;
    QString m_targetId;
    std::string m_modelId;

    QPolygonF m_line;   // the route, stopping where the arrowhead starts
    QPolygonF m_arrow;  // filled triangle at the target end
    QPointF m_barCenter;
    bool m_barHorizontal = true;
    QRectF m_labelRect;
    Qt::Alignment m_labelAlignment = Qt::AlignLeft; // towards the bar
    QRectF m_bounds;
    // Built when the scene first asks (a click, a rubber band), not at every
    // label change: stroking the route is most of a refresh.
    mutable QPainterPath m_shape;
    mutable bool m_shapeValid = false;

    QString m_priorityText;   // empty when the priority is not shown
    QString m_separator;      // ": " between priority and condition, or empty
    QString m_conditionText;  // full, on one line
    QString m_elidedCondition;
    // Measured once per label change rather than at every paint.
    double m_priorityWidth = 0;  // of m_priorityText
    double m_shownWidth = 0;     // of the whole label as shown
    bool m_conditionCut = false;
    int m_noteNumber = 0;
    bool m_overlined = false;
    bool m_problem = false;
    bool m_fired = false;
    QList<bool> m_tokens;
};

} // namespace editor
