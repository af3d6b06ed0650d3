#pragma once

#include "editor/commands/machinecommand.h"

namespace editor {

// "Add cylinder Clamp": a component at the end of the machine (the
// machine's first makes the Machine tab appear).
class AddMachineComponentCommand : public MachineCommand {
    Q_DECLARE_TR_FUNCTIONS(AddMachineComponentCommand)

public:
    AddMachineComponentCommand(Document& document, core::machine::Component component);
    int id() const override;
};

} // namespace editor
