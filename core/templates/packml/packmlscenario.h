#pragma once

// Scenarios on a PackML model (docs/packml.md, Simulation): the scenario
// language of core/simulation/scenario.h with
//
//   at 5: command Start     # CntrlCmd := 2 with a rising edge of CmdChangeRequest
//   at 9: mode Manual       # UnitMode := 3 with a rising edge of UnitModeChangeRequest
//   at 9: expect state Idle
//   at 9: expect mode Manual
//   at 9: expect fired Stopped-Reset->Idle
//   at 3: set complete Production_Resetting = FALSE   # a manual SC (auto: the skeleton's)
//
// and the `set` and `expect variable` lines of every scenario. A command or
// a mode goes through the PackTags request for exactly one scan: the request
// is TRUE before the scan and FALSE after it, so the scan right after one
// cannot issue another (EdgeTooSoon). Names are PackTags names, compared
// ignoring case; a mode or a state may also be given by its number.

#include "core/simulation/scenario.h"
#include "core/templates/packml/packmlsimulator.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace core::packml {

// Names and values against the simulator's program: unknown variables,
// commands, modes and states, sets of non-inputs, values not of the
// variable's type, two commands (modes) in one scan or in two scans in a
// row, `set complete` of an unknown instance or of one running a GRAFCET,
// and the GEMMA-only lines (steps, tokens, expect complete, Entry, nested).
std::vector<ScenarioError> validatePackmlScenario(const Scenario& scenario, const PackmlSimulator& simulator);

struct PackmlScenarioFailure {
    enum class Kind {
        CannotApply,      // subject: what was set; detail: why (English, from the simulator)
        WrongState,       // expected, actual: state names
        WrongMode,        // expected, actual: mode names
        WrongVariable,    // subject: the variable as declared; expected: as written; actual
        NothingFired,     // expected: the transition
        WrongFiring,      // expected, actual: transitions ("Idle-Start->Execute")
        UnexpectedFiring, // actual: the transition that fired
    };
    std::int64_t scan = 0;
    int line = 0;
    Kind kind = Kind::WrongState;
    std::string subject;
    std::string expected;
    std::string actual;
    std::string detail;

    friend bool operator==(const PackmlScenarioFailure&, const PackmlScenarioFailure&) = default;
};

// "scan 9: expected state Execute, the state is Held".
std::string toText(const PackmlScenarioFailure& failure);

// Plays a validated scenario one scan at a time; keeps references to both.
class PackmlScenarioRunner {
public:
    PackmlScenarioRunner(const Scenario& scenario, PackmlSimulator& simulator);

    PackmlScanRecord step();
    const std::vector<PackmlScenarioFailure>& lastFailures() const { return m_lastFailures; }
    const std::vector<PackmlScenarioFailure>& failures() const { return m_failures; }

private:
    void apply(const ScenarioAction& action);
    void setInput(const ScenarioAction& action, std::string_view name, const std::string& value);
    void setManualComplete(const ScenarioAction& action);
    void check(const ScenarioAction& action, const PackmlScanRecord& record);

    const Scenario& m_scenario;
    PackmlSimulator& m_simulator;
    std::map<std::int64_t, std::vector<const ScenarioAction*>> m_byScan;
    std::vector<PackmlScenarioFailure> m_failures;
    std::vector<PackmlScenarioFailure> m_lastFailures;
};

struct PackmlScenarioRunResult {
    std::vector<PackmlScanRecord> records; // the scan that faulted included
    std::vector<PackmlScenarioFailure> failures;
    // The run-time fault that stopped the run (its scan's expectations are
    // not checked, no later scan runs).
    std::optional<SimulationFault> fault;
    bool passed() const { return failures.empty() && !fault; }
};

// Resets the simulator and runs `scans` scans (0: to the scenario's last scan).
PackmlScenarioRunResult runPackmlScenario(const Scenario& scenario, PackmlSimulator& simulator, std::int64_t scans = 0);

// Name lookups shared with the command line: PackTags names ignoring case,
// a mode or a state also by its number.
std::optional<Command> findCommandNamed(std::string_view name, Edition edition);
std::optional<int> findModeNamed(const PackmlProgram& program, std::string_view name);
std::optional<State> findStateNamed(std::string_view name);
std::optional<int> findInstanceNamed(const PackmlProgram& program, std::string_view name); // index in instances

} // namespace core::packml
