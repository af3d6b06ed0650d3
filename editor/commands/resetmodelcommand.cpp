#include "editor/commands/resetmodelcommand.h"

#include "editor/commands/commandids.h"

namespace editor {

ResetModelCommand::ResetModelCommand(Document& document)
    : ModelCommand(document, [=] { return tr("Reset to template"); })
{
}

int ResetModelCommand::id() const
{
    return ResetModelId;
}

core::Status ResetModelCommand::apply()
{
    if (firstRun()) {
        m_snapshot = std::make_unique<core::Model>(model());
        m_snapshot->resetToTemplate();
        if (model().sameContent(*m_snapshot))
            return core::Status::success(); // already the template: nothing to undo
        m_snapshot = std::make_unique<core::Model>(model());
    }
    model().resetToTemplate();
    return core::Status::success();
}

core::Status ResetModelCommand::revert()
{
    model().assign(*m_snapshot);
    return core::Status::success();
}

} // namespace editor
