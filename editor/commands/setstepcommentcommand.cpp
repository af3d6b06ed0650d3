#include "editor/commands/setstepcommentcommand.h"

#include "editor/commands/commandids.h"

#include "core/model.h"

namespace editor {

SetStepCommentCommand::SetStepCommentCommand(Document& document, const QString& stepId, const QString& comment)
    : ModelCommand(document, tr("Edit comment of %1").arg(stepId))
    , m_stepId(toStdString(stepId))
    , m_comment(toStdString(comment))
{
}

int SetStepCommentCommand::id() const
{
    return SetStepCommentId;
}

bool SetStepCommentCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const SetStepCommentCommand*>(other); // same id()
    if (next->m_stepId != m_stepId)
        return false;
    m_comment = next->m_comment;
    setObsolete(m_comment == m_previous); // typed back to where it started
    return true;
}

core::Status SetStepCommentCommand::apply()
{
    if (firstRun()) {
        if (const core::Step* step = model().step(m_stepId))
            m_previous = step->comment;
    }
    return model().setStepComment(m_stepId, m_comment);
}

core::Status SetStepCommentCommand::revert()
{
    return model().setStepComment(m_stepId, m_previous);
}

} // namespace editor
