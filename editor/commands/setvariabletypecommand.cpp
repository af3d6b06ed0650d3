#include "editor/commands/setvariabletypecommand.h"

#include "editor/commands/commandids.h"

#include "core/model/model.h"

namespace editor {

SetVariableTypeCommand::SetVariableTypeCommand(Document& document, const QString& name, core::IecType type)
    : ModelCommand(document, [=] { return tr("Set type of %1 to %2").arg(name, toQString(core::iecTypeName(type))); })
    , m_name(toStdString(name))
    , m_type(type)
{
}

int SetVariableTypeCommand::id() const
{
    return SetVariableTypeId;
}

core::Status SetVariableTypeCommand::apply()
{
    if (firstRun()) {
        if (const core::Variable* variable = model().variable(m_name))
            m_previous = variable->type;
    }
    return model().setVariableType(m_name, m_type);
}

core::Status SetVariableTypeCommand::revert()
{
    return model().setVariableType(m_name, m_previous);
}

} // namespace editor
