#include "core/formats/gggeneratorformat.h"

#include <algorithm>

#include "core/templates/gemma/gemmachartlayout.h"
#include "core/condition/conditionanalysis.h"
#include "core/condition/conditionparser.h"
#include "core/formats/gggeneratordropped.h"
#include "core/formats/jsonreader.h"
#include "core/formats/modelloading.h"
#include "core/condition/symboltable.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <cstdio>
#include <map>
#include <optional>
#include <unordered_set>

using json = nlohmann::ordered_json;
using nlohmann::ordered_json;

namespace core {

namespace {

struct FrameName {
    Family family;
    std::string_view name;
};

constexpr std::array<FrameName, 3> kFrames{{
    {Family::A, "A family"},
    {Family::F, "F family"},
    {Family::D, "D family"},
}};

const FrameName* findFrame(std::string_view name)
{
    for (const FrameName& frame : kFrames) {
        if (frame.name == name)
            return &frame;
    }
    return nullptr;
}

std::string lowerAscii(std::string_view text)
{
    std::string result(text);
    for (char& c : result) {
        if (c >= 'A' && c <= 'Z')
            c = static_cast<char>(c - 'A' + 'a');
    }
    return result;
}

// ---- Writing ---------------------------------------------------------------

std::uint64_t fnv1a(std::string_view text, std::uint64_t seed)
{
    std::uint64_t hash = seed;
    for (char c : text) {
        hash ^= static_cast<unsigned char>(c);
        hash *= 0x100000001b3ull;
    }
    return hash;
}

// splitmix64's finaliser: spreads FNV's similar hashes of similar names.
std::uint64_t mix(std::uint64_t value)
{
    value = (value ^ (value >> 30)) * 0xbf58476d1ce4e5b9ull;
    value = (value ^ (value >> 27)) * 0x94d049bb133111ebull;
    return value ^ (value >> 31);
}

// A UUID-shaped key that depends only on the name, so exports are
// deterministic and a node keeps its key from one export to the next.
std::string nodeKey(std::string_view name)
{
    const std::string seedText = "ggstudio:" + std::string(name);
    const std::uint64_t high = mix(fnv1a(seedText, 0xcbf29ce484222325ull));
    const std::uint64_t low = mix(fnv1a(seedText, 0x84222325cbf29ce4ull));
    char hex[33];
    std::snprintf(hex, sizeof hex, "%016llx%016llx", static_cast<unsigned long long>(high),
        static_cast<unsigned long long>(low));
    hex[12] = '8'; // version nibble: custom (RFC 9562 UUIDv8)
    hex[16] = "89ab"[hex[16] % 4];
    const std::string digits(hex, 32);
    return digits.substr(0, 8) + "-" + digits.substr(8, 4) + "-" + digits.substr(12, 4) + "-" + digits.substr(16, 4)
        + "-" + digits.substr(20, 12);
}

std::string nodeType(StepType type)
{
    switch (type) {
    case StepType::Simple: return "SIMPLE";
    case StepType::Macro: return "MACRO";
    case StepType::Enclosing: return "ENCLOSING";
    }
    return "SIMPLE";
}

ordered_json nodeJson(std::string_view name, const Rect& rect, bool hidden, Family family, std::string type,
    bool initial)
{
    ordered_json node;
    node["key"] = nodeKey(name);
    node["name"] = name;
    node["x"] = rect.x;
    node["y"] = rect.y;
    node["width"] = rect.width;
    node["height"] = rect.height;
    node["isHidden"] = hidden;
    ordered_json data;
    data["family"] = familyName(family);
    data["type"] = std::move(type);
    data["isInitial"] = initial;
    node["data"] = std::move(data);
    return node;
}

ordered_json nodesJson(const Model& model, const ChartLayout& layout)
{
    ordered_json nodes = ordered_json::array();
    for (const FrameName& frame : kFrames) {
        const FrameLayout* frameLayout = layout.frame(frame.family);
        nodes.push_back(nodeJson(frame.name, frameLayout ? frameLayout->rect : Rect{}, false, frame.family,
            "CONTAINER", false));
    }
    for (const Step& step : model.steps()) {
        const StepLayout* stepLayout = layout.step(step.id);
        nodes.push_back(nodeJson(step.id, stepLayout ? stepLayout->box : Rect{}, step.hidden, step.family,
            nodeType(step.type), step.initial));
    }
    return nodes;
}

// "NO" for a token on X, "NC" for one on NOT X: the web tool's names for
// normally open and normally closed contacts.
std::string tokenBehaviour(const cond::Expression& expression, bool parsed, std::string_view variable)
{
    if (!parsed)
        return "NO";
    for (const cond::Literal& literal : cond::booleanLiterals(expression)) {
        if (equalsIgnoreCase(expression.at(literal.variableNode).text, variable))
            return literal.negated ? "NC" : "NO";
    }
    return "NO";
}

ordered_json savedSignalsJson(const Transition& transition)
{
    const cond::ParseResult parsed = cond::parse(transition.condition);
    ordered_json saved = ordered_json::object();
    for (const std::string& token : transition.tokens) {
        ordered_json entry;
        entry["withMemory"] = true;
        entry["behaviour"] = tokenBehaviour(parsed.expression, parsed.ok(), token);
        saved[token] = std::move(entry);
    }
    return saved;
}

ordered_json connectionJson(const Transition& transition, const ChartLayout& layout)
{
    ordered_json connection;
    const std::string source = transition.isFamilyTransition() ? std::string("F family") : transition.source;
    connection["from"] = nodeKey(source);
    connection["to"] = nodeKey(transition.target);
    ordered_json data;
    data["conditionExpression"] = transition.condition;
    data["priority"] = transition.order;
    data["isNegated"] = transition.negated;
    if (!transition.tokens.empty())
        data["savedSignalsWithMemory"] = savedSignalsJson(transition);
    connection["data"] = std::move(data);
    connection["isHidden"] = transition.hidden;
    // The web tool draws the ends itself; it stores only the bends.
    ordered_json points = ordered_json::array();
    if (const TransitionLayout* route = layout.transition(transition.id)) {
        for (std::size_t i = 1; i + 1 < route->route.size(); ++i)
            points.push_back({{"x", route->route[i].x}, {"y", route->route[i].y}});
    }
    connection["innerPoints"] = std::move(points);
    return connection;
}

ordered_json signalsJson(const Model& model)
{
    ordered_json signals = ordered_json::array();
    for (const Variable& variable : model.variables()) {
        ordered_json signal;
        signal["name"] = variable.name;
        signal["type"] = lowerAscii(iecTypeName(variable.type));
        signal["defaultValue"] = variable.defaultValue;
        signals.push_back(std::move(signal));
    }
    return signals;
}

// ---- Reading ---------------------------------------------------------------

struct NodeInfo {
    std::string name; // step id, or a frame name
    std::string path;
};

struct ReadState {
    std::map<std::string, NodeInfo> nodesByKey;
    bool familyFrameHidden = false;
};

const VariableEntrySpelling kSignalSpelling{
    "signal", "a type such as \"bool\"", "bool, sint, int, dint, lint, usint, uint, udint, ulint, real or lreal"};

std::string readSignalDefault(const json& value, const std::string& path)
{
    if (value.is_null())
        return {};
    if (value.is_string())
        return value.get<std::string>();
    if (value.is_boolean())
        return value.get<bool>() ? "TRUE" : "FALSE";
    if (value.is_number())
        return value.dump();
    failAt(path, "expected a string, found " + describeJsonValue(value));
}

void readSignals(Model& model, const json& root)
{
    const json* graph = findMember(root, "graph");
    if (!graph)
        return;
    const json* data = findMember(expectObject(*graph, "/graph"), "data");
    if (!data)
        return;
    const json* signalsValue = findMember(expectObject(*data, "/graph/data"), "signals");
    if (!signalsValue)
        return;
    const json& signals = expectArray(*signalsValue, "/graph/data/signals");
    std::vector<VariableEntry> entries;
    entries.reserve(signals.size());
    for (std::size_t i = 0; i < signals.size(); ++i) {
        const std::string path = childPath("/graph/data/signals", i);
        const json& signal = expectObject(signals[i], path);
        VariableEntry entry = readVariableNameAndType(signal, path, kSignalSpelling);
        if (const json* value = findMember(signal, "defaultValue"))
            entry.variable.defaultValue = readSignalDefault(*value, path + "/defaultValue");
        entries.push_back(std::move(entry));
    }
    addVariables(model, entries, "/graph/data/signals");
}

StepType readNodeType(const json& value, const std::string& path)
{
    const std::string name = readString(value, path);
    const std::string lower = lowerAscii(name);
    StepType type = StepType::Simple;
    if (lower == "container")
        failAt(path, "a GEMMA state cannot be a CONTAINER (only the family frames are)");
    if (!parseStepType(lower, type))
        failAt(path, "unknown node type \"" + name + "\"; expected \"SIMPLE\", \"MACRO\" or \"ENCLOSING\"");
    return type;
}

// Registers the node's key and name, refusing repeats and unknown names.
void registerNode(ReadState& state, std::map<std::string, std::string>& pathByName, const json& node,
    const std::string& path)
{
    const json* nameValue = findMember(node, "name");
    if (!nameValue)
        failAt(path + "/name", "missing; every node needs a name");
    const std::string name = readString(*nameValue, path + "/name");
    if (!findTemplateState(name) && !findFrame(name))
        failAt(path + "/name", "unknown node \"" + name
            + "\"; GG-Generator nodes are the states A1 to A7, F1 to F6, D1 to D3 and the frames "
              "\"A family\", \"F family\" and \"D family\"");
    if (const auto [slot, inserted] = pathByName.emplace(name, path); !inserted)
        failAt(path + "/name", "a second node named \"" + name + "\" (the first is " + slot->second + ")");

    const json* keyValue = findMember(node, "key");
    if (!keyValue)
        failAt(path + "/key", "missing; every node needs a key");
    const std::string key = readString(*keyValue, path + "/key");
    if (const auto [slot, inserted] = state.nodesByKey.emplace(key, NodeInfo{name, path}); !inserted)
        failAt(path + "/key", "a second node with the key \"" + key + "\" (the first is " + slot->second.path + ")");
}

void readNodes(Model& model, ReadState& state, const json& root)
{
    const json* nodesValue = findMember(root, "nodes");
    if (!nodesValue)
        failAt("/nodes", "missing; a GG-Generator file has \"nodes\" and \"connections\"");
    const json& nodes = expectArray(*nodesValue, "/nodes");
    std::map<std::string, std::string> pathByName;
    std::vector<InitialFlag> initialFlags;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const std::string path = childPath("/nodes", i);
        const json& node = expectObject(nodes[i], path);
        registerNode(state, pathByName, node, path);
        const std::string name = node.at("name").get<std::string>();
        const json* hidden = findMember(node, "isHidden");
        const bool isHidden = hidden ? readBool(*hidden, path + "/isHidden") : false;
        if (findFrame(name)) {
            // Hiding the F frame in the web tool switches its family transition off.
            if (name == "F family" && isHidden)
                state.familyFrameHidden = true;
            continue;
        }
        require(model.setStepHidden(name, isHidden), path + "/isHidden");
        const json* dataValue = findMember(node, "data");
        if (!dataValue)
            continue;
        const json& data = expectObject(*dataValue, path + "/data");
        if (const json* type = findMember(data, "type"))
            require(model.setStepType(name, readNodeType(*type, path + "/data/type")), path + "/data/type");
        if (const json* initial = findMember(data, "isInitial"))
            initialFlags.push_back({name, readBool(*initial, path + "/data/isInitial"), path + "/data/isInitial"});
    }
    applyInitialFlags(model, initialFlags, "/nodes");
}

// Tokens: the remembered signals that are BOOL variables of the condition.
std::vector<std::string> readTokens(const Model& model, const json& saved, const std::string& condition,
    const std::string& path)
{
    std::vector<std::string> candidates;
    if (saved.is_object()) {
        for (const auto& [name, setting] : saved.items()) {
            const json* withMemory = setting.is_object() ? findMember(setting, "withMemory") : &setting;
            if (withMemory && withMemory->is_boolean() && withMemory->get<bool>())
                candidates.push_back(name);
        }
    } else if (saved.is_array()) {
        // An older form: the list of the signals with memory.
        for (const json& name : saved) {
            if (name.is_string())
                candidates.push_back(name.get<std::string>());
        }
    } else {
        failAt(path, "expected an object such as {\"Stop\": {\"withMemory\": true, \"behaviour\": \"NC\"}}, found "
            + describeJsonValue(saved));
    }

    // Sets and hash lookups: a hostile file may hold a million candidates.
    std::unordered_set<std::string> identifiers;
    for (const cond::Token& token : cond::tokenize(condition)) {
        if (token.kind == cond::TokenKind::Identifier)
            identifiers.insert(toUpperAscii(token.text));
    }
    const SymbolTable symbols(model.variables());
    std::unordered_set<std::string> taken;
    std::vector<std::string> tokens;
    for (const std::string& candidate : candidates) {
        const Variable* variable = symbols.find(candidate);
        if (!variable || variable->type != IecType::Bool || !identifiers.count(toUpperAscii(variable->name)))
            continue;
        if (taken.insert(variable->name).second)
            tokens.push_back(variable->name);
    }
    return tokens;
}

struct ConnectionData {
    std::string transitionId;
    std::string path;
    const json* object;
};

std::string endpointName(const ReadState& state, const json& connection, const std::string& path, const char* end)
{
    const json* value = findMember(connection, end);
    if (!value)
        failAt(path + "/" + end, "missing; a connection names its nodes by key");
    const std::string key = readString(*value, path + "/" + end);
    const auto found = state.nodesByKey.find(key);
    if (found == state.nodesByKey.end())
        failAt(path + "/" + end, "no node has the key \"" + key + "\"");
    return found->second.name;
}

std::vector<ConnectionData> resolveConnections(const Model& model, const ReadState& state, const json& connections)
{
    std::vector<ConnectionData> resolved;
    std::map<std::string, std::string> pathById;
    for (std::size_t i = 0; i < connections.size(); ++i) {
        const std::string path = childPath("/connections", i);
        const json& connection = expectObject(connections[i], path);
        const std::string from = endpointName(state, connection, path, "from");
        const std::string to = endpointName(state, connection, path, "to");
        const std::string source = from == "F family" ? std::string(kFamilySource) : from;
        const std::string id = makeTransitionId(source, to);
        if (!model.transition(id))
            failAt(path, "the GEMMA template has no transition from " + from + " to " + to);
        if (const auto [slot, inserted] = pathById.emplace(id, path); !inserted)
            failAt(path, "a second connection from " + from + " to " + to + " (the first is " + slot->second + ")");
        resolved.push_back({id, path, &connection});
    }
    return resolved;
}

void readConnections(Model& model, const ReadState& state, const json& root)
{
    const json* connectionsValue = findMember(root, "connections");
    if (!connectionsValue)
        failAt("/connections", "missing; a GG-Generator file has \"nodes\" and \"connections\"");
    const std::vector<ConnectionData> connections =
        resolveConnections(model, state, expectArray(*connectionsValue, "/connections"));

    std::vector<OrderValue> orders;
    for (const ConnectionData& connection : connections) {
        const json* data = findMember(*connection.object, "data");
        if (!data)
            continue;
        if (const json* priority = findMember(expectObject(*data, connection.path + "/data"), "priority")) {
            const auto count = static_cast<long long>(model.outgoing(model.transition(connection.transitionId)->source).size());
            const std::string path = connection.path + "/data/priority";
            orders.push_back({connection.transitionId, static_cast<int>(readInteger(*priority, path, 1, count)), path});
        }
    }
    applyOrders(model, orders);

    for (const ConnectionData& connection : connections) {
        const std::string& id = connection.transitionId;
        const std::string& path = connection.path;
        if (const json* hidden = findMember(*connection.object, "isHidden"))
            require(model.setTransitionHidden(id, readBool(*hidden, path + "/isHidden")), path + "/isHidden");
        const json* data = findMember(*connection.object, "data");
        if (!data)
            continue;
        if (const json* condition = findMember(*data, "conditionExpression")) {
            const std::string conditionPath = path + "/data/conditionExpression";
            require(model.setCondition(id, readString(*condition, conditionPath)), conditionPath);
        }
        if (const json* negated = findMember(*data, "isNegated"))
            require(model.setNegated(id, readBool(*negated, path + "/data/isNegated")), path + "/data/isNegated");
        if (const json* saved = findMember(*data, "savedSignalsWithMemory")) {
            const std::string savedPath = path + "/data/savedSignalsWithMemory";
            require(model.setTokens(id, readTokens(model, *saved, model.transition(id)->condition, savedPath)), savedPath);
        }
    }
    if (state.familyFrameHidden) {
        for (const Transition* transition : model.outgoing(kFamilySource))
            require(model.setTransitionHidden(transition->id, true), "/nodes");
    }
}

std::unique_ptr<Model> buildModel(const json& root)
{
    expectObject(root, "");
    auto model = std::make_unique<Model>();
    ReadState state;
    readSignals(*model, root);
    readNodes(*model, state, root);
    readConnections(*model, state, root);
    return model;
}

} // namespace

std::string saveGGGeneratorJson(const Model& model)
{
    const ChartLayout& layout = templateLayout();
    ordered_json root;
    ordered_json graph;
    graph["data"] = {{"signals", signalsJson(model)}};
    graph["key"] = nodeKey("graph");
    root["graph"] = std::move(graph);
    root["nodes"] = nodesJson(model, layout);
    ordered_json connections = ordered_json::array();
    for (const Transition& transition : model.transitions())
        connections.push_back(connectionJson(transition, layout));
    root["connections"] = std::move(connections);
    return root.dump(2, ' ', false, ordered_json::error_handler_t::replace) + "\n";
}

std::variant<std::unique_ptr<Model>, LoadError> loadGGGeneratorJson(std::string_view text, const std::string& displayName,
                                                                    std::vector<LoadWarning>* warnings)
{
    return loadModelJson(text, displayName, [&](const json& root) {
        std::unique_ptr<Model> model = buildModel(root);
        if (warnings)
            *warnings = ggStudioKeysInGGGeneratorFile(root, displayName);
        return model;
    });
}

bool looksLikeGGGeneratorJson(std::string_view text)
{
    return firstSignificantCharacter(text) == '{' && text.find("\"nodes\"") != std::string_view::npos
        && text.find("\"connections\"") != std::string_view::npos;
}

std::vector<GGGeneratorLoss> ggGeneratorLosses(const Model& model)
{
    std::vector<GGGeneratorLoss> losses;
    GGGeneratorLoss nested{GGGeneratorLoss::Kind::NestedGrafcets, {}};
    for (const Step& step : model.steps()) {
        if (model.grafcet(step.id))
            nested.steps.push_back(step.id);
    }
    if (!nested.steps.empty())
        losses.push_back(std::move(nested));
    const bool kinds = std::any_of(model.variables().begin(), model.variables().end(),
                                   [](const Variable& v) { return v.kind != VariableKind::Input; });
    if (kinds)
        losses.push_back({GGGeneratorLoss::Kind::VariableKinds, {}});
    if (model.settings().evolution != EvolutionRule::OneEvolutionPerScan)
        losses.push_back({GGGeneratorLoss::Kind::UntilStableRule, {}});
    if (!model.properties().empty())
        losses.push_back({GGGeneratorLoss::Kind::Properties, {}});
    return losses;
}

std::string toText(const GGGeneratorLoss& loss)
{
    switch (loss.kind) {
    case GGGeneratorLoss::Kind::NestedGrafcets: {
        std::string steps;
        for (const std::string& step : loss.steps)
            steps += (steps.empty() ? "" : ", ") + step;
        return "the nested GRAFCETs of " + steps + " are left out: GG-Generator has no place for nested behaviour";
    }
    case GGGeneratorLoss::Kind::VariableKinds:
        return "the variable kinds (output, internal) are left out: GG-Generator reads every variable as an input";
    case GGGeneratorLoss::Kind::UntilStableRule:
        return "the until-stable evolution rule is left out";
    case GGGeneratorLoss::Kind::Properties:
        return "the verification properties are left out";
    }
    return {};
}

} // namespace core
