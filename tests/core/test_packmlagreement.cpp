#include <catch2/catch.hpp>

#include "core/codegen/stgenerator.h"
#include "core/templates/packml/packmlprogram.h"
#include "core/templates/packml/packmlsimulator.h"
#include "packmlcapper.h"
#include "packmlsamples.h"
#include "generatedcode.h"
#include "stinterpreter.h"

#include <functional>
#include <random>
#include <string>
#include <vector>

namespace test_packmlagreement {

using namespace core;
using namespace core::packml;

// Issue 34's proof: on random PackML models (random modes, disabled states,
// both editions, random GRAFCETs in acting states, random command and mode
// schedules) the simulator and the generated Structured Text, interpreted
// statement by statement, agree on State, Mode, Entry, Resume, every
// variable (outputs, PackTags, memories), and every instance's nested steps
// and Complete at every scan. Mutations of the generated code must be caught,
// so the comparison cannot pass by looking at nothing.

namespace {

using sttest::kSanitized;
using Generated = sttest::GeneratedCode;

Generated generate(const Model& model)
{
    return sttest::generateIec(model);
}

std::string boolText(bool value)
{
    return value ? "TRUE" : "FALSE";
}

// Where the interpreter keeps what the simulator has, looked up once.
struct Probe {
    int state = -1, mode = -1, entry = -1, resume = -1;
    std::vector<int> variables; // interpreter global slot per simulator slot
    struct Instance {
        int index = -1; // the interpreter's instance
        int complete = -1;
        std::vector<std::pair<int, int>> steps; // nested step number, X<n> member
    };
    std::vector<Instance> instances; // by PackmlProgram::instances
    std::string problem;

    Probe(const PackmlSimulator& sim, const sttest::StInterpreter& plc)
    {
        const auto require = [&](int index, const std::string& what) {
            if (index < 0 && problem.empty())
                problem = what + " is not declared in the generated code";
            return index;
        };
        state = require(plc.globalIndex("State"), "State");
        mode = require(plc.globalIndex("Mode"), "Mode");
        entry = require(plc.globalIndex("Entry"), "Entry");
        resume = require(plc.globalIndex("Resume"), "Resume");
        for (const Variable& variable : sim.program().variables)
            variables.push_back(require(plc.globalIndex(variable.name), variable.name));
        const std::vector<ProgramInstance>& programInstances = sim.program().instances;
        for (std::size_t i = 0; i < programInstances.size(); ++i) {
            Instance probe;
            const std::string& name = programInstances[i].name;
            probe.index = require(plc.instanceIndex(name), name);
            probe.complete = require(plc.memberIndex(probe.index, "Complete"), name + ".Complete");
            if (const NestedEngine* engine = sim.engine(static_cast<int>(i))) {
                for (const NestedStep& step : engine->grafcet().steps) {
                    const std::string x = stepActivityName(step.number);
                    probe.steps.emplace_back(step.number, require(plc.memberIndex(probe.index, x), name + "." + x));
                }
            }
            instances.push_back(std::move(probe));
        }
    }
};

std::string difference(const PackmlSimulator& sim, const sttest::StInterpreter& plc, const Probe& probe)
{
    if (!probe.problem.empty())
        return probe.problem;
    if (!plc.runtimeError().empty())
        return "interpreter: " + plc.runtimeError();
    const auto number = [&](int slot) { return std::get<std::int64_t>(plc.globalAt(slot)); };
    if (static_cast<int>(sim.state()) != number(probe.state))
        return "State: simulator " + std::to_string(static_cast<int>(sim.state())) + ", code "
            + std::to_string(number(probe.state));
    if (sim.mode() != number(probe.mode))
        return "Mode: simulator " + std::to_string(sim.mode()) + ", code " + std::to_string(number(probe.mode));
    if (sim.entry() != cond::isTrue(plc.globalAt(probe.entry)))
        return "Entry: simulator " + boolText(sim.entry());
    if (sim.resume() != cond::isTrue(plc.globalAt(probe.resume)))
        return "Resume: simulator " + boolText(sim.resume());
    for (std::size_t i = 0; i < probe.instances.size(); ++i) {
        const Probe::Instance& instance = probe.instances[i];
        const std::string& name = sim.program().instances[i].name;
        if (sim.complete(static_cast<int>(i)) != cond::isTrue(plc.memberAt(instance.index, instance.complete)))
            return name + ".Complete: simulator " + boolText(sim.complete(static_cast<int>(i)));
        const NestedEngine* engine = sim.engine(static_cast<int>(i));
        for (const auto& [step, member] : instance.steps) {
            if (engine->active(step) != cond::isTrue(plc.memberAt(instance.index, member)))
                return name + ".X" + std::to_string(step) + ": simulator " + boolText(engine->active(step));
        }
    }
    for (std::size_t slot = 0; slot < probe.variables.size(); ++slot) {
        const cond::Value simulated = sim.value(static_cast<int>(slot));
        const cond::Value& interpreted = plc.globalAt(probe.variables[slot]);
        if (simulated != interpreted)
            return "variable " + sim.program().variables[slot].name + ": simulator " + cond::formatValue(simulated)
                + ", code " + cond::formatValue(interpreted);
    }
    return {};
}

// One random input change: commands and requests mostly through their
// inputs, sometimes through CntrlCmd / UnitMode and their change requests.
cond::Value randomInput(std::mt19937& random, const Variable& variable, const PackmlProgram& program)
{
    if (variable.name == "CntrlCmd")
        return static_cast<std::int64_t>(random() % 12); // 0..11: none, the commands, one that is none
    if (variable.name == "UnitMode" || variable.name == "ModeKey") {
        const std::size_t index = random() % (program.modes.size() + 1);
        return static_cast<std::int64_t>(index < program.modes.size() ? program.modes[index].number : 30);
    }
    if (variable.type == IecType::Bool)
        return random() % 2 == 0;
    return static_cast<std::int64_t>(random() % 4);
}

// 1 / the probability that an input changes in a scan: the nested
// GRAFCETs' inputs often, so that they evolve; Abort, Stop and the inputs
// that issue any command rarely, so that the unit gets to Execute and
// through the Hold and Suspend loops between them.
unsigned changeOdds(const std::string& name)
{
    if (name.rfind("Nested", 0) == 0)
        return 2;
    for (const char* rare : {"Cmd_Abort", "Cmd_Stop", "AnyCommand", "CmdChangeRequest"})
        if (name == rare)
            return 40;
    for (const char* modes : {"UnitModeChangeRequest", "ModeKey", "UnitMode"})
        if (name == modes)
            return 12;
    return 5;
}

// What a run exercised, so the test cannot pass by idling.
struct Coverage {
    int models = 0;
    int fired = 0;
    int skipped = 0;      // transitions fired past a disabled state
    int modeChanges = 0;
    int resumes = 0;
    int calls = 0;        // scans calling an instance that runs a GRAFCET
    int completes = 0;    // SC transitions fired
    int dropped = 0;
};

using Mutation = std::function<std::string(const std::string&)>;

// Runs the simulator and the code side by side; the first difference, or
// empty when they agree on every scan.
std::string runBoth(const Model& model, std::uint32_t seed, int scans, Coverage& coverage,
                    const Mutation& mutate = {})
{
    Generated code = generate(model);
    if (mutate)
        code.program = mutate(code.program);
    sttest::StInterpreter plc(code.program, code.globals, code.functionBlocks);
    if (!plc.error().empty())
        return "the interpreter cannot read the generated code: " + plc.error() + "\n" + code.all();
    PackmlSimulator sim(model);
    const PackmlProgram& program = sim.program();
    ++coverage.models;
    std::vector<int> inputs; // simulator slots of the inputs
    for (std::size_t slot = 0; slot < program.variables.size(); ++slot) {
        const Variable& variable = program.variables[slot];
        if (variable.kind == VariableKind::Input)
            inputs.push_back(static_cast<int>(slot));
    }
    std::mt19937 random(seed * 7919u + 17u);
    const Probe probe(sim, plc);
    const int cycleMs = model.settings().cycleTimeMs;
    const auto check = [&](int scan) -> std::string {
        const std::string different = difference(sim, plc, probe);
        return different.empty() ? different
                                 : "scan " + std::to_string(scan) + ": " + different + " (seed "
                + std::to_string(seed) + ")\nThe generated code:\n" + code.all();
    };
    if (std::string different = check(0); !different.empty())
        return different;
    for (int scan = 1; scan <= scans; ++scan) {
        for (const int slot : inputs) {
            const Variable& variable = program.variables[static_cast<std::size_t>(slot)];
            if (random() % changeOdds(variable.name) != 0)
                continue;
            const cond::Value value = randomInput(random, variable, program);
            if (!sim.setInput(variable.name, value))
                return "the simulator refuses " + variable.name + " = " + cond::formatValue(value);
            plc.setInput(variable.name, value);
        }
        const PackmlScanRecord record = sim.scan();
        plc.advanceTime(cycleMs);
        plc.scan();
        if (std::string different = check(scan); !different.empty())
            return different;
        coverage.fired += record.fired ? 1 : 0;
        coverage.skipped += record.fired && record.fired->destination.skipped ? 1 : 0;
        coverage.completes += record.fired && record.fired->transition.trigger == Trigger::StateComplete ? 1 : 0;
        coverage.modeChanges += record.modeChanged() ? 1 : 0;
        coverage.resumes += record.resumed ? 1 : 0;
        coverage.calls += record.calledInstance >= 0 && sim.engine(record.calledInstance) ? 1 : 0;
        coverage.dropped += static_cast<int>(record.dropped.size());
    }
    return {};
}

// Replaces the first occurrence of `from` by `to`; empty when absent.
std::string replaced(const std::string& text, const std::string& from, const std::string& to)
{
    const std::size_t at = text.find(from);
    if (at == std::string::npos)
        return {};
    return text.substr(0, at) + to + text.substr(at + from.size());
}

} // namespace

TEST_CASE("PackML: the simulator agrees with the generated code on random models", "[packml-agreement]")
{
    // Under the sanitizers (ten times slower) every fifth model only.
    const std::uint32_t stride = kSanitized ? 5 : 1;
    Coverage coverage;
    for (std::uint32_t seed = 1; seed <= 150; seed += stride) {
        const Model model = samples::randomPackmlModel(seed);
        const std::string different = runBoth(model, seed, 400, coverage);
        if (!different.empty())
            FAIL(different);
    }
    // What 150 models of 400 scans exercise (measured: 2,500 transitions fired,
    // 220 past a skipped state, 1,030 on an SC, 200 mode changes, 69 resumes of
    // Execute, 30,600 scans calling a GRAFCET, 20,200 dropped events), with margin.
    const int scale = static_cast<int>(stride);
    CHECK(coverage.models * scale >= 150);
    CHECK(coverage.fired * scale > 1500);
    CHECK(coverage.skipped * scale > 130);
    CHECK(coverage.completes * scale > 600);
    CHECK(coverage.modeChanges * scale > 120);
    CHECK(coverage.resumes * scale > 35);
    CHECK(coverage.calls * scale > 18000);
    CHECK(coverage.dropped * scale > 12000);
}

TEST_CASE("PackML agreement: the Capper of spec §6.6 under random schedules", "[packml-agreement]")
{
    const auto capper = packmltests::loadCapper();
    Coverage coverage;
    for (std::uint32_t seed = 1; seed <= 20; ++seed) {
        const std::string different = runBoth(*capper, seed, 300, coverage);
        if (!different.empty())
            FAIL(different);
    }
    CHECK(coverage.resumes > 0);
    CHECK(coverage.modeChanges > 0);
}

TEST_CASE("PackML agreement catches a wrong generated program", "[packml-agreement]")
{
    // Each mutation breaks one rule of spec §6.3-§6.5 in the generated
    // PROGRAM; on the random models the comparison must see it.
    const std::vector<std::pair<std::string, Mutation>> mutations{
        {"Execute resumes never", [](const std::string& text) {
             return replaced(text, "Resume := TRUE;", "Resume := FALSE;");
         }},
        {"CntrlCmd 9 issues Abort", [](const std::string& text) {
             return replaced(text, "(Trig_CmdChange.Q AND CntrlCmd = 8)", "(Trig_CmdChange.Q AND CntrlCmd = 9)");
         }},
        {"continuous outputs in the entering scan", [](const std::string& text) {
             return replaced(text, " AND NOT Entry AND ", " AND ");
         }},
        {"the status copies the state before the scan", [](const std::string& text) {
             return replaced(text, "StateCurrent := State;", "StateCurrent := StateCurrent;");
         }},
        {"UnitModeChangeRequest is ignored", [](const std::string& text) {
             return replaced(text, "Trig_ModeChange(CLK := UnitModeChangeRequest);", "Trig_ModeChange(CLK := FALSE);");
         }},
    };
    for (const auto& [what, mutation] : mutations) {
        INFO(what);
        bool applied = false;
        bool caught = false;
        Coverage coverage;
        for (std::uint32_t seed = 1; seed <= 60 && !caught; ++seed) {
            const Model model = samples::randomPackmlModel(seed);
            const Generated code = generate(model);
            if (mutation(code.program).empty())
                continue; // the mutated text is not in this model's program
            applied = true;
            caught = !runBoth(model, seed, 200, coverage, mutation).empty();
        }
        CHECK(applied);
        CHECK(caught);
    }
}

} // namespace test_packmlagreement
