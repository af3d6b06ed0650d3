#include "editor/commands/setvariablecommentcommand.h"

#include "editor/commands/commandids.h"

#include "core/model/model.h"

namespace editor {

SetVariableCommentCommand::SetVariableCommentCommand(Document& document, const QString& name, const QString& value)
    : TextFieldCommand(
        document, [=] { return tr("Edit comment of %1").arg(name); }, name, value, NameCase::Ignored)
{
}

int SetVariableCommentCommand::id() const
{
    return SetVariableCommentId;
}

std::string SetVariableCommentCommand::read(const std::string& element) const
{
    const core::Variable* variable = model().variable(element);
    return variable ? variable->comment : std::string();
}

core::Status SetVariableCommentCommand::write(const std::string& element, const std::string& value)
{
    return model().setVariableComment(element, value);
}

} // namespace editor
