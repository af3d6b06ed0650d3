#include "editor/commands/editgrafcetcommand.h"

#include "editor/commands/commandids.h"

#include "core/model/model.h"

#include <utility>

namespace editor {

EditGrafcetCommand::EditGrafcetCommand(Document& document, const QString& stepId, Edit edit, Wording wording)
    : ModelCommand(document, std::move(wording))
    , m_stepId(toStdString(stepId))
    , m_edit(std::move(edit))
{
}

int EditGrafcetCommand::id() const
{
    return EditGrafcetId;
}

core::Status EditGrafcetCommand::apply()
{
    if (firstRun()) {
        const core::Grafcet* current = model().grafcet(m_stepId);
        if (current)
            m_before = *current;
        core::Grafcet edited = current ? *current : core::Grafcet();
        if (core::Status status = m_edit(edited); !status)
            return status;
        m_after = std::move(edited);
        m_edit = nullptr; // what it captured is not needed again
    }
    return model().setGrafcet(m_stepId, m_after);
}

core::Status EditGrafcetCommand::revert()
{
    return m_before ? model().setGrafcet(m_stepId, *m_before) : model().removeGrafcet(m_stepId);
}

} // namespace editor
