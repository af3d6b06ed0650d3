#include <catch2/catch.hpp>

#include "core/codegen/stgenerator.h"
#include "core/formats/fileio.h"
#include "core/formats/modelfiles.h"
#include "core/model/model.h"
#include "core/simulation/simulator.h"
#include "samplemodels.h"
#include "generatedcode.h"
#include "stinterpreter.h"

#include <random>
#include <string>
#include <vector>

namespace test_nestedagreement {

using namespace core;

// Issue #16: the simulator runs exactly the code the PLC runs, nested
// GRAFCETs included. Under each evolution rule, random models with random
// nested GRAFCETs (and the drilling-cell example) are run by the simulator
// and by the generated Structured Text (the GEMMA program and every
// FUNCTION_BLOCK), interpreted statement by statement, with the same random
// inputs; after every scan State, Entry, the tokens, every Complete, every
// nested step X<n>, Unstable, every continuous output of every FB, every TON
// (Q, ET) and every variable must agree.

namespace {

using sttest::kSanitized;
using Generated = sttest::GeneratedCode;

Generated generate(const Model& model)
{
    return sttest::generateIec(model);
}

cond::Value randomValue(std::mt19937& random, IecType type)
{
    if (type == IecType::Bool)
        return random() % 2 == 0;
    if (isRealType(type))
        return static_cast<double>(random() % 9) / 2.0 - 1.0;
    return static_cast<std::int64_t>(random() % 101); // fits every integer type
}

// Where the interpreter keeps what the simulator shows, looked up once per model.
struct Probe {
    std::vector<int> tokens;    // global slots, in Simulator::tokenNames() order
    std::vector<int> variables; // global slots, in Simulator::variableNames() order
    struct Fb {
        std::string step;
        int instance = -1;
        int complete = -1;
        const NestedEngine* engine = nullptr;  // nullptr without a GRAFCET
        std::vector<std::pair<int, int>> steps; // nested step number, X<n> slot
        int unstable = -1;
        std::vector<int> outputs;               // in NestedEngine::outputNames() order
    };
    std::vector<Fb> fbs;
    std::string problem; // what the code does not declare

    Probe(const Simulator& sim, const sttest::StInterpreter& plc)
    {
        const auto require = [&](int index, const std::string& what) {
            if (index < 0 && problem.empty())
                problem = what + " is not declared in the generated code";
            return index;
        };
        for (const std::string& token : sim.tokenNames())
            tokens.push_back(require(plc.globalIndex(token), token));
        for (const std::string& variable : sim.variableNames())
            variables.push_back(require(plc.globalIndex(variable), variable));
        for (const std::string& step : sim.nestedSteps()) {
            Fb fb;
            fb.step = step;
            fb.instance = require(plc.instanceIndex(step), step);
            fb.complete = require(plc.memberIndex(fb.instance, "Complete"), step + ".Complete");
            fb.engine = sim.grafcetEngine(step);
            if (fb.engine) {
                if (!plc.runsBody(step) && problem.empty())
                    problem = "the code has no FUNCTION_BLOCK body for " + step;
                for (const NestedStep& nested : fb.engine->grafcet().steps) {
                    const std::string x = stepActivityName(nested.number);
                    fb.steps.emplace_back(nested.number, require(plc.memberIndex(fb.instance, x), step + "." + x));
                }
                const int unstable = plc.memberIndex(fb.instance, kUnstableName);
                if (fb.engine->grafcet().rule == EvolutionRule::UntilStable)
                    fb.unstable = require(unstable, step + ".Unstable");
                else if (unstable >= 0 && problem.empty())
                    problem = step + " declares Unstable under one evolution per scan";
                for (const std::string& output : fb.engine->outputNames())
                    fb.outputs.push_back(require(plc.memberIndex(fb.instance, output), step + "." + output));
                for (const NestedTimerState& timer : fb.engine->timers()) {
                    if (!plc.timer(step, timer.name) && problem.empty())
                        problem = step + "." + timer.name + " is not declared in the generated code";
                }
            }
            fbs.push_back(std::move(fb));
        }
    }
};

std::string boolText(bool value)
{
    return value ? "TRUE" : "FALSE";
}

// The first difference between the simulator and the interpreted code, empty when none.
std::string difference(const Simulator& sim, const sttest::StInterpreter& plc, const Probe& probe)
{
    if (!probe.problem.empty())
        return probe.problem;
    if (!plc.runtimeError().empty())
        return "interpreter: " + plc.runtimeError();
    if (sim.activeStepNumber() != plc.state())
        return "State: simulator " + std::to_string(sim.activeStepNumber()) + ", code " + std::to_string(plc.state());
    if (sim.entry() != plc.entry())
        return "Entry: simulator " + boolText(sim.entry());
    const std::vector<bool> tokens = sim.tokenValues();
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        if (tokens[i] != cond::isTrue(plc.globalAt(probe.tokens[i])))
            return "token " + sim.tokenNames()[i] + ": simulator " + boolText(tokens[i]);
    }
    for (const Probe::Fb& fb : probe.fbs) {
        const bool complete = sim.complete(fb.step);
        if (complete != cond::isTrue(plc.memberAt(fb.instance, fb.complete)))
            return fb.step + ".Complete: simulator " + boolText(complete);
        if (!fb.engine)
            continue;
        for (const auto& [number, slot] : fb.steps) {
            if (fb.engine->active(number) != cond::isTrue(plc.memberAt(fb.instance, slot)))
                return fb.step + ".X" + std::to_string(number) + ": simulator " + boolText(fb.engine->active(number));
        }
        if (fb.unstable >= 0 && fb.engine->unstable() != cond::isTrue(plc.memberAt(fb.instance, fb.unstable)))
            return fb.step + ".Unstable: simulator " + boolText(fb.engine->unstable());
        for (std::size_t o = 0; o < fb.outputs.size(); ++o) {
            if (fb.engine->output(o) != cond::isTrue(plc.memberAt(fb.instance, fb.outputs[o])))
                return fb.step + "." + fb.engine->outputNames()[o] + ": simulator " + boolText(fb.engine->output(o));
        }
        for (const NestedTimerState& timer : fb.engine->timers()) {
            const auto ton = plc.timer(fb.step, timer.name);
            if (ton->q != timer.done || ton->etMs != timer.elapsedMs)
                return fb.step + "." + timer.name + ": simulator Q " + boolText(timer.done) + " ET "
                    + std::to_string(timer.elapsedMs) + ", code Q " + boolText(ton->q) + " ET "
                    + std::to_string(ton->etMs);
        }
    }
    for (std::size_t i = 0; i < probe.variables.size(); ++i) {
        const cond::Value simulated = sim.variableValue(i);
        const cond::Value& interpreted = plc.globalAt(probe.variables[i]);
        if (simulated != interpreted)
            return "variable " + sim.variableNames()[i] + ": simulator " + cond::formatValue(simulated) + ", code "
                + cond::formatValue(interpreted);
    }
    return {};
}

// What a run exercised, so the test cannot pass by idling.
struct Coverage {
    int models = 0;
    int grafcets = 0;
    int nestedScans = 0;      // scans that call a nested GRAFCET's FB, not entering it
    int nestedEvolutions = 0; // scans in which some nested GRAFCET changed its situation without Initialization
    // In the scans that call a nested GRAFCET's FB:
    int unstable = 0;         // calls ending Unstable
    int timersDone = 0;       // its TONs with Q, summed
    int completes = 0;        // calls ending with Complete TRUE
};

void runBoth(const Model& model, std::uint32_t seed, int scans, Coverage& coverage)
{
    const Generated code = generate(model);
    sttest::StInterpreter plc(code.program, code.globals, code.functionBlocks);
    const std::string rule = model.settings().evolution == EvolutionRule::UntilStable ? "until stable"
                                                                                      : "one evolution per scan";
    INFO("seed " << seed << ", " << rule);
    if (!plc.error().empty())
        FAIL("the interpreter cannot read the generated code: " << plc.error() << "\n" << code.all());
    Simulator sim(model);
    REQUIRE(sim.tokenNames() == plc.tokenNames());
    REQUIRE(sim.nestedSteps() == plc.instances());
    ++coverage.models;
    for (const std::string& step : sim.nestedSteps())
        coverage.grafcets += sim.hasGrafcet(step) ? 1 : 0;

    // Inputs only. The GEMMA layer's change less often, so that the nested
    // GRAFCETs have scans to evolve in; those only they read change often.
    std::vector<std::pair<std::size_t, unsigned>> inputs; // index, 1 / probability of a change in a scan
    for (std::size_t i = 0; i < sim.variableNames().size(); ++i) {
        if (sim.variableKind(i) == VariableKind::Input)
            inputs.emplace_back(i, sim.variableNames()[i].rfind("Nested", 0) == 0 ? 2u : 8u);
    }
    std::mt19937 random(seed * 7919u + 17u);
    const Probe probe(sim, plc);
    const auto check = [&](int scan) {
        const std::string different = difference(sim, plc, probe);
        if (!different.empty())
            FAIL("scan " << scan << " (" << sim.simulatedTimeMs() << " ms): " << different << "\nReproduce: seed "
                         << seed << ", " << rule << ". The generated code:\n"
                         << code.all());
    };
    check(0);
    std::vector<std::vector<int>> before(sim.nestedSteps().size());
    for (int scan = 1; scan <= scans; ++scan) {
        for (const auto& [i, odds] : inputs) {
            if (random() % odds != 0)
                continue;
            const cond::Value value = randomValue(random, sim.variableType(i));
            REQUIRE(sim.setVariableAt(i, value));
            plc.setInput(sim.variableNames()[i], value);
        }
        const int stateBefore = sim.activeStepNumber();
        const bool entryBefore = sim.entry();
        for (std::size_t n = 0; n < before.size(); ++n)
            before[n] = sim.activeNestedSteps(sim.nestedSteps()[n]);
        sim.step();
        plc.advanceTime(sim.cycleTimeMs());
        plc.scan();
        check(scan);
        bool evolved = false;
        for (std::size_t n = 0; n < before.size(); ++n) {
            const std::string& step = sim.nestedSteps()[n];
            const NestedEngine* engine = sim.grafcetEngine(step);
            if (!engine)
                continue;
            if (sim.program().step(step)->number != stateBefore)
                continue; // not called in this scan
            if (!entryBefore) {
                ++coverage.nestedScans;
                if (before[n] != engine->activeSteps())
                    evolved = true;
            }
            coverage.unstable += engine->unstable() ? 1 : 0;
            coverage.completes += engine->complete() ? 1 : 0;
            for (const NestedTimerState& timer : engine->timers())
                coverage.timersDone += timer.done ? 1 : 0;
        }
        coverage.nestedEvolutions += evolved ? 1 : 0;
    }
}

Model withRule(const Model& model, EvolutionRule rule)
{
    Model copy(model);
    copy.setEvolutionRule(rule);
    return copy;
}

} // namespace

TEST_CASE("Nested GRAFCETs: the simulator agrees with the generated code on random models", "[simulation][nested]")
{
    // Under the sanitizers (ten times slower) every fifth model only.
    const std::uint32_t stride = kSanitized ? 5 : 1;
    Coverage coverage[2];
    int withoutGrafcet = 0;
    for (std::uint32_t seed = 1; seed <= 200; seed += stride) {
        Model model = samples::randomModel(seed);
        std::mt19937 random(seed);
        if (samples::addValidRandomNestedGrafcets(model, random) == 0)
            ++withoutGrafcet; // the checks found no error in it: randomModel's promise
        int r = 0;
        for (EvolutionRule rule : {EvolutionRule::OneEvolutionPerScan, EvolutionRule::UntilStable})
            runBoth(withRule(model, rule), seed, 150, coverage[r++]);
    }
    // What 200 models exercise (measured: about 16500 nested scans, 3900 and
    // 2200 nested evolutions, 390 and 200 TONs done, 4400 Complete, 2200
    // Unstable), with margin.
    const int scale = static_cast<int>(stride);
    for (const Coverage& c : coverage) {
        INFO("models " << c.models << ", GRAFCETs " << c.grafcets << ", nested scans " << c.nestedScans
                       << ", nested evolutions " << c.nestedEvolutions << ", Unstable " << c.unstable
                       << ", TONs done " << c.timersDone << ", Complete " << c.completes);
        CHECK(c.grafcets > 1000 / scale);
        CHECK(c.nestedScans > 10000 / scale);
        CHECK(c.nestedEvolutions > 1500 / scale);
        CHECK(c.timersDone > (kSanitized ? 8 : 100)); // the subset: about 19
        CHECK(c.completes > 2000 / scale);
    }
    CHECK(coverage[1].unstable > 1000 / scale);
    CHECK(coverage[0].unstable == 0);
    CHECK(withoutGrafcet * 10 < coverage[0].models); // measured: none
}

TEST_CASE("Nested GRAFCETs: the simulator agrees with the generated code on the drilling cell", "[simulation][nested]")
{
    const LoadedModel example = loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    REQUIRE(example.model);
    Coverage coverage;
    for (EvolutionRule rule : {EvolutionRule::OneEvolutionPerScan, EvolutionRule::UntilStable}) {
        for (std::uint32_t seed = 1; seed <= 4; ++seed)
            runBoth(withRule(*example.model, rule), seed, 500, coverage);
    }
    INFO("nested evolutions " << coverage.nestedEvolutions << ", TONs done " << coverage.timersDone);
    CHECK(coverage.nestedEvolutions > 100);
}

TEST_CASE("The ST interpreter runs the function blocks the generator writes", "[simulation][nested]")
{
    const LoadedModel example = loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    REQUIRE(example.model);
    const Generated code = generate(*example.model);
    sttest::StInterpreter plc(code.program, code.globals, code.functionBlocks);
    REQUIRE(plc.error().empty());
    REQUIRE(plc.runsBody("F1"));
    CHECK(plc.member("F1", "X1"));
    CHECK(plc.timer("F1", "GG_T5_2000ms"));
    const std::int64_t before = plc.statementsRun();
    plc.scan();
    CHECK(plc.statementsRun() > before);
    CHECK(plc.runtimeError().empty());

    // What it cannot read is an error, not a silent no-op.
    const auto refused = [&](const std::string& from, const std::string& to) {
        std::vector<std::string> blocks = code.functionBlocks;
        for (std::string& fb : blocks) {
            const std::size_t at = fb.find(from);
            if (at != std::string::npos)
                fb.replace(at, from.size(), to);
        }
        return !sttest::StInterpreter(code.program, code.globals, blocks).error().empty();
    };
    CHECK(refused("GG_T5_2000ms(IN := X5, PT := T#2s);", "WHILE X5 DO X5 := FALSE; END_WHILE;"));
    CHECK(refused("GG_Fire1 := X1", "GG_Fire1 := Undeclared"));
    CHECK(refused("PT := T#2s", "PT := T#2x"));
    CHECK(refused("    PartPresent : BOOL;\n", ""));  // read without VAR_EXTERNAL
    CHECK(refused("GG_T5_2000ms.Q", "GG_T5_2000ms.R"));
}

} // namespace test_nestedagreement
