#include "filetestsupport.h"
#include "nativeloadchecks.h"

#include "core/formats/modelfiles.h"
#include "core/formats/nativeformat.h"
#include "core/templates/packml/packmlconfiguration.h"
#include "core/templates/packml/packmlmodel.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace test_packmlformat {

using namespace core;
using packml::Command;
using packml::GrafcetChoice;
using packml::State;

namespace {

const std::filesystem::path kFillerFile = std::filesystem::path(GGSTUDIO_TEST_DATA_DIR) / "packml-filler.json";

using filetests::loadError;
using filetests::loadOk;

const std::string kHeader = R"({"format": "ggstudio-model", "version": "3.0", "template": "packml")";

std::string packmlFile(const std::string& members)
{
    return kHeader + (members.empty() ? "" : ", " + members) + "}";
}

// The small model of packml-filler.json, built through the model's operations.
Model fillerModel()
{
    Model model(packml::defaultConfiguration(packml::Edition::Y2015));
    REQUIRE(model.setName("Filler"));
    Variable key;
    key.name = "KeyManual";
    REQUIRE(model.addVariable(key));
    REQUIRE(model.setCommandCondition(Command::Abort, "Cmd_Abort OR NOT EStopOK"));
    REQUIRE(model.setCommandComment(Command::Abort, "emergency stop"));
    REQUIRE(model.removeMode(3));
    REQUIRE(model.addMode(4, "Cleaning"));
    REQUIRE(model.setModeComment(4, "CIP"));
    REQUIRE(model.setModeChangeStates(4, {State::Stopped}));
    REQUIRE(model.setGrafcetChoice(4, State::Execute, GrafcetChoice::own()));
    REQUIRE(model.setModeRequest(1, "NOT KeyManual"));
    REQUIRE(model.setModeDisabled(1, {State::Starting, State::Clearing}));
    REQUIRE(model.setGrafcetChoice(1, State::Resetting, GrafcetChoice::own()));
    GrafcetStep first;
    first.number = 1;
    first.initial = true;
    REQUIRE(model.addGrafcetStep("1/Resetting", first));
    REQUIRE(model.setGrafcetChoice(1, State::Execute, GrafcetChoice::sameAs(4)));
    return model;
}

// ---- random PackML models ----

class RandomPackML {
public:
    explicit RandomPackML(unsigned seed) : m_random(seed) {}

    Model make()
    {
        Model model = packml::newModel(chance(2) ? packml::Edition::Y2015 : packml::Edition::Y2022);
        REQUIRE(model.setName(text()));
        REQUIRE(model.setCycleTimeMs(between(1, 1000)));
        model.setDialect(chance(2) ? Dialect::Iec : Dialect::Codesys);
        model.setEvolutionRule(chance(2) ? EvolutionRule::OneEvolutionPerScan : EvolutionRule::UntilStable);
        REQUIRE(model.setPackMLOptions({chance(2) ? packml::Edition::Y2015 : packml::Edition::Y2022, chance(2),
                                        chance(2)}));
        REQUIRE(model.setPackMLInitialState(anyState()));
        REQUIRE(model.setPackMLInitialMode(between(1, 31)));
        for (const packml::CommandInfo& info : packml::allCommands()) {
            if (chance(3))
                REQUIRE(model.setCommandCondition(info.command, text()));
            if (chance(3))
                REQUIRE(model.setCommandComment(info.command, text()));
        }
        for (int i = between(0, 4); i > 0; --i) {
            const int number = between(1, 31);
            if (!model.packml()->mode(number))
                REQUIRE(model.addMode(number, number >= packml::kFirstUserMode ? text() : std::string()));
        }
        if (chance(4))
            REQUIRE(model.removeMode(model.packml()->modes.front().number));
        std::vector<int> numbers;
        for (const packml::Mode& mode : model.packml()->modes)
            numbers.push_back(mode.number);
        for (int number : numbers)
            fillMode(model, number);
        for (int i = between(0, 3); i > 0; --i) {
            Variable v;
            v.name = "V" + std::to_string(i);
            v.kind = chance(2) ? VariableKind::Output : VariableKind::Internal;
            v.comment = text();
            REQUIRE(model.addVariable(v));
        }
        if (chance(2))
            REQUIRE(model.addProperty({"never X AND Y", text()}));
        return model;
    }

private:
    void fillMode(Model& model, int number)
    {
        REQUIRE(model.setModeComment(number, text()));
        REQUIRE(model.setModeRequest(number, chance(2) ? std::string() : text()));
        REQUIRE(model.setModeDisabled(number, anySet()));
        REQUIRE(model.setModeChangeStates(number, anySet()));
        for (const packml::StateInfo& info : packml::states()) {
            if (!packml::holdsGrafcet(info.state))
                continue;
            switch (between(0, 3)) {
            case 0: break;
            case 1: REQUIRE(model.setGrafcetChoice(number, info.state, GrafcetChoice::sameAs(between(1, 31)))); break;
            default: addOwnGrafcet(model, packml::grafcetKey(number, info.state)); break;
            }
        }
    }

    void addOwnGrafcet(Model& model, const std::string& key)
    {
        const auto [mode, state] = *packml::parseGrafcetKey(key);
        REQUIRE(model.setGrafcetChoice(mode, state, GrafcetChoice::own()));
        const int steps = between(0, 3);
        for (int n = 1; n <= steps; ++n) {
            GrafcetStep step;
            step.number = n;
            step.initial = n == 1;
            step.comment = text();
            if (chance(2))
                step.actions.push_back({ActionTiming::Continuous, "Out" + std::to_string(n)});
            REQUIRE(model.addGrafcetStep(key, step));
        }
        for (int n = 1; n < steps; ++n) {
            GrafcetTransition t;
            t.number = n;
            t.upstream = {n};
            t.downstream = {n + 1};
            t.receptivity = text();
            REQUIRE(model.addGrafcetTransition(key, t));
        }
    }

    int between(int low, int high) { return std::uniform_int_distribution<int>(low, high)(m_random); }
    bool chance(int inverse) { return between(1, inverse) == 1; }
    State anyState() { return *packml::stateFromNumber(between(1, packml::kStateCount)); }
    packml::StateSet anySet()
    {
        packml::StateSet set;
        for (int i = between(0, 5); i > 0; --i)
            set.insert(anyState());
        return set;
    }
    std::string text()
    {
        static const std::vector<std::string> pieces{"", "Go", " AND ", "\"q\"", "é", "\n", "NOT x", "Cmd_Start", "\\"};
        std::string result;
        for (int i = between(0, 3); i > 0; --i)
            result += pieces[static_cast<std::size_t>(between(0, static_cast<int>(pieces.size()) - 1))];
        return result;
    }

    std::mt19937 m_random;
};

} // namespace

TEST_CASE("A PackML model is written exactly as spec §9 orders its keys", "[packml-format]")
{
    const Model model = fillerModel();
    REQUIRE(model.invariantViolations().empty());
    CHECK(saveNativeJson(model) == filetests::readBinaryFile(kFillerFile));
    const auto loaded = loadOk(filetests::readBinaryFile(kFillerFile));
    CHECK(loaded->sameContent(model));
    CHECK(loaded->invariantViolations().empty());
}

TEST_CASE("A new PackML model of each edition survives a save and load", "[packml-format]")
{
    for (packml::Edition edition : {packml::Edition::Y2015, packml::Edition::Y2022}) {
        const Model model = packml::newModel(edition);
        const std::string text = saveNativeJson(model);
        CHECK((text.find("\"Complete\": {") != std::string::npos) == (edition == packml::Edition::Y2022));
        const auto loaded = loadOk(text);
        CHECK(loaded->sameContent(model));
    }
}

TEST_CASE("Random PackML models survive a save and load", "[packml-format]")
{
    for (unsigned seed = 1; seed <= 200; ++seed) {
        INFO("seed " << seed);
        const Model model = RandomPackML(seed).make();
        REQUIRE(model.invariantViolations().empty());
        const std::string text = saveNativeJson(model);
        const auto loaded = loadOk(text);
        CHECK(loaded->sameContent(model));
        CHECK(loaded->invariantViolations().empty());
        CHECK(saveNativeJson(*loaded) == text);
    }
}

TEST_CASE("Missing PackML keys keep the template defaults", "[packml-format]")
{
    const auto minimal = loadOk(packmlFile(""));
    const Model expected(packml::defaultConfiguration(packml::Edition::Y2015));
    CHECK(minimal->sameContent(expected));
    const auto edition2022 = loadOk(packmlFile(R"("settings": {"edition": "2022"}, "modes": [{"number": 5}])"));
    CHECK(edition2022->packml()->options.holdInSuspended);
    CHECK(edition2022->packml()->command(Command::Complete).condition == "Cmd_Complete");
    REQUIRE(edition2022->packml()->modes.size() == 1);
    CHECK(edition2022->packml()->modes[0] == packml::defaultMode(5));
    // Modes out of order are read in number order; a 2015 Complete is kept.
    const auto unordered = loadOk(packmlFile(
        R"("modes": [{"number": 9, "name": "B"}, {"number": 2}], "commands": {"Complete": {"condition": "Done"}})"));
    CHECK(unordered->packml()->modes[0].number == 2);
    CHECK(unordered->packml()->modes[1].number == 9);
    CHECK(unordered->packml()->command(Command::Complete).condition == "Done");
    CHECK(saveNativeJson(*unordered).find("\"Complete\": {") != std::string::npos);
}

TEST_CASE("Malformed PackML files are refused with the place and the fault", "[packml-format]")
{
    struct Case {
        std::string members;
        std::string location;
        std::string message;
    };
    const std::vector<Case> cases{
        {R"("steps": {})", "/steps", "\"steps\" is a key of GEMMA models; a PackML model file"},
        {R"("transitions": {})", "/transitions", "\"transitions\" is a key of GEMMA models"},
        {R"("grafcets": {})", "/grafcets", "\"grafcets\" is a key of GEMMA models"},
        {R"("unit": 1)", "/unit", "unknown key \"unit\" in a PackML model file; format 3.0 knows \"format\""},
        {R"("settings": {"edition": "2019"})", "/settings/edition",
         "unknown edition \"2019\"; expected \"2015\" or \"2022\""},
        {R"("settings": {"edition": 2015})", "/settings/edition", "expected a string, found 2015"},
        {R"("settings": {"initialState": "Running"})", "/settings/initialState",
         "unknown state \"Running\"; the PackML states are Clearing, Stopped,"},
        {R"("settings": {"initialMode": 32})", "/settings/initialMode", "expected an integer from 1 to 31"},
        {R"("settings": {"holdInSuspended": "yes"})", "/settings/holdInSuspended", "expected true or false"},
        {R"("settings": {"cycleTimeMs": 0})", "/settings/cycleTimeMs", "expected an integer from 1 to 3600000"},
        {R"("settings": {"dialect": "st"})", "/settings/dialect", "unknown dialect \"st\""},
        {R"("settings": {"steps": 1})", "/settings/steps", "unknown key \"steps\" in the settings"},
        {R"("settings": [])", "/settings", "expected an object"},
        {R"("commands": {"Go": {}})", "/commands/Go", "unknown command \"Go\"; the PackML commands are Reset,"},
        {R"("commands": {"Start": {"condition": 1}})", "/commands/Start/condition", "expected a string"},
        {R"("commands": {"Start": {"priority": 1}})", "/commands/Start/priority", "unknown key \"priority\" in a command"},
        {R"("commands": [])", "/commands", "expected an object"},
        {R"("modes": {})", "/modes", "expected an array"},
        {R"("modes": [{"comment": ""}])", "/modes/0/number", "missing; every mode has a number (1..31)"},
        {R"("modes": [{"number": 0}])", "/modes/0/number", "expected an integer from 1 to 31"},
        {R"("modes": [{"number": 4}, {"number": 1}, {"number": 4}])", "/modes/2/number",
         "mode 4 is listed twice (also at /modes/0)"},
        {R"("modes": [{"number": 1, "name": "Run"}])", "/modes/0/name",
         "mode 1 is named Production; only user modes (4..31) have a name"},
        {R"("modes": [{"number": 1, "disabled": ["Starting", "Idel"]}])", "/modes/0/disabled/1",
         "unknown state \"Idel\""},
        {R"("modes": [{"number": 1, "modeChange": ["Idle", "Idle"]}])", "/modes/0/modeChange/1",
         "\"Idle\" is listed twice"},
        {R"("modes": [{"number": 1, "grafcets": {"Idle": {}}}])", "/modes/0/grafcets/Idle",
         "Idle holds no GRAFCET; the keys are the states that hold one: Clearing, Starting, Execute,"},
        {R"("modes": [{"number": 1, "grafcets": {"A1": {}}}])", "/modes/0/grafcets/A1", "unknown state \"A1\""},
        {R"("modes": [{"number": 1, "grafcets": {"Execute": {"sameAs": 2, "steps": []}}}])",
         "/modes/0/grafcets/Execute", "\"sameAs\" stands alone"},
        {R"("modes": [{"number": 1, "grafcets": {"Execute": {"sameAs": 40}}}])", "/modes/0/grafcets/Execute/sameAs",
         "expected an integer from 1 to 31"},
        {R"("modes": [{"number": 1, "grafcets": {"Execute": {"steps": [{"number": 1}, {"number": 1}]}}}])",
         "/modes/0/grafcets/Execute/steps/1/number", ""},
        {R"("modes": [{"number": 1, "grafcets": {"Execute": {"stepz": []}}}])", "/modes/0/grafcets/Execute/stepz",
         "unknown key \"stepz\" in a nested GRAFCET; format 3.0 knows"},
        {R"("modes": [{"number": 1, "colour": 1}])", "/modes/0/colour", "unknown key \"colour\" in a mode"},
        {R"("variables": [{"name": "A", "type": "BOOL"}, {"name": "a", "type": "BOOL"}])", "/variables/1/name",
         "duplicate variable name \"a\""},
        {R"("properties": [{}])", "/properties/0/text", "missing"},
    };
    for (const Case& c : cases) {
        INFO(c.members);
        const LoadError error = loadError(packmlFile(c.members));
        CHECK(error.location == c.location);
        CHECK_THAT(error.message, Catch::StartsWith(c.message));
    }
}

TEST_CASE("Only a 3.0 file of template packml is read as PackML", "[packml-format]")
{
    const std::string newer = "this file was written by a newer GG Studio (format 3.0); this version reads formats "
                              "1.x and 2.x";
    CHECK(loadError(R"({"format": "ggstudio-model", "version": "3.0"})").message == newer);
    CHECK(loadError(R"({"format": "ggstudio-model", "version": "3.0", "template": "gemma"})").message == newer);
    CHECK(loadError(R"({"format": "ggstudio-model", "version": "3.0", "template": 1})").message == newer);
    CHECK(loadError(R"({"format": "ggstudio-model", "version": "4.0", "template": "packml"})").message
          == "this file was written by a newer GG Studio (format 4.0); this version reads formats 1.x and 2.x");
    const LoadError gemma = loadError(R"({"format": "ggstudio-model", "version": "2.0", "template": "packml"})");
    CHECK(gemma.location == "/template");
    CHECK_THAT(gemma.message, Catch::StartsWith("unknown key \"template\" in a model file; format 2.0 knows"));
    // A newer minor version may add keys.
    CHECK(loadOk(R"({"format": "ggstudio-model", "version": "3.1", "template": "packml", "later": 1})")->packml());
}

TEST_CASE("GEMMA models are still written as 1.0 and 2.0 without a template", "[packml-format]")
{
    const Model plain;
    const std::string text = saveNativeJson(plain);
    CHECK(text.find("\"version\": \"1.0\"") != std::string::npos);
    CHECK(text.find("template") == std::string::npos);
    CHECK(loadOk(text)->templateKind() == TemplateKind::Gemma);
    const Model rich = filetests::richNativeModel();
    const std::string richText = saveNativeJson(rich);
    CHECK(richText.find("template") == std::string::npos);
    CHECK(loadOk(richText)->sameContent(rich));
}

TEST_CASE("Files the editor and the CLI open refuse a PackML model for now", "[packml-format]")
{
    const Model gemma;
    CHECK(unsupportedModelMessage(gemma).empty());
    CHECK(unsupportedModelMessage(packml::newModel())
          == "a PackML model (format 3.0); GG Studio does not handle PackML models here yet (ggstudio-cli new, "
             "convert, validate, export, st, simulate and verify do)");
    CHECK(unsupportedModelMessage(packml::newModel(), TemplateSupport::GemmaAndPackML).empty());

    const std::string path = kFillerFile.string();
    CHECK(loadModelFile(path).ok());
    const LoadedModel refused = loadSupportedModelFile(path);
    CHECK_FALSE(refused.ok());
    CHECK(refused.error.toString() == path + ": " + unsupportedModelMessage(*loadModelFile(path).model));

    filetests::ScratchFolder folder;
    const std::filesystem::path gemmaPath = folder.path() / "gemma.json";
    REQUIRE(saveModelFile(gemma, gemmaPath.string(), ModelFormat::Native));
    CHECK(loadSupportedModelFile(gemmaPath.string()).ok());
}

TEST_CASE("A PackML model is saved natively and never as GG-Generator JSON", "[packml-format]")
{
    filetests::ScratchFolder folder;
    const Model model = fillerModel();
    const Status refused = saveModelFile(model, folder.file("filler.gg.json").string(), ModelFormat::GGGenerator);
    CHECK_FALSE(refused.ok);
    CHECK(refused.message == "GG-Generator JSON holds GEMMA models only; save a PackML model as a GG Studio model file");
    CHECK(folder.entries().empty());
    REQUIRE(saveModelFile(model, folder.file("filler.json").string(), ModelFormat::Native));
    CHECK(filetests::readBinaryFile(folder.file("filler.json")) == filetests::readBinaryFile(kFillerFile));
}

} // namespace test_packmlformat
