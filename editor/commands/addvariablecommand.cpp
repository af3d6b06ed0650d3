#include "editor/commands/addvariablecommand.h"

#include "editor/commands/commandids.h"

#include <utility>

namespace editor {

AddVariableCommand::AddVariableCommand(Document& document, core::Variable variable, int index)
    : ModelCommand(document, [=] { return tr("Add variable %1").arg(toQString(variable.name)); })
    , m_variable(std::move(variable))
    , m_index(index)
{
}

int AddVariableCommand::id() const
{
    return AddVariableId;
}

core::Status AddVariableCommand::apply()
{
    return model().addVariable(m_variable, m_index);
}

core::Status AddVariableCommand::revert()
{
    return model().removeVariable(m_variable.name);
}

} // namespace editor
