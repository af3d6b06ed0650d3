#include "editor/commands/setgrafcetactioncommand.h"

#include "editor/commands/commandids.h"

#include "core/model/model.h"

#include <utility>

namespace editor {

SetGrafcetActionCommand::SetGrafcetActionCommand(
    Document& document, const QString& stepId, int step, int index, core::GrafcetAction action)
    //: %1 is the action's place in the list (from 1), %2 the GEMMA step, %3 the nested step number
    : ModelCommand(document, [=] { return tr("Set action %1 of %2 step %3").arg(index + 1).arg(stepId).arg(step); })
    , m_stepId(toStdString(stepId))
    , m_step(step)
    , m_index(index)
    , m_action(std::move(action))
{
}

int SetGrafcetActionCommand::id() const
{
    return SetGrafcetActionId;
}

bool SetGrafcetActionCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const SetGrafcetActionCommand*>(other);
    if (next->m_stepId != m_stepId || next->m_step != m_step || next->m_index != m_index)
        return false;
    m_action = next->m_action;
    setObsolete(m_action == m_previous); // edited back to where it started
    return true;
}

core::Status SetGrafcetActionCommand::apply()
{
    if (firstRun()) {
        const core::Grafcet* grafcet = model().grafcet(m_stepId);
        const core::GrafcetStep* step = grafcet ? grafcet->step(m_step) : nullptr;
        if (step && m_index >= 0 && m_index < static_cast<int>(step->actions.size()))
            m_previous = step->actions[static_cast<std::size_t>(m_index)];
    }
    return model().setGrafcetAction(m_stepId, m_step, m_index, m_action);
}

core::Status SetGrafcetActionCommand::revert()
{
    return model().setGrafcetAction(m_stepId, m_step, m_index, m_previous);
}

} // namespace editor
