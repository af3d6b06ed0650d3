#pragma once

#include <QWidget>

#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;
class QUndoCommand;

namespace editor {

class Document;

// The PackML part of Model Settings (spec packml.md §5.1) for a PackML
// model: the edition, the options holdInSuspended and
// completeInSuspendedHeld (2022 only), and the initial state (Stopped, Idle
// or Aborted). Choosing an edition sets the options to that edition's
// defaults, which the user may then change. The initial mode is the Modes
// panel's. Nothing changes until the dialog applies pendingCommands().
class PackmlSettingsWidget : public QWidget {
    Q_OBJECT

public:
    explicit PackmlSettingsWidget(Document& document, QWidget* parent = nullptr);

    // One undo command per setting that differs from the model's, for the
    // dialog to push (in one macro with its own); the caller owns them.
    std::vector<QUndoCommand*> pendingCommands() const;

private:
    void onEditionChosen();
    void updateOptionStates();

    Document& m_document;
    QComboBox* m_editionCombo;
    QCheckBox* m_holdInSuspendedCheck;
    QCheckBox* m_completeInSuspendedHeldCheck;
    QComboBox* m_initialStateCombo;
    QLabel* m_editionHint;
};

} // namespace editor
