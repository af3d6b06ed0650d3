// Durations past what IEC TIME holds (issue #32): TIME is 32-bit
// milliseconds, so a TON preset is T#24d20h31m23s647ms at most. A longer
// t/Xn is an error with its place (GG407) and the receptivity never fires,
// in the generated code, the simulator and the verifier alike; the generator
// never clamps (25d and 26d would both become the same preset and fire
// together on the PLC).

#include <catch2/catch.hpp>

#include "core/checks/checks.h"
#include "core/templates/gemma/gemmaprogram.h"
#include "core/codegen/stgenerator.h"
#include "core/condition/conditionparser.h"
#include "core/model/model.h"
#include "core/simulation/simulator.h"
#include "samplemodels.h"

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

namespace test_durationlimit {

using namespace core;

namespace {

std::string functionBlock(const Model& model, const std::string& name)
{
    const PlcProject project = buildPlcProject(model, Dialect::Iec);
    for (const PlcPou& pou : project.pous) {
        if (pou.name == name)
            return formatPou(pou, Dialect::Iec);
    }
    FAIL("no POU " << name);
    return {};
}

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

std::vector<Diagnostic> withCode(const std::vector<Diagnostic>& diagnostics, const std::string& code)
{
    std::vector<Diagnostic> result;
    std::copy_if(diagnostics.begin(), diagnostics.end(), std::back_inserter(result),
                 [&](const Diagnostic& d) { return d.code == code; });
    return result;
}

// F1: 1 --RE Start--> 2 --<receptivity>--> 3.
Model lampWithT2(const std::string& receptivity)
{
    Model model = samples::lampGrafcetModel();
    REQUIRE(model.setReceptivity("F1", 2, receptivity));
    return model;
}

} // namespace

TEST_CASE("Durations: the longest TIME parses exactly, longer ones saturate", "[duration]")
{
    CHECK(cond::parseDurationMs("24d20h31m23s647ms") == cond::kMaxTimeMs);
    CHECK(cond::parseDurationMs("T#24d20h31m23s648ms") == cond::kMaxTimeMs + 1);
    CHECK(cond::parseDurationMs("9999999999d") == 9'999'999'999LL * 86'400'000LL);
    // Beyond 64 bits: still a duration (so the checks can say it is too long), never an overflow.
    CHECK(cond::parseDurationMs("99999999999999999999d") == std::numeric_limits<std::int64_t>::max());
    CHECK(cond::parseDurationMs("106751991167d1ms") == std::numeric_limits<std::int64_t>::max());
    CHECK(cond::parseDurationMs("99999999999999999999d1x") == std::nullopt); // malformed stays malformed
    CHECK(formatDuration(cond::kMaxTimeMs) == "T#24d20h31m23s647ms");
}

TEST_CASE("Durations: a preset IEC TIME cannot hold is an error with its place", "[duration][checks]")
{
    const std::vector<std::string> receptivities = {
        "25d/X2", "26d/X2", "T#24d20h31m23s648ms/X2", "9999999999d/X2", "99999999999999999999d/X2", "Start AND 25d/X2",
    };
    for (const std::string& receptivity : receptivities) {
        INFO(receptivity);
        const Model model = lampWithT2(receptivity);
        const std::vector<Diagnostic> found = withCode(checkModel(model), "GG407");
        REQUIRE(found.size() == 1);
        CHECK(found[0].severity == Severity::Error);
        CHECK(found[0].target == Diagnostic::Target::GrafcetTransition);
        CHECK(found[0].nestedNumber == 2);
        REQUIRE(found[0].span.has_value());
        CHECK(found[0].span->end == receptivity.size());
        const GemmaProgram program = buildGemmaProgram(model);
        const NestedGrafcet& nested = *program.step("F1")->nested;
        CHECK_FALSE(nested.transitions[1].usable);
        CHECK(nested.timers.empty()); // no TON for it, so no preset to clamp
    }
    const Diagnostic d = withCode(checkModel(lampWithT2("25d/X2")), "GG407").front();
    CHECK(d.arguments == std::vector<std::string>{"F1", "the receptivity of T2 of F1", "25d/X2", "T#24d20h31m23s647ms"});
    CHECK(d.message
          == "in the receptivity of T2 of F1: 25d/X2 is longer than T#24d20h31m23s647ms, the longest duration an IEC "
             "TIME (a TON preset) holds");
    // In an action a duration is refused anyway (GG411); its length is reported too.
    Model action = samples::lampGrafcetModel();
    REQUIRE(action.addGrafcetAction("F1", 3, {ActionTiming::OnActivation, "Lamp := 30d/X3"}));
    const std::vector<Diagnostic> diagnostics = checkModel(action);
    CHECK(withCode(diagnostics, "GG407").size() == 1);
    CHECK(withCode(diagnostics, "GG411").size() == 1);
}

TEST_CASE("Durations: the generated code never clamps a preset", "[duration][codegen]")
{
    const std::string longest = functionBlock(lampWithT2("24d20h31m23s647ms/X2"), "F1_FB");
    CHECK(contains(longest, "GG_T2_2147483647ms(IN := X2, PT := T#24d20h31m23s647ms);"));

    // 25d and 26d out of one step: before, both came out as the same clamped
    // preset and fired together on the PLC, while the simulator fired one.
    Model model = lampWithT2("25d/X2");
    REQUIRE(model.addGrafcetTransition("F1", {3, {2}, {1}, "26d/X2"}));
    CHECK(withCode(checkModel(model), "GG407").size() == 2);
    const std::string code = functionBlock(model, "F1_FB");
    CHECK(contains(code, "(* ERROR GG407: in the receptivity of T2 of F1: 25d/X2 is longer than T#24d20h31m23s647ms"));
    CHECK(contains(code, "(* ERROR GG407: in the receptivity of T3 of F1: 26d/X2 is longer than T#24d20h31m23s647ms"));
    CHECK_FALSE(contains(code, "PT := T#24d20h31m23s647ms"));
    CHECK_FALSE(contains(code, ": TON;"));
    CHECK_FALSE(contains(code, "GG_Fire2"));
    CHECK_FALSE(contains(code, "GG_Fire3"));
}

TEST_CASE("Durations: the simulator never fires a receptivity whose duration is too long", "[duration][simulation]")
{
    Model model = lampWithT2("25d/X2 OR TRUE");
    REQUIRE(model.setInitialStep("F1"));
    REQUIRE(model.setReceptivity("F1", 1, "TRUE"));
    Simulator sim(model);
    sim.run(5);
    // T1 fired in the entry scan; T2 would fire at once if its receptivity were used.
    CHECK(sim.activeNestedSteps("F1") == std::vector<int>{2});
    CHECK(sim.nestedTimers("F1").empty());
}

} // namespace test_durationlimit
