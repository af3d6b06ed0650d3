#include "editor/commands/setmodelnamecommand.h"

#include "editor/commands/commandids.h"

#include "core/model/model.h"

namespace editor {

SetModelNameCommand::SetModelNameCommand(Document& document, const QString& name)
    : ModelCommand(document, [=] { return tr("Rename model"); })
    , m_name(toStdString(name))
{
}

int SetModelNameCommand::id() const
{
    return SetModelNameId;
}

bool SetModelNameCommand::mergeWith(const QUndoCommand* other)
{
    m_name = static_cast<const SetModelNameCommand*>(other)->m_name; // same id()
    setObsolete(m_name == m_previous);                                // typed back to where it started
    return true;
}

core::Status SetModelNameCommand::apply()
{
    if (firstRun())
        m_previous = model().settings().name;
    return model().setName(m_name);
}

core::Status SetModelNameCommand::revert()
{
    return model().setName(m_previous);
}

} // namespace editor
