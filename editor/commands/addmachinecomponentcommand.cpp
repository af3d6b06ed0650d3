#include "editor/commands/addmachinecomponentcommand.h"

#include "editor/commands/commandids.h"
#include "editor/document.h"
#include "editor/machine/machinetext.h"

namespace editor {

namespace {

core::machine::Machine withComponent(const Document& document, core::machine::Component component)
{
    core::machine::Machine machine = document.model().machine();
    machine.components.push_back(std::move(component));
    return machine;
}

} // namespace

AddMachineComponentCommand::AddMachineComponentCommand(Document& document, core::machine::Component component)
    : MachineCommand(document,
                     [kind = component.kind, name = toQString(component.name)] {
                         //: %1: a kind of machine component ("Conveyor"); %2: its name
                         return tr("Add %1 %2").arg(machinetext::kindName(kind), name);
                     },
                     withComponent(document, component))
{
}

int AddMachineComponentCommand::id() const
{
    return AddMachineComponentId;
}

} // namespace editor
