#include "editor/commands/setprioritycommand.h"

#include "editor/commands/commandids.h"
#include "editor/text/elementlabels.h"

#include "core/model/model.h"

namespace editor {

SetPriorityCommand::SetPriorityCommand(Document& document, const QString& transitionId, int priority)
    : ModelCommand(
        document, [=] { return tr("Set priority of %1 to %2").arg(transitionLabel(transitionId)).arg(priority); })
    , m_transitionId(toStdString(transitionId))
    , m_priority(priority)
{
}

int SetPriorityCommand::id() const
{
    return SetPriorityId;
}

core::Status SetPriorityCommand::apply()
{
    if (firstRun()) {
        if (const core::Transition* transition = model().transition(m_transitionId)) {
            for (const core::Transition* sibling : model().outgoing(transition->source))
                m_previousOrder.push_back(sibling->id);
        }
    }
    return model().setPriority(m_transitionId, m_priority);
}

core::Status SetPriorityCommand::revert()
{
    // Placing each transition at its old position in turn, first to last,
    // leaves positions 1..k right after step k.
    int order = 0;
    for (const std::string& id : m_previousOrder) {
        core::Status status = model().setOrder(id, ++order);
        if (!status)
            return status;
    }
    return core::Status::success();
}

} // namespace editor
