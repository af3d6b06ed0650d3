#pragma once

// The text fields of a PackML command (spec packml.md §2.2): its condition
// and its comment. Typing in the same field of the same command merges.

#include "editor/commands/textfieldcommand.h"

#include <QCoreApplication>

namespace editor {

// "Edit condition of command Hold".
class SetCommandConditionCommand : public TextFieldCommand {
    Q_DECLARE_TR_FUNCTIONS(SetCommandConditionCommand)

public:
    // `command` is the PackTags name ("Hold").
    SetCommandConditionCommand(Document& document, const QString& command, const QString& condition);
    int id() const override;

private:
    std::string read(const std::string& element) const override;
    core::Status write(const std::string& element, const std::string& value) override;
};

// "Edit comment of command Hold".
class SetCommandCommentCommand : public TextFieldCommand {
    Q_DECLARE_TR_FUNCTIONS(SetCommandCommentCommand)

public:
    SetCommandCommentCommand(Document& document, const QString& command, const QString& comment);
    int id() const override;

private:
    std::string read(const std::string& element) const override;
    core::Status write(const std::string& element, const std::string& value) override;
};

} // namespace editor
