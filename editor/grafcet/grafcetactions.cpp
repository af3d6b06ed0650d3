#include "editor/grafcet/grafcetactions.h"

#include "editor/commands/editgrafcetcommand.h"
#include "editor/document.h"
#include "editor/grafcet/branchdrag.h"
#include "editor/grafcet/connecttransitiondialog.h"
#include "editor/grafcet/grafcetclipboard.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetstepitem.h"
#include "editor/grafcet/grafcettransitionitem.h"
#include "editor/grafcet/grafcetview.h"
#include "editor/grafcet/linkdrag.h"

#include "core/model/branchorder.h"
#include "core/model/model.h"

#include <QAction>
#include <QClipboard>
#include <QEvent>
#include <QGuiApplication>
#include <QGraphicsItem>
#include <QLabel>
#include <QMenu>
#include <QVBoxLayout>

#include <algorithm>
#include <memory>
#include <variant>

namespace editor {

namespace {

// The step or transition item at or above `item`; nullptr for the wiring.
QGraphicsItem* elementItem(QGraphicsItem* item)
{
    for (; item; item = item->parentItem())
        if (item->type() == GrafcetStepItem::Type || item->type() == GrafcetTransitionItem::Type)
            return item;
    return nullptr;
}

// Re-sends LanguageChange of the view to the actions.
class LanguageWatcher : public QObject {
public:
    LanguageWatcher(QObject* watched, std::function<void()> onChange)
        : QObject(watched)
        , m_onChange(std::move(onChange))
    {
        watched->installEventFilter(this);
    }

    bool eventFilter(QObject*, QEvent* event) override
    {
        if (event->type() == QEvent::LanguageChange)
            m_onChange();
        return false;
    }

private:
    std::function<void()> m_onChange;
};

} // namespace

GrafcetActions::GrafcetActions(Document& document, GrafcetView& view)
    : QObject(&view)
    , m_document(document)
    , m_view(view)
    , m_scene(*view.grafcetScene())
    , m_stepId(view.grafcetScene()->stepId())
    , m_runDialog([](QDialog& dialog) { return dialog.exec(); })
{
    setObjectName(QStringLiteral("grafcetActions"));
    createActions();
    createEmptyLink();
    retranslate();
    m_view.setContextMenuPolicy(Qt::CustomContextMenu);
    connect(&m_view, &QWidget::customContextMenuRequested, this, &GrafcetActions::showContextMenu);
    connect(&m_scene, &QGraphicsScene::selectionChanged, this, &GrafcetActions::updateActions);
    connect(&m_document, &Document::grafcetChanged, this, &GrafcetActions::updateActions);
    connect(&m_document, &Document::modelReset, this, &GrafcetActions::updateActions);
    connect(&m_document, &Document::stepChanged, this, &GrafcetActions::updateActions);
    connect(&m_document, &Document::readOnlyChanged, this, &GrafcetActions::updateActions);
    connect(QGuiApplication::clipboard(), &QClipboard::dataChanged, this, &GrafcetActions::updateActions);
    new LanguageWatcher(&m_view, [this] { retranslate(); });
    // The mouse: a drag from a connection handle links, one from a step's
    // body moves its branch. LinkDrag's event filter, installed last, runs
    // first and keeps the drags from a handle to itself.
    new BranchDrag(m_document, m_view);
    new LinkDrag(m_document, m_view);
    updateActions();
}

QAction* GrafcetActions::addAction(const char* name, void (GrafcetActions::*slot)(), const QKeySequence& shortcut)
{
    auto* action = new QAction(&m_view);
    action->setObjectName(QString::fromLatin1(name));
    action->setShortcut(shortcut);
    // Only while the GRAFCET tab has the focus: Delete and Ctrl+C mean other things elsewhere.
    action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    connect(action, &QAction::triggered, this, slot);
    m_view.addAction(action);
    return action;
}

void GrafcetActions::createActions()
{
    m_insertAfter = addAction("grafcetInsertAfterAction", &GrafcetActions::insertAfter, QKeySequence(Qt::Key_Insert));
    m_insertBefore = addAction("grafcetInsertBeforeAction", &GrafcetActions::insertBefore,
                               QKeySequence(Qt::SHIFT | Qt::Key_Insert));
    m_selectionBranch = addAction("grafcetSelectionBranchAction", &GrafcetActions::addSelectionBranch);
    m_parallelBranch = addAction("grafcetParallelBranchAction", &GrafcetActions::addParallelBranch);
    m_endingBranch = addAction("grafcetEndingBranchAction", &GrafcetActions::addBranchEndingOnStep);
    m_moveBranchLeft = addAction("grafcetMoveBranchLeftAction", &GrafcetActions::moveBranchLeft,
                                 QKeySequence(Qt::ALT | Qt::Key_Left));
    m_moveBranchRight = addAction("grafcetMoveBranchRightAction", &GrafcetActions::moveBranchRight,
                                  QKeySequence(Qt::ALT | Qt::Key_Right));
    m_remove = addAction("grafcetRemoveAction", &GrafcetActions::removeSelected, QKeySequence::Delete);
    m_removeBranch = addAction("grafcetRemoveBranchAction", &GrafcetActions::removeBranch);
    m_renumber = addAction("grafcetRenumberAction", &GrafcetActions::renumber);
    m_connect = addAction("grafcetConnectAction", &GrafcetActions::connectDirectly);
    m_cut = addAction("grafcetCutAction", &GrafcetActions::cut, QKeySequence::Cut);
    m_copy = addAction("grafcetCopyAction", &GrafcetActions::copy, QKeySequence::Copy);
    m_paste = addAction("grafcetPasteAction", &GrafcetActions::paste, QKeySequence::Paste);
    m_createUsual = addAction("grafcetCreateUsualAction", &GrafcetActions::createUsualShape);
}

// A link in the empty view: the first thing to do with a GRAFCET never drawn.
void GrafcetActions::createEmptyLink()
{
    m_emptyLink = new QLabel(m_view.viewport());
    m_emptyLink->setObjectName(QStringLiteral("grafcetEmptyLink"));
    m_emptyLink->setTextFormat(Qt::RichText);
    m_emptyLink->setAlignment(Qt::AlignCenter);
    m_emptyLink->setWordWrap(true);
    m_emptyLink->setMinimumWidth(360); // two lines, not a narrow column
    connect(m_emptyLink, &QLabel::linkActivated, this, [this] { m_createUsual->trigger(); });
    auto* layout = new QVBoxLayout(m_view.viewport());
    layout->addWidget(m_emptyLink, 0, Qt::AlignCenter);
}

void GrafcetActions::retranslate()
{
    m_insertAfter->setText(tr("Insert Step &After"));
    m_insertBefore->setText(tr("Insert Step &Before"));
    m_selectionBranch->setText(tr("Add &Selection Branch"));
    m_parallelBranch->setText(tr("Add &Parallel Branch"));
    m_endingBranch->setText(tr("Add Branch &Ending on a Step"));
    m_endingBranch->setToolTip(tr("A new branch from this step to a new step with no transition after it "
                                  "(an exit step)"));
    m_moveBranchLeft->setText(tr("Move Branch &Left"));
    m_moveBranchLeft->setToolTip(tr("Swap the branch holding this step with the one at its left"));
    m_moveBranchRight->setText(tr("Move Branch Ri&ght"));
    m_moveBranchRight->setToolTip(tr("Swap the branch holding this step with the one at its right"));
    m_remove->setText(tr("&Remove"));
    m_removeBranch->setText(tr("Remove Bra&nch"));
    m_renumber->setText(tr("Ren&umber Steps and Transitions"));
    m_connect->setText(tr("&Connect Directly…"));
    m_cut->setText(tr("Cu&t Steps"));
    m_copy->setText(tr("&Copy Steps"));
    m_paste->setText(tr("&Paste Steps"));
    m_createUsual->setText(tr("Create the &Usual Shape"));
    m_createUsual->setToolTip(tr("Initial step 1, then step 2, then step 3, which sets Complete"));
    //: %1 the GEMMA step; the link creates its GRAFCET
    m_emptyLink->setText(tr("%1 has no GRAFCET yet.<br><a href=\"create\">Create the usual shape</a>: "
                            "initial step 1, step 2, and step 3, which sets Complete.")
                             .arg(m_stepId));
}

const core::Grafcet* GrafcetActions::grafcet() const
{
    return m_document.model().grafcet(m_stepId.toStdString());
}

std::vector<int> GrafcetActions::selectedSteps() const
{
    std::vector<int> numbers;
    for (QGraphicsItem* item : m_scene.selectedItems())
        if (item->type() == GrafcetStepItem::Type)
            numbers.push_back(static_cast<GrafcetStepItem*>(item)->number());
    std::sort(numbers.begin(), numbers.end());
    return numbers;
}

std::vector<int> GrafcetActions::selectedTransitions() const
{
    std::vector<int> numbers;
    for (QGraphicsItem* item : m_scene.selectedItems())
        if (item->type() == GrafcetTransitionItem::Type)
            numbers.push_back(static_cast<GrafcetTransitionItem*>(item)->number());
    std::sort(numbers.begin(), numbers.end());
    return numbers;
}

void GrafcetActions::select(const std::vector<int>& steps, const std::vector<int>& transitions)
{
    m_scene.clearSelection();
    for (int number : steps)
        if (GrafcetStepItem* item = m_scene.stepItem(number))
            item->setSelected(true);
    for (int number : transitions)
        if (GrafcetTransitionItem* item = m_scene.transitionItem(number))
            item->setSelected(true);
}

int GrafcetActions::singleStep() const
{
    const std::vector<int> steps = selectedSteps();
    return steps.size() == 1 && selectedTransitions().empty() ? steps.front() : 0;
}

int GrafcetActions::singleTransition() const
{
    const std::vector<int> transitions = selectedTransitions();
    return transitions.size() == 1 && selectedSteps().empty() ? transitions.front() : 0;
}

bool GrafcetActions::isSelectionBranch(int transition) const
{
    const core::Grafcet* g = grafcet();
    const core::GrafcetTransition* t = g ? g->transition(transition) : nullptr;
    return t && t->upstream.size() == 1 && g->transitionsFrom(t->upstream.front()).size() >= 2;
}

bool GrafcetActions::isParallelBranch(int step) const
{
    const core::Grafcet* g = grafcet();
    if (!g)
        return false;
    const auto reaching = g->transitionsTo(step);
    return std::any_of(reaching.begin(), reaching.end(),
                       [](const core::GrafcetTransition* t) { return t->downstream.size() >= 2; });
}

bool GrafcetActions::canMoveBranch(int offset) const
{
    const core::Grafcet* g = grafcet();
    if (!g)
        return false;
    if (const int transition = singleTransition(); transition != 0 && core::canMoveSelectionBranch(*g, transition, offset))
        return true;
    const int step = branchStep();
    return step != 0 && core::canMoveBranch(*g, step, offset);
}

int GrafcetActions::branchStep() const
{
    if (const int step = singleStep(); step != 0)
        return step;
    const core::Grafcet* g = grafcet();
    const core::GrafcetTransition* t = g ? g->transition(singleTransition()) : nullptr;
    return t ? t->downstream.front() : 0;
}

void GrafcetActions::updateActions()
{
    const bool editable = !m_document.isReadOnly();
    const core::Grafcet* g = grafcet();
    const bool empty = !g || g->steps().empty();
    const int step = singleStep();
    const int transition = singleTransition();
    const bool element = step != 0 || transition != 0;
    m_insertAfter->setEnabled(editable && element);
    m_insertBefore->setEnabled(editable && element);
    const core::GrafcetTransition* t = g && transition != 0 ? g->transition(transition) : nullptr;
    m_selectionBranch->setEnabled(editable && ((step != 0 && g && !g->transitionsFrom(step).empty())
                                               || (t && t->upstream.size() == 1)));
    m_parallelBranch->setEnabled(editable && transition != 0);
    m_endingBranch->setEnabled(editable && step != 0);
    m_moveBranchLeft->setEnabled(editable && canMoveBranch(-1));
    m_moveBranchRight->setEnabled(editable && canMoveBranch(+1));
    m_remove->setEnabled(editable && !m_scene.selectedItems().isEmpty());
    m_removeBranch->setEnabled(editable && ((transition != 0 && isSelectionBranch(transition))
                                            || (step != 0 && isParallelBranch(step))));
    m_renumber->setEnabled(editable && !empty);
    m_connect->setEnabled(editable && transition != 0);
    m_cut->setEnabled(editable && !selectedSteps().empty());
    m_copy->setEnabled(!selectedSteps().empty());
    m_paste->setEnabled(editable && GrafcetClipboard::holdsFragment()
                        && (step != 0 || m_scene.selectedItems().isEmpty()));
    m_createUsual->setEnabled(editable && empty);
    m_emptyLink->setVisible(empty);
}

void GrafcetActions::showContextMenu(const QPoint& pos)
{
    QGraphicsItem* item = elementItem(m_view.itemAt(pos));
    if (!item)
        m_scene.clearSelection();
    else if (!item->isSelected()) {
        m_scene.clearSelection();
        item->setSelected(true);
    }
    QMenu menu(&m_view);
    menu.setObjectName(QStringLiteral("grafcetContextMenu"));
    populate(&menu);
    menu.exec(m_view.viewport()->mapToGlobal(pos));
}

void GrafcetActions::populate(QMenu* menu)
{
    updateActions();
    const core::Grafcet* g = grafcet();
    if (!g || g->steps().empty()) {
        menu->addActions({m_createUsual, m_paste});
        return;
    }
    const int step = singleStep();
    const int transition = singleTransition();
    if (step != 0 || transition != 0) {
        menu->addActions({m_insertAfter, m_insertBefore});
        menu->addSeparator();
        menu->addAction(m_selectionBranch);
        if (transition != 0)
            menu->addAction(m_parallelBranch);
        if (step != 0) {
            menu->addAction(m_endingBranch);
            addJumpMenu(menu);
        }
        menu->addActions({m_moveBranchLeft, m_moveBranchRight});
        menu->addSeparator();
    }
    if (m_remove->isEnabled())
        menu->addAction(m_remove);
    if (m_removeBranch->isEnabled())
        menu->addAction(m_removeBranch);
    if (transition != 0)
        menu->addAction(m_connect);
    menu->addSeparator();
    if (m_cut->isEnabled())
        menu->addAction(m_cut);
    if (m_copy->isEnabled())
        menu->addAction(m_copy);
    menu->addAction(m_paste);
    menu->addSeparator();
    menu->addAction(m_renumber);
}

// A loop or a jump from the selected step to one the user picks.
void GrafcetActions::addJumpMenu(QMenu* menu)
{
    QMenu* jumps = menu->addMenu(tr("Add Loop or &Jump To"));
    jumps->setObjectName(QStringLiteral("grafcetJumpMenu"));
    jumps->setEnabled(!m_document.isReadOnly());
    for (const core::GrafcetStep& target : grafcet()->steps()) {
        QAction* action = jumps->addAction(tr("Step %1").arg(target.number));
        action->setObjectName(QStringLiteral("grafcetJumpTo_%1").arg(target.number));
        connect(action, &QAction::triggered, this, [this, number = target.number] { addJumpTo(number); });
    }
}

bool GrafcetActions::edit(Wording wording, const Edit& operation)
{
    auto created = std::make_shared<core::GrafcetCreated>();
    auto* command = new EditGrafcetCommand(
        m_document, m_stepId, [operation, created](core::Grafcet& g) { return operation(g, *created); },
        std::move(wording));
    if (!m_document.push(command))
        return false;
    select(created->steps, created->transitions);
    return true;
}

void GrafcetActions::insertAfter()
{
    insertStep(core::insertStepAfterStep, core::insertStepAfterTransition);
}

void GrafcetActions::insertBefore()
{
    insertStep(core::insertStepBeforeStep, core::insertStepBeforeTransition);
}

// A step and a transition at the selected step or transition, by the core
// operation for each.
void GrafcetActions::insertStep(InsertOperation atStep, InsertOperation atTransition)
{
    const int step = singleStep();
    const int transition = singleTransition();
    if (!grafcet() || (step == 0 && transition == 0))
        return;
    const auto wording = [number = grafcet()->nextStepNumber(), stepId = m_stepId] {
        return tr("Add step %1 to %2").arg(number).arg(stepId);
    };
    edit(wording, [=](core::Grafcet& g, core::GrafcetCreated& created) {
        return step != 0 ? atStep(g, step, &created) : atTransition(g, transition, &created);
    });
}

void GrafcetActions::addSelectionBranch()
{
    const int step = singleStep();
    const int transition = singleTransition();
    if (step == 0 && transition == 0)
        return;
    edit([stepId = m_stepId] { return tr("Add selection branch to %1").arg(stepId); },
        [step, transition](core::Grafcet& g, core::GrafcetCreated& created) {
            return step != 0 ? core::addSelectionBranchAtStep(g, step, &created)
                             : core::addSelectionBranchAtTransition(g, transition, &created);
        });
}

void GrafcetActions::addParallelBranch()
{
    const int transition = singleTransition();
    if (transition == 0)
        return;
    edit([stepId = m_stepId] { return tr("Add parallel branch to %1").arg(stepId); },
        [transition](core::Grafcet& g, core::GrafcetCreated& created) {
            return core::addParallelBranch(g, transition, &created);
        });
}

void GrafcetActions::addBranchEndingOnStep()
{
    const int step = singleStep();
    if (step == 0)
        return;
    edit(
        [step, stepId = m_stepId] {
            //: %1 the step the branch leaves, %2 the GEMMA step whose GRAFCET it is
            return tr("Add branch ending on a step at step %1 in %2").arg(step).arg(stepId);
        },
        [step](core::Grafcet& g, core::GrafcetCreated& created) {
            return core::addBranchEndingOnStep(g, step, &created);
        });
}

void GrafcetActions::moveBranchLeft()
{
    moveBranch(-1);
}

void GrafcetActions::moveBranchRight()
{
    moveBranch(+1);
}

// Moves the branch one place; the selection stays on what it was.
void GrafcetActions::moveBranch(int offset)
{
    if (!canMoveBranch(offset))
        return;
    // A selection branch named by its first transition (a jump back has no step to name it by).
    const int transition = core::canMoveSelectionBranch(*grafcet(), singleTransition(), offset) ? singleTransition() : 0;
    const int step = branchStep();
    const std::vector<int> steps = selectedSteps();
    const std::vector<int> transitions = selectedTransitions();
    const auto wording = [offset, stepId = m_stepId] {
        //: %1 the GEMMA step whose GRAFCET it is
        return offset < 0 ? tr("Move branch left in %1").arg(stepId) : tr("Move branch right in %1").arg(stepId);
    };
    edit(wording, [transition, step, offset, steps, transitions](core::Grafcet& g, core::GrafcetCreated& created) {
        created.steps = steps;
        created.transitions = transitions;
        return transition != 0 ? core::moveSelectionBranch(g, transition, offset) : core::moveBranch(g, step, offset);
    });
}

void GrafcetActions::addJumpTo(int target)
{
    const int step = singleStep();
    if (step == 0)
        return;
    edit(
        [step, target, stepId = m_stepId] {
            //: %1 and %2 step numbers, %3 the GEMMA step whose GRAFCET it is
            return tr("Add jump from step %1 to step %2 in %3").arg(step).arg(target).arg(stepId);
        },
        [step, target](
            core::Grafcet& g, core::GrafcetCreated& created) { return core::addJump(g, step, target, &created); });
}

// The selected transitions go as they are (what they leave dangling, the
// checks report), then the selected steps with their sequences repaired.
void GrafcetActions::removeSelected()
{
    const std::vector<int> steps = selectedSteps();
    const std::vector<int> transitions = selectedTransitions();
    if (steps.empty() && transitions.empty())
        return;
    removeElements(steps, transitions, [steps, transitions, stepId = m_stepId] {
        if (transitions.empty())
            return steps.size() == 1 ? tr("Remove step %1 from %2").arg(steps.front()).arg(stepId)
                                     : tr("Remove %n steps from %1", nullptr, int(steps.size())).arg(stepId);
        if (steps.empty())
            return transitions.size() == 1
                ? tr("Remove T%1 from %2").arg(transitions.front()).arg(stepId)
                : tr("Remove %n transitions from %1", nullptr, int(transitions.size())).arg(stepId);
        return tr("Remove %n elements from %1", nullptr, int(steps.size() + transitions.size())).arg(stepId);
    });
}

// The transitions go as they are, then each step with repair (what it
// connected joined), in one command.
void GrafcetActions::removeElements(const std::vector<int>& steps, const std::vector<int>& transitions, Wording wording)
{
    edit(std::move(wording), [steps, transitions](core::Grafcet& g, core::GrafcetCreated&) {
        for (int transition : transitions)
            if (core::Status status = g.removeTransition(transition); !status)
                return status;
        for (int step : steps)
            if (core::Status status = core::removeStepWithRepair(g, step); !status)
                return status;
        return core::Status::success();
    });
}

void GrafcetActions::removeBranch()
{
    const int step = singleStep();
    const int transition = singleTransition();
    if (step == 0 && transition == 0)
        return;
    edit([stepId = m_stepId] { return tr("Remove branch from %1").arg(stepId); },
        [step, transition](core::Grafcet& g, core::GrafcetCreated&) {
            return step != 0 ? core::removeParallelBranch(g, step) : core::removeSelectionBranch(g, transition);
        });
}

void GrafcetActions::renumber()
{
    edit([stepId = m_stepId] { return tr("Renumber %1").arg(stepId); },
        [](core::Grafcet& g, core::GrafcetCreated&) { return core::renumberAll(g); });
}

void GrafcetActions::connectDirectly()
{
    const int transition = singleTransition();
    if (transition == 0 || !grafcet())
        return;
    ConnectTransitionDialog dialog(*grafcet(), transition, m_stepId, &m_view);
    if (m_runDialog(dialog) != QDialog::Accepted)
        return;
    const std::vector<int> upstream = dialog.upstream();
    const std::vector<int> downstream = dialog.downstream();
    edit(
        [transition, stepId = m_stepId] {
            //: %1 the GEMMA step, %2 the transition's number
            return tr("Connect %1 T%2").arg(stepId).arg(transition);
        },
        [transition, upstream, downstream](core::Grafcet& g, core::GrafcetCreated& created) {
            created.transitions.push_back(transition);
            return core::connectDirectly(g, transition, upstream, downstream);
        });
}

// Copy, then the steps removed as Delete removes them.
void GrafcetActions::cut()
{
    const std::vector<int> steps = selectedSteps();
    if (steps.empty() || m_document.isReadOnly())
        return;
    copy();
    removeElements(steps, {}, [steps, stepId = m_stepId] {
        return steps.size() == 1 ? tr("Cut step %1 from %2").arg(steps.front()).arg(stepId)
                                 : tr("Cut %n steps from %1", nullptr, int(steps.size())).arg(stepId);
    });
}

void GrafcetActions::copy()
{
    if (const core::Grafcet* g = grafcet(); g && !selectedSteps().empty())
        GrafcetClipboard::put(core::copyFragment(*g, selectedSteps()));
}

void GrafcetActions::paste()
{
    if (singleStep() == 0 && !m_scene.selectedItems().isEmpty())
        return;
    auto read = GrafcetClipboard::fragment();
    if (const QString* problem = std::get_if<QString>(&read)) {
        emit statusMessage(*problem);
        return;
    }
    const core::GrafcetFragment fragment = std::get<core::GrafcetFragment>(std::move(read));
    const int after = singleStep();
    const auto wording = [count = int(fragment.steps.size()), stepId = m_stepId] {
        return tr("Paste %n steps into %1", nullptr, count).arg(stepId);
    };
    edit(wording, [fragment, after](core::Grafcet& g, core::GrafcetCreated& created) {
        return core::pasteFragment(g, fragment, after, &created);
    });
}

void GrafcetActions::createUsualShape()
{
    if (const core::Grafcet* g = grafcet(); g && !g->steps().empty())
        return;
    edit([stepId = m_stepId] { return tr("Create GRAFCET of %1").arg(stepId); },
        [](core::Grafcet& g, core::GrafcetCreated& created) {
            g = core::usualGrafcet();
            // One element selected, so that the menu inserts at once: the first
            // transition, whose receptivity (TRUE) is the first thing to write.
            created.transitions.push_back(g.transitions().front().number);
            return core::Status::success();
        });
}

} // namespace editor
