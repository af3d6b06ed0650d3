// Verification in closed loop (docs/verification.md, "Closed loop
// (--machine)"): the program explored with its machine, the inputs the
// machine's sensors drive computed from its state; counterexamples replayed
// with core::machine::MachineLoop.

#include "samplemodels.h"
#include "verificationtestsupport.h"

#include "core/formats/modelfiles.h"
#include "core/machine/closedloopscenario.h"
#include "core/machine/machine.h"
#include "core/machine/machineloop.h"
#include "core/machine/machinestate.h"
#include "core/model/model.h"
#include "core/simulation/simulator.h"
#include "core/verification/abstractmachine.h"
#include "core/verification/closedloopreplay.h"
#include "core/verification/programexplorer.h"
#include "core/verification/property.h"
#include "core/verification/propertyevaluation.h"
#include "core/verification/verification.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <memory>
#include <random>
#include <set>
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

TEST_CASE("Every run of the machine is a run of its abstraction", "[closed-loop-verify]")
{
    // The drilling cell's machine, a spring-return cylinder and a delayed
    // sensor, at 10 ms: the actuators change at random (seldom, so that
    // travels end), and after each cycle some abstract state reached by
    // choosing how travels end shows the machine's sensors.
    const auto model = drillingCell();
    Machine machine = model->machine();
    Component spring = makeComponent(ComponentKind::SingleActingCylinder, "Spring");
    spring.wires = {"S_Out", "S_In", "S_Ext"};
    spring.parameters = {50, 20};
    Component delayed = makeComponent(ComponentKind::DelayedSensor, "Delay");
    delayed.wires = {"D_Out", "D_In"};
    delayed.parameters = {30, 0};
    machine.components.push_back(spring);
    machine.components.push_back(delayed);
    std::vector<std::string> names;
    const auto wire = [&](std::string_view name, SignalDirection) {
        const auto known = std::find(names.begin(), names.end(), name);
        if (known != names.end())
            return static_cast<int>(known - names.begin());
        names.emplace_back(name);
        return static_cast<int>(names.size()) - 1;
    };
    MachineState exact(machine, 10, wire);
    explore::AbstractMachine abstract(machine, exact, 10, wire);
    const std::vector<SignalSlot>& table = exact.signalSlots();
    const auto sensors = [&](const auto& m) {
        std::string out;
        for (std::size_t i = 0; i < table.size(); ++i)
            out += table[i].direction == SignalDirection::Sensor && m.signal(i) ? '1' : '0';
        return out;
    };
    std::set<std::string> possible;
    std::string start;
    abstract.appendKey(start);
    possible.insert(start);
    REQUIRE(sensors(abstract) == sensors(exact));
    std::mt19937 random(35);
    std::vector<char> actuators(table.size(), 0);
    for (int cycle = 0; cycle < 3000; ++cycle) {
        for (std::size_t i = 0; i < table.size(); ++i) {
            if (table[i].direction == SignalDirection::Actuator && random() % 40 == 0)
                actuators[i] = !actuators[i];
            exact.setSignal(i, actuators[i] != 0);
        }
        exact.cycle();
        std::set<std::string> next;
        for (const std::string& key : possible) {
            std::vector<int> answers; // every way the travels may end, depth first
            bool more = true;
            while (more) {
                std::size_t at = 0;
                REQUIRE(abstract.restoreKey(key) == key.size());
                for (std::size_t i = 0; i < table.size(); ++i) {
                    if (table[i].direction == SignalDirection::Actuator)
                        abstract.setSignal(i, actuators[i] != 0);
                }
                abstract.cycle([&](int) {
                    if (at == answers.size())
                        answers.push_back(0);
                    return answers[at++];
                });
                answers.resize(at);
                if (sensors(abstract) == sensors(exact)) {
                    std::string reached;
                    abstract.appendKey(reached);
                    next.insert(reached);
                }
                while (!answers.empty() && answers.back() == 1)
                    answers.pop_back();
                more = !answers.empty();
                if (more)
                    answers.back() = 1;
            }
        }
        INFO("cycle " << cycle << ", sensors " << sensors(exact));
        REQUIRE_FALSE(next.empty());
        possible = std::move(next);
    }
}

TEST_CASE("Limit switches of one cylinder: never together with the machine, free without it",
          "[closed-loop-verify]")
{
    const Model model = samples::cylinderCell();
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
    const Model model = samples::cylinderCell();
    const VerificationResult holds = verifyModel(model, withProperty("never F1.X2 AND B", true));
    CHECK(outcomeOf(holds) == PropertyOutcome::Holds);
    CHECK(outcomeOf(verifyModel(model, withProperty("never F1.X2 AND B", false))) == PropertyOutcome::Violated);

    const std::string violated = "never F1.X2 AND A";
    const VerificationResult result = verifyModel(model, withProperty(violated, true));
    REQUIRE(outcomeOf(result) == PropertyOutcome::Violated);
    CHECK(replaysToViolation(model, result, violated));
}

TEST_CASE("By hand: a travel shorter than the machine's is no violation", "[closed-loop-verify]")
{
    // 1 --A--> 2 --NOT A--> 3 --TRUE--> 4 --TRUE--> 5, Lamp extending the
    // cylinder from step 2 on. Step 2 is entered in the scan K that reads A,
    // 3 in K+1 and 4 in K+2, left in K+3; B is read from K+3 on (three
    // cycles out). Under the abstraction the rod may arrive a cycle sooner:
    // that run does not replay, and the search with the machine counted in
    // scans shows there is none.
    Model model = samples::cylinderCell();
    require(model.removeGrafcetTransition("F1", 2));
    for (int step = 3; step <= 5; ++step)
        samples::addMachineStep(model, step, false, {{ActionTiming::Continuous, "N Lamp"}});
    samples::addMachineTransition(model, 2, {2}, {3}, "NOT A");
    samples::addMachineTransition(model, 3, {3}, {4}, "TRUE");
    samples::addMachineTransition(model, 4, {4}, {5}, "TRUE");
    const std::string property = "never F1.X4 AND B";
    explore::Options options;
    options.machine = &model.machine();
    options.properties = {property};
    explore::ProgramExplorer explorer(model, options);
    const explore::Exploration& exploration = explorer.run();
    REQUIRE(exploration.exhaustive);
    const auto spurious = std::find_if(exploration.events.begin(), exploration.events.end(), [](const explore::Event& e) {
        return e.kind == explore::EventKind::PropertyViolated;
    });
    REQUIRE(spurious != exploration.events.end());
    CHECK_FALSE(explorer.counterexample(*spurious, "too soon").confirmed);

    const VerificationResult abstracted = verifyModel(model, withProperty(property, true));
    INFO(codesOf(abstracted).size());
    CHECK(outcomeOf(abstracted) == PropertyOutcome::Holds);
    VerificationOptions counted = withProperty(property, true);
    counted.exactTime = true;
    CHECK(outcomeOf(verifyModel(model, counted)) == PropertyOutcome::Holds);
    // One scan later it is a real violation.
    const std::string later = "never F1.X5 AND B";
    const VerificationResult violated = verifyModel(model, withProperty(later, true));
    REQUIRE(outcomeOf(violated) == PropertyOutcome::Violated);
    CHECK(replaysToViolation(model, violated, later));
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

TEST_CASE("Cut short, the search counted in scans leaves a closed-loop violation undecided, and says so",
          "[closed-loop-verify]")
{
    // The first exploration (machine travels abstracted, 1080 states) ends;
    // the search with time counted in scans for a run that replays needs more
    // states than the limit leaves it. The violation is then undecided, and
    // the reason must not claim that no run replays.
    const auto model = drillingCell();
    const std::string property = "never Marker AND NOT DrillHigh";
    VerificationOptions options = withProperty(property, true);
    options.maxProgramStates = 1100;
    const VerificationResult result = verifyModel(*model, options);
    REQUIRE(result.programStates < options.maxProgramStates);
    CHECK(result.exhaustive);
    REQUIRE(outcomeOf(result) == PropertyOutcome::Undecided);
    CHECK_THAT(result.propertyVerdicts.front().reason,
               Catch::Contains("the search for one with time counted in scans stopped at the time or size limit"));
}

TEST_CASE("Cut short, a closed-loop run claims no run of arbitrary sensors", "[closed-loop-verify]")
{
    // The GEMMA layer's findings that claim a run (GV104-GV107) were decided
    // with every input free: only the exploration with the machine may claim
    // them, and every counterexample leaves the sensors to the machine.
    const auto model = drillingCell();
    VerificationOptions options;
    options.closedLoop = true;
    options.maxProgramStates = 50;
    const VerificationResult result = verifyModel(*model, options);
    CHECK_FALSE(result.exhaustive);
    VerificationOptions open = options;
    open.closedLoop = false;
    const VerificationResult openLoop = verifyModel(*model, open);
    REQUIRE(findingOf(openLoop, verification::kOverlap)); // the open loop claims some
    Simulator simulator(*model);
    MachineLoop loop(simulator, model->machine());
    for (const VerificationFinding& f : result.findings) {
        INFO(f.code << " " << f.message);
        const bool claimsRun = f.code == verification::kOverlap || f.code == verification::kNoReturn
            || f.code == verification::kStuck || f.code == verification::kNoEmergencyStop;
        CHECK((!claimsRun || f.origin == FindingOrigin::BothLayers));
        if (f.counterexample)
            CHECK(validateClosedLoopScenario(f.counterexample->scenario, loop).empty());
    }
}

TEST_CASE("Closed loop needs a machine", "[closed-loop-verify]")
{
    Model model = samples::soundMachine();
    const VerificationResult result = verifyModel(model, withProperty("never A AND B", true));
    CHECK_FALSE(result.closedLoop);
    CHECK(outcomeOf(result) == PropertyOutcome::Violated);
}

} // namespace test_closedloopverification
