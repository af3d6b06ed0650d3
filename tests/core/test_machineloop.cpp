// The closed loop (core/machine/machineloop.h): the GEMMA simulator and the
// model's virtual machine, scan K's outputs moving the machine for one cycle
// and its sensors read by scan K+1; and the shipped drilling cell with its
// machine, played by the operator's actions only.

#include "core/formats/fileio.h"
#include "core/formats/modelfiles.h"
#include "core/machine/closedloopscenario.h"
#include "core/machine/machineloop.h"
#include "core/simulation/scenario.h"
#include "core/simulation/simulator.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

namespace test_machineloop {

using namespace core;
using namespace core::machine;

namespace {

std::unique_ptr<Model> drillingCell()
{
    auto loaded = loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    REQUIRE(loaded.model);
    return std::move(loaded.model);
}

Scenario startScenario()
{
    std::string text;
    REQUIRE(readFileLimited(GGSTUDIO_EXAMPLES_DIR "/drilling-cell-start.scenario", 1u << 20, text));
    ScenarioParseResult parsed = parseScenario(text, "drilling-cell-start.scenario");
    REQUIRE(parsed.ok());
    return parsed.scenario;
}

bool changed(const std::vector<InputChange>& changes, const std::string& name, bool value)
{
    return std::any_of(changes.begin(), changes.end(), [&](const InputChange& c) {
        return c.variable == name && c.value == cond::Value{value};
    });
}

} // namespace

TEST_CASE("The machine's sensors are the inputs of the next scan", "[machine][machine-loop]")
{
    const auto model = drillingCell();
    Simulator simulator(*model);
    MachineLoop loop(simulator, model->machine());
    // The start state: the cylinders retracted, a part on the infeed's entry,
    // the emergency stop released.
    CHECK(simulator.variable("DrillHigh") == cond::Value{true});
    CHECK(simulator.variable("Unclamped") == cond::Value{true});
    CHECK(simulator.variable("EmergencyOk") == cond::Value{true});
    CHECK(simulator.variable("PartPresent") == cond::Value{false});
    CHECK(loop.drivesVariable("clamped"));
    CHECK_FALSE(loop.drivesVariable("StartButton")); // an operator input: the user's
    REQUIRE(loop.sensorOwner("DrillLow"));
    CHECK(loop.sensorOwner("DrillLow")->name == "DrillHead");

    REQUIRE(simulator.setVariable("StartButton", true));
    loop.step();
    REQUIRE(simulator.setVariable("StartButton", false));
    // Run until the program extends the clamp, then count the cycles to its limit switch.
    std::int64_t clampOut = 0;
    for (int i = 0; i < 2000 && clampOut == 0; ++i) {
        const ScanRecord record = loop.step();
        if (changed(record.changedOutputs, "ClampOut", true))
            clampOut = record.scan;
    }
    REQUIRE(clampOut > 0);
    // The cycle after scan K moved the rod off its home switch; scan K+1 reads it.
    CHECK(changed(loop.lastSensorChanges(), "Unclamped", false));
    CHECK(changed(loop.step().changedInputs, "Unclamped", false));
    std::int64_t clamped = 0;
    for (int i = 0; i < 100 && clamped == 0; ++i) {
        const ScanRecord record = loop.step();
        if (changed(record.changedInputs, "Clamped", true))
            clamped = record.scan;
        if (changed(loop.lastSensorChanges(), "Clamped", true))
            CHECK(clamped == 0); // the machine sets it after the scan, the next scan reads it
    }
    CHECK(clamped == clampOut + 30); // 300 ms at 10 ms: 30 cycles, read by the scan after the 30th
}

TEST_CASE("The drilling cell drills its parts in closed loop from the operator's actions",
          "[machine][machine-loop][example]")
{
    const auto model = drillingCell();
    const Scenario scenario = startScenario();
    // The scenario sets only operator inputs.
    for (const ScenarioAction& action : scenario.actions) {
        if (action.kind == ScenarioAction::Kind::SetVariable)
            CHECK(action.name == "StartButton");
    }
    Simulator simulator(*model);
    MachineLoop loop(simulator, model->machine());
    REQUIRE(validateScenario(scenario, simulator).empty());
    REQUIRE(validateClosedLoopScenario(scenario, loop).empty());
    const ScenarioRunResult result = runScenario(scenario, loop);
    for (const ScenarioFailure& failure : result.failures)
        FAIL_CHECK(toText(failure));
    CHECK(result.passed());

    // The states the open-loop scenario reached by setting the sensors by
    // hand: F1, the part clamped (F1 step 2 with ClampOut), drilled and
    // marked in parallel (steps 3 and 5), then, past it, the part unclamped,
    // ejected and counted.
    const std::vector<ScanRecord>& records = result.records;
    const auto firstScan = [&](auto&& holds) {
        const auto found = std::find_if(records.begin(), records.end(), holds);
        return found == records.end() ? std::int64_t{0} : found->scan;
    };
    const std::vector<std::string>& nested = simulator.nestedSteps();
    const auto f1 = static_cast<std::size_t>(std::find(nested.begin(), nested.end(), "F1") - nested.begin());
    const auto nestedF1 = [&](std::vector<int> steps) {
        return [f1, steps](const ScanRecord& r) { return r.stepAfter == "F1" && r.nestedActive[f1] == steps; };
    };
    const std::int64_t inF1 = firstScan([](const ScanRecord& r) { return r.stepAfter == "F1"; });
    const std::int64_t clamping = firstScan(nestedF1({2}));
    const std::int64_t drilling = firstScan(nestedF1({3, 5}));
    const std::int64_t unclamping = firstScan(nestedF1({7}));
    const std::int64_t ejecting = firstScan(nestedF1({8}));
    CHECK(inF1 == 1003);
    CHECK(clamping > inF1);
    CHECK(drilling > clamping);
    CHECK(unclamping > drilling);
    CHECK(ejecting > unclamping);
    CHECK(simulator.variable("PartCount") == cond::Value{std::int64_t{1}});
    CHECK(loop.state().partsDelivered(2) == 1); // the Infeed conveyor carried the part off
}

TEST_CASE("A closed-loop scenario may not set the machine's sensors", "[machine][machine-loop]")
{
    const auto model = drillingCell();
    Simulator simulator(*model);
    MachineLoop loop(simulator, model->machine());
    const ScenarioParseResult parsed =
        parseScenario("at 1: set StartButton = TRUE\nat 2: set EmergencyOk = FALSE, clamped = TRUE\n", "s.scenario");
    REQUIRE(parsed.ok());
    const std::vector<ScenarioError> errors = validateClosedLoopScenario(parsed.scenario, loop);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].kind == ScenarioError::Kind::MachineSensor);
    CHECK(errors[0].toString() == "s.scenario:2:32: Clamped is a sensor of the machine's Clamp: the machine sets it; "
                                  "set it by hand in open loop only");
}

TEST_CASE("The simulator alone ignores the machine", "[machine][machine-loop]")
{
    const auto model = drillingCell();
    Simulator simulator(*model);
    CHECK(simulator.variable("DrillHigh") == cond::Value{false});
    simulator.run(5);
    CHECK(simulator.variable("DrillHigh") == cond::Value{false});
    CHECK(simulator.activeStepId() == "A1");
}

TEST_CASE("A loop restored to a past scan plays on as it did then", "[machine][machine-loop]")
{
    const auto model = drillingCell();
    Simulator simulator(*model);
    MachineLoop loop(simulator, model->machine());
    simulator.setVariable("StartButton", cond::Value{true});
    loop.run(2);
    simulator.setVariable("StartButton", cond::Value{false});
    loop.run(1130); // the clamp is moving
    const Simulator simulatorThen = simulator;
    const MachineLoop::Snapshot machineThen = loop.snapshot();
    const double clampThen = loop.state().position(0);
    REQUIRE(clampThen > 0.0);
    REQUIRE(clampThen < 1.0);
    loop.run(100);
    const std::string stepLater = simulator.activeStepId();
    const double drillLater = loop.state().position(1);
    REQUIRE(loop.state().position(0) == 1.0);

    simulator = simulatorThen;
    loop.restore(machineThen);
    CHECK(loop.state().position(0) == clampThen);
    loop.run(100);
    CHECK(simulator.activeStepId() == stepLater);
    CHECK(loop.state().position(1) == drillLater);
    CHECK(loop.state().position(0) == 1.0);
}

TEST_CASE("A loop restored to a past scan takes back the faults of then", "[machine][machine-loop][fault]")
{
    const auto model = drillingCell();
    Simulator simulator(*model);
    MachineLoop loop(simulator, model->machine());
    loop.run(3);
    const Simulator simulatorThen = simulator;
    const MachineLoop::Snapshot sound = loop.snapshot();
    REQUIRE(loop.applyFault({FaultKind::StuckTrue, "Clamped"}));
    REQUIRE(loop.applyFault({FaultKind::Jam, "Clamp"}));
    loop.run(2);
    const MachineLoop::Snapshot faulted = loop.snapshot();
    CHECK(loop.sensorFault(faulted, "clamped") == SensorFault::StuckTrue);
    CHECK(loop.sensorFault(sound, "Clamped") == SensorFault::None);
    CHECK(simulator.variable("Clamped") == cond::Value{true});

    simulator = simulatorThen;
    loop.restore(sound);
    CHECK(loop.sensorFault("Clamped") == SensorFault::None);
    CHECK_FALSE(loop.state().jammed(0));
    loop.run(2);
    CHECK(simulator.variable("Clamped") == cond::Value{false});

    loop.restore(faulted);
    CHECK(loop.sensorFault("Clamped") == SensorFault::StuckTrue);
    CHECK(loop.state().jammed(0));
}

} // namespace test_machineloop
