#pragma once

// Runs one nested GRAFCET the way its generated S_FB runs (spec
// grafcet-layer.md §4.2, core/codegen/nestedcode.h): one call per
// `call()`, with the Initialization call, simultaneous firing, the actions
// in their order, the TONs of the time-dependent receptivities and the
// continuous outputs computed at the end of the call. The simulator owns the
// global variables; the engine reads and writes them through NestedGlobals.

#include "core/codegen/nestedprogram.h"
#include "core/condition/conditionevaluator.h"
#include "core/simulation/explanationreason.h"
#include "core/simulation/simulationfault.h"
#include "core/model/iectypes.h"

#include <map>
#include <optional>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace core {

enum class EvolutionRule;

// The globals as the FB sees them, by slot (declaration index).
class NestedGlobals {
public:
    virtual ~NestedGlobals() = default;
    virtual cond::Value read(int slot) const = 0;
    virtual void write(int slot, const cond::Value& value) = 0;
    // <V>_PREV: the value at the end of the previous scan.
    virtual bool previous(int slot) const = 0;
};

struct NestedTimerState {
    std::string name;   // the TON instance of the generated code
    int step = 0;
    std::int64_t durationMs = 0;
    std::int64_t elapsedMs = 0; // ET
    bool done = false;          // Q
    // IN was TRUE at the last call and startMs is when it rose: what the
    // PackML verifier needs to tell two paused situations apart.
    bool running = false;
    std::int64_t startMs = 0;
};

// Decides Q of a TON where the PackML verifier abstracts time
// (docs/packml.md, "Verification"): instead of comparing the simulated time
// with the TON's start, the engine asks whether a TON that runs since an
// earlier call and was not yet seen elapsed has elapsed now. It is asked
// only when the call reads that Q, at most once per call and TON, so that
// the verifier branches only on the TONs a scan reads.
class TimerOracle {
public:
    virtual ~TimerOracle() = default;
    // `index`: the TON's index in NestedGrafcet::timers.
    virtual bool elapsed(const NestedTimer& timer, std::size_t index) = 0;
};

enum class NestedTransitionStatus {
    Fires,            // it fires in the first evolution of the next call
    UpstreamInactive, // some of its upstream steps are not active (reasons: which)
    ReceptivityFalse, // its upstream steps are active, its receptivity is FALSE (reasons: why)
    Unusable,         // its receptivity does not parse or type-check: it never fires
    NotCalled,        // the GEMMA step is not active: the function block is not called
};

std::string_view nestedTransitionStatusName(NestedTransitionStatus status); // "fires", "upstream inactive", ...

// Why one transition of a nested GRAFCET does or does not fire in the first
// evolution of the next call.
struct NestedTransitionExplanation {
    int number = 0;
    std::vector<int> upstream;
    std::vector<int> downstream;
    std::string receptivity; // as written
    NestedTransitionStatus status = NestedTransitionStatus::ReceptivityFalse;
    // As data (toText() words them): StepsInactive for UpstreamInactive; the
    // operands that made the receptivity FALSE (Reading of a variable, of
    // `X3` or of `Complete`, Literal, Expression for comparisons,
    // NoRisingEdge/NoFallingEdge, TimerNotElapsed); Unusable: its problems;
    // NotCalled: one NotCalled.
    std::vector<ExplanationReason> reasons;
};

class NestedEngine {
public:
    // `slotOf` gives the declaration index of a variable name (-1 when
    // undeclared: usable texts never name one).
    NestedEngine(const NestedGrafcet& grafcet, const std::function<int(std::string_view)>& slotOf,
                 const std::function<IecType(int)>& typeOf);

    // Power-on: no step active, outputs FALSE, timers stopped.
    void reset();
    // One call of S_FB at time nowMs (scan number x cycle time).
    void call(bool initialization, std::int64_t nowMs, NestedGlobals& globals);

    bool complete() const { return m_complete; }
    bool unstable() const { return m_unstable; }
    bool active(int stepNumber) const;
    std::vector<int> activeSteps() const; // in number order
    // The continuous outputs (Complete excluded), in NestedGrafcet::outputs order.
    const std::vector<std::string>& outputNames() const { return m_shape->outputNames; }
    const std::vector<int>& outputSlots() const { return m_shape->outputSlots; }
    bool output(std::size_t index) const { return m_outputs[index] != 0; }
    // Whether the continuous action `actionIndex` (its index in the step's
    // list of actions, NestedAction::index) of step `stepNumber` emitted its
    // output in the last call: the step is active in the situation the call
    // ended with and the action's condition held there. FALSE for any other
    // action, an unusable one, or an unknown step.
    bool emitting(int stepNumber, int actionIndex) const;
    // The transitions that fired in the last call, in number order: under
    // *until stable* every one that fired in any of its evolutions. Empty
    // after reset() and after an Initialization call (nothing evolves).
    const std::vector<int>& firedTransitions() const { return m_fired; }
    // Receptivities evaluated by the calls since the engine was built (reset()
    // keeps the count): the work its evolutions did, which tests bound.
    std::uint64_t receptivityEvaluations() const { return m_receptivityEvaluations; }
    std::vector<NestedTimerState> timers() const;
    const NestedGrafcet& grafcet() const { return *m_grafcet; }

    // nullptr (the default): Q compares the time with the start, as the PLC.
    // Otherwise `oracle` decides it (see TimerOracle); it is not owned and
    // copies of the engine keep the pointer.
    void setTimerOracle(TimerOracle* oracle) { m_timerOracle = oracle; }

    // The first integer division or MOD by zero evaluated since the last
    // clearDivisionFault() (the call went on with 0 as the quotient): the
    // PLC would have stopped there. stepId, scan and transitionId are left
    // for the caller.
    const std::optional<SimulationFault>& divisionFault() const { return m_divisionFault; }
    void clearDivisionFault() { m_divisionFault.reset(); }

    // Predicts the first evolution of the next evolving call at nowMs without
    // changing the engine: on a copy, the Initialization call first when
    // `initialization` (it may write `globals`: pass scratch globals), then
    // the TONs as the call runs them, then every transition as evolve()
    // evaluates it (edges live: first evolution). `situation` receives the
    // active steps the evolution starts from.
    std::vector<NestedTransitionExplanation> explainNextCall(bool initialization, std::int64_t nowMs,
                                                             NestedGlobals& globals, std::vector<int>* situation) const;
    // Every transition NotCalled: the GEMMA step `stepId` is not active, so
    // its function block does not run next scan.
    std::vector<NestedTransitionExplanation> explainNotCalled(const std::string& stepId) const;

private:
    struct Timer {
        bool running = false;
        std::int64_t start = 0;
        std::int64_t elapsed = 0;
        bool q = false;
        bool undecided = false; // under a TimerOracle: running, Q not yet decided in this call
    };

    cond::Value evaluate(const cond::Expression& expression, const std::map<int, int>* timers,
                         const NestedGlobals& globals, bool firstEvolution) const;
    void noteDivisionByZero(const cond::Expression& expression, int node) const;
    cond::Value atom(const cond::Expression& expression, int node, const std::map<int, int>* timers,
                     const NestedGlobals& globals, bool firstEvolution) const;
    int stepIndex(int number) const;
    void explainNode(const cond::Expression& expression, int node, const std::map<int, int>& timers,
                     const NestedGlobals& globals, std::vector<ExplanationReason>& reasons) const;
    // A node that is no NOT, AND, OR or XOR.
    void explainLeaf(const cond::Expression& expression, int node, const std::map<int, int>& timers,
                     const NestedGlobals& globals, std::vector<ExplanationReason>& reasons) const;
    std::string declaredName(const std::string& written) const;
    int ownOutput(std::string_view name) const; // index into Shape::outputNames, -1 when not one
    void runTon(std::size_t timer, bool in, std::int64_t nowMs);
    bool timerDone(std::size_t timer) const;
    bool evolve(bool firstEvolution, std::int64_t nowMs, NestedGlobals& globals);
    bool enabled(std::size_t transition) const;
    void findEnabled();
    void updateEnabled(const std::vector<std::size_t>& entered);
    void runStored(const std::vector<NestedAction>& actions, NestedGlobals& globals);
    void computeOutputs(const NestedGlobals& globals);
    int slot(std::string_view name) const;

    // What a call never changes: built once by the constructor and shared by
    // copies, so that copying an engine copies only its state (a simulator's
    // history keeps one per scan; the search of the simulator's runs copies
    // one per successor).
    struct Shape {
        std::function<int(std::string_view)> slotOf;
        std::function<IecType(int)> targetTypes;
        bool untilStable = false;
        std::vector<int> stepNumbers;         // by index
        std::vector<std::string> outputNames;
        std::vector<int> outputSlots;
        std::vector<int> outputOf;            // NestedGrafcet::outputs index -> m_outputs index, -1 for Complete
        // By continuous action: m_emitting[continuousStart[step index] + i]
        // for NestedStep::continuous[i].
        std::vector<std::size_t> continuousStart;
        std::size_t continuousActions = 0;    // in all the steps: m_emitting's size
        // The transitions by index, so that an evolution looks only at the
        // transitions it can fire (a search for stability makes up to
        // transitions + 1 evolutions per call).
        std::vector<std::vector<std::size_t>> upstream;   // by transition: step indices
        std::vector<std::vector<std::size_t>> downstream; // by transition: step indices
        std::vector<std::vector<std::size_t>> following;  // by step: the usable transitions it is upstream of
        std::vector<char> usable; // by transition: usable, and every step it names exists
    };
    static std::shared_ptr<const Shape> makeShape(const NestedGrafcet& grafcet,
                                                  const std::function<int(std::string_view)>& slotOf,
                                                  const std::function<IecType(int)>& typeOf);

    const NestedGrafcet* m_grafcet;
    std::shared_ptr<const Shape> m_shape;
    std::vector<char> m_x;                // by step index
    // Mutable: under a TimerOracle, reading a Q decides it (timerDone()).
    mutable std::vector<Timer> m_timers;
    TimerOracle* m_timerOracle = nullptr;
    std::vector<char> m_outputs;
    bool m_complete = false;
    bool m_unstable = false;
    mutable std::optional<SimulationFault> m_divisionFault; // see divisionFault()
    std::vector<int> m_fired;             // transition numbers, see firedTransitions()
    std::uint64_t m_receptivityEvaluations = 0;
    std::vector<char> m_emitting;         // by continuous action, see Shape::continuousStart
    // During an evolving call: the usable transitions whose upstream steps
    // are all active, ascending (firing order does not matter: all fire
    // together; the lists keep the number order of the old full pass).
    std::vector<std::size_t> m_enabled;
};

} // namespace core
