#pragma once

#include "editor/commands/modelcommand.h"

#include <QCoreApplication>

namespace editor {

// "Edit comment of Speed". Consecutive edits of the same variable's comment merge into one
// undo step, so typing undoes as a whole.
class SetVariableCommentCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetVariableCommentCommand)

public:
    SetVariableCommentCommand(Document& document, const QString& name, const QString& value);
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_name;
    std::string m_value;
    std::string m_previous;
};

} // namespace editor
