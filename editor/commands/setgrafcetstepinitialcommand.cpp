#include "editor/commands/setgrafcetstepinitialcommand.h"

#include "editor/commands/commandids.h"

#include "core/model/model.h"

namespace editor {

namespace {

QString commandText(const QString& stepId, int step, bool initial)
{
    //: %1 is the GEMMA step, %2 a step number of its nested GRAFCET
    return initial ? SetGrafcetStepInitialCommand::tr("Make %1 step %2 initial").arg(stepId).arg(step)
                   : SetGrafcetStepInitialCommand::tr("Make %1 step %2 not initial").arg(stepId).arg(step);
}

} // namespace

SetGrafcetStepInitialCommand::SetGrafcetStepInitialCommand(
    Document& document, const QString& stepId, int step, bool initial)
    : ModelCommand(document, [=] { return commandText(stepId, step, initial); })
    , m_stepId(toStdString(stepId))
    , m_step(step)
    , m_initial(initial)
{
}

int SetGrafcetStepInitialCommand::id() const
{
    return SetGrafcetStepInitialId;
}

core::Status SetGrafcetStepInitialCommand::apply()
{
    return model().setGrafcetStepInitial(m_stepId, m_step, m_initial);
}

core::Status SetGrafcetStepInitialCommand::revert()
{
    return model().setGrafcetStepInitial(m_stepId, m_step, !m_initial);
}

} // namespace editor
