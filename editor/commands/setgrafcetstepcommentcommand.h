#pragma once

#include "editor/commands/grafcettextcommand.h"

#include <QCoreApplication>

namespace editor {

// "Edit comment of F1 step 3"; typing in the same comment merges.
class SetGrafcetStepCommentCommand : public GrafcetTextCommand {
    Q_DECLARE_TR_FUNCTIONS(SetGrafcetStepCommentCommand)

public:
    SetGrafcetStepCommentCommand(Document& document, const QString& stepId, int step, const QString& comment);
    int id() const override;

private:
    std::string read(const std::string& stepId, int number) const override;
    core::Status write(const std::string& stepId, int number, const std::string& value) override;
};

} // namespace editor
