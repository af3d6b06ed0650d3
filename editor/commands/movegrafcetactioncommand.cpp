#include "editor/commands/movegrafcetactioncommand.h"

#include "editor/commands/commandids.h"

#include "core/model/model.h"

namespace editor {

namespace {

QString commandText(const QString& stepId, int step, int from, int to)
{
    //: %1 is the action's place in the list (from 1), %2 the GEMMA step, %3 the nested step number
    return (to < from ? MoveGrafcetActionCommand::tr("Move action %1 of %2 step %3 up")
                      : MoveGrafcetActionCommand::tr("Move action %1 of %2 step %3 down"))
        .arg(from + 1)
        .arg(stepId)
        .arg(step);
}

} // namespace

MoveGrafcetActionCommand::MoveGrafcetActionCommand(
    Document& document, const QString& stepId, int step, int from, int to)
    : ModelCommand(document, [=] { return commandText(stepId, step, from, to); })
    , m_stepId(toStdString(stepId))
    , m_step(step)
    , m_from(from)
    , m_to(to)
{
}

int MoveGrafcetActionCommand::id() const
{
    return MoveGrafcetActionId;
}

core::Status MoveGrafcetActionCommand::apply()
{
    return model().moveGrafcetAction(m_stepId, m_step, m_from, m_to);
}

core::Status MoveGrafcetActionCommand::revert()
{
    return model().moveGrafcetAction(m_stepId, m_step, m_to, m_from);
}

} // namespace editor
