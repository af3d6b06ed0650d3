#include "editor/commands/editmachinecomponentcommand.h"

#include "editor/commands/commandids.h"
#include "editor/document.h"

#include "core/model/iectypes.h"

namespace editor {

namespace {

core::machine::Machine withEdit(const Document& document, std::size_t component, core::machine::Component edited)
{
    core::machine::Machine machine = document.model().machine();
    if (component >= machine.components.size())
        return machine;
    const std::string previousName = machine.components[component].name;
    if (edited.kind == core::machine::ComponentKind::Conveyor && edited.name != previousName) {
        for (core::machine::Component& source : machine.components) {
            if (!source.conveyor.empty() && core::equalsIgnoreCase(source.conveyor, previousName))
                source.conveyor = edited.name;
        }
    }
    machine.components[component] = std::move(edited);
    return machine;
}

} // namespace

EditMachineComponentCommand::EditMachineComponentCommand(Document& document, std::size_t component,
                                                         core::machine::Component edited, QString field)
    : MachineCommand(document, [name = toQString(edited.name)] { return tr("Edit %1").arg(name); },
                     withEdit(document, component, edited))
    , m_component(component)
    , m_field(std::move(field))
{
}

// Only a time or a count steps through values; a name, a wiring or a
// contact is chosen once, each choice its own step of Undo.
bool EditMachineComponentCommand::isParameter() const
{
    if (m_component >= after().components.size())
        return false;
    for (const core::machine::ParameterSpec& parameter :
         core::machine::kindSpec(after().components[m_component].kind).parameters) {
        if (toQString(parameter.key) == m_field)
            return true;
    }
    return false;
}

int EditMachineComponentCommand::id() const
{
    return EditMachineComponentId;
}

bool EditMachineComponentCommand::mergeWith(const QUndoCommand* other)
{
    const auto* edit = static_cast<const EditMachineComponentCommand*>(other); // same id()
    if (edit->m_component != m_component || edit->m_field != m_field || !isParameter())
        return false;
    setAfter(edit->after());
    setObsolete(after() == before()); // stepped back to where it started
    return true;
}

} // namespace editor
