// Issue 36: a stored internal BOOL that nothing reads is written as the
// program writes it, but not kept apart in the explored states (SPIN hides
// such write-only variables too). The findings must be those of the
// exploration that keeps them apart, in fewer states; a variable that
// anything reads (a condition, a receptivity, an action, a property, an
// edge) must stay in the state.

#include "modelfactory.h"
#include "samplemodels.h"
#include "verificationtestsupport.h"

#include "core/model/model.h"
#include "core/verification/programexplorer.h"
#include "core/verification/verification.h"

#include <catch2/catch.hpp>

#include <random>
#include <set>
#include <string>
#include <vector>

namespace test_writeonlyvariables {

using namespace core;

namespace {

VerificationOptions unlimited(bool hide)
{
    VerificationOptions options;
    options.timeLimit = std::chrono::milliseconds(0);
    options.hideWriteOnlyVariables = hide;
    return options;
}

// With `priorities` false, without GV103's and GV104's events: a budget of
// scans may run out while one exploration decides them and not the other
// (Exploration::prioritiesDecided), as the states it probes differ in number.
std::set<std::string> eventKeys(const explore::Exploration& e, bool priorities)
{
    std::set<std::string> keys;
    for (const explore::Event& event : e.events) {
        if (priorities || (event.kind != explore::EventKind::AlwaysTrue && event.kind != explore::EventKind::Overlap))
            keys.insert(explore::eventKey(event));
    }
    return keys;
}

// The same findings, claims and verdicts; returns the two state counts.
std::pair<std::size_t, std::size_t> compareHiddenAndKept(const Model& model, const VerificationOptions& base)
{
    VerificationOptions hide = base, keep = base;
    hide.hideWriteOnlyVariables = true;
    keep.hideWriteOnlyVariables = false;
    const VerificationResult hidden = verifyModel(model, hide);
    const VerificationResult kept = verifyModel(model, keep);
    CHECK(hidden.exhaustive);
    CHECK(kept.exhaustive);
    CHECK(verificationtest::findingLines(hidden) == verificationtest::findingLines(kept));
    REQUIRE(hidden.propertyVerdicts.size() == kept.propertyVerdicts.size());
    for (std::size_t p = 0; p < kept.propertyVerdicts.size(); ++p)
        CHECK(hidden.propertyVerdicts[p].outcome == kept.propertyVerdicts[p].outcome);
    CHECK(hidden.reachableSteps == kept.reachableSteps);
    CHECK(hidden.unsafeNestedSteps == kept.unsafeNestedSteps);
    return {hidden.programStates, kept.programStates};
}

// A stored internal BOOL nothing reads in every nested GRAFCET: set on
// entering one random step, reset on entering another. The random GRAFCETs
// read the memories they write, mostly.
void addWriteOnlyTrail(Model& model, std::mt19937& random)
{
    Variable trail{"Trail", IecType::Bool, "", ""};
    trail.kind = VariableKind::Internal;
    verificationtest::require(model.addVariable(trail));
    std::vector<std::pair<std::string, std::vector<int>>> grafcets;
    for (const auto& [owner, grafcet] : model.grafcets()) {
        std::vector<int> numbers;
        for (const GrafcetStep& step : grafcet.steps())
            numbers.push_back(step.number);
        grafcets.emplace_back(owner, numbers);
    }
    for (const auto& [owner, numbers] : grafcets) {
        const int set = numbers[random() % numbers.size()];
        const int reset = numbers[random() % numbers.size()];
        verificationtest::require(model.addGrafcetAction(owner, set, {ActionTiming::OnActivation, "S Trail"}));
        if (reset != set)
            verificationtest::require(model.addGrafcetAction(owner, reset, {ActionTiming::OnActivation, "R Trail"}));
    }
}

} // namespace

TEST_CASE("Stored BOOLs nothing reads: the same findings in the states SPIN stores", "[verification][write-only]")
{
    // The series' stored BOOLs (Mem0-Mem9) are set by the branch steps and
    // reset at the join, and nothing reads them. pan stores 57 states for
    // 2x10 and 91 for 4x10 (spin -o3 -a, as docs/verification.md runs it):
    // the exploration keeping them apart had 479 and 2,151.
    SECTION("series 2x10")
    {
        const auto [hidden, kept] = compareHiddenAndKept(factory::verificationSeriesModel(2, 10), unlimited(true));
        CHECK(hidden == 57);
        CHECK(kept == 479);
    }
    SECTION("series 4x10")
    {
        const auto [hidden, kept] = compareHiddenAndKept(factory::verificationSeriesModel(4, 10), unlimited(true));
        CHECK(hidden == 91);
        CHECK(kept == 2151);
    }
    SECTION("both-layers stress model")
    {
        const auto [hidden, kept] = compareHiddenAndKept(factory::bothLayersStressModel(), unlimited(true));
        CHECK(hidden == 443);
        CHECK(kept == 9692);
    }
}

TEST_CASE("A stored BOOL a property reads stays in the state", "[verification][write-only]")
{
    // Mem0 belongs to F1's GRAFCET, Mem1 to F2's; leaving F1 in mid-cycle
    // keeps Mem0 set while F2 sets Mem1.
    const Model model = factory::verificationSeriesModel(2, 10);
    VerificationOptions options = unlimited(true);
    options.properties = {"never Mem0 AND Mem1", "never Mem0 AND in A1"};
    const auto [hidden, kept] = compareHiddenAndKept(model, options);
    CHECK(hidden > 57);
    CHECK(hidden < kept);
    const VerificationResult result = verifyModel(model, options);
    REQUIRE(result.propertyVerdicts.size() == 2);
    CHECK(result.propertyVerdicts[0].outcome == PropertyOutcome::Violated);
    CHECK(result.propertyVerdicts[1].outcome == PropertyOutcome::Holds);
    const auto violated = verificationtest::findingsWith(result, verification::kPropertyViolated);
    REQUIRE(violated.size() == 1);
    REQUIRE(violated.front()->counterexample);
    CHECK(violated.front()->counterexample->confirmed);
}

TEST_CASE("Random models: hiding what nothing reads changes no event, only the states", "[verification][write-only]")
{
    // Random valid nested GRAFCETs write NestedMem0-1 and NestedCount and
    // mostly read them; three models in four also get a BOOL nothing reads
    // (addWriteOnlyTrail), every other one a property that reads NestedMem0,
    // so that both sides are drawn.
    // The twelve seeds of 1-84 whose model the exploration keeping every
    // variable decides within its budget. The 72 others ran to the budget
    // and were skipped, most of the test's time under the sanitizers; every
    // model is still drawn, so that the random sequence and the listed models
    // stay the same, and a listed model no longer decided fails the test
    // instead of dropping out of it.
    const std::set<std::uint32_t> decided = {10, 17, 25, 29, 31, 34, 40, 44, 50, 71, 83, 84};
    std::mt19937 random(20261207);
    int compared = 0, reduced = 0;
    for (std::uint32_t seed = 1; seed <= 84; ++seed) {
        Model model = samples::randomModel(seed);
        if (samples::addValidRandomNestedGrafcets(model, random) == 0)
            continue;
        if (seed % 3 == 0)
            model.setEvolutionRule(EvolutionRule::UntilStable);
        if (seed % 4 != 1)
            addWriteOnlyTrail(model, random);
        if (decided.count(seed) == 0)
            continue;
        INFO("seed " << seed);
        explore::Options options;
        options.maxScansRun = 30'000; // the same budget on every machine
        if (seed % 2 == 0)
            options.properties = {"never NestedMem0 AND NOT NestedIn0"};
        options.hideWriteOnlyVariables = false;
        explore::ProgramExplorer keep(model, options);
        const explore::Exploration& kept = keep.run();
        REQUIRE(kept.exhaustive);
        options.hideWriteOnlyVariables = true;
        explore::ProgramExplorer hide(model, options);
        const explore::Exploration& hidden = hide.run();
        ++compared;
        REQUIRE(hidden.exhaustive);
        const bool priorities = hidden.prioritiesDecided && kept.prioritiesDecided;
        CHECK(eventKeys(hidden, priorities) == eventKeys(kept, priorities));
        CHECK(hidden.reachableSteps == kept.reachableSteps);
        CHECK(hidden.fireableTransitions == kept.fireableTransitions);
        CHECK(hidden.activeNestedSteps == kept.activeNestedSteps);
        CHECK(hidden.firedNestedTransitions == kept.firedNestedTransitions);
        CHECK(hidden.completeSeen == kept.completeSeen);
        if (priorities) {
            CHECK(hidden.alwaysTrueTransitions == kept.alwaysTrueTransitions);
            CHECK(hidden.overlaps == kept.overlaps);
        }
        CHECK((hidden.prioritiesDecided || !kept.prioritiesDecided)); // fewer states: decided whenever the other is
        CHECK(hidden.maxDepth <= kept.maxDepth); // merged states may be reached sooner
        CHECK(hidden.states <= kept.states);
        if (hidden.states < kept.states)
            ++reduced;
    }
    INFO("models compared: " << compared << ", with fewer states: " << reduced);
    CHECK(compared == 12);
    CHECK(reduced >= 4);
}

} // namespace test_writeonlyvariables
