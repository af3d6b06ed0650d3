#pragma once

#include "core/templates/packml/packmlchartlayout.h"
#include "editor/elementref.h"

#include <QGraphicsScene>
#include <QHash>
#include <QList>

#include <optional>

namespace core {
class Model;
}

namespace editor {

class PackmlArrowItem;
class PackmlFrameItem;
class PackmlStateItem;
class Selection;

// The PackML chart (spec packml.md §2.4): the fixed figure of
// core::packml::chartLayout, one unit mode at a time. Items are built once
// per edition and options; showing another mode, or a change of the model,
// only re-reads what each item shows: the states the mode disables greyed
// and dashed, the transitions that do not exist in it left out, an arrow
// whose target the mode skips grey and labelled with where it leads, all as
// core/templates/packml/packmlrules.h says. The scene selection and the
// shared Selection follow each other.
//
// It reads a core::Model rather than a Document: the Document cannot hold a
// PackML model yet (its checks expect GEMMA steps). Whoever owns the model
// calls refresh() after each change of it (connect the change signal there);
// `model` must outlive the scene.
class PackmlChartScene : public QGraphicsScene {
    Q_OBJECT

public:
    PackmlChartScene(const core::Model* model, Selection* selection, QObject* parent = nullptr);
    ~PackmlChartScene() override;

    const core::Model& model() const { return *m_model; }
    Selection* selection() const { return m_selection; }

    // The unit mode shown; 0 shows the template as such (nothing greyed).
    int mode() const { return m_mode; }
    // A number the model has no mode for shows the template.
    void setMode(int number);
    // "3 Manual"; empty for 0.
    QString modeTitle() const;

    const QList<PackmlStateItem*>& states() const { return m_states; } // state-number order
    const QList<PackmlArrowItem*>& transitions() const { return m_transitions; } // layout order
    const QList<PackmlFrameItem*>& frames() const { return m_frames; }          // Abort, Stop
    PackmlStateItem* stateItem(core::packml::State state) const;
    PackmlArrowItem* transitionItem(core::packml::State source, core::packml::State target) const;
    PackmlFrameItem* frameItem(core::packml::Command command) const;
    PackmlArrowItem* frameArrowItem(core::packml::Command command) const;
    // The template transition an arrow of transitions() draws.
    std::optional<core::packml::TemplateTransition> transitionOf(const PackmlArrowItem* item) const;

    // A state in the mode shown, a transition in it, or a frame's command.
    ElementRef elementOf(const QGraphicsItem* item) const;
    QGraphicsItem* itemFor(const ElementRef& element) const;

public slots:
    // Re-reads the model: rebuilds the items when the edition or the options
    // changed, shows the initial mode when the mode shown is gone.
    void refresh();
    // The tooltips in the UI language.
    void retranslate();

signals:
    void modeChanged(int mode);
    // The model's modes may have changed (numbers, names).
    void modesChanged();
    // A double click on a state: `state` is its PackTags name, `mode` the mode shown.
    void stateDoubleClicked(int mode, const QString& state);

protected:
    void mouseDoubleClickEvent(QGraphicsSceneMouseEvent* event) override;

private:
    struct TransitionEntry {
        core::packml::TemplateTransition transition;
        PackmlArrowItem* item;
    };

    void buildItems(const core::packml::Options& options);
    void applyMode();
    void followModeInSelection();
    void applyToStates(const core::packml::StateSet& enabled);
    void applyToTransitions(const core::packml::StateSet& enabled);
    void applyToFrames(const core::packml::StateSet& enabled);
    core::packml::StateSet enabledStates() const;
    void onSceneSelectionChanged();
    void selectFromSelection();

    const core::Model* m_model;
    Selection* m_selection;
    int m_mode = 0;
    std::optional<core::packml::Options> m_builtFor;
    bool m_syncingSelection = false;

    QList<PackmlFrameItem*> m_frames;
    QList<PackmlArrowItem*> m_frameArrows; // same order as m_frames
    QList<PackmlStateItem*> m_states;
    QList<PackmlArrowItem*> m_transitions;
    QList<TransitionEntry> m_entries; // same order as m_transitions
};

} // namespace editor
