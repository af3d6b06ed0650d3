#pragma once

// A model's virtual machine as the user describes it: components wired to
// the model's variables by name (docs/simulation.md, "The virtual machine";
// the native file's "machine" key, docs/file-formats.md). A description only:
// machinestate.h runs it, machinechecks.h checks it against the model.

#include "core/machine/componentkind.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace core::machine {

struct Component {
    std::string name; // unique in the machine (case-insensitively), never empty
    ComponentKind kind = ComponentKind::Lamp;
    // The variable of each role, in kindSpec(kind).roles order, spelled as
    // the user wrote it; empty: not wired.
    std::vector<std::string> wires;
    // Each parameter, in kindSpec(kind).parameters order.
    std::vector<std::int64_t> parameters;
    Contact contact = Contact::NormallyOpen; // operator inputs only
    std::string conveyor;                    // part sources only: the conveyor component it feeds

    // The variable wired to a role, by key; empty when unwired or no such role.
    std::string_view signal(std::string_view roleKey) const;
    // False (and nothing changed) when the kind has no such role or parameter.
    bool setSignal(std::string_view roleKey, std::string variable);
    bool setParameter(std::string_view parameterKey, std::int64_t value);
    std::int64_t parameter(std::string_view parameterKey) const; // 0 when no such parameter

    friend bool operator==(const Component&, const Component&) = default;
};

// A component of the kind with nothing wired and the default parameters
// (an emergency stop is normally closed).
Component makeComponent(ComponentKind kind, std::string name);

struct Machine {
    std::vector<Component> components; // in the user's order

    bool empty() const { return components.empty(); }
    const Component* find(std::string_view name) const; // case-insensitive; nullptr when absent

    // Problems that make the description unusable, whatever the model: an
    // empty or repeated name, signals or parameters not sized to the kind, a
    // conveyor link on a component that is no part source. Empty when none.
    std::vector<std::string> structuralProblems() const;

    // Rewires every signal naming `previous` (case-insensitively) to `newName`;
    // true when one changed.
    bool renameVariable(std::string_view previous, const std::string& newName);

    friend bool operator==(const Machine&, const Machine&) = default;
};

} // namespace core::machine
