// The bounds of the verification of both layers (docs/verification.md,
// "Budget" and "Timers"): a TON is counted exactly whatever its length, so
// a "never" claim holds for every duration; a violation found under the
// timer abstraction is dropped only when the search with time counted in
// scans was exhaustive; the budget and the cancel callback are looked at
// inside a scan, not only between states.

#include "modelfactory.h"
#include "samplemodels.h"
#include "verificationtestsupport.h"

#include "core/model/model.h"
#include "core/simulation/simulator.h"
#include "core/verification/programexplorer.h"
#include "core/verification/verification.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace test_verificationbounds {

using namespace core;

namespace {

namespace code = core::verification;
using verificationtest::findingsWith;

const std::vector<std::string> kLongTimerProperties{"never F1.X2", "never Out1"};

// The scan in which the simulator first has F1's step 2 active and Out1 TRUE
// (Start pressed from the first scan on), or 0 within `limit` scans.
long long scanReachingStep2(const Model& model, long long limit)
{
    Simulator simulator(model);
    REQUIRE(simulator.setVariable("Start", true));
    for (long long scan = 1; scan <= limit; ++scan) {
        simulator.step();
        const std::vector<int> active = simulator.activeNestedSteps("F1");
        if (std::find(active.begin(), active.end(), 2) != active.end() && cond::isTrue(simulator.variable("Out1")))
            return scan;
    }
    return 0;
}

VerificationResult verifyLongTimer(bool exactTime, std::size_t maxStates)
{
    VerificationOptions options;
    options.properties = kLongTimerProperties;
    options.exactTime = exactTime;
    options.maxProgramStates = maxStates;
    options.timeLimit = std::chrono::milliseconds{0}; // the budget of states decides, the same on every machine
    return verifyModel(samples::longTimerMachine(), options);
}

// Both properties are violated, each with a run that replays in the simulator.
void requireViolatedAndReplayed(const VerificationResult& result, long long simulatorScan)
{
    CHECK(result.propertyHolds == std::vector<bool>{false, false});
    const auto violated = findingsWith(result, code::kPropertyViolated);
    REQUIRE(violated.size() == 2);
    for (const VerificationFinding* finding : violated) {
        REQUIRE(finding->counterexample);
        CHECK(finding->counterexample->confirmed);
        CHECK(finding->counterexample->scans >= simulatorScan);
        CHECK(finding->severity == Severity::Error);
    }
    CHECK(findingsWith(result, code::kNestedStepNeverActive).empty());
}

// Not proved, not refuted: no "holds", and what is reported says it is not confirmed.
void requireUndecided(const VerificationResult& result)
{
    CHECK(result.propertyHolds == std::vector<bool>{false, false});
    CHECK(findingsWith(result, code::kPropertyHolds).empty());
    CHECK(findingsWith(result, code::kNestedStepNeverActive).empty());
    for (const VerificationFinding* finding : findingsWith(result, code::kPropertyViolated))
        CHECK(finding->severity == Severity::Info);
}

} // namespace

TEST_CASE("Verification bounds: a TON longer than 65,535 scans is counted exactly", "[bothlayers][timers]")
{
    const Model model = samples::longTimerMachine();
    const long long reached = scanReachingStep2(model, 80'000);
    // 25 minutes are 75,000 cycles of 20 ms; A1 -> F1 fires in scan 1.
    CHECK(reached == 75'002);

    SECTION("time counted in scans finds the run the simulator takes")
    {
        requireViolatedAndReplayed(verifyLongTimer(true, 2'000'000), reached);
    }
    SECTION("the timer abstraction's run is searched again in scans and confirmed")
    {
        requireViolatedAndReplayed(verifyLongTimer(false, 2'000'000), reached);
    }
    SECTION("out of budget, counted in scans: undecided, never 'holds'")
    {
        const VerificationResult result = verifyLongTimer(true, 10'000);
        CHECK_FALSE(result.exhaustive);
        requireUndecided(result);
    }
    SECTION("the abstraction's run not confirmed in scans within the budget: not dropped, not 'holds'")
    {
        const VerificationResult result = verifyLongTimer(false, 10'000);
        requireUndecided(result);
        // Neither property is dropped: each is undecided (GV123), its run unconfirmed.
        CHECK(findingsWith(result, code::kPropertyUndecided).size() == 2);
        CHECK(result.undecided());
    }
}

TEST_CASE("Verification bounds: a TON counted only up to a limit may elapse after it", "[bothlayers][timers]")
{
    explore::Options options;
    options.exactTime = true;
    options.properties = kLongTimerProperties;
    options.maxCountedTimerRuns = 1'000; // both TONs need more: counted to 1,000, then chosen
    explore::ProgramExplorer explorer(samples::longTimerMachine(), options);
    const explore::Exploration& e = explorer.run();
    REQUIRE(e.exhaustive);
    CHECK(e.activeNestedSteps.at("F1") == std::vector<int>{1, 2});
    CHECK(std::count_if(e.events.begin(), e.events.end(),
                        [](const explore::Event& event) { return event.kind == explore::EventKind::PropertyViolated; })
          == 2);
    CHECK(std::any_of(e.abstractions.begin(), e.abstractions.end(), [](const std::string& line) {
        return line.find("longer than 1000 scans") != std::string::npos;
    }));
}

TEST_CASE("Verification bounds: the cancel callback is polled inside a scan that never settles", "[bothlayers][budget]")
{
    const Model model = factory::unstableCycleModel(10'000, 0);
    int polls = 0;
    constexpr int kCancelAt = 5;
    explore::Options options;
    options.cancelled = [&polls] { return ++polls >= kCancelAt; };
    explore::ProgramExplorer explorer(model, options);
    const explore::Exploration& e = explorer.run();
    CHECK(e.cancelled);
    CHECK_FALSE(e.exhaustive);
    CHECK(polls == kCancelAt);
    // Stopped within F1's first scan: far fewer of its 10,000 steps were ever active.
    REQUIRE(e.activeNestedSteps.count("F1") == 1);
    CHECK(e.activeNestedSteps.at("F1").size() < 1'000);
    CHECK(e.states <= 3);

    VerificationOptions verification;
    verification.cancelled = [&polls] { return ++polls >= 2 * kCancelAt; };
    polls = kCancelAt;
    const VerificationResult result = verifyModel(model, verification);
    CHECK(result.cancelled);
    CHECK_FALSE(result.exhaustive);
}

TEST_CASE("Verification bounds: a long cycle that never settles is explored in linear time", "[bothlayers][budget]")
{
    // Each scan of F1 runs 1,001 evolutions; reading only the transitions of
    // the active steps keeps the whole exploration to about a million.
    explore::Options options;
    explore::ProgramExplorer explorer(factory::unstableCycleModel(1'000, 0), options);
    const explore::Exploration& e = explorer.run();
    REQUIRE(e.exhaustive);
    CHECK(e.activeNestedSteps.at("F1").size() == 1'000);
    CHECK(e.firedNestedTransitions.at("F1").size() == 1'000);
    CHECK(std::any_of(e.events.begin(), e.events.end(),
                      [](const explore::Event& event) { return event.kind == explore::EventKind::Unstable; }));
}

} // namespace test_verificationbounds
