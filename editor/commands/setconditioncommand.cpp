#include "editor/commands/setconditioncommand.h"

#include "editor/commands/commandids.h"
#include "editor/text/elementlabels.h"

#include "core/model/model.h"

namespace editor {

SetConditionCommand::SetConditionCommand(Document& document, const QString& transitionId, const QString& condition)
    : TextFieldCommand(
        document, [=] { return tr("Edit condition of %1").arg(transitionLabel(transitionId)); }, transitionId,
        condition)
{
}

int SetConditionCommand::id() const
{
    return SetConditionId;
}

std::string SetConditionCommand::read(const std::string& element) const
{
    const core::Transition* transition = model().transition(element);
    return transition ? transition->condition : std::string();
}

core::Status SetConditionCommand::write(const std::string& element, const std::string& value)
{
    return model().setCondition(element, value);
}

} // namespace editor
