#pragma once

// Simulation scenarios: a line-oriented text that says which inputs change
// at which scan and what the GEMMA program must do (docs/simulation.md).
//
//   # Filling machine: start, then stop
//   at 1: set Start = TRUE, AutoMode = TRUE
//   at 2: set Start = FALSE
//   at 3: expect step F1
//   at 3: expect fired A1->F1
//   at 5: set complete F1 = FALSE     # F1's Complete becomes manual, FALSE
//   at 6: expect token Stop_F1_2_MEM = TRUE
//   at 9: set complete F1 = auto      # back to the skeleton FB's behaviour
//   at 12: fault Clamped stuck FALSE  # closed loop only: a sensor fault
//
// A PackML model's scenario (core/templates/packml/packmlscenario.h) also
// has `at 5: command Start`, `at 9: mode Manual`, `expect state Execute`
// and `expect mode Manual`, and no steps, tokens or Complete.
//
// Scans are numbered from 1, as Simulator and `ggstudio-cli simulate` number
// them. `at N: set ...` applies before scan N runs (scan N reads the values);
// `at N: expect ...` is checked after scan N. Keywords are case-insensitive,
// `#` starts a comment.

#include "core/machine/fault.h"
#include "core/simulation/scenarioerror.h"
#include "core/simulation/simulator.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace core {

namespace machine {
class MachineLoop;
}

struct ScenarioAction {
    enum class Kind {
        SetVariable,    // set NAME = VALUE
        SetComplete,    // set complete STEP = TRUE|FALSE (Manual mode with that value)
        SetCompleteAuto, // set complete STEP = auto (Automatic mode)
        Command,        // command NAME (PackML: CntrlCmd with a rising edge of CmdChangeRequest)
        Mode,           // mode NAME (PackML: UnitMode with a rising edge of UnitModeChangeRequest)
        Fault,          // fault TARGET stuck TRUE|FALSE|flicker|jam|clear (closed loop; value: machine::faultKindText)
        ExpectStep,     // expect step STEP
        ExpectFired,    // expect fired TRANSITION
        ExpectNoFiring, // expect fired none
        ExpectToken,    // expect token TOKEN = TRUE|FALSE
        ExpectVariable, // expect variable NAME = VALUE
        ExpectEntry,    // expect entry = TRUE|FALSE
        ExpectComplete, // expect complete STEP = TRUE|FALSE
        ExpectNestedSteps, // expect nested STEP steps 6, 8, 10 (value: "6, 8, 10", ascending)
        ExpectUnstable,    // expect nested STEP unstable = TRUE|FALSE
        ExpectState,       // expect state NAME (PackML)
        ExpectMode,        // expect mode NAME (PackML)
    };
    Kind kind = Kind::SetVariable;
    std::int64_t scan = 1;
    std::string name;  // variable, step id, transition id or token name, as written
    std::string value; // the value as written ("TRUE", "-3", "1.5"); empty when none
    int line = 0;      // 1-based, of the action
    int column = 0;    // 1-based, of the name (of the keyword when there is no name)
    int valueColumn = 0;

    bool isExpectation() const { return kind >= Kind::ExpectStep; }
};

// The highest scan a scenario may name, and the most scans `simulate --scans`
// runs: every run is bounded (10,000,000 scans is 55 hours of a 20 ms cycle
// and takes seconds to simulate; four billion would print gigabytes).
inline constexpr std::int64_t kMaxScenarioScan = 10'000'000;

struct Scenario {
    std::string fileName; // for messages; may be empty
    std::vector<ScenarioAction> actions; // in file order

    // The highest scan an action names; 0 when there is none.
    std::int64_t lastScan() const;
};

struct ScenarioParseResult {
    Scenario scenario;
    std::vector<ScenarioError> errors; // every malformed line, in order

    bool ok() const { return errors.empty(); }
};

// How a scenario line spells the action: "command", "expect state".
std::string_view scenarioKeyword(ScenarioAction::Kind kind);

// Syntax only: names are not looked up (see validateScenario).
ScenarioParseResult parseScenario(std::string_view text, std::string fileName = {});

// Whether a scenario's fault lines are refused (open loop: no machine to
// fault) or left to validateClosedLoopScenario (core/machine/closedloopscenario.h).
enum class FaultLines { Refused, CheckedByMachine };

// Names and values against the program the simulator runs: unknown or hidden
// variables, steps, transitions and tokens, `complete` on a step without
// nested behaviour, values that are not of the variable's type; fault lines
// as `faults` says.
std::vector<ScenarioError> validateScenario(const Scenario& scenario, const Simulator& simulator,
                                            FaultLines faults = FaultLines::Refused);

// The fault of a `fault` action (its name and value); nullopt for another action.
std::optional<machine::Fault> scenarioFault(const ScenarioAction& action);

// An expectation that did not hold, or a set that could not be applied, as
// data: the editor words it in the UI language, toText() in English. Names
// and values are IEC text.
struct ScenarioFailure {
    enum class Kind {
        CannotApply,      // subject: the name set; detail: why (English, from the simulator)
        WrongStep,        // expected: the step; actual: the active step
        NoVisibleStep,    // expected: the step; actual: the value of State, which names no visible step
        NothingFired,     // expected: the transition; none fired
        WrongFiring,      // expected: the transition; actual: the one that fired
        UnexpectedFiring, // none expected; actual: the one that fired
        WrongToken,       // subject: the token; expected, actual: TRUE/FALSE
        WrongVariable,    // subject: the variable as declared; expected: as written; actual
        UnknownVariable,  // subject: the name as written
        WrongEntry,       // expected, actual: TRUE/FALSE
        WrongComplete,    // subject: the step; expected, actual: TRUE/FALSE
        WrongNestedSteps, // subject: the step; expected, actual: "6, 8, 10" ("none" for no step)
        WrongUnstable,    // subject: the step; expected, actual: TRUE/FALSE
    };
    std::int64_t scan = 0;
    int line = 0; // of the action in the scenario
    Kind kind = Kind::WrongStep;
    std::string subject;
    std::string expected;
    std::string actual;
    std::string detail;

    friend bool operator==(const ScenarioFailure&, const ScenarioFailure&) = default;
};

// "scan 3: expected step F1, active step is A1".
std::string toText(const ScenarioFailure& failure);

// Plays a scenario on a simulator one scan at a time (the editor steps it,
// the command line runs it). Scan numbers are the simulator's: the next scan
// is simulator.scanCount() + 1. The scenario must have passed
// validateScenario; actions with unknown names are reported as failures.
// The runner keeps references: the scenario and the simulator must outlive it.
class ScenarioRunner {
public:
    ScenarioRunner(const Scenario& scenario, Simulator& simulator);
    // In closed loop: each step() runs the loop's simulator, checks the
    // scan's expectations (so they see what the scan read), then runs the
    // machine's cycle. The loop must outlive the runner.
    ScenarioRunner(const Scenario& scenario, machine::MachineLoop& loop);

    // Applies the sets of the next scan, runs it, checks its expectations.
    ScanRecord step();
    // In closed loop: the next step() runs no machine cycle after its scan,
    // so the simulator keeps the sensors that scan read (a replay's last
    // scan, core/verification/closedloopreplay.h).
    void skipNextMachineCycle() { m_skipCycle = true; }
    // Failures of the last step() only.
    const std::vector<ScenarioFailure>& lastFailures() const { return m_lastFailures; }
    // Every failure so far.
    const std::vector<ScenarioFailure>& failures() const { return m_failures; }

private:
    void apply(const ScenarioAction& action);
    Status applyFault(const ScenarioAction& action);
    void check(const ScenarioAction& action, const ScanRecord& record);

    const Scenario& m_scenario;
    Simulator& m_simulator;
    machine::MachineLoop* m_loop = nullptr;
    bool m_skipCycle = false;
    std::map<std::int64_t, std::vector<const ScenarioAction*>> m_byScan;
    std::vector<ScenarioFailure> m_failures;
    std::vector<ScenarioFailure> m_lastFailures;
};

struct ScenarioRunResult {
    std::vector<ScanRecord> records; // one per scan run, the one that faulted included
    std::vector<ScenarioFailure> failures;
    // The run-time fault that stopped the run before its last scan (its
    // scan's expectations are not checked, no later scan runs).
    std::optional<SimulationFault> fault;

    bool passed() const { return failures.empty() && !fault; }
};

// Resets the simulator and runs `scans` scans (0: the scenario's last scan).
ScenarioRunResult runScenario(const Scenario& scenario, Simulator& simulator, std::int64_t scans = 0);
// The same in closed loop: resets the loop (the simulator and the machine).
ScenarioRunResult runScenario(const Scenario& scenario, machine::MachineLoop& loop, std::int64_t scans = 0);

// --- Writing: "record the session as a scenario file" -----------------------

// What the user changed before one scan.
struct RecordedScan {
    std::int64_t scan = 1;
    std::vector<InputChange> inputs;
    struct CompleteSetting {
        std::string stepId;
        std::optional<bool> manualValue; // nullopt: back to Automatic
    };
    std::vector<CompleteSetting> completes;
    std::vector<machine::Fault> faults; // injected before the scan (closed loop)
};

struct ScenarioRecording {
    std::string title;                 // a leading `#` comment when not empty (line breaks kept as comment lines)
    std::vector<RecordedScan> changes; // by scan
    // Optional: what happened, so replaying the file checks the session
    // still behaves the same. After each record's scan it writes `expect
    // fired` and `expect step` when a transition fired, `expect variable`
    // for each output the scan changed (ScanRecord::changedOutputs), and,
    // when nestedSteps names the GRAFCETs of ScanRecord::nestedActive,
    // `expect nested S steps ...` for each GRAFCET whose situation differs
    // from the previous record's (the first record: from none) and `expect
    // nested S unstable = ...` when its Unstable differs (from FALSE at
    // first). So the records must hold every scan in which a situation or an
    // Unstable changed (SimulationSession keeps them).
    std::vector<ScanRecord> records;
    // Simulator::nestedSteps(): which GRAFCET each record's nestedActive and
    // unstable entry belongs to; empty: no nested expectations.
    std::vector<std::string> nestedSteps;
};

// True when the scan did something a recording writes an expectation for:
// it fired, changed an output, or changed a nested situation or Unstable
// since `previous` (nullptr for the first scan).
bool recordWorthKeeping(const ScanRecord& record, const ScanRecord* previous);

// Scenario text that parseScenario reads back to the same actions.
std::string writeScenario(const ScenarioRecording& recording);

} // namespace core
