#pragma once

// Explores the whole program as generated, both layers at once
// (docs/verification.md, "Both layers"): the GEMMA state, Entry and the
// tokens, the situation of the active step's nested GRAFCET with its
// function block's outputs and its TONs, the stored BOOL variables and the
// edge memories. Inputs are free at every scan.
//
// One scan from a state is run by the same steps the simulator takes
// (core/simulation/simulator.cpp, nestedengine.cpp), with every value the
// scan reads and the program does not determine (an input, a numeric
// variable, a TON that may or may not have elapsed, the Complete of a step
// without GRAFCET) asked of a chooser. The chooser enumerates its answers
// depth first, so the scans of a state are exactly the distinct ways its
// inputs can go, and inputs the scan never reads do not multiply them.
//
// What is abstracted (Exploration::abstractions says which apply):
// - numeric variables the actions write: any value of their type when read;
// - numeric inputs: one value per combination of the comparisons with
//   constants on them; any other comparison (A + B > C) is a free BOOL;
// - a TON whose duration is longer than a cycle may or may not have elapsed
//   from its second run on; once elapsed it stays so while its step stays.
//   With exactTime it is counted in scans instead, whatever its duration
//   (up to Options::maxCountedTimerRuns runs, then chosen as above).
// Every abstraction only adds behaviour: a "never" claim is never wrong.
// Inactive nested GRAFCETs are not kept: the Initialization call of their
// step's entry scan starts them afresh.
//
// In closed loop (Options::machine, docs/verification.md, "Closed loop
// (--machine)") the machine's state is part of the state: the inputs its
// sensors drive are read from it, not chosen, and after each scan it moves
// one cycle from the outputs, as core::machine::MachineLoop does. With
// exactTime its travels and delays are counted in scans like the TONs;
// without, they are abstracted like the TONs (abstractmachine.h).

#include "core/verification/tonscans.h"
#include "core/verification/verification.h"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace core {

class Model;

namespace machine {
struct Machine;
}

namespace explore {

struct Options {
    // Complete of the macro/enclosing steps without GRAFCET (Free when not listed).
    std::map<std::string, CompleteAssumption> complete;
    // Property texts (core/verification/property.h), checked at the end of
    // every scan; one that does not pass checkProperty is skipped.
    std::vector<std::string> properties;
    // Time counted in scans: each TON elapses exactly when the PLC's would
    // (more states), instead of "may or may not have elapsed".
    bool exactTime = false;
    // Exact time: a TON is counted run by run up to this many runs (every
    // TON by default: see core/verification/tonscans.h); one that needs more
    // may or may not have elapsed from then on. Lower only to test that.
    std::int64_t maxCountedTimerRuns = tonscans::kMaxCountedRuns;
    // Decide GV103 and GV104 (Exploration::alwaysTrueTransitions, overlaps).
    bool decidePriorities = true;
    // A search for runs rather than a proof: the exploration stops (not
    // exhaustive) as soon as it has found an event of each of these keys
    // (eventKey). The Overlap events among them are probed state by state as
    // the states are explored; the graph properties (Stuck, NoReturn, ...)
    // are only found by a whole exploration. Empty: explore everything.
    std::set<std::string> searchFor;
    // Closed loop with this machine (it must outlive the explorer); nullptr
    // or an empty machine: every input is free.
    const machine::Machine* machine = nullptr;
    // With the machine: before any scan while no fault is in effect, one
    // sensor may become stuck TRUE, stuck FALSE or flicker, or one cylinder
    // or conveyor jam, for the rest of the run (docs/verification.md,
    // "Single faults (--faults single)"). The state keeps which.
    bool singleFaults = false;
    // A stored internal BOOL that nothing reads (no condition, receptivity,
    // action, property, edge or token names it; not an output) is written as
    // the program writes it, races included, but its value is not kept apart
    // in the states: no run's future depends on it. SPIN hides such
    // write-only variables from its state vector too (spin -o2 keeps them).
    // False keeps them apart (more states, the same findings; the tests
    // compare the two).
    bool hideWriteOnlyVariables = true;
    std::size_t maxStates = 1'000'000;
    // Scans run (each way the inputs of a state go): a budget of work that,
    // unlike the deadline, ends at the same point on every machine.
    std::size_t maxScansRun = SIZE_MAX;
    std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
    std::function<bool()> cancelled;
};

// A scan that shows something: the state it starts from (an index into the
// explored states) and the answers of its chooser.
struct Witness {
    std::size_t state = 0;
    std::vector<int> answers;
};

enum class EventKind {
    UnsafeStep,           // stepId, numbers: {the nested step}
    Unstable,             // stepId
    SimultaneousBranches, // stepId, numbers: {upstream step, transition, transition}
    Race,                 // stepId, numbers: {step, step}, variable
    OutputOnD1,           // variable: an output still TRUE in the scan that enters D1
    PropertyViolated,     // property: its index in Options::properties
    StuckWithoutComplete, // stepId: from the witness state, Complete never becomes TRUE while the step stays
    Stuck,                // stepId: from the witness state, no transition out of the step can ever fire
    NoReturn,             // stepId: from the witness state, the initial step never becomes active again
    NoEmergencyStop,      // stepId: in the witness state no scan enters D1
    AlwaysTrue,           // stepId, numbers: {the transition's position in the step}: the witness scan fires it;
                          // its condition is TRUE in every reachable scan of every step that evaluates it
    Overlap,              // stepId, numbers: {higher, lower position}: the higher fires while the lower's condition holds
};

struct Event {
    EventKind kind = EventKind::UnsafeStep;
    std::string stepId;
    std::vector<int> numbers;
    std::string variable;
    std::string transition; // AlwaysTrue, Overlap: the GEMMA transition (the higher one)
    int property = -1;
    Witness witness;
    bool stateOnly = false; // the witness is the state itself (graph properties): no scan from it is part of it
};

// What tells one event from another (its kind and what it names, not its
// witness). AlwaysTrue is told by its transition alone: the family transition
// is evaluated by every F step.
std::string eventKey(const Event& event);

struct Exploration {
    bool exhaustive = true; // false: the state or time budget ran out (or cancelled)
    bool cancelled = false;
    std::size_t states = 0;
    std::size_t scans = 0;   // distinct (state, successor) pairs
    std::size_t scansRun = 0; // every scan run, probes included: the work done (Options::maxScansRun)
    std::size_t maxDepth = 0;
    std::vector<std::string> reachableSteps;      // active at the start of some reachable scan, state order
    std::vector<std::string> fireableTransitions; // fire in some reachable scan, program order
    std::map<std::string, std::vector<int>> activeNestedSteps;  // active after some evolution or Initialization call
    std::map<std::string, std::vector<int>> firedNestedTransitions;
    std::map<std::string, bool> completeSeen;     // per GRAFCET step: Complete TRUE after some call
    std::vector<Event> events;                    // the first witness of each distinct event
    // GV103 and GV104 with the real Complete. A transition's condition is
    // "gated": AND Complete where it waits for it, FALSE when unusable.
    // alwaysTrueTransitions: usable, fire in some reachable scan, gated TRUE in
    // every reachable scan of every step that evaluates them (program order).
    // overlaps: (higher, lower) of one step, both usable and firing somewhere,
    // the higher not the family transition: in some reachable scan the higher
    // fires while the lower's gated condition holds (state order, then pairs).
    std::vector<std::string> alwaysTrueTransitions;
    std::vector<std::pair<std::string, std::string>> overlaps;
    bool prioritiesDecided = true; // false: the budget ran out while deciding the two above
    std::vector<std::string> abstractions;        // English, one line each
    std::vector<bool> propertyChecked;            // per Options::properties: it passed checkProperty
    std::size_t faultChoices = 0;                 // single faults: the faults a scan may begin
    std::size_t faultedStates = 0;                // single faults: explored states with a fault in effect
};

// Runs the exploration once, then writes counterexamples of its witnesses.
class ProgramExplorer {
public:
    ProgramExplorer(const Model& model, Options options);
    ~ProgramExplorer();
    ProgramExplorer(const ProgramExplorer&) = delete;
    ProgramExplorer& operator=(const ProgramExplorer&) = delete;

    const Exploration& run();
    const Exploration& result() const;

    // The run from reset to the witness's state, then its scan (unless
    // stateOnly), as a scenario: inputs set at the scans that read them,
    // `expect step` / `expect nested` at the last scan. `title` is the
    // leading comment. Replayed in the simulator to confirm it; for a
    // property, the property is also evaluated on the replay's last scan.
    // Under the timer abstraction the run is first stretched: before a scan
    // where a TON elapses sooner than the PLC's would, scans in which only
    // time passes are inserted, as many as it still needs.
    Counterexample counterexample(const Event& event, const std::string& title) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace explore
} // namespace core
