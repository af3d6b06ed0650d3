#include "editor/commands/setgrafcetstepcommentcommand.h"

#include "editor/commands/commandids.h"

#include "core/model/model.h"

namespace editor {

SetGrafcetStepCommentCommand::SetGrafcetStepCommentCommand(
    Document& document, const QString& stepId, int step, const QString& comment)
    //: %1 is the GEMMA step, %2 a step number of its nested GRAFCET: "Edit comment of F1 step 3"
    : GrafcetTextCommand(
        document, [=] { return tr("Edit comment of %1 step %2").arg(stepId).arg(step); }, stepId, step, comment)
{
}

int SetGrafcetStepCommentCommand::id() const
{
    return SetGrafcetStepCommentId;
}

std::string SetGrafcetStepCommentCommand::read(const std::string& stepId, int number) const
{
    const core::Grafcet* grafcet = model().grafcet(stepId);
    const core::GrafcetStep* step = grafcet ? grafcet->step(number) : nullptr;
    return step ? step->comment : std::string();
}

core::Status SetGrafcetStepCommentCommand::write(const std::string& stepId, int number, const std::string& value)
{
    return model().setGrafcetStepComment(stepId, number, value);
}

} // namespace editor
