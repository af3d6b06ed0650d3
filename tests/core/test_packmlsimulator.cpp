#include "packmlcapper.h"

#include "core/templates/packml/packmlmodel.h"
#include "core/templates/packml/packmlscenario.h"
#include "core/templates/packml/packmlsimulator.h"

#include <catch2/catch.hpp>

#include <map>
#include <string>
#include <vector>

namespace test_packmlsimulator {

using namespace core;
using namespace core::packml;

namespace {

std::string bit(const std::optional<cond::Value>& value)
{
    REQUIRE(value.has_value());
    return cond::isTrue(*value) ? "1" : "0";
}

std::string number(const std::optional<cond::Value>& value)
{
    REQUIRE(value.has_value());
    return cond::formatValue(*value);
}

// The called instance as spec §6.6 prints it: "Production_Resetting X=1
// Complete=0 Unstable=0", or "-" when the scan called no function block.
std::string instanceText(const PackmlSimulator& simulator, const PackmlScanRecord* record)
{
    if (!record || record->calledInstance < 0)
        return "-";
    const int index = record->calledInstance;
    std::string text = simulator.program().instances[static_cast<std::size_t>(index)].name + " X=";
    const NestedEngine* engine = simulator.engine(index);
    std::string steps;
    for (int step : engine ? engine->activeSteps() : std::vector<int>{})
        steps += (steps.empty() ? "" : ",") + std::to_string(step);
    text += steps + " Complete=" + (simulator.complete(index) ? "1" : "0");
    text += std::string(" Unstable=") + (engine && engine->unstable() ? "1" : "0");
    return text;
}

// One line of spec §6.6's trace: record is nullptr for scan 0 (nothing run yet).
std::string traceLine(const PackmlSimulator& simulator, const PackmlScanRecord* record)
{
    std::string line = "scan " + std::to_string(simulator.scanCount()) + ": State="
        + number(simulator.value("StateCurrent")) + " UnitModeCurrent=" + number(simulator.value("UnitModeCurrent"));
    const std::string summary = record ? summaryText(*record) : std::string();
    if (!summary.empty())
        line += " " + summary;
    line += " | " + instanceText(simulator, record) + " | HomeAxis=" + bit(simulator.value("HomeAxis"))
        + " Cap=" + bit(simulator.value("Cap")) + " Eject=" + bit(simulator.value("Eject"));
    return line;
}

void setAll(PackmlSimulator& simulator, const std::vector<std::pair<std::string, std::string>>& inputs)
{
    for (const auto& [name, value] : inputs) {
        const Status status = simulator.setInputText(name, value);
        INFO(name << " = " << value << ": " << status.message);
        REQUIRE(status.ok);
    }
}

} // namespace

TEST_CASE("The Capper gives the trace of spec §6.6 scan by scan", "[packml-sim]")
{
    const auto model = packmltests::loadCapper();
    PackmlSimulator simulator(*model);
    // Spec §6.6: `K Name=VALUE`, set before scan K; values persist.
    const std::map<int, std::vector<std::pair<std::string, std::string>>> scenario{
        {1, {{"Cmd_Reset", "TRUE"}}},
        {2, {{"Cmd_Reset", "FALSE"}}},
        {4, {{"Homed", "TRUE"}}},
        {5, {{"Cmd_Start", "TRUE"}}},
        {6, {{"Cmd_Start", "FALSE"}}},
        {7, {{"KeyManual", "TRUE"}, {"Capped", "TRUE"}}},
        {8, {{"Cmd_Hold", "TRUE"}}},
        {9, {{"Cmd_Hold", "FALSE"}, {"Capped", "FALSE"}}},
        {10, {{"Cmd_Unhold", "TRUE"}}},
        {11, {{"Cmd_Unhold", "FALSE"}}},
        {12, {{"Cmd_Stop", "TRUE"}}},
        {13, {{"Cmd_Stop", "FALSE"}, {"KeyManual", "FALSE"}}},
        {14, {{"KeyManual", "TRUE"}, {"Cmd_Reset", "TRUE"}}},
        {15, {{"EStopOK", "FALSE"}}},
        {16, {{"EStopOK", "TRUE"}, {"Cmd_Reset", "FALSE"}}},
        {17, {{"CntrlCmd", "9"}, {"CmdChangeRequest", "TRUE"}}},
        {18, {{"UnitMode", "1"}, {"UnitModeChangeRequest", "TRUE"}}},
    };
    const std::vector<std::string> expected{
        "scan 0: State=2 UnitModeCurrent=1 | - | HomeAxis=0 Cap=0 Eject=0",
        "scan 1: State=15 UnitModeCurrent=1 fired Stopped-Reset->Resetting | - | HomeAxis=0 Cap=0 Eject=0",
        "scan 2: State=15 UnitModeCurrent=1 | Production_Resetting X=1 Complete=0 Unstable=0 | HomeAxis=1 Cap=0 Eject=0",
        "scan 3: State=15 UnitModeCurrent=1 | Production_Resetting X=1 Complete=0 Unstable=0 | HomeAxis=1 Cap=0 Eject=0",
        "scan 4: State=4 UnitModeCurrent=1 fired Resetting-SC->Idle | Production_Resetting X=2 Complete=1 Unstable=0 | HomeAxis=0 Cap=0 Eject=0",
        "scan 5: State=6 UnitModeCurrent=1 fired Idle-Start->Execute | - | HomeAxis=0 Cap=0 Eject=0",
        "scan 6: State=6 UnitModeCurrent=1 | Production_Execute X=1 Complete=0 Unstable=0 | HomeAxis=0 Cap=1 Eject=0",
        "scan 7: State=6 UnitModeCurrent=1 | Production_Execute X=2 Complete=0 Unstable=0 | HomeAxis=0 Cap=0 Eject=1",
        "scan 8: State=11 UnitModeCurrent=1 fired Execute-Hold->Held | Production_Execute X=2 Complete=0 Unstable=0 | HomeAxis=0 Cap=0 Eject=0",
        "scan 9: State=11 UnitModeCurrent=1 | - | HomeAxis=0 Cap=0 Eject=0",
        "scan 10: State=6 UnitModeCurrent=1 fired Held-Unhold->Execute | - | HomeAxis=0 Cap=0 Eject=0",
        "scan 11: State=6 UnitModeCurrent=1 resumed | Production_Execute X=2 Complete=0 Unstable=0 | HomeAxis=0 Cap=0 Eject=1",
        "scan 12: State=2 UnitModeCurrent=1 fired Execute-Stop->Stopped | Production_Execute X=2 Complete=0 Unstable=0 | HomeAxis=0 Cap=0 Eject=0",
        "scan 13: State=2 UnitModeCurrent=1 | - | HomeAxis=0 Cap=0 Eject=0",
        "scan 14: State=4 UnitModeCurrent=3 mode 1->3 fired Stopped-Reset->Idle | - | HomeAxis=0 Cap=0 Eject=0",
        "scan 15: State=9 UnitModeCurrent=3 fired Idle-Abort->Aborted | - | HomeAxis=0 Cap=0 Eject=0",
        "scan 16: State=9 UnitModeCurrent=3 | - | HomeAxis=0 Cap=0 Eject=0",
        "scan 17: State=2 UnitModeCurrent=3 fired Aborted-Clear->Stopped | - | HomeAxis=0 Cap=0 Eject=0",
        "scan 18: State=2 UnitModeCurrent=1 mode 3->1 | - | HomeAxis=0 Cap=0 Eject=0",
    };
    std::vector<std::string> actual{traceLine(simulator, nullptr)};
    for (int scan = 1; scan <= 18; ++scan) {
        if (const auto found = scenario.find(scan); found != scenario.end())
            setAll(simulator, found->second);
        const PackmlScanRecord record = simulator.scan();
        actual.push_back(traceLine(simulator, &record));
    }
    for (std::size_t i = 0; i < expected.size(); ++i)
        CHECK(actual[i] == expected[i]);
}

namespace {

PackmlScanRecord scanWith(PackmlSimulator& simulator, const std::vector<std::pair<std::string, std::string>>& inputs)
{
    setAll(simulator, inputs);
    return simulator.scan();
}

// Sets the input TRUE for one scan (its rising edge) and FALSE again after it.
PackmlScanRecord pulse(PackmlSimulator& simulator, const std::string& input)
{
    PackmlScanRecord record = scanWith(simulator, {{input, "TRUE"}});
    setAll(simulator, {{input, "FALSE"}});
    return record;
}

// Asks for a mode through UnitMode and a rising edge of UnitModeChangeRequest
// (FALSE again after the scan: the next request needs a scan in between).
PackmlScanRecord requestMode(PackmlSimulator& simulator, int mode)
{
    PackmlScanRecord record = scanWith(simulator, {{"UnitMode", std::to_string(mode)}, {"UnitModeChangeRequest", "TRUE"}});
    setAll(simulator, {{"UnitModeChangeRequest", "FALSE"}});
    return record;
}

std::vector<std::string> droppedTexts(const PackmlScanRecord& record)
{
    std::vector<std::string> texts;
    for (const DroppedEvent& event : record.dropped)
        texts.push_back(toText(event));
    return texts;
}

std::string firedText(const PackmlScanRecord& record)
{
    return record.fired ? transitionText(*record.fired) : std::string("none");
}

void addVariable(Model& model, const std::string& name, VariableKind kind, IecType type = IecType::Bool)
{
    Variable variable;
    variable.name = name;
    variable.type = type;
    variable.kind = kind;
    REQUIRE(model.addVariable(variable).ok);
}

// Gives (mode, state) its own GRAFCET: steps as "number:initial:actions"
// triples, transitions from -> to with their receptivity.
struct StepSpec {
    int number;
    bool initial;
    std::vector<std::string> actions; // continuous unless they start with "S " or "R " or hold ":="
};
struct TransitionSpec {
    int number;
    int from;
    int to;
    std::string receptivity;
};

void addGrafcet(Model& model, int mode, State state, const std::vector<StepSpec>& steps,
                const std::vector<TransitionSpec>& transitions)
{
    REQUIRE(model.setGrafcetChoice(mode, state, GrafcetChoice::own()).ok);
    const std::string key = grafcetKey(mode, state);
    for (const StepSpec& spec : steps) {
        GrafcetStep step;
        step.number = spec.number;
        step.initial = spec.initial;
        for (const std::string& text : spec.actions) {
            const bool stored = text.rfind("S ", 0) == 0 || text.rfind("R ", 0) == 0 || text.find(":=") != std::string::npos;
            step.actions.push_back({stored ? ActionTiming::OnActivation : ActionTiming::Continuous, text});
        }
        REQUIRE(model.addGrafcetStep(key, step).ok);
    }
    for (const TransitionSpec& spec : transitions)
        REQUIRE(model.addGrafcetTransition(key, {spec.number, {spec.from}, {spec.to}, spec.receptivity}).ok);
}

std::string activeSteps(const PackmlSimulator& simulator, int mode, State state)
{
    const ProgramInstance* instance = simulator.program().instance(mode, state);
    REQUIRE(instance != nullptr);
    const NestedEngine* engine = simulator.engine(static_cast<int>(instance - simulator.program().instances.data()));
    REQUIRE(engine != nullptr);
    std::string text;
    for (int step : engine->activeSteps())
        text += (text.empty() ? "" : ",") + std::to_string(step);
    return text;
}

bool boolValue(const PackmlSimulator& simulator, std::string_view name)
{
    const std::optional<cond::Value> value = simulator.value(name);
    REQUIRE(value.has_value());
    return cond::isTrue(*value);
}

// A 2015 model with every state of Production enabled, whose Execute runs
// 1 `N Cap` -Capped-> 2 `N Eject`; mode changes of Production and
// Maintenance also in Held, of Production also in Execute; Manual disables
// the Hold loop but lists Held; Maintenance is requested by KeyMaint too.
Model resumeModel()
{
    Model model = newModel(Edition::Y2015);
    REQUIRE(model.setName("Resumer").ok);
    addVariable(model, "Capped", VariableKind::Input);
    addVariable(model, "KeyMaint", VariableKind::Input);
    addVariable(model, "Cap", VariableKind::Output);
    addVariable(model, "Eject", VariableKind::Output);
    addGrafcet(model, 1, State::Execute, {{1, true, {"N Cap"}}, {2, false, {"N Eject"}}}, {{1, 1, 2, "Capped"}});
    const StateSet base{State::Stopped, State::Idle, State::Aborted};
    StateSet production = base, withHeld = base;
    production.insert(State::Held);
    production.insert(State::Execute);
    withHeld.insert(State::Held);
    REQUIRE(model.setModeChangeStates(1, production).ok);
    REQUIRE(model.setModeChangeStates(2, withHeld).ok);
    REQUIRE(model.setModeChangeStates(3, withHeld).ok);
    REQUIRE(model.setModeDisabled(3, {State::Holding, State::Held, State::Unholding}).ok);
    REQUIRE(model.setModeRequest(2, "KeyMaint").ok);
    return model;
}

// From power-up to Production's Execute (fresh, in step 1): Reset,
// Resetting's skeleton, Start, Starting's skeleton, Execute's first scan.
void startExecute(PackmlSimulator& simulator)
{
    CHECK(firedText(pulse(simulator, "Cmd_Reset")) == "Stopped-Reset->Resetting");
    CHECK(firedText(simulator.scan()) == "Resetting-SC->Idle");
    CHECK(firedText(pulse(simulator, "Cmd_Start")) == "Idle-Start->Starting");
    CHECK(firedText(simulator.scan()) == "Starting-SC->Execute");
    CHECK_FALSE(simulator.scan().resumed); // Execute's first scan (its SC may end it, in 2015)
}

} // namespace

TEST_CASE("Dropped events say why, as data and in English", "[packml-sim]")
{
    const auto capper = packmltests::loadCapper();
    PackmlSimulator simulator(*capper);
    pulse(simulator, "Cmd_Reset");
    setAll(simulator, {{"Homed", "TRUE"}});
    simulator.scan();
    simulator.scan();
    REQUIRE(simulator.state() == State::Idle);

    SECTION("a command the state does not accept")
    {
        const PackmlScanRecord record = pulse(simulator, "Cmd_Hold");
        CHECK_FALSE(record.fired);
        REQUIRE(record.dropped.size() == 1);
        const DroppedEvent expected{DroppedEvent::Kind::Command, DropReason::NotAcceptedInState, 4, "Hold",
                                    State::Idle, "Production", {}};
        CHECK(record.dropped[0] == expected);
        CHECK(toText(record.dropped[0]) == "Hold is not accepted in Idle");
    }
    SECTION("a mode requested in a state where the current mode allows no change")
    {
        pulse(simulator, "Cmd_Start");
        REQUIRE(simulator.state() == State::Execute);
        const PackmlScanRecord record = scanWith(simulator, {{"KeyManual", "TRUE"}});
        CHECK(record.mode == 1);
        REQUIRE(record.dropped.size() == 1);
        CHECK(record.dropped[0].kind == DroppedEvent::Kind::ModeRequest);
        CHECK(record.dropped[0].reason == DropReason::NotAllowedByCurrentMode);
        CHECK(toText(record.dropped[0]) == "Manual is not granted in Execute: Production allows no mode change there");
    }
    SECTION("two commands in one scan: the one of higher priority fires, the other is pre-empted")
    {
        pulse(simulator, "Cmd_Start");
        const PackmlScanRecord record = scanWith(simulator, {{"Cmd_Hold", "TRUE"}, {"Cmd_Stop", "TRUE"}});
        CHECK(firedText(record) == "Execute-Stop->Stopped");
        CHECK(droppedTexts(record) == std::vector<std::string>{"Hold is pre-empted by Execute-Stop->Stopped"});
        CHECK(record.dropped[0].reason == DropReason::Preempted);
    }
    SECTION("a command the template accepts but the mode disables where it leads")
    {
        // Manual in Stopped: Reset skips Resetting to Idle; Start then Execute.
        const PackmlScanRecord toManual = scanWith(simulator, {{"Cmd_Stop", "TRUE"}, {"KeyManual", "TRUE"}});
        // The request met Idle, where Manual is granted; Stop then acts in Manual.
        CHECK(toManual.mode == 3);
        CHECK(toManual.modeChanged());
        CHECK(firedText(toManual) == "Idle-Stop->Stopped");
        pulse(simulator, "Cmd_Start"); // not accepted in Stopped
        const PackmlScanRecord reset = pulse(simulator, "Cmd_Reset");
        REQUIRE(reset.fired);
        CHECK(reset.fired->destination.skipped == State::Resetting);
        pulse(simulator, "Cmd_Start");
        REQUIRE(simulator.state() == State::Execute);
        const PackmlScanRecord hold = pulse(simulator, "Cmd_Hold");
        REQUIRE(hold.dropped.size() == 1);
        CHECK(hold.dropped[0].reason == DropReason::NotAcceptedInMode);
        CHECK(toText(hold.dropped[0]) == "Hold is not accepted in Execute in Manual: the mode disables where it leads");
    }
    SECTION("CntrlCmd naming no command of the edition")
    {
        const PackmlScanRecord record = scanWith(simulator, {{"CntrlCmd", "10"}, {"CmdChangeRequest", "TRUE"}});
        REQUIRE(record.dropped.size() == 1);
        CHECK(record.dropped[0].reason == DropReason::NoSuchCommand);
        CHECK(toText(record.dropped[0]) == "CntrlCmd = 10 names no command");
    }
}

TEST_CASE("Execute resumes after the Hold loop, and starts fresh after a mode change granted in Held", "[packml-sim]")
{
    const Model model = resumeModel();
    PackmlSimulator simulator(model);
    REQUIRE(simulator.program().problems.empty());
    startExecute(simulator);
    REQUIRE(simulator.state() == State::Execute);
    CHECK(activeSteps(simulator, 1, State::Execute) == "1");
    setAll(simulator, {{"Capped", "TRUE"}});
    simulator.scan();
    CHECK(activeSteps(simulator, 1, State::Execute) == "2");
    CHECK(boolValue(simulator, "Eject"));
    setAll(simulator, {{"Capped", "FALSE"}});

    SECTION("resume: no Initialization call, the step it was paused in")
    {
        CHECK(firedText(pulse(simulator, "Cmd_Hold")) == "Execute-Hold->Holding");
        CHECK(simulator.resume());
        CHECK(firedText(simulator.scan()) == "Holding-SC->Held");
        CHECK(firedText(pulse(simulator, "Cmd_Unhold")) == "Held-Unhold->Unholding");
        CHECK(firedText(simulator.scan()) == "Unholding-SC->Execute");
        CHECK_FALSE(boolValue(simulator, "Eject")); // Entry: Execute's outputs come back when it runs
        const PackmlScanRecord resumed = simulator.scan();
        CHECK(resumed.resumed);
        CHECK(summaryText(resumed) == "resumed");
        CHECK(activeSteps(simulator, 1, State::Execute) == "2");
        CHECK(boolValue(simulator, "Eject"));
        CHECK_FALSE(simulator.resume());
    }
    SECTION("a mode change granted in Held makes the return fresh")
    {
        pulse(simulator, "Cmd_Hold");
        simulator.scan();
        REQUIRE(simulator.state() == State::Held);
        // Manual lists Held as a mode-change state but disables it.
        const PackmlScanRecord manual = requestMode(simulator, 3);
        REQUIRE(manual.dropped.size() == 1);
        CHECK(manual.dropped[0].reason == DropReason::DisabledInRequestedMode);
        CHECK(toText(manual.dropped[0]) == "Manual is not granted in Held: Manual disables it");
        simulator.scan();
        CHECK(summaryText(requestMode(simulator, 2)) == "mode 1->2");
        simulator.scan();
        CHECK(summaryText(requestMode(simulator, 1)) == "mode 2->1");
        CHECK_FALSE(simulator.resume());
        pulse(simulator, "Cmd_Unhold");
        simulator.scan();
        const PackmlScanRecord fresh = simulator.scan();
        CHECK(simulator.state() == State::Execute);
        CHECK_FALSE(fresh.resumed);
        CHECK(activeSteps(simulator, 1, State::Execute) == "1");
        CHECK(boolValue(simulator, "Cap"));
        CHECK_FALSE(boolValue(simulator, "Eject"));
    }
    SECTION("mode requests refused by the requested mode, pre-empted, for the current mode, or for no mode")
    {
        const PackmlScanRecord maintenance = requestMode(simulator, 2);
        REQUIRE(maintenance.dropped.size() == 1);
        CHECK(maintenance.dropped[0].reason == DropReason::NotAllowedByRequestedMode);
        CHECK(toText(maintenance.dropped[0]) == "Maintenance is not granted in Execute: Maintenance allows no mode change there");
        pulse(simulator, "Cmd_Stop");
        REQUIRE(simulator.state() == State::Stopping);
        simulator.scan();
        REQUIRE(simulator.state() == State::Stopped);
        // Maintenance through its request condition and Manual through UnitMode in one scan: 2 wins.
        const PackmlScanRecord both = scanWith(simulator, {{"KeyMaint", "TRUE"}, {"UnitMode", "3"},
                                                           {"UnitModeChangeRequest", "TRUE"}});
        CHECK(both.mode == 2);
        CHECK(droppedTexts(both)
              == std::vector<std::string>{"Manual is not granted: Maintenance, lower-numbered, is granted in the same scan"});
        setAll(simulator, {{"UnitModeChangeRequest", "FALSE"}});
        simulator.scan();
        CHECK(droppedTexts(requestMode(simulator, 2))
              == std::vector<std::string>{"Maintenance is requested: it is already the current mode"});
        simulator.scan();
        CHECK(droppedTexts(requestMode(simulator, 7)) == std::vector<std::string>{"UnitMode = 7 names no unit mode"});
        CHECK(simulator.mode() == 2);
    }
}

TEST_CASE("Edition 2022: Execute leaves on the Complete command, not on its GRAFCET's Complete", "[packml-sim]")
{
    for (const Edition edition : {Edition::Y2015, Edition::Y2022}) {
        Model model = newModel(edition);
        addGrafcet(model, 1, State::Execute, {{1, true, {"S Complete"}}}, {});
        PackmlSimulator simulator(model);
        startExecute(simulator);
        if (edition == Edition::Y2015) {
            // Execute's first scan already fired its SC.
            CHECK(simulator.state() == State::Completing);
            continue;
        }
        CHECK(simulator.state() == State::Execute);
        simulator.scan();
        CHECK(simulator.state() == State::Execute);
        CHECK(firedText(pulse(simulator, "Cmd_Complete")) == "Execute-Complete->Completing");
        CHECK(firedText(simulator.scan()) == "Completing-SC->Complete");
        CHECK(firedText(pulse(simulator, "Cmd_Reset")) == "Complete-Reset->Resetting");
    }
}

TEST_CASE("holdInSuspended: Hold in Suspended, and Execute resumes after both loops", "[packml-sim]")
{
    for (const bool holdInSuspended : {false, true}) {
        Model model = newModel(Edition::Y2015);
        Options options = model.packml()->options;
        options.holdInSuspended = holdInSuspended;
        REQUIRE(model.setPackMLOptions(options).ok);
        addVariable(model, "Capped", VariableKind::Input);
        addVariable(model, "Cap", VariableKind::Output);
        addGrafcet(model, 1, State::Execute, {{1, true, {}}, {2, false, {"N Cap"}}}, {{1, 1, 2, "Capped"}});
        PackmlSimulator simulator(model);
        startExecute(simulator);
        scanWith(simulator, {{"Capped", "TRUE"}});
        setAll(simulator, {{"Capped", "FALSE"}});
        CHECK(firedText(pulse(simulator, "Cmd_Suspend")) == "Execute-Suspend->Suspending");
        CHECK(firedText(simulator.scan()) == "Suspending-SC->Suspended");
        const PackmlScanRecord hold = pulse(simulator, "Cmd_Hold");
        if (!holdInSuspended) {
            CHECK(droppedTexts(hold) == std::vector<std::string>{"Hold is not accepted in Suspended"});
            continue;
        }
        CHECK(firedText(hold) == "Suspended-Hold->Holding");
        simulator.scan();
        pulse(simulator, "Cmd_Unhold");
        CHECK(firedText(simulator.scan()) == "Unholding-SC->Execute");
        CHECK(simulator.scan().resumed);
        CHECK(boolValue(simulator, "Cap"));
    }
}

TEST_CASE("A user mode runs its own instances and is entered through its request condition", "[packml-sim]")
{
    Model model = newModel(Edition::Y2015);
    REQUIRE(model.addMode(4, "Cleaning").ok);
    addVariable(model, "KeyClean", VariableKind::Input);
    addVariable(model, "Rinse", VariableKind::Output);
    REQUIRE(model.setModeRequest(4, "KeyClean").ok);
    REQUIRE(model.setModeDisabled(4, {State::Resetting, State::Starting}).ok);
    addGrafcet(model, 4, State::Execute, {{1, true, {"N Rinse"}}}, {});
    PackmlSimulator simulator(model);
    const PackmlScanRecord toCleaning = scanWith(simulator, {{"KeyClean", "TRUE"}});
    CHECK(summaryText(toCleaning) == "mode 1->4");
    CHECK(simulator.value("UnitModeCurrent") == std::optional<cond::Value>(std::int64_t{4}));
    CHECK(firedText(pulse(simulator, "Cmd_Reset")) == "Stopped-Reset->Idle");
    CHECK(firedText(pulse(simulator, "Cmd_Start")) == "Idle-Start->Execute");
    const PackmlScanRecord running = simulator.scan();
    REQUIRE(running.calledInstance >= 0);
    CHECK(simulator.program().instances[static_cast<std::size_t>(running.calledInstance)].name == "Cleaning_Execute");
    CHECK(boolValue(simulator, "Rinse"));
    // Stop drops the output in the scan it leaves Execute.
    pulse(simulator, "Cmd_Stop");
    CHECK_FALSE(boolValue(simulator, "Rinse"));
}

TEST_CASE("A TON of the resumed GRAFCET counts the pause (spec §4)", "[packml-sim]")
{
    Model model = newModel(Edition::Y2015);
    REQUIRE(model.setCycleTimeMs(100).ok);
    addVariable(model, "Done", VariableKind::Output);
    // Holding and Unholding skipped: Hold -> Held, Unhold -> Execute.
    REQUIRE(model.setModeDisabled(1, {State::Holding, State::Unholding}).ok);
    addGrafcet(model, 1, State::Execute, {{1, true, {}}, {2, false, {"N Done"}}}, {{1, 1, 2, "1s/X1"}});
    PackmlSimulator simulator(model);
    startExecute(simulator); // the TON of X1 starts in this call
    const std::int64_t started = simulator.simulatedTimeMs();
    simulator.scan(); // 100 ms in Execute
    CHECK(firedText(pulse(simulator, "Cmd_Hold")) == "Execute-Hold->Held");
    for (int i = 0; i < 20; ++i) // two seconds in Held: Execute's FB is not called
        simulator.scan();
    CHECK(activeSteps(simulator, 1, State::Execute) == "1");
    CHECK(firedText(pulse(simulator, "Cmd_Unhold")) == "Held-Unhold->Execute");
    // 100 ms of Execute only, but 2.3 s since the TON started: Q at the resume's call.
    const PackmlScanRecord resumed = simulator.scan();
    CHECK(resumed.resumed);
    CHECK(simulator.simulatedTimeMs() - started >= 1000);
    CHECK(activeSteps(simulator, 1, State::Execute) == "2");
    CHECK(boolValue(simulator, "Done"));
}

TEST_CASE("A manual SC holds or completes a state without GRAFCET (spec §4's simulation aid)", "[packml-sim]")
{
    Model model = newModel(Edition::Y2015);
    addGrafcet(model, 1, State::Starting, {{1, true, {"S Complete"}}}, {});
    PackmlSimulator simulator(model);
    const auto indexOf = [&](State state) {
        const ProgramInstance* instance = simulator.program().instance(1, state);
        REQUIRE(instance != nullptr);
        return static_cast<int>(instance - simulator.program().instances.data());
    };
    const int resetting = indexOf(State::Resetting);
    REQUIRE(simulator.setManualComplete(resetting, false).ok);
    CHECK(simulator.manualComplete(resetting) == std::optional<bool>(false));
    CHECK(firedText(pulse(simulator, "Cmd_Reset")) == "Stopped-Reset->Resetting");
    for (int i = 0; i < 3; ++i)
        CHECK(firedText(simulator.scan()) == "none"); // held: the skeleton would complete at once
    REQUIRE(simulator.setManualComplete(resetting, true).ok);
    CHECK(firedText(simulator.scan()) == "Resetting-SC->Idle");

    // Execute's skeleton never completes; a manual TRUE is its SC in 2015.
    const int execute = indexOf(State::Execute);
    REQUIRE(simulator.setManualComplete(execute, true).ok);
    CHECK(firedText(pulse(simulator, "Cmd_Start")) == "Idle-Start->Starting");
    CHECK(firedText(simulator.scan()) == "Starting-SC->Execute");
    CHECK(firedText(simulator.scan()) == "Execute-SC->Completing");
    const Status refused = simulator.setManualComplete(indexOf(State::Starting), true);
    CHECK_FALSE(refused.ok);
    CHECK(refused.message == "the Complete of Production_Starting comes from its nested GRAFCET");
    CHECK_FALSE(simulator.setManualComplete(-1, true).ok);

    // Back to the skeleton: Resetting completes at once again.
    REQUIRE(simulator.setManualComplete(resetting, std::nullopt).ok);
    simulator.reset();
    pulse(simulator, "Cmd_Reset");
    CHECK(firedText(simulator.scan()) == "Resetting-SC->Idle");
    CHECK(simulator.manualComplete(execute) == std::optional<bool>(true)); // kept by reset()
}

TEST_CASE("An integer division by zero stops the run where the PLC stops", "[packml-sim]")
{
    Model model = newModel(Edition::Y2015);
    addVariable(model, "Count", VariableKind::Input, IecType::Int);
    addVariable(model, "Batch", VariableKind::Input, IecType::Int);
    addVariable(model, "Cap", VariableKind::Output);

    SECTION("in a command condition: the scan stops in section 1")
    {
        REQUIRE(model.setCommandCondition(Command::Start, "Count / Batch > 1").ok);
        PackmlSimulator simulator(model);
        const PackmlScanRecord first = pulse(simulator, "Cmd_Reset");
        REQUIRE(simulator.fault().has_value());
        CHECK_FALSE(first.fired); // Reset's edge came before, but the state machine never ran
        CHECK(toText(*simulator.fault())
              == "scan 1: integer division by zero in the condition of the Start command (Count / Batch in "
                 "'Count / Batch > 1'): the PLC stops with a fault, and so does the simulation");
        simulator.scan();
        CHECK(simulator.scanCount() == 1);
        simulator.reset();
        CHECK_FALSE(simulator.fault().has_value());
        // A scenario stops at the fault: its later scans never run, its expectations are not checked.
        const ScenarioParseResult parsed = parseScenario("at 1: command Reset\nat 1: expect state Idle\nat 3: expect state Idle\n");
        REQUIRE(parsed.ok());
        const PackmlScenarioRunResult result = runPackmlScenario(parsed.scenario, simulator);
        CHECK(result.records.size() == 1);
        CHECK(result.failures.empty());
        CHECK(result.fault.has_value());
        CHECK_FALSE(result.passed());
    }
    SECTION("in a GRAFCET: after the instance's call, before the transitions")
    {
        addGrafcet(model, 1, State::Resetting, {{1, true, {"N Cap"}}, {2, false, {}}}, {{1, 1, 2, "Count / Batch > 1"}});
        PackmlSimulator simulator(model);
        pulse(simulator, "Cmd_Reset");
        CHECK_FALSE(simulator.fault().has_value());
        const PackmlScanRecord faulted = scanWith(simulator, {{"Cmd_Abort", "TRUE"}});
        REQUIRE(simulator.fault().has_value());
        CHECK(simulator.fault()->stepId == "Production_Resetting");
        CHECK(simulator.fault()->scan == 2);
        CHECK_FALSE(faulted.fired); // the Abort never came to be evaluated
        CHECK(simulator.state() == State::Resetting);
    }
}

} // namespace test_packmlsimulator
