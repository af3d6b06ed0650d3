#pragma once

#include "editor/commands/modelcommand.h"

#include <QCoreApplication>

namespace editor {

// "Make F1 step 3 initial", "Make F1 step 3 not initial": a nested GRAFCET
// may have several initial steps, so this changes that one step alone.
class SetGrafcetStepInitialCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(SetGrafcetStepInitialCommand)

public:
    SetGrafcetStepInitialCommand(Document& document, const QString& stepId, int step, bool initial);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_stepId;
    int m_step;
    bool m_initial;
};

} // namespace editor
