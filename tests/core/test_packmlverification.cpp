// The PackML verifier (spec packml.md §8, docs/packml.md "Verification"):
// GV130-GV138 on the Capper of §6.6, the shipped example and variants, and
// programs built wrong on purpose to show that each check sees what it
// claims to.

#include "packmlcapper.h"
#include "packmlsamples.h"
#include "verificationtestsupport.h"

#include "core/formats/modelfiles.h"
#include "core/templates/packml/packmlexplorer.h"
#include "core/templates/packml/packmlprogram.h"
#include "core/templates/packml/packmlscanchecks.h"
#include "core/templates/packml/packmlscenario.h"
#include "core/templates/packml/packmlsimulator.h"
#include "core/templates/packml/packmlverifier.h"
#include "core/verification/property.h"
#include "core/verification/verification.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <functional>
#include <string>
#include <variant>
#include <vector>

namespace test_packmlverification {

using namespace core;
using namespace core::packml;

namespace {

using packmltests::capperText;
using packmltests::capperWith;

using verificationtest::codesOf;
using verificationtest::findingOf;

// The counterexample replays as a scenario in a simulator of `program`,
// every expectation holding.
void requireReplays(const Model& model, const PackmlProgram& program, const VerificationFinding& finding)
{
    REQUIRE(finding.counterexample);
    CHECK(finding.counterexample->confirmed);
    INFO(finding.counterexample->text);
    const ScenarioParseResult parsed = parseScenario(finding.counterexample->text);
    REQUIRE(parsed.ok());
    PackmlSimulator simulator(model, program);
    REQUIRE(validatePackmlScenario(parsed.scenario, simulator).empty());
    CHECK(runPackmlScenario(parsed.scenario, simulator).passed());
}

} // namespace

TEST_CASE("The Capper of spec §6.6 verifies exhaustively without a finding", "[packml-verify]")
{
    const auto model = packmltests::loadCapper();
    const VerificationResult result = verifyModel(*model);
    INFO(Catch::Detail::stringify(codesOf(result)));
    CHECK(result.findings.empty());
    CHECK(result.exhaustive);
    CHECK_FALSE(result.violated());
    CHECK(result.configurations > 10);
}

TEST_CASE("A transition into a state the mode disables is GV132, with a counterexample that replays", "[packml-verify]")
{
    const auto model = packmltests::loadCapper();
    PackmlProgram program = buildPackmlProgram(*model);
    // Production disables Starting: Start from Idle must lead to Execute.
    packmltests::transitionOf(program, 1, State::Idle, Command::Start).destination = Destination{State::Starting, std::nullopt};
    const VerificationResult result = verifyPackmlProgram(*model, program);
    const VerificationFinding* f = findingOf(result, "GV132");
    REQUIRE(f);
    CHECK(f->severity == Severity::Error);
    REQUIRE(f->location);
    CHECK(f->location->target == Diagnostic::Target::ModeState);
    CHECK(f->location->mode == 1);
    CHECK(f->location->state == "Starting");
    CHECK(f->counterexample->text.find("expect state Starting") != std::string::npos);
    requireReplays(*model, program, *f);
    CHECK(result.violated());
}

TEST_CASE("A mode change granted outside S(c,r) is GV133", "[packml-verify]")
{
    const auto model = packmltests::loadCapper();
    PackmlProgram program = buildPackmlProgram(*model);
    ProgramMode& production = program.modes.front();
    REQUIRE(production.number == 1);
    REQUIRE_FALSE(production.grants.empty());
    production.grants.front().states.insert(State::Execute);
    const VerificationResult result = verifyPackmlProgram(*model, program);
    const VerificationFinding* f = findingOf(result, "GV133");
    REQUIRE(f);
    CHECK(f->severity == Severity::Error);
    CHECK(f->location->target == Diagnostic::Target::Mode);
    CHECK(f->message.find("Execute") != std::string::npos);
    requireReplays(*model, program, *f);
    // The model's own program has none.
    CHECK_FALSE(findingOf(verifyModel(*model), "GV133"));
}

TEST_CASE("Execute that starts afresh after the Hold loop, or resumes after a fresh start, is GV138", "[packml-verify]")
{
    const auto model = packmltests::loadCapper();
    SECTION("Unhold that clears Resume")
    {
        PackmlProgram program = buildPackmlProgram(*model);
        // Seen as a fresh start (from Starting), the Unhold clears Resume.
        packmltests::transitionOf(program, 1, State::Held, Command::Unhold).transition.target = State::Starting;
        const VerificationResult result = verifyPackmlProgram(*model, program);
        const VerificationFinding* f = findingOf(result, "GV138");
        REQUIRE(f);
        CHECK(f->message.find("afresh") != std::string::npos);
        requireReplays(*model, program, *f);
    }
    SECTION("Start that does not clear Resume after a Hold and a Stop")
    {
        PackmlProgram program = buildPackmlProgram(*model);
        // Start from Idle no longer clears Resume; the Stop out of Held left it set.
        packmltests::transitionOf(program, 1, State::Idle, Command::Start).transition.target = State::Execute;
        const VerificationResult result = verifyPackmlProgram(*model, program);
        const VerificationFinding* f = findingOf(result, "GV138");
        REQUIRE(f);
        CHECK(f->message.find("resumed where it should have started afresh") != std::string::npos);
        requireReplays(*model, program, *f);
    }
}

TEST_CASE("A continuous output TRUE in the scan that enters Aborted is GV136", "[packml-verify]")
{
    ScanReference reference(*packmltests::loadCapper()->packml());
    ScanFacts facts;
    facts.record.stateBefore = State::Execute;
    facts.record.modeBefore = 1;
    facts.record.state = State::Aborted;
    facts.record.mode = 1;
    facts.record.fired = packml::ModeTransition{packml::TemplateTransition{State::Execute, State::Aborting, Trigger::Command, Command::Abort, false},
                                                packml::Destination{State::Aborted, State::Aborting}};
    CHECK(checkScan(reference, {}, facts).empty());
    facts.continuousOutputsTrue = {"Cap"};
    const std::vector<ScanFinding> findings = checkScan(reference, {}, facts);
    REQUIRE(findings.size() == 1);
    CHECK(findings.front().code == "GV136");
    CHECK(findings.front().names == std::vector<std::string>{"Cap"});
    facts.record.fired.reset(); // not the scan that enters it
    CHECK(checkScan(reference, {}, facts).empty());
}

TEST_CASE("A stored output still TRUE when Aborted is entered is GV137 (info)", "[packml-verify]")
{
    const auto model = capperWith({{"\"timing\": \"continuous\",\n                  \"text\": \"N Eject\"",
                                   "\"timing\": \"activation\",\n                  \"text\": \"S Eject\""}});
    const VerificationResult result = verifyModel(*model);
    const VerificationFinding* f = findingOf(result, "GV137");
    REQUIRE(f);
    CHECK(f->severity == Severity::Info);
    CHECK(f->message.find("Eject") != std::string::npos);
    requireReplays(*model, buildPackmlProgram(*model), *f);
    CHECK_FALSE(findingOf(result, "GV136"));
    CHECK_FALSE(findingOf(verifyModel(*packmltests::loadCapper()), "GV137"));
}

TEST_CASE("A GRAFCET that never completes is GV130, and what it cuts off GV134 and GV135", "[packml-verify]")
{
    // Resetting never completes, and Manual changes mode in Stopped only:
    // Production's Idle can be reached neither by Resetting's SC nor from Manual.
    const auto model = capperWith({{"\"receptivity\": \"Homed\"", "\"receptivity\": \"FALSE\""},
                                   {"\"Idle\",\n        \"Aborted\"", "\"Aborted\"", "\"request\": \"KeyManual\""}});
    const VerificationResult result = verifyModel(*model);
    INFO(Catch::Detail::stringify(codesOf(result)));
    REQUIRE(result.exhaustive);
    const VerificationFinding* stuck = findingOf(result, "GV130");
    REQUIRE(stuck);
    CHECK(stuck->severity == Severity::Error);
    CHECK(stuck->location->target == Diagnostic::Target::ModeState);
    CHECK(stuck->location->state == "Resetting");
    REQUIRE(stuck->counterexample);
    CHECK(stuck->counterexample->confirmed);
    std::vector<std::string> neverActive, neverAccepted;
    for (const VerificationFinding& f : result.findings) {
        if (f.code == "GV134")
            neverActive.push_back(f.location->state);
        if (f.code == "GV135")
            neverAccepted.push_back(f.location->element);
    }
    // Production never leaves Resetting by its SC: Idle, Execute and Held are cut off there.
    CHECK(neverActive == std::vector<std::string>{"Idle", "Execute", "Held"});
    CHECK(neverAccepted == std::vector<std::string>{"Hold", "Unhold"});
}

TEST_CASE("A mode no other mode may change to is never current: GV134", "[packml-verify]")
{
    // Manual allows no mode change: S(Production, Manual) is empty.
    std::string text = capperText();
    const std::size_t manual = text.find("\"request\": \"KeyManual\"");
    REQUIRE(manual != std::string::npos);
    const std::size_t list = text.find("\"modeChange\": [", manual);
    const std::size_t end = text.find(']', list);
    text.replace(list, end - list + 1, "\"modeChange\": []");
    auto loaded = core::loadNativeJson(text, "capper-variant.json");
    REQUIRE(std::holds_alternative<std::unique_ptr<Model>>(loaded));
    const VerificationResult result = verifyModel(*std::get<std::unique_ptr<Model>>(loaded));
    const VerificationFinding* f = findingOf(result, "GV134");
    REQUIRE(f);
    CHECK(f->location->target == Diagnostic::Target::Mode);
    CHECK(f->location->mode == 3);
}

TEST_CASE("A budget too small says GV100 and claims no never-finding", "[packml-verify]")
{
    const auto model = capperWith({{"\"receptivity\": \"Homed\"", "\"receptivity\": \"FALSE\""}});
    VerificationOptions options;
    options.maxProgramStates = 3;
    const VerificationResult result = verifyModel(*model, options);
    CHECK_FALSE(result.exhaustive);
    CHECK(result.undecided());
    CHECK(findingOf(result, "GV100"));
    for (const char* never : {"GV130", "GV131", "GV134", "GV135"})
        CHECK_FALSE(findingOf(result, never));
}

TEST_CASE("The engineer's properties read in <State>, mode <Mode> and <Mode>_<State>.Xn", "[packml-verify]")
{
    const auto model = packmltests::loadCapper();
    VerificationOptions options;
    options.properties = {
        "never Cap AND NOT in Execute",             // Cap is driven in Execute only
        "always Cap -> Production_Execute.X1",      // by its step 1
        "never mode Manual AND in Held",            // Manual disables Held
        "never in Execute AND mode Manual",         // Manual's Execute is reachable
        "never Production_Execute.X2 AND Eject",    // step 2 drives Eject
        "never in Nowhere",                         // no such state
    };
    const VerificationResult result = verifyModel(*model, options);
    INFO(Catch::Detail::stringify(codesOf(result)));
    REQUIRE(result.propertyVerdicts.size() == 6);
    CHECK(result.propertyVerdicts[0].outcome == PropertyOutcome::Holds);
    CHECK(result.propertyVerdicts[1].outcome == PropertyOutcome::Holds);
    CHECK(result.propertyVerdicts[2].outcome == PropertyOutcome::Holds);
    CHECK(result.propertyVerdicts[3].outcome == PropertyOutcome::Violated);
    CHECK(result.propertyVerdicts[4].outcome == PropertyOutcome::Violated);
    CHECK(result.propertyVerdicts[5].outcome == PropertyOutcome::Undecided);
    std::vector<std::string> codes(6);
    for (const VerificationFinding& f : result.findings)
        if (f.property >= 0)
            codes[static_cast<std::size_t>(f.property)] = f.code;
    CHECK(codes == std::vector<std::string>{"GV121", "GV121", "GV121", "GV120", "GV120", "GV122"});
    for (const VerificationFinding& f : result.findings)
        if (f.code == "GV120") {
            requireReplays(*model, buildPackmlProgram(*model), f);
            CHECK(verificationElementLabel(f) == "property '" + options.properties[static_cast<std::size_t>(f.property)] + "'");
        }
}

TEST_CASE("PackML property names are checked against the program", "[packml-verify]")
{
    const auto model = packmltests::loadCapper();
    CHECK(checkProperty(*model, "never in Execute AND mode Manual").empty());
    CHECK(checkProperty(*model, "never IN held OR MODE production").empty());
    const auto codeOf = [&](const std::string& text) {
        const std::vector<PropertyProblem> problems = checkProperty(*model, text);
        return problems.empty() ? std::string() : problems.front().code;
    };
    CHECK(codeOf("never in Nowhere") == "GP003");
    CHECK(codeOf("never mode Cleaning") == "GP003");
    CHECK(codeOf("never Manual_Execute.X1") == "GP004");
    CHECK(codeOf("never Production_Execute.X9") == "GP005");
    CHECK(codeOf("never Ghost") == "GP002");
    CHECK(codeOf("never mode") == "GP002"); // `mode` alone is a variable name
    // The span of a problem is that of the text as written.
    const std::vector<PropertyProblem> problems = checkProperty(*model, "never mode Cleaning");
    REQUIRE(problems.size() == 1);
    CHECK(problems.front().span.begin == 6);
}

TEST_CASE("On random PackML models the generated rules hold and every claimed violation replays", "[packml-verify]")
{
    // The program is right by construction (the agreement test proves the
    // simulator equals the generated code): GV132, GV133, GV136 and GV138
    // must never fire, and whatever is claimed reachable must replay.
    VerificationOptions options;
    options.timeLimit = std::chrono::milliseconds(200);
    options.maxProgramStates = 20'000;
    int exhaustive = 0, violations = 0;
    for (std::uint32_t seed = 1; seed <= 30; ++seed) {
        const Model model = samples::randomPackmlModel(seed);
        const VerificationResult result = verifyModel(model, options);
        exhaustive += result.exhaustive ? 1 : 0;
        violations += result.violated() ? 1 : 0;
        INFO("seed " << seed << ": " << Catch::Detail::stringify(codesOf(result)));
        for (const VerificationFinding& f : result.findings) {
            CHECK(f.code != "GV132");
            CHECK(f.code != "GV133");
            CHECK(f.code != "GV136");
            CHECK(f.code != "GV138");
            for (const char* never : {"GV130", "GV131", "GV134", "GV135", "GV121"})
                CHECK((f.code != never || result.exhaustive));
            if (f.counterexample)
                CHECK(f.counterexample->confirmed);
            CHECK(f.location);
        }
    }
    // Random models are large (timers, INT selectors, many inputs): none is
    // explored exhaustively in this budget, so no never-claim may appear,
    // and nothing the explorer reached may be a violation.
    CHECK(exhaustive == 0);
    CHECK(violations == 0);
}

TEST_CASE("Memories the next scan cannot read do not split the explored configurations", "[packml-verify]")
{
    const auto model = packmltests::loadCapper();
    const PackmlExplorer explorer(*model, buildPackmlProgram(*model), ExplorerLimits{});
    const auto afterOneScan = [&](const char* input, bool value) {
        PackmlSimulator simulator(*model);
        REQUIRE(simulator.setInput(input, value).ok);
        (void)simulator.scan();
        return simulator;
    };
    // Hold acts in Execute only: its R_TRIG memory after a scan in Stopped is overwritten unread.
    const PackmlSimulator held = afterOneScan("Cmd_Hold", true), released = afterOneScan("Cmd_Hold", false);
    REQUIRE(held.state() == State::Stopped);
    REQUIRE(held.commandMemory(static_cast<std::size_t>(std::find_if(held.program().commands.begin(),
        held.program().commands.end(), [](const ProgramCommand& c) { return c.command == Command::Hold; })
        - held.program().commands.begin())));
    CHECK(explorer.key(held, PauseGhost{}) == explorer.key(released, PauseGhost{}));

    // The bottle filler reads BottleIn under an edge in Execute only: in
    // Stopped its BottleIn_PREV is overwritten unread too.
    const LoadedModel filler = loadModelFile(GGSTUDIO_EXAMPLES_DIR "/bottle-filler.ggstudio.json");
    REQUIRE(filler.ok());
    const PackmlExplorer fillerExplorer(*filler.model, buildPackmlProgram(*filler.model), ExplorerLimits{});
    PackmlSimulator bottle(*filler.model), none(*filler.model);
    REQUIRE(bottle.setInput("BottleIn", true).ok);
    (void)bottle.scan();
    (void)none.scan();
    REQUIRE(bottle.state() == State::Stopped);
    REQUIRE(bottle.previous(bottle.slotOf("BottleIn")));
    CHECK(fillerExplorer.key(bottle, PauseGhost{}) == fillerExplorer.key(none, PauseGhost{}));
}

} // namespace test_packmlverification
