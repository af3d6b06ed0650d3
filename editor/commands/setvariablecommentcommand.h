#pragma once

#include "editor/commands/variabletextcommand.h"

#include <QCoreApplication>

namespace editor {

// "Edit comment of Speed"; typing in the same comment merges.
class SetVariableCommentCommand : public VariableTextCommand {
    Q_DECLARE_TR_FUNCTIONS(SetVariableCommentCommand)

public:
    SetVariableCommentCommand(Document& document, const QString& name, const QString& value);
    int id() const override;

private:
    std::string field(const core::Variable& variable) const override;
    core::Status setField(const std::string& name, const std::string& value) override;
};

} // namespace editor
