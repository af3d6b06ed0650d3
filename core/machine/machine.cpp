#include "core/machine/machine.h"

#include "core/model/iectypes.h"

#include <algorithm>
#include <set>

namespace core::machine {

namespace {

template <typename Spec>
int indexOf(std::span<const Spec> specs, std::string_view key)
{
    for (std::size_t i = 0; i < specs.size(); ++i) {
        if (specs[i].key == key)
            return static_cast<int>(i);
    }
    return -1;
}

} // namespace

std::string_view Component::signal(std::string_view roleKey) const
{
    const int index = indexOf(kindSpec(kind).roles, roleKey);
    if (index < 0 || static_cast<std::size_t>(index) >= wires.size())
        return {};
    return wires[static_cast<std::size_t>(index)];
}

bool Component::setSignal(std::string_view roleKey, std::string variable)
{
    const int index = indexOf(kindSpec(kind).roles, roleKey);
    if (index < 0 || static_cast<std::size_t>(index) >= wires.size())
        return false;
    wires[static_cast<std::size_t>(index)] = std::move(variable);
    return true;
}

bool Component::setParameter(std::string_view parameterKey, std::int64_t value)
{
    const int index = indexOf(kindSpec(kind).parameters, parameterKey);
    if (index < 0 || static_cast<std::size_t>(index) >= parameters.size())
        return false;
    parameters[static_cast<std::size_t>(index)] = value;
    return true;
}

std::int64_t Component::parameter(std::string_view parameterKey) const
{
    const int index = indexOf(kindSpec(kind).parameters, parameterKey);
    if (index < 0 || static_cast<std::size_t>(index) >= parameters.size())
        return 0;
    return parameters[static_cast<std::size_t>(index)];
}

Component makeComponent(ComponentKind kind, std::string name)
{
    const ComponentKindSpec& spec = kindSpec(kind);
    Component component;
    component.name = std::move(name);
    component.kind = kind;
    component.wires.resize(spec.roles.size());
    for (const ParameterSpec& parameter : spec.parameters)
        component.parameters.push_back(parameter.defaultValue);
    if (kind == ComponentKind::EmergencyStop)
        component.contact = Contact::NormallyClosed;
    return component;
}

const Component* Machine::find(std::string_view name) const
{
    const auto found = std::find_if(components.begin(), components.end(),
                                    [&](const Component& c) { return equalsIgnoreCase(c.name, name); });
    return found == components.end() ? nullptr : &*found;
}

std::vector<std::string> Machine::structuralProblems() const
{
    std::vector<std::string> problems;
    std::set<std::string> upperNames;
    for (const Component& component : components) {
        const ComponentKindSpec& spec = kindSpec(component.kind);
        if (component.name.empty())
            problems.push_back("a machine component has an empty name");
        else if (!upperNames.insert(toUpperAscii(component.name)).second)
            problems.push_back("two machine components are named '" + component.name + "' (ignoring case)");
        if (component.wires.size() != spec.roles.size() || component.parameters.size() != spec.parameters.size())
            problems.push_back("machine component '" + component.name + "' does not have the signals and "
                               "parameters of a " + std::string(componentKindName(component.kind)));
        if (!spec.feedsConveyor && !component.conveyor.empty())
            problems.push_back("machine component '" + component.name + "' names a conveyor but is no part source");
    }
    return problems;
}

bool Machine::renameVariable(std::string_view previous, const std::string& newName)
{
    bool changed = false;
    for (Component& component : components) {
        for (std::string& variable : component.wires) {
            if (!variable.empty() && equalsIgnoreCase(variable, previous)) {
                variable = newName;
                changed = true;
            }
        }
    }
    return changed;
}

} // namespace core::machine
