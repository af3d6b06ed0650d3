#include "editor/grafcet/grafcetactions.h"

#include "editor/commands/editgrafcetcommand.h"
#include "editor/document.h"
#include "editor/grafcet/branchdrag.h"
#include "editor/grafcet/connecttransitiondialog.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetstepitem.h"
#include "editor/grafcet/grafcettransitionitem.h"
#include "editor/grafcet/grafcetview.h"
#include "editor/grafcet/linkdrag.h"

#include "core/model/model.h"

#include <QAction>
#include <QEvent>
#include <QGraphicsItem>
#include <QLabel>
#include <QMenu>
#include <QVBoxLayout>

#include <algorithm>
#include <memory>

namespace editor {

namespace {

core::GrafcetFragment& clipboard()
{
    static core::GrafcetFragment fragment;
    return fragment;
}

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
    new LanguageWatcher(&m_view, [this] { retranslate(); });
    // The mouse: a drag from a connection handle links, one from a step's
    // body moves its branch. LinkDrag's event filter, installed last, runs
    // first and keeps the drags from a handle to itself.
    new BranchDrag(m_document, m_view);
    new LinkDrag(m_document, m_view);
    updateActions();
}

const core::GrafcetFragment& GrafcetActions::copiedFragment()
{
    return clipboard();
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
    m_remove = addAction("grafcetRemoveAction", &GrafcetActions::removeSelected, QKeySequence::Delete);
    m_removeBranch = addAction("grafcetRemoveBranchAction", &GrafcetActions::removeBranch);
    m_renumber = addAction("grafcetRenumberAction", &GrafcetActions::renumber);
    m_connect = addAction("grafcetConnectAction", &GrafcetActions::connectDirectly);
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
    m_remove->setText(tr("&Remove"));
    m_removeBranch->setText(tr("Remove Bra&nch"));
    m_renumber->setText(tr("Ren&umber Steps and Transitions"));
    m_connect->setText(tr("&Connect Directly…"));
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
    m_remove->setEnabled(editable
                         && (!selectedSteps().empty() || (transition != 0 && isSelectionBranch(transition))));
    m_removeBranch->setEnabled(editable && ((transition != 0 && isSelectionBranch(transition))
                                            || (step != 0 && isParallelBranch(step))));
    m_renumber->setEnabled(editable && !empty);
    m_connect->setEnabled(editable && transition != 0);
    m_copy->setEnabled(!selectedSteps().empty());
    m_paste->setEnabled(editable && !clipboard().empty() && (step != 0 || m_scene.selectedItems().isEmpty()));
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
        if (step != 0)
            addJumpMenu(menu);
        menu->addSeparator();
    }
    if (m_remove->isEnabled())
        menu->addAction(m_remove);
    if (m_removeBranch->isEnabled())
        menu->addAction(m_removeBranch);
    if (transition != 0)
        menu->addAction(m_connect);
    menu->addSeparator();
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

bool GrafcetActions::edit(const QString& text, const Edit& operation)
{
    auto created = std::make_shared<core::GrafcetCreated>();
    auto* command = new EditGrafcetCommand(
        m_document, m_stepId, [operation, created](core::Grafcet& g) { return operation(g, *created); }, text);
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
    edit(tr("Add step %1 to %2").arg(grafcet()->nextStepNumber()).arg(m_stepId),
         [=](core::Grafcet& g, core::GrafcetCreated& created) {
             return step != 0 ? atStep(g, step, &created) : atTransition(g, transition, &created);
         });
}

void GrafcetActions::addSelectionBranch()
{
    const int step = singleStep();
    const int transition = singleTransition();
    if (step == 0 && transition == 0)
        return;
    edit(tr("Add selection branch to %1").arg(m_stepId),
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
    edit(tr("Add parallel branch to %1").arg(m_stepId), [transition](core::Grafcet& g, core::GrafcetCreated& created) {
        return core::addParallelBranch(g, transition, &created);
    });
}

void GrafcetActions::addJumpTo(int target)
{
    const int step = singleStep();
    if (step == 0)
        return;
    //: %1 and %2 step numbers, %3 the GEMMA step whose GRAFCET it is
    edit(tr("Add jump from step %1 to step %2 in %3").arg(step).arg(target).arg(m_stepId),
         [step, target](core::Grafcet& g, core::GrafcetCreated& created) {
             return core::addJump(g, step, target, &created);
         });
}

void GrafcetActions::removeSelected()
{
    const std::vector<int> steps = selectedSteps();
    if (steps.empty()) {
        const int transition = singleTransition();
        if (transition != 0 && isSelectionBranch(transition))
            removeBranch();
        return;
    }
    const QString text = steps.size() == 1 ? tr("Remove step %1 from %2").arg(steps.front()).arg(m_stepId)
                                           : tr("Remove %n steps from %1", nullptr, int(steps.size())).arg(m_stepId);
    edit(text, [steps](core::Grafcet& g, core::GrafcetCreated&) {
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
    edit(tr("Remove branch from %1").arg(m_stepId), [step, transition](core::Grafcet& g, core::GrafcetCreated&) {
        return step != 0 ? core::removeParallelBranch(g, step) : core::removeSelectionBranch(g, transition);
    });
}

void GrafcetActions::renumber()
{
    edit(tr("Renumber %1").arg(m_stepId),
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
    //: %1 the GEMMA step, %2 the transition's number
    edit(tr("Connect %1 T%2").arg(m_stepId).arg(transition),
         [transition, upstream, downstream](core::Grafcet& g, core::GrafcetCreated& created) {
             created.transitions.push_back(transition);
             return core::connectDirectly(g, transition, upstream, downstream);
         });
}

void GrafcetActions::copy()
{
    if (const core::Grafcet* g = grafcet(); g && !selectedSteps().empty()) {
        clipboard() = core::copyFragment(*g, selectedSteps());
        updateActions();
    }
}

void GrafcetActions::paste()
{
    const core::GrafcetFragment fragment = clipboard();
    if (fragment.empty() || (singleStep() == 0 && !m_scene.selectedItems().isEmpty()))
        return;
    const int after = singleStep();
    edit(tr("Paste %n steps into %1", nullptr, int(fragment.steps.size())).arg(m_stepId),
         [fragment, after](core::Grafcet& g, core::GrafcetCreated& created) {
             return core::pasteFragment(g, fragment, after, &created);
         });
}

void GrafcetActions::createUsualShape()
{
    if (const core::Grafcet* g = grafcet(); g && !g->steps().empty())
        return;
    edit(tr("Create GRAFCET of %1").arg(m_stepId), [](core::Grafcet& g, core::GrafcetCreated& created) {
        g = core::usualGrafcet();
        for (const core::GrafcetStep& step : g.steps())
            created.steps.push_back(step.number);
        return core::Status::success();
    });
}

} // namespace editor
