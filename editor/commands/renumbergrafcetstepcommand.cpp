#include "editor/commands/renumbergrafcetstepcommand.h"

#include "editor/commands/commandids.h"

#include "core/model/model.h"

namespace editor {

RenumberGrafcetStepCommand::RenumberGrafcetStepCommand(
    Document& document, const QString& stepId, int step, int newNumber)
    //: %1 is the GEMMA step, %2 a step number of its nested GRAFCET, %3 its new number
    : ModelCommand(document, [=] { return tr("Renumber %1 step %2 to %3").arg(stepId).arg(step).arg(newNumber); })
    , m_stepId(toStdString(stepId))
    , m_step(step)
    , m_newNumber(newNumber)
{
}

int RenumberGrafcetStepCommand::id() const
{
    return RenumberGrafcetStepId;
}

core::Status RenumberGrafcetStepCommand::apply()
{
    return model().renumberGrafcetStep(m_stepId, m_step, m_newNumber);
}

core::Status RenumberGrafcetStepCommand::revert()
{
    return model().renumberGrafcetStep(m_stepId, m_newNumber, m_step);
}

} // namespace editor
