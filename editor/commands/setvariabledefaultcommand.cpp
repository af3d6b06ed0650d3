#include "editor/commands/setvariabledefaultcommand.h"

#include "editor/commands/commandids.h"

#include "core/model/model.h"

namespace editor {

SetVariableDefaultCommand::SetVariableDefaultCommand(Document& document, const QString& name, const QString& value)
    : TextFieldCommand(
        document, [=] { return tr("Set default of %1").arg(name); }, name, value, NameCase::Ignored)
{
}

int SetVariableDefaultCommand::id() const
{
    return SetVariableDefaultId;
}

std::string SetVariableDefaultCommand::read(const std::string& element) const
{
    const core::Variable* variable = model().variable(element);
    return variable ? variable->defaultValue : std::string();
}

core::Status SetVariableDefaultCommand::write(const std::string& element, const std::string& value)
{
    return model().setVariableDefault(element, value);
}

} // namespace editor
