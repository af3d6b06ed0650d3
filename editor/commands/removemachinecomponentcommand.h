#pragma once

#include "editor/commands/machinecommand.h"

namespace editor {

// "Remove Clamp": the component and its wiring; undo puts it back in its place.
class RemoveMachineComponentCommand : public MachineCommand {
    Q_DECLARE_TR_FUNCTIONS(RemoveMachineComponentCommand)

public:
    RemoveMachineComponentCommand(Document& document, std::size_t component);
    int id() const override;
};

} // namespace editor
