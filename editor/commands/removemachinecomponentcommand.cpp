#include "editor/commands/removemachinecomponentcommand.h"

#include "editor/commands/commandids.h"
#include "editor/document.h"

namespace editor {

namespace {

core::machine::Machine withoutComponent(const Document& document, std::size_t component)
{
    core::machine::Machine machine = document.model().machine();
    if (component < machine.components.size())
        machine.components.erase(machine.components.begin() + static_cast<std::ptrdiff_t>(component));
    return machine;
}

QString nameOf(const Document& document, std::size_t component)
{
    const auto& components = document.model().machine().components;
    return component < components.size() ? toQString(components[component].name) : QString();
}

} // namespace

RemoveMachineComponentCommand::RemoveMachineComponentCommand(Document& document, std::size_t component)
    : MachineCommand(document, [name = nameOf(document, component)] { return tr("Remove %1").arg(name); },
                     withoutComponent(document, component))
{
}

int RemoveMachineComponentCommand::id() const
{
    return RemoveMachineComponentId;
}

} // namespace editor
