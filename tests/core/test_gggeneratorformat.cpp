#include "filetestsupport.h"

#include "core/formats/gggeneratorformat.h"
#include "core/formats/nativeformat.h"

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <set>
#include <string>

namespace test_gggeneratorformat {

using namespace core;
using nlohmann::ordered_json;

namespace {

std::string referenceText()
{
    return filetests::readBinaryFile(std::filesystem::path(GGSTUDIO_REFERENCE_DIR) / "gg-generator/template.json");
}

ordered_json reference()
{
    return ordered_json::parse(referenceText());
}

std::unique_ptr<Model> loadOk(const std::string& text)
{
    auto result = loadGGGeneratorJson(text, "gg.json");
    if (const auto* error = std::get_if<LoadError>(&result))
        FAIL("unexpected load error: " << error->toString());
    return std::move(std::get<std::unique_ptr<Model>>(result));
}

LoadError loadError(const std::string& text)
{
    auto result = loadGGGeneratorJson(text, "gg.json");
    if (std::holds_alternative<std::unique_ptr<Model>>(result))
        FAIL("the file was accepted");
    return std::get<LoadError>(result);
}

// Index of the node with this name in a GG-Generator document.
std::size_t nodeIndex(const ordered_json& document, const std::string& name)
{
    for (std::size_t i = 0; i < document["nodes"].size(); ++i) {
        if (document["nodes"][i]["name"] == name)
            return i;
    }
    FAIL("no node " << name);
    return 0;
}

std::string nodeKey(const ordered_json& document, const std::string& name)
{
    return document["nodes"][nodeIndex(document, name)]["key"].get<std::string>();
}

// Index of the connection between two named nodes.
std::size_t connectionIndex(const ordered_json& document, const std::string& from, const std::string& to)
{
    const std::string fromKey = nodeKey(document, from);
    const std::string toKey = nodeKey(document, to);
    for (std::size_t i = 0; i < document["connections"].size(); ++i) {
        const ordered_json& connection = document["connections"][i];
        if (connection["from"] == fromKey && connection["to"] == toKey)
            return i;
    }
    FAIL("no connection " << from << " -> " << to);
    return 0;
}

ordered_json& connection(ordered_json& document, const std::string& from, const std::string& to)
{
    return document["connections"][connectionIndex(document, from, to)];
}

// What GG-Generator cannot hold, reset to the template's values.
void clearNativeOnly(Model& model)
{
    REQUIRE(model.setName("GEMMA"));
    REQUIRE(model.setCycleTimeMs(20));
    model.setDialect(Dialect::Iec);
    for (const TemplateState& state : templateStates())
        REQUIRE(model.setStepComment(state.id, ""));
    std::vector<std::string> names;
    for (const Variable& variable : model.variables())
        names.push_back(variable.name);
    for (const std::string& name : names)
        REQUIRE(model.setVariableComment(name, ""));
}

} // namespace

TEST_CASE("The GG-Generator reference file imports as the template", "[files]")
{
    const auto model = loadOk(referenceText());
    CHECK(model->sameContent(Model()));
    // Its remembered Stop and EmptyMachine settings name no declared signal: no tokens.
    CHECK(model->transition("F1->A2")->tokens.empty());
    CHECK(model->transition("F1->F3")->tokens.empty());
}

TEST_CASE("A model survives native -> GG-Generator -> native in everything both express", "[files]")
{
    const Model rich = filetests::richNativeModel();
    const auto imported = loadOk(saveGGGeneratorJson(*loadOk(saveGGGeneratorJson(rich))));
    Model expected(rich);
    clearNativeOnly(expected);
    CHECK(imported->sameContent(expected));
    CHECK(saveNativeJson(*imported) == saveNativeJson(expected));
    CHECK(imported->invariantViolations().empty());
}

TEST_CASE("The template survives a GG-Generator export and import", "[files]")
{
    CHECK(loadOk(saveGGGeneratorJson(Model()))->sameContent(Model()));
}

TEST_CASE("GG-Generator export is deterministic and well formed", "[files]")
{
    const Model model = filetests::richGGModel();
    const std::string text = saveGGGeneratorJson(model);
    CHECK(text == saveGGGeneratorJson(Model(model)));
    CHECK(text.back() == '\n');

    const ordered_json document = ordered_json::parse(text);
    REQUIRE(document["nodes"].size() == 19);
    REQUIRE(document["connections"].size() == 34);
    std::set<std::string> keys;
    for (const ordered_json& node : document["nodes"])
        keys.insert(node["key"].get<std::string>());
    CHECK(keys.size() == 19);
    keys.insert(document["graph"]["key"].get<std::string>());
    CHECK(keys.size() == 20);
    for (const ordered_json& c : document["connections"]) {
        CHECK(keys.count(c["from"].get<std::string>()) == 1);
        CHECK(keys.count(c["to"].get<std::string>()) == 1);
    }

    const ordered_json& frame = document["nodes"][nodeIndex(document, "F family")];
    CHECK(frame["data"]["type"] == "CONTAINER");
    CHECK(frame["width"].get<double>() > 0);
    const ordered_json& a1 = document["nodes"][nodeIndex(document, "A1")];
    CHECK(a1["data"] == ordered_json({{"family", "A"}, {"type", "MACRO"}, {"isInitial", true}}));
    CHECK(document["nodes"][nodeIndex(document, "F6")]["isHidden"] == true);

    const ordered_json signals = document["graph"]["data"]["signals"];
    REQUIRE(signals.size() == model.variables().size());
    CHECK(signals[0] == ordered_json({{"name", "Start"}, {"type", "bool"}, {"defaultValue", ""}}));
    CHECK(signals[3]["type"] == "int");
    CHECK(signals[5]["type"] == "usint");
}

TEST_CASE("GG-Generator export writes tokens with their contact behaviour", "[files]")
{
    ordered_json document = ordered_json::parse(saveGGGeneratorJson(filetests::richGGModel()));
    const ordered_json expectedA1 = ordered_json::parse(
        R"({"Stop": {"withMemory": true, "behaviour": "NC"}, "Start": {"withMemory": true, "behaviour": "NO"}})");
    CHECK(connection(document, "A1", "F4")["data"]["savedSignalsWithMemory"] == expectedA1);
    CHECK(connection(document, "F1", "A2")["data"]["savedSignalsWithMemory"]
        == ordered_json::parse(R"({"Stop": {"withMemory": true, "behaviour": "NC"}})"));
    CHECK(connection(document, "F1", "F3")["data"]["savedSignalsWithMemory"]["Start"]["behaviour"] == "NO");
    CHECK_FALSE(connection(document, "F1", "D3")["data"].contains("savedSignalsWithMemory"));
    CHECK(connection(document, "F1", "A2")["data"]["priority"] == 1);
    CHECK(connection(document, "F5", "F1")["data"]["isNegated"] == true);
    CHECK(connection(document, "F family", "D1")["isHidden"] == true);
}

TEST_CASE("GG-Generator import keeps only tokens on declared BOOL signals of the condition", "[files]")
{
    ordered_json document = reference();
    document["graph"]["data"]["signals"] = ordered_json::parse(R"([
        {"name": "Stop", "type": "bool", "defaultValue": ""},
        {"name": "EmptyMachine", "type": "bool", "defaultValue": "FALSE"},
        {"name": "Count", "type": "int", "defaultValue": 3},
        {"name": "Manual", "type": "BOOL", "defaultValue": null}])");
    ordered_json& f1a2 = connection(document, "F1", "A2");
    f1a2["data"]["conditionExpression"] = "NOT stop";
    ordered_json& f1f3 = connection(document, "F1", "F3");
    f1f3["data"]["conditionExpression"] = "Manual"; // EmptyMachine is remembered but absent
    ordered_json& f1f4 = connection(document, "F1", "F4");
    f1f4["data"]["conditionExpression"] = "Manual AND Count > 2 AND Unknown";
    f1f4["data"]["savedSignalsWithMemory"] = ordered_json::parse(R"({
        "Count": {"withMemory": true, "behaviour": "NO"},
        "Unknown": {"withMemory": true, "behaviour": "NO"},
        "manual": {"withMemory": true, "behaviour": "NO"},
        "MANUAL": {"withMemory": true, "behaviour": "NC"}})");
    ordered_json& f1f5 = connection(document, "F1", "F5");
    f1f5["data"]["conditionExpression"] = "Manual";
    f1f5["data"]["savedSignalsWithMemory"] = ordered_json::parse(R"({"Manual": {"withMemory": false, "behaviour": "NO"}})");

    const auto model = loadOk(document.dump());
    CHECK(model->transition("F1->A2")->tokens == std::vector<std::string>{"Stop"});
    CHECK(model->transition("F1->F3")->tokens.empty());
    CHECK(model->transition("F1->F4")->tokens == std::vector<std::string>{"Manual"});
    CHECK(model->transition("F1->F5")->tokens.empty());
    CHECK(model->variable("Count")->defaultValue == "3");
    CHECK(model->variable("Manual")->defaultValue.empty());
    CHECK(model->variable("Manual")->type == IecType::Bool);
}

TEST_CASE("GG-Generator import reads priorities, negations, hidden elements and the initial step", "[files]")
{
    ordered_json document = reference();
    document["nodes"][nodeIndex(document, "A6")]["data"]["isInitial"] = false;
    document["nodes"][nodeIndex(document, "F2")]["data"]["isInitial"] = true;
    document["nodes"][nodeIndex(document, "D3")]["isHidden"] = true;
    document["nodes"][nodeIndex(document, "D2")]["data"]["type"] = "MACRO";
    connection(document, "D1", "A5")["data"]["priority"] = 2;
    connection(document, "D1", "D2")["data"]["priority"] = 1;
    connection(document, "F6", "F1")["data"]["isNegated"] = true;
    connection(document, "A1", "F5")["isHidden"] = true;
    document["nodes"][nodeIndex(document, "F family")]["isHidden"] = true;

    const auto model = loadOk(document.dump());
    CHECK(model->initialStep().id == "F2");
    CHECK(model->step("D3")->hidden);
    CHECK(model->step("D2")->type == StepType::Macro);
    CHECK(model->transition("D1->D2")->order == 1);
    CHECK(model->transition("D1->A5")->order == 2);
    CHECK(model->transition("F6->F1")->negated);
    CHECK(model->transition("A1->F5")->hidden);
    CHECK(model->transition("F->D1")->hidden); // the hidden F frame switches its family transition off
    CHECK(model->invariantViolations().empty());
}

TEST_CASE("GG-Generator: a node with an unknown name is refused", "[files]")
{
    ordered_json document = reference();
    const std::size_t index = nodeIndex(document, "A3");
    document["nodes"][index]["name"] = "A8";
    const LoadError error = loadError(document.dump());
    CHECK(error.location == "/nodes/" + std::to_string(index) + "/name");
    CHECK_THAT(error.message, Catch::StartsWith("unknown node \"A8\""));
}

TEST_CASE("GG-Generator: a connection the template lacks is refused", "[files]")
{
    ordered_json document = reference();
    ordered_json& first = document["connections"][0];
    first["from"] = nodeKey(document, "A1");
    first["to"] = nodeKey(document, "D3");
    LoadError error = loadError(document.dump());
    CHECK(error.toString() == "gg.json: /connections/0: the GEMMA template has no transition from A1 to D3");

    document = reference();
    document["connections"][2]["to"] = "no-such-key";
    error = loadError(document.dump());
    CHECK(error.toString() == "gg.json: /connections/2/to: no node has the key \"no-such-key\"");

    document = reference();
    document["connections"].push_back(document["connections"][5]);
    error = loadError(document.dump());
    CHECK(error.location == "/connections/34");
    CHECK_THAT(error.message, Catch::StartsWith("a second connection from D1 to D2"));
}

TEST_CASE("GG-Generator: bad nodes, priorities, signals and JSON are refused", "[files]")
{
    ordered_json document = reference();
    document["nodes"].push_back(document["nodes"][1]);
    CHECK_THAT(loadError(document.dump()).message, Catch::StartsWith("a second node named \"A3\""));

    document = reference();
    document["nodes"][nodeIndex(document, "D1")]["data"]["isInitial"] = true;
    LoadError error = loadError(document.dump());
    CHECK_THAT(error.message, Catch::StartsWith("a second initial step"));

    document = reference();
    document["nodes"][nodeIndex(document, "A1")]["data"]["type"] = "CONTAINER";
    CHECK_THAT(loadError(document.dump()).message, Catch::StartsWith("a GEMMA state cannot be a CONTAINER"));

    document = reference();
    connection(document, "A5", "A7")["data"]["priority"] = 3;
    error = loadError(document.dump());
    CHECK(error.location == "/connections/" + std::to_string(connectionIndex(document, "A5", "A7")) + "/data/priority");
    CHECK(error.message == "expected an integer from 1 to 2, found 3");

    document = reference();
    document["graph"]["data"]["signals"] = ordered_json::parse(R"([{"name": "Label", "type": "string", "defaultValue": ""}])");
    CHECK(loadError(document.dump()).toString() == "gg.json: /graph/data/signals/0/type: unknown type \"string\"; "
                                                   "expected bool, sint, int, dint, lint, usint, uint, udint, ulint, real or lreal");

    document["graph"]["data"]["signals"] = ordered_json::parse(
        R"([{"name": "Go", "type": "bool", "defaultValue": ""}, {"name": "GO", "type": "bool", "defaultValue": ""}])");
    CHECK(loadError(document.dump()).location == "/graph/data/signals/1/name");

    CHECK(loadError(R"({"graph": {}, "nodes": []})").toString()
        == "gg.json: /connections: missing; a GG-Generator file has \"nodes\" and \"connections\"");
    CHECK(loadError("{\"nodes\": [}").location == "line 1, column 12");
}

TEST_CASE("GG-Generator format detection", "[files]")
{
    CHECK(looksLikeGGGeneratorJson(referenceText()));
    CHECK(looksLikeGGGeneratorJson(saveGGGeneratorJson(Model())));
    CHECK_FALSE(looksLikeGGGeneratorJson(saveNativeJson(Model())));
}

TEST_CASE("GG-Generator export says what of the nested layer it leaves out", "[files][gggenerator]")
{
    core::Model model;
    CHECK(core::ggGeneratorLosses(model).empty());
    REQUIRE(model.addGrafcetStep("F1", {1, true, "", {}}));
    core::Variable lamp{"Lamp", core::IecType::Bool, "", ""};
    lamp.kind = core::VariableKind::Output;
    REQUIRE(model.addVariable(lamp));
    model.setEvolutionRule(core::EvolutionRule::UntilStable);
    REQUIRE(model.addGrafcetStep("F2", {1, true, "", {}}));
    const std::vector<core::GGGeneratorLoss> losses = core::ggGeneratorLosses(model);
    REQUIRE(losses.size() == 3);
    CHECK(losses[0].kind == core::GGGeneratorLoss::Kind::NestedGrafcets);
    CHECK(losses[0].steps == std::vector<std::string>{"F1", "F2"});
    CHECK(core::toText(losses[0])
          == "the nested GRAFCETs of F1, F2 are left out: GG-Generator has no place for nested behaviour");
    CHECK(losses[1].kind == core::GGGeneratorLoss::Kind::VariableKinds);
    CHECK(losses[2].kind == core::GGGeneratorLoss::Kind::UntilStableRule);
    CHECK(core::toText(losses[2]) == "the until-stable evolution rule is left out");
    // And indeed nothing of it is in the file.
    CHECK(core::saveGGGeneratorJson(model).find("Initialization") == std::string::npos);
}

TEST_CASE("GG-Generator import names GG Studio's keys it does not load", "[files][gggenerator]")
{
    // Loading used to drop them without a word, with exit code 0.
    ordered_json file = reference();
    file["grafcets"] = {{"F1", {{"steps", ordered_json::array()}}}, {"F3", {{"steps", ordered_json::array()}}}};
    file["properties"] = ordered_json::array({{{"text", "never A1 AND F1"}}});
    file["settings"] = {{"evolution", "until-stable"}};
    file["graph"]["data"]["signals"] = ordered_json::array({{{"name", "Done"}, {"type", "bool"}, {"kind", "output"}}});
    std::vector<LoadWarning> warnings;
    auto result = loadGGGeneratorJson(file.dump(), "mixed.json", &warnings);
    REQUIRE(std::holds_alternative<std::unique_ptr<Model>>(result));
    std::vector<std::string> texts;
    for (const LoadWarning& warning : warnings)
        texts.push_back(warning.toString());
    CHECK(texts == std::vector<std::string>{
        "mixed.json: /grafcets: warning: the nested GRAFCETs of F1, F3 are not loaded: a GG-Generator file has no "
        "place for nested behaviour",
        "mixed.json: /properties: warning: the verification properties (1) are not loaded: a GG-Generator file has "
        "no place for them",
        "mixed.json: /settings/evolution: warning: the setting \"evolution\" (\"until-stable\") is not loaded: a "
        "GG-Generator file has no place for settings",
        "mixed.json: /graph/data/signals/0/kind: warning: the variable kind \"output\" is not loaded: GG-Generator "
        "reads every signal as an input",
    });

    // The tool's own file, and a GG Studio export, carry none.
    warnings = {{"x", "", "stale"}};
    REQUIRE(std::holds_alternative<std::unique_ptr<Model>>(loadGGGeneratorJson(referenceText(), "gg.json", &warnings)));
    CHECK(warnings.empty());
    REQUIRE(std::holds_alternative<std::unique_ptr<Model>>(
        loadGGGeneratorJson(saveGGGeneratorJson(filetests::richNativeModel()), "gg.json", &warnings)));
    CHECK(warnings.empty());
}

} // namespace test_gggeneratorformat
