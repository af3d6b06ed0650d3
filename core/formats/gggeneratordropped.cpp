#include "core/formats/gggeneratordropped.h"

#include "core/formats/jsonreader.h"

#include <string_view>

namespace core {

namespace {

using json = nlohmann::ordered_json;

constexpr std::string_view kNoPlace = "a GG-Generator file has no place for ";

// "F1, F3" for an object's keys; empty for anything else.
std::string memberNames(const json& value)
{
    std::string names;
    if (!value.is_object())
        return names;
    for (const auto& [key, member] : value.items())
        names += (names.empty() ? "" : ", ") + key;
    return names;
}

// " (3)" for an array of three; empty for anything else.
std::string countIn(const json& value)
{
    return value.is_array() ? " (" + std::to_string(value.size()) + ")" : std::string();
}

// What a root key of the GG Studio format holds, and why it is not loaded;
// empty for a key that is not one of GG Studio's.
std::string droppedRootKey(std::string_view key, const json& value)
{
    if (key == "name")
        return "the model name " + describeJsonValue(value) + " is not loaded: " + std::string(kNoPlace) + "it";
    if (key == "steps" || key == "transitions")
        return "GG Studio's \"" + std::string(key) + "\" are not loaded: a GG-Generator file gives them as \""
            + (key == "steps" ? "nodes" : "connections") + "\"";
    if (key == "variables")
        return "GG Studio's \"variables\" are not loaded: a GG-Generator file gives them as \"graph.data.signals\"";
    if (key == "grafcets") {
        const std::string steps = memberNames(value);
        return "the nested GRAFCETs" + (steps.empty() ? std::string() : " of " + steps) + " are not loaded: "
            + std::string(kNoPlace) + "nested behaviour";
    }
    if (key == "properties")
        return "the verification properties" + countIn(value) + " are not loaded: " + std::string(kNoPlace) + "them";
    return {};
}

void addSettings(std::vector<LoadWarning>& warnings, const json& settings, const std::string& displayName)
{
    if (!settings.is_object() || settings.empty()) {
        warnings.push_back({displayName, "/settings", "the settings are not loaded: " + std::string(kNoPlace) + "them"});
        return;
    }
    for (const auto& [key, value] : settings.items()) {
        warnings.push_back({displayName, childPath("/settings", key),
                            "the setting \"" + key + "\" (" + describeJsonValue(value) + ") is not loaded: "
                                + std::string(kNoPlace) + "settings"});
    }
}

void addSignalKeys(std::vector<LoadWarning>& warnings, const json& root, const std::string& displayName)
{
    const json* graph = findMember(root, "graph");
    const json* data = graph && graph->is_object() ? findMember(*graph, "data") : nullptr;
    const json* signals = data && data->is_object() ? findMember(*data, "signals") : nullptr;
    if (!signals || !signals->is_array())
        return;
    for (std::size_t i = 0; i < signals->size(); ++i) {
        const json& signal = (*signals)[i];
        if (!signal.is_object())
            continue;
        const std::string path = childPath("/graph/data/signals", i);
        if (const json* kind = findMember(signal, "kind")) {
            warnings.push_back({displayName, path + "/kind",
                                "the variable kind " + describeJsonValue(*kind)
                                    + " is not loaded: GG-Generator reads every signal as an input"});
        }
        if (const json* comment = findMember(signal, "comment")) {
            warnings.push_back({displayName, path + "/comment",
                                "the variable comment " + describeJsonValue(*comment) + " is not loaded: "
                                    + std::string(kNoPlace) + "comments"});
        }
    }
}

} // namespace

std::vector<LoadWarning> ggStudioKeysInGGGeneratorFile(const json& root, const std::string& displayName)
{
    std::vector<LoadWarning> warnings;
    if (!root.is_object())
        return warnings;
    for (const auto& [key, value] : root.items()) {
        if (key == "settings") {
            addSettings(warnings, value, displayName);
        } else if (std::string message = droppedRootKey(key, value); !message.empty()) {
            warnings.push_back({displayName, childPath("", key), std::move(message)});
        }
    }
    addSignalKeys(warnings, root, displayName);
    return warnings;
}

} // namespace core
