#include "core/formats/grafcetfragmentjson.h"

#include "core/formats/nativegrafcetjson.h"

#include <optional>

using nlohmann::ordered_json;

namespace core {

namespace {

Grafcet asGrafcet(const GrafcetFragment& fragment)
{
    // copyFragment gives unique numbers and transitions between its own
    // steps, which a Grafcet accepts as they are.
    Grafcet grafcet;
    for (const GrafcetStep& step : fragment.steps)
        (void)grafcet.addStep(step);
    for (const GrafcetTransition& transition : fragment.transitions)
        (void)grafcet.addTransition(transition);
    return grafcet;
}

void checkFormat(const ordered_json& root)
{
    const ordered_json* format = findMember(root, "format");
    if (!format || !format->is_string() || format->get<std::string>() != kGrafcetFragmentFormatName)
        failAt("/format", "expected \"" + std::string(kGrafcetFragmentFormatName) + "\", found "
            + (format ? describeJsonValue(*format) : std::string("nothing")));
    const ordered_json* version = findMember(root, "version");
    if (!version)
        failAt("/version", "missing; expected \"" + std::string(kGrafcetFragmentVersion) + "\"");
    if (readString(*version, "/version") != kGrafcetFragmentVersion)
        failAt("/version", "this version reads fragments " + std::string(kGrafcetFragmentVersion) + ", found "
            + describeJsonValue(*version));
    for (const auto& [key, value] : root.items())
        if (key != "format" && key != "version" && key != "grafcet")
            failAt(childPath("", key), "unknown key \"" + key + "\"; a fragment has \"format\", \"version\" and \"grafcet\"");
}

// Before the steps are read: each transition looks its steps up among them.
void checkCount(const ordered_json& grafcet, std::string_view key, std::size_t max)
{
    const ordered_json* list = findMember(grafcet, key);
    if (list && list->is_array() && list->size() > max)
        failAt("/grafcet/" + std::string(key), std::to_string(list->size()) + " " + std::string(key)
            + "; a fragment holds at most " + std::to_string(max));
}

GrafcetFragment buildFragment(const ordered_json& root)
{
    expectObject(root, "");
    checkFormat(root);
    const ordered_json* grafcetValue = findMember(root, "grafcet");
    if (!grafcetValue)
        failAt("/grafcet", "missing; a fragment holds its steps and transitions there");
    checkCount(expectObject(*grafcetValue, "/grafcet"), "steps", kMaxGrafcetFragmentSteps);
    checkCount(*grafcetValue, "transitions", kMaxGrafcetFragmentTransitions);
    const Grafcet grafcet = readNativeGrafcet(*grafcetValue, "/grafcet");
    if (grafcet.steps().empty())
        failAt("/grafcet/steps", "no step; a fragment holds at least one");
    GrafcetFragment fragment{grafcet.steps(), grafcet.transitions()};
    for (GrafcetStep& step : fragment.steps)
        step.initial = false;
    return fragment;
}

} // namespace

std::string saveGrafcetFragmentJson(const GrafcetFragment& fragment)
{
    ordered_json root;
    root["format"] = kGrafcetFragmentFormatName;
    root["version"] = kGrafcetFragmentVersion;
    root["grafcet"] = nativeGrafcetJson(asGrafcet(fragment));
    return root.dump(2, ' ', false, ordered_json::error_handler_t::replace) + "\n";
}

std::variant<GrafcetFragment, JsonReadError> loadGrafcetFragmentJson(std::string_view text)
{
    if (text.size() > kMaxGrafcetFragmentBytes)
        return JsonReadError{"", std::to_string(text.size()) + " bytes; a fragment holds at most "
                                     + std::to_string(kMaxGrafcetFragmentBytes)};
    JsonReadError error;
    const std::optional<ordered_json> root = parseStrictJson(text, error);
    if (!root)
        return error;
    try {
        return buildFragment(*root);
    } catch (const JsonReadError& thrown) {
        return thrown;
    }
}

} // namespace core
