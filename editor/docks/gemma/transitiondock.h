#pragma once

#include "editor/docks/propertydock.h"

#include <QList>

class QCheckBox;
class QGroupBox;
class QLabel;
class QSpinBox;
class QVBoxLayout;

namespace core {
class Model;
struct Transition;
} // namespace core

namespace editor {

class ConditionEdit;
class DiagnosticList;
class Document;
class Selection;

// Properties of the selected transition: its condition (checked as it is
// typed), priority, negation, visibility and tokens. Edits are commands
// pushed on the Document; typing a condition merges into one undo step.
class TransitionDock : public PropertyDock {
    Q_OBJECT

public:
    // Also the title of the empty frame that stands for the dock at start-up.
    static QString title();
    TransitionDock(Document* document, Selection* selection, QWidget* parent = nullptr);

    // The transition shown; empty when the selection is not a transition.
    QString transitionId() const { return elementId(); }

private:
    // One checkbox of the token area.
    struct TokenRow {
        QString variable; // as declared, or as the token names it
        QString text;
        QString toolTip;
        bool checked = false;
        bool enabled = true;
    };

    QWidget* createForm();
    void retranslate() override;
    void refreshForm() override;
    void focusField(const QString& field) override;
    void refreshHeader(const core::Transition& transition);
    void refreshCondition(const core::Transition& transition);
    void refreshPriority(const core::Transition& transition);
    void refreshNegation(const core::Transition& transition);
    void refreshTokens(const core::Transition& transition);
    QList<TokenRow> tokenRows(const core::Transition& transition, QString* hint) const;
    void focusCondition();

    void onConditionEdited(const QString& text);
    void onPriorityChanged(int priority);
    void onNegatedToggled(bool checked);
    void onHiddenToggled(bool checked);
    void onTokenToggled(const QString& variable, bool checked);
    void onStepLinkActivated(const QString& stepId);

    QLabel* m_titleLabel = nullptr;
    QLabel* m_namesLabel = nullptr;
    QLabel* m_effectLabel = nullptr;
    QLabel* m_conditionLabel = nullptr;
    ConditionEdit* m_conditionEdit = nullptr;
    DiagnosticList* m_problemList = nullptr;
    QLabel* m_priorityLabel = nullptr;
    QSpinBox* m_prioritySpin = nullptr;
    QCheckBox* m_negatedCheck = nullptr;
    QLabel* m_negatedHint = nullptr;
    QCheckBox* m_hiddenCheck = nullptr;
    QGroupBox* m_tokenGroup = nullptr;
    QLabel* m_tokenHint = nullptr;
    QVBoxLayout* m_tokenLayout = nullptr;
    QList<QCheckBox*> m_tokenChecks;
    QList<TokenRow> m_tokenRows;
};

} // namespace editor
