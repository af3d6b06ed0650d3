#include "filetestsupport.h"
#include "nativeloadchecks.h"

#include "core/formats/nativeformat.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace test_nativeformat {

using namespace core;

namespace {

const std::string kHeader = "{\"format\": \"ggstudio-model\", \"version\": \"1.0\"";

using filetests::loadError;
using filetests::loadOk;

// A minimal file with the given members after the header.
std::string nativeFile(const std::string& members)
{
    return kHeader + (members.empty() ? "" : ", " + members) + "}";
}

} // namespace

TEST_CASE("The template survives a native save and load", "[files]")
{
    const auto loaded = loadOk(saveNativeJson(Model()));
    CHECK(loaded->sameContent(Model()));
    CHECK(loaded->invariantViolations().empty());
}

TEST_CASE("A rich model survives a native save and load", "[files]")
{
    const Model model = filetests::richNativeModel();
    const auto loaded = loadOk(saveNativeJson(model));
    CHECK(loaded->sameContent(model));
    CHECK(loaded->invariantViolations().empty());
    CHECK(loaded->initialStep().id == "A1");
    CHECK(loaded->transition("F1->A2")->order == 1);
    CHECK(loaded->settings().dialect == Dialect::Codesys);
}

TEST_CASE("Native save, load, save is byte-identical", "[files]")
{
    for (const Model& model : {Model(), filetests::richGGModel(), filetests::richNativeModel()}) {
        const std::string first = saveNativeJson(model);
        const std::string second = saveNativeJson(*loadOk(first));
        CHECK(first == second);
    }
}

TEST_CASE("The native file layout is fixed", "[files]")
{
    const std::string text = saveNativeJson(Model());
    CHECK_THAT(text, Catch::StartsWith("{\n  \"format\": \"ggstudio-model\",\n  \"version\": \"1.0\",\n"
                                       "  \"name\": \"GEMMA\",\n  \"settings\": {\n    \"cycleTimeMs\": 20,\n"
                                       "    \"dialect\": \"iec\"\n  },\n  \"steps\": {\n    \"A1\": {\n"
                                       "      \"type\": \"simple\",\n      \"initial\": false,\n"
                                       "      \"hidden\": false,\n      \"comment\": \"\"\n    },\n"));
    CHECK_THAT(text, Catch::Contains("  \"transitions\": {\n    \"F->D1\": {\n      \"condition\": \"\",\n"
                                     "      \"order\": 1,\n      \"negated\": false,\n      \"hidden\": false,\n"
                                     "      \"tokens\": []\n    },\n    \"A1->F4\": {"));
    CHECK_THAT(text, Catch::EndsWith("  \"variables\": []\n}\n"));
}

TEST_CASE("The golden native file still loads to the rich model and is written the same", "[files]")
{
    const std::filesystem::path golden = std::filesystem::path(GGSTUDIO_TEST_DATA_DIR) / "rich-model.ggstudio.json";
    const std::string text = filetests::readBinaryFile(golden);
    CHECK(loadOk(text)->sameContent(filetests::richNativeModel()));
    CHECK(saveNativeJson(filetests::richNativeModel()) == text);
}

TEST_CASE("A native file may leave out what keeps its template default", "[files]")
{
    CHECK(loadOk(nativeFile(""))->sameContent(Model()));

    const auto model = loadOk(nativeFile(R"("steps": {"F1": {"initial": true}, "D3": {"hidden": true}},
        "transitions": {"F1->A3": {"order": 1}, "F1->D1": {"order": 7}}, "variables": [{"name": "Start", "type": "bool"}])"));
    CHECK(model->initialStep().id == "F1");
    CHECK_FALSE(model->step("A6")->initial);
    CHECK(model->step("D3")->hidden);
    CHECK(model->step("D3")->type == StepType::Enclosing);
    CHECK(model->transition("F1->A3")->order == 1);
    CHECK(model->transition("F1->D1")->order == 7);
    CHECK(model->transition("F1->D3")->order == 2); // not in the file: keeps its order
    CHECK(model->transition("F1->D2")->order == 9);
    REQUIRE(model->variables().size() == 1);
    CHECK(model->variables()[0].type == IecType::Bool);
    CHECK(model->invariantViolations().empty());
}

TEST_CASE("A newer minor version with unknown keys is read", "[files]")
{
    const auto model = loadOk(R"({"format": "ggstudio-model", "version": "1.7", "futureSetting": {"a": [1, 2]},
        "settings": {"cycleTimeMs": 50, "colour": "red"},
        "steps": {"A2": {"hidden": true, "icon": "x"}},
        "transitions": {"A2->A1": {"condition": "TRUE", "weight": 3}},
        "variables": [{"name": "Go", "type": "BOOL", "unit": "none"}]})");
    CHECK(model->settings().cycleTimeMs == 50);
    CHECK(model->step("A2")->hidden);
    CHECK(model->transition("A2->A1")->condition == "TRUE");
    CHECK(model->variable("go") != nullptr);
}

TEST_CASE("Native: malformed JSON is reported with line and column", "[files]")
{
    const LoadError error = loadError("{\n  \"format\": \"ggstudio-model\",\n  \"version\": \"1.0\",\n"
                                      "  \"name\": \"x\"\n  \"steps\": {}\n}\n");
    CHECK(error.file == "test.json");
    CHECK(error.location == "line 5, column 9"); // where the parser stopped: the end of "steps"
    CHECK_THAT(error.message, Catch::StartsWith("malformed JSON: syntax error"));

    const LoadError truncated = loadError("{\"format\": \"ggstudio-model\", \"version\": \"1.0\", \"name\": \"x");
    CHECK_THAT(truncated.location, Catch::StartsWith("line 1, column "));
    CHECK_THAT(truncated.message, Catch::StartsWith("malformed JSON"));

    CHECK(loadError("{\"format\": \"ggstudio-model\", /* comment */ \"version\": \"1.0\"}").location
        == "line 1, column 30");
}

TEST_CASE("Native: a value of the wrong type is reported at its JSON path", "[files]")
{
    LoadError error = loadError(nativeFile(R"("steps": {"F1": {"hidden": "yes"}})"));
    CHECK(error.toString() == "test.json: /steps/F1/hidden: expected true or false, found \"yes\"");

    error = loadError(nativeFile(R"("transitions": {"F1->A2": {"order": "2"}})"));
    CHECK(error.location == "/transitions/F1->A2/order");
    CHECK(error.message == "expected an integer from 1 to 9, found \"2\"");

    error = loadError(nativeFile(R"("transitions": {"A2->A1": {"condition": 5}})"));
    CHECK(error.toString() == "test.json: /transitions/A2->A1/condition: expected a string, found 5");

    error = loadError(nativeFile(R"("transitions": {"F1->A2": {"tokens": "Stop"}})"));
    CHECK(error.toString() == "test.json: /transitions/F1->A2/tokens: expected an array, found \"Stop\"");

    error = loadError(nativeFile(R"("variables": {"Start": "BOOL"})"));
    CHECK(error.toString() == "test.json: /variables: expected an array, found an object");

    error = loadError(nativeFile(R"("steps": {"A1": {"type": "macrostep"}})"));
    CHECK(error.location == "/steps/A1/type");
    CHECK(error.message == "unknown step type \"macrostep\"; expected \"simple\", \"macro\" or \"enclosing\"");

    error = loadError(nativeFile(R"("settings": {"dialect": "beckhoff"})"));
    CHECK(error.toString() == "test.json: /settings/dialect: unknown dialect \"beckhoff\"; expected \"iec\" or \"codesys\"");

    error = loadError("[1, 2]");
    CHECK(error.toString() == "test.json: expected an object, found an array");
}

TEST_CASE("Native: an unknown step id is refused", "[files]")
{
    const LoadError error = loadError(nativeFile(R"("steps": {"A1": {}, "X9": {"hidden": true}})"));
    CHECK(error.location == "/steps/X9");
    CHECK(error.message == "unknown step \"X9\"; the template's steps are A1 to A7, F1 to F6 and D1 to D3");
}

TEST_CASE("Native: an unknown transition id is refused", "[files]")
{
    const LoadError error = loadError(nativeFile(R"("transitions": {"A1->D3": {"condition": "TRUE"}})"));
    CHECK(error.location == "/transitions/A1->D3");
    CHECK_THAT(error.message, Catch::StartsWith("unknown transition \"A1->D3\""));

    CHECK(loadError(nativeFile(R"("transitions": {"a/b~c": {}})")).location == "/transitions/a~1b~0c");
}

TEST_CASE("Native: a duplicate key is refused", "[files]")
{
    LoadError error = loadError(nativeFile(R"("steps": {"A1": {"hidden": true}, "A1": {"hidden": false}})"));
    CHECK(error.location == "/steps/A1");
    CHECK(error.message == "duplicate key \"A1\" (each key may appear once per object)");

    error = loadError(nativeFile(R"("variables": [{"name": "A", "type": "BOOL", "name": "B"}])"));
    CHECK(error.location == "/variables/0/name");

    error = loadError(R"({"format": "ggstudio-model", "version": "1.0", "version": "2.0"})");
    CHECK(error.location == "/version");
    CHECK_THAT(error.message, Catch::StartsWith("duplicate key"));
}

TEST_CASE("Native: a cycle time out of range is refused", "[files]")
{
    LoadError error = loadError(nativeFile(R"("settings": {"cycleTimeMs": 0})"));
    CHECK(error.toString() == "test.json: /settings/cycleTimeMs: expected an integer from 1 to 3600000, found 0");
    error = loadError(nativeFile(R"("settings": {"cycleTimeMs": 3600001})"));
    CHECK(error.message == "expected an integer from 1 to 3600000, found 3600001");
    error = loadError(nativeFile(R"("settings": {"cycleTimeMs": 20.5})"));
    CHECK(error.message == "expected an integer from 1 to 3600000, found 20.5");
    error = loadError(nativeFile(R"("settings": {"cycleTimeMs": 18446744073709551616})"));
    CHECK(error.location == "/settings/cycleTimeMs");
    CHECK(loadOk(nativeFile(R"("settings": {"cycleTimeMs": 3600000})"))->settings().cycleTimeMs == 3600000);
}

TEST_CASE("Native: orders out of range or repeated are refused", "[files]")
{
    LoadError error = loadError(nativeFile(R"("transitions": {"A1->F4": {"order": 5}})"));
    CHECK(error.toString() == "test.json: /transitions/A1->F4/order: expected an integer from 1 to 4, found 5");
    error = loadError(nativeFile(R"("transitions": {"A1->F4": {"order": 0}})"));
    CHECK(error.location == "/transitions/A1->F4/order");

    error = loadError(nativeFile(R"("transitions": {"A1->F4": {"order": 2}})"));
    CHECK(error.location == "/transitions/A1->F4/order");
    CHECK(error.message == "order 2 is also the order of A1->F2; the 4 transitions leaving A1 need the orders 1 to 4, each once");

    error = loadError(nativeFile(R"("transitions": {"D1->A5": {"order": 1}, "D1->D2": {"order": 1}})"));
    CHECK(error.location == "/transitions/D1->D2/order");

    // A consistent permutation given in full is fine.
    const auto model = loadOk(nativeFile(R"("transitions": {"D1->A5": {"order": 2}, "D1->D2": {"order": 1}})"));
    CHECK(model->transition("D1->D2")->order == 1);
    CHECK(model->transition("D1->A5")->order == 2);
}

TEST_CASE("Native: invalid UTF-8 is reported with line and column", "[files]")
{
    const LoadError error = loadError("{\"format\": \"ggstudio-model\",\n\"version\": \"1.0\",\n"
                                      "\"name\": \"d\xC3\xA9j\xE0 vu\"}");
    CHECK(error.toString() == "test.json: line 3, column 13: invalid UTF-8: the file must be UTF-8 text");
}

TEST_CASE("Native: nesting deeper than 64 levels is refused", "[files]")
{
    // The root object is level 1, so 63 arrays inside it are allowed and 64 are not.
    // A newer minor version, where the unknown key "extra" is allowed.
    const std::string header = "{\"format\": \"ggstudio-model\", \"version\": \"1.1\"";
    const auto nested = [&](int depth) {
        return header + ", \"extra\": " + std::string(static_cast<std::size_t>(depth), '[')
            + std::string(static_cast<std::size_t>(depth), ']') + "}";
    };
    CHECK(loadOk(nested(63))->sameContent(Model()));
    const LoadError error = loadError(nested(64));
    CHECK(error.message == "nesting deeper than 64 levels");
    CHECK(error.location == "line 1, column " + std::to_string(header.size() + 11 + 64));

    // Brackets inside strings do not count.
    CHECK(loadOk(nativeFile("\"name\": \"" + std::string(100, '[') + "\""))->settings().name == std::string(100, '['));
    // Far deeper input fails the same way, without exhausting the stack.
    CHECK(loadError(std::string(100000, '[')).message == "nesting deeper than 64 levels");
}

TEST_CASE("Native: a NUL byte is an error at its place, not the end of the file", "[files]")
{
    // nlohmann's lexer stops at a NUL: the header alone used to load as the template.
    const std::string headerThenGarbage = nativeFile("") + "\n" + std::string("\0", 1) + "garbage";
    CHECK(loadError(headerThenGarbage).toString()
        == "test.json: line 2, column 1: a NUL byte outside any string: JSON text cannot contain one");

    // Nor may a whole model hide what follows it.
    const std::string modelThenMore = saveNativeJson(Model()) + std::string("\0", 1) + "{\"steps\": 5}";
    const LoadError error = loadError(modelThenMore);
    CHECK_THAT(error.location, Catch::StartsWith("line "));
    CHECK_THAT(error.message, Catch::StartsWith("a NUL byte"));

    // A raw NUL inside a string is located too, with the escape that writes
    // it (the advice used to offer the escape for an outside NUL as well).
    const LoadError inside = loadError(nativeFile("\"name\": \"a" + std::string("\0", 1) + "b\""));
    CHECK(inside.location == "line 1, column " + std::to_string(kHeader.size() + 13));
    CHECK(inside.message == "a NUL byte inside a string: JSON text cannot contain one raw");
    CHECK(inside.advice == "write it as \\u0000");
    CHECK(inside.toString() == "test.json: " + inside.location
                                   + ": a NUL byte inside a string: JSON text cannot contain one raw; write it as "
                                     "\\u0000");
    // A quote escaped inside a string does not end it.
    CHECK(loadError(nativeFile("\"name\": \"a\\\"" + std::string("\0", 1) + "\"")).message
        == "a NUL byte inside a string: JSON text cannot contain one raw");
    CHECK(loadOk(nativeFile(R"("name": "a\u0000b")"))->settings().name == std::string("a\0b", 3));
}

TEST_CASE("Native: an unknown key in a file of this version is refused with its JSON path", "[files]")
{
    // A misspelt "hidden" used to be skipped, leaving the step visible.
    CHECK(loadError(nativeFile(R"("steps": {"F1": {"hiden": true}})")).toString()
        == "test.json: /steps/F1/hiden: unknown key \"hiden\" in a step; format 1.0 knows \"type\", \"initial\", "
           "\"hidden\" and \"comment\"");

    struct Case {
        std::string members;
        std::string location;
    };
    const std::vector<Case> cases = {
        {R"("nmae": "Press")", "/nmae"},
        {R"("settings": {"cycleTime": 50})", "/settings/cycleTime"},
        {R"("transitions": {"F1->A2": {"condition": "TRUE", "negate": true}})", "/transitions/F1->A2/negate"},
        {R"("variables": [{"name": "Go", "type": "BOOL"}, {"name": "Stop", "type": "BOOL", "defualt": "TRUE"}])",
         "/variables/1/defualt"},
        {R"("steps": {"A1": {"comment": "x", "a/b~": 1}})", "/steps/A1/a~1b~0"},
    };
    for (const Case& c : cases) {
        INFO(c.members);
        const LoadError error = loadError(nativeFile(c.members));
        CHECK(error.location == c.location);
        CHECK_THAT(error.message, Catch::StartsWith("unknown key \""));
    }
    CHECK(loadError(nativeFile(R"("settings": {"cycleTime": 50})")).message
        == "unknown key \"cycleTime\" in the settings; format 1.0 knows \"cycleTimeMs\" and \"dialect\"");
    CHECK(loadError(nativeFile(R"("nmae": "Press")")).message
        == "unknown key \"nmae\" in a model file; format 1.0 knows \"format\", \"version\", \"name\", \"settings\", "
           "\"steps\", \"transitions\" and \"variables\"");
}

TEST_CASE("Native: a version is two whole numbers, nothing else", "[files]")
{
    for (const char* version : {"1.-1", "-1.0", "+1.0", "1.+0", " 1.0", "1.0 ", "1. 0", "1.", ".0", "1..0", "1.0.0",
                                "1,0", "1.0a", "01.0", "1.00", "1.01", "1", ""}) {
        INFO(version);
        const LoadError error = loadError(std::string("{\"format\": \"ggstudio-model\", \"version\": \"") + version + "\"}");
        CHECK(error.location == "/version");
        CHECK(error.message == std::string("expected a version MAJOR.MINOR of two whole numbers such as \"1.0\", found \"")
            + version + "\"");
    }
    // Numbers too large for an int are still versions, newer than any real one.
    CHECK(loadOk(R"({"format": "ggstudio-model", "version": "1.99999999999", "later": 1})")->sameContent(Model()));
    CHECK_THAT(loadError(R"({"format": "ggstudio-model", "version": "99999999999.0"})").message,
               Catch::StartsWith("this file was written by a newer GG Studio"));
    CHECK(loadOk(R"({"format": "ggstudio-model", "version": "1.10", "later": 1})")->sameContent(Model()));
}

TEST_CASE("Native: a newer major version is refused", "[files]")
{
    const LoadError error = loadError(R"({"format": "ggstudio-model", "version": "3.0", "steps": {"Z1": 5}})");
    CHECK(error.toString()
        == "test.json: /version: this file was written by a newer GG Studio (format 3.0); this version reads "
           "formats 1.x and 2.x");

    CHECK(loadError(R"({"format": "ggstudio-model", "version": "0.9"})").message
        == "unsupported format version 0.9; this version reads formats 1.x and 2.x");
    CHECK(loadError(R"({"format": "ggstudio-model", "version": "1"})").location == "/version");
    CHECK(loadError(R"({"format": "ggstudio-model", "version": 1.0})").message == "expected a string, found 1.0");
    CHECK(loadError(R"({"format": "ggstudio-model"})").toString()
        == "test.json: /version: missing; expected a version such as \"1.0\"");
}

TEST_CASE("Native: the format name is required", "[files]")
{
    CHECK(loadError(R"({"version": "1.0"})").toString()
        == "test.json: /format: missing; a GG Studio model file has \"format\": \"ggstudio-model\"");
    CHECK(loadError(R"({"format": "other", "version": "1.0"})").message
        == "expected \"ggstudio-model\", found \"other\"");
}

TEST_CASE("Native: two initial steps are refused", "[files]")
{
    LoadError error = loadError(nativeFile(R"("steps": {"F1": {"initial": true}, "A1": {"initial": true}})"));
    CHECK(error.toString()
        == "test.json: /steps/A1/initial: a second initial step (F1 is initial too); exactly one step must be initial");

    error = loadError(nativeFile(R"("steps": {"A6": {"initial": false}})"));
    CHECK(error.toString() == "test.json: /steps: no initial step; exactly one step must be initial");
}

TEST_CASE("Native: variable names must be present and unique ignoring case", "[files]")
{
    LoadError error = loadError(nativeFile(
        R"("variables": [{"name": "Start", "type": "BOOL"}, {"name": "Stop", "type": "BOOL"}, {"name": "START", "type": "INT"}])"));
    CHECK(error.toString() == "test.json: /variables/2/name: duplicate variable name \"START\": "
                              "/variables/0/name is \"Start\" (names are compared ignoring case)");

    error = loadError(nativeFile(R"("variables": [{"name": "", "type": "BOOL"}])"));
    CHECK(error.toString() == "test.json: /variables/0/name: empty variable name");

    error = loadError(nativeFile(R"("variables": [{"type": "BOOL"}])"));
    CHECK(error.location == "/variables/0/name");
}

TEST_CASE("Native: an unknown IEC type is refused", "[files]")
{
    const LoadError error = loadError(nativeFile(R"("variables": [{"name": "Label", "type": "STRING"}])"));
    CHECK(error.toString() == "test.json: /variables/0/type: unknown type \"STRING\"; expected BOOL, SINT, INT, "
                              "DINT, LINT, USINT, UINT, UDINT, ULINT, REAL or LREAL");
}

TEST_CASE("Native: a repeated token is refused", "[files]")
{
    const LoadError error = loadError(nativeFile(
        R"("variables": [{"name": "Stop", "type": "BOOL"}], "transitions": {"F1->A2": {"tokens": ["Stop", "STOP"]}})"));
    CHECK(error.location == "/transitions/F1->A2/tokens");
}

TEST_CASE("Native format detection", "[files]")
{
    CHECK(looksLikeNativeJson(saveNativeJson(Model())));
    CHECK(looksLikeNativeJson("\xEF\xBB\xBF{ \"format\" :\n\"ggstudio-model\" }"));
    CHECK_FALSE(looksLikeNativeJson("{\"name\": \"ggstudio-model\"}"));
    CHECK_FALSE(looksLikeNativeJson("[\"format\", \"ggstudio-model\"]"));
    CHECK_FALSE(looksLikeNativeJson(""));
}

TEST_CASE("Native: more variables than a model may hold are refused", "[files]")
{
    std::string list;
    for (int i = 0; i <= 10000; ++i)
        list += std::string(i ? "," : "") + "{\"name\": \"V" + std::to_string(i) + "\", \"type\": \"BOOL\"}";
    const LoadError error = loadError(nativeFile("\"variables\": [" + list + "]"));
    CHECK(error.toString() == "test.json: /variables: 10001 variables; a model holds at most 10000");
}

// ---- format 2.0: nested GRAFCETs, variable kinds, the evolution rule ---------

namespace {

Model nestedModel()
{
    Model model;
    REQUIRE(model.addVariable(Variable{"Start", IecType::Bool, "", "start button"}));
    Variable lamp{"Lamp", IecType::Bool, "", ""};
    lamp.kind = VariableKind::Output;
    REQUIRE(model.addVariable(lamp));
    Variable count{"Count", IecType::Int, "0", ""};
    count.kind = VariableKind::Internal;
    REQUIRE(model.addVariable(count));
    model.setEvolutionRule(EvolutionRule::UntilStable);
    REQUIRE(model.addGrafcetStep("F1", GrafcetStep{1, true, "wait", {}}));
    REQUIRE(model.addGrafcetStep("F1", GrafcetStep{2, false, "", {{ActionTiming::Continuous, "N Lamp IF Start"},
                                                                 {ActionTiming::OnActivation, "Count := Count + 1"},
                                                                 {ActionTiming::OnDeactivation, "S Complete"}}}));
    REQUIRE(model.addGrafcetStep("F1", GrafcetStep{3, false, "", {}}));
    REQUIRE(model.addGrafcetTransition("F1", GrafcetTransition{1, {1}, {2, 3}, "RE Start"}));
    REQUIRE(model.addGrafcetTransition("F1", GrafcetTransition{2, {2, 3}, {1}, "5s/X2"}));
    // A GRAFCET kept on a simple step is saved too.
    REQUIRE(model.addGrafcetStep("F2", GrafcetStep{1, true, "", {}}));
    REQUIRE(model.setStepType("F2", StepType::Simple));
    return model;
}

std::string withGrafcet(const std::string& grafcet)
{
    return R"({"format": "ggstudio-model", "version": "2.0", "grafcets": {"F1": )" + grafcet + "}}";
}

} // namespace

TEST_CASE("Native 2.0: nested GRAFCETs, kinds and the rule round-trip", "[files][native]")
{
    const Model model = nestedModel();
    const std::string text = saveNativeJson(model);
    CHECK(text.find("\"version\": \"2.0\"") != std::string::npos);
    CHECK(text.find("\"evolution\": \"until-stable\"") != std::string::npos);
    CHECK(text.find("\"kind\": \"output\"") != std::string::npos);
    const std::unique_ptr<Model> loaded = loadOk(text);
    CHECK(loaded->sameContent(model));
    CHECK(saveNativeJson(*loaded) == text);
}

TEST_CASE("Native 2.0: the branch order, the layout hint of a nested GRAFCET, is kept", "[files][native]")
{
    // Branches drawn right to left of their numbers: a simultaneous divergence
    // to 5 then 3, a selection whose branch T9 stands left of T4.
    Model model;
    for (int number : {1, 5, 3, 7})
        REQUIRE(model.addGrafcetStep("F1", GrafcetStep{number, number == 1, "", {}}));
    REQUIRE(model.addGrafcetTransition("F1", GrafcetTransition{9, {1}, {5, 3}, "TRUE"}));
    REQUIRE(model.addGrafcetTransition("F1", GrafcetTransition{4, {1}, {7}, "FALSE"}));
    REQUIRE(model.addGrafcetTransition("F1", GrafcetTransition{2, {3, 5}, {1}, "TRUE"}));
    const std::unique_ptr<Model> loaded = loadOk(saveNativeJson(model));
    const Grafcet* grafcet = loaded->grafcet("F1");
    REQUIRE(grafcet);
    CHECK(grafcet->transition(9)->downstream == std::vector<int>{5, 3});
    CHECK(grafcet->transition(2)->upstream == std::vector<int>{3, 5});
    const std::vector<const GrafcetTransition*> selection = grafcet->transitionsFrom(1);
    REQUIRE(selection.size() == 2);
    CHECK(selection[0]->number == 9);
    CHECK(selection[1]->number == 4);
    CHECK(grafcet->steps()[1].number == 5);
}

TEST_CASE("Native: a model without nested content is still written as 1.0", "[files][native]")
{
    Model model;
    REQUIRE(model.addVariable(Variable{"Start", IecType::Bool, "", ""}));
    const std::string text = saveNativeJson(model);
    CHECK(text.find("\"version\": \"1.0\"") != std::string::npos);
    CHECK(text.find("kind") == std::string::npos);
    CHECK(text.find("evolution") == std::string::npos);
    CHECK(text.find("grafcets") == std::string::npos);
}

TEST_CASE("Native 1.0 files cannot hold the keys of 2.0", "[files][native]")
{
    CHECK(loadError(R"({"format": "ggstudio-model", "version": "1.0", "grafcets": {}})").toString()
        == "test.json: /grafcets: unknown key \"grafcets\" in a model file; format 1.0 knows \"format\", \"version\", "
           "\"name\", \"settings\", \"steps\", \"transitions\" and \"variables\"");
    CHECK(loadError(R"({"format": "ggstudio-model", "version": "1.0", "variables": [{"name": "A", "type": "BOOL", "kind": "output"}]})")
              .location == "/variables/0/kind");
}

TEST_CASE("Native 2.0: malformed nested parts are refused with their path", "[files][native]")
{
    struct Case {
        std::string grafcet;
        std::string location;
        std::string message;
    };
    const std::vector<Case> cases = {
        {"[]", "/grafcets/F1", "expected an object, found an array"},
        {R"({"steps": [{"initial": true}]})", "/grafcets/F1/steps/0/number", "missing; every nested step has a number"},
        {R"({"steps": [{"number": 0}]})", "/grafcets/F1/steps/0/number", "expected an integer from 1 to 999999, found 0"},
        {R"({"steps": [{"number": 1}, {"number": 1}]})", "/grafcets/F1/steps/1/number", ""},
        {R"({"steps": [{"number": 1, "actions": [{"timing": "always", "text": "A"}]}]})",
         "/grafcets/F1/steps/0/actions/0/timing",
         "unknown timing \"always\"; expected \"continuous\", \"activation\" or \"deactivation\""},
        {R"({"steps": [{"number": 1, "actions": [{"txt": "A"}]}]})", "/grafcets/F1/steps/0/actions/0/txt", ""},
        {R"({"steps": [{"number": 1}], "transitions": [{"number": 1, "upstream": [], "downstream": [1]}]})",
         "/grafcets/F1/transitions/0", ""},
        {R"({"steps": [{"number": 1}], "transitions": [{"number": 1, "upstream": [1], "downstream": [7]}]})",
         "/grafcets/F1/transitions/0", ""},
        {R"({"steps": [{"number": 1}], "transitions": [{"number": 1, "upstream": [1]}]})",
         "/grafcets/F1/transitions/0/downstream", "missing; a transition needs its downstream steps"},
        {R"({"steps": [{"number": 1}], "transitions": [{"number": 1, "upstream": ["1"], "downstream": [1]}]})",
         "/grafcets/F1/transitions/0/upstream/0", ""},
        {R"({"steps": [], "links": []})", "/grafcets/F1/links", ""},
    };
    for (const Case& c : cases) {
        INFO(c.grafcet);
        const LoadError error = loadError(withGrafcet(c.grafcet));
        CHECK(error.location == c.location);
        if (!c.message.empty())
            CHECK(error.message == c.message);
        CHECK_FALSE(error.message.empty());
    }
    CHECK(loadError(R"({"format": "ggstudio-model", "version": "2.0", "grafcets": {"Z9": {}}})").location
        == "/grafcets/Z9");
    CHECK(loadError(R"({"format": "ggstudio-model", "version": "2.0", "settings": {"evolution": "fast"}})").message
        == "unknown evolution rule \"fast\"; expected \"one-per-scan\" or \"until-stable\"");
    CHECK(loadError(R"({"format": "ggstudio-model", "version": "2.0", "variables": [{"name": "A", "type": "BOOL", "kind": "in"}]})")
              .message
        == "unknown variable kind \"in\"; expected \"input\", \"output\" or \"internal\"");

    std::string many = R"({"steps": [)";
    for (int i = 1; i <= 10001; ++i)
        many += (i > 1 ? "," : "") + std::string(R"({"number": )") + std::to_string(i) + "}";
    CHECK(loadError(withGrafcet(many + "]}")).message
        == "10001 steps; a nested GRAFCET holds at most 10000");
}

} // namespace test_nativeformat
