#pragma once

#include "editor/commands/grafcettextcommand.h"

#include <QCoreApplication>

namespace editor {

// "Set receptivity of F1 T3"; typing in the same receptivity merges.
class SetReceptivityCommand : public GrafcetTextCommand {
    Q_DECLARE_TR_FUNCTIONS(SetReceptivityCommand)

public:
    SetReceptivityCommand(Document& document, const QString& stepId, int transition, const QString& receptivity);
    int id() const override;

private:
    std::string read(const std::string& stepId, int number) const override;
    core::Status write(const std::string& stepId, int number, const std::string& value) override;
};

} // namespace editor
