#include "core/checks/checks.h"
#include "core/formats/modelfiles.h"
#include "core/model/model.h"
#include "core/templates/packml/packmlconfiguration.h"
#include "core/templates/packml/packmlmodel.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace test_packmlchecks {

using namespace core;
using packml::Command;
using packml::Edition;
using packml::GrafcetChoice;
using packml::State;
using packml::StateSet;
using Target = Diagnostic::Target;
using Strings = std::vector<std::string>;

namespace {

std::vector<Diagnostic> withCode(const Model& model, const std::string& code)
{
    std::vector<Diagnostic> found;
    for (const Diagnostic& d : checkModel(model))
        if (d.code == code)
            found.push_back(d);
    return found;
}

// The one diagnostic of a code; fails the test when there is not exactly one.
Diagnostic only(const Model& model, const std::string& code)
{
    const std::vector<Diagnostic> found = withCode(model, code);
    INFO(code);
    REQUIRE(found.size() == 1);
    return found.front();
}

Strings labels(const std::vector<Diagnostic>& diagnostics)
{
    Strings result;
    for (const Diagnostic& d : diagnostics)
        result.push_back(diagnosticElementLabel(d));
    return result;
}

Variable variable(std::string name, IecType type = IecType::Bool, VariableKind kind = VariableKind::Input)
{
    Variable v;
    v.name = std::move(name);
    v.type = type;
    v.kind = kind;
    return v;
}

// Gives (mode, state) its own GRAFCET: one initial step with these actions
// (stored ones on activation).
void ownGrafcet(Model& model, int mode, State state, const Strings& actions)
{
    REQUIRE(model.setGrafcetChoice(mode, state, GrafcetChoice::own()));
    GrafcetStep step;
    step.number = 1;
    step.initial = true;
    for (const std::string& text : actions) {
        const bool stored = text.starts_with("S ") || text.starts_with("R ") || text.find(":=") != std::string::npos;
        step.actions.push_back(GrafcetAction{stored ? ActionTiming::OnActivation : ActionTiming::Continuous, text});
    }
    REQUIRE(model.addGrafcetStep(packml::grafcetKey(mode, state), step));
}

// A 2022 model: every state of the default model is reachable there (the
// Complete command leads out of Execute), so it has no diagnostic at all.
Model cleanModel()
{
    return packml::newModel(Edition::Y2022);
}

} // namespace

TEST_CASE("A new 2022 PackML model has no diagnostic", "[packml-checks]")
{
    CHECK(checkModel(cleanModel()).empty());
}

TEST_CASE("A new 2015 PackML model only warns that Completing and Complete are never reached", "[packml-checks]")
{
    // Execute has no GRAFCET yet, and its skeleton never completes: in 2015
    // only Execute's SC leads to Completing.
    Model model = packml::newModel(Edition::Y2015);
    const std::vector<Diagnostic> all = checkModel(model);
    CHECK(std::all_of(all.begin(), all.end(), [](const Diagnostic& d) { return d.code == "PM009"; }));
    CHECK(labels(all)
          == Strings{"Production: Completing", "Production: Complete", "Maintenance: Completing",
                     "Maintenance: Complete", "Manual: Completing", "Manual: Complete"});
    for (int mode = 1; mode <= 3; ++mode)
        ownGrafcet(model, mode, State::Execute, {"S Complete"});
    CHECK(checkModel(model).empty());
}

TEST_CASE("PM001: no mode, or an initial mode that is none of the model's", "[packml-checks]")
{
    Model model = cleanModel();
    REQUIRE(model.removeMode(1));
    Diagnostic d = only(model, "PM001");
    CHECK(d.severity == Severity::Error);
    CHECK(d.target == Target::Model);
    CHECK(d.field == "initialMode");
    CHECK(d.arguments == Strings{"1"});

    REQUIRE(model.removeMode(2));
    REQUIRE(model.removeMode(3));
    d = only(model, "PM001");
    CHECK(d.field == "modes");
    CHECK(d.arguments.empty());
}

TEST_CASE("PM002: mode numbers and names", "[packml-checks]")
{
    SECTION("numbers outside 1..31 or repeated, a base mode with a name of its own")
    {
        packml::Configuration configuration = packml::defaultConfiguration(Edition::Y2022);
        configuration.modes[1].name = "Service";
        configuration.modes.push_back(packml::defaultMode(3));
        configuration.modes.back().name.clear();
        configuration.modes.push_back(packml::defaultMode(32));
        configuration.modes.back().name = "Far";
        const Model model(configuration);
        const std::vector<Diagnostic> found = withCode(model, "PM002");
        REQUIRE(found.size() == 3);
        CHECK(found[0].target == Target::Mode);
        CHECK(found[0].mode == 2);
        CHECK(found[0].arguments == Strings{"2", "fixed-name", "Service"});
        CHECK(found[1].arguments == Strings{"3", "repeated"});
        CHECK(found[2].arguments == Strings{"32", "out-of-range"});
        CHECK(found[2].field == "number");
    }
    SECTION("a user mode name that is no identifier, is reserved, or is another's ignoring case")
    {
        Model model = cleanModel();
        REQUIRE(model.addMode(4, "4Cleaning"));
        REQUIRE(model.addMode(5, "Trig_Clean"));
        REQUIRE(model.addMode(6, "MANUAL"));
        REQUIRE(model.addMode(7, "Clean"));
        REQUIRE(model.addMode(8, "clean"));
        const std::vector<Diagnostic> found = withCode(model, "PM002");
        REQUIRE(found.size() == 4);
        CHECK(found[0].arguments == Strings{"4", "not-identifier", "4Cleaning"});
        CHECK(found[1].arguments == Strings{"5", "reserved", "Trig_Clean"});
        CHECK(found[2].arguments == Strings{"6", "duplicate-name", "MANUAL", "Manual"});
        CHECK(found[3].arguments == Strings{"8", "duplicate-name", "clean", "Clean"});
        CHECK(diagnosticElementLabel(found[3]) == "mode clean");
        CHECK(std::all_of(found.begin(), found.end(), [](const Diagnostic& d) { return d.field == "name"; }));
    }
}

TEST_CASE("PM003: the initial state, and a model name that cannot name the PROGRAM", "[packml-checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setPackMLInitialState(State::Execute));
    Diagnostic d = only(model, "PM003");
    CHECK(d.severity == Severity::Error);
    CHECK(d.field == "initialState");
    CHECK(d.arguments == Strings{"Execute"});

    REQUIRE(model.setPackMLInitialState(State::Idle));
    REQUIRE(model.setName("Filler line"));
    d = only(model, "PM003");
    CHECK(d.severity == Severity::Warning);
    CHECK(d.field == "name");
    CHECK(d.arguments == Strings{"Filler line", "PackML"});

    REQUIRE(model.setName("Filler"));
    CHECK(withCode(model, "PM003").empty());
    REQUIRE(model.addVariable(variable("filler")));
    REQUIRE(model.setCommandCondition(Command::Start, "Cmd_Start AND Filler"));
    CHECK(only(model, "PM003").arguments == Strings{"Filler", "PackML"});
}

TEST_CASE("PM004, PM005: listings that are ignored or overridden", "[packml-checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setModeDisabled(1, StateSet{State::Stopped, State::Held, State::Unholding}));
    Diagnostic d = only(model, "PM004");
    CHECK(d.severity == Severity::Warning);
    CHECK(d.target == Target::Mode);
    CHECK(d.field == "disabled");
    CHECK(d.arguments == Strings{"Production", "Stopped"});
    CHECK(diagnosticElementLabel(d) == "mode Production");
    d = only(model, "PM005");
    CHECK(d.arguments == Strings{"Production", "Held", "Holding"});

    REQUIRE(model.setModeDisabled(1, StateSet{State::Held, State::Holding, State::Unholding}));
    CHECK(withCode(model, "PM004").empty());
    CHECK(withCode(model, "PM005").empty());
}

TEST_CASE("PM006: a mode change allowed in an acting state or a disabled one", "[packml-checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setModeDisabled(3, StateSet{State::Completing, State::Complete}));
    REQUIRE(model.setModeChangeStates(
        3, StateSet{State::Clearing, State::Stopped, State::Idle, State::Aborted, State::Complete}));
    const std::vector<Diagnostic> found = withCode(model, "PM006");
    REQUIRE(found.size() == 2);
    CHECK(found[0].arguments == Strings{"Manual", "Clearing", "acting"});
    CHECK(found[1].arguments == Strings{"Manual", "Complete", "disabled"});
    CHECK(found[1].field == "modeChange");
}

TEST_CASE("PM007: a mode no other mode can change into", "[packml-checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setModeChangeStates(2, StateSet{}));
    Diagnostic d = only(model, "PM007");
    CHECK(d.target == Target::Mode);
    CHECK(d.mode == 2);
    CHECK(d.arguments == Strings{"Maintenance"});
    // A mode that never begins has no paths to report.
    CHECK(withCode(model, "PM008").empty());

    REQUIRE(model.setPackMLInitialMode(2));
    CHECK(withCode(model, "PM007").empty());
}

TEST_CASE("PM008, PM009: paths to Execute count an SC only where Complete is written", "[packml-checks]")
{
    Model model = cleanModel();
    // Production begins in Stopped only (no mode change into it but there).
    REQUIRE(model.setModeChangeStates(1, StateSet{State::Stopped}));
    CHECK(withCode(model, "PM008").empty());
    // A Resetting that never completes: Reset leads nowhere further.
    ownGrafcet(model, 1, State::Resetting, {"HomeAxis"});
    REQUIRE(model.addVariable(variable("HomeAxis", IecType::Bool, VariableKind::Output)));
    Diagnostic d = only(model, "PM008");
    CHECK(d.severity == Severity::Warning);
    CHECK(d.target == Target::Mode);
    CHECK(d.arguments == Strings{"Production"});
    const std::vector<Diagnostic> unreached = withCode(model, "PM009");
    const Strings unreachedLabels = labels(unreached);
    CHECK(std::find(unreachedLabels.begin(), unreachedLabels.end(), "Production: Idle") != unreachedLabels.end());
    CHECK(std::find(unreachedLabels.begin(), unreachedLabels.end(), "Production: Execute") == unreachedLabels.end());
    CHECK(unreached.front().target == Target::ModeState);
    CHECK(unreached.front().state == "Starting");

    // Skipping Resetting leads Reset to Idle: Execute is reached again.
    REQUIRE(model.setModeDisabled(1, StateSet{State::Resetting}));
    CHECK(withCode(model, "PM008").empty());
    CHECK(withCode(model, "PM009").empty());
}

TEST_CASE("PM010: an acting state's GRAFCET that never writes Complete", "[packml-checks]")
{
    Model model = cleanModel();
    ownGrafcet(model, 3, State::Starting, {"R Complete"});
    Diagnostic d = only(model, "PM010");
    CHECK(d.severity == Severity::Warning);
    CHECK(d.target == Target::ModeState);
    CHECK(d.field == "grafcet");
    CHECK(d.arguments == Strings{"Manual", "Starting"});
    CHECK(diagnosticElementLabel(d) == "Manual: Starting");

    REQUIRE(model.setGrafcetChoice(3, State::Starting, GrafcetChoice::none()));
    ownGrafcet(model, 3, State::Aborting, {});
    d = only(model, "PM010");
    CHECK(d.severity == Severity::Error);
    CHECK(d.state == "Aborting");

    // The same GRAFCET run by another mode is that mode's too.
    REQUIRE(model.setGrafcetChoice(1, State::Aborting, GrafcetChoice::sameAs(3)));
    CHECK(withCode(model, "PM010").size() == 2);

    REQUIRE(model.addGrafcetAction(packml::grafcetKey(3, State::Aborting), 1,
                                   GrafcetAction{ActionTiming::OnActivation, "Complete := TRUE"}));
    CHECK(withCode(model, "PM010").empty());
}

TEST_CASE("PM010, PM016: a GRAFCET that resets Complete and then sets it, shared by two modes", "[packml-checks]")
{
    // The path checks read what each GRAFCET writes once, however many
    // modes run it: a reset before the set must not hide the set.
    Model model = cleanModel();
    ownGrafcet(model, 3, State::Starting, {"R Complete", "S Complete"});
    REQUIRE(model.setGrafcetChoice(1, State::Starting, GrafcetChoice::sameAs(3)));
    CHECK(withCode(model, "PM010").empty());

    ownGrafcet(model, 3, State::Execute, {"R Complete"});
    REQUIRE(model.setGrafcetChoice(1, State::Execute, GrafcetChoice::sameAs(3)));
    CHECK(labels(withCode(model, "PM016")) == Strings{"Production: Execute", "Manual: Execute"});
}

TEST_CASE("PM011: two commands or two requests with the same condition", "[packml-checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setCommandCondition(Command::Stop, "cmd_hold"));
    Diagnostic d = only(model, "PM011");
    CHECK(d.severity == Severity::Warning);
    CHECK(d.target == Target::Command);
    CHECK(d.element == "Hold");
    CHECK(d.arguments == Strings{"Stop", "Hold"});

    // FALSE: commands that come only through CntrlCmd.
    REQUIRE(model.setCommandCondition(Command::Stop, "FALSE"));
    REQUIRE(model.setCommandCondition(Command::Hold, "false"));
    CHECK(withCode(model, "PM011").empty());

    REQUIRE(model.addVariable(variable("KeyManual")));
    REQUIRE(model.setModeRequest(1, "NOT KeyManual"));
    REQUIRE(model.setModeRequest(3, "NOT (keymanual)"));
    d = only(model, "PM011");
    CHECK(d.target == Target::Request);
    CHECK(d.mode == 3);
    CHECK(d.arguments == Strings{"Production", "Manual"});
    CHECK(diagnosticElementLabel(d) == "request of mode Manual");
}

TEST_CASE("PM012: a command or request condition that reads an output", "[packml-checks]")
{
    Model model = cleanModel();
    REQUIRE(model.addVariable(variable("Lamp", IecType::Bool, VariableKind::Output)));
    REQUIRE(model.setCommandCondition(Command::Start, "Cmd_Start AND NOT Lamp OR Lamp"));
    Diagnostic d = only(model, "PM012");
    CHECK(d.target == Target::Command);
    CHECK(d.arguments == Strings{"command Start", "Lamp"});
    REQUIRE(d.span.has_value());
    CHECK(d.span->begin == 18);

    REQUIRE(model.setCommandCondition(Command::Start, "Cmd_Start"));
    REQUIRE(model.setModeRequest(2, "StateCurrent = 2"));
    d = only(model, "PM012");
    CHECK(d.target == Target::Request);
    CHECK(d.arguments == Strings{"request of mode Maintenance", "StateCurrent"});
}

TEST_CASE("PM013: a command no enabled state of any mode accepts", "[packml-checks]")
{
    Model model = cleanModel();
    for (int mode = 1; mode <= 3; ++mode)
        REQUIRE(model.setModeDisabled(mode, StateSet{State::Holding, State::Held, State::Unholding}));
    const std::vector<Diagnostic> found = withCode(model, "PM013");
    REQUIRE(found.size() == 2);
    CHECK(found[0].severity == Severity::Info);
    CHECK(found[0].target == Target::Command);
    CHECK(found[0].arguments == Strings{"Hold"});
    CHECK(found[1].arguments == Strings{"Unhold"});
    CHECK(diagnosticElementLabel(found[1]) == "command Unhold");

    REQUIRE(model.setModeDisabled(2, StateSet{}));
    CHECK(withCode(model, "PM013").empty());
}

TEST_CASE("PM014: a GRAFCET on a state the mode disables", "[packml-checks]")
{
    Model model = cleanModel();
    ownGrafcet(model, 2, State::Clearing, {"S Complete"});
    CHECK(withCode(model, "PM014").empty());
    REQUIRE(model.setModeDisabled(2, StateSet{State::Clearing}));
    const Diagnostic d = only(model, "PM014");
    CHECK(d.severity == Severity::Info);
    CHECK(d.arguments == Strings{"Maintenance", "Clearing"});
    CHECK(d.mode == 2);
}

TEST_CASE("PM015: a \"same as\" that names no usable GRAFCET", "[packml-checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setGrafcetChoice(2, State::Stopping, GrafcetChoice::sameAs(1)));
    REQUIRE(model.setGrafcetChoice(2, State::Holding, GrafcetChoice::sameAs(2)));
    REQUIRE(model.setGrafcetChoice(2, State::Suspending, GrafcetChoice::sameAs(9)));
    ownGrafcet(model, 1, State::Clearing, {"S Complete"});
    REQUIRE(model.setGrafcetChoice(2, State::Clearing, GrafcetChoice::sameAs(1)));
    const std::vector<Diagnostic> found = withCode(model, "PM015");
    REQUIRE(found.size() == 3);
    CHECK(found[0].arguments == Strings{"Maintenance", "Stopping", "1", "not-own"});
    CHECK(found[1].arguments == Strings{"Maintenance", "Holding", "2", "itself"});
    CHECK(found[2].arguments == Strings{"Maintenance", "Suspending", "9", "no-mode"});
    CHECK(found[2].severity == Severity::Error);
    CHECK(found[2].target == Target::ModeState);

    // Not reported where the mode disables the state: it runs nothing there.
    REQUIRE(model.setModeDisabled(2, StateSet{State::Stopping, State::Holding, State::Suspending}));
    CHECK(withCode(model, "PM015").empty());
}

TEST_CASE("PM016: in 2022, Execute's GRAFCET writes Complete", "[packml-checks]")
{
    Model model = cleanModel();
    ownGrafcet(model, 1, State::Execute, {"R Complete"});
    const Diagnostic d = only(model, "PM016");
    CHECK(d.target == Target::ModeState);
    CHECK(d.state == "Execute");
    CHECK(d.arguments == Strings{"Production"});

    Model y2015 = packml::newModel(Edition::Y2015);
    ownGrafcet(y2015, 1, State::Execute, {"S Complete"});
    CHECK(withCode(y2015, "PM016").empty());
}

TEST_CASE("PM017: the Complete command and its option in a 2015 model", "[packml-checks]")
{
    Model model = packml::newModel(Edition::Y2015);
    CHECK(withCode(model, "PM017").empty());
    REQUIRE(model.setCommandCondition(Command::Complete, "Cmd_Stop"));
    packml::Options options = model.packml()->options;
    options.completeInSuspendedHeld = true;
    REQUIRE(model.setPackMLOptions(options));
    const std::vector<Diagnostic> found = withCode(model, "PM017");
    REQUIRE(found.size() == 2);
    CHECK(found[0].target == Target::Command);
    CHECK(found[0].element == "Complete");
    CHECK(found[0].field == "condition");
    CHECK(found[1].field == "completeInSuspendedHeld");
    // Ignored, so not checked either: the same condition as Stop is no PM011.
    CHECK(withCode(model, "PM011").empty());
}

TEST_CASE("PM018: a variable named as the generated PackML code names things", "[packml-checks]")
{
    Model model = cleanModel();
    for (const char* name : {"CntrlCmd", "trig_start", "Manual_Execute", "Holding_FB", "PackML", "Resume", "gvl"})
        REQUIRE(model.addVariable(variable(name)));
    REQUIRE(model.addVariable(variable("GEMMA"))); // GEMMA's generator names are free here, but GVL
    const std::vector<Diagnostic> found = withCode(model, "PM018");
    Strings names;
    for (const Diagnostic& d : found) {
        CHECK(d.target == Target::Variable);
        CHECK(d.severity == Severity::Error);
        names.push_back(d.arguments.at(0));
    }
    CHECK(names == Strings{"CntrlCmd", "trig_start", "Manual_Execute", "Holding_FB", "PackML", "Resume", "gvl"});
    CHECK(withCode(model, "GG303").empty());
}

TEST_CASE("PM019: X<n>, Complete, an edge or t/X<n> in a command or request condition", "[packml-checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setCommandCondition(Command::Start, "RE Cmd_Start AND X3"));
    REQUIRE(model.setCommandCondition(Command::Stop, "Complete OR 5s/X1"));
    const std::vector<Diagnostic> found = withCode(model, "PM019");
    REQUIRE(found.size() == 4);
    CHECK(found[0].arguments == Strings{"command Start", "RE Cmd_Start", "edge"});
    CHECK(found[1].arguments == Strings{"command Start", "X3", "step-activity"});
    CHECK(found[2].arguments == Strings{"command Stop", "Complete", "complete"});
    CHECK(found[3].arguments == Strings{"command Stop", "5s/X1", "step-duration"});
    REQUIRE(found[1].span.has_value());
    CHECK(found[1].span->begin == 17);
    // Reported instead of the undeclared variable or syntax error.
    CHECK(withCode(model, "GG201").empty());
    CHECK(withCode(model, "GG203").empty());
}

TEST_CASE("Command and request conditions get GG201-GG204 and may read the PackTags", "[packml-checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setCommandCondition(Command::Reset, "Cmd_Reset AND"));
    REQUIRE(model.setCommandCondition(Command::Start, " "));
    REQUIRE(model.setCommandCondition(Command::Stop, "Cmd_Stop OR EStop"));
    REQUIRE(model.setCommandCondition(Command::Hold, "Cmd_Hold + 1"));
    REQUIRE(model.setCommandCondition(Command::Abort, "Cmd_Abort OR CntrlCmd = 8 AND NOT CmdChangeRequest"));
    REQUIRE(model.setModeRequest(3, "KeyManual"));
    REQUIRE(model.setModeRequest(2, "UnitMode = 2"));

    Diagnostic d = only(model, "GG201");
    CHECK(d.target == Target::Command);
    CHECK(d.element == "Reset");
    CHECK(d.field == "condition");
    CHECK(d.arguments.at(0) == "command Reset");
    CHECK(only(model, "GG202").element == "Start");
    const std::vector<Diagnostic> undeclared = withCode(model, "GG203");
    REQUIRE(undeclared.size() == 2);
    CHECK(undeclared[0].element == "Stop");
    CHECK(undeclared[0].arguments.at(1) == "EStop");
    CHECK(undeclared[1].target == Target::Request);
    CHECK(undeclared[1].arguments.at(0) == "request of mode Manual");
    d = only(model, "GG204");
    CHECK(d.element == "Hold");
    CHECK(d.severity == Severity::Error);
}

TEST_CASE("PackML variables get the GEMMA name and default checks", "[packml-checks]")
{
    Model model = cleanModel();
    Variable bad = variable("Speed_", IecType::Int);
    bad.defaultValue = "TRUE";
    REQUIRE(model.addVariable(bad));
    REQUIRE(model.addVariable(variable("THEN")));
    CHECK(only(model, "GG301").arguments.at(0) == "Speed_");
    CHECK(only(model, "GG302").arguments.at(0) == "THEN");
    const Diagnostic d = only(model, "GG304");
    CHECK(d.target == Target::Variable);
    CHECK(d.field == "default");
}

TEST_CASE("GG305: a variable no command, request or GRAFCET that generates code uses", "[packml-checks]")
{
    Model model = packml::newModel(Edition::Y2015);
    for (const char* name : {"Go", "Halt", "Finish", "ToManual", "Lamp", "Spare"})
        REQUIRE(model.addVariable(variable(name)));
    REQUIRE(model.setCommandCondition(Command::Start, "Go AND ("));  // counts while still being typed
    REQUIRE(model.setCommandCondition(Command::Hold, "Halt"));       // no enabled state accepts Hold below
    REQUIRE(model.setCommandCondition(Command::Complete, "Finish")); // 2022 only: ignored in 2015
    REQUIRE(model.setModeRequest(3, "ToManual"));
    ownGrafcet(model, 1, State::Suspending, {"Lamp"});
    const StateSet holdLoop{State::Holding, State::Held, State::Unholding};
    for (int mode = 1; mode <= 3; ++mode)
        REQUIRE(model.setModeDisabled(mode, holdLoop));
    const auto unused = [&model] {
        Strings names;
        for (const Diagnostic& d : withCode(model, "GG305")) {
            CHECK(d.severity == Severity::Warning);
            CHECK(d.target == Target::Variable);
            CHECK(d.field == "name");
            names.push_back(d.arguments.at(0));
        }
        return names;
    };
    // A new model's Cmd_<Command> inputs: Start and Hold read others now, and
    // no state accepts Unhold.
    CHECK(unused() == Strings{"Cmd_Start", "Cmd_Hold", "Cmd_Unhold", "Halt", "Finish", "Spare"});

    // Hold accepted in one mode; the GRAFCET on a state its mode disables
    // generates no code (PM014).
    REQUIRE(model.setModeDisabled(2, StateSet{}));
    REQUIRE(model.setModeDisabled(1, StateSet{State::Holding, State::Held, State::Unholding, State::Suspending,
                                              State::Suspended, State::Unsuspending}));
    CHECK(unused() == Strings{"Cmd_Start", "Cmd_Hold", "Finish", "Lamp", "Spare"});
}

TEST_CASE("GG305: the shipped bottle filler uses every variable it declares", "[packml-checks]")
{
    const LoadedModel loaded = loadModelFile(std::string(GGSTUDIO_EXAMPLES_DIR) + "/bottle-filler.ggstudio.json");
    REQUIRE(loaded.ok());
    CHECK(withCode(*loaded.model, "GG305").empty());
}

} // namespace test_packmlchecks
