#pragma once

#include "editor/commands/modelcommand.h"

#include <QCoreApplication>

namespace editor {

// "Renumber F1 step 3 to 7": the transitions and the X3 and t/X3 of the
// GRAFCET's texts follow (core::Grafcet::renumberStep); undo numbers it back.
class RenumberGrafcetStepCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(RenumberGrafcetStepCommand)

public:
    RenumberGrafcetStepCommand(Document& document, const QString& stepId, int step, int newNumber);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    std::string m_stepId;
    int m_step;
    int m_newNumber;
};

} // namespace editor
