#pragma once

#include "editor/docks/propertydock.h"

class QAbstractItemView;
class QCheckBox;
class QLabel;
class QPlainTextEdit;
class QSpinBox;
class QTableView;
class QToolButton;

namespace core {
struct GrafcetStep;
}

namespace editor {

class DiagnosticList;
class GrafcetActionsModel;
class WrappingLabel;

// Properties of the selected step of a nested GRAFCET: its number (a used
// one is refused with a message), whether it is initial, its comment, and
// its actions as a table (GrafcetActionsModel) with buttons to add, remove
// and reorder them. Every edit is one command pushed on the Document;
// typing a comment or in one action's cell merges into one undo step.
class GrafcetStepDock : public PropertyDock {
    Q_OBJECT

public:
    // Also the title of the empty frame that stands for the dock at start-up.
    static QString title();
    GrafcetStepDock(Document* document, Selection* selection, QWidget* parent = nullptr);

    GrafcetActionsModel* actionsModel() const { return m_actionsModel; }
    QTableView* actionsView() const { return m_actionsView; }

private:
    QWidget* createForm();
    QWidget* createActionsArea(QWidget* parent);
    void retranslate() override;
    void refreshForm() override;
    void focusField(const QString& field) override;
    void focusFirstAction();
    void leaveOnCancelledEdit(QAbstractItemView* view);
    const core::GrafcetStep* step() const;
    void refreshActionButtons();
    void showActionProblem(const QString& typed = {});
    QStringList writableVariables() const;

    void onNumberChosen(int number);
    void onInitialToggled(bool checked);
    void onCommentEdited();
    void onAddAction();
    void onRemoveAction();
    void onMoveAction(int offset);

    QLabel* m_titleLabel = nullptr;
    QLabel* m_grafcetLabel = nullptr;
    QLabel* m_numberLabel = nullptr;
    QSpinBox* m_numberSpin = nullptr;
    WrappingLabel* m_numberMessage = nullptr;
    QCheckBox* m_initialCheck = nullptr;
    QLabel* m_commentLabel = nullptr;
    QPlainTextEdit* m_commentEdit = nullptr;
    QLabel* m_actionsLabel = nullptr;
    GrafcetActionsModel* m_actionsModel = nullptr;
    QTableView* m_actionsView = nullptr;
    QToolButton* m_addButton = nullptr;
    QToolButton* m_removeButton = nullptr;
    QToolButton* m_upButton = nullptr;
    QToolButton* m_downButton = nullptr;
    WrappingLabel* m_actionMessage = nullptr;
    DiagnosticList* m_problemList = nullptr;
};

} // namespace editor
