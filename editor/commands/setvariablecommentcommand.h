#pragma once

#include "editor/commands/textfieldcommand.h"

#include <QCoreApplication>

namespace editor {

// "Edit comment of Speed"; typing in the same comment merges.
class SetVariableCommentCommand : public TextFieldCommand {
    Q_DECLARE_TR_FUNCTIONS(SetVariableCommentCommand)

public:
    SetVariableCommentCommand(Document& document, const QString& name, const QString& value);
    int id() const override;

private:
    std::string read(const std::string& element) const override;
    core::Status write(const std::string& element, const std::string& value) override;
};

} // namespace editor
