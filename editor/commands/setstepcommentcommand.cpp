#include "editor/commands/setstepcommentcommand.h"

#include "editor/commands/commandids.h"

#include "core/model/model.h"

namespace editor {

SetStepCommentCommand::SetStepCommentCommand(Document& document, const QString& stepId, const QString& comment)
    : TextFieldCommand(
        document, [=] { return tr("Edit comment of %1").arg(stepId); }, stepId, comment)
{
}

int SetStepCommentCommand::id() const
{
    return SetStepCommentId;
}

std::string SetStepCommentCommand::read(const std::string& element) const
{
    const core::Step* step = model().step(element);
    return step ? step->comment : std::string();
}

core::Status SetStepCommentCommand::write(const std::string& element, const std::string& value)
{
    return model().setStepComment(element, value);
}

} // namespace editor
