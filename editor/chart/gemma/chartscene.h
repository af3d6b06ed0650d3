#pragma once

#include "core/templates/gemma/gemmatemplate.h"
#include "editor/elementref.h"

#include <QGraphicsScene>
#include <QHash>
#include <QList>

#include <optional>

namespace editor {

class Document;
class FrameItem;
class Selection;
class StepItem;
class TransitionItem;

// The GEMMA-GRAFCET chart: a view of the Document's model drawn on the
// fixed template layout. Items are built once; Document signals update only
// the items concerned. The scene selection and the shared Selection follow
// each other.
class ChartScene : public QGraphicsScene {
    Q_OBJECT

public:
    ChartScene(Document* document, Selection* selection, QObject* parent = nullptr);
    ~ChartScene() override;

    Document* document() const { return m_document; }
    Selection* selection() const { return m_selection; }

    // Hidden elements are drawn faded and dashed when shown, not at all otherwise.
    bool showHidden() const { return m_showHidden; }
    void setShowHidden(bool show);

    // The step drawn filled as the active state (simulation); empty for none.
    QString activeStep() const { return m_activeStep; }
    void setActiveStep(const QString& id);
    // The transition drawn thick and green as the one that fired last; empty for none.
    QString firedTransition() const { return m_firedTransition; }
    void setFiredTransition(const QString& id);
    // Complete of a nested step as a badge on it (nullopt: no badge), and
    // the tokens of a transition as dots on its bar (empty: none).
    void setCompleteMark(const QString& stepId, std::optional<bool> complete);
    void setTokenMarks(const QString& transitionId, const QList<bool>& tokens);
    // A step whose nested GRAFCET runs: its GRAFCET mark highlighted, its
    // active steps ("3, 5") in the tooltip; nullopt: not running.
    void setNestedRunning(const QString& stepId, const std::optional<QString>& activeSteps);
    // Removes every simulation mark: active step, fired transition, badges, dots, running GRAFCETs.
    void clearSimulationMarks();

    // Redraws texts that come from the UI language (the frame titles; the
    // tooltips are built in it when they show).
    void retranslate();

    StepItem* stepItem(const QString& id) const { return m_stepItems.value(id); }
    TransitionItem* transitionItem(const QString& id) const { return m_transitionItems.value(id); }
    FrameItem* frameItem(core::Family family) const;
    const QList<StepItem*>& steps() const { return m_steps; }                   // state-number order
    const QList<TransitionItem*>& transitions() const { return m_transitions; } // template order
    const QList<FrameItem*>& frames() const { return m_frames; }

    // The selectable items a keyboard user walks through: the visible steps in
    // state order, then the visible transitions in template order.
    QList<QGraphicsItem*> tabOrder() const;

    QGraphicsItem* itemFor(const ElementRef& element) const;
    static ElementRef elementOf(const QGraphicsItem* item);

protected:
    void helpEvent(QGraphicsSceneHelpEvent* event) override;

private:
    // The tooltip of the topmost step or transition at a point, as a view
    // with that viewport transform shows it; empty where there is none.
    QString toolTipAt(QPointF scenePos, const QTransform& viewportTransform) const;
    void buildItems();
    void onStepChanged(const QString& id);
    void onTransitionChanged(const QString& id);
    void onModelReset();
    void onDiagnosticsChanged();
    void onSceneSelectionChanged();
    void onSelectionChanged(const ElementRef& element);

    void refreshStep(StepItem* item);
    // Priorities and effectiveness are per source: a change to one
    // transition or end can renumber its siblings.
    void refreshTransitionsFrom(const QString& source);
    void refreshTransition(TransitionItem* item);
    void applyVisibility(QGraphicsItem* item, bool hiddenInModel);
    void selectFromSelection();

    Document* m_document;
    Selection* m_selection;
    bool m_showHidden = false;
    bool m_syncingSelection = false;
    QString m_activeStep;
    QString m_firedTransition;

    QList<FrameItem*> m_frames;
    QList<StepItem*> m_steps;
    QList<TransitionItem*> m_transitions;
    QHash<QString, StepItem*> m_stepItems;
    QHash<QString, TransitionItem*> m_transitionItems;
    QHash<QString, QList<TransitionItem*>> m_transitionsBySource;
    QHash<QString, QList<TransitionItem*>> m_transitionsByEnd; // both source and target
};

} // namespace editor
