#pragma once

// The text fields of a unit mode (spec packml.md §3): a user mode's name, the
// comment and the request condition of any mode. Typing in the same field of
// the same mode merges.

#include "editor/commands/textfieldcommand.h"

#include <QCoreApplication>

namespace editor {

// "Rename mode 4 Cleaning" (the name it had). Refused (never entering the stack) for the
// base modes 1..3 and for a name modeNameProblem() objects to.
class RenameModeCommand : public TextFieldCommand {
    Q_DECLARE_TR_FUNCTIONS(RenameModeCommand)

public:
    RenameModeCommand(Document& document, int mode, const QString& name);
    int id() const override;

private:
    std::string read(const std::string& element) const override;
    core::Status write(const std::string& element, const std::string& value) override;
    core::Status validate(const std::string& element, const std::string& value) const override;
};

// "Edit comment of mode 3 Manual".
class SetModeCommentCommand : public TextFieldCommand {
    Q_DECLARE_TR_FUNCTIONS(SetModeCommentCommand)

public:
    SetModeCommentCommand(Document& document, int mode, const QString& comment);
    int id() const override;

private:
    std::string read(const std::string& element) const override;
    core::Status write(const std::string& element, const std::string& value) override;
};

// "Edit request condition of mode 3 Manual"; empty: no request condition.
class SetModeRequestCommand : public TextFieldCommand {
    Q_DECLARE_TR_FUNCTIONS(SetModeRequestCommand)

public:
    SetModeRequestCommand(Document& document, int mode, const QString& condition);
    int id() const override;

private:
    std::string read(const std::string& element) const override;
    core::Status write(const std::string& element, const std::string& value) override;
};

} // namespace editor
