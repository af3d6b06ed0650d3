#include "editor/commands/setvariabledefaultcommand.h"

#include "editor/commands/commandids.h"

#include "core/model.h"

namespace editor {

SetVariableDefaultCommand::SetVariableDefaultCommand(Document& document, const QString& name,
                                                     const QString& value)
    : ModelCommand(document, tr("Set default of %1").arg(name))
    , m_name(toStdString(name))
    , m_value(toStdString(value))
{
}

int SetVariableDefaultCommand::id() const
{
    return SetVariableDefaultId;
}

bool SetVariableDefaultCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const SetVariableDefaultCommand*>(other); // same id()
    if (!core::equalsIgnoreCase(next->m_name, m_name)) // IEC names ignore case
        return false;
    m_value = next->m_value;
    setObsolete(m_value == m_previous); // typed back to where it started
    return true;
}

core::Status SetVariableDefaultCommand::apply()
{
    if (firstRun()) {
        if (const core::Variable* variable = model().variable(m_name))
            m_previous = variable->defaultValue;
    }
    return model().setVariableDefault(m_name, m_value);
}

core::Status SetVariableDefaultCommand::revert()
{
    return model().setVariableDefault(m_name, m_previous);
}

} // namespace editor
