// Faults of the virtual machine (core/machine/fault.h, docs/simulation.md,
// "Faults"): sensors stuck or flickering and components jammed, applied
// before a scan so that this scan reads them, refused on what the machine
// does not drive; and the scenario lines that inject them.

#include "core/formats/fileio.h"
#include "core/formats/modelfiles.h"
#include "core/machine/closedloopscenario.h"
#include "core/machine/fault.h"
#include "core/machine/machineloop.h"
#include "core/simulation/scenario.h"
#include "core/simulation/simulator.h"

#include <catch2/catch.hpp>

#include <memory>
#include <string>
#include <vector>

namespace test_machinefaults {

using namespace core;
using namespace core::machine;

namespace {

std::unique_ptr<Model> drillingCell(const std::string& file = "drilling-cell.ggstudio.json")
{
    auto loaded = loadModelFile(GGSTUDIO_EXAMPLES_DIR "/" + file);
    REQUIRE(loaded.model);
    return std::move(loaded.model);
}

std::string exampleText(const std::string& file)
{
    std::string text;
    REQUIRE(readFileLimited(GGSTUDIO_EXAMPLES_DIR "/" + file, 1u << 20, text));
    return text;
}

bool reads(const Simulator& simulator, const std::string& name)
{
    return simulator.variable(name) == cond::Value{true};
}

// Parses, validates in closed loop and runs a scenario on the drilling cell.
ScenarioRunResult runClosedLoop(const std::string& text, const std::string& modelFile = "drilling-cell.ggstudio.json")
{
    const auto model = drillingCell(modelFile);
    Simulator simulator(*model);
    MachineLoop loop(simulator, model->machine());
    const ScenarioParseResult parsed = parseScenario(text, "f.scenario");
    for (const ScenarioError& error : parsed.errors)
        FAIL_CHECK(error.toString());
    REQUIRE(parsed.ok());
    REQUIRE(validateScenario(parsed.scenario, simulator, FaultLines::CheckedByMachine).empty());
    const std::vector<ScenarioError> errors = validateClosedLoopScenario(parsed.scenario, loop);
    for (const ScenarioError& error : errors)
        FAIL_CHECK(error.toString());
    return runScenario(parsed.scenario, loop);
}

void requirePassed(const ScenarioRunResult& result)
{
    for (const ScenarioFailure& failure : result.failures)
        FAIL_CHECK(toText(failure));
    CHECK(result.passed());
}

// Press Start: F1 from scan 1003, ClampOut from scan 1124, Clamped read at scan 1154.
const std::string kStart = "at 1: set StartButton = TRUE\nat 3: set StartButton = FALSE\n";

} // namespace

TEST_CASE("A sensor stuck at FALSE is read from the scan it begins, and reads the machine again once cleared",
          "[machine][faults]")
{
    requirePassed(runClosedLoop(kStart + "at 1100: fault Clamped stuck FALSE\n"
                                         "at 1154: expect variable Clamped = FALSE\n"
                                         "at 1154: expect nested F1 steps 2\n" // still clamping
                                         "at 1199: expect variable Clamped = FALSE\n"
                                         "at 1200: fault clamped clear\n"
                                         "at 1200: expect variable Clamped = TRUE\n" // the machine's value, at once
                                         "at 1200: expect nested F1 steps 3, 5\n"));
}

TEST_CASE("A sensor stuck at TRUE reads TRUE whatever the machine does", "[machine][faults]")
{
    requirePassed(runClosedLoop("at 4: expect variable DrillLow = FALSE\n"
                                "at 5: fault DrillLow stuck TRUE\n"
                                "at 5: expect variable DrillLow = TRUE\n"
                                "at 500: expect variable DrillLow = TRUE\n"));
}

TEST_CASE("A flickering sensor reads the opposite of its previous reading at every scan", "[machine][faults]")
{
    const auto model = drillingCell();
    Simulator simulator(*model);
    MachineLoop loop(simulator, model->machine());
    REQUIRE(reads(simulator, "DrillHigh"));
    REQUIRE(loop.applyFault({FaultKind::Flicker, "DrillHigh"}));
    CHECK(loop.sensorFault("drillhigh") == SensorFault::Flicker);
    CHECK_FALSE(reads(simulator, "DrillHigh")); // the next scan reads it
    std::vector<bool> readings;
    for (int i = 0; i < 4; ++i) {
        readings.push_back(reads(simulator, "DrillHigh"));
        loop.step();
    }
    CHECK(readings == std::vector<bool>{false, true, false, true});
    REQUIRE(loop.applyFault({FaultKind::Clear, "DrillHigh"}));
    CHECK(reads(simulator, "DrillHigh")); // the head is up
    loop.step();
    CHECK(reads(simulator, "DrillHigh"));
}

TEST_CASE("A jammed cylinder stops where it is, whatever its outputs, until cleared", "[machine][faults]")
{
    requirePassed(runClosedLoop(kStart + "at 1100: fault Clamp jam\n"
                                         "at 1154: expect variable ClampOut = TRUE\n"
                                         "at 1154: expect variable Clamped = FALSE\n"
                                         "at 1154: expect variable Unclamped = TRUE\n" // it never left
                                         "at 1160: fault Clamp clear\n"
                                         // the cycle after scan 1160 is the first to move it: 30 cycles
                                         "at 1189: expect variable Clamped = FALSE\n"
                                         "at 1190: expect variable Clamped = TRUE\n"));
    const auto model = drillingCell();
    Simulator simulator(*model);
    MachineLoop loop(simulator, model->machine());
    REQUIRE(loop.applyFault({FaultKind::Jam, "infeed"}));
    CHECK(loop.state().jammed(2));
    loop.reset(); // a new run: every fault cleared
    CHECK_FALSE(loop.state().jammed(2));
}

TEST_CASE("A reset clears the sensor faults", "[machine][faults]")
{
    const auto model = drillingCell();
    Simulator simulator(*model);
    MachineLoop loop(simulator, model->machine());
    REQUIRE(loop.applyFault({FaultKind::StuckFalse, "DrillHigh"}));
    CHECK_FALSE(reads(simulator, "DrillHigh"));
    loop.reset();
    CHECK(loop.sensorFault("DrillHigh") == SensorFault::None);
    CHECK(reads(simulator, "DrillHigh"));
}

TEST_CASE("Faults on what the machine does not drive are refused", "[machine][faults]")
{
    const auto model = drillingCell();
    Simulator simulator(*model);
    MachineLoop loop(simulator, model->machine());
    const auto refusal = [&](FaultKind kind, const std::string& target) {
        const std::optional<FaultRefusal> found = loop.checkFault({kind, target});
        return found ? toText(*found) : std::string("accepted");
    };
    CHECK(refusal(FaultKind::StuckTrue, "startbutton")
          == "StartButton is an operator input of the machine's Start: the user drives it with set; a fault applies "
             "to the machine's sensors");
    CHECK(refusal(FaultKind::Flicker, "ClampOut")
          == "ClampOut is no sensor of the machine: a fault applies to the inputs a component writes");
    CHECK(refusal(FaultKind::StuckFalse, "Ghost") == "unknown variable 'Ghost'");
    CHECK(refusal(FaultKind::Jam, "Ready") == "Ready is a lamp: only cylinders and conveyors jam");
    CHECK(refusal(FaultKind::Jam, "Clamped") == "no component 'Clamped' in the machine");
    CHECK(refusal(FaultKind::Clear, "Ghost") == "'Ghost' is neither a sensor nor a component of the machine");
    CHECK(refusal(FaultKind::Clear, "DrillHead") == "accepted");
    CHECK(refusal(FaultKind::StuckTrue, "PartPresent") == "accepted");
    const bool before = reads(simulator, "StartButton");
    CHECK_FALSE(loop.applyFault({FaultKind::StuckTrue, "StartButton"}));
    CHECK(reads(simulator, "StartButton") == before);
}

TEST_CASE("Scenario fault lines are parsed strictly, with their line and column", "[machine][faults][scenario]")
{
    const ScenarioParseResult parsed = parseScenario("at 120: fault Clamped stuck false\n"
                                                     "at 121: FAULT Clamp Jam   # a comment\n"
                                                     "at 122: fault PartPresent flicker\n"
                                                     "at 130: fault Clamp clear\n",
                                                     "s.scenario");
    REQUIRE(parsed.ok());
    REQUIRE(parsed.scenario.actions.size() == 4);
    const ScenarioAction& stuck = parsed.scenario.actions[0];
    CHECK(stuck.kind == ScenarioAction::Kind::Fault);
    CHECK(stuck.scan == 120);
    CHECK(stuck.column == 15);
    CHECK_FALSE(stuck.isExpectation());
    CHECK(scenarioFault(stuck) == Fault{FaultKind::StuckFalse, "Clamped"});
    CHECK(scenarioFault(parsed.scenario.actions[1]) == Fault{FaultKind::Jam, "Clamp"});
    CHECK(scenarioFault(parsed.scenario.actions[2]) == Fault{FaultKind::Flicker, "PartPresent"});
    CHECK(scenarioFault(parsed.scenario.actions[3]) == Fault{FaultKind::Clear, "Clamp"});

    const auto firstError = [](const std::string& text) {
        const ScenarioParseResult result = parseScenario(text, "s.scenario");
        return result.errors.empty() ? std::string("no error") : result.errors.front().toString();
    };
    CHECK(firstError("at 1: fault\n") == "s.scenario:1:12: expected a sensor or component name after 'fault', found "
                                         "the end of the line");
    CHECK(firstError("at 1: fault Clamped\n")
          == "s.scenario:1:20: expected stuck, flicker, jam or clear after the name, found the end of the line");
    CHECK(firstError("at 1: fault Clamped stuck maybe\n") == "s.scenario:1:27: expected TRUE or FALSE, found 'maybe'");
    CHECK(firstError("at 1: fault Clamped broken\n")
          == "s.scenario:1:21: expected stuck, flicker, jam or clear after the name, found 'broken'");
    CHECK(firstError("at 1: fault Clamp jam now\n") == "s.scenario:1:23: expected the end of the line, found 'now'");
    CHECK(firstError("at 1: fault = jam\n")
          == "s.scenario:1:13: expected a sensor or component name after 'fault', found '='");
}

TEST_CASE("Scenario fault lines are checked against the machine, and refused in open loop",
          "[machine][faults][scenario]")
{
    const auto model = drillingCell();
    Simulator simulator(*model);
    MachineLoop loop(simulator, model->machine());
    const ScenarioParseResult parsed = parseScenario("at 1: fault StartButton stuck TRUE\n"
                                                     "at 2: fault Ready jam\n"
                                                     "at 3: fault Ghost clear\n"
                                                     "at 4: fault ClampIn flicker\n"
                                                     "at 5: fault Nobody jam\n"
                                                     "at 6: fault Ghost stuck FALSE\n"
                                                     "at 7: fault Clamped stuck TRUE\n",
                                                     "s.scenario");
    REQUIRE(parsed.ok());
    const std::vector<ScenarioError> errors = validateClosedLoopScenario(parsed.scenario, loop);
    REQUIRE(errors.size() == 6);
    using Kind = ScenarioError::Kind;
    CHECK(errors[0].kind == Kind::FaultOnOperatorInput);
    CHECK(errors[0].detail == "Start");
    CHECK(errors[0].toString().rfind("s.scenario:1:13: StartButton is an operator input", 0) == 0);
    CHECK(errors[1].kind == Kind::FaultCannotJam);
    CHECK(errors[2].kind == Kind::FaultUnknownTarget);
    CHECK(errors[3].kind == Kind::FaultNotMachineSensor);
    CHECK(errors[4].kind == Kind::FaultUnknownComponent);
    CHECK(errors[5].kind == Kind::UnknownVariable);
    CHECK(errors[5].toString() == "s.scenario:6:13: unknown variable 'Ghost'");

    // Open loop: no machine to fault.
    const std::vector<ScenarioError> openLoop = validateScenario(parsed.scenario, simulator);
    REQUIRE(openLoop.size() == 7);
    CHECK(openLoop[0].kind == Kind::FaultInOpenLoop);
    CHECK(openLoop[0].toString()
          == "s.scenario:1:13: a fault needs the virtual machine: run the scenario in closed loop, on a model with a "
             "machine");
    CHECK(validateScenario(parsed.scenario, simulator, FaultLines::CheckedByMachine).empty());
    // Played anyway in open loop, a fault cannot apply.
    const ScenarioRunResult run = runScenario(parsed.scenario, simulator);
    REQUIRE_FALSE(run.failures.empty());
    CHECK(run.failures[0].kind == ScenarioFailure::Kind::CannotApply);
}

TEST_CASE("A recorded run with faults writes fault lines that replay", "[machine][faults][scenario]")
{
    ScenarioRecording recording;
    RecordedScan first;
    first.scan = 1;
    first.inputs.push_back({"StartButton", cond::Value{true}});
    first.faults.push_back({FaultKind::StuckFalse, "Clamped"});
    RecordedScan later;
    later.scan = 9;
    later.faults.push_back({FaultKind::Jam, "Clamp"});
    later.faults.push_back({FaultKind::Clear, "Clamped"});
    recording.changes = {first, later};
    const std::string text = writeScenario(recording);
    CHECK(text == "at 1: set StartButton = TRUE\nat 1: fault Clamped stuck FALSE\nat 9: fault Clamp jam\n"
                  "at 9: fault Clamped clear\n");
    const ScenarioParseResult parsed = parseScenario(text);
    REQUIRE(parsed.ok());
    REQUIRE(parsed.scenario.actions.size() == 4);
    CHECK(scenarioFault(parsed.scenario.actions[2]) == Fault{FaultKind::Jam, "Clamp"});
}

TEST_CASE("The watchdog example goes to D2 when a limit switch does not arrive within its travel time and margin",
          "[machine][faults][example]")
{
    const std::string model = "drilling-cell-watchdog.ggstudio.json";
    const ScenarioRunResult faulty = runClosedLoop(exampleText("drilling-cell-clamp-fault.scenario"), model);
    requirePassed(faulty);
    // ClampOut from scan 1124; 300 ms of travel and 200 ms of margin at 10 ms: step 10 at 1174, D2 next.
    std::int64_t inD2 = 0;
    for (const ScanRecord& record : faulty.records) {
        if (inD2 == 0 && record.stepAfter == "D2")
            inD2 = record.scan;
    }
    CHECK(inD2 == 1124 + 30 + 20 + 1);
    // A sound machine: no false alarm, the start scenario passes as on the plain cell.
    const ScenarioRunResult sound = runClosedLoop(exampleText("drilling-cell-start.scenario"), model);
    requirePassed(sound);
    for (const ScanRecord& record : sound.records)
        CHECK(record.stepAfter != "D2");
    // The drill head's switch: the 2 s watchdog of step 3.
    const ScenarioRunResult drill = runClosedLoop("at 1: set StartButton = TRUE\nat 3: set StartButton = FALSE\n"
                                                  "at 1200: fault DrillLow stuck FALSE\n"
                                                  "at 1500: expect step D2\n",
                                                  model);
    requirePassed(drill);
}

} // namespace test_machinefaults
