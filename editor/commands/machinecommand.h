#pragma once

// The edits of the virtual machine (core/machine/machine.h), each one
// undoable command: the model keeps the description whole
// (Model::setMachine refuses one with structural problems), so a command
// keeps the description before and after its change.

#include "editor/commands/modelcommand.h"

#include "core/machine/machine.h"

#include <QCoreApplication>

namespace editor {

// Applies `after` and restores `before`: the base of the machine's commands.
class MachineCommand : public ModelCommand {
protected:
    MachineCommand(Document& document, Wording wording, core::machine::Machine after);

    const core::machine::Machine& after() const { return m_after; }
    const core::machine::Machine& before() const { return m_before; }
    // A merged edit: the later command's result, from this one's start.
    void setAfter(core::machine::Machine after) { m_after = std::move(after); }

private:
    core::Status apply() override;
    core::Status revert() override;

    core::machine::Machine m_after;
    core::machine::Machine m_before;
};

} // namespace editor
