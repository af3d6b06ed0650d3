#pragma once

#include "editor/commands/modelcommand.h"

#include <QCoreApplication>

namespace editor {

// "Edit comment of F1". Consecutive edits of the same step's comment merge
// into one undo step, so typing undoes as a whole.
class SetStepCommentCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetStepCommentCommand)

public:
    SetStepCommentCommand(Document& document, const QString& stepId, const QString& comment);
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_stepId;
    std::string m_comment;
    std::string m_previous;
};

} // namespace editor
