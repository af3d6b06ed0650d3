#pragma once

#include "editor/commands/textfieldcommand.h"

#include <QCoreApplication>

namespace editor {

// "Edit condition of F1->A2"; typing in the same condition merges.
class SetConditionCommand : public TextFieldCommand {
    Q_DECLARE_TR_FUNCTIONS(SetConditionCommand)

public:
    SetConditionCommand(Document& document, const QString& transitionId, const QString& condition);
    int id() const override;

private:
    std::string read(const std::string& element) const override;
    core::Status write(const std::string& element, const std::string& value) override;
};

} // namespace editor
