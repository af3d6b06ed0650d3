#include "editor/commands/removevariablecommand.h"

#include "editor/commands/commandids.h"

namespace editor {

RemoveVariableCommand::RemoveVariableCommand(Document& document, const QString& name)
    : ModelCommand(document, [=] { return tr("Remove variable %1").arg(name); })
    , m_name(toStdString(name))
{
}

int RemoveVariableCommand::id() const
{
    return RemoveVariableId;
}

core::Status RemoveVariableCommand::apply()
{
    if (firstRun()) {
        m_index = model().variableIndex(m_name);
        if (const core::Variable* variable = model().variable(m_name))
            m_removed = *variable;
    }
    return model().removeVariable(m_name);
}

core::Status RemoveVariableCommand::revert()
{
    return model().addVariable(m_removed, m_index);
}

} // namespace editor
