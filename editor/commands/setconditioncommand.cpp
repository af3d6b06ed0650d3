#include "editor/commands/setconditioncommand.h"

#include "editor/commands/commandids.h"

#include "core/model.h"

namespace editor {

SetConditionCommand::SetConditionCommand(Document& document, const QString& transitionId,
                                         const QString& condition)
    : ModelCommand(document, tr("Edit condition of %1").arg(transitionId))
    , m_transitionId(toStdString(transitionId))
    , m_condition(toStdString(condition))
{
}

int SetConditionCommand::id() const
{
    return SetConditionId;
}

bool SetConditionCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const SetConditionCommand*>(other); // same id()
    if (next->m_transitionId != m_transitionId)
        return false;
    m_condition = next->m_condition;
    setObsolete(m_condition == m_previous); // typed back to where it started
    return true;
}

core::Status SetConditionCommand::apply()
{
    if (firstRun()) {
        if (const core::Transition* transition = model().transition(m_transitionId))
            m_previous = transition->condition;
    }
    return model().setCondition(m_transitionId, m_condition);
}

core::Status SetConditionCommand::revert()
{
    return model().setCondition(m_transitionId, m_previous);
}

} // namespace editor
