#pragma once

#include "editor/commands/modelcommand.h"

#include <QCoreApplication>

namespace editor {

// "Make A1 the initial step"; undo makes the previous initial step initial again.
class SetInitialStepCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetInitialStepCommand)

public:
    SetInitialStepCommand(Document& document, const QString& stepId);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_stepId;
    std::string m_previous;
};

} // namespace editor
