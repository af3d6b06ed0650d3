#include "editor/chart/gemma/chartcontextmenu.h"

#include "editor/commands/initialsteprule.h"
#include "editor/commands/setelementshiddencommand.h"
#include "editor/commands/setinitialstepcommand.h"
#include "editor/commands/setnegatedcommand.h"
#include "editor/commands/setprioritycommand.h"
#include "editor/commands/setstephiddencommand.h"
#include "editor/commands/setsteptypecommand.h"
#include "editor/commands/settransitionhiddencommand.h"
#include "editor/document.h"
#include "editor/grafcet/nestedgrafcetavailable.h"
#include "editor/selection.h"
#include "editor/text/elementlabels.h"

#include "core/model/model.h"

#include <QActionGroup>
#include <QMenu>

namespace editor {

namespace {

QAction* addNamed(QMenu* menu, const char* name, const QString& text)
{
    QAction* action = menu->addAction(text);
    action->setObjectName(QLatin1String(name));
    return action;
}

// Disabled, with why on hovering it, when `refusal` says why it cannot be done.
void refuseIf(QMenu* menu, QAction* action, const QString& refusal)
{
    if (refusal.isEmpty())
        return;
    action->setEnabled(false);
    action->setToolTip(refusal);
    action->setStatusTip(refusal);
    menu->setToolTipsVisible(true);
}

} // namespace

ChartContextMenu::ChartContextMenu(Document& document, Selection& selection, SheetActions sheet, QObject* parent)
    : QObject(parent)
    , m_document(document)
    , m_selection(selection)
    , m_sheet(sheet)
{
}

void ChartContextMenu::populate(QMenu* menu, const ElementRef& element)
{
    const QList<ElementRef>& selected = m_selection.elements();
    if (selected.size() > 1 && selected.contains(element)) {
        addSelectionEntries(menu, selected);
        menu->addSeparator();
    }
    switch (element.kind) {
    case ElementRef::Kind::Step:
        addStepEntries(menu, element.id);
        break;
    case ElementRef::Kind::Transition:
        addTransitionEntries(menu, element.id);
        break;
    default:
        addSheetEntries(menu);
        break;
    }
}

void ChartContextMenu::addStepEntries(QMenu* menu, const QString& stepId)
{
    const core::Step* step = m_document.model().step(stepId.toStdString());
    if (!step)
        return;
    if (canOpenNestedGrafcet(m_document.model(), stepId)) {
        QAction* open = addNamed(menu, "openGrafcetAction", tr("&Open Nested GRAFCET"));
        connect(open, &QAction::triggered, this, [this, stepId] { emit openGrafcetRequested(stepId); });
        menu->addSeparator();
    }
    const bool hidden = step->hidden;
    QAction* hide = addNamed(menu, hidden ? "showElementAction" : "hideElementAction",
                             hidden ? tr("&Show %1").arg(stepId) : tr("&Hide %1").arg(stepId));
    connect(hide, &QAction::triggered, this,
            [this, stepId, hidden] { m_document.push(new SetStepHiddenCommand(m_document, stepId, !hidden)); });
    refuseIf(menu, hide, InitialStepRule::hidingRefusal(m_document.model(), stepId));

    QMenu* types = menu->addMenu(tr("Step &Type"));
    types->setObjectName(QStringLiteral("stepTypeMenu"));
    auto* group = new QActionGroup(types);
    for (core::StepType type : {core::StepType::Simple, core::StepType::Macro, core::StepType::Enclosing}) {
        QAction* choice = types->addAction(stepTypeText(type));
        choice->setObjectName(QStringLiteral("stepType_%1").arg(int(type)));
        choice->setCheckable(true);
        choice->setChecked(step->type == type);
        group->addAction(choice);
        connect(choice, &QAction::triggered, this, [this, stepId, type] {
            if (const core::Step* current = m_document.model().step(stepId.toStdString()); current && current->type != type)
                m_document.push(new SetStepTypeCommand(m_document, stepId, type));
        });
    }

    QAction* initial = addNamed(menu, "makeInitialAction", tr("Make &Initial Step"));
    initial->setEnabled(!step->initial);
    refuseIf(menu, initial, InitialStepRule::initialRefusal(m_document.model(), stepId));
    connect(initial, &QAction::triggered, this,
            [this, stepId] { m_document.push(new SetInitialStepCommand(m_document, stepId)); });

    menu->addSeparator();
    QAction* comment = addNamed(menu, "editCommentAction", tr("Edit &Comment…"));
    connect(comment, &QAction::triggered, this,
            [this, stepId] { m_selection.select(ElementRef::step(stepId), QStringLiteral("comment")); });
}

void ChartContextMenu::addTransitionEntries(QMenu* menu, const QString& transitionId)
{
    const core::Model& model = m_document.model();
    const std::string id = transitionId.toStdString();
    const core::Transition* transition = model.transition(id);
    if (!transition)
        return;
    const QString label = transitionLabel(transitionId);
    QAction* condition = addNamed(menu, "editConditionAction", tr("Edit &Condition…"));
    connect(condition, &QAction::triggered, this, [this, transitionId] {
        m_selection.select(ElementRef::transition(transitionId), QStringLiteral("condition"));
    });

    const bool hidden = transition->hidden;
    QAction* hide = addNamed(menu, hidden ? "showElementAction" : "hideElementAction",
                             hidden ? tr("&Show %1").arg(label) : tr("&Hide %1").arg(label));
    connect(hide, &QAction::triggered, this, [this, transitionId, hidden] {
        m_document.push(new SetTransitionHiddenCommand(m_document, transitionId, !hidden));
    });

    if (!transition->isFamilyTransition()) {
        QAction* negate = addNamed(menu, "negateAction", tr("&Negated"));
        negate->setStatusTip(tr("Flips whether this transition waits for Complete of its source's nested behaviour"));
        negate->setCheckable(true);
        negate->setChecked(transition->negated);
        connect(negate, &QAction::triggered, this, [this, transitionId](bool negated) {
            m_document.push(new SetNegatedCommand(m_document, transitionId, negated));
        });
    }

    // Priority among the effective transitions of its source.
    const int priority = model.priority(id);
    const int count = priority > 0 ? int(model.effectiveOutgoing(transition->source).size()) : 0;
    menu->addSeparator();
    QAction* up = addNamed(menu, "priorityUpAction", tr("Priority &Up"));
    up->setEnabled(!transition->isFamilyTransition() && priority > 1);
    connect(up, &QAction::triggered, this, [this, transitionId, priority] {
        m_document.push(new SetPriorityCommand(m_document, transitionId, priority - 1));
    });
    QAction* down = addNamed(menu, "priorityDownAction", tr("Priority &Down"));
    down->setEnabled(!transition->isFamilyTransition() && priority > 0 && priority < count);
    connect(down, &QAction::triggered, this, [this, transitionId, priority] {
        m_document.push(new SetPriorityCommand(m_document, transitionId, priority + 1));
    });
}

void ChartContextMenu::addSelectionEntries(QMenu* menu, const QList<ElementRef>& elements)
{
    const int count = int(elements.size());
    QAction* hide = addNamed(menu, "hideSelectionAction", tr("Hide the %n Selected Elements", nullptr, count));
    connect(hide, &QAction::triggered, this,
            [this, elements] { m_document.push(new SetElementsHiddenCommand(m_document, elements, true)); });
    refuseIf(menu, hide, InitialStepRule::hidingRefusal(m_document.model(), elements));
    QAction* show = addNamed(menu, "showSelectionAction", tr("Show the %n Selected Elements", nullptr, count));
    connect(show, &QAction::triggered, this,
            [this, elements] { m_document.push(new SetElementsHiddenCommand(m_document, elements, false)); });
}

void ChartContextMenu::addSheetEntries(QMenu* menu)
{
    for (QAction* action : {m_sheet.showHidden, m_sheet.fit, m_sheet.exportChart}) {
        if (action)
            menu->addAction(action);
    }
}

} // namespace editor
