#include "editor/commands/setstephiddencommand.h"

#include "editor/commands/commandids.h"
#include "editor/commands/initialsteprule.h"

#include "core/model/model.h"

namespace editor {

SetStepHiddenCommand::SetStepHiddenCommand(Document& document, const QString& stepId, bool hidden)
    : ModelCommand(document, [=] { return hidden ? tr("Hide step %1").arg(stepId) : tr("Show step %1").arg(stepId); })
    , m_stepId(toStdString(stepId))
    , m_hidden(hidden)
{
}

int SetStepHiddenCommand::id() const
{
    return SetStepHiddenId;
}

// A first run that finds the step already so changes nothing and is dropped,
// so the inverse is always the opposite flag.
core::Status SetStepHiddenCommand::apply()
{
    if (firstRun() && m_hidden) {
        if (const QString refusal = InitialStepRule::hidingRefusal(model(), toQString(m_stepId)); !refusal.isEmpty())
            return core::Status::failure("initial-step-hidden", toStdString(refusal));
    }
    return model().setStepHidden(m_stepId, m_hidden);
}

core::Status SetStepHiddenCommand::revert()
{
    return model().setStepHidden(m_stepId, !m_hidden);
}

} // namespace editor
