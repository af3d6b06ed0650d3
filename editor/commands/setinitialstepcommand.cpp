#include "editor/commands/setinitialstepcommand.h"

#include "editor/commands/commandids.h"
#include "editor/commands/initialsteprule.h"

#include "core/model/model.h"

namespace editor {

SetInitialStepCommand::SetInitialStepCommand(Document& document, const QString& stepId)
    : ModelCommand(document, [=] { return tr("Make %1 the initial step").arg(stepId); })
    , m_stepId(toStdString(stepId))
{
}

int SetInitialStepCommand::id() const
{
    return SetInitialStepId;
}

core::Status SetInitialStepCommand::apply()
{
    if (firstRun()) {
        if (const QString refusal = InitialStepRule::initialRefusal(model(), toQString(m_stepId)); !refusal.isEmpty())
            return core::Status::failure("initial-step-hidden", toStdString(refusal));
        m_previous = model().initialStep().id;
    }
    return model().setInitialStep(m_stepId);
}

core::Status SetInitialStepCommand::revert()
{
    return model().setInitialStep(m_previous);
}

} // namespace editor
