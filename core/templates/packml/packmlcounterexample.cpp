#include "core/templates/packml/packmlcounterexample.h"

#include "core/templates/packml/packmlscenario.h"

namespace core::packml {

Counterexample writeCounterexample(const PackmlSimulator& start, const std::vector<InputChoice>& scans,
                                   const std::string& title, const std::string& expectedModeName)
{
    PackmlSimulator simulator = start;
    simulator.reset();
    std::string text = "# " + title + "\n";
    for (std::size_t scan = 0; scan < scans.size(); ++scan) {
        std::string sets;
        for (const InputValue& input : scans[scan]) {
            if (simulator.value(input.slot) == input.value)
                continue; // inputs keep their value from scan to scan
            sets += (sets.empty() ? "" : ", ") + simulator.program().variables[static_cast<std::size_t>(input.slot)].name
                    + " = " + cond::formatValue(input.value);
        }
        if (!sets.empty())
            text += "at " + std::to_string(scan + 1) + ": set " + sets + "\n";
        for (const InputValue& input : scans[scan])
            simulator.setInput(input.slot, input.value);
        simulator.scan();
    }
    const std::string last = "at " + std::to_string(scans.size()) + ": ";
    if (!scans.empty()) {
        text += last + "expect state " + std::string(stateName(simulator.state())) + "\n";
        text += last + "expect mode " + expectedModeName + "\n";
    }
    Counterexample counterexample;
    counterexample.text = text;
    counterexample.scenario = parseScenario(text).scenario;
    counterexample.scans = static_cast<std::int64_t>(scans.size());
    return counterexample;
}

std::optional<Replay> replay(const PackmlSimulator& simulator, const Counterexample& counterexample)
{
    const ScenarioParseResult parsed = parseScenario(counterexample.text);
    if (!parsed.ok() || counterexample.scans < 1)
        return std::nullopt;
    PackmlSimulator run = simulator;
    if (!validatePackmlScenario(parsed.scenario, run).empty())
        return std::nullopt;
    run.reset();
    for (std::size_t i = 0; i < run.program().instances.size(); ++i)
        if (run.program().instances[i].isSkeleton())
            run.setManualComplete(static_cast<int>(i), std::nullopt);
    PackmlScenarioRunner runner(parsed.scenario, run);
    PauseGhost ghost;
    for (std::int64_t scan = 1; scan <= counterexample.scans; ++scan) {
        if (run.fault())
            return std::nullopt;
        PackmlSimulator before = run;
        PackmlScanRecord record = runner.step();
        ScanFacts facts = observeScan(before, run, std::move(record));
        if (scan == counterexample.scans) {
            if (!runner.failures().empty())
                return std::nullopt;
            return Replay{std::move(before), run, ghost, std::move(facts)};
        }
        ghost = nextGhost(ghost, facts);
    }
    return std::nullopt;
}

} // namespace core::packml
