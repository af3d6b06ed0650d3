#include "editor/commands/setvariabledefaultcommand.h"

#include "editor/commands/commandids.h"

#include "core/model.h"

namespace editor {

SetVariableDefaultCommand::SetVariableDefaultCommand(Document& document, const QString& name,
                                                     const QString& value)
    : VariableTextCommand(document, tr("Set default of %1").arg(name), name, value)
{
}

int SetVariableDefaultCommand::id() const
{
    return SetVariableDefaultId;
}

std::string SetVariableDefaultCommand::field(const core::Variable& variable) const
{
    return variable.defaultValue;
}

core::Status SetVariableDefaultCommand::setField(const std::string& name, const std::string& value)
{
    return model().setVariableDefault(name, value);
}

} // namespace editor
