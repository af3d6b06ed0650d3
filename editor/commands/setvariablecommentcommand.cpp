#include "editor/commands/setvariablecommentcommand.h"

#include "editor/commands/commandids.h"

#include "core/model.h"

namespace editor {

SetVariableCommentCommand::SetVariableCommentCommand(Document& document, const QString& name,
                                                     const QString& value)
    : ModelCommand(document, tr("Edit comment of %1").arg(name))
    , m_name(toStdString(name))
    , m_value(toStdString(value))
{
}

int SetVariableCommentCommand::id() const
{
    return SetVariableCommentId;
}

bool SetVariableCommentCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const SetVariableCommentCommand*>(other); // same id()
    if (!core::equalsIgnoreCase(next->m_name, m_name)) // IEC names ignore case
        return false;
    m_value = next->m_value;
    setObsolete(m_value == m_previous); // typed back to where it started
    return true;
}

core::Status SetVariableCommentCommand::apply()
{
    if (firstRun()) {
        if (const core::Variable* variable = model().variable(m_name))
            m_previous = variable->comment;
    }
    return model().setVariableComment(m_name, m_value);
}

core::Status SetVariableCommentCommand::revert()
{
    return model().setVariableComment(m_name, m_previous);
}

} // namespace editor
