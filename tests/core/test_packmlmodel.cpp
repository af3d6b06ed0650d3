#include "core/model/model.h"
#include "core/templates/packml/packmlconfiguration.h"
#include "core/templates/packml/packmlmodel.h"
#include "core/templates/packml/packtags.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace test_packmlmodel {

using namespace core;
using packml::Command;
using packml::GrafcetChoice;
using packml::State;

namespace {

// Every change an operation reported, as "Kind:id".
struct ChangeLog {
    explicit ChangeLog(Model& model)
    {
        model.addObserver([this](const ModelChange& change) { entries.push_back(describe(change)); });
    }
    static std::string describe(const ModelChange& change)
    {
        static const char* const names[] = {"Step",     "Transition",     "Variable",      "VariableList",
                                            "Settings", "Grafcet",        "Properties",    "Reset",
                                            "PackMLSettings", "PackMLCommand", "PackMLModes", "PackMLMode"};
        return std::string(names[static_cast<int>(change.kind)]) + ":" + change.id;
    }
    std::vector<std::string> entries;
};

GrafcetStep nestedStep(int number, bool initial = false)
{
    GrafcetStep step;
    step.number = number;
    step.initial = initial;
    return step;
}

Variable boolInput(std::string name)
{
    Variable v;
    v.name = std::move(name);
    return v;
}

} // namespace

TEST_CASE("A new PackML model has the base modes, the defaults and the command inputs", "[packml-model]")
{
    const Model model = packml::newModel(packml::Edition::Y2015);
    REQUIRE(model.templateKind() == TemplateKind::PackML);
    REQUIRE(model.packml() != nullptr);
    CHECK(model.steps().empty());
    CHECK(model.transitions().empty());
    CHECK(model.grafcets().empty());
    CHECK_THROWS_AS(model.initialStep(), std::logic_error); // GEMMA only: a loud error, not UB
    CHECK(model.settings().name == "PackML");
    CHECK(model.invariantViolations().empty());

    const packml::Configuration& configuration = *model.packml();
    CHECK(configuration.options.edition == packml::Edition::Y2015);
    CHECK_FALSE(configuration.options.holdInSuspended);
    CHECK_FALSE(configuration.options.completeInSuspendedHeld);
    CHECK(configuration.initialState == State::Stopped);
    CHECK(configuration.initialMode == 1);
    REQUIRE(configuration.modes.size() == 3);
    for (int number = 1; number <= 3; ++number) {
        const packml::Mode& mode = configuration.modes[static_cast<std::size_t>(number - 1)];
        CHECK(mode.number == number);
        CHECK(mode.name.empty());
        CHECK(mode.request.empty());
        CHECK(mode.disabled.empty());
        CHECK(mode.modeChange == packml::StateSet{State::Stopped, State::Idle, State::Aborted});
        for (const packml::StateInfo& info : packml::states())
            CHECK(mode.grafcetChoice(info.state) == GrafcetChoice::none());
    }
    CHECK(configuration.modes[0].displayName() == "Production");
    CHECK(configuration.modes[1].displayName() == "Maintenance");
    CHECK(configuration.modes[2].displayName() == "Manual");

    std::vector<std::string> names;
    for (const Variable& v : model.variables()) {
        names.push_back(v.name);
        CHECK(v.type == IecType::Bool);
        CHECK(v.kind == VariableKind::Input);
    }
    CHECK(names == std::vector<std::string>{"Cmd_Reset", "Cmd_Start", "Cmd_Stop", "Cmd_Hold", "Cmd_Unhold",
                                            "Cmd_Suspend", "Cmd_Unsuspend", "Cmd_Abort", "Cmd_Clear"});
    CHECK(configuration.command(Command::Reset).condition == "Cmd_Reset");
    CHECK(configuration.command(Command::Clear).condition == "Cmd_Clear");
    CHECK(configuration.command(Command::Complete).condition.empty());
}

TEST_CASE("A new 2022 PackML model declares and uses Cmd_Complete and holds in Suspended", "[packml-model]")
{
    const Model model = packml::newModel(packml::Edition::Y2022);
    const packml::Configuration& configuration = *model.packml();
    CHECK(configuration.options.edition == packml::Edition::Y2022);
    CHECK(configuration.options.holdInSuspended);
    CHECK(configuration.command(Command::Complete).condition == "Cmd_Complete");
    REQUIRE(model.variables().size() == 10);
    CHECK(model.variables().back().name == "Cmd_Complete");
}

TEST_CASE("A GEMMA model has no PackML part and refuses the PackML operations", "[packml-model]")
{
    Model model;
    CHECK(model.templateKind() == TemplateKind::Gemma);
    CHECK(model.packml() == nullptr);
    const auto revision = model.revision();
    CHECK(model.setPackMLInitialState(State::Idle).code == "not-packml");
    CHECK(model.setPackMLOptions(packml::defaultOptions(packml::Edition::Y2022)).code == "not-packml");
    CHECK(model.setPackMLInitialMode(2).code == "not-packml");
    CHECK(model.setCommandCondition(Command::Start, "X").code == "not-packml");
    CHECK(model.setCommandComment(Command::Start, "X").code == "not-packml");
    CHECK(model.addMode(4, "Cleaning").code == "not-packml");
    CHECK(model.removeMode(1).code == "not-packml");
    CHECK(model.renameMode(4, "X").code == "not-packml");
    CHECK(model.setModeComment(1, "X").code == "not-packml");
    CHECK(model.setModeRequest(1, "X").code == "not-packml");
    CHECK(model.setModeDisabled(1, {State::Starting}).code == "not-packml");
    CHECK(model.setModeChangeStates(1, {State::Idle}).code == "not-packml");
    CHECK(model.setGrafcetChoice(1, State::Execute, GrafcetChoice::own()).code == "not-packml");
    CHECK(model.revision() == revision);
    CHECK(model.sameContent(Model()));
    CHECK(model.setGrafcet("1/Execute", Grafcet()).code == "unknown-step");
}

TEST_CASE("PackML settings and commands are set, reported and kept as written", "[packml-model]")
{
    Model model = packml::newModel();
    ChangeLog log(model);
    REQUIRE(model.setPackMLOptions({packml::Edition::Y2022, true, true}));
    CHECK(model.packml()->options.edition == packml::Edition::Y2022);
    CHECK(model.packml()->options.completeInSuspendedHeld);
    REQUIRE(model.setPackMLInitialState(State::Execute)); // wrong (PM003), kept
    CHECK(model.packml()->initialState == State::Execute);
    REQUIRE(model.setPackMLInitialMode(7)); // no such mode (PM001), kept
    CHECK(model.packml()->initialMode == 7);
    REQUIRE(model.setCommandCondition(Command::Abort, "Cmd_Abort OR NOT EStopOK"));
    REQUIRE(model.setCommandComment(Command::Abort, "emergency stop"));
    REQUIRE(model.setCommandCondition(Command::Start, "")); // empty (GG202), kept
    CHECK(model.packml()->command(Command::Abort).condition == "Cmd_Abort OR NOT EStopOK");
    CHECK(model.packml()->command(Command::Abort).comment == "emergency stop");
    CHECK(model.packml()->command(Command::Start).condition.empty());
    CHECK(log.entries == std::vector<std::string>{"PackMLSettings:", "PackMLSettings:", "PackMLSettings:",
                                                  "PackMLCommand:Abort", "PackMLCommand:Abort", "PackMLCommand:Start"});

    // Setting what is already there changes nothing and tells nobody.
    const auto revision = model.revision();
    REQUIRE(model.setPackMLInitialMode(7));
    REQUIRE(model.setCommandComment(Command::Abort, "emergency stop"));
    CHECK(model.revision() == revision);

    CHECK(model.setPackMLInitialMode(0).code == "mode-out-of-range");
    CHECK(model.setPackMLInitialMode(32).code == "mode-out-of-range");
    CHECK(model.packml()->initialMode == 7);
    CHECK(model.revision() == revision);
    CHECK(model.invariantViolations().empty());
}

TEST_CASE("User modes are added in number order, renamed and commented", "[packml-model]")
{
    Model model = packml::newModel();
    ChangeLog log(model);
    REQUIRE(model.addMode(9, "Cleaning"));
    REQUIRE(model.addMode(4, "1 bad name")); // kept as written (PM002)
    std::vector<int> numbers;
    for (const packml::Mode& mode : model.packml()->modes)
        numbers.push_back(mode.number);
    CHECK(numbers == std::vector<int>{1, 2, 3, 4, 9});
    const packml::Mode& cleaning = *model.packml()->mode(9);
    CHECK(cleaning.displayName() == "Cleaning");
    CHECK(cleaning.modeChange == packml::StateSet{State::Stopped, State::Idle, State::Aborted});
    REQUIRE(model.renameMode(9, "Washing"));
    REQUIRE(model.setModeComment(9, "CIP"));
    CHECK(model.packml()->mode(9)->name == "Washing");
    CHECK(model.packml()->mode(9)->comment == "CIP");
    CHECK(log.entries == std::vector<std::string>{"PackMLModes:9", "PackMLModes:4", "PackMLMode:9", "PackMLMode:9"});
    CHECK(model.invariantViolations().empty());

    const Model before(model);
    const auto revision = model.revision();
    CHECK(model.addMode(9, "Again").code == "duplicate-mode");
    CHECK(model.addMode(0).code == "mode-out-of-range");
    CHECK(model.addMode(32, "Far").code == "mode-out-of-range");
    CHECK(model.addMode(2, "Service").code == "duplicate-mode");
    CHECK(model.renameMode(1, "Run").code == "fixed-mode-name");
    CHECK(model.renameMode(5, "Nobody").code == "unknown-mode");
    CHECK(model.setModeComment(5, "x").code == "unknown-mode");
    CHECK(model.revision() == revision);
    CHECK(model.sameContent(before));

    // A base mode removed comes back under its fixed name only.
    REQUIRE(model.removeMode(3));
    CHECK(model.addMode(3, "Hand").code == "fixed-mode-name");
    REQUIRE(model.addMode(3));
    CHECK(model.packml()->mode(3)->displayName() == "Manual");
}

TEST_CASE("Mode requests and listings are kept as written", "[packml-model]")
{
    Model model = packml::newModel();
    ChangeLog log(model);
    REQUIRE(model.setModeRequest(3, "KeyManual"));
    // Stopped cannot be disabled (PM004) and Starting allows no mode change (PM006): kept.
    REQUIRE(model.setModeDisabled(3, {State::Stopped, State::Clearing}));
    REQUIRE(model.setModeChangeStates(3, {State::Starting, State::Held}));
    const packml::Mode& manual = *model.packml()->mode(3);
    CHECK(manual.request == "KeyManual");
    CHECK(manual.disabled == packml::StateSet{State::Stopped, State::Clearing});
    CHECK(manual.modeChange == packml::StateSet{State::Starting, State::Held});
    CHECK(log.entries == std::vector<std::string>{"PackMLMode:3", "PackMLMode:3", "PackMLMode:3"});
    const auto revision = model.revision();
    CHECK(model.setModeRequest(8, "x").code == "unknown-mode");
    CHECK(model.setModeDisabled(8, {}).code == "unknown-mode");
    CHECK(model.setModeChangeStates(8, {}).code == "unknown-mode");
    REQUIRE(model.setModeRequest(3, "KeyManual"));
    CHECK(model.revision() == revision);
}

TEST_CASE("A PackML GRAFCET is chosen, edited through its key and resolved", "[packml-model]")
{
    Model model = packml::newModel();
    ChangeLog log(model);
    CHECK(packml::grafcetKey(3, State::Execute) == "3/Execute");

    REQUIRE(model.setGrafcetChoice(1, State::Execute, GrafcetChoice::own()));
    CHECK(log.entries == std::vector<std::string>{"Grafcet:1/Execute", "PackMLMode:1"});
    REQUIRE(model.grafcet("1/Execute") != nullptr);
    REQUIRE(model.addGrafcetStep("1/Execute", nestedStep(1, true)));
    CHECK(model.grafcet("1/Execute")->steps().size() == 1);
    CHECK(model.effectiveGrafcet("1/Execute") == model.grafcet("1/Execute"));

    REQUIRE(model.setGrafcetChoice(2, State::Execute, GrafcetChoice::sameAs(1)));
    CHECK(model.grafcet("2/Execute") == nullptr);
    CHECK(model.effectiveGrafcet("2/Execute") == model.grafcet("1/Execute"));
    CHECK(model.effectiveGrafcet("3/Execute") == nullptr);

    // "Same as" a mode without its own GRAFCET there (PM015) is kept and resolves to nothing.
    REQUIRE(model.setGrafcetChoice(3, State::Execute, GrafcetChoice::sameAs(2)));
    CHECK(model.effectiveGrafcet("3/Execute") == nullptr);

    // A state the mode disables runs nothing; its GRAFCET is kept (PM014).
    REQUIRE(model.setGrafcetChoice(1, State::Starting, GrafcetChoice::own()));
    REQUIRE(model.setModeDisabled(1, {State::Starting}));
    CHECK(model.grafcet("1/Starting") != nullptr);
    CHECK(model.effectiveGrafcet("1/Starting") == nullptr);
    CHECK(model.invariantViolations().empty());

    // Leaving Own removes the GRAFCET; removeGrafcet sets the choice to none.
    REQUIRE(model.setGrafcetChoice(1, State::Starting, GrafcetChoice::none()));
    CHECK(model.grafcet("1/Starting") == nullptr);
    REQUIRE(model.setGrafcet("2/Stopping", Grafcet()));
    CHECK(model.packml()->mode(2)->grafcetChoice(State::Stopping) == GrafcetChoice::own());
    REQUIRE(model.removeGrafcet("2/Stopping"));
    CHECK(model.packml()->mode(2)->grafcetChoice(State::Stopping) == GrafcetChoice::none());
    CHECK(model.invariantViolations().empty());

    const Model before(model);
    const auto revision = model.revision();
    CHECK(model.setGrafcetChoice(1, State::Idle, GrafcetChoice::own()).code == "no-grafcet-state");
    CHECK(model.setGrafcetChoice(5, State::Execute, GrafcetChoice::own()).code == "unknown-mode");
    CHECK(model.setGrafcetChoice(1, State::Holding, GrafcetChoice::sameAs(40)).code == "mode-out-of-range");
    CHECK(model.addGrafcetStep("2/Execute", nestedStep(1)).code == "no-grafcet");
    CHECK(model.setGrafcet("1/Idle", Grafcet()).code == "unknown-step");
    CHECK(model.setGrafcet("7/Execute", Grafcet()).code == "unknown-step");
    CHECK(model.setGrafcet("A1", Grafcet()).code == "unknown-step");
    CHECK(model.removeGrafcet("2/Execute").code == "no-grafcet");
    CHECK(model.revision() == revision);
    CHECK(model.sameContent(before));
}

TEST_CASE("Removing a mode takes its GRAFCETs and turns 'same as' it into none", "[packml-model]")
{
    Model model = packml::newModel();
    REQUIRE(model.addMode(4, "Cleaning"));
    REQUIRE(model.setGrafcetChoice(4, State::Execute, GrafcetChoice::own()));
    REQUIRE(model.setGrafcetChoice(4, State::Stopping, GrafcetChoice::own()));
    REQUIRE(model.setGrafcetChoice(1, State::Execute, GrafcetChoice::sameAs(4)));
    REQUIRE(model.setGrafcetChoice(2, State::Stopping, GrafcetChoice::sameAs(4)));
    REQUIRE(model.setGrafcetChoice(3, State::Execute, GrafcetChoice::own()));
    ChangeLog log(model);
    REQUIRE(model.removeMode(4));
    CHECK(model.packml()->mode(4) == nullptr);
    CHECK(model.grafcets().size() == 1);
    CHECK(model.grafcet("3/Execute") != nullptr);
    CHECK(model.packml()->mode(1)->grafcetChoice(State::Execute) == GrafcetChoice::none());
    CHECK(model.packml()->mode(2)->grafcetChoice(State::Stopping) == GrafcetChoice::none());
    CHECK(log.entries == std::vector<std::string>{"Grafcet:4/Execute", "Grafcet:4/Stopping", "PackMLMode:1",
                                                  "PackMLMode:2", "PackMLModes:4"});
    CHECK(model.invariantViolations().empty());
    CHECK(model.removeMode(4).code == "unknown-mode");
}

TEST_CASE("Renaming a variable rewrites the command and request conditions", "[packml-model]")
{
    Model model = packml::newModel();
    REQUIRE(model.addVariable(boolInput("EStopOK")));
    REQUIRE(model.setCommandCondition(Command::Abort, "Cmd_Abort OR NOT EStopOK"));
    REQUIRE(model.setModeRequest(2, "estopok AND Key"));
    REQUIRE(model.setGrafcetChoice(1, State::Aborting, GrafcetChoice::own()));
    REQUIRE(model.addGrafcetStep("1/Aborting", nestedStep(1, true)));
    REQUIRE(model.addGrafcetStep("1/Aborting", nestedStep(2)));
    GrafcetTransition t;
    t.number = 1;
    t.upstream = {1};
    t.downstream = {2};
    t.receptivity = "EStopOK";
    REQUIRE(model.addGrafcetTransition("1/Aborting", t));
    ChangeLog log(model);
    REQUIRE(model.renameVariable("EStopOK", "SafetyOK"));
    CHECK(model.packml()->command(Command::Abort).condition == "Cmd_Abort OR NOT SafetyOK");
    CHECK(model.packml()->mode(2)->request == "SafetyOK AND Key");
    CHECK(model.grafcet("1/Aborting")->transition(1)->receptivity == "SafetyOK");
    CHECK(std::count(log.entries.begin(), log.entries.end(), "PackMLCommand:Abort") == 1);
    CHECK(std::count(log.entries.begin(), log.entries.end(), "PackMLMode:2") == 1);
    CHECK(std::count(log.entries.begin(), log.entries.end(), "Grafcet:1/Aborting") == 1);

    REQUIRE(model.renameVariable("Cmd_Start", "StartButton"));
    CHECK(model.packml()->command(Command::Start).condition == "StartButton");
    REQUIRE(model.removeVariable("StartButton"));
    CHECK(model.packml()->command(Command::Start).condition == "StartButton"); // kept; the checks report it
    CHECK(model.invariantViolations().empty());
}

TEST_CASE("PackML content takes part in copies, assign, sameContent and reset", "[packml-model]")
{
    Model model = packml::newModel();
    REQUIRE(model.addMode(5, "Jog"));
    Model copy(model);
    CHECK(copy.sameContent(model));
    REQUIRE(copy.setModeComment(5, "slow"));
    CHECK_FALSE(copy.sameContent(model));
    Model gemma;
    CHECK_FALSE(gemma.sameContent(model));
    gemma.assign(copy);
    CHECK(gemma.templateKind() == TemplateKind::PackML);
    CHECK(gemma.sameContent(copy));
    gemma.resetToTemplate();
    CHECK(gemma.sameContent(packml::newModel()));
    REQUIRE(copy.setPackMLOptions(packml::defaultOptions(packml::Edition::Y2022)));
    copy.resetToTemplate();
    CHECK(copy.sameContent(packml::newModel(packml::Edition::Y2022)));
    copy.assign(Model());
    CHECK(copy.templateKind() == TemplateKind::Gemma);
}

TEST_CASE("PackML invariants find a broken structure", "[packml-model]")
{
    packml::Configuration configuration = packml::defaultConfiguration(packml::Edition::Y2015);
    CHECK(packml::structureProblems(configuration).empty());
    configuration.modes.push_back(packml::defaultMode(2));
    CHECK_FALSE(packml::structureProblems(configuration).empty());
    configuration.modes.pop_back();
    configuration.modes[0].grafcets[static_cast<std::size_t>(State::Idle)] = GrafcetChoice::own();
    CHECK_FALSE(packml::structureProblems(configuration).empty());
    configuration.modes[0].grafcets[static_cast<std::size_t>(State::Idle)] = GrafcetChoice::none();
    configuration.modes[0].grafcets[static_cast<std::size_t>(State::Execute)] = GrafcetChoice::own();
    const Model model(configuration); // Own chosen, GRAFCET missing
    CHECK_FALSE(model.invariantViolations().empty());
}

TEST_CASE("PackML GRAFCET keys are spelt and parsed by one pair of functions", "[packml-model]")
{
    CHECK(packml::grafcetKey(12, State::Unsuspending) == "12/Unsuspending");
    const auto parsed = packml::parseGrafcetKey("31/Completing");
    REQUIRE(parsed);
    CHECK(parsed->first == 31);
    CHECK(parsed->second == State::Completing);
    for (const char* bad : {"", "/Execute", "1/", "1/execute", "01/Execute", "+1/Execute", "-1/Execute", "1x/Execute",
                            "A1", "1/Execute/2"})
        CHECK_FALSE(packml::parseGrafcetKey(bad));
}

TEST_CASE("The PackTags interface: six globals typed and initialised from the configuration", "[packml-model]")
{
    packml::Configuration configuration = packml::defaultConfiguration(packml::Edition::Y2015);
    configuration.initialMode = 3;
    configuration.initialState = State::Aborted;
    const std::vector<Variable> tags = packml::packTagVariables(configuration);
    std::vector<std::string> summary;
    for (const Variable& v : tags)
        summary.push_back(v.name + ":" + std::string(iecTypeName(v.type)) + ":" + v.defaultValue + ":"
                          + std::string(variableKindName(v.kind)));
    CHECK(summary
          == std::vector<std::string>{"CntrlCmd:DINT:0:input", "CmdChangeRequest:BOOL:FALSE:input",
                                      "UnitMode:DINT:3:input", "UnitModeChangeRequest:BOOL:FALSE:input",
                                      "StateCurrent:DINT:9:output", "UnitModeCurrent:DINT:3:output"});
    CHECK(packml::isPackTagName("cntrlcmd"));
    CHECK(packml::isPackTagName("UnitModeCurrent"));
    CHECK_FALSE(packml::isPackTagName("UnitModeCurrentX"));
    CHECK_FALSE(packml::isPackTagName("State"));
}

} // namespace test_packmlmodel
