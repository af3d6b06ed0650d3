#pragma once

// Runs the GEMMA program scan by scan, exactly as the generated PROGRAM GEMMA
// (spec §6.6, core/templates/gemma/gemmacodegen.cpp) runs on a PLC, before any PLC exists.
//
// The simulator reads the one intermediate form, core::GemmaProgram: the
// visible steps, the transitions each step evaluates in evaluation order
// (family transitions first), which of them wait for Complete, the tokens and
// which conditions are usable. It never re-derives any of that. Conditions
// are compiled once into a flat postfix program, so a scan does no
// allocation, no string and no map work (over a million scans per second on
// the realistic model).
//
// One scan (step()), mirroring the generated code line by line:
//  1. If the active step S has a nested behaviour (macro/enclosing):
//       IF Entry THEN S(Initialization := Entry); Entry := FALSE; S's tokens := FALSE; END_IF;
//       S(Initialization := Entry);
//     so S's Complete for this scan is what its function block yields (see
//     CompleteMode). A simple step does not touch Entry: Entry stays TRUE
//     after a transition into a simple step until a macro/enclosing step
//     consumes it, as in the generated code.
//  2. The first transition, in evaluation order, whose condition holds
//     (token literals read the tokens; `AND S.Complete` where it waits for
//     Complete) fires: State := target, Entry := TRUE. At most one per scan.
//     A condition that does not parse or type-check is FALSE.
//  3. After END_CASE, for every token of every visible step, with the NEW
//     State and the current inputs:
//       IF State = <source no.> AND <literal> THEN token := TRUE; END_IF;
// A hidden step or transition does not exist for the simulator. A state with
// no CASE branch (a hidden initial step) does nothing: no transition, no
// token update, as on the PLC.
//
// Scans are numbered from 1: the first scan is scan 1. scanCount() is the
// number of scans run; simulated time is scanCount() x the model's cycle time.
//
// Inputs are the model's variables; setVariable() changes a value for the
// following scans (the GEMMA program never writes them).
//
// A Simulator is not thread-safe: even const calls (explain()) share its
// evaluation scratch space. Copies are independent.

#include "core/condition/conditionevaluator.h"
#include "core/simulation/explanationreason.h"
#include "core/simulation/nestedengine.h"
#include "core/simulation/simulationfault.h"
#include "core/templates/gemma/gemmaprogram.h"
#include "core/model/model.h"
#include "core/model/status.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace core {

class Model;

// How the Complete output of a nested step's function block is computed.
enum class CompleteMode {
    // As the generated skeleton FB behaves: Initialization sets Complete :=
    // FALSE, then the skeleton's `Complete := TRUE;` runs in the same call, so
    // Complete is TRUE in every scan the FB is called, the entry scan included.
    Automatic,
    // The user plays the nested behaviour: the FB writes the user's value
    // (setComplete) into Complete in its body on every call. The body runs
    // after the Initialization block, so on the entry scan the user's value
    // also applies (Initialization's reset to FALSE is overwritten in the
    // same call): holding TRUE while entering the step makes Complete TRUE in
    // its entry scan. Hold FALSE to model a nested behaviour still running.
    Manual,
};

// A variable whose value differs from the previous scan's.
struct InputChange {
    std::string variable; // spelled as declared
    cond::Value value;    // the new value
};

// What one scan did.
struct ScanRecord {
    std::int64_t scan = 0;    // 1 for the first scan
    std::string stepBefore;   // active step id when the scan began ("" when State names no visible step)
    std::string fired;        // transition id ("F1->A2", "F->D1"), empty when none fired
    std::string stepAfter;    // active step id after the scan
    bool entry = false;       // Entry after the scan
    std::vector<bool> tokens;   // after the scan, in Simulator::tokenNames() order
    std::vector<bool> complete; // Complete output of each nested step after the scan, in Simulator::nestedSteps() order
    std::vector<InputChange> changedInputs; // variables changed since the previous scan (for scan 1: since reset)
    // After the scan, in Simulator::nestedSteps() order: the active nested
    // steps of each GRAFCET (empty for a step without one).
    std::vector<std::vector<int>> nestedActive;
    // After the scan, in Simulator::nestedSteps() order: Unstable of each
    // GRAFCET (FALSE for a step without one, and under one evolution per scan).
    std::vector<bool> unstable;
    // Output variables (VariableKind::Output) the scan changed: their value
    // after it differs from their value when it began. Declaration order.
    std::vector<InputChange> changedOutputs;
};

enum class TransitionStatus {
    Fires,                     // the next scan fires it
    ConditionFalse,            // its condition is FALSE (reasons say why)
    WaitingForComplete,        // its condition holds but it waits for Complete, which is FALSE
    PreemptedByHigherPriority, // it could fire, but an earlier one fires (preemptedBy)
    Unusable,                  // its condition does not parse or type-check: always FALSE (reasons give the problem)
};

std::string_view transitionStatusName(TransitionStatus status); // "fires", "condition false", ...

// Why a transition of the active step does or does not fire in the NEXT scan.
// explain() predicts that scan without running it: if Entry is TRUE and the
// step has a nested behaviour, its tokens read FALSE (the entry block resets
// them) and Complete is what its FB will yield in that scan; for a nested
// GRAFCET the FB's calls are run on copies first, so Complete is the
// GRAFCET's and the conditions read what its stored actions write.
struct TransitionExplanation {
    std::string transitionId; // "F1->A2"
    std::string targetId;
    int priority = 0;         // among its own source's transitions (family ones: among the family)
    bool family = false;
    bool waitsForComplete = false;
    TransitionStatus status = TransitionStatus::ConditionFalse;
    // Why, as data (toText() words it in English): for ConditionFalse the
    // operands that made it FALSE, down to variables and comparisons
    // ("Start = FALSE", "Speed > 10 is FALSE (Speed = 3)",
    // "Stop_F1_3_MEM = FALSE (token of NOT Stop)"), then "F1.Complete = FALSE"
    // when it also waits for Complete; for WaitingForComplete
    // "F1.Complete = FALSE"; for Unusable its problems; for
    // PreemptedByHigherPriority "F->D1 fires first".
    std::vector<ExplanationReason> reasons;
    std::string preemptedBy; // the transition that fires instead (PreemptedByHigherPriority only)
};

// What the next scan does with the nested GRAFCET of a macro/enclosing step
// (Simulator::explainNested()), predicted as the engine will run it: when
// Entry is TRUE the Initialization call first puts the GRAFCET in its
// initial situation (running its initial steps' on-activation actions), then
// the TONs run, then the first evolution evaluates every transition on that
// situation, edges included. Under *until stable* only that first evolution
// is explained: later ones follow in the same call with edges FALSE.
struct NestedExplanation {
    std::string stepId;
    bool called = false;         // the step is the active one: the next scan calls its FB
    bool initialization = false; // the next scan re-initialises the GRAFCET before evolving
    bool untilStable = false;    // more evolutions may follow the one explained
    std::vector<int> situation;  // the active steps the first evolution starts from
    std::vector<NestedTransitionExplanation> transitions; // in number order
};

class Simulator {
public:
    // Builds the GemmaProgram of the model and compiles it. The simulator
    // keeps no reference to the model: rebuild it after the model changes.
    explicit Simulator(const Model& model);
    ~Simulator();
    Simulator(const Simulator& other);
    Simulator& operator=(const Simulator& other);
    Simulator(Simulator&&) noexcept;
    Simulator& operator=(Simulator&&) noexcept;

    // Start state (spec §6.6): State = initial step, Entry = TRUE, tokens and
    // Complete FALSE, variables at their defaults, scan count 0, trace
    // cleared. Complete modes and manual values are kept.
    void reset();

    // Runs one scan and returns what it did (appended to trace() when enabled).
    ScanRecord step();
    // Runs `scans` scans without building records (unless tracing is on).
    void run(std::int64_t scans);

    // Inputs. Names are matched case-insensitively. A value must be of the
    // variable's kind (BOOL; integer for integer types, integer or real for
    // REAL/LREAL) and in the range of its IEC type; otherwise nothing changes
    // and the Status says why.
    Status setVariable(std::string_view name, const cond::Value& value);
    // The same from ST text ("TRUE", "-3", "1.5"), as a scenario writes it.
    Status setVariableText(std::string_view name, std::string_view text);
    // The same by variableNames() index: no name lookup, for tight loops.
    Status setVariableAt(std::size_t index, const cond::Value& value);
    int variableIndex(std::string_view name) const; // case-insensitive; -1 when unknown
    cond::Value variable(std::string_view name) const; // FALSE for an unknown name
    const std::vector<std::string>& variableNames() const; // as declared, declaration order
    cond::Value variableValue(std::size_t index) const;    // by variableNames() index
    IecType variableType(std::size_t index) const;         // BOOL for an index out of range
    VariableKind variableKind(std::size_t index) const;    // input for an index out of range

    // Complete of nested steps. Unknown ids or simple steps: failed Status.
    Status setCompleteMode(std::string_view stepId, CompleteMode mode);
    // Switches nothing: sets the value a Manual step's FB writes (kept while Automatic).
    Status setComplete(std::string_view stepId, bool complete);
    CompleteMode completeMode(std::string_view stepId) const; // Automatic for unknown ids
    bool manualComplete(std::string_view stepId) const;       // the user's value
    // The Complete output of the step's FB instance after the last call of it
    // (FALSE before its first call; it keeps its value while the step is inactive).
    bool complete(std::string_view stepId) const;
    const std::vector<std::string>& nestedSteps() const; // visible macro/enclosing step ids, state order

    // Nested GRAFCETs (spec grafcet-layer.md §4). A step that has one takes
    // its Complete from it: Complete modes apply only to the others.
    bool hasGrafcet(std::string_view stepId) const;
    std::vector<int> activeNestedSteps(std::string_view stepId) const; // in number order
    bool unstable(std::string_view stepId) const;                      // until stable only
    std::vector<NestedTimerState> nestedTimers(std::string_view stepId) const;
    std::vector<std::string> nestedOutputs(std::string_view stepId) const; // the continuous outputs it drives
    const NestedEngine* grafcetEngine(std::string_view stepId) const;      // nullptr without a GRAFCET
    // The transitions of the step's GRAFCET that fired in the last scan, in
    // number order (under *until stable*, in any evolution of it). Empty when
    // the last scan did not call its function block (the step was not the
    // active one), before the first scan, and for a step without GRAFCET. A
    // copy of the simulator keeps them: a scan restored from the history
    // shows its own.
    std::vector<int> firedNestedTransitions(std::string_view stepId) const;
    // Whether the last scan called the step's function block (it was the
    // active step when the scan began): what unstable() and the engine's
    // other outputs say is about that scan only then.
    bool nestedCalled(std::string_view stepId) const;
    // Why each transition of the step's GRAFCET fires or not in the next
    // scan; empty transitions (and stepId) for a step without GRAFCET.
    NestedExplanation explainNested(std::string_view stepId) const;

    // State.
    std::string activeStepId() const;  // "" when State names no visible step
    int activeStepNumber() const;      // the value of State
    bool entry() const;
    const std::vector<std::string>& tokenNames() const; // "Stop_F1_3_MEM", in generated-code order
    std::vector<bool> tokenValues() const;
    bool token(std::string_view tokenName) const;       // FALSE for an unknown name (case-insensitive)
    std::int64_t scanCount() const;
    // The run-time fault that stopped the run (an integer division or MOD by
    // zero, as the PLC's task stops on it), nullopt while running. The scan
    // that faults stops where the PLC does: in a GEMMA condition, before any
    // transition fires (no token update, no output written after END_CASE);
    // in a nested GRAFCET, after the FB's call (which went on with 0 as the
    // quotient). After it step() and run() run no scan; reset() clears it.
    const std::optional<SimulationFault>& fault() const;
    std::int64_t simulatedTimeMs() const;               // scanCount() x cycle time
    int cycleTimeMs() const;
    // The transition fired by the last scan, empty when none (or no scan yet).
    std::string lastFired() const;

    // Why each transition of the active step will or will not fire in the
    // next scan, in evaluation order.
    std::vector<TransitionExplanation> explain() const;

    // Trace of every scan since reset(), recorded only while enabled.
    void setTraceEnabled(bool enabled);
    bool traceEnabled() const;
    const std::vector<ScanRecord>& trace() const;
    void clearTrace();
    // Called after every scan step() or run() performs, with its record
    // (builds records even when the trace is off). Empty to remove.
    void setScanCallback(std::function<void(const ScanRecord&)> callback);

    // The program the simulator runs (ids, numbers, transitions, tokens).
    const GemmaProgram& program() const;

    // Lookups for the editor: -1 when unknown.
    int stepIndexForNumber(int number) const; // index in program().steps

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace core
