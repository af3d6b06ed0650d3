#include "editor/commands/setcycletimecommand.h"

#include "editor/commands/commandids.h"

#include "core/model/model.h"

namespace editor {

namespace {

QString describe(int cycleTimeMs)
{
    return SetCycleTimeCommand::tr("Set cycle time to %1 ms").arg(cycleTimeMs);
}

} // namespace

SetCycleTimeCommand::SetCycleTimeCommand(Document& document, int cycleTimeMs)
    : ModelCommand(document, [=] { return describe(cycleTimeMs); })
    , m_cycleTimeMs(cycleTimeMs)
{
}

int SetCycleTimeCommand::id() const
{
    return SetCycleTimeId;
}

bool SetCycleTimeCommand::mergeWith(const QUndoCommand* other)
{
    m_cycleTimeMs = static_cast<const SetCycleTimeCommand*>(other)->m_cycleTimeMs; // same id()
    setText(describe(m_cycleTimeMs));
    setObsolete(m_cycleTimeMs == m_previous); // stepped back to where it started
    return true;
}

core::Status SetCycleTimeCommand::apply()
{
    if (firstRun())
        m_previous = model().settings().cycleTimeMs;
    return model().setCycleTimeMs(m_cycleTimeMs);
}

core::Status SetCycleTimeCommand::revert()
{
    return model().setCycleTimeMs(m_previous);
}

} // namespace editor
