#pragma once

#include "editor/commands/modelcommand.h"

#include "core/templates/gemma/gemmatemplate.h"

#include <QCoreApplication>

namespace editor {

// "Set F1 to macro-step".
class SetStepTypeCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetStepTypeCommand)

public:
    SetStepTypeCommand(Document& document, const QString& stepId, core::StepType type);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_stepId;
    core::StepType m_type;
    core::StepType m_previous = core::StepType::Simple;
};

} // namespace editor
