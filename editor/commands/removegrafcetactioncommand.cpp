#include "editor/commands/removegrafcetactioncommand.h"

#include "editor/commands/commandids.h"

#include "core/model/model.h"

namespace editor {

RemoveGrafcetActionCommand::RemoveGrafcetActionCommand(Document& document, const QString& stepId, int step, int index)
    //: %1 is the action's place in the list (from 1), %2 the GEMMA step, %3 the nested step number
    : ModelCommand(document, [=] { return tr("Remove action %1 of %2 step %3").arg(index + 1).arg(stepId).arg(step); })
    , m_stepId(toStdString(stepId))
    , m_step(step)
    , m_index(index)
{
}

int RemoveGrafcetActionCommand::id() const
{
    return RemoveGrafcetActionId;
}

core::Status RemoveGrafcetActionCommand::apply()
{
    if (firstRun()) {
        const core::Grafcet* grafcet = model().grafcet(m_stepId);
        const core::GrafcetStep* step = grafcet ? grafcet->step(m_step) : nullptr;
        if (step && m_index >= 0 && m_index < static_cast<int>(step->actions.size()))
            m_removed = step->actions[static_cast<std::size_t>(m_index)];
    }
    return model().removeGrafcetAction(m_stepId, m_step, m_index);
}

core::Status RemoveGrafcetActionCommand::revert()
{
    return model().addGrafcetAction(m_stepId, m_step, m_removed, m_index);
}

} // namespace editor
