#pragma once

#include "editor/elementref.h"

#include "core/layout/grafcetlayout.h"

#include <QGraphicsScene>
#include <QHash>
#include <QString>

namespace editor {

class Document;
class GrafcetStepItem;
class GrafcetTransitionItem;
class GrafcetWiringItem;

// The drawing of the nested GRAFCET of one GEMMA step, as IEC 60848 draws
// it, from core::layoutGrafcet(): the step boxes with their actions, the
// transition bars with their receptivities, and the links and branch lines
// between them. It observes the Document and lays the drawing out again
// whenever that GRAFCET changes; a GEMMA step without a GRAFCET shows an
// empty scene.
class GrafcetScene : public QGraphicsScene {
    Q_OBJECT

public:
    GrafcetScene(Document* document, const QString& stepId, QObject* parent = nullptr);
    ~GrafcetScene() override;

    const QString& stepId() const { return m_stepId; }
    const core::GrafcetLayout& layout() const { return m_layout; }
    GrafcetStepItem* stepItem(int number) const { return m_steps.value(number); }
    GrafcetTransitionItem* transitionItem(int number) const { return m_transitions.value(number); }
    GrafcetWiringItem* wiringItem() const { return m_wiring; }
    // The drawing's rectangle: the layout's bounding rectangle (the scene
    // rectangle, unless an overlay such as the simulation marks widens it).
    QRectF drawingRect() const;

    // The width of `text` in the drawing's font, in scene units.
    static double textWidth(std::string_view text);

    // True while the items are deleted and made again: the selection they
    // lose then is not the user's doing.
    bool isRebuilding() const { return m_rebuilding; }

    // The steps, actions and transitions with an error or a warning are
    // drawn in the chart's problem colour, their messages as tooltip, after
    // every change of the document's checks. Pictures turn the marks off
    // (GrafcetExport): on paper the drawing is the clean one.
    bool problemMarksShown() const { return m_problemMarksShown; }
    void setProblemMarksShown(bool shown);
    // The messages of the problems of the element at `scenePos`, one a line,
    // in the UI language; empty where there is none.
    QString toolTipAt(QPointF scenePos) const;

signals:
    // The drawing follows a change of the GRAFCET: the items were made
    // again from the model (every item pointer taken before is gone), or,
    // when only receptivities' labels changed, relabelled in place.
    void rebuilt();

protected:
    void helpEvent(QGraphicsSceneHelpEvent* event) override;

private:
    void rebuild();
    bool relabel(const core::Grafcet& grafcet, core::GrafcetLayout& layout);
    void makeItems(const core::Grafcet* grafcet, core::GrafcetLayout layout);
    void applyProblemMarks();
    QString problemToolTip(const ElementRef& element) const;

    Document* m_document;
    QString m_stepId;
    core::GrafcetLayout m_layout;
    QHash<int, GrafcetStepItem*> m_steps;
    QHash<int, GrafcetTransitionItem*> m_transitions;
    GrafcetWiringItem* m_wiring = nullptr;
    bool m_rebuilding = false;
    bool m_problemMarksShown = true;
};

} // namespace editor
