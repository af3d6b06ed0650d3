#include "editor/commands/variabletextcommand.h"

#include "core/model.h"

namespace editor {

VariableTextCommand::VariableTextCommand(Document& document, const QString& text, const QString& name,
                                         const QString& value)
    : ModelCommand(document, text)
    , m_name(toStdString(name))
    , m_value(toStdString(value))
{
}

bool VariableTextCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const VariableTextCommand*>(other); // same id(), so same field
    if (!core::equalsIgnoreCase(next->m_name, m_name))                 // IEC names ignore case
        return false;
    m_value = next->m_value;
    setObsolete(m_value == m_previous); // typed back to where it started
    return true;
}

core::Status VariableTextCommand::apply()
{
    if (firstRun()) {
        if (const core::Variable* variable = model().variable(m_name))
            m_previous = field(*variable);
    }
    return setField(m_name, m_value);
}

core::Status VariableTextCommand::revert()
{
    return setField(m_name, m_previous);
}

} // namespace editor
