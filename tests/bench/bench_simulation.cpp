#include "benchrepeats.h"
#include "modelfactory.h"

#include "core/formats/modelfiles.h"
#include "core/machine/machineloop.h"
#include "core/simulation/simulator.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <cstdint>
#include <iostream>
#include <random>
#include <vector>

namespace {

constexpr int kScansPerRun = 100'000;

// A fixed random script of input changes: one BOOL flips every scan and the
// temperature moves every eighth scan, so the bottling machine wanders
// through its states (and its tokens) instead of idling in one.
struct InputScript {
    struct Change {
        std::size_t variable;
        core::cond::Value value;
    };
    std::vector<Change> changes;

    explicit InputScript(const core::Simulator& simulator)
    {
        std::mt19937 random(2026);
        std::vector<std::size_t> bools;
        std::size_t temperature = 0;
        for (std::size_t i = 0; i < simulator.variableNames().size(); ++i) {
            if (simulator.variableType(i) == core::IecType::Bool)
                bools.push_back(i);
            if (simulator.variableNames()[i] == "Temperature")
                temperature = i;
        }
        for (int i = 0; i < 4096; ++i) {
            if (i % 8 == 7)
                changes.push_back({temperature, 20.0 + static_cast<double>(random() % 40)});
            else
                changes.push_back({bools[random() % bools.size()], random() % 2 == 0});
        }
    }
};

// Fast path: run(1) builds no record.
std::int64_t runScans(core::Simulator& simulator, const InputScript& script)
{
    std::int64_t fired = 0;
    std::size_t next = 0;
    for (int scan = 0; scan < kScansPerRun; ++scan) {
        const InputScript::Change& change = script.changes[next];
        next = (next + 1) % script.changes.size();
        simulator.setVariableAt(change.variable, change.value);
        const int before = simulator.activeStepNumber();
        simulator.run(1);
        fired += simulator.activeStepNumber() != before ? 1 : 0;
    }
    return fired;
}

// The editor's path: step() returns a full ScanRecord every scan.
std::int64_t stepScans(core::Simulator& simulator, const InputScript& script)
{
    std::int64_t fired = 0;
    std::size_t next = 0;
    for (int scan = 0; scan < kScansPerRun; ++scan) {
        const InputScript::Change& change = script.changes[next];
        next = (next + 1) % script.changes.size();
        simulator.setVariableAt(change.variable, change.value);
        fired += simulator.step().fired.empty() ? 0 : 1;
    }
    return fired;
}

template <typename Run>
void reportScansPerSecond(const char* what, core::Simulator& simulator, const InputScript& script, Run run)
{
    const int runs = benchRepeats(10);
    const auto start = std::chrono::steady_clock::now();
    std::int64_t fired = 0;
    for (int i = 0; i < runs; ++i)
        fired += run(simulator, script);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "simulation, " << what << ": " << static_cast<std::int64_t>(runs * kScansPerRun / seconds)
              << " scans per second on the realistic model (" << fired << " transitions fired in "
              << runs * kScansPerRun << " scans)\n";
}

} // namespace

TEST_CASE("Simulation of the realistic model (target >= 1,000,000 scans/s)", "[benchmark][simulation]")
{
    core::Simulator simulator(factory::realisticModel());
    const InputScript script(simulator);
    reportScansPerSecond("run()", simulator, script, runScans);
    reportScansPerSecond("step() with records", simulator, script, stepScans);
    BENCHMARK("100,000 scans, changing inputs, run()") { return runScans(simulator, script); };
    BENCHMARK("100,000 scans, changing inputs, step() with records") { return stepScans(simulator, script); };
}

// Issue 35: the drilling cell in closed loop with its machine (core/machine/
// machineloop.h). The operator presses Start once; the machine then moves
// the clamp and the drill head, feeds and carries the parts, and the program
// runs its cycle on the sensors the machine sets, part after part until the
// magazine is empty.
TEST_CASE("Closed-loop simulation of the drilling cell (target >= 1,000,000 scans/s)",
          "[benchmark][simulation][machine]")
{
    const core::LoadedModel loaded = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    REQUIRE(loaded.ok());
    REQUIRE_FALSE(loaded.model->machine().empty());
    core::Simulator simulator(*loaded.model);
    core::machine::MachineLoop loop(simulator, loaded.model->machine());
    auto runFromStart = [&] {
        loop.reset();
        REQUIRE(simulator.setVariable("StartButton", true).ok);
        loop.run(2);
        REQUIRE(simulator.setVariable("StartButton", false).ok);
        loop.run(kScansPerRun - 2);
        return simulator.variableValue(static_cast<std::size_t>(simulator.variableIndex("PartCount")));
    };

    const int runs = benchRepeats(10);
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < runs; ++i)
        runFromStart();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const core::cond::Value parts = runFromStart();
    std::cout << "closed-loop simulation, drilling cell: " << static_cast<std::int64_t>(runs * kScansPerRun / seconds)
              << " scans per second (" << core::cond::formatValue(parts) << " parts in " << kScansPerRun << " scans)\n";
    BENCHMARK("100,000 scans of the drilling cell with its machine") { return runFromStart(); };
}
