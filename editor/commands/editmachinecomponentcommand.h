#pragma once

#include "editor/commands/machinecommand.h"

namespace editor {

// "Edit Clamp": a component's name, wiring, times, contact or conveyor
// changed. Renaming a conveyor renames it in the part sources that feed it.
// Consecutive edits of the same time or count of the same component merge,
// so stepping a spin box undoes as a whole.
class EditMachineComponentCommand : public MachineCommand {
    Q_DECLARE_TR_FUNCTIONS(EditMachineComponentCommand)

public:
    // `field` tells edits apart for merging: a role or parameter key, "name",
    // "contact" or "conveyor".
    EditMachineComponentCommand(Document& document, std::size_t component, core::machine::Component edited,
                                QString field);
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    bool isParameter() const;

    std::size_t m_component;
    QString m_field;
};

} // namespace editor
