#include "core/formats/modelloading.h"

#include "core/formats/jsonreader.h"

#include <algorithm>
#include <map>

namespace core {

void require(const Status& status, const std::string& path)
{
    if (!status)
        failAt(path, status.message);
}

void applyInitialFlags(Model& model, const std::vector<InitialFlag>& flags, const std::string& stepsPath)
{
    const InitialFlag* chosen = nullptr;
    bool currentCleared = false;
    const std::string current = model.initialStep().id;
    for (const InitialFlag& flag : flags) {
        if (flag.initial) {
            if (chosen)
                failAt(flag.path, "a second initial step (" + chosen->stepId + " is initial too); exactly one step must be initial");
            chosen = &flag;
        } else if (flag.stepId == current) {
            currentCleared = true;
        }
    }
    if (chosen)
        require(model.setInitialStep(chosen->stepId), chosen->path);
    else if (currentCleared)
        failAt(stepsPath, "no initial step; exactly one step must be initial");
}

void applyOrders(Model& model, const std::vector<OrderValue>& orders)
{
    std::map<std::string, const OrderValue*> given;
    for (const OrderValue& value : orders)
        given[value.transitionId] = &value;

    std::vector<std::string> sources;
    for (const OrderValue& value : orders) {
        const Transition* transition = model.transition(value.transitionId);
        if (transition && std::find(sources.begin(), sources.end(), transition->source) == sources.end())
            sources.push_back(transition->source);
    }

    for (const std::string& source : sources) {
        const std::vector<const Transition*> outgoing = model.outgoing(source);
        // order -> transition id, checking each order is taken once.
        std::map<int, std::string> byOrder;
        for (const Transition* transition : outgoing) {
            const auto found = given.find(transition->id);
            const int order = found != given.end() ? found->second->order : transition->order;
            auto [slot, inserted] = byOrder.emplace(order, transition->id);
            if (inserted)
                continue;
            // Report at a value the file gave (a default cannot be wrong alone).
            const bool thisGiven = found != given.end();
            const OrderValue* culprit = thisGiven ? found->second : given.at(slot->second);
            const std::string other = thisGiven ? slot->second : transition->id;
            failAt(culprit->path, "order " + std::to_string(order) + " is also the order of " + other + "; the "
                + std::to_string(outgoing.size()) + " transitions leaving " + describeSource(source)
                + " need the orders 1 to " + std::to_string(outgoing.size()) + ", each once");
        }
        // Placing them 1, 2, ... in turn leaves the earlier places untouched.
        for (const auto& [order, id] : byOrder) {
            const auto found = given.find(id);
            require(model.setOrder(id, order), found != given.end() ? found->second->path : std::string());
        }
    }
}

void addVariables(Model& model, const std::vector<VariableEntry>& variables, const std::string& listPath)
{
    if (variables.size() > kMaxFileVariables)
        failAt(listPath, std::to_string(variables.size()) + " variables; a model holds at most "
            + std::to_string(kMaxFileVariables));
    std::map<std::string, const VariableEntry*> byUpperName;
    for (const VariableEntry& entry : variables) {
        const std::string& name = entry.variable.name;
        if (name.empty())
            failAt(entry.namePath, "empty variable name");
        const auto [slot, inserted] = byUpperName.emplace(toUpperAscii(name), &entry);
        if (!inserted) {
            const VariableEntry& earlier = *slot->second;
            failAt(entry.namePath, "duplicate variable name \"" + name + "\": " + earlier.namePath
                + " is \"" + earlier.variable.name + "\" (names are compared ignoring case)");
        }
        require(model.addVariable(entry.variable), entry.namePath);
    }
}

std::string describeSource(std::string_view source)
{
    if (source == kFamilySource)
        return "the F family frame";
    return std::string(source);
}

VariableEntry readVariableNameAndType(const nlohmann::ordered_json& object, const std::string& path,
                                      const VariableEntrySpelling& spelling)
{
    VariableEntry entry;
    entry.namePath = path + "/name";
    const nlohmann::ordered_json* name = findMember(object, "name");
    if (!name)
        failAt(entry.namePath, std::string("missing; every ") + spelling.noun + " needs a name");
    entry.variable.name = readString(*name, entry.namePath);
    const nlohmann::ordered_json* type = findMember(object, "type");
    if (!type)
        failAt(path + "/type", std::string("missing; expected ") + spelling.typeExample);
    const std::string typeName = readString(*type, path + "/type");
    const auto parsed = parseIecType(typeName);
    if (!parsed)
        failAt(path + "/type", "unknown type \"" + typeName + "\"; expected " + spelling.typeList);
    entry.variable.type = *parsed;
    return entry;
}

} // namespace core
