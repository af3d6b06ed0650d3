#include "editor/commands/machinecommand.h"

#include "core/model/model.h"

namespace editor {

MachineCommand::MachineCommand(Document& document, Wording wording, core::machine::Machine after)
    : ModelCommand(document, std::move(wording))
    , m_after(std::move(after))
{
}

core::Status MachineCommand::apply()
{
    if (firstRun())
        m_before = model().machine();
    if (m_after == model().machine())
        return core::Status::success();
    return model().setMachine(m_after);
}

core::Status MachineCommand::revert()
{
    return model().setMachine(m_before);
}

} // namespace editor
