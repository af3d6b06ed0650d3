#pragma once

// The structured editing of one GRAFCET tab, as SFC editors offer it:
// insert a step after or before the selected step or transition, add a
// selection or parallel branch, a branch ending on an exit step, a loop or
// jump, move a branch left or right, remove a step (what it connected
// repaired), a transition or a branch, renumber, connect a transition directly,
// cut, copy and paste steps (through the system clipboard,
// grafcetclipboard.h), and create the usual shape of a new GRAFCET. Each
// entry is one EditGrafcetCommand running a core/model/grafcetediting.h
// operation; afterwards the created steps and transitions are selected.
//
// It attaches to a GrafcetView: the view's context menu (on a step, a
// transition or the background), the keyboard shortcuts inside it (Insert,
// Shift+Insert, Delete, Alt+Left, Alt+Right, Ctrl+X, Ctrl+C, Ctrl+V),
// linking and moving branches with the mouse (LinkDrag, BranchDrag) and,
// while the GRAFCET has no step, a link in the empty view to create the
// usual shape. The selection it edits is the GrafcetScene's own (its
// selectable step and transition items). The actions are named
// (objectName) for tests and scripts.

#include "core/model/grafcetediting.h"

#include <QKeySequence>
#include <QObject>
#include <QString>

#include <functional>
#include <vector>

class QAction;
class QDialog;
class QLabel;
class QMenu;

namespace editor {

class Document;
class GrafcetScene;
class GrafcetView;

class GrafcetActions : public QObject {
    Q_OBJECT

public:
    GrafcetActions(Document& document, GrafcetView& view);

    // Fills `menu` for what the scene has selected (nothing: the background).
    void populate(QMenu* menu);

    // The steps and transitions selected in the scene, in ascending order.
    std::vector<int> selectedSteps() const;
    std::vector<int> selectedTransitions() const;
    // Selects exactly these (unknown numbers are skipped).
    void select(const std::vector<int>& steps, const std::vector<int>& transitions);

    // Runs a dialog (Connect Directly) and returns its result; tests replace
    // it to fill the dialog in.
    using DialogRunner = std::function<int(QDialog&)>;
    void setDialogRunner(DialogRunner runner) { m_runDialog = std::move(runner); }

signals:
    // For the status bar: why Paste did nothing.
    void statusMessage(const QString& message);

private:
    QAction* addAction(const char* name, void (GrafcetActions::*slot)(), const QKeySequence& shortcut = {});
    void createActions();
    void createEmptyLink();
    void retranslate();
    void updateActions();
    void showContextMenu(const QPoint& pos);
    void addJumpMenu(QMenu* menu);

    const core::Grafcet* grafcet() const;
    // The one selected step (transition); 0 unless exactly one element is selected.
    int singleStep() const;
    int singleTransition() const;
    bool isSelectionBranch(int transition) const;
    bool isParallelBranch(int step) const;
    // The step naming the branch to move: the selected step, or the first
    // downstream step of the selected transition; 0 otherwise.
    int branchStep() const;
    // Whether Move Branch Left (-1) or Right (+1) has a branch to move: the
    // selection branch the selected transition starts, or the branch of branchStep.
    bool canMoveBranch(int offset) const;

    // Pushes one command running `edit`; selects what it created. The
    // wording calls tr() each time it runs (capturing what it names by
    // value), so the undo entry follows the UI language.
    using Edit = std::function<core::Status(core::Grafcet&, core::GrafcetCreated&)>;
    using Wording = std::function<QString()>;
    bool edit(Wording wording, const Edit& operation);

    void insertAfter();
    void insertBefore();
    using InsertOperation = core::Status (*)(core::Grafcet&, int, core::GrafcetCreated*);
    void insertStep(InsertOperation atStep, InsertOperation atTransition);
    void addSelectionBranch();
    void addParallelBranch();
    void addBranchEndingOnStep();
    void moveBranchLeft();
    void moveBranchRight();
    void moveBranch(int offset);
    void addJumpTo(int target);
    void removeSelected();
    void removeElements(const std::vector<int>& steps, const std::vector<int>& transitions, Wording wording);
    void removeBranch();
    void renumber();
    void connectDirectly();
    void cut();
    void copy();
    void paste();
    void createUsualShape();

    Document& m_document;
    GrafcetView& m_view;
    GrafcetScene& m_scene;
    QString m_stepId;
    DialogRunner m_runDialog;
    QLabel* m_emptyLink = nullptr;

    QAction* m_insertAfter = nullptr;
    QAction* m_insertBefore = nullptr;
    QAction* m_selectionBranch = nullptr;
    QAction* m_parallelBranch = nullptr;
    QAction* m_endingBranch = nullptr;
    QAction* m_moveBranchLeft = nullptr;
    QAction* m_moveBranchRight = nullptr;
    QAction* m_remove = nullptr;
    QAction* m_removeBranch = nullptr;
    QAction* m_renumber = nullptr;
    QAction* m_connect = nullptr;
    QAction* m_cut = nullptr;
    QAction* m_copy = nullptr;
    QAction* m_paste = nullptr;
    QAction* m_createUsual = nullptr;
};

} // namespace editor
