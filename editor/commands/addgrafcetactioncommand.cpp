#include "editor/commands/addgrafcetactioncommand.h"

#include "editor/commands/commandids.h"

#include "core/model/model.h"

#include <utility>

namespace editor {

AddGrafcetActionCommand::AddGrafcetActionCommand(
    Document& document, const QString& stepId, int step, int index, core::GrafcetAction action)
    //: %1 is the action's place in the list (from 1), %2 the GEMMA step, %3 the nested step number
    : ModelCommand(document, [=] { return tr("Add action %1 to %2 step %3").arg(index + 1).arg(stepId).arg(step); })
    , m_stepId(toStdString(stepId))
    , m_step(step)
    , m_index(index)
    , m_action(std::move(action))
{
}

int AddGrafcetActionCommand::id() const
{
    return AddGrafcetActionId;
}

core::Status AddGrafcetActionCommand::apply()
{
    return model().addGrafcetAction(m_stepId, m_step, m_action, m_index);
}

core::Status AddGrafcetActionCommand::revert()
{
    return model().removeGrafcetAction(m_stepId, m_step, m_index);
}

} // namespace editor
