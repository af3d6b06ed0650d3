// The outcome of the engineer's properties (docs/verification.md,
// "Properties"): holds, violated with a counterexample that replays to the
// violation, or undecided; never "holds" nor a violation that does not replay.

#include "samplemodels.h"
#include "verificationtestsupport.h"

#include "core/formats/modelfiles.h"
#include "core/model/model.h"
#include "core/simulation/scenario.h"
#include "core/simulation/simulator.h"
#include "core/verification/verification.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

namespace test_propertyoutcome {

using namespace core;

namespace {

namespace code = core::verification;
using verificationtest::findingsWith;
using verificationtest::require;

// F1's GRAFCET counts its cycles: step 2 adds one to Count each time it is
// entered (on A), step 1 comes back on NOT A. The exploration takes the
// numeric memory Count as any value, so `Count > 2` seems possible at once;
// the simulator needs three cycles.
Model countingMachine()
{
    Model model = samples::nestedMachine();
    require(model.addVariable(samples::variable("Count", IecType::Int, VariableKind::Internal)));
    samples::addMachineStep(model, 1, true);
    samples::addMachineStep(model, 2, false, {{ActionTiming::OnActivation, "Count := Count + 1"}});
    samples::addMachineTransition(model, 1, {1}, {2}, "A");
    samples::addMachineTransition(model, 2, {2}, {1}, "NOT A");
    return model;
}

VerificationResult verify(const Model& model, std::vector<std::string> properties, std::size_t concreteStates = 20'000)
{
    VerificationOptions options;
    options.properties = std::move(properties);
    options.maxConcreteStates = concreteStates;
    return verifyModel(model, options);
}

} // namespace

TEST_CASE("A violation the abstractions hide is found by searching the simulator's runs", "[propertyoutcome]")
{
    const Model model = countingMachine();
    const VerificationResult result = verify(model, {"never Count > 2"});
    REQUIRE(result.propertyVerdicts.size() == 1);
    CHECK(result.propertyVerdicts[0].outcome == PropertyOutcome::Violated);
    CHECK(result.propertyHolds == std::vector<bool>{false});
    CHECK(result.violated());
    const auto violated = findingsWith(result, code::kPropertyViolated);
    REQUIRE(violated.size() == 1);
    CHECK(violated[0]->severity == Severity::Error);
    REQUIRE(violated[0]->counterexample);
    const Counterexample& counterexample = *violated[0]->counterexample;
    INFO(counterexample.text);
    CHECK(counterexample.confirmed);
    CHECK(counterexample.scans > 1);

    // Replayed independently: Count is 3 at the last scan.
    Simulator simulator(model);
    REQUIRE(validateScenario(counterexample.scenario, simulator).empty());
    CHECK(runScenario(counterexample.scenario, simulator, counterexample.scans).passed());
    CHECK(simulator.variable("Count") == cond::Value{std::int64_t{3}});
}

TEST_CASE("A property neither proved nor shown violated is undecided", "[propertyoutcome]")
{
    // Count only grows: no run makes it negative before it wraps at 32767,
    // farther than a bounded search goes; the exploration cannot tell.
    const VerificationResult result = verify(countingMachine(), {"never Count < 0", "never Lamp"}, 500);
    REQUIRE(result.propertyVerdicts.size() == 2);
    CHECK(result.propertyVerdicts[0].outcome == PropertyOutcome::Undecided);
    CHECK_FALSE(result.propertyVerdicts[0].reason.empty());
    CHECK(result.propertyVerdicts[1].outcome == PropertyOutcome::Holds);
    CHECK(result.propertyHolds == std::vector<bool>{false, true});
    CHECK(findingsWith(result, code::kPropertyViolated).empty());
    const auto undecided = findingsWith(result, code::kPropertyUndecided);
    REQUIRE(undecided.size() == 1);
    CHECK(undecided[0]->property == 0);
    CHECK(undecided[0]->severity == Severity::Warning);
    CHECK_FALSE(undecided[0]->counterexample);
    CHECK(undecided[0]->arguments.size() == 2);
    CHECK(undecided[0]->message.find("undecided") != std::string::npos);
    CHECK(result.undecided());
    // Undecided is not violated: a result with only that finding is not.
    VerificationResult alone;
    alone.findings = {*undecided[0]};
    CHECK_FALSE(alone.violated());
    CHECK(alone.undecided());
}

TEST_CASE("Properties that hold or are violated outright keep their outcome", "[propertyoutcome]")
{
    const VerificationResult result = verify(samples::soundMachine(), {"never Lamp AND NOT A", "never Lamp", "never ("});
    REQUIRE(result.propertyVerdicts.size() == 3);
    CHECK(result.propertyVerdicts[0].outcome == PropertyOutcome::Holds);
    CHECK(result.propertyVerdicts[1].outcome == PropertyOutcome::Violated);
    CHECK(result.propertyVerdicts[2].outcome == PropertyOutcome::Undecided);
    CHECK(result.propertyVerdicts[2].reason.find("cannot be checked") != std::string::npos);
    CHECK_FALSE(result.undecided());
}

TEST_CASE("The search of the simulator's runs sets only the inputs a scan reads", "[propertyoutcome]")
{
    // The drilling cell has more than 4096 combinations of all its inputs per
    // scan, so the search used to give up at once; a scan reads a few of them.
    // Three parts are drilled after the 10 s warm-up and three 2 s markings:
    // over 1,600 scans, which the search reaches within its bounds.
    const LoadedModel loaded = loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    REQUIRE(loaded.model);
    const Model& model = *loaded.model;
    VerificationOptions options;
    options.properties = {"never PartCount > 2", "never PartCount < 0"};
    options.timeLimit = std::chrono::minutes(1); // about 1.5 s in a debug build; sanitizers are slower
    const VerificationResult result = verifyModel(model, options);
    REQUIRE(result.propertyVerdicts.size() == 2);
    CHECK(result.propertyVerdicts[0].outcome == PropertyOutcome::Violated);
    const auto violated = findingsWith(result, code::kPropertyViolated);
    REQUIRE(violated.size() == 1);
    REQUIRE(violated[0]->counterexample);
    const Counterexample& counterexample = *violated[0]->counterexample;
    CHECK(counterexample.confirmed);
    Simulator simulator(model);
    REQUIRE(validateScenario(counterexample.scenario, simulator).empty());
    CHECK(runScenario(counterexample.scenario, simulator, counterexample.scans).passed());
    CHECK(simulator.variable("PartCount") == cond::Value{std::int64_t{3}});

    // PartCount only grows from 0 (and is reset): never 'holds', never violated.
    CHECK(result.propertyVerdicts[1].outcome == PropertyOutcome::Undecided);
}

} // namespace test_propertyoutcome
