#pragma once

#include "editor/commands/variabletextcommand.h"

#include <QCoreApplication>

namespace editor {

// "Set default of Speed"; typing in the same default merges.
class SetVariableDefaultCommand : public VariableTextCommand {
    Q_DECLARE_TR_FUNCTIONS(SetVariableDefaultCommand)

public:
    SetVariableDefaultCommand(Document& document, const QString& name, const QString& value);
    int id() const override;

private:
    std::string field(const core::Variable& variable) const override;
    core::Status setField(const std::string& name, const std::string& value) override;
};

} // namespace editor
