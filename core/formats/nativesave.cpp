// saveNativeJson (nativeformat.h): the model written straight to text with
// JsonWriter, in the key order and layout the format has always had (the
// ordered_json DOM dumped with two-space indentation); building and freeing
// that DOM was most of the time of a save (issue #36).

#include "core/formats/nativeformat.h"

#include "core/formats/jsonwriter.h"
#include "core/formats/nativemachinejson.h"
#include "core/formats/nativemodelparts.h"
#include "core/templates/gemma/gemmatemplate.h"
#include "core/templates/packml/packmlformat.h"

#include <algorithm>

namespace core {

namespace {

// Whether the model needs format 2.0 (nativeformat.h).
bool savesNestedFormat(const Model& model)
{
    const auto& variables = model.variables();
    return !model.grafcets().empty() || !model.properties().empty() || !model.machine().empty()
        || model.settings().evolution != EvolutionRule::OneEvolutionPerScan
        || std::any_of(variables.begin(), variables.end(),
                       [](const Variable& v) { return v.kind != VariableKind::Input; });
}

void writeSavedStep(JsonWriter& out, const Step& step)
{
    out.beginObject();
    out.key("type");
    out.string(stepTypeName(step.type));
    out.key("initial");
    out.boolean(step.initial);
    out.key("hidden");
    out.boolean(step.hidden);
    out.key("comment");
    out.string(step.comment);
    out.endObject();
}

void writeSavedTransition(JsonWriter& out, const Transition& transition)
{
    out.beginObject();
    out.key("condition");
    out.string(transition.condition);
    out.key("order");
    out.integer(transition.order);
    out.key("negated");
    out.boolean(transition.negated);
    out.key("hidden");
    out.boolean(transition.hidden);
    out.key("tokens");
    out.beginArray();
    for (const std::string& token : transition.tokens)
        out.string(token);
    out.endArray();
    out.endObject();
}

void writeSavedVariable(JsonWriter& out, const Variable& variable, bool nested)
{
    out.beginObject();
    out.key("name");
    out.string(variable.name);
    out.key("type");
    out.string(iecTypeName(variable.type));
    if (nested) {
        out.key("kind");
        out.string(variableKindName(variable.kind));
    }
    out.key("default");
    out.string(variable.defaultValue);
    out.key("comment");
    out.string(variable.comment);
    out.endObject();
}

void writeSavedStepSet(JsonWriter& out, const std::vector<int>& steps)
{
    out.beginArray();
    for (const int number : steps)
        out.integer(number);
    out.endArray();
}

void writeSavedGrafcet(JsonWriter& out, const Grafcet& grafcet)
{
    out.beginObject();
    out.key("steps");
    out.beginArray();
    for (const GrafcetStep& step : grafcet.steps()) {
        out.beginObject();
        out.key("number");
        out.integer(step.number);
        out.key("initial");
        out.boolean(step.initial);
        out.key("comment");
        out.string(step.comment);
        out.key("actions");
        out.beginArray();
        for (const GrafcetAction& action : step.actions) {
            out.beginObject();
            out.key("timing");
            out.string(nativeTimingName(action.timing));
            out.key("text");
            out.string(action.text);
            out.endObject();
        }
        out.endArray();
        out.endObject();
    }
    out.endArray();
    out.key("transitions");
    out.beginArray();
    for (const GrafcetTransition& transition : grafcet.transitions()) {
        out.beginObject();
        out.key("number");
        out.integer(transition.number);
        out.key("upstream");
        writeSavedStepSet(out, transition.upstream);
        out.key("downstream");
        writeSavedStepSet(out, transition.downstream);
        out.key("receptivity");
        out.string(transition.receptivity);
        out.endObject();
    }
    out.endArray();
    out.endObject();
}

} // namespace

std::string saveNativeJson(const Model& model)
{
    if (model.packml())
        return packml::saveJson(model);
    const bool nested = savesNestedFormat(model);
    JsonWriter out;
    out.beginObject();
    out.key("format");
    out.string(kNativeFormatName);
    out.key("version");
    out.string(nativeVersionText(nested ? 2 : 1));
    out.key("name");
    out.string(model.settings().name);
    out.key("settings");
    out.beginObject();
    out.key("cycleTimeMs");
    out.integer(model.settings().cycleTimeMs);
    out.key("dialect");
    out.string(dialectName(model.settings().dialect));
    if (nested) {
        out.key("evolution");
        out.string(evolutionRuleName(model.settings().evolution));
    }
    out.endObject();

    out.key("steps");
    out.beginObject();
    for (const Step& step : model.steps()) {
        out.key(step.id);
        writeSavedStep(out, step);
    }
    out.endObject();

    out.key("transitions");
    out.beginObject();
    for (const Transition& transition : model.transitions()) {
        out.key(transition.id);
        writeSavedTransition(out, transition);
    }
    out.endObject();

    out.key("variables");
    out.beginArray();
    for (const Variable& variable : model.variables())
        writeSavedVariable(out, variable, nested);
    out.endArray();

    if (nested) {
        out.key("grafcets");
        out.beginObject();
        for (const Step& step : model.steps()) {
            if (const Grafcet* grafcet = model.grafcet(step.id)) {
                out.key(step.id);
                writeSavedGrafcet(out, *grafcet);
            }
        }
        out.endObject();
    }
    if (!model.properties().empty()) {
        out.key("properties");
        out.value(nativePropertiesJson(model));
    }
    if (!model.machine().empty()) {
        out.key("machine");
        out.value(nativeMachineJson(model.machine()));
    }
    out.endObject();
    // Text from elsewhere may hold invalid UTF-8: JsonWriter replaces it as
    // nlohmann's dump does rather than throw.
    std::string text = out.take();
    text += '\n';
    return text;
}

} // namespace core
