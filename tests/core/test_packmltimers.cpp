// The PackML verifier's timer abstraction (docs/packml.md, "Verification",
// Timers): a TON longer than one cycle may or may not have elapsed from its
// second run on. The shipped bottle filler is decided with it; a finding
// whose run exists only under the abstraction is searched again with time
// counted in scans (kept when found, dropped when that search is exhaustive);
// and on random variants every finding time counted in scans confirms is
// also found with the abstraction.

#include "packmlcapper.h"
#include "verificationtestsupport.h"

#include "core/formats/modelfiles.h"
#include "core/templates/packml/packmlexplorer.h"
#include "core/templates/packml/packmlscenario.h"
#include "core/templates/packml/packmlsimulator.h"
#include "core/templates/packml/packmlverifier.h"
#include "core/verification/verification.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace test_packmltimers {

using namespace core;
using namespace core::packml;
using packmltests::capperWith;
using packmltests::Replacement;

namespace {

using verificationtest::codesOf;
using verificationtest::findingOf;

const VerificationFinding* propertyFinding(const VerificationResult& result, int property)
{
    const auto found = std::find_if(result.findings.begin(), result.findings.end(),
                                    [&](const VerificationFinding& f) { return f.property == property; });
    return found == result.findings.end() ? nullptr : &*found;
}

// The counterexample replays as a scenario at nominal time, every expectation holding.
bool replays(const Model& model, const VerificationFinding& finding)
{
    if (!finding.counterexample)
        return false;
    INFO(finding.counterexample->text);
    const ScenarioParseResult parsed = parseScenario(finding.counterexample->text);
    if (!parsed.ok())
        return false;
    PackmlSimulator simulator(model);
    return validatePackmlScenario(parsed.scenario, simulator).empty() && runPackmlScenario(parsed.scenario, simulator).passed();
}

// Production's Resetting: step 1 leaves for step 2 (Complete) on `homing`;
// with `early`, also for step 3 (which never completes, unless
// `earlyCompletes`) on it. Execute's
// step 1 leaves on `capped`. Manual allows no mode change, so Idle is
// reached through Resetting only.
std::unique_ptr<Model> capperWithTimers(const std::string& homing, const std::string& early = {},
                                        const std::string& capped = "Capped", bool earlyCompletes = false)
{
    const std::string earlyActions = earlyCompletes ? "[{ \"timing\": \"activation\", \"text\": \"S Complete\" }]" : "[]";
    std::vector<Replacement> replacements{{"\"receptivity\": \"Homed\"", "\"receptivity\": \"" + homing + "\""},
                                          {"\"receptivity\": \"Capped\"", "\"receptivity\": \"" + capped + "\""},
                                          {"\"modeChange\": [\n        \"Stopped\",\n        \"Idle\",\n        \"Aborted\"\n      ]",
                                           "\"modeChange\": []", "\"request\": \"KeyManual\""}};
    if (!early.empty()) {
        replacements.push_back({"\"receptivity\": \"" + homing + "\"",
                                "\"receptivity\": \"" + homing + "\" }, { \"number\": 2, \"upstream\": [1], "
                                "\"downstream\": [3], \"receptivity\": \"" + early + "\""});
        replacements.push_back({"\"text\": \"S Complete\"\n                }\n              ]\n            }",
                                "\"text\": \"S Complete\"\n                }\n              ]\n            }, "
                                "{ \"number\": 3, \"initial\": false, \"comment\": \"Early\", \"actions\": " + earlyActions + " }",
                                "\"comment\": \"Homed\","});
    }
    return capperWith(replacements);
}

} // namespace

TEST_CASE("The shipped bottle filler: its timers are abstracted, no longer a reason for GV100", "[packml-verify][timers]")
{
    const LoadedModel loaded = loadModelFile(GGSTUDIO_EXAMPLES_DIR "/bottle-filler.ggstudio.json");
    REQUIRE(loaded.ok());
    VerificationOptions options;
    options.timeLimit = std::chrono::milliseconds(1000);
    const VerificationResult result = verifyModel(*loaded.model, options);
    INFO(Catch::Detail::stringify(codesOf(result)));
    // Its Starting, Stopping and Aborting wait on 2 s TONs at 10 ms: each
    // TON is idle, running or elapsed, not one configuration per scan.
    REQUIRE(result.abstractions.size() == 1);
    CHECK(result.abstractions.front().find("timers longer than one cycle") != std::string::npos);
    // Its configurations (inputs shared by Suspend and Unsuspend, by the two
    // mode requests, the BottleIn edge, the batch count) outnumber the
    // budget: GV100 names the budget, never the timers.
    for (const VerificationFinding& f : result.findings) {
        if (f.code == "GV100") {
            CHECK(f.message.find("budget") != std::string::npos);
            CHECK(f.message.find("timer") == std::string::npos);
            CHECK(f.message.find("cycle time") == std::string::npos);
        }
        if (f.counterexample && f.severity != Severity::Info)
            CHECK(replays(*loaded.model, f));
    }
    CHECK_FALSE(result.violated());
}

TEST_CASE("Under the timer abstraction a never-claim holds and GV130 needs a sure way to Complete", "[packml-verify][timers]")
{
    // Resetting waits 100 ms (6 runs at 20 ms): decided, and the Capper's
    // verdicts stay those of the Capper (no GV100).
    const auto model = capperWithTimers("100ms/X1");
    const VerificationResult result = verifyModel(*model);
    INFO(Catch::Detail::stringify(codesOf(result)));
    CHECK(result.exhaustive);
    CHECK_FALSE(findingOf(result, "GV100"));
    CHECK_FALSE(findingOf(result, "GV130"));
    for (const VerificationFinding& f : result.findings)
        CHECK((f.code != "GV134" || f.message == "Manual is never the current mode")); // no mode change leads to it
    // A TON that never elapses (its step is left by nothing else) leaves
    // Resetting stuck: shown on a run the simulator replays.
    const auto stuck = capperWithTimers("100ms/X1 AND FALSE");
    const VerificationResult stuckResult = verifyModel(*stuck);
    INFO(Catch::Detail::stringify(codesOf(stuckResult)));
    const VerificationFinding* gv130 = findingOf(stuckResult, "GV130");
    REQUIRE(gv130);
    CHECK(gv130->severity == Severity::Error);
    CHECK(replays(*stuck, *gv130));
}

TEST_CASE("A violation that needs a TON to elapse is confirmed on a run at nominal time", "[packml-verify][timers]")
{
    const auto model = capperWithTimers("100ms/X1");
    VerificationOptions options;
    options.properties = {"never in Idle"};
    const VerificationResult result = verifyModel(*model, options);
    INFO(Catch::Detail::stringify(codesOf(result)));
    const VerificationFinding* f = propertyFinding(result, 0);
    REQUIRE(f);
    CHECK(f->code == "GV120");
    CHECK(f->severity == Severity::Error);
    REQUIRE(f->counterexample);
    CHECK(f->counterexample->confirmed);
    // The abstraction's own run lets the TON elapse at its second run; the
    // one reported waits the 6 runs the PLC's does.
    CHECK(replays(*model, *f));
    REQUIRE(result.propertyVerdicts.size() == 1);
    CHECK(result.propertyVerdicts[0].outcome == PropertyOutcome::Violated);
}

TEST_CASE("A violation only the timer abstraction shows is never reported", "[packml-verify][timers]")
{
    // Step 1 leaves for step 3 after 40 ms, long before its 100 ms TON could
    // lead to step 2 and Idle; the abstraction lets either elapse first.
    const auto model = capperWithTimers("100ms/X1", "40ms/X1");
    VerificationOptions options;
    options.properties = {"never in Idle", "never Production_Resetting.X3"};
    const VerificationResult result = verifyModel(*model, options);
    INFO(Catch::Detail::stringify(codesOf(result)));
    REQUIRE(result.propertyVerdicts.size() == 2);
    const VerificationFinding* spurious = propertyFinding(result, 0);
    REQUIRE(spurious);
    // Time counted in scans explores this small model to the end: the run
    // is dropped, and it decides GV130 where two TONs run (below).
    CHECK(spurious->code == "GV121");
    CHECK(result.propertyVerdicts[0].outcome == PropertyOutcome::Holds);
    CHECK(result.propertyVerdicts[1].outcome == PropertyOutcome::Violated);
    CHECK(result.exhaustive);
    CHECK_FALSE(findingOf(result, "GV100"));
    // Step 3 never completes: a real GV130, on a run at nominal time.
    const VerificationFinding* gv130 = findingOf(result, "GV130");
    REQUIRE(gv130);
    CHECK(gv130->severity == Severity::Error);
    CHECK(replays(*model, *gv130));
}

TEST_CASE("Where time counted in scans runs out, an abstraction-only run stays info and GV130 undecided",
          "[packml-verify][timers]")
{
    // The same at 1000 s and 400 s: 50,000 and 20,000 scans, far beyond the budget.
    const auto model = capperWithTimers("1000s/X1", "400s/X1");
    VerificationOptions options;
    options.properties = {"never in Idle"};
    options.maxProgramStates = 5'000;
    const VerificationResult result = verifyModel(*model, options);
    INFO(Catch::Detail::stringify(codesOf(result)));
    const VerificationFinding* spurious = propertyFinding(result, 0);
    REQUIRE(spurious);
    CHECK(spurious->severity == Severity::Info);
    CHECK(spurious->message.find("(not confirmed:") != std::string::npos);
    CHECK(result.propertyVerdicts[0].outcome == PropertyOutcome::Undecided);
    // Two TONs read in one scan: no sure way to Complete is claimed from
    // where both run, so GV130 and GV131 are left undecided there.
    const VerificationFinding* undecided = findingOf(result, "GV100");
    REQUIRE(undecided);
    CHECK(undecided->message.find("GV130 and GV131 were not decided in Production Resetting") != std::string::npos);
    CHECK_FALSE(result.exhaustive);
    // Step 3's GV130 is seen on the abstraction's run only (400 s elapsed at once).
    for (const VerificationFinding& f : result.findings)
        if (f.code == "GV130")
            CHECK(f.severity == Severity::Info);
}

TEST_CASE("Where two TONs race, the abstraction's way to Complete is not taken for the PLC's", "[packml-verify][timers]")
{
    // Both ways complete, but a way to Complete that needs the 1000 s TON
    // before the 400 s one exists only under the abstraction: from where
    // both run, the scans that wait decide two TONs, so no sure way is
    // known, and time counted in scans cannot end (70,000 scans of waiting).
    const auto model = capperWithTimers("1000s/X1", "400s/X1", "Capped", true);
    VerificationOptions options;
    options.maxProgramStates = 5'000;
    const VerificationResult result = verifyModel(*model, options);
    INFO(Catch::Detail::stringify(codesOf(result)));
    const VerificationFinding* undecided = findingOf(result, "GV100");
    REQUIRE(undecided);
    CHECK(undecided->message == "GV130 and GV131 were not decided in Production Resetting: timers longer than one cycle "
                                "may or may not have elapsed, and the runs to Complete found from some situations let "
                                "TONs elapse in an order the PLC's may not");
    CHECK(undecided->arguments == std::vector<std::string>{"stuck", "Production Resetting"}); // the editor's wording
    CHECK_FALSE(findingOf(result, "GV130"));
    CHECK_FALSE(result.exhaustive);
    // One TON alone: waiting for it is sure, GV130 and GV131 are decided.
    const VerificationResult single = verifyModel(*capperWithTimers("1000s/X1"), options);
    INFO(Catch::Detail::stringify(codesOf(single)));
    CHECK_FALSE(findingOf(single, "GV100"));
    CHECK(single.exhaustive);
}

TEST_CASE("On random timer variants, what time counted in scans confirms the abstraction finds too", "[packml-verify][timers]")
{
    const std::vector<std::string> properties = {"never in Idle", "never Production_Resetting.X3",
                                                 "never Production_Execute.X2", "never in Held"};
    int compared = 0, confirmedFindings = 0;
    for (std::uint32_t seed = 1; seed <= 12; ++seed) {
        std::mt19937 random(seed);
        const auto ms = [&] { return std::to_string(20 * std::uniform_int_distribution<int>(1, 8)(random)) + "ms"; };
        const std::string homing = random() % 2 ? ms() + "/X1" : "Homed AND " + ms() + "/X1";
        const std::string early = random() % 2 ? ms() + "/X1" : std::string();
        const std::string capped = random() % 2 ? "Capped" : "Capped AND " + ms() + "/X1";
        const auto model = capperWithTimers(homing, early, capped);
        VerificationOptions options;
        options.properties = properties;
        const VerificationResult abstracted = verifyModel(*model, options);
        options.exactTime = true;
        const VerificationResult exact = verifyModel(*model, options);
        INFO("seed " << seed << ": " << homing << " / " << early << " / " << capped);
        INFO("abstracted: " << Catch::Detail::stringify(codesOf(abstracted)));
        INFO("exact: " << Catch::Detail::stringify(codesOf(exact)));
        CHECK(exact.abstractions.empty());
        const bool exactDecided = !findingOf(exact, "GV100");
        compared += exactDecided ? 1 : 0;
        // What time counted in scans shows on a run at nominal time, the
        // abstraction (which has every run the PLC has) reports too.
        for (const VerificationFinding& f : exact.findings) {
            if (!f.counterexample || !f.counterexample->confirmed)
                continue;
            ++confirmedFindings;
            CHECK(std::any_of(abstracted.findings.begin(), abstracted.findings.end(), [&](const VerificationFinding& a) {
                return a.code == f.code && a.property == f.property && a.message == f.message && a.severity == f.severity;
            }));
        }
        // And what the abstraction claims never happens, time counted in
        // scans (exhaustive) claims too.
        for (const VerificationFinding& a : abstracted.findings) {
            const bool never = a.code == "GV121" || a.code == "GV134" || a.code == "GV135";
            if (!never || !exactDecided)
                continue;
            CHECK(std::any_of(exact.findings.begin(), exact.findings.end(), [&](const VerificationFinding& f) {
                return a.code == f.code && a.property == f.property && a.message == f.message;
            }));
        }
    }
    CHECK(compared > 6);
    CHECK(confirmedFindings > 6);
}

} // namespace test_packmltimers
