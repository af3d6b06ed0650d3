#pragma once

#include "editor/commands/modelcommand.h"

#include <QCoreApplication>

namespace editor {

// "Add mode 4 Cleaning": a unit mode with the defaults of a new one (spec
// packml.md §3.1). A user mode (4..31) needs a name modeNameProblem()
// accepts; a base mode (1..3) takes none. Refused for a number outside
// 1..31 or one the model has.
class AddModeCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(AddModeCommand)

public:
    AddModeCommand(Document& document, int mode, const QString& name = {});
    int id() const override;

    // The lowest user mode number (4..31) the model does not have; 0 when all are taken.
    static int firstFreeUserMode(const core::Model& model);
    // A name for a new user mode that modeNameProblem() accepts: "Mode4".
    static QString suggestedName(const core::Model& model, int mode);

private:
    core::Status apply() override;
    core::Status revert() override;

    int m_mode;
    std::string m_name;
};

} // namespace editor
