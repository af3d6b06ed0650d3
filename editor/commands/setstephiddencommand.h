#pragma once

#include "editor/commands/modelcommand.h"

#include <QCoreApplication>

namespace editor {

// "Hide step F2" / "Show step F2".
class SetStepHiddenCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetStepHiddenCommand)

public:
    SetStepHiddenCommand(Document& document, const QString& stepId, bool hidden);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_stepId;
    bool m_hidden;
};

} // namespace editor
