#pragma once

#include "editor/commands/textfieldcommand.h"

#include <QCoreApplication>

namespace editor {

// "Edit comment of F1"; typing in the same comment merges.
class SetStepCommentCommand : public TextFieldCommand {
    Q_DECLARE_TR_FUNCTIONS(SetStepCommentCommand)

public:
    SetStepCommentCommand(Document& document, const QString& stepId, const QString& comment);
    int id() const override;

private:
    std::string read(const std::string& element) const override;
    core::Status write(const std::string& element, const std::string& value) override;
};

} // namespace editor
