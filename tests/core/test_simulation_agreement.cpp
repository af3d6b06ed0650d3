#include <catch2/catch.hpp>

#include "core/model/model.h"
#include "core/simulation/simulator.h"
#include "core/codegen/stgenerator.h"
#include "core/templates/gemma/gemmacodegen.h"
#include "modelfactory.h"
#include "samplemodels.h"
#include "stinterpreter.h"

#include <random>
#include <string>
#include <vector>

namespace test_simulation_agreement {

using namespace core;

// The simulator must run exactly the code the PLC runs: the generated GEMMA
// program, interpreted statement by statement, and the simulator give the
// same State, Entry, tokens and Complete at every scan.

namespace {

sttest::StInterpreter interpreterFor(const Model& model)
{
    const PlcProject project = buildPlcProject(model, Dialect::Iec);
    return sttest::StInterpreter(previewGemmaProgram(model, Dialect::Iec).text, formatGlobals(project));
}

cond::Value randomValue(std::mt19937& random, IecType type)
{
    if (type == IecType::Bool)
        return random() % 2 == 0;
    if (isRealType(type))
        return static_cast<double>(random() % 9) / 2.0 - 1.0; // -1.0 .. 3.0, around the models' 1.5
    return static_cast<std::int64_t>(random() % 101); // fits every integer type
}

void compareAt(const Simulator& sim, const sttest::StInterpreter& plc, std::int64_t scan)
{
    INFO("scan " << scan);
    REQUIRE(plc.runtimeError().empty());
    REQUIRE(sim.activeStepNumber() == plc.state());
    REQUIRE(sim.entry() == plc.entry());
    const std::vector<bool> tokens = sim.tokenValues();
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        INFO("token " << sim.tokenNames()[i]);
        REQUIRE(tokens[i] == cond::isTrue(plc.value(sim.tokenNames()[i])));
    }
    for (const std::string& step : sim.nestedSteps()) {
        INFO("Complete of " << step);
        REQUIRE(sim.complete(step) == plc.complete(step));
    }
}

void runBoth(const Model& model, std::uint32_t seed, int scans)
{
    sttest::StInterpreter plc = interpreterFor(model);
    INFO("seed " << seed);
    REQUIRE(plc.error().empty());
    Simulator sim(model);
    REQUIRE(sim.tokenNames() == plc.tokenNames());
    REQUIRE(sim.nestedSteps() == plc.instances());

    std::mt19937 random(seed * 7919u + 1u);
    std::vector<bool> manual;
    for (const std::string& step : sim.nestedSteps()) {
        manual.push_back(random() % 2 == 0);
        REQUIRE(sim.setCompleteMode(step, manual.back() ? CompleteMode::Manual : CompleteMode::Automatic));
    }
    compareAt(sim, plc, 0);
    for (int scan = 1; scan <= scans; ++scan) {
        for (std::size_t i = 0; i < sim.variableNames().size(); ++i) {
            if (random() % 3 != 0)
                continue;
            const cond::Value value = randomValue(random, sim.variableType(i));
            REQUIRE(sim.setVariableAt(i, value));
            plc.setInput(sim.variableNames()[i], value);
        }
        for (std::size_t i = 0; i < manual.size(); ++i) {
            if (!manual[i])
                continue;
            const bool complete = random() % 3 == 0; // mostly still running
            REQUIRE(sim.setComplete(sim.nestedSteps()[i], complete));
            plc.setManualComplete(sim.nestedSteps()[i], complete);
        }
        sim.step();
        plc.scan();
        compareAt(sim, plc, scan);
    }
}

} // namespace

TEST_CASE("Simulation agrees with the generated code on 200 random models", "[simulation]")
{
    int fired = 0;
    for (std::uint32_t seed = 1; seed <= 200; ++seed) {
        const Model model = samples::randomModel(seed);
        runBoth(model, seed, 50);
        // The test must exercise transitions, not only idle scans.
        Simulator probe(model);
        std::mt19937 random(seed);
        for (int scan = 0; scan < 50; ++scan) {
            for (std::size_t i = 0; i < probe.variableNames().size(); ++i)
                probe.setVariableAt(i, randomValue(random, probe.variableType(i)));
            fired += probe.step().fired.empty() ? 0 : 1;
        }
    }
    CHECK(fired > 1000);
}

TEST_CASE("Simulation agrees with the generated code on the shared models", "[simulation]")
{
    runBoth(factory::realisticModel(), 1, 300);
    runBoth(samples::caseStudyModel(), 2, 300);
    runBoth(Model(), 3, 20); // the template: every condition empty, so unusable and FALSE
}

TEST_CASE("The ST interpreter reads what the generator writes", "[simulation]")
{
    // Guard against an interpreter that silently does nothing.
    const Model model = factory::realisticModel();
    sttest::StInterpreter plc = interpreterFor(model);
    REQUIRE(plc.error().empty());
    CHECK(plc.state() == 6);
    CHECK(plc.entry());
    CHECK(plc.tokenNames().size() == 3);
    plc.setInput("HomePosition", true);
    plc.setInput("AirPressureOk", true);
    plc.scan();
    CHECK(plc.state() == 1);
    CHECK(plc.runtimeError().empty());
}

TEST_CASE("The ST interpreter runs the standard R_TRIG as a program instance", "[simulation]")
{
    // PackML programs sample each command through an R_TRIG (spec packml.md §6.3).
    const std::string globals = "VAR_GLOBAL\n    Button : BOOL;\n    Count : INT;\nEND_VAR\n";
    const std::string program = "PROGRAM P\nVAR_EXTERNAL\n    Button : BOOL;\n    Count : INT;\nEND_VAR\n"
                                "VAR\n    Trig_Button : R_TRIG;\nEND_VAR\n"
                                "Trig_Button(CLK := Button);\nIF Trig_Button.Q THEN Count := Count + 1; END_IF;\n"
                                "END_PROGRAM\n";
    sttest::StInterpreter plc(program, globals);
    REQUIRE(plc.error().empty());
    const std::vector<bool> presses{true, true, false, true, false, false, true};
    std::vector<std::int64_t> counts;
    for (const bool pressed : presses) {
        plc.setInput("Button", pressed);
        plc.scan();
        counts.push_back(std::get<std::int64_t>(plc.value("Count")));
    }
    // TRUE in the first scan is an edge; holding it is not.
    CHECK(counts == std::vector<std::int64_t>{1, 1, 1, 2, 2, 2, 3});
    CHECK(plc.runtimeError().empty());
    CHECK(plc.member("Trig_Button", "Q") == std::optional<core::cond::Value>(true));
}

} // namespace test_simulation_agreement
