// Verification in closed loop (docs/verification.md, "Closed loop
// (--machine)"): the program explored with its machine, the inputs the
// machine's sensors drive computed from its state; counterexamples replayed
// with core::machine::MachineLoop.

#include "samplemodels.h"
#include "verificationtestsupport.h"

#include "core/formats/modelfiles.h"
#include "core/machine/machine.h"
#include "core/machine/machineloop.h"
#include "core/machine/machinestate.h"
#include "core/model/model.h"
#include "core/simulation/simulator.h"
#include "core/verification/closedloopreplay.h"
#include "core/verification/property.h"
#include "core/verification/propertyevaluation.h"
#include "core/verification/verification.h"

#include <catch2/catch.hpp>

#include <memory>
#include <string>
#include <vector>

namespace test_closedloopverification {

using namespace core;
using namespace core::machine;
using verificationtest::codesOf;
using verificationtest::findingOf;
using verificationtest::require;

namespace {

std::unique_ptr<Model> drillingCell()
{
    auto loaded = loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    REQUIRE(loaded.model);
    return std::move(loaded.model);
}

VerificationOptions withProperty(const std::string& property, bool closedLoop)
{
    VerificationOptions options;
    options.properties = {property};
    options.closedLoop = closedLoop;
    options.timeLimit = std::chrono::milliseconds(60'000);
    return options;
}

PropertyOutcome outcomeOf(const VerificationResult& result)
{
    INFO(codesOf(result).size());
    REQUIRE(result.propertyVerdicts.size() == 1);
    return result.propertyVerdicts.front().outcome;
}

// F1's GRAFCET: 1 --A--> 2 (N Lamp) --B--> 1, Lamp extending a
// single-acting cylinder whose retracted switch is A and extended switch B,
// 3 cycles out (60 ms at 20 ms) and 2 back.
Model cylinderCell()
{
    Model model = samples::nestedMachine();
    samples::addMachineStep(model, 1, true);
    samples::addMachineStep(model, 2, false, {{ActionTiming::Continuous, "N Lamp"}});
    samples::addMachineTransition(model, 1, {1}, {2}, "A");
    samples::addMachineTransition(model, 2, {2}, {1}, "B");
    Component cylinder = makeComponent(ComponentKind::SingleActingCylinder, "Pusher");
    REQUIRE(cylinder.setSignal("extend", "Lamp"));
    REQUIRE(cylinder.setSignal("retracted", "A"));
    REQUIRE(cylinder.setSignal("extended", "B"));
    REQUIRE(cylinder.setParameter("extendMs", 60));
    REQUIRE(cylinder.setParameter("retractMs", 40));
    require(model.setMachine(Machine{{cylinder}}));
    return model;
}

// The counterexample of the property's violation, replayed with the
// machine up to its last scan: whether the property is violated there.
bool replaysToViolation(const Model& model, const VerificationResult& result, const std::string& property)
{
    const VerificationFinding* violated = findingOf(result, verification::kPropertyViolated);
    REQUIRE(violated);
    REQUIRE(violated->counterexample);
    const Counterexample& counterexample = *violated->counterexample;
    INFO(counterexample.text);
    CHECK(counterexample.confirmed);
    CHECK(counterexample.text.find("closed loop") != std::string::npos);
    Simulator simulator(model);
    MachineLoop loop(simulator, model.machine());
    const ScenarioRunResult run = replayClosedLoop(counterexample.scenario, loop, counterexample.scans);
    CHECK(run.passed());
    return propertyViolatedOn(model, parseProperty(property), simulator);
}

} // namespace

TEST_CASE("A machine state's key restores the same state and futures", "[closed-loop-verify]")
{
    const auto model = drillingCell();
    const Machine& machine = model->machine();
    std::vector<std::string> names;
    const auto wires = [&](std::string_view name, SignalDirection) {
        names.emplace_back(name);
        return static_cast<int>(names.size()) - 1;
    };
    MachineState running(machine, 10, wires);
    std::string start;
    running.appendKey(start);
    for (std::size_t slot = 0; slot < running.signalSlots().size(); ++slot) {
        const std::string& name = names[static_cast<std::size_t>(running.signalSlots()[slot].variable)];
        running.setSignal(slot, name == "Conveyor" || name == "DrillDown");
    }
    for (int i = 0; i < 37; ++i)
        running.cycle(); // a part travels on the infeed, the drill head goes down
    std::string moved;
    running.appendKey(moved);
    CHECK(moved != start);

    MachineState restored(machine, 10, [](std::string_view, SignalDirection) { return -1; });
    CHECK(restored.restoreKey(moved) == moved.size());
    std::string again;
    restored.appendKey(again);
    CHECK(again == moved);
    for (std::size_t c = 0; c < machine.components.size(); ++c) {
        CHECK(restored.position(c) == running.position(c));
        CHECK(restored.hasPart(c) == running.hasPart(c));
        CHECK(restored.partsLeft(c) == running.partsLeft(c));
    }
    CHECK(restored.restoreKey(std::string_view(moved).substr(0, 1)) == 0); // truncated: refused
}

TEST_CASE("Limit switches of one cylinder: never together with the machine, free without it",
          "[closed-loop-verify]")
{
    const Model model = cylinderCell();
    const std::string property = "never A AND B";
    const VerificationResult open = verifyModel(model, withProperty(property, false));
    CHECK(outcomeOf(open) == PropertyOutcome::Violated);
    CHECK_FALSE(open.closedLoop);

    const VerificationResult closed = verifyModel(model, withProperty(property, true));
    INFO(codesOf(closed).size());
    CHECK(closed.closedLoop);
    CHECK(closed.exhaustive);
    CHECK(outcomeOf(closed) == PropertyOutcome::Holds);
}

TEST_CASE("By hand: step 2 is left in the scan that reads the extended switch", "[closed-loop-verify]")
{
    // Step 2 is entered on A (the rod retracted) and left on B: it can never
    // be active at the end of a scan that read B. It can be active in the
    // scan that entered it, which still read A.
    const Model model = cylinderCell();
    const VerificationResult holds = verifyModel(model, withProperty("never F1.X2 AND B", true));
    CHECK(outcomeOf(holds) == PropertyOutcome::Holds);
    CHECK(outcomeOf(verifyModel(model, withProperty("never F1.X2 AND B", false))) == PropertyOutcome::Violated);

    const std::string violated = "never F1.X2 AND A";
    const VerificationResult result = verifyModel(model, withProperty(violated, true));
    REQUIRE(outcomeOf(result) == PropertyOutcome::Violated);
    CHECK(replaysToViolation(model, result, violated));
}

TEST_CASE("A part source without limit keeps the closed-loop exploration finite", "[closed-loop-verify]")
{
    // The conveyor runs while Lamp is TRUE (in F1): the parts delivered grow
    // without bound but are no part of the state. A part is at the sensor A
    // for one scan: the scan that reads it leaves step 1, the next leaves 2.
    Model model = samples::nestedMachine();
    samples::addMachineStep(model, 1, true, {{ActionTiming::Continuous, "N Lamp"}});
    samples::addMachineStep(model, 2, false, {{ActionTiming::Continuous, "N Lamp"}});
    samples::addMachineTransition(model, 1, {1}, {2}, "A");
    samples::addMachineTransition(model, 2, {2}, {1}, "NOT A");
    Component conveyor = makeComponent(ComponentKind::Conveyor, "Belt");
    REQUIRE(conveyor.setSignal("run", "Lamp"));
    REQUIRE(conveyor.setSignal("partPresent", "A"));
    REQUIRE(conveyor.setParameter("travelMs", 100));
    Component source = makeComponent(ComponentKind::PartSource, "Hopper");
    REQUIRE(source.setParameter("parts", kUnlimitedParts));
    source.conveyor = "Belt";
    require(model.setMachine(Machine{{conveyor, source}}));

    VerificationOptions options = withProperty("never F1.X1 AND A", true);
    options.maxProgramStates = 5'000;
    const VerificationResult result = verifyModel(model, options);
    INFO(codesOf(result).size());
    CHECK(result.exhaustive);
    CHECK(result.programStates < 1000);
    CHECK(outcomeOf(result) == PropertyOutcome::Holds);
    // Counted in scans, the same.
    options.exactTime = true;
    const VerificationResult counted = verifyModel(model, options);
    CHECK(counted.exhaustive);
    CHECK(outcomeOf(counted) == PropertyOutcome::Holds);
}

TEST_CASE("Drilling cell: the machine's physics excludes what arbitrary sensors allow", "[closed-loop-verify]")
{
    const auto model = drillingCell();
    for (const std::string property : {"never Clamped AND Unclamped", "never DrillLow AND DrillHigh"}) {
        INFO(property);
        CHECK(outcomeOf(verifyModel(*model, withProperty(property, false))) == PropertyOutcome::Violated);
        const VerificationResult closed = verifyModel(*model, withProperty(property, true));
        CHECK(closed.closedLoop);
        CHECK(closed.exhaustive);
        CHECK(outcomeOf(closed) == PropertyOutcome::Holds);
    }
}

TEST_CASE("Drilling cell: a closed-loop violation replays with the machine", "[closed-loop-verify]")
{
    // Marking (F1's step 5) runs beside drilling (step 3): the marker is on
    // while the drill head is down.
    const auto model = drillingCell();
    const std::string property = "never Marker AND NOT DrillHigh";
    const VerificationResult result = verifyModel(*model, withProperty(property, true));
    REQUIRE(outcomeOf(result) == PropertyOutcome::Violated);
    CHECK(replaysToViolation(*model, result, property));
}

TEST_CASE("Closed loop needs a machine", "[closed-loop-verify]")
{
    Model model = samples::soundMachine();
    const VerificationResult result = verifyModel(model, withProperty("never A AND B", true));
    CHECK_FALSE(result.closedLoop);
    CHECK(outcomeOf(result) == PropertyOutcome::Violated);
}

} // namespace test_closedloopverification
