#include "core/templates/packml/packmlformat.h"

#include "core/formats/jsonreader.h"
#include "core/formats/modelloading.h"
#include "core/formats/nativeformat.h"
#include "core/formats/nativegrafcetjson.h"
#include "core/templates/packml/packmlconfiguration.h"

#include <map>
#include <vector>

namespace core::packml {

namespace {

using json = nlohmann::ordered_json;

// ---- Writing ---------------------------------------------------------------

json settingsJson(const Model& model)
{
    const ModelSettings& settings = model.settings();
    const Configuration& configuration = *model.packml();
    json object;
    object["cycleTimeMs"] = settings.cycleTimeMs;
    object["dialect"] = dialectName(settings.dialect);
    object["evolution"] = evolutionRuleName(settings.evolution);
    object["edition"] = editionName(configuration.options.edition);
    object["initialState"] = stateName(configuration.initialState);
    object["initialMode"] = configuration.initialMode;
    object["holdInSuspended"] = configuration.options.holdInSuspended;
    object["completeInSuspendedHeld"] = configuration.options.completeInSuspendedHeld;
    return object;
}

// Every command of the edition; Complete in a 2015 model only when set.
json commandsJson(const Configuration& configuration)
{
    json object = json::object();
    for (const CommandInfo& info : allCommands()) {
        const CommandSetting& setting = configuration.command(info.command);
        const bool set = !setting.condition.empty() || !setting.comment.empty();
        if (commandInEdition(info.command, configuration.options.edition) || set)
            object[std::string(info.name)] = json{{"condition", setting.condition}, {"comment", setting.comment}};
    }
    return object;
}

json stateNames(const StateSet& set)
{
    json names = json::array();
    for (State state : set.list())
        names.push_back(json(stateName(state)));
    return names;
}

json modeGrafcetsJson(const Model& model, const Mode& mode)
{
    json object = json::object();
    for (const StateInfo& info : states()) {
        const GrafcetChoice& choice = mode.grafcetChoice(info.state);
        const std::string name(info.name);
        if (choice.kind == GrafcetChoice::Kind::Own)
            object[name] = nativeGrafcetJson(*model.grafcet(grafcetKey(mode.number, info.state)));
        else if (choice.kind == GrafcetChoice::Kind::SameAs)
            object[name] = json{{"sameAs", choice.sameAsMode}};
    }
    return object;
}

json modeJson(const Model& model, const Mode& mode)
{
    json object;
    object["number"] = mode.number;
    if (mode.number >= kFirstUserMode)
        object["name"] = mode.name;
    object["comment"] = mode.comment;
    if (!mode.request.empty())
        object["request"] = mode.request;
    object["disabled"] = stateNames(mode.disabled);
    object["modeChange"] = stateNames(mode.modeChange);
    object["grafcets"] = modeGrafcetsJson(model, mode);
    return object;
}

// ---- Reading ---------------------------------------------------------------

std::string listNames(const std::vector<std::string_view>& names)
{
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i)
        text += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + std::string(names[i]);
    return text;
}

std::string stateList(bool (*filter)(State))
{
    std::vector<std::string_view> names;
    for (const StateInfo& info : states()) {
        if (!filter || filter(info.state))
            names.push_back(info.name);
    }
    return listNames(names);
}

State readState(const json& value, const std::string& path)
{
    const std::string name = readString(value, path);
    const std::optional<State> state = findState(name);
    if (!state)
        failAt(path, "unknown state \"" + name + "\"; the PackML states are " + stateList(nullptr));
    return *state;
}

int readModeNumber(const json& value, const std::string& path)
{
    return static_cast<int>(readInteger(value, path, kMinModeNumber, kMaxModeNumber));
}

void checkRootKeys(const json& root, NativeVersion version)
{
    for (const char* gemmaKey : {"steps", "transitions", "grafcets"}) {
        if (findMember(root, gemmaKey))
            failAt(childPath("", gemmaKey), "\"" + std::string(gemmaKey)
                + "\" is a key of GEMMA models; a PackML model file (\"template\": \"packml\") has \"commands\" "
                  "and \"modes\" instead");
    }
    checkNativeKeys(root, "", "a PackML model file",
                    {"format", "version", "template", "name", "settings", "commands", "modes", "variables",
                     "properties"},
                    version);
}

void readPackMLSettings(Configuration& configuration, const json& settings, NativeVersion version)
{
    checkNativeKeys(settings, "/settings", "the settings",
                    {"cycleTimeMs", "dialect", "evolution", "edition", "initialState", "initialMode",
                     "holdInSuspended", "completeInSuspendedHeld"},
                    version);
    if (const json* value = findMember(settings, "initialState"))
        configuration.initialState = readState(*value, "/settings/initialState");
    if (const json* value = findMember(settings, "initialMode"))
        configuration.initialMode = readModeNumber(*value, "/settings/initialMode");
    if (const json* value = findMember(settings, "holdInSuspended"))
        configuration.options.holdInSuspended = readBool(*value, "/settings/holdInSuspended");
    if (const json* value = findMember(settings, "completeInSuspendedHeld"))
        configuration.options.completeInSuspendedHeld = readBool(*value, "/settings/completeInSuspendedHeld");
}

// The edition first: the defaults of everything else depend on it.
Edition readEdition(const json* settings)
{
    const json* value = settings ? findMember(*settings, "edition") : nullptr;
    if (!value)
        return Edition::Y2015;
    const std::string name = readString(*value, "/settings/edition");
    const std::optional<Edition> edition = parseEdition(name);
    if (!edition)
        failAt("/settings/edition", "unknown edition \"" + name + "\"; expected \"2015\" or \"2022\"");
    return *edition;
}

void readCommands(Configuration& configuration, const json& root, NativeVersion version)
{
    const json* commandsValue = findMember(root, "commands");
    if (!commandsValue)
        return;
    const json& commands = expectObject(*commandsValue, "/commands");
    for (const auto& [name, value] : commands.items()) {
        const std::string path = childPath("/commands", name);
        const std::optional<Command> command = findCommand(name);
        if (!command) {
            std::vector<std::string_view> names;
            for (const CommandInfo& info : allCommands())
                names.push_back(info.name);
            failAt(path, "unknown command \"" + name + "\"; the PackML commands are " + listNames(names));
        }
        const json& object = expectObject(value, path);
        checkNativeKeys(object, path, "a command", {"condition", "comment"}, version);
        CommandSetting& setting = configuration.command(*command);
        if (const json* condition = findMember(object, "condition"))
            setting.condition = readString(*condition, path + "/condition");
        if (const json* comment = findMember(object, "comment"))
            setting.comment = readString(*comment, path + "/comment");
    }
}

StateSet readStateSet(const json& value, const std::string& path)
{
    const json& list = expectArray(value, path);
    StateSet set;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string itemPath = childPath(path, i);
        const State state = readState(list[i], itemPath);
        if (set.contains(state))
            failAt(itemPath, "\"" + std::string(stateName(state)) + "\" is listed twice");
        set.insert(state);
    }
    return set;
}

// A mode's own GRAFCET, read once the model exists.
struct OwnGrafcet {
    std::string key;
    const json* value;
    std::string path;
};

void readModeGrafcets(Mode& mode, const json& value, const std::string& path, std::vector<OwnGrafcet>& owns)
{
    const json& grafcets = expectObject(value, path);
    for (const auto& [name, entry] : grafcets.items()) {
        const std::string entryPath = childPath(path, name);
        const std::optional<State> state = findState(name);
        if (!state || !holdsGrafcet(*state))
            failAt(entryPath, (state ? name + " holds no GRAFCET" : "unknown state \"" + name + "\"")
                + "; the keys are the states that hold one: " + stateList(holdsGrafcet));
        const json& object = expectObject(entry, entryPath);
        if (const json* sameAs = findMember(object, "sameAs")) {
            if (object.size() != 1)
                failAt(entryPath, "\"sameAs\" stands alone: the GRAFCET is mode k's, so it has no steps or "
                                  "transitions of its own");
            mode.grafcets[static_cast<std::size_t>(*state)] =
                GrafcetChoice::sameAs(readModeNumber(*sameAs, entryPath + "/sameAs"));
        } else
            owns.push_back({grafcetKey(mode.number, *state), &entry, entryPath});
    }
}

Mode readMode(const json& value, const std::string& path, NativeVersion version, std::vector<OwnGrafcet>& owns)
{
    const json& object = expectObject(value, path);
    checkNativeKeys(object, path, "a mode",
                    {"number", "name", "comment", "request", "disabled", "modeChange", "grafcets"}, version);
    const json* number = findMember(object, "number");
    if (!number)
        failAt(path + "/number", "missing; every mode has a number (1..31)");
    Mode mode = defaultMode(readModeNumber(*number, path + "/number"));
    if (const json* name = findMember(object, "name")) {
        if (mode.number < kFirstUserMode)
            failAt(path + "/name", "mode " + std::to_string(mode.number) + " is named "
                + std::string(baseModeName(mode.number)) + "; only user modes (4..31) have a name");
        mode.name = readString(*name, path + "/name");
    }
    if (const json* comment = findMember(object, "comment"))
        mode.comment = readString(*comment, path + "/comment");
    if (const json* request = findMember(object, "request"))
        mode.request = readString(*request, path + "/request");
    if (const json* disabled = findMember(object, "disabled"))
        mode.disabled = readStateSet(*disabled, path + "/disabled");
    if (const json* modeChange = findMember(object, "modeChange"))
        mode.modeChange = readStateSet(*modeChange, path + "/modeChange");
    if (const json* grafcets = findMember(object, "grafcets"))
        readModeGrafcets(mode, *grafcets, path + "/grafcets", owns);
    return mode;
}

void readModes(Configuration& configuration, const json& root, NativeVersion version, std::vector<OwnGrafcet>& owns)
{
    const json* modesValue = findMember(root, "modes");
    if (!modesValue)
        return; // the template's three modes
    const json& list = expectArray(*modesValue, "/modes");
    std::map<int, Mode> modes; // in number order, whatever the file's
    std::map<int, std::string> paths;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string path = childPath("/modes", i);
        Mode mode = readMode(list[i], path, version, owns);
        const int number = mode.number;
        if (const auto previous = paths.find(number); previous != paths.end())
            failAt(path + "/number", "mode " + std::to_string(number) + " is listed twice (also at "
                + previous->second + ")");
        paths.emplace(number, path);
        modes.emplace(number, std::move(mode));
    }
    configuration.modes.clear();
    for (auto& [number, mode] : modes)
        configuration.modes.push_back(std::move(mode));
}

} // namespace

std::string saveJson(const Model& model)
{
    json root;
    root["format"] = kNativeFormatName;
    root["version"] = std::to_string(kFormatMajor) + "." + std::to_string(kFormatMinor);
    root["template"] = kTemplateName;
    root["name"] = model.settings().name;
    root["settings"] = settingsJson(model);
    root["commands"] = commandsJson(*model.packml());
    json modes = json::array();
    for (const Mode& mode : model.packml()->modes)
        modes.push_back(modeJson(model, mode));
    root["modes"] = std::move(modes);
    root["variables"] = nativeVariablesJson(model);
    root["properties"] = nativePropertiesJson(model);
    // Text from elsewhere may hold invalid UTF-8: replace it rather than throw.
    return root.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

std::unique_ptr<Model> buildModel(const json& root, NativeVersion version)
{
    checkRootKeys(root, version);
    const json* settingsValue = findMember(root, "settings");
    const json* settings = settingsValue ? &expectObject(*settingsValue, "/settings") : nullptr;
    Configuration configuration = defaultConfiguration(readEdition(settings));
    if (settings)
        readPackMLSettings(configuration, *settings, version);
    readCommands(configuration, root, version);
    std::vector<OwnGrafcet> owns;
    readModes(configuration, root, version, owns);

    auto model = std::make_unique<Model>(std::move(configuration));
    if (const json* name = findMember(root, "name"))
        require(model->setName(readString(*name, "/name")), "/name");
    if (settings)
        readNativeCommonSettings(*model, *settings, "/settings");
    readNativeVariables(*model, root, version);
    for (const OwnGrafcet& own : owns)
        require(model->setGrafcet(own.key, readNativeGrafcet(*own.value, own.path, version)), own.path);
    readNativeProperties(*model, root, version);
    return model;
}

} // namespace core::packml
