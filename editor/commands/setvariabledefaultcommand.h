#pragma once

#include "editor/commands/textfieldcommand.h"

#include <QCoreApplication>

namespace editor {

// "Set default of Speed"; typing in the same default merges.
class SetVariableDefaultCommand : public TextFieldCommand {
    Q_DECLARE_TR_FUNCTIONS(SetVariableDefaultCommand)

public:
    SetVariableDefaultCommand(Document& document, const QString& name, const QString& value);
    int id() const override;

private:
    std::string read(const std::string& element) const override;
    core::Status write(const std::string& element, const std::string& value) override;
};

} // namespace editor
