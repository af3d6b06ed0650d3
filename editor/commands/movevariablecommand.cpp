#include "editor/commands/movevariablecommand.h"

#include "editor/commands/commandids.h"

#include "core/model/model.h"

namespace editor {

MoveVariableCommand::MoveVariableCommand(Document& document, const QString& name, int index)
    : ModelCommand(document, [=] { return tr("Move variable %1").arg(name); })
    , m_name(toStdString(name))
    , m_index(index)
{
}

int MoveVariableCommand::id() const
{
    return MoveVariableId;
}

core::Status MoveVariableCommand::apply()
{
    if (firstRun())
        m_previous = model().variableIndex(m_name);
    return model().moveVariable(m_name, m_index);
}

core::Status MoveVariableCommand::revert()
{
    return model().moveVariable(m_name, m_previous);
}

} // namespace editor
