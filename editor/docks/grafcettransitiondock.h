#pragma once

#include "editor/docks/propertydock.h"

class QLabel;

namespace core {
struct GrafcetTransition;
}

namespace editor {

class ConditionEdit;
class DiagnosticList;
class WrappingLabel;

// Properties of the selected transition of a nested GRAFCET: its number,
// its upstream and downstream steps (links that select them), and its
// receptivity in the editor of the GEMMA conditions, read as a nested text:
// the checks' problems underlined with their messages, completion of the
// declared variables, of the X<n> of this GRAFCET's steps and of Complete;
// edges (↑a, RE a) and timers (5s/X3) as the spec writes them. Typing
// merges into one SetReceptivityCommand.
class GrafcetTransitionDock : public PropertyDock {
    Q_OBJECT

public:
    // Also the title of the empty frame that stands for the dock at start-up.
    static QString title();
    GrafcetTransitionDock(Document* document, Selection* selection, QWidget* parent = nullptr);

    ConditionEdit* receptivityEdit() const { return m_receptivityEdit; }

private:
    QWidget* createForm();
    void retranslate() override;
    void refreshForm() override;
    void focusField(const QString& field) override;
    const core::GrafcetTransition* transition() const;
    void refreshLinks(const core::GrafcetTransition& transition);
    void refreshReceptivity(const core::GrafcetTransition& transition);
    QStringList completions() const;

    void onReceptivityEdited(const QString& text);
    void onStepLinkActivated(const QString& number);

    QLabel* m_titleLabel = nullptr;
    QLabel* m_grafcetLabel = nullptr;
    QLabel* m_upstreamLabel = nullptr;
    QLabel* m_upstreamSteps = nullptr;
    QLabel* m_downstreamLabel = nullptr;
    QLabel* m_downstreamSteps = nullptr;
    QLabel* m_receptivityLabel = nullptr;
    ConditionEdit* m_receptivityEdit = nullptr;
    DiagnosticList* m_problemList = nullptr;
};

} // namespace editor
