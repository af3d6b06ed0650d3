#pragma once

#include "editor/docks/propertydock.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace core {
struct Transition;
}

namespace editor {

class DiagnosticList;
class Document;
class Selection;
class StartGuide;

// Properties of the selected step: its official name, type, initial and
// hidden flags, comment, and the transitions in and out of it as links.
// Edits are commands pushed on the Document. While nothing is selected it
// shows the StartGuide.
class StepDock : public PropertyDock {
    Q_OBJECT

public:
    // Also the title of the empty frame that stands for the dock at start-up.
    static QString title();
    StepDock(Document* document, Selection* selection, QWidget* parent = nullptr);

    // The step shown; empty when the selection is not a step.
    QString stepId() const { return elementId(); }
    StartGuide* startGuide() const { return m_startGuide; }

signals:
    // "Open Nested GRAFCET" on a step that has one.
    void openGrafcetRequested(const QString& stepId);

private:
    QWidget* createForm();
    QTreeWidget* createTransitionList(const QString& objectName);
    void retranslate() override;
    void refreshForm() override;
    void focusField(const QString& field) override;
    void refreshTransitions();
    void fillList(QTreeWidget* list, const std::vector<const core::Transition*>& transitions, bool outgoing);
    QTreeWidgetItem* transitionItem(const core::Transition& transition, bool outgoing) const;
    void refreshProblems();

    void onTypeChosen(int index);
    void onInitialToggled(bool checked);
    void onHiddenToggled(bool checked);
    void onCommentEdited();
    void onTransitionClicked(QTreeWidgetItem* item);

    StartGuide* m_startGuide = nullptr;
    QLabel* m_idLabel = nullptr;
    QLabel* m_nameLabel = nullptr;
    QLabel* m_familyLabel = nullptr;
    QLabel* m_typeLabel = nullptr;
    QComboBox* m_typeCombo = nullptr;
    QCheckBox* m_initialCheck = nullptr;
    QCheckBox* m_hiddenCheck = nullptr;
    QPushButton* m_openGrafcetButton = nullptr;
    QLabel* m_commentLabel = nullptr;
    QPlainTextEdit* m_commentEdit = nullptr;
    QLabel* m_incomingHeading = nullptr;
    QLabel* m_outgoingHeading = nullptr;
    QTreeWidget* m_incomingList = nullptr;
    QTreeWidget* m_outgoingList = nullptr;
    DiagnosticList* m_problemList = nullptr;
};

} // namespace editor
