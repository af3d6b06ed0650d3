#include "core/formats/nativemachinejson.h"

#include "core/formats/jsonreader.h"
#include "core/formats/nativeformat.h"
#include "core/model/iectypes.h"

#include <algorithm>
#include <set>
#include <vector>

using nlohmann::ordered_json;

namespace core {

namespace {

using namespace core::machine;

std::string quotedList(const std::vector<std::string_view>& words)
{
    std::string text;
    for (std::size_t i = 0; i < words.size(); ++i) {
        if (i > 0)
            text += i + 1 == words.size() ? " and " : ", ";
        text += "\"" + std::string(words[i]) + "\"";
    }
    return text;
}

std::vector<std::string_view> knownKeys(const ComponentKindSpec& spec)
{
    std::vector<std::string_view> keys{"name", "kind"};
    for (const RoleSpec& role : spec.roles)
        keys.push_back(role.key);
    for (const ParameterSpec& parameter : spec.parameters)
        keys.push_back(parameter.key);
    if (spec.hasContact)
        keys.push_back("contact");
    if (spec.feedsConveyor)
        keys.push_back("conveyor");
    return keys;
}

std::string kindList()
{
    std::vector<std::string_view> names;
    for (ComponentKind kind : allComponentKinds())
        names.push_back(componentKindName(kind));
    return quotedList(names);
}

ComponentKind readKind(const ordered_json& object, const std::string& path)
{
    const ordered_json* value = findMember(object, "kind");
    if (!value)
        failAt(path + "/kind", "missing; a component needs its kind, one of " + kindList());
    const std::string name = readString(*value, path + "/kind");
    ComponentKind kind{};
    if (!parseComponentKind(name, kind))
        failAt(path + "/kind", "unknown component kind \"" + name + "\"; expected " + kindList());
    return kind;
}

void checkKeys(const ordered_json& object, const std::string& path, const ComponentKindSpec& spec)
{
    const std::vector<std::string_view> keys = knownKeys(spec);
    for (const auto& [key, value] : object.items()) {
        if (std::find(keys.begin(), keys.end(), key) == keys.end())
            failAt(childPath(path, key), "unknown key \"" + key + "\" in a " + std::string(componentKindName(spec.kind))
                                             + "; it knows " + quotedList(keys));
    }
}

std::int64_t readParameter(const ordered_json& value, const std::string& path, ParameterKind kind)
{
    if (kind == ParameterKind::PartCount)
        return readInteger(value, path, 0, kMaxParts);
    // A zero travel time reads, so that the checks can name it (GG606); a
    // negative one is no time at all.
    return readInteger(value, path, 0, kMaxMachineTimeMs);
}

Component readComponent(const ordered_json& value, const std::string& path, bool strictKeys)
{
    const ordered_json& object = expectObject(value, path);
    const ComponentKind kind = readKind(object, path);
    const ComponentKindSpec& spec = kindSpec(kind);
    if (strictKeys)
        checkKeys(object, path, spec);
    const ordered_json* name = findMember(object, "name");
    if (!name)
        failAt(path + "/name", "missing; every component has a name");
    Component component = makeComponent(kind, readString(*name, path + "/name"));
    if (component.name.empty())
        failAt(path + "/name", "empty; every component has a name");
    for (std::size_t i = 0; i < spec.roles.size(); ++i) {
        if (const ordered_json* variable = findMember(object, spec.roles[i].key))
            component.wires[i] = readString(*variable, childPath(path, spec.roles[i].key));
    }
    for (std::size_t i = 0; i < spec.parameters.size(); ++i) {
        if (const ordered_json* parameter = findMember(object, spec.parameters[i].key))
            component.parameters[i] =
                readParameter(*parameter, childPath(path, spec.parameters[i].key), spec.parameters[i].kind);
    }
    if (const ordered_json* contact = findMember(object, "contact"); contact && spec.hasContact) {
        const std::string text = readString(*contact, path + "/contact");
        if (!parseContact(text, component.contact))
            failAt(path + "/contact", "unknown contact \"" + text + "\"; expected \"normally-open\" or "
                                      "\"normally-closed\"");
    }
    if (const ordered_json* conveyor = findMember(object, "conveyor"); conveyor && spec.feedsConveyor)
        component.conveyor = readString(*conveyor, path + "/conveyor");
    return component;
}

} // namespace

ordered_json nativeMachineJson(const machine::Machine& machine)
{
    ordered_json components = ordered_json::array();
    for (const Component& component : machine.components) {
        const ComponentKindSpec& spec = kindSpec(component.kind);
        ordered_json object;
        object["name"] = component.name;
        object["kind"] = componentKindName(component.kind);
        for (std::size_t i = 0; i < spec.roles.size() && i < component.wires.size(); ++i) {
            if (!component.wires[i].empty())
                object[std::string(spec.roles[i].key)] = component.wires[i];
        }
        for (std::size_t i = 0; i < spec.parameters.size() && i < component.parameters.size(); ++i) {
            if (spec.parameters[i].kind != ParameterKind::PartCount || component.parameters[i] != kUnlimitedParts)
                object[std::string(spec.parameters[i].key)] = component.parameters[i];
        }
        if (spec.hasContact)
            object["contact"] = contactName(component.contact);
        if (spec.feedsConveyor)
            object["conveyor"] = component.conveyor;
        components.push_back(std::move(object));
    }
    ordered_json root;
    root["components"] = std::move(components);
    return root;
}

machine::Machine readNativeMachine(const ordered_json& value, const std::string& path, NativeVersion version)
{
    const bool strictKeys = version.minor <= kNativeFormatMinor;
    const ordered_json& object = expectObject(value, path);
    if (strictKeys) {
        for (const auto& [key, member] : object.items()) {
            if (key != "components")
                failAt(childPath(path, key), "unknown key \"" + key + "\" in the machine; it knows \"components\"");
        }
    }
    machine::Machine machine;
    const ordered_json* components = findMember(object, "components");
    if (!components)
        return machine;
    const ordered_json& list = expectArray(*components, path + "/components");
    if (list.size() > kMaxGrafcetElements)
        failAt(path + "/components", std::to_string(list.size()) + " components; a machine holds at most "
                                         + std::to_string(kMaxGrafcetElements));
    std::set<std::string> upperNames;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string componentPath = childPath(path + "/components", i);
        Component component = readComponent(list[i], componentPath, strictKeys);
        if (!upperNames.insert(toUpperAscii(component.name)).second)
            failAt(componentPath + "/name", "a second component named \"" + component.name
                                                + "\"; component names are unique (ignoring case)");
        machine.components.push_back(std::move(component));
    }
    return machine;
}

} // namespace core
