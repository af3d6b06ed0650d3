#include "core/formats/nativeformat.h"

#include "core/formats/jsonreader.h"
#include "core/formats/modelloading.h"
#include "core/formats/nativegrafcetjson.h"
#include "core/formats/nativemachinejson.h"
#include "core/formats/nativemodelparts.h"
#include "core/templates/packml/packmlformat.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <initializer_list>
#include <limits>

using json = nlohmann::ordered_json;
using nlohmann::ordered_json;

namespace core {

namespace {

const VariableEntrySpelling kVariableSpelling{
    "variable", "an IEC type such as \"BOOL\"", "BOOL, SINT, INT, DINT, LINT, USINT, UINT, UDINT, ULINT, REAL or LREAL"};

// ---- Writing ---------------------------------------------------------------

std::string_view timingName(ActionTiming timing)
{
    switch (timing) {
    case ActionTiming::OnActivation: return "activation";
    case ActionTiming::OnDeactivation: return "deactivation";
    case ActionTiming::Continuous: break;
    }
    return "continuous";
}

bool parseTiming(std::string_view name, ActionTiming& timing)
{
    for (ActionTiming candidate : {ActionTiming::Continuous, ActionTiming::OnActivation, ActionTiming::OnDeactivation}) {
        if (name == timingName(candidate)) {
            timing = candidate;
            return true;
        }
    }
    return false;
}

ordered_json grafcetJson(const Grafcet& grafcet)
{
    ordered_json steps = ordered_json::array();
    for (const GrafcetStep& step : grafcet.steps()) {
        ordered_json actions = ordered_json::array();
        for (const GrafcetAction& action : step.actions)
            actions.push_back(ordered_json{{"timing", timingName(action.timing)}, {"text", action.text}});
        steps.push_back(ordered_json{{"number", step.number}, {"initial", step.initial}, {"comment", step.comment},
                                     {"actions", std::move(actions)}});
    }
    ordered_json transitions = ordered_json::array();
    for (const GrafcetTransition& t : grafcet.transitions())
        transitions.push_back(ordered_json{{"number", t.number}, {"upstream", t.upstream},
                                           {"downstream", t.downstream}, {"receptivity", t.receptivity}});
    return ordered_json{{"steps", std::move(steps)}, {"transitions", std::move(transitions)}};
}

ordered_json variableJson(const Variable& variable, bool nested)
{
    ordered_json object;
    object["name"] = variable.name;
    object["type"] = iecTypeName(variable.type);
    if (nested)
        object["kind"] = variableKindName(variable.kind);
    object["default"] = variable.defaultValue;
    object["comment"] = variable.comment;
    return object;
}

// ---- Reading ---------------------------------------------------------------

std::string versionText(int major = kNativeFormatMajor)
{
    return std::to_string(major) + "." + std::to_string(kNativeFormatMinor);
}

// A version part: decimal digits only (no sign, no blanks), without leading
// zeros so "1.01" cannot pass for "1.1". Parts too large for an int saturate,
// which still orders them after every real version.
bool parseVersionPart(std::string_view text, int& value)
{
    if (text.empty() || (text.size() > 1 && text.front() == '0'))
        return false;
    long long number = 0;
    for (char c : text) {
        if (c < '0' || c > '9')
            return false;
        number = std::min<long long>(number * 10 + (c - '0'), std::numeric_limits<int>::max());
    }
    value = static_cast<int>(number);
    return true;
}

using FormatVersion = NativeVersion;

FormatVersion readFormatAndVersion(const json& root)
{
    const json* format = findMember(root, "format");
    if (!format)
        failAt("/format", "missing; a GG Studio model file has \"format\": \"" + std::string(kNativeFormatName) + "\"");
    if (!format->is_string() || format->get<std::string>() != kNativeFormatName)
        failAt("/format", "expected \"" + std::string(kNativeFormatName) + "\", found " + describeJsonValue(*format));

    const json* versionValue = findMember(root, "version");
    if (!versionValue)
        failAt("/version", "missing; expected a version such as \"" + versionText(1) + "\"");
    const std::string version = readString(*versionValue, "/version");
    const std::size_t dot = version.find('.');
    FormatVersion parsed;
    if (dot == std::string::npos || !parseVersionPart(std::string_view(version).substr(0, dot), parsed.major)
        || !parseVersionPart(std::string_view(version).substr(dot + 1), parsed.minor))
        failAt("/version", "expected a version MAJOR.MINOR of two whole numbers such as \"" + versionText(1)
            + "\", found " + describeJsonValue(*versionValue));
    return parsed;
}

// Whether a file of this version is a PackML model (spec packml.md §9).
bool isPackMLFile(const json& root, FormatVersion version)
{
    const json* templateValue = findMember(root, "template");
    return version.major == packml::kFormatMajor && templateValue && templateValue->is_string()
        && templateValue->get<std::string>() == packml::kTemplateName;
}

// Refuses the versions a GEMMA model file cannot have (readFormatAndVersion
// has read `parsed` from "/version").
void checkGemmaVersion(const json& root, FormatVersion parsed)
{
    const std::string version = findMember(root, "version")->get<std::string>();
    const std::string supported = "this version reads formats 1.x and 2.x";
    if (parsed.major > kNativeFormatMajor)
        failAt("/version", "this file was written by a newer GG Studio (format " + version + "); " + supported);
    if (parsed.major < kNativeFormatOldestMajor)
        failAt("/version", "unsupported format version " + version + "; " + supported);
}

// Which keys an object may hold. A file of the version this build writes (or
// older) must use only the known keys, so a misspelt key is an error rather
// than a setting silently left at its default; a newer minor version may add
// keys, and those are skipped.
class KeyRule {
public:
    explicit KeyRule(FormatVersion version) : m_version(version) {}

    // Whether the file may hold format 2.0's keys (nested GRAFCETs, kinds, the rule).
    bool nested() const { return m_version.major >= 2; }

    // `known` in every version, `nestedKeys` from 2.0 on.
    void check(const json& object, const std::string& path, const char* what,
               std::initializer_list<std::string_view> known,
               std::initializer_list<std::string_view> nestedKeys = {}) const
    {
        if (m_version.minor > kNativeFormatMinor)
            return;
        std::vector<std::string_view> keys(known);
        if (nested())
            keys.insert(keys.end(), nestedKeys.begin(), nestedKeys.end());
        for (const auto& [key, value] : object.items()) {
            if (std::find(keys.begin(), keys.end(), key) == keys.end())
                failAt(childPath(path, key), "unknown key \"" + key + "\" in " + what + "; format "
                    + versionText(m_version.major) + " knows " + listKeys(keys));
        }
    }

private:
    static std::string listKeys(const std::vector<std::string_view>& keys)
    {
        std::string text;
        std::size_t index = 0;
        for (std::string_view key : keys) {
            if (index > 0)
                text += index + 1 == keys.size() ? " and " : ", ";
            text += "\"" + std::string(key) + "\"";
            ++index;
        }
        return text;
    }

    FormatVersion m_version;
};

void readSettings(Model& model, const json& root, const KeyRule& keys)
{
    if (const json* name = findMember(root, "name"))
        require(model.setName(readString(*name, "/name")), "/name");
    const json* settingsValue = findMember(root, "settings");
    if (!settingsValue)
        return;
    const json& settings = expectObject(*settingsValue, "/settings");
    keys.check(settings, "/settings", "the settings", {"cycleTimeMs", "dialect"}, {"evolution"});
    readNativeCommonSettings(model, settings, "/settings");
}

} // namespace

void readNativeCommonSettings(Model& model, const json& settings, const std::string& path)
{
    if (const json* evolution = findMember(settings, "evolution")) {
        const std::string name = readString(*evolution, path + "/evolution");
        EvolutionRule rule = EvolutionRule::OneEvolutionPerScan;
        if (!parseEvolutionRule(name, rule))
            failAt(path + "/evolution",
                   "unknown evolution rule \"" + name + "\"; expected \"one-per-scan\" or \"until-stable\"");
        model.setEvolutionRule(rule);
    }
    if (const json* cycle = findMember(settings, "cycleTimeMs")) {
        const long long value = readInteger(*cycle, path + "/cycleTimeMs", kMinCycleTimeMs, kMaxCycleTimeMs);
        require(model.setCycleTimeMs(static_cast<int>(value)), path + "/cycleTimeMs");
    }
    if (const json* dialectValue = findMember(settings, "dialect")) {
        const std::string name = readString(*dialectValue, path + "/dialect");
        Dialect dialect = Dialect::Iec;
        if (!parseDialect(name, dialect))
            failAt(path + "/dialect", "unknown dialect \"" + name + "\"; expected \"iec\" or \"codesys\"");
        model.setDialect(dialect);
    }
}

namespace {

void readVariables(Model& model, const json& root, const KeyRule& keys)
{
    const json* listValue = findMember(root, "variables");
    if (!listValue)
        return;
    const json& list = expectArray(*listValue, "/variables");
    if (list.size() > kMaxFileVariables)
        failAt("/variables", std::to_string(list.size()) + " variables; a model holds at most "
            + std::to_string(kMaxFileVariables));
    std::vector<VariableEntry> entries;
    entries.reserve(list.size());
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string path = childPath("/variables", i);
        const json& object = expectObject(list[i], path);
        keys.check(object, path, "a variable", {"name", "type", "default", "comment"}, {"kind"});
        VariableEntry entry = readVariableNameAndType(object, path, kVariableSpelling);
        if (const json* kind = findMember(object, "kind")) {
            const std::string name = readString(*kind, path + "/kind");
            if (!parseVariableKind(name, entry.variable.kind))
                failAt(path + "/kind",
                       "unknown variable kind \"" + name + "\"; expected \"input\", \"output\" or \"internal\"");
        }
        if (const json* value = findMember(object, "default"))
            entry.variable.defaultValue = readString(*value, path + "/default");
        if (const json* comment = findMember(object, "comment"))
            entry.variable.comment = readString(*comment, path + "/comment");
        entries.push_back(std::move(entry));
    }
    addVariables(model, entries, "/variables");
}

void readSteps(Model& model, const json& root, const KeyRule& keys)
{
    const json* stepsValue = findMember(root, "steps");
    if (!stepsValue)
        return;
    const json& steps = expectObject(*stepsValue, "/steps");
    std::vector<InitialFlag> initialFlags;
    for (const auto& [id, value] : steps.items()) {
        const std::string path = childPath("/steps", id);
        if (!findTemplateState(id))
            failAt(path, "unknown step \"" + id + "\"; the template's steps are A1 to A7, F1 to F6 and D1 to D3");
        keys.check(expectObject(value, path), path, "a step", {"type", "initial", "hidden", "comment"});
        if (const json* initial = findMember(value, "initial"))
            initialFlags.push_back({id, readBool(*initial, path + "/initial"), path + "/initial"});
    }
    applyInitialFlags(model, initialFlags, "/steps");

    for (const auto& [id, value] : steps.items()) {
        const std::string path = childPath("/steps", id);
        if (const json* type = findMember(value, "type")) {
            const std::string name = readString(*type, path + "/type");
            StepType stepType = StepType::Simple;
            if (!parseStepType(name, stepType))
                failAt(path + "/type", "unknown step type \"" + name + "\"; expected \"simple\", \"macro\" or \"enclosing\"");
            require(model.setStepType(id, stepType), path + "/type");
        }
        if (const json* hidden = findMember(value, "hidden"))
            require(model.setStepHidden(id, readBool(*hidden, path + "/hidden")), path + "/hidden");
        if (const json* comment = findMember(value, "comment"))
            require(model.setStepComment(id, readString(*comment, path + "/comment")), path + "/comment");
    }
}

std::vector<std::string> readTokens(const json& value, const std::string& path)
{
    const json& list = expectArray(value, path);
    if (list.size() > kMaxFileVariables)
        failAt(path, std::to_string(list.size()) + " tokens; a transition has at most one per variable, and a model "
            "holds at most " + std::to_string(kMaxFileVariables) + " variables");
    std::vector<std::string> tokens;
    tokens.reserve(list.size());
    for (std::size_t i = 0; i < list.size(); ++i)
        tokens.push_back(readString(list[i], childPath(path, i)));
    return tokens;
}

void readTransitions(Model& model, const json& root, const KeyRule& keys)
{
    const json* transitionsValue = findMember(root, "transitions");
    if (!transitionsValue)
        return;
    const json& transitions = expectObject(*transitionsValue, "/transitions");
    std::vector<OrderValue> orders;
    for (const auto& [id, value] : transitions.items()) {
        const std::string path = childPath("/transitions", id);
        const Transition* transition = model.transition(id);
        if (!transition)
            failAt(path, "unknown transition \"" + id
                + "\"; transitions are named SOURCE->TARGET after the template, such as \"F1->A2\" or \"F->D1\"");
        keys.check(expectObject(value, path), path, "a transition",
                   {"condition", "order", "negated", "hidden", "tokens"});
        if (const json* order = findMember(value, "order")) {
            const auto count = static_cast<long long>(model.outgoing(transition->source).size());
            orders.push_back({id, static_cast<int>(readInteger(*order, path + "/order", 1, count)), path + "/order"});
        }
    }
    applyOrders(model, orders);

    for (const auto& [id, value] : transitions.items()) {
        const std::string path = childPath("/transitions", id);
        if (const json* condition = findMember(value, "condition"))
            require(model.setCondition(id, readString(*condition, path + "/condition")), path + "/condition");
        if (const json* negated = findMember(value, "negated"))
            require(model.setNegated(id, readBool(*negated, path + "/negated")), path + "/negated");
        if (const json* hidden = findMember(value, "hidden"))
            require(model.setTransitionHidden(id, readBool(*hidden, path + "/hidden")), path + "/hidden");
        if (const json* tokens = findMember(value, "tokens"))
            require(model.setTokens(id, readTokens(*tokens, path + "/tokens")), path + "/tokens");
    }
}

// ---- nested GRAFCETs ----

int readNumber(const json& value, const std::string& path)
{
    return static_cast<int>(readInteger(value, path, 1, kMaxGrafcetNumber));
}

const json& expectBoundedArray(const json& value, const std::string& path, const char* what)
{
    const json& list = expectArray(value, path);
    if (list.size() > kMaxGrafcetElements)
        failAt(path, std::to_string(list.size()) + " " + what + "; a nested GRAFCET holds at most "
            + std::to_string(kMaxGrafcetElements));
    return list;
}

std::vector<int> readStepSet(const json& value, const std::string& path)
{
    const json& list = expectBoundedArray(value, path, "steps");
    std::vector<int> steps;
    for (std::size_t i = 0; i < list.size(); ++i)
        steps.push_back(readNumber(list[i], childPath(path, i)));
    return steps;
}

GrafcetAction readAction(const json& value, const std::string& path, const KeyRule& keys)
{
    const json& object = expectObject(value, path);
    keys.check(object, path, "an action", {"timing", "text"});
    GrafcetAction action;
    if (const json* timing = findMember(object, "timing")) {
        const std::string name = readString(*timing, path + "/timing");
        if (!parseTiming(name, action.timing))
            failAt(path + "/timing",
                   "unknown timing \"" + name + "\"; expected \"continuous\", \"activation\" or \"deactivation\"");
    }
    if (const json* text = findMember(object, "text"))
        action.text = readString(*text, path + "/text");
    return action;
}

GrafcetStep readGrafcetStep(const json& value, const std::string& path, const KeyRule& keys)
{
    const json& object = expectObject(value, path);
    keys.check(object, path, "a nested step", {"number", "initial", "comment", "actions"});
    const json* number = findMember(object, "number");
    if (!number)
        failAt(path + "/number", "missing; every nested step has a number");
    GrafcetStep step;
    step.number = readNumber(*number, path + "/number");
    if (const json* initial = findMember(object, "initial"))
        step.initial = readBool(*initial, path + "/initial");
    if (const json* comment = findMember(object, "comment"))
        step.comment = readString(*comment, path + "/comment");
    if (const json* actions = findMember(object, "actions")) {
        const json& list = expectBoundedArray(*actions, path + "/actions", "actions");
        for (std::size_t i = 0; i < list.size(); ++i)
            step.actions.push_back(readAction(list[i], childPath(path + "/actions", i), keys));
    }
    return step;
}

GrafcetTransition readGrafcetTransition(const json& value, const std::string& path, const KeyRule& keys)
{
    const json& object = expectObject(value, path);
    keys.check(object, path, "a nested transition", {"number", "upstream", "downstream", "receptivity"});
    GrafcetTransition transition;
    const json* number = findMember(object, "number");
    if (!number)
        failAt(path + "/number", "missing; every nested transition has a number");
    transition.number = readNumber(*number, path + "/number");
    for (const auto& [key, set] : {std::pair{"upstream", &GrafcetTransition::upstream},
                                   std::pair{"downstream", &GrafcetTransition::downstream}}) {
        const json* steps = findMember(object, key);
        if (!steps)
            failAt(path + "/" + key, std::string("missing; a transition needs its ") + key + " steps");
        transition.*set = readStepSet(*steps, path + "/" + key);
    }
    if (const json* receptivity = findMember(object, "receptivity"))
        transition.receptivity = readString(*receptivity, path + "/receptivity");
    return transition;
}

Grafcet readGrafcet(const json& value, const std::string& path, const KeyRule& keys)
{
    const json& object = expectObject(value, path);
    keys.check(object, path, "a nested GRAFCET", {"steps", "transitions"});
    Grafcet grafcet;
    if (const json* steps = findMember(object, "steps")) {
        const json& list = expectBoundedArray(*steps, path + "/steps", "steps");
        for (std::size_t i = 0; i < list.size(); ++i) {
            const std::string stepPath = childPath(path + "/steps", i);
            require(grafcet.addStep(readGrafcetStep(list[i], stepPath, keys)), stepPath + "/number");
        }
    }
    if (const json* transitions = findMember(object, "transitions")) {
        const json& list = expectBoundedArray(*transitions, path + "/transitions", "transitions");
        for (std::size_t i = 0; i < list.size(); ++i) {
            const std::string transitionPath = childPath(path + "/transitions", i);
            require(grafcet.addTransition(readGrafcetTransition(list[i], transitionPath, keys)), transitionPath);
        }
    }
    return grafcet;
}

void readGrafcets(Model& model, const json& root, const KeyRule& keys)
{
    const json* grafcetsValue = findMember(root, "grafcets");
    if (!grafcetsValue)
        return;
    const json& grafcets = expectObject(*grafcetsValue, "/grafcets");
    for (const auto& [id, value] : grafcets.items()) {
        const std::string path = childPath("/grafcets", id);
        if (!model.step(id))
            failAt(path, "unknown step \"" + id + "\"; the template's steps are A1 to A7, F1 to F6 and D1 to D3");
        require(model.setGrafcet(id, readGrafcet(value, path, keys)), path);
    }
}

// The engineer's verification properties: [{"text": ..., "comment": ...}], format 2.0.
void readProperties(Model& model, const json& root, const KeyRule& keys)
{
    const json* propertiesValue = findMember(root, "properties");
    if (!propertiesValue)
        return;
    if (!keys.nested())
        failAt("/properties", "verification properties need format 2.0");
    const json& list = expectArray(*propertiesValue, "/properties");
    if (list.size() > kMaxGrafcetElements)
        failAt("/properties", std::to_string(list.size()) + " properties; a model holds at most "
            + std::to_string(kMaxGrafcetElements));
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string path = childPath("/properties", i);
        const json& object = expectObject(list[i], path);
        keys.check(object, path, "a property", {"text", "comment"});
        const json* text = findMember(object, "text");
        if (!text)
            failAt(path + "/text", "missing; expected the property, such as \"never A AND B\"");
        UserProperty property;
        property.text = readString(*text, path + "/text");
        if (const json* comment = findMember(object, "comment"))
            property.comment = readString(*comment, path + "/comment");
        require(model.addProperty(std::move(property)), path);
    }
}

std::unique_ptr<Model> buildModel(const json& root)
{
    expectObject(root, "");
    const FormatVersion version = readFormatAndVersion(root);
    if (isPackMLFile(root, version))
        return packml::buildModel(root, version);
    checkGemmaVersion(root, version);
    const KeyRule keys(version);
    keys.check(root, "", "a model file", {"format", "version", "name", "settings", "steps", "transitions", "variables"},
               {"grafcets", "properties", "machine"});
    auto model = std::make_unique<Model>();
    readSettings(*model, root, keys);
    readVariables(*model, root, keys);
    readSteps(*model, root, keys);
    readTransitions(*model, root, keys);
    readGrafcets(*model, root, keys);
    readProperties(*model, root, keys);
    if (const json* machine = findMember(root, "machine"))
        require(model->setMachine(readNativeMachine(*machine, "/machine", version)), "/machine");
    return model;
}

// Does `"format"` map to the native format name somewhere in the text?
bool hasNativeFormatMember(std::string_view text)
{
    const std::string_view key = "\"format\"";
    const std::string value = "\"" + std::string(kNativeFormatName) + "\"";
    for (std::size_t at = text.find(key); at != std::string_view::npos; at = text.find(key, at + 1)) {
        std::size_t i = at + key.size();
        const auto skipBlanks = [&] {
            while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\n' || text[i] == '\r'))
                ++i;
        };
        skipBlanks();
        if (i >= text.size() || text[i] != ':')
            continue;
        ++i;
        skipBlanks();
        if (text.substr(i, value.size()) == value)
            return true;
    }
    return false;
}

} // namespace

std::string nativeVersionText(int major)
{
    return versionText(major);
}

std::string_view nativeTimingName(ActionTiming timing)
{
    return timingName(timing);
}

void checkNativeKeys(const json& object, const std::string& path, const char* what,
                     std::initializer_list<std::string_view> known, NativeVersion version)
{
    KeyRule(version).check(object, path, what, known);
}

void readNativeVariables(Model& model, const json& root, NativeVersion version)
{
    readVariables(model, root, KeyRule(version));
}

void readNativeProperties(Model& model, const json& root, NativeVersion version)
{
    readProperties(model, root, KeyRule(version));
}

Grafcet readNativeGrafcet(const json& value, const std::string& path, NativeVersion version)
{
    return readGrafcet(value, path, KeyRule(version));
}

ordered_json nativeVariablesJson(const Model& model)
{
    ordered_json variables = ordered_json::array();
    for (const Variable& variable : model.variables())
        variables.push_back(variableJson(variable, true));
    return variables;
}

ordered_json nativePropertiesJson(const Model& model)
{
    ordered_json properties = ordered_json::array();
    for (const UserProperty& property : model.properties()) {
        ordered_json object;
        object["text"] = property.text;
        if (!property.comment.empty())
            object["comment"] = property.comment;
        properties.push_back(std::move(object));
    }
    return properties;
}

ordered_json nativeGrafcetJson(const Grafcet& grafcet)
{
    return grafcetJson(grafcet);
}

Grafcet readNativeGrafcet(const ordered_json& value, const std::string& path)
{
    return readGrafcet(value, path, KeyRule(FormatVersion{kNativeFormatMajor, kNativeFormatMinor}));
}

std::variant<std::unique_ptr<Model>, LoadError> loadNativeJson(std::string_view text, const std::string& displayName)
{
    return loadModelJson(text, displayName, buildModel);
}

bool looksLikeNativeJson(std::string_view text)
{
    return firstSignificantCharacter(text) == '{' && hasNativeFormatMember(text);
}

} // namespace core
