#include "editor/commands/setvariablecommentcommand.h"

#include "editor/commands/commandids.h"

#include "core/model.h"

namespace editor {

SetVariableCommentCommand::SetVariableCommentCommand(Document& document, const QString& name,
                                                     const QString& value)
    : VariableTextCommand(document, tr("Edit comment of %1").arg(name), name, value)
{
}

int SetVariableCommentCommand::id() const
{
    return SetVariableCommentId;
}

std::string SetVariableCommentCommand::field(const core::Variable& variable) const
{
    return variable.comment;
}

core::Status SetVariableCommentCommand::setField(const std::string& name, const std::string& value)
{
    return model().setVariableComment(name, value);
}

} // namespace editor
