#include "editor/commands/setreceptivitycommand.h"

#include "editor/commands/commandids.h"

#include "core/model/model.h"

namespace editor {

SetReceptivityCommand::SetReceptivityCommand(
    Document& document, const QString& stepId, int transition, const QString& receptivity)
    //: %1 is the GEMMA step, %2 the transition number of its nested GRAFCET: "Set receptivity of F1 T3"
    : GrafcetTextCommand(
        document, [=] { return tr("Set receptivity of %1 T%2").arg(stepId).arg(transition); }, stepId, transition,
        receptivity)
{
}

int SetReceptivityCommand::id() const
{
    return SetReceptivityId;
}

std::string SetReceptivityCommand::read(const std::string& stepId, int number) const
{
    const core::Grafcet* grafcet = model().grafcet(stepId);
    const core::GrafcetTransition* transition = grafcet ? grafcet->transition(number) : nullptr;
    return transition ? transition->receptivity : std::string();
}

core::Status SetReceptivityCommand::write(const std::string& stepId, int number, const std::string& value)
{
    return model().setReceptivity(stepId, number, value);
}

} // namespace editor
