// The simulator runs nested GRAFCETs as spec grafcet-layer.md §4 says.

#include "core/formats/modelfiles.h"
#include "core/model/model.h"
#include "core/simulation/nestedengine.h"
#include "core/simulation/scenario.h"
#include "core/simulation/simulator.h"
#include "modelfactory.h"
#include "samplemodels.h"

#include <catch2/catch.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace test_nestedsimulation {

using namespace core;

namespace {

// F1 is the initial step. Its GRAFCET: 1 --RE Start--> 2 (N Lamp,
// Count := Count + 1) --5s/X2--> 3 (S Complete). F1 -> A2 waits for Complete;
// F -> D1 on Stop.
Model timedModel()
{
    Model model;
    REQUIRE(model.addVariable(samples::variable("Start", IecType::Bool, VariableKind::Input)));
    REQUIRE(model.addVariable(samples::variable("Stop", IecType::Bool, VariableKind::Input)));
    REQUIRE(model.addVariable(samples::variable("Lamp", IecType::Bool, VariableKind::Output)));
    REQUIRE(model.addVariable(samples::variable("Count", IecType::Int, VariableKind::Internal)));
    REQUIRE(model.setInitialStep("F1"));
    REQUIRE(model.setCondition("F1->A2", "TRUE"));
    REQUIRE(model.setCondition("F->D1", "Stop"));
    REQUIRE(model.setTransitionHidden("F->D1", false));
    REQUIRE(model.addGrafcetStep("F1", {1, true, "", {}}));
    REQUIRE(model.addGrafcetStep("F1", {2, false, "", {{ActionTiming::Continuous, "N Lamp"},
                                                       {ActionTiming::OnActivation, "Count := Count + 1"}}}));
    REQUIRE(model.addGrafcetStep("F1", {3, false, "", {{ActionTiming::OnActivation, "S Complete"}}}));
    REQUIRE(model.addGrafcetTransition("F1", {1, {1}, {2}, "RE Start"}));
    REQUIRE(model.addGrafcetTransition("F1", {2, {2}, {3}, "5s/X2"}));
    return model;
}

} // namespace

TEST_CASE("Nested GRAFCET: edges, stored and continuous actions, the TON count", "[simulation][nested-simulation]")
{
    Simulator simulator(timedModel());
    REQUIRE(simulator.hasGrafcet("F1"));
    CHECK_FALSE(simulator.setCompleteMode("F1", CompleteMode::Manual).ok);

    simulator.step(); // the entry scan: Initialization, then one evolution
    CHECK(simulator.activeNestedSteps("F1") == std::vector<int>{1});
    simulator.step();
    REQUIRE(simulator.setVariable("Start", true));
    const ScanRecord third = simulator.step(); // scan 3: the rising edge
    CHECK(simulator.activeNestedSteps("F1") == std::vector<int>{2});
    REQUIRE(third.nestedActive.size() == simulator.nestedSteps().size());
    CHECK(simulator.variable("Count") == cond::Value{std::int64_t{1}});
    CHECK(simulator.variable("Lamp") == cond::Value{true}); // written after END_CASE in the same scan
    simulator.step(); // Start still TRUE: no edge, step 2 stays, Count stays
    CHECK(simulator.variable("Count") == cond::Value{std::int64_t{1}});

    // 5s/X2 at 20 ms: TRUE in the (250 + 1)th scan after scan 3.
    simulator.run(253 - 4);
    CHECK(simulator.scanCount() == 253);
    CHECK(simulator.activeNestedSteps("F1") == std::vector<int>{2});
    const ScanRecord fired = simulator.step();
    CHECK(fired.scan == 254);
    CHECK(simulator.activeNestedSteps("F1") == std::vector<int>{3});
    CHECK(simulator.complete("F1"));
    CHECK(fired.fired == "F1->A2"); // Complete is seen by the GEMMA layer in the same scan
    CHECK(simulator.variable("Lamp") == cond::Value{false});
}

TEST_CASE("Leaving the GEMMA state drops its continuous outputs in the same scan", "[simulation][nested-simulation]")
{
    Simulator simulator(timedModel());
    simulator.step();
    REQUIRE(simulator.setVariable("Start", true));
    simulator.step();
    REQUIRE(simulator.variable("Lamp") == cond::Value{true});
    REQUIRE(simulator.setVariable("Stop", true));
    const ScanRecord record = simulator.step();
    CHECK(record.fired == "F->D1");
    CHECK(simulator.variable("Lamp") == cond::Value{false});
    CHECK(simulator.activeNestedSteps("F1") == std::vector<int>{2}); // the FB is no longer called
}

TEST_CASE("An edge on an FB's own continuous output reads its VAR_OUTPUT, as the generated code does",
          "[simulation][nested-simulation]")
{
    // Step 1 drives Lamp; T1 waits for RE Lamp. The generated code compares
    // the VAR_OUTPUT Lamp (TRUE since the Initialization call of the entry
    // scan) with Lamp_PREV (FALSE, the global at the end of the previous
    // scan): T1 fires in the entry scan. The global Lamp, written after
    // END_CASE, was FALSE there: reading it, the edge would never be seen.
    Model model;
    REQUIRE(model.addVariable(samples::variable("Lamp", IecType::Bool, VariableKind::Output)));
    REQUIRE(model.setInitialStep("F1"));
    REQUIRE(model.setCondition("F1->A2", "FALSE")); // F1 stays
    REQUIRE(model.addGrafcetStep("F1", {1, true, "", {{ActionTiming::Continuous, "N Lamp"}}}));
    REQUIRE(model.addGrafcetStep("F1", {2, false, "", {{ActionTiming::OnActivation, "S Complete"}}}));
    REQUIRE(model.addGrafcetTransition("F1", {1, {1}, {2}, "RE Lamp"}));
    REQUIRE(model.addGrafcetTransition("F1", {2, {2}, {1}, "FE Lamp"}));
    Simulator simulator(model);
    simulator.step();
    CHECK(simulator.activeNestedSteps("F1") == std::vector<int>{2});
    CHECK(simulator.variable("Lamp") == cond::Value{false});
    // Scan 2: the VAR_OUTPUT is FALSE (step 2), Lamp_PREV FALSE: no falling edge.
    simulator.step();
    CHECK(simulator.activeNestedSteps("F1") == std::vector<int>{2});
    CHECK(simulator.activeStepId() == "F1");
}

TEST_CASE("Simultaneous divergence and convergence; a step both left and entered stays", "[simulation][nested-simulation]")
{
    Model model;
    REQUIRE(model.addVariable(samples::variable("Go", IecType::Bool, VariableKind::Input)));
    REQUIRE(model.addVariable(samples::variable("Count", IecType::Int, VariableKind::Internal)));
    REQUIRE(model.setInitialStep("F1"));
    REQUIRE(model.addGrafcetStep("F1", {1, true, "", {}}));
    REQUIRE(model.addGrafcetStep("F1", {2, false, "", {{ActionTiming::OnActivation, "Count := Count + 1"}}}));
    REQUIRE(model.addGrafcetStep("F1", {3, false, "", {}}));
    REQUIRE(model.addGrafcetStep("F1", {4, false, "", {}}));
    REQUIRE(model.addGrafcetTransition("F1", {1, {1}, {2, 3}, "Go"}));
    REQUIRE(model.addGrafcetTransition("F1", {2, {2, 3}, {4}, "NOT Go"}));
    // 2 -> 2 when Go: left and entered at once, it stays and its action does not run again.
    REQUIRE(model.addGrafcetTransition("F1", {3, {2}, {2}, "Go"}));
    Simulator simulator(model);
    REQUIRE(simulator.setVariable("Go", true));
    simulator.step();
    CHECK(simulator.activeNestedSteps("F1") == std::vector<int>{2, 3});
    CHECK(simulator.variable("Count") == cond::Value{std::int64_t{1}});
    simulator.step();
    CHECK(simulator.activeNestedSteps("F1") == std::vector<int>{2, 3});
    CHECK(simulator.variable("Count") == cond::Value{std::int64_t{1}});
    REQUIRE(simulator.setVariable("Go", false));
    simulator.step();
    CHECK(simulator.activeNestedSteps("F1") == std::vector<int>{4});
}

TEST_CASE("Until stable: the search goes on, bounded, and reports Unstable", "[simulation][nested-simulation]")
{
    Model model;
    REQUIRE(model.addVariable(samples::variable("A", IecType::Bool, VariableKind::Input)));
    REQUIRE(model.setInitialStep("F1"));
    REQUIRE(model.addGrafcetStep("F1", {1, true, "", {}}));
    REQUIRE(model.addGrafcetStep("F1", {2, false, "", {}}));
    REQUIRE(model.addGrafcetStep("F1", {3, false, "", {}}));
    REQUIRE(model.addGrafcetTransition("F1", {1, {1}, {2}, "A"}));
    REQUIRE(model.addGrafcetTransition("F1", {2, {2}, {3}, "TRUE"}));
    REQUIRE(model.addGrafcetTransition("F1", {3, {3}, {1}, "NOT A"}));
    Model stable(model);
    stable.setEvolutionRule(EvolutionRule::UntilStable);

    Simulator perScan(model);
    REQUIRE(perScan.setVariable("A", true));
    perScan.step();
    CHECK(perScan.activeNestedSteps("F1") == std::vector<int>{2}); // one evolution per call

    Simulator search(stable);
    REQUIRE(search.setVariable("A", true));
    search.step();
    CHECK(search.activeNestedSteps("F1") == std::vector<int>{3}); // 1 -> 2 -> 3 in one call
    CHECK_FALSE(search.unstable("F1"));

    Model looping(stable);
    REQUIRE(looping.setReceptivity("F1", 3, "TRUE"));
    Simulator endless(looping);
    REQUIRE(endless.setVariable("A", true));
    endless.step();
    CHECK(endless.unstable("F1")); // four evolutions allowed, the last still fired
}

// Issue 32: each of the 10,001 evolutions of a scan evaluated all 10,000
// transitions (over 30 s a scan); only the enabled ones can fire.
TEST_CASE("Until stable: a scan of a 10,000-step unstable GRAFCET evaluates only enabled transitions",
          "[simulation][nested-simulation][performance]")
{
    Simulator simulator(factory::unstableGrafcetModel(10000));
    simulator.step();
    simulator.step();
    // 10,001 evolutions per scan, one step each: the token goes round once and one step on.
    CHECK(simulator.activeNestedSteps("F1") == std::vector<int>{3});
    CHECK(simulator.unstable("F1"));
    CHECK(simulator.firedNestedTransitions("F1").size() == 10000);
    // One enabled transition per evolution: 2 x 10,001 receptivities in the
    // two scans, where evaluating every transition at every evolution took
    // 200 million. Counted, not timed (the time is a benchmark's figure).
    const NestedEngine* engine = simulator.grafcetEngine("F1");
    REQUIRE(engine);
    CHECK(engine->receptivityEvaluations() == 2 * 10'001);
}

TEST_CASE("Scenarios set inputs only and expect nested steps and Unstable", "[simulation][nested-simulation][scenario]")
{
    Simulator simulator(timedModel());
    const ScenarioParseResult bad = parseScenario("at 1: set Lamp = TRUE\nat 1: set complete F1 = TRUE\n", "s.txt");
    REQUIRE(bad.ok());
    const std::vector<ScenarioError> errors = validateScenario(bad.scenario, simulator);
    REQUIRE(errors.size() == 2);
    CHECK(errors[0].toString() == "s.txt:1:11: Lamp is an output variable: the program writes it, a scenario sets only inputs");
    CHECK(errors[1].toString() == "s.txt:2:20: the Complete of F1 comes from its nested GRAFCET: it cannot be set");

    const ScenarioParseResult good = parseScenario("at 1: expect nested F1 steps 1\n"
                                                   "at 3: set Start = TRUE\n"
                                                   "at 3: expect nested f1 steps 2\n"
                                                   "at 3: expect variable Lamp = TRUE\n"
                                                   "at 3: expect nested F1 unstable = FALSE\n"
                                                   "at 4: expect nested F1 steps 3, 1\n",
                                                   "s.txt");
    REQUIRE(good.ok());
    REQUIRE(validateScenario(good.scenario, simulator).empty());
    ScenarioRunner runner(good.scenario, simulator);
    std::vector<ScenarioFailure> failures;
    for (int scan = 0; scan < 4; ++scan) {
        runner.step();
        failures.insert(failures.end(), runner.lastFailures().begin(), runner.lastFailures().end());
    }
    REQUIRE(failures.size() == 1);
    CHECK(toText(failures[0]) == "scan 4: expected the active steps of F1 to be 1, 3, they are 2");

    CHECK_FALSE(parseScenario("at 1: expect nested F1 stages 2\n").ok());
    CHECK_FALSE(parseScenario("at 1: expect nested F1 steps two\n").ok());
}

TEST_CASE("The shipped example runs a production cycle", "[simulation][nested-simulation][example]")
{
    const auto loaded = loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    REQUIRE(loaded.model);
    Simulator simulator(*loaded.model);
    const auto set = [&](const char* name, bool value) { REQUIRE(simulator.setVariable(name, value)); };
    set("DrillHigh", true);
    set("Unclamped", true);
    set("StartButton", true);
    simulator.run(2);
    CHECK(simulator.activeStepId() == "F2");
    simulator.run(1100); // 10 s of warm-up at 10 ms
    CHECK(simulator.activeStepId() == "F1");
    CHECK(simulator.variable("ReadyLamp") == cond::Value{true});
    set("PartPresent", true);
    simulator.run(2);
    CHECK(simulator.activeNestedSteps("F1") == std::vector<int>{2});
    CHECK(simulator.variable("ClampOut") == cond::Value{true});
    set("Unclamped", false);
    set("Clamped", true);
    simulator.run(2);
    CHECK(simulator.activeNestedSteps("F1") == std::vector<int>{3, 5}); // drill and mark in parallel
    CHECK(simulator.variable("Spindle") == cond::Value{true});
    CHECK(simulator.variable("Marker") == cond::Value{true});
}

namespace {

// Plays `sets` (scan -> variable -> value) as the editor's session records
// it: the inputs of each scan, and the scans a recording keeps.
ScenarioRecording recordSession(Simulator& simulator, std::int64_t scans,
                                const std::map<std::int64_t, std::vector<std::pair<std::string, bool>>>& sets)
{
    ScenarioRecording recording;
    recording.title = "recorded";
    recording.nestedSteps = simulator.nestedSteps();
    std::optional<ScanRecord> previous;
    for (std::int64_t scan = 1; scan <= scans; ++scan) {
        if (auto found = sets.find(scan); found != sets.end()) {
            for (const auto& [name, value] : found->second)
                REQUIRE(simulator.setVariable(name, value));
        }
        ScanRecord record = simulator.step();
        if (!record.changedInputs.empty())
            recording.changes.push_back(RecordedScan{record.scan, record.changedInputs, {}, {}});
        if (recordWorthKeeping(record, previous ? &*previous : nullptr))
            recording.records.push_back(record);
        previous = std::move(record);
    }
    return recording;
}

} // namespace

TEST_CASE("A recorded session writes nested expectations and outputs, and replays", "[simulation][nested-simulation][scenario][example]")
{
    const auto loaded = loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    REQUIRE(loaded.model);
    Simulator simulator(*loaded.model);
    // The inputs of examples/drilling-cell-start.scenario, then the part drilled.
    const ScenarioRecording recording = recordSession(
        simulator, 1400,
        {{1, {{"DrillHigh", true}, {"Unclamped", true}, {"StartButton", true}}},
         {3, {{"StartButton", false}}},
         {1010, {{"PartPresent", true}}},
         {1012, {{"Unclamped", false}, {"Clamped", true}}},
         {1020, {{"DrillHigh", false}}},
         {1030, {{"DrillLow", true}}},
         {1040, {{"DrillLow", false}}},
         {1050, {{"DrillHigh", true}}}});
    const std::string text = writeScenario(recording);
    INFO(text);
    CHECK(text.find("at 1: expect fired A1->F2\n") != std::string::npos);
    CHECK(text.find("at 2: expect nested F2 steps 3\n") != std::string::npos);
    CHECK(text.find("at 2: expect variable Spindle = TRUE\n") != std::string::npos);
    CHECK(text.find("at 1003: expect fired F2->F1\n") != std::string::npos);
    CHECK(text.find("at 1004: expect nested F1 steps 1\n") != std::string::npos); // F1's entry scan
    // Inputs set before scan 1010 are read by it.
    CHECK(text.find("at 1010: expect nested F1 steps 2\n") != std::string::npos);
    CHECK(text.find("at 1010: expect variable ClampOut = TRUE\n") != std::string::npos);
    CHECK(text.find("at 1012: expect nested F1 steps 3, 5\n") != std::string::npos);
    CHECK(text.find("at 1012: expect variable Marker = TRUE\n") != std::string::npos);
    CHECK(text.find("unstable") == std::string::npos); // one evolution per scan: never Unstable
    // Written once per change: 3, 5 stay active until 1030, one line for them.
    const std::size_t first = text.find("expect nested F1 steps 3, 5\n");
    CHECK(text.find("expect nested F1 steps 3, 5\n", first + 1) == std::string::npos);
    CHECK(text.find("at 1011: expect") == std::string::npos); // nothing changed in scan 1011

    const ScenarioParseResult parsed = parseScenario(text, "recorded.scenario");
    REQUIRE(parsed.ok());
    Simulator replay(*loaded.model);
    REQUIRE(validateScenario(parsed.scenario, replay).empty());
    const ScenarioRunResult result = runScenario(parsed.scenario, replay);
    for (const ScenarioFailure& failure : result.failures)
        FAIL_CHECK(toText(failure));
    CHECK(result.passed());
}

TEST_CASE("A recorded session writes Unstable when it changes", "[simulation][nested-simulation][scenario]")
{
    Model model;
    REQUIRE(model.addVariable(samples::variable("A", IecType::Bool, VariableKind::Input)));
    REQUIRE(model.setInitialStep("F1"));
    REQUIRE(model.addGrafcetStep("F1", {1, true, "", {}}));
    REQUIRE(model.addGrafcetStep("F1", {2, false, "", {}}));
    REQUIRE(model.addGrafcetTransition("F1", {1, {1}, {2}, "A"}));
    REQUIRE(model.addGrafcetTransition("F1", {2, {2}, {1}, "A"}));
    model.setEvolutionRule(EvolutionRule::UntilStable);
    Simulator simulator(model);
    const ScenarioRecording recording = recordSession(simulator, 6, {{3, {{"A", true}}}, {5, {{"A", false}}}});
    const std::string text = writeScenario(recording);
    INFO(text);
    CHECK(text.find("at 1: expect nested F1 steps 1\n") != std::string::npos);
    CHECK(text.find("at 3: expect nested F1 unstable = TRUE\n") != std::string::npos);
    CHECK(text.find("at 5: expect nested F1 unstable = FALSE\n") != std::string::npos);
    const ScenarioParseResult parsed = parseScenario(text);
    REQUIRE(parsed.ok());
    Simulator replay(model);
    CHECK(runScenario(parsed.scenario, replay).passed());
}

TEST_CASE("The transitions a scan fired in a nested GRAFCET", "[simulation][nested-simulation][nested-fired]")
{
    SECTION("one evolution per scan: the transition of that scan, none in a scan that fires none")
    {
        Simulator simulator(timedModel());
        CHECK(simulator.firedNestedTransitions("F1").empty()); // no scan yet
        CHECK_FALSE(simulator.nestedCalled("F1"));
        simulator.step(); // the entry scan: Initialization, then an evolution in which RE Start is FALSE
        CHECK(simulator.nestedCalled("F1"));
        CHECK(simulator.firedNestedTransitions("F1").empty());
        REQUIRE(simulator.setVariable("Start", true));
        simulator.step();
        CHECK(simulator.firedNestedTransitions("F1") == std::vector<int>{1});
        CHECK(simulator.grafcetEngine("F1")->firedTransitions() == std::vector<int>{1});
        simulator.step(); // Start still TRUE: no edge, 5s/X2 not elapsed
        CHECK(simulator.firedNestedTransitions("F1").empty());
        CHECK(simulator.firedNestedTransitions("A1").empty()); // no GRAFCET
        CHECK(simulator.firedNestedTransitions("nowhere").empty());
        simulator.reset();
        CHECK(simulator.firedNestedTransitions("F1").empty());
    }
    SECTION("transitions that fire together are all kept")
    {
        Model model;
        REQUIRE(model.addVariable(samples::variable("Go", IecType::Bool, VariableKind::Input)));
        REQUIRE(model.setInitialStep("F1"));
        REQUIRE(model.addGrafcetStep("F1", {1, true, "", {}}));
        REQUIRE(model.addGrafcetStep("F1", {2, false, "", {}}));
        REQUIRE(model.addGrafcetStep("F1", {3, false, "", {}}));
        REQUIRE(model.addGrafcetStep("F1", {4, false, "", {}}));
        REQUIRE(model.addGrafcetStep("F1", {5, false, "", {}}));
        REQUIRE(model.addGrafcetTransition("F1", {1, {1}, {2, 3}, "Go"}));
        REQUIRE(model.addGrafcetTransition("F1", {2, {2}, {4}, "NOT Go"}));
        REQUIRE(model.addGrafcetTransition("F1", {3, {3}, {5}, "NOT Go"}));
        Simulator simulator(model);
        REQUIRE(simulator.setVariable("Go", true));
        simulator.step();
        CHECK(simulator.firedNestedTransitions("F1") == std::vector<int>{1});
        REQUIRE(simulator.setVariable("Go", false));
        simulator.step();
        CHECK(simulator.activeNestedSteps("F1") == std::vector<int>{4, 5});
        CHECK(simulator.firedNestedTransitions("F1") == std::vector<int>{2, 3});
    }
    SECTION("until stable: every transition of every evolution of the scan, in number order")
    {
        Model model;
        REQUIRE(model.addVariable(samples::variable("A", IecType::Bool, VariableKind::Input)));
        REQUIRE(model.setInitialStep("F1"));
        model.setEvolutionRule(EvolutionRule::UntilStable);
        REQUIRE(model.addGrafcetStep("F1", {1, true, "", {}}));
        REQUIRE(model.addGrafcetStep("F1", {2, false, "", {}}));
        REQUIRE(model.addGrafcetStep("F1", {3, false, "", {}}));
        // Numbered against the order they fire in: 1 -> 2 is T3, 2 -> 3 is T1.
        REQUIRE(model.addGrafcetTransition("F1", {3, {1}, {2}, "A"}));
        REQUIRE(model.addGrafcetTransition("F1", {1, {2}, {3}, "TRUE"}));
        REQUIRE(model.addGrafcetTransition("F1", {2, {3}, {1}, "NOT A"}));
        Simulator simulator(model);
        REQUIRE(simulator.setVariable("A", true));
        simulator.step(); // 1 -> 2 -> 3 in one call
        CHECK(simulator.activeNestedSteps("F1") == std::vector<int>{3});
        CHECK(simulator.firedNestedTransitions("F1") == std::vector<int>{1, 3});
        simulator.step(); // stable
        CHECK(simulator.firedNestedTransitions("F1").empty());
        REQUIRE(simulator.setVariable("A", false));
        simulator.step(); // 3 -> 1, then A is FALSE: stable
        CHECK(simulator.firedNestedTransitions("F1") == std::vector<int>{2});

        Model looping(model);
        REQUIRE(looping.setReceptivity("F1", 2, "TRUE"));
        Simulator endless(looping);
        REQUIRE(endless.setVariable("A", true));
        endless.step(); // four evolutions, every transition fired at least once, each kept once
        CHECK(endless.unstable("F1"));
        CHECK(endless.firedNestedTransitions("F1") == std::vector<int>{1, 2, 3});
    }
    SECTION("a scan that does not call the function block fired nothing in its GRAFCET")
    {
        Simulator simulator(timedModel());
        simulator.step();
        REQUIRE(simulator.setVariable("Start", true));
        REQUIRE(simulator.setVariable("Stop", true));
        const ScanRecord leaving = simulator.step(); // F1's FB fires T1, then F -> D1 leaves F1
        CHECK(leaving.fired == "F->D1");
        CHECK(simulator.nestedCalled("F1"));
        CHECK(simulator.firedNestedTransitions("F1") == std::vector<int>{1});
        simulator.step(); // D1: F1's FB is not called
        CHECK(simulator.activeStepId() == "D1");
        CHECK_FALSE(simulator.nestedCalled("F1"));
        CHECK(simulator.firedNestedTransitions("F1").empty());
        CHECK(simulator.grafcetEngine("F1")->firedTransitions() == std::vector<int>{1}); // its last call's
        CHECK(simulator.activeNestedSteps("F1") == std::vector<int>{2}); // the frozen situation
    }
    SECTION("a copy keeps the scan's own, as the editor's history restores it")
    {
        Simulator simulator(timedModel());
        simulator.step();
        REQUIRE(simulator.setVariable("Start", true));
        simulator.step();
        const Simulator atScan2(simulator);
        simulator.step();
        REQUIRE(simulator.firedNestedTransitions("F1").empty());
        CHECK(atScan2.firedNestedTransitions("F1") == std::vector<int>{1});
        simulator = atScan2; // back to scan 2, as a step back then play on does
        CHECK(simulator.scanCount() == 2);
        CHECK(simulator.firedNestedTransitions("F1") == std::vector<int>{1});
    }
}

TEST_CASE("Which continuous actions emit their output after a call", "[simulation][nested-simulation][nested-fired]")
{
    // Step 1 drives Lamp only IF Go, and Horn; step 2 drives Lamp too.
    Model model;
    REQUIRE(model.addVariable(samples::variable("Go", IecType::Bool, VariableKind::Input)));
    REQUIRE(model.addVariable(samples::variable("Next", IecType::Bool, VariableKind::Input)));
    REQUIRE(model.addVariable(samples::variable("Lamp", IecType::Bool, VariableKind::Output)));
    REQUIRE(model.addVariable(samples::variable("Horn", IecType::Bool, VariableKind::Output)));
    REQUIRE(model.addVariable(samples::variable("Count", IecType::Int, VariableKind::Internal)));
    REQUIRE(model.setInitialStep("F1"));
    REQUIRE(model.setCondition("F1->A2", "FALSE")); // F1 stays
    REQUIRE(model.addGrafcetStep("F1", {1, true, "", {{ActionTiming::OnActivation, "Count := Count + 1"},
                                                      {ActionTiming::Continuous, "N Lamp IF Go"},
                                                      {ActionTiming::Continuous, "Horn"}}}));
    REQUIRE(model.addGrafcetStep("F1", {2, false, "", {{ActionTiming::Continuous, "N Lamp"}}}));
    REQUIRE(model.addGrafcetTransition("F1", {1, {1}, {2}, "Next"}));
    Simulator simulator(model);
    const NestedEngine* engine = simulator.grafcetEngine("F1");
    REQUIRE(engine);
    CHECK_FALSE(engine->emitting(1, 2)); // before any call
    simulator.step();
    CHECK_FALSE(engine->emitting(1, 0)); // a stored action
    CHECK_FALSE(engine->emitting(1, 1)); // Go is FALSE
    CHECK(engine->emitting(1, 2));
    CHECK_FALSE(engine->emitting(2, 0));
    REQUIRE(simulator.setVariable("Go", true));
    simulator.step();
    CHECK(engine->emitting(1, 1));
    CHECK(simulator.variable("Lamp") == cond::Value{true});
    REQUIRE(simulator.setVariable("Next", true));
    simulator.step();
    CHECK_FALSE(engine->emitting(1, 1));
    CHECK_FALSE(engine->emitting(1, 2));
    CHECK(engine->emitting(2, 0)); // Lamp from step 2 now
    CHECK(simulator.variable("Lamp") == cond::Value{true});
    CHECK(simulator.variable("Horn") == cond::Value{false});
    CHECK_FALSE(engine->emitting(2, 1)); // no such action
    CHECK_FALSE(engine->emitting(9, 0)); // no such step
    simulator.reset();
    CHECK_FALSE(engine->emitting(2, 0));
}

} // namespace test_nestedsimulation
