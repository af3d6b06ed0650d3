#include "core/verification/programexplorer.h"

#include "core/templates/gemma/gemmaprogram.h"
#include "core/condition/conditionanalysis.h"
#include "core/condition/conditionevaluator.h"
#include "core/condition/symboltable.h"
#include "core/machine/closedloopscenario.h"
#include "core/machine/machineloop.h"
#include "core/machine/machinestate.h"
#include "core/model/model.h"
#include "core/simulation/scenario.h"
#include "core/simulation/simulator.h"
#include "core/verification/abstractmachine.h"
#include "core/verification/closedloopreplay.h"
#include "core/verification/comparisonshape.h"
#include "core/verification/property.h"
#include "core/verification/propertyevaluation.h"
#include "core/verification/satisfiability.h"
#include "core/verification/statestore.h"
#include "core/verification/tonscans.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <deque>
#include <optional>
#include <set>
#include <sstream>

namespace core::explore {

namespace {

std::string upper(std::string_view text)
{
    std::string out(text);
    for (char& c : out)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

bool isComparison(cond::BinaryOp op)
{
    using B = cond::BinaryOp;
    return op == B::Less || op == B::Greater || op == B::LessEqual || op == B::GreaterEqual || op == B::Equal
        || op == B::NotEqual;
}

// One comparison the explorer cannot decide on values, in a form shared by
// its equivalents, so that `A < B` and `A >= B` stay each other's negation:
// a < b, b < a for a > b, NOT (b < a) for a <= b, NOT (a < b) for a >= b,
// and = / <> with the operands in text order.
std::string canonicalComparison(const cond::Expression& expression, int index, bool& negated)
{
    using B = cond::BinaryOp;
    const cond::Node& node = expression.at(index);
    std::string left = cond::print(cond::Expression{expression.nodes, node.left});
    std::string right = cond::print(cond::Expression{expression.nodes, node.right});
    negated = node.binaryOp == B::LessEqual || node.binaryOp == B::GreaterEqual || node.binaryOp == B::NotEqual;
    if (node.binaryOp == B::Equal || node.binaryOp == B::NotEqual) {
        if (right < left)
            std::swap(left, right);
        return "(" + left + ") = (" + right + ")";
    }
    if (node.binaryOp == B::Greater || node.binaryOp == B::LessEqual)
        std::swap(left, right);
    return "(" + left + ") < (" + right + ")";
}

// What a variable is to the explorer.
enum class SlotClass {
    FreeBool,    // an input: any value at every scan
    MachineBool, // closed loop: an input a machine's sensor drives, read from the machine's state
    StateBool,   // written by the program (stored or continuous): kept in the state
    ConstBool,   // neither: its default for ever
    FreeNumber,  // a numeric input, or a numeric variable the actions write (abstracted)
    ConstNumber, // a numeric variable nothing writes
};

struct Slot {
    std::string name;
    IecType type = IecType::Bool;
    VariableKind kind = VariableKind::Input;
    SlotClass cls = SlotClass::FreeBool;
    cond::Value initial;
    std::vector<cond::Value> representatives; // FreeNumber
    int stateBit = -1;                        // StateBool: index among the state's BOOLs
    int edge = -1;                            // read under an edge: index of its <V>_PREV
    int machineSignal = -1;                   // MachineBool: its slot in the machine's signal table
    bool writeOnly = false;                   // StateBool nothing reads (Options::hideWriteOnlyVariables)
    // What the simulator holds before the first scan: the initial value, or
    // in closed loop an operator input's rest value (MachineLoop::reset).
    cond::Value replayInitial;
};

// How the explorer reads one node of an expression.
enum class NodeRole {
    Logical,     // NOT, AND, OR, XOR, ->, = and <> between BOOLs: evaluated here, short-circuit
    Literal,     // TRUE / FALSE
    BoolRead,    // a BOOL variable
    Exact,       // constants only, or one numeric variable against constants (`Speed > 10`): computed on its value
    Opaque,      // any other comparison: a free BOOL
    Token,       // a token literal of a GEMMA condition
    Step,        // Xn
    Duration,    // t/Xn
    Complete,    // Complete inside a nested GRAFCET
    Faulted,     // a property's `faulted`: a fault is in effect (single faults)
    FaultTime,   // a property's `T/faulted`: in effect for index scans at least
    Edge,        // RE / FE
    InStep,      // in S
    NestedStep,  // S.Xn
    Other,       // never reached in a BOOL context
};

struct NodeInfo {
    NodeRole role = NodeRole::Other;
    int slot = -1;        // BoolRead, Edge: the variable; Exact: the numeric variable (-1 for none)
    int index = -1;       // Token: token index; Duration: timer; Step/NestedStep: nested step number; InStep: step index
    int step = -1;        // NestedStep: GEMMA step index
    std::string text;     // Opaque: its canonical text (its identity within a scan)
    bool negated = false; // Opaque: the node is the negation of that canonical comparison
    std::shared_ptr<cond::Expression> sub; // Exact: the comparison as an expression of its own
    // BoolRead, Edge in a nested GRAFCET: the index of the variable among the
    // outputs of the GRAFCET it is compiled for (owner), -1 when not one of
    // them; Literal: 1 for TRUE. Looked up once here rather than by name at
    // every read.
    int ownOutput = -1;
    int owner = -1;
    bool literalTrue = false;
    // Exact on a free numeric variable: bit i set when its representative i makes it TRUE (computed at first use).
    mutable std::uint64_t truth = 0;
    mutable bool truthKnown = false;
};

struct ExpressionInfo {
    const cond::Expression* expression = nullptr;
    std::vector<NodeInfo> nodes;
};

struct CompiledToken {
    int slot = -1;
    bool normallyClosed = false;
};

struct CompiledTransition {
    const GemmaTransition* source = nullptr;
    int globalIndex = 0; // in Impl::transitionIds
    int target = -1;     // step index, -1 when the target is not visible
    const ExpressionInfo* condition = nullptr; // nullptr: unusable (FALSE)
};

struct CompiledNestedTransition {
    const NestedTransition* source = nullptr;
    std::vector<int> upstream, downstream; // step indices
    const ExpressionInfo* receptivity = nullptr;
};

struct CompiledAction {
    const NestedAction* source = nullptr;
    int slot = -1; // -1: Complete, or a numeric target (ignored)
    bool complete = false;
    const ExpressionInfo* value = nullptr; // Assign
};

struct CompiledGrafcet {
    const NestedGrafcet* source = nullptr;
    std::vector<int> numbers; // by step index
    std::vector<bool> initial;
    std::vector<std::vector<CompiledAction>> onActivation, onDeactivation;
    std::vector<std::vector<const ExpressionInfo*>> continuous; // by step index, by continuous action: condition (nullptr: none)
    // By output (source->outputs): its drivers whose action is usable, in
    // order: (step index, condition; nullptr: none).
    std::vector<std::vector<std::pair<int, const ExpressionInfo*>>> outputDrivers;
    std::vector<CompiledNestedTransition> transitions;
    // By step index: the usable transitions it is upstream of, the only ones
    // an evolution reads while it is active; plus those without upstream step.
    std::vector<std::vector<int>> transitionsFrom;
    std::vector<int> transitionsWithoutUpstream;
    std::vector<int> timerStep; // by timer: step index
    std::vector<bool> timerShort; // duration <= cycle: elapses at its second run
    // Exact time: the runs with IN TRUE after which Q is TRUE (tonscans::runsToElapse),
    // and the count stored, up to Options::maxCountedTimerRuns (past it: chosen).
    std::vector<std::int64_t> timerRuns;
    std::vector<std::int64_t> timerCountLimit;
    std::vector<std::vector<int>> timersOfStep;
    std::map<std::string, int> ownOutput; // upper name -> index into source->outputs
    int completeOutput = -1;              // index into source->outputs of Complete's drivers

    int stepIndex(int number) const
    {
        auto it = std::find(numbers.begin(), numbers.end(), number);
        return it == numbers.end() ? -1 : static_cast<int>(it - numbers.begin());
    }
};

struct CompiledStep {
    const GemmaStep* source = nullptr;
    bool nested = false;
    bool freeComplete = true;
    int grafcet = -1; // index into Impl::grafcets
    int firstToken = 0;
    int tokenCount = 0;
    std::vector<CompiledTransition> transitions;
};

struct OutputWrite {
    int slot = -1;
    struct Driver {
        int step = -1;   // GEMMA step index
        int output = -1; // index into its grafcet's outputs
    };
    std::vector<Driver> drivers;
};

// The layout of a state in bytes.
struct Layout {
    int tokens = 3;
    int x = 0, outputs = 0, complete = 0, timers = 0, bools = 0, prev = 0, size = 0;
    int timerBytes = 2; // per TON: enough for the largest value stored (little-endian)
    // Single faults: at `fault`, the fault in effect (4 bytes: 0 none, else
    // 1 + its index in faultChoices), a flickering sensor's reading for the
    // next scan (1 byte), the scans it has been in effect (4 bytes,
    // saturated where no property reads more); -1 without faults.
    int fault = -1;
};

constexpr int kExplorerFaultBytes = 9;

// One answer the chooser gave, in the order the scan asked.
struct Decision {
    // NumberTest: a comparison of a free numeric variable with constants,
    // decided on the representatives still possible (Impl::numberPossible).
    // Machine: closed loop under the time abstraction, whether a travel or delay ends.
    // Fault: single faults, before the scan with no fault in effect: 0 none
    // begins, else 1 + the fault's index in Impl::faultChoices.
    enum class Kind { Bool, Number, NumberTest, Opaque, Timer, Complete, Machine, Fault } kind = Kind::Bool;
    int slot = -1; // Bool, Number: the variable; Timer: the timer; Complete: the step index
    int value = 0; // Bool, Opaque, Timer, Complete: 0/1; Number: representative index
};

class Chooser {
public:
    void restart(const std::vector<int>* replay)
    {
        m_position = 0;
        m_replay = replay;
        decisions.clear();
    }
    int choose(int alternatives)
    {
        if (m_replay)
            return m_position < m_replay->size() ? (*m_replay)[m_position++] : 0;
        if (m_position == m_values.size()) {
            m_values.push_back(0);
            m_alternatives.push_back(alternatives);
        }
        return m_values[m_position++];
    }
    // The next combination of answers; false when every one was tried.
    bool advance()
    {
        m_values.resize(m_position);
        m_alternatives.resize(m_position);
        while (!m_values.empty() && m_values.back() + 1 >= m_alternatives.back()) {
            m_values.pop_back();
            m_alternatives.pop_back();
        }
        if (m_values.empty())
            return false;
        ++m_values.back();
        return true;
    }
    void reset()
    {
        m_values.clear();
        m_alternatives.clear();
    }
    const std::vector<int>& answers() const { return m_values; }

    std::vector<Decision> decisions;

private:
    std::vector<int> m_values;
    std::vector<int> m_alternatives;
    std::size_t m_position = 0;
    const std::vector<int>* m_replay = nullptr;
};

// What one scan did, beyond the state it ends in.
struct ScanOutcome {
    int firedTransition = -1; // global index
    bool completeTrue = false; // the active step's FB yielded Complete TRUE
    bool entersD1 = false;
    std::vector<Event> events; // without witnesses
};

using State = std::string;

// What one evolution works with, kept between evolutions so that none
// allocates or walks the whole GRAFCET: the active steps (sorted step
// indices, maintained through the call) and lists of what it touches.
struct EvolutionScratch {
    static constexpr char kDeactivated = 1, kActivated = 2;
    std::vector<int> active, candidates, fired, deactivated, activated, left, entered, next;
    std::vector<char> stepMark;      // by step index, all 0 between evolutions
    std::vector<int> firstFiringFrom; // by step index, all -1 between evolutions

    void mark(std::vector<int>& list, int step, char flag)
    {
        char& m = stepMark[static_cast<std::size_t>(step)];
        if (!(m & flag))
            list.push_back(step);
        m = static_cast<char>(m | flag);
    }
    // active := active - left + entered (left are active, entered are not).
    void updateActive()
    {
        next.clear();
        std::set_difference(active.begin(), active.end(), left.begin(), left.end(), std::back_inserter(next));
        active.clear();
        std::merge(next.begin(), next.end(), entered.begin(), entered.end(), std::back_inserter(active));
    }
};

// Which elements were seen, by index, with the list of their numbers that
// Exploration reports: adding is constant time, however many there are.
// `numbers` is the list in Exploration, looked up (and created) by its
// step's id once, the first time it is needed, not at every scan.
struct FlagSet {
    std::vector<char> seen;
    std::vector<int>* numbers = nullptr;
    std::vector<int>& list(std::map<std::string, std::vector<int>>& lists, const std::string& key)
    {
        if (!numbers)
            numbers = &lists[key];
        return *numbers;
    }
    void add(int index, int number, std::vector<int>& list)
    {
        char& flag = seen[static_cast<std::size_t>(index)];
        if (!flag)
            list.push_back(number);
        flag = 1;
    }
};

// Thrown inside a scan when the time limit passed or the run was cancelled:
// the scan under way is dropped, what was explored before it is kept.
struct Interrupted {};

// What a scan also evaluates before its CASE fires a transition, for GV103
// and GV104: whether some input makes a transition's gated condition FALSE,
// or lets a higher transition fire while a lower one's holds. Its reads are
// the scan's own (cached), so the CASE that follows sees the same values.
// Evaluates every condition of one step's CASE in the scans of a state, before
// the CASE runs, to decide GV103 and GV104 on both layers: one enumeration of
// the inputs those conditions read answers every transition and every pair.
struct Probe {
    int step = -1;     // the step index whose scans it probes (-1: plain scans)
    bool only = false; // stop the scan once the conditions are read (exploring, not replaying)
};

} // namespace

struct ProgramExplorer::Impl {
    Impl(const Model& model, Options options);

    // --- compiling -------------------------------------------------------------------
    void compileSlots(const Model& model);
    void compileMachine();
    void compileFaults();
    void advanceMachine();
    void beginFaults();
    bool faultedSensor(bool machineValue) const;
    std::uint32_t faultField(int offset, int bytes) const;
    void setFaultField(int offset, int bytes, std::uint32_t value);
    void compileSteps();
    void compileGrafcet(CompiledStep& step);
    void compileProperties(const Model& model);
    void compileWriteOnlyBools();
    const ExpressionInfo* info(const cond::Expression& expression, const std::map<int, std::string>* substitutions,
                               const CompiledStep* step, const CompiledGrafcet* grafcet,
                               const std::map<int, int>* timerOfNode);
    void collectComparisons(const cond::Expression& expression);
    int slotOf(std::string_view name) const;
    void noteRead(int slot)
    {
        if (slot >= 0)
            slotRead[static_cast<std::size_t>(slot)] = 1;
    }

    // --- one scan ----------------------------------------------------------------------
    State initialState() const;
    ScanOutcome scan(const State& from, State& to);
    bool readBool(int slot);
    cond::Value readNumber(int slot);
    bool testNumber(const ExpressionInfo& info, const NodeInfo& n);
    bool choose(Decision::Kind kind, int slot);
    bool eval(const ExpressionInfo& info, int node);
    int ownOutputIndex(const NodeInfo& n, const std::string& name) const;
    bool evalNode(const ExpressionInfo& info, int node);
    void initializationCall(const CompiledStep& step);
    void evolvingCall(const CompiledStep& step, ScanOutcome& outcome);
    bool evolve(const CompiledStep& step, bool first, ScanOutcome& outcome);
    void runStored(const CompiledStep& step, int stepIndex, const std::vector<CompiledAction>& actions,
                   ScanOutcome& outcome);
    void computeOutputs(const CompiledGrafcet& grafcet);
    bool timerElapsed(int timer);
    std::int64_t timerState(int timer) const;
    void setTimerState(int timer, std::int64_t value);
    void runTimer(const CompiledGrafcet& g, int timer, bool in);
    void noteActive(const CompiledStep& step);
    void noteEntered(const CompiledStep& step, const std::vector<int>& entered);
    void pollInsideScan();
    bool gated(const CompiledTransition& transition, bool complete);
    void runProbe(const CompiledStep& step, bool complete);

    // --- exploring ----------------------------------------------------------------------
    void explore();
    bool exploreState(std::size_t next, const State& from);
    void noteScan(std::size_t next, std::uint32_t to, ScanOutcome& outcome);
    std::uint32_t reachedState(std::size_t from);
    // The last successors of the state being explored, as they are (not
    // encoded), with their indices: most scans of a state end in one an
    // earlier scan of it reached, found here without encoding nor hashing
    // it. A ring of kRecent, its strings' buffers reused.
    static constexpr std::size_t kRecent = 8;
    std::array<std::pair<State, std::uint32_t>, kRecent> recent;
    std::size_t recentCount = 0;
    void finishExploration(const std::vector<bool>& reached);
    void addEvent(Event event, std::size_t state, bool gemmaFired);
    void analyseGraph();
    void probePriorities();
    void probeState(std::size_t state, std::set<std::pair<int, std::pair<std::size_t, std::size_t>>>& overlapFound);
    void probeScans(std::size_t state, std::size_t& leaves,
                    std::set<std::pair<int, std::pair<std::size_t, std::size_t>>>& overlapFound);
    bool worthProbing(int step, const std::set<std::pair<int, std::pair<std::size_t, std::size_t>>>& overlapFound) const;
    void compileSearchedOverlaps();
    void probeSearchedOverlaps(std::size_t state);
    void noteSearched(const std::string& key);
    bool outOfBudget();

    // --- counterexamples -------------------------------------------------------------------
    using Path = std::vector<std::pair<std::size_t, std::vector<int>>>;
    Path stretchForTimers(const Path& path, const Event& event);
    std::optional<std::pair<std::size_t, std::vector<int>>> stutter(std::size_t state);
    std::int64_t missingRuns(std::size_t from, const std::vector<std::int64_t>& counts) const;
    void replayScan(std::size_t from, const std::vector<int>& answers, const Event& event, bool witnessScan);
    std::vector<std::int64_t> countRuns(const std::vector<std::int64_t>& counts, std::int64_t scans) const;
    std::vector<std::pair<std::size_t, std::vector<int>>> pathTo(std::size_t state) const;
    std::vector<int> answersTo(std::size_t from, std::size_t to) const;

    const Model& model;
    Options options;
    GemmaProgram program;
    SymbolTable symbols;
    std::vector<Slot> slots;
    std::map<std::string, int> slotByName;
    std::vector<int> edgeSlots;
    std::vector<int> stateBoolSlots;
    std::vector<char> slotRead; // by slot: some expression or token reads it
    // State BOOLs nothing reads (Options::hideWriteOnlyVariables): their
    // byte in the state and the value it is reset to after every scan.
    std::vector<std::pair<int, char>> writeOnlyBools;
    std::map<int, std::vector<std::pair<cond::BinaryOp, cond::Value>>> comparisons; // numeric slot -> constants
    std::vector<std::unique_ptr<ExpressionInfo>> infos;
    std::vector<CompiledStep> steps;
    std::vector<CompiledGrafcet> grafcets;
    std::vector<CompiledToken> tokens;
    std::vector<std::string> transitionIds;
    std::vector<const GemmaTransition*> transitionSources;
    std::vector<OutputWrite> outputWrites;
    std::vector<int> outputsToCheckOnD1; // BOOL Output slots the program writes
    int initialStep = -1;
    int d1Step = -1;
    Layout layout;
    int cycleMs = 20;
    // Closed loop: the machine, restored from each state's tail (after
    // layout.size) before its scan: counted in scans with exactTime, else
    // abstracted as the TONs are (abstractMachine); its actuators (signal
    // slot, variable slot).
    std::optional<machine::MachineState> machineState;
    std::optional<AbstractMachine> abstractMachine;
    std::vector<std::pair<std::size_t, int>> actuators;
    std::string machineStart; // the key of the machine's start state
    // Single faults (Options::singleFaults): what a scan may begin, and in
    // the scan being run, the sensor (signal slot) under a fault and how.
    struct FaultChoice {
        machine::Fault fault;
        int signal = -1;    // stuck, flicker: the sensor's signal slot
        int component = -1; // jam: the component's index
    };
    std::vector<FaultChoice> faultChoices;
    bool singleFaults = false;
    std::int64_t faultScanLimit = 0; // the most scans a `T/faulted` needs (0: none read)
    bool compilingProperty = false;
    int faultSignal = -1;
    machine::FaultKind faultKind = machine::FaultKind::Clear;
    std::vector<ParsedProperty> parsedProperties;
    std::vector<const ExpressionInfo*> propertyInfos; // nullptr: skipped

    // The scan being run.
    Chooser chooser;
    State work;
    State successor; // the state a scan ends in, its buffer kept from scan to scan
    std::optional<Simulator> replaySimulator; // the counterexamples' runs: copies of it, never run itself
    std::vector<char> outputValues; // computeOutputs's, kept from scan to scan
    std::vector<int> boolCache;   // by slot: -1 undecided
    std::vector<int> numberCache; // by slot
    std::vector<std::uint64_t> numberPossible; // by slot: representatives still possible this scan (0: all)
    std::map<std::string, bool> opaqueCache;
    std::vector<int> timerCache;  // by timer of the active GRAFCET
    EvolutionScratch evolution;
    std::vector<FlagSet> nestedActiveSeen, nestedFiredSeen; // by grafcet: steps, transitions (by index)
    // Work done inside scans since the last look at the clock and the cancel
    // callback; looked at only while exploring (not while writing counterexamples).
    unsigned workSincePoll = 0;
    bool polling = false;
    const CompiledGrafcet* activeGrafcet = nullptr;
    const CompiledStep* activeStep = nullptr;
    bool firstEvolution = false;
    // By slot, the stored write of the scan: (step index, value), step -1
    // when none; writtenSlots lists the slots to clear for the next scan.
    std::vector<std::pair<int, bool>> writes;
    std::vector<int> writtenSlots;
    bool propertyPhase = false;
    int newStep = -1;
    // What the TONs did in the scan being replayed (logTimers), for
    // stretchForTimers: by timer of the active GRAFCET, -1 not run, else IN;
    // reset: set to 0 after its run (its step entered); initialized: the
    // Initialization call set them all to 0 before their run.
    struct TimerLog {
        std::vector<int> in;
        std::vector<char> reset;
        bool initialized = false;
    };
    bool logTimers = false;
    TimerLog timerLog;
    Probe probe;                 // the probe the scans run
    std::vector<char> probeTrue; // by position in the probed step: its gated condition in the last scan
    std::vector<char> failSeen; // by global transition: its gated condition was FALSE in some scan

    // The explored graph (statestore.h): each state once, encoded, with by
    // index its parent, depth, step (stepIndexOf + 1) and edges.
    StateStore store;
    ChunkedArray<std::uint32_t> parent;
    ChunkedArray<std::uint32_t> depth;
    ChunkedArray<std::uint16_t> stepRaw;
    using Edge = StateEdge;
    EdgeStore edges;
    int stepOfState(std::size_t state) const { return static_cast<int>(stepRaw[state]) - 1; }
    std::uint32_t addState(const State& state, std::size_t from);
    std::set<std::string> eventKeys;
    std::map<std::string, std::pair<std::size_t, bool>> eventAt; // key -> (index in events, its scan fired a GEMMA transition)
    std::vector<char> firedGlobal; // by global transition: fires in some reachable scan
    std::vector<char> completeSeenByStep; // by step index: Exploration::completeSeen set for it
    std::vector<int> stepsWithTokens;     // nested steps with tokens: cleared at the end of a scan unless active
    struct FirstFire {
        bool seen = false;
        int step = -1;
        Witness witness;
    };
    std::vector<FirstFire> firstFire; // by global transition: the first (shortest) scan that fires it
    // GV104 pairs (step, (higher, lower)) found by a probe, while searching and after the exploration.
    std::set<std::pair<int, std::pair<std::size_t, std::size_t>>> overlapFound;
    // Options::searchFor: the keys found so far, and by step index the Overlap keys searched for.
    std::size_t searchedFound = 0;
    std::vector<std::vector<std::string>> searchedOverlaps;
    Exploration result;
    std::chrono::steady_clock::time_point started;
    std::size_t scansRun = 0;
};

// ---------------------------------------------------------------------------------------
// Compiling

ProgramExplorer::Impl::Impl(const Model& m, Options o)
    : model(m)
    , options(std::move(o))
    , program(buildGemmaProgram(m))
    , symbols(m.variables())
{
    cycleMs = m.settings().cycleTimeMs;
    compileSlots(m);
    compileMachine();
    compileSteps();
    compileFaults();
    compileProperties(m);
    compileWriteOnlyBools();
    for (const auto& [slot, list] : comparisons) {
        std::vector<sat::Atom> atoms;
        for (const auto& [op, constant] : list) {
            sat::Atom atom;
            atom.kind = sat::Atom::Kind::Comparison;
            atom.variable = slot;
            atom.constant = constant;
            using B = cond::BinaryOp;
            atom.relation = op == B::Less ? sat::Relation::Less
                : op == B::LessEqual      ? sat::Relation::LessEqual
                : op == B::Greater        ? sat::Relation::Greater
                : op == B::GreaterEqual   ? sat::Relation::GreaterEqual
                : op == B::Equal          ? sat::Relation::Equal
                                          : sat::Relation::NotEqual;
            atoms.push_back(atom);
        }
        std::vector<const sat::Atom*> pointers;
        for (const sat::Atom& atom : atoms)
            pointers.push_back(&atom);
        Slot& s = slots[static_cast<std::size_t>(slot)];
        if (s.cls == SlotClass::FreeNumber)
            s.representatives = sat::representatives(s.type, pointers);
    }
    for (Slot& s : slots) {
        if (s.cls == SlotClass::FreeNumber && s.representatives.empty())
            s.representatives = {s.initial};
        if (s.cls == SlotClass::FreeNumber && s.kind != VariableKind::Input && isRealType(s.type)) {
            const std::vector<cond::Value> beyond = sat::nonFiniteReals();
            s.representatives.insert(s.representatives.end(), beyond.begin(), beyond.end());
        }
    }
    boolCache.assign(slots.size(), -1);
    numberCache.assign(slots.size(), -1);
    writes.assign(slots.size(), {-1, false});
    numberPossible.assign(slots.size(), 0);
}

int ProgramExplorer::Impl::slotOf(std::string_view name) const
{
    auto it = slotByName.find(upper(name));
    return it == slotByName.end() ? -1 : it->second;
}

void ProgramExplorer::Impl::compileSlots(const Model& m)
{
    std::set<std::string> written;
    std::set<std::string> continuousTargets;
    for (const GemmaStep& step : program.steps) {
        if (!step.nested)
            continue;
        for (const std::string& target : step.nested->storedTargets)
            written.insert(upper(target));
        for (const ContinuousOutput& output : step.nested->outputs) {
            if (!output.isComplete) {
                written.insert(upper(output.variable));
                continuousTargets.insert(upper(output.variable));
            }
        }
    }
    for (const Variable& variable : m.variables()) {
        Slot slot;
        slot.name = variable.name;
        slot.type = variable.type;
        slot.kind = variable.kind;
        std::optional<cond::Value> value = cond::parseValue(variable.type, variable.defaultValue);
        if (!value)
            value = cond::parseValue(variable.type, "");
        slot.initial = value.value_or(cond::Value{false});
        slot.replayInitial = slot.initial;
        const bool isWritten = written.count(upper(variable.name)) > 0;
        if (variable.type == IecType::Bool) {
            slot.cls = variable.kind == VariableKind::Input ? SlotClass::FreeBool
                : isWritten                                  ? SlotClass::StateBool
                                                             : SlotClass::ConstBool;
        } else {
            slot.cls = variable.kind == VariableKind::Input || isWritten ? SlotClass::FreeNumber : SlotClass::ConstNumber;
        }
        if (slot.cls == SlotClass::StateBool) {
            slot.stateBit = static_cast<int>(stateBoolSlots.size());
            stateBoolSlots.push_back(static_cast<int>(slots.size()));
        }
        if (variable.kind == VariableKind::Output && variable.type == IecType::Bool && isWritten)
            outputsToCheckOnD1.push_back(static_cast<int>(slots.size()));
        slotByName.emplace(upper(variable.name), static_cast<int>(slots.size()));
        slots.push_back(std::move(slot));
    }
    slotRead.assign(slots.size(), 0);
    for (const std::string& name : program.edgeVariables) {
        const int s = slotOf(name);
        noteRead(s);
        if (s < 0)
            continue;
        slots[static_cast<std::size_t>(s)].edge = static_cast<int>(edgeSlots.size());
        edgeSlots.push_back(s);
    }
    bool abstractedNumbers = false;
    for (const Slot& slot : slots) {
        if (slot.cls == SlotClass::FreeNumber && slot.kind != VariableKind::Input) {
            if (!abstractedNumbers)
                result.abstractions.push_back("numeric variables written by actions take any value of their type");
            abstractedNumbers = true;
        }
    }
}

// After every expression is compiled: which state BOOLs nothing reads.
// Outputs always count as read: the machine, the D1 rule (GV119) and the
// user look at them.
void ProgramExplorer::Impl::compileWriteOnlyBools()
{
    if (!options.hideWriteOnlyVariables)
        return;
    for (int s : stateBoolSlots) {
        Slot& slot = slots[static_cast<std::size_t>(s)];
        if (slot.kind == VariableKind::Output || slotRead[static_cast<std::size_t>(s)] || slot.edge >= 0)
            continue;
        slot.writeOnly = true;
        writeOnlyBools.emplace_back(layout.bools + slot.stateBit, cond::isTrue(slot.initial) ? 1 : 0);
    }
}

// Closed loop: the variables wired as MachineLoop wires them (a BOOL output
// to an actuator role, a BOOL input to a sensor or operator role); the
// inputs a sensor writes are no longer free.
void ProgramExplorer::Impl::compileMachine()
{
    if (!options.machine || options.machine->empty())
        return;
    const auto wire = [&](std::string_view name, machine::SignalDirection direction) {
        const int s = slotOf(name);
        if (s < 0)
            return -1;
        const Slot& slot = slots[static_cast<std::size_t>(s)];
        const VariableKind wanted
            = direction == machine::SignalDirection::Actuator ? VariableKind::Output : VariableKind::Input;
        return slot.type == IecType::Bool && slot.kind == wanted ? s : -1;
    };
    machineState.emplace(*options.machine, cycleMs, wire);
    singleFaults = options.singleFaults;
    if (!options.exactTime) {
        abstractMachine.emplace(*options.machine, *machineState, cycleMs, wire);
        result.abstractions.push_back("machine travels and delays longer than one cycle may or may not have ended");
    }
    const std::vector<machine::SignalSlot>& table = machineState->signalSlots();
    for (std::size_t i = 0; i < table.size(); ++i) {
        Slot& slot = slots[static_cast<std::size_t>(table[i].variable)];
        switch (table[i].direction) {
        case machine::SignalDirection::Sensor:
            slot.cls = SlotClass::MachineBool;
            slot.machineSignal = static_cast<int>(i);
            break;
        case machine::SignalDirection::Operator: slot.replayInitial = machineState->signal(i); break;
        case machine::SignalDirection::Actuator: actuators.emplace_back(i, table[i].variable); break;
        }
    }
    if (abstractMachine)
        abstractMachine->appendKey(machineStart);
    else
        machineState->appendKey(machineStart);
}

// Single faults: every sensor the machine drives stuck TRUE, stuck FALSE or
// flickering (signal table order), then every cylinder and conveyor jammed
// (component order), as MachineLoop::applyFault applies them.
void ProgramExplorer::Impl::compileFaults()
{
    if (!singleFaults)
        return;
    const std::vector<machine::SignalSlot>& table = machineState->signalSlots();
    for (std::size_t i = 0; i < table.size(); ++i) {
        if (table[i].direction != machine::SignalDirection::Sensor)
            continue;
        const std::string& name = slots[static_cast<std::size_t>(table[i].variable)].name;
        for (machine::FaultKind kind :
             {machine::FaultKind::StuckTrue, machine::FaultKind::StuckFalse, machine::FaultKind::Flicker})
            faultChoices.push_back(FaultChoice{machine::Fault{kind, name}, static_cast<int>(i), -1});
    }
    const std::vector<machine::Component>& components = options.machine->components;
    for (std::size_t c = 0; c < components.size(); ++c) {
        if (machine::canJam(components[c].kind))
            faultChoices.push_back(
                FaultChoice{machine::Fault{machine::FaultKind::Jam, components[c].name}, -1, static_cast<int>(c)});
    }
    result.faultChoices = faultChoices.size();
}

std::uint32_t ProgramExplorer::Impl::faultField(int offset, int bytes) const
{
    std::uint32_t value = 0;
    for (int b = bytes - 1; b >= 0; --b)
        value = (value << 8) | static_cast<unsigned char>(work[static_cast<std::size_t>(layout.fault + offset + b)]);
    return value;
}

void ProgramExplorer::Impl::setFaultField(int offset, int bytes, std::uint32_t value)
{
    for (int b = 0; b < bytes; ++b, value >>= 8)
        work[static_cast<std::size_t>(layout.fault + offset + b)] = static_cast<char>(value & 0xFF);
}

// Before the scan, the machine restored: with no fault in effect, a choice
// of the fault that begins here (or none); then the fault in effect for
// this scan's readings and the machine's next cycle.
void ProgramExplorer::Impl::beginFaults()
{
    faultSignal = -1;
    if (layout.fault < 0 || faultChoices.empty())
        return;
    std::uint32_t fault = faultField(0, 4);
    const bool begins = fault == 0;
    if (begins) {
        const int value = chooser.choose(static_cast<int>(faultChoices.size()) + 1);
        chooser.decisions.push_back({Decision::Kind::Fault, -1, value});
        fault = static_cast<std::uint32_t>(value);
        setFaultField(0, 4, fault);
    }
    for (const FaultChoice& choice : faultChoices) {
        if (choice.component < 0)
            continue;
        const bool jammed = fault > 0 && &faultChoices[fault - 1] == &choice;
        if (abstractMachine)
            abstractMachine->setJammed(static_cast<std::size_t>(choice.component), jammed);
        else
            machineState->setJammed(static_cast<std::size_t>(choice.component), jammed);
    }
    if (fault == 0)
        return;
    const FaultChoice& choice = faultChoices[fault - 1];
    faultSignal = choice.signal;
    faultKind = choice.fault.kind;
    if (begins && faultKind == machine::FaultKind::Flicker) {
        // The opposite of what the scan would have read (MachineLoop::writeReading).
        const auto signal = static_cast<std::size_t>(choice.signal);
        const bool reading = abstractMachine ? abstractMachine->signal(signal) : machineState->signal(signal);
        work[static_cast<std::size_t>(layout.fault + 4)] = reading ? 0 : 1;
    }
    if (faultScanLimit > 0)
        setFaultField(5, 4, static_cast<std::uint32_t>(
                                std::min<std::int64_t>(faultField(5, 4) + 1, faultScanLimit)));
}

// What the program reads of the sensor under the fault in effect.
bool ProgramExplorer::Impl::faultedSensor(bool machineValue) const
{
    switch (faultKind) {
    case machine::FaultKind::StuckTrue: return true;
    case machine::FaultKind::StuckFalse: return false;
    case machine::FaultKind::Flicker: return work[static_cast<std::size_t>(layout.fault + 4)] != 0;
    default: return machineValue;
    }
}

void ProgramExplorer::Impl::compileSteps()
{
    for (std::size_t i = 0; i < program.steps.size(); ++i) {
        const GemmaStep& g = program.steps[i];
        if (g.id == program.initialStepId)
            initialStep = static_cast<int>(i);
        if (g.id == "D1")
            d1Step = static_cast<int>(i);
    }
    std::map<std::string, int> tokenByName;
    for (const GemmaStep& g : program.steps) {
        CompiledStep step;
        step.source = &g;
        step.nested = g.hasNestedBehaviour();
        auto assumption = options.complete.find(g.id);
        step.freeComplete = assumption == options.complete.end() || assumption->second == CompleteAssumption::Free;
        step.firstToken = static_cast<int>(tokens.size());
        step.tokenCount = static_cast<int>(g.tokens.size());
        for (const GemmaToken& token : g.tokens) {
            tokenByName.emplace(token.name, static_cast<int>(tokens.size()));
            tokens.push_back({slotOf(token.variable), token.polarity == TokenPolarity::NormallyClosed});
            noteRead(tokens.back().slot);
        }
        steps.push_back(std::move(step));
    }
    layout.tokens = 3;
    for (CompiledStep& step : steps) {
        for (const GemmaTransition& t : step.source->transitions) {
            auto known = std::find(transitionIds.begin(), transitionIds.end(), t.id);
            const int global = known == transitionIds.end() ? static_cast<int>(transitionIds.size())
                                                             : static_cast<int>(known - transitionIds.begin());
            if (known == transitionIds.end()) {
                transitionIds.push_back(t.id);
                transitionSources.push_back(&t);
            }
            CompiledTransition compiled;
            compiled.source = &t;
            compiled.globalIndex = global;
            for (std::size_t s = 0; s < program.steps.size(); ++s) {
                if (program.steps[s].id == t.targetId)
                    compiled.target = static_cast<int>(s);
            }
            if (t.conditionUsable) {
                std::map<int, std::string> substitutions;
                for (const auto& [node, name] : t.substitutions) {
                    auto token = tokenByName.find(name);
                    if (token != tokenByName.end())
                        substitutions.emplace(node, std::to_string(token->second));
                }
                compiled.condition = info(t.condition.expression, &substitutions, &step, nullptr, nullptr);
            }
            step.transitions.push_back(compiled);
        }
        if (step.source->nested)
            compileGrafcet(step);
    }
    int maxX = 0, maxOutputs = 0, maxTimers = 0;
    std::int64_t maxStored = 2; // abstract time: 0 stopped, 1 running, 2 elapsed
    for (const CompiledGrafcet& g : grafcets) {
        maxX = std::max(maxX, static_cast<int>(g.numbers.size()));
        maxOutputs = std::max(maxOutputs, static_cast<int>(g.source->outputs.size()));
        maxTimers = std::max(maxTimers, static_cast<int>(g.timerStep.size()));
        if (options.exactTime) {
            for (std::int64_t limit : g.timerCountLimit)
                maxStored = std::max(maxStored, limit + 1); // + 1: elapsed, for a TON counted partly
        }
    }
    // Two bytes as before whenever they suffice: the states stay as small.
    layout.timerBytes = maxStored <= 0xFFFF ? 2 : 4;
    layout.x = layout.tokens + static_cast<int>(tokens.size());
    layout.outputs = layout.x + maxX;
    layout.complete = layout.outputs + maxOutputs;
    layout.timers = layout.complete + 1;
    layout.bools = layout.timers + layout.timerBytes * maxTimers;
    layout.prev = layout.bools + static_cast<int>(stateBoolSlots.size());
    layout.size = layout.prev + static_cast<int>(edgeSlots.size());
    if (singleFaults) {
        layout.fault = layout.size;
        layout.size += kExplorerFaultBytes;
    }
    timerCache.assign(static_cast<std::size_t>(maxTimers), -1);
    failSeen.assign(transitionIds.size(), 0);
    firedGlobal.assign(transitionIds.size(), 0);
    completeSeenByStep.assign(steps.size(), 0);
    for (std::size_t s = 0; s < steps.size(); ++s) {
        if (steps[s].nested && steps[s].tokenCount > 0)
            stepsWithTokens.push_back(static_cast<int>(s));
    }
    firstFire.assign(transitionIds.size(), FirstFire{});
}

void ProgramExplorer::Impl::compileGrafcet(CompiledStep& step)
{
    const NestedGrafcet& nested = *step.source->nested;
    CompiledGrafcet g;
    g.source = &nested;
    for (const NestedStep& s : nested.steps) {
        g.numbers.push_back(s.number);
        g.initial.push_back(s.initial);
    }
    for (std::size_t o = 0; o < nested.outputs.size(); ++o) {
        if (nested.outputs[o].isComplete)
            g.completeOutput = static_cast<int>(o);
        else
            g.ownOutput.emplace(upper(nested.outputs[o].variable), static_cast<int>(o));
    }
    bool longTimer = false, countedPartly = false;
    for (const NestedTimer& timer : nested.timers) {
        g.timerStep.push_back(g.stepIndex(timer.step));
        g.timerShort.push_back(timer.durationMs <= cycleMs);
        const std::int64_t runs = tonscans::runsToElapse(timer.durationMs, cycleMs);
        g.timerRuns.push_back(runs);
        g.timerCountLimit.push_back(tonscans::countLimit(runs, options.maxCountedTimerRuns));
        longTimer = longTimer || timer.durationMs > cycleMs;
        countedPartly = countedPartly || tonscans::countedPartly(runs, options.maxCountedTimerRuns);
    }
    const auto note = [&](const std::string& line) {
        if (std::find(result.abstractions.begin(), result.abstractions.end(), line) == result.abstractions.end())
            result.abstractions.push_back(line);
    };
    if (longTimer && !options.exactTime)
        note("timers longer than one cycle may or may not have elapsed");
    if (countedPartly && options.exactTime)
        note("timers longer than " + std::to_string(options.maxCountedTimerRuns)
             + " scans are counted up to that many, then may or may not have elapsed");
    g.timersOfStep.resize(g.numbers.size());
    for (std::size_t t = 0; t < g.timerStep.size(); ++t) {
        if (g.timerStep[t] >= 0)
            g.timersOfStep[static_cast<std::size_t>(g.timerStep[t])].push_back(static_cast<int>(t));
    }
    grafcets.push_back(std::move(g));
    step.grafcet = static_cast<int>(grafcets.size()) - 1;
    CompiledGrafcet& compiled = grafcets.back();
    auto actions = [&](const std::vector<NestedAction>& list) {
        std::vector<CompiledAction> out;
        for (const NestedAction& action : list) {
            if (!action.usable)
                continue;
            CompiledAction a;
            a.source = &action;
            a.complete = action.targetIsComplete;
            if (!a.complete) {
                const int s = slotOf(action.target);
                if (s < 0 || slots[static_cast<std::size_t>(s)].cls != SlotClass::StateBool)
                    continue; // numeric targets are abstracted; inputs stay free
                a.slot = s;
            }
            if (action.parsed.action.form == cond::ActionForm::Assign)
                a.value = info(action.parsed.action.value, nullptr, &step, &compiled, nullptr);
            out.push_back(a);
        }
        return out;
    };
    for (const NestedStep& s : nested.steps) {
        compiled.onActivation.push_back(actions(s.onActivation));
        compiled.onDeactivation.push_back(actions(s.onDeactivation));
        std::vector<const ExpressionInfo*> conditions;
        for (const NestedAction& action : s.continuous) {
            const cond::Expression& condition = action.parsed.action.condition;
            conditions.push_back(condition.empty() || !action.usable
                                     ? nullptr
                                     : info(condition, nullptr, &step, &compiled, nullptr));
        }
        compiled.continuous.push_back(std::move(conditions));
    }
    for (const auto& output : nested.outputs) {
        std::vector<std::pair<int, const ExpressionInfo*>> drivers;
        for (const auto& driver : output.drivers) {
            const int i = compiled.stepIndex(driver.step);
            const auto u = [](int k) { return static_cast<std::size_t>(k); };
            if (i >= 0 && nested.steps[u(i)].continuous[u(driver.action)].usable)
                drivers.emplace_back(i, compiled.continuous[u(i)][u(driver.action)]);
        }
        compiled.outputDrivers.push_back(std::move(drivers));
    }
    for (const NestedTransition& t : nested.transitions) {
        CompiledNestedTransition c;
        c.source = &t;
        for (int n : t.upstream)
            c.upstream.push_back(compiled.stepIndex(n));
        for (int n : t.downstream)
            c.downstream.push_back(compiled.stepIndex(n));
        if (t.usable)
            c.receptivity = info(t.receptivity.expression, nullptr, &step, &compiled, &t.timerOfNode);
        compiled.transitions.push_back(std::move(c));
    }
    compiled.transitionsFrom.resize(compiled.numbers.size());
    for (std::size_t t = 0; t < compiled.transitions.size(); ++t) {
        const CompiledNestedTransition& c = compiled.transitions[t];
        if (!c.receptivity)
            continue; // never fires
        if (c.upstream.empty())
            compiled.transitionsWithoutUpstream.push_back(static_cast<int>(t));
        // One upstream step is enough to find it: it is enabled only when all are active.
        if (!c.upstream.empty() && c.upstream.front() >= 0)
            compiled.transitionsFrom[static_cast<std::size_t>(c.upstream.front())].push_back(static_cast<int>(t));
    }
    nestedActiveSeen.push_back(FlagSet{std::vector<char>(compiled.numbers.size(), 0)});
    nestedFiredSeen.push_back(FlagSet{std::vector<char>(compiled.transitions.size(), 0)});
    evolution.stepMark.resize(std::max(evolution.stepMark.size(), compiled.numbers.size()), 0);
    evolution.firstFiringFrom.resize(std::max(evolution.firstFiringFrom.size(), compiled.numbers.size()), -1);
    const int stepIndex = static_cast<int>(&step - steps.data());
    for (std::size_t o = 0; o < nested.outputs.size(); ++o) {
        if (nested.outputs[o].isComplete)
            continue;
        const int s = slotOf(nested.outputs[o].variable);
        auto found = std::find_if(outputWrites.begin(), outputWrites.end(),
                                  [s](const OutputWrite& w) { return w.slot == s; });
        if (found == outputWrites.end()) {
            outputWrites.push_back({s, {}});
            found = outputWrites.end() - 1;
        }
        found->drivers.push_back({stepIndex, static_cast<int>(o)});
    }
}

void ProgramExplorer::Impl::compileProperties(const Model& m)
{
    parsedProperties.reserve(options.properties.size()); // the infos point into it
    compilingProperty = true;
    for (const std::string& text : options.properties) {
        parsedProperties.push_back(parseProperty(text));
        const bool usable
            = parsedProperties.back().ok() && checkProperty(m, text, PropertyAtoms{singleFaults}).empty();
        result.propertyChecked.push_back(usable);
        propertyInfos.push_back(usable ? info(parsedProperties.back().expression, nullptr, nullptr, nullptr, nullptr)
                                       : nullptr);
    }
    compilingProperty = false;
}

void ProgramExplorer::Impl::collectComparisons(const cond::Expression& expression)
{
    for (const cond::Node& node : expression.nodes) {
        if (node.kind != cond::NodeKind::Binary || !isComparison(node.binaryOp))
            continue;
        const cond::Node& left = expression.at(node.left);
        const cond::Node& right = expression.at(node.right);
        auto constantValue = [&](int n) -> std::optional<cond::Value> {
            cond::Expression sub{expression.nodes, n};
            bool reads = false;
            const cond::Value value = cond::evaluate(sub, [&](int) {
                reads = true;
                return cond::Value{false};
            });
            if (reads)
                return std::nullopt;
            return value;
        };
        auto record = [&](const cond::Node& variable, int other, cond::BinaryOp op) {
            if (variable.kind != cond::NodeKind::Variable)
                return;
            const int s = slotOf(variable.text);
            if (s < 0 || slots[static_cast<std::size_t>(s)].type == IecType::Bool)
                return;
            if (std::optional<cond::Value> constant = constantValue(other))
                comparisons[s].emplace_back(op, *constant);
        };
        using B = cond::BinaryOp;
        const B mirrored = node.binaryOp == B::Less  ? B::Greater
            : node.binaryOp == B::Greater            ? B::Less
            : node.binaryOp == B::LessEqual          ? B::GreaterEqual
            : node.binaryOp == B::GreaterEqual       ? B::LessEqual
                                                     : node.binaryOp;
        record(left, node.right, node.binaryOp);
        record(right, node.left, mirrored);
    }
}

const ExpressionInfo* ProgramExplorer::Impl::info(const cond::Expression& expression,
                                                  const std::map<int, std::string>* substitutions,
                                                  const CompiledStep* step, const CompiledGrafcet* grafcet,
                                                  const std::map<int, int>* timerOfNode)
{
    (void)step;
    collectComparisons(expression);
    const auto ownOutputOf = [&](NodeInfo& n, const std::string& name) {
        if (!grafcet)
            return;
        n.owner = static_cast<int>(grafcet - grafcets.data());
        auto own = grafcet->ownOutput.find(upper(name));
        n.ownOutput = own == grafcet->ownOutput.end() ? -1 : own->second;
    };
    auto out = std::make_unique<ExpressionInfo>();
    out->expression = &expression;
    out->nodes.resize(expression.nodes.size());
    for (std::size_t i = 0; i < expression.nodes.size(); ++i) {
        const cond::Node& node = expression.nodes[i];
        NodeInfo& n = out->nodes[i];
        const int index = static_cast<int>(i);
        if (substitutions && substitutions->count(index)) {
            n.role = NodeRole::Token;
            n.index = std::stoi(substitutions->at(index));
            continue;
        }
        switch (node.kind) {
        case cond::NodeKind::BoolLiteral:
            n.role = NodeRole::Literal;
            n.literalTrue = upper(node.text) == "TRUE";
            break;
        case cond::NodeKind::Variable: {
            if (compilingProperty && isFaultedAtom(model, node)) {
                n.role = NodeRole::Faulted;
                break;
            }
            n.slot = slotOf(node.text);
            n.role = NodeRole::BoolRead;
            noteRead(n.slot);
            ownOutputOf(n, node.text);
            break;
        }
        case cond::NodeKind::StepActivity:
            n.role = NodeRole::Step;
            n.index = node.number;
            break;
        case cond::NodeKind::StepDuration: {
            if (compilingProperty && isFaultedAtom(model, node)) {
                n.role = NodeRole::FaultTime;
                n.index = static_cast<int>(std::min<std::int64_t>(faultedScansFor(node.durationMs, cycleMs), INT32_MAX));
                faultScanLimit = std::max<std::int64_t>(faultScanLimit, n.index);
                break;
            }
            n.role = NodeRole::Duration;
            n.index = -1;
            if (timerOfNode) {
                auto it = timerOfNode->find(index);
                if (it != timerOfNode->end())
                    n.index = it->second;
            }
            break;
        }
        case cond::NodeKind::Complete: n.role = NodeRole::Complete; break;
        case cond::NodeKind::InStep: {
            n.role = NodeRole::InStep;
            const std::string id = propertyStepId(model, node.text);
            for (std::size_t s = 0; s < program.steps.size(); ++s) {
                if (program.steps[s].id == id)
                    n.index = static_cast<int>(s);
            }
            break;
        }
        case cond::NodeKind::NestedStepActivity: {
            n.role = NodeRole::NestedStep;
            const std::string id = propertyStepId(model, node.text);
            for (std::size_t s = 0; s < program.steps.size(); ++s) {
                if (program.steps[s].id == id)
                    n.step = static_cast<int>(s);
            }
            n.index = node.number;
            break;
        }
        case cond::NodeKind::Unary:
            if (node.unaryOp == cond::UnaryOp::Not) {
                n.role = NodeRole::Logical;
            } else if (node.unaryOp == cond::UnaryOp::RisingEdge || node.unaryOp == cond::UnaryOp::FallingEdge) {
                n.role = NodeRole::Edge;
                n.slot = slotOf(expression.at(node.operand).text);
                ownOutputOf(n, expression.at(node.operand).text);
            }
            break;
        case cond::NodeKind::Binary: {
            using B = cond::BinaryOp;
            const B op = node.binaryOp;
            const bool boolOperands = cond::valueKind(expression, node.left, symbols) == cond::ValueKind::Bool;
            if (op == B::And || op == B::Or || op == B::Xor || op == B::Implies
                || ((op == B::Equal || op == B::NotEqual) && boolOperands)) {
                n.role = NodeRole::Logical;
                break;
            }
            if (!isComparison(op))
                break; // arithmetic: read inside a comparison only
            std::set<int> numeric; // every numeric variable it reads
            bool other = false;
            std::vector<int> stack{index};
            while (!stack.empty()) {
                const int at = stack.back();
                stack.pop_back();
                const cond::Node& sub = expression.at(at);
                if (sub.kind == cond::NodeKind::Variable) {
                    const int s = slotOf(sub.text);
                    if (s >= 0 && slots[static_cast<std::size_t>(s)].type != IecType::Bool)
                        numeric.insert(s);
                    else
                        other = true;
                } else if (sub.kind == cond::NodeKind::Unary) {
                    stack.push_back(sub.operand);
                } else if (sub.kind == cond::NodeKind::Binary) {
                    stack.push_back(sub.left);
                    stack.push_back(sub.right);
                } else if (sub.kind != cond::NodeKind::IntegerLiteral && sub.kind != cond::NodeKind::RealLiteral) {
                    other = true;
                }
            }
            // Only a bare variable against a constant is decided exactly
            // (core/verification/comparisonshape.h): a division by a variable
            // is never one, so its possible fault or INF / NaN stays free.
            const bool direct = verification::isVariableAgainstConstant(expression, index);
            if (!other && numeric.size() <= 1 && (numeric.empty() || direct)) {
                n.role = NodeRole::Exact;
                n.slot = numeric.empty() ? -1 : *numeric.begin();
                n.sub = std::make_shared<cond::Expression>(cond::Expression{expression.nodes, index});
            } else {
                n.role = NodeRole::Opaque;
                n.text = canonicalComparison(expression, index, n.negated);
                const std::string note
                    = "comparison read as a free BOOL: " + cond::print(cond::Expression{expression.nodes, index});
                if (std::find(result.abstractions.begin(), result.abstractions.end(), note) == result.abstractions.end())
                    result.abstractions.push_back(note);
            }
            break;
        }
        default: break;
        }
    }
    (void)grafcet;
    infos.push_back(std::move(out));
    return infos.back().get();
}

// ---------------------------------------------------------------------------------------
// One scan

namespace {

int stepIndexOf(const State& state)
{
    const int raw = static_cast<unsigned char>(state[0]) | (static_cast<unsigned char>(state[1]) << 8);
    return raw - 1;
}

void setStepIndex(State& state, int index)
{
    const int raw = index + 1;
    state[0] = static_cast<char>(raw & 0xFF);
    state[1] = static_cast<char>((raw >> 8) & 0xFF);
}

} // namespace

State ProgramExplorer::Impl::initialState() const
{
    State state(static_cast<std::size_t>(layout.size), '\0');
    state += machineStart;
    setStepIndex(state, initialStep);
    state[2] = 1; // Entry
    for (const Slot& slot : slots) {
        if (slot.stateBit >= 0)
            state[static_cast<std::size_t>(layout.bools + slot.stateBit)] = cond::isTrue(slot.initial) ? 1 : 0;
        if (slot.edge >= 0)
            state[static_cast<std::size_t>(layout.prev + slot.edge)]
                = slot.type == IecType::Bool && cond::isTrue(slot.initial) ? 1 : 0;
    }
    return state;
}

bool ProgramExplorer::Impl::choose(Decision::Kind kind, int slot)
{
    const int value = chooser.choose(2);
    chooser.decisions.push_back({kind, slot, value});
    return value != 0;
}

bool ProgramExplorer::Impl::readBool(int slot)
{
    if (slot < 0)
        return false;
    const Slot& s = slots[static_cast<std::size_t>(slot)];
    switch (s.cls) {
    case SlotClass::StateBool:
        assert(!s.writeOnly && "a variable hidden as write-only is read"); // compileWriteOnlyBools missed a reader
        return work[static_cast<std::size_t>(layout.bools + s.stateBit)] != 0;
    case SlotClass::ConstBool: return cond::isTrue(s.initial);
    case SlotClass::MachineBool: {
        const auto signal = static_cast<std::size_t>(s.machineSignal);
        const bool value = abstractMachine ? abstractMachine->signal(signal) : machineState->signal(signal);
        return s.machineSignal == faultSignal ? faultedSensor(value) : value;
    }
    case SlotClass::FreeBool: {
        int& cached = boolCache[static_cast<std::size_t>(slot)];
        if (cached < 0)
            cached = choose(Decision::Kind::Bool, slot) ? 1 : 0;
        return cached != 0;
    }
    default: return cond::isTrue(readNumber(slot));
    }
}

cond::Value ProgramExplorer::Impl::readNumber(int slot)
{
    if (slot < 0)
        return std::int64_t{0};
    const Slot& s = slots[static_cast<std::size_t>(slot)];
    if (s.cls != SlotClass::FreeNumber) {
        if (s.type == IecType::Bool)
            return readBool(slot);
        return s.initial;
    }
    int& cached = numberCache[static_cast<std::size_t>(slot)];
    if (cached < 0) {
        std::uint64_t& possible = numberPossible[static_cast<std::size_t>(slot)];
        if (possible != 0) {
            // Comparisons already narrowed it: one of the values left.
            const int k = chooser.choose(std::popcount(possible));
            std::uint64_t bits = possible;
            for (int i = 0; i < k; ++i)
                bits &= bits - 1;
            cached = std::countr_zero(bits);
            possible = std::uint64_t{1} << cached;
        } else {
            cached = chooser.choose(static_cast<int>(s.representatives.size()));
        }
        chooser.decisions.push_back({Decision::Kind::Number, slot, cached});
    }
    return s.representatives[static_cast<std::size_t>(cached)];
}

// `Speed > 10` on a free Speed: TRUE or FALSE as the values still possible
// allow, narrowing them, so that a scan branches on the comparisons it
// evaluates rather than on every value of every variable it reads.
bool ProgramExplorer::Impl::testNumber(const ExpressionInfo& info, const NodeInfo& n)
{
    const Slot& s = slots[static_cast<std::size_t>(n.slot)];
    const std::uint64_t all = s.representatives.size() == 64 ? ~std::uint64_t{0}
                                                              : (std::uint64_t{1} << s.representatives.size()) - 1;
    if (!n.truthKnown) {
        for (std::size_t i = 0; i < s.representatives.size(); ++i) {
            const bool holds = cond::isTrue(cond::evaluate(*n.sub, [&](int leaf) -> cond::Value {
                const int read = slotOf(info.expression->at(leaf).text);
                return read == n.slot ? s.representatives[i] : readNumber(read);
            }));
            if (holds)
                n.truth |= std::uint64_t{1} << i;
        }
        n.truthKnown = true;
    }
    std::uint64_t& possible = numberPossible[static_cast<std::size_t>(n.slot)];
    const int cached = numberCache[static_cast<std::size_t>(n.slot)];
    if (cached >= 0)
        return (n.truth >> cached) & 1;
    const std::uint64_t current = possible == 0 ? all : possible;
    const std::uint64_t whenTrue = current & n.truth;
    const std::uint64_t whenFalse = current & ~n.truth;
    if (whenFalse == 0 || whenTrue == 0)
        return whenFalse == 0;
    const bool value = choose(Decision::Kind::NumberTest, n.slot);
    possible = value ? whenTrue : whenFalse;
    return value;
}

// The index among the active GRAFCET's outputs of the variable a node reads,
// -1 when not one of them: compiled for the expressions of that GRAFCET,
// looked up by name for any other (none is evaluated while it is active).
int ProgramExplorer::Impl::ownOutputIndex(const NodeInfo& n, const std::string& name) const
{
    if (n.owner >= 0 && &grafcets[static_cast<std::size_t>(n.owner)] == activeGrafcet)
        return n.ownOutput;
    auto own = activeGrafcet->ownOutput.find(upper(name));
    return own == activeGrafcet->ownOutput.end() ? -1 : own->second;
}

bool ProgramExplorer::Impl::eval(const ExpressionInfo& info, int node)
{
    if (!info.expression || info.expression->root < 0)
        return false;
    return evalNode(info, node < 0 ? info.expression->root : node);
}

bool ProgramExplorer::Impl::evalNode(const ExpressionInfo& info, int index)
{
    const cond::Node& node = info.expression->at(index);
    const NodeInfo& n = info.nodes[static_cast<std::size_t>(index)];
    const auto u = [](int i) { return static_cast<std::size_t>(i); };
    switch (n.role) {
    case NodeRole::Literal: return n.literalTrue;
    case NodeRole::BoolRead: {
        if (activeGrafcet && !propertyPhase) {
            const int own = ownOutputIndex(n, node.text);
            if (own >= 0)
                return work[u(layout.outputs + own)] != 0;
        }
        return readBool(n.slot);
    }
    case NodeRole::Token: return work[u(layout.tokens + n.index)] != 0;
    case NodeRole::Step: {
        const int i = activeGrafcet ? activeGrafcet->stepIndex(n.index) : -1;
        return i >= 0 && work[u(layout.x + i)] != 0;
    }
    case NodeRole::Duration: {
        if (!activeGrafcet || n.index < 0)
            return false;
        const int i = activeGrafcet->stepIndex(node.number);
        return i >= 0 && work[u(layout.x + i)] != 0 && timerElapsed(n.index);
    }
    case NodeRole::Complete: return work[u(layout.complete)] != 0;
    case NodeRole::Faulted: return layout.fault >= 0 && faultField(0, 4) != 0;
    case NodeRole::FaultTime: return layout.fault >= 0 && faultField(0, 4) != 0 && faultField(5, 4) >= u(n.index);
    case NodeRole::Edge: {
        if (!firstEvolution || n.slot < 0)
            return false;
        const int own = activeGrafcet ? ownOutputIndex(n, info.expression->at(node.operand).text) : -1;
        const bool now = own >= 0 ? work[u(layout.outputs + own)] != 0 : readBool(n.slot);
        const int edge = slots[u(n.slot)].edge;
        const bool before = edge >= 0 && work[u(layout.prev + edge)] != 0;
        return node.unaryOp == cond::UnaryOp::RisingEdge ? now && !before : !now && before;
    }
    case NodeRole::InStep: return n.index >= 0 && newStep == n.index;
    case NodeRole::NestedStep: {
        if (n.step < 0 || newStep != n.step || work[2] != 0)
            return false;
        const CompiledStep& step = steps[u(n.step)];
        if (step.grafcet < 0)
            return false;
        const int i = grafcets[u(step.grafcet)].stepIndex(n.index);
        return i >= 0 && work[u(layout.x + i)] != 0;
    }
    case NodeRole::Exact:
        if (n.slot >= 0 && slots[u(n.slot)].cls == SlotClass::FreeNumber && slots[u(n.slot)].representatives.size() <= 64)
            return testNumber(info, n);
        return cond::isTrue(cond::evaluate(*n.sub, [&](int leaf) -> cond::Value {
            const cond::Node& variable = info.expression->at(leaf);
            return readNumber(slotOf(variable.text));
        }));
    case NodeRole::Opaque: {
        auto cached = opaqueCache.find(n.text);
        if (cached != opaqueCache.end())
            return cached->second != n.negated;
        const bool value = choose(Decision::Kind::Opaque, -1);
        opaqueCache.emplace(n.text, value);
        return value != n.negated;
    }
    case NodeRole::Logical: {
        if (node.kind == cond::NodeKind::Unary)
            return !evalNode(info, node.operand);
        using B = cond::BinaryOp;
        const bool left = evalNode(info, node.left);
        switch (node.binaryOp) {
        case B::And: return left && evalNode(info, node.right);
        case B::Or: return left || evalNode(info, node.right);
        case B::Implies: return !left || evalNode(info, node.right);
        case B::Xor:
        case B::NotEqual: return left != evalNode(info, node.right);
        case B::Equal: return left == evalNode(info, node.right);
        default: return false;
        }
    }
    case NodeRole::Other: return false;
    }
    return false;
}

// A TON's state: abstract 0 stopped, 1 running, 2 elapsed; exact: the runs
// with IN TRUE so far, up to timerCountLimit, and timerCountLimit + 1 once a
// TON counted partly was chosen elapsed.
std::int64_t ProgramExplorer::Impl::timerState(int timer) const
{
    const auto at = static_cast<std::size_t>(layout.timers + layout.timerBytes * timer);
    std::int64_t value = 0;
    for (int b = layout.timerBytes - 1; b >= 0; --b)
        value = (value << 8) | static_cast<unsigned char>(work[at + static_cast<std::size_t>(b)]);
    return value;
}

void ProgramExplorer::Impl::setTimerState(int timer, std::int64_t value)
{
    const auto at = static_cast<std::size_t>(layout.timers + layout.timerBytes * timer);
    for (int b = 0; b < layout.timerBytes; ++b)
        work[at + static_cast<std::size_t>(b)] = static_cast<char>((value >> (8 * b)) & 0xFF);
}

// The TON run before the first evolution, IN := Xn as the previous call left it.
void ProgramExplorer::Impl::runTimer(const CompiledGrafcet& g, int timer, bool in)
{
    const auto t = static_cast<std::size_t>(timer);
    if (logTimers)
        timerLog.in[t] = in ? 1 : 0;
    const std::int64_t state = timerState(timer);
    if (!in)
        setTimerState(timer, 0);
    else if (options.exactTime && state < g.timerCountLimit[t])
        setTimerState(timer, state + 1);
    else if (options.exactTime)
        ; // counted up to its limit, or chosen elapsed: stays
    else if (state == 0)
        setTimerState(timer, 1);
    else if (state == 1 && g.timerShort[t])
        setTimerState(timer, 2);
    timerCache[t] = -1;
}

bool ProgramExplorer::Impl::timerElapsed(int timer)
{
    const auto t = static_cast<std::size_t>(timer);
    const std::int64_t state = timerState(timer);
    if (options.exactTime) {
        const std::int64_t limit = activeGrafcet->timerCountLimit[t];
        if (!tonscans::countedPartly(activeGrafcet->timerRuns[t], limit))
            return state >= activeGrafcet->timerRuns[t];
        if (state != limit)
            return state > limit;
        // Counted as far as it goes, short of its duration: it may or may not have elapsed.
    } else {
        if (state == 2)
            return true;
        if (state != 1 || activeGrafcet->timerShort[t])
            return false;
    }
    if (timerCache[t] < 0) {
        timerCache[t] = choose(Decision::Kind::Timer, timer) ? 1 : 0;
        if (timerCache[t])
            setTimerState(timer, options.exactTime ? state + 1 : 2);
    }
    return timerCache[t] != 0;
}

void ProgramExplorer::Impl::noteActive(const CompiledStep& step)
{
    const CompiledGrafcet& g = grafcets[static_cast<std::size_t>(step.grafcet)];
    FlagSet& activeSeen = nestedActiveSeen[static_cast<std::size_t>(step.grafcet)];
    std::vector<int>& seen = activeSeen.list(result.activeNestedSteps, step.source->id);
    for (std::size_t i = 0; i < g.numbers.size(); ++i) {
        if (work[static_cast<std::size_t>(layout.x) + i])
            activeSeen.add(static_cast<int>(i), g.numbers[i], seen);
    }
}

// After an evolution: the steps active before it were noted when they entered.
void ProgramExplorer::Impl::noteEntered(const CompiledStep& step, const std::vector<int>& entered)
{
    const CompiledGrafcet& g = grafcets[static_cast<std::size_t>(step.grafcet)];
    FlagSet& activeSeen = nestedActiveSeen[static_cast<std::size_t>(step.grafcet)];
    std::vector<int>& seen = activeSeen.list(result.activeNestedSteps, step.source->id);
    for (int i : entered)
        activeSeen.add(i, g.numbers[static_cast<std::size_t>(i)], seen);
}

// The time limit and the cancel callback, looked at every kPollEvery units of
// work inside a scan (an evolution), so that even one scan of a GRAFCET of
// thousands of steps that never settles stops within the limit.
void ProgramExplorer::Impl::pollInsideScan()
{
    constexpr unsigned kPollEvery = 64;
    if (!polling || ++workSincePoll < kPollEvery)
        return;
    workSincePoll = 0;
    if (options.cancelled && options.cancelled()) {
        result.cancelled = true;
        throw Interrupted{};
    }
    if (std::chrono::steady_clock::now() > options.deadline)
        throw Interrupted{};
}

// A GEMMA transition's condition as the CASE reads it: AND Complete where it
// waits for it, FALSE when unusable.
bool ProgramExplorer::Impl::gated(const CompiledTransition& transition, bool complete)
{
    return transition.condition && (!transition.source->waitsForComplete || complete)
        && eval(*transition.condition, -1);
}

void ProgramExplorer::Impl::runProbe(const CompiledStep& step, bool complete)
{
    probeTrue.assign(step.transitions.size(), 0);
    for (std::size_t k = 0; k < step.transitions.size(); ++k) {
        const CompiledTransition& transition = step.transitions[k];
        probeTrue[k] = gated(transition, complete) ? 1 : 0;
        if (transition.condition && !probeTrue[k])
            failSeen[static_cast<std::size_t>(transition.globalIndex)] = 1;
    }
}

void ProgramExplorer::Impl::runStored(const CompiledStep& step, int stepIndex, const std::vector<CompiledAction>& actions,
                                      ScanOutcome& outcome)
{
    for (const CompiledAction& action : actions) {
        const cond::ActionForm form = action.source->parsed.action.form;
        const bool value = form == cond::ActionForm::Set ? true
            : form == cond::ActionForm::Reset            ? false
                                                         : (action.value && eval(*action.value, -1));
        if (action.complete) {
            work[static_cast<std::size_t>(layout.complete)] = value ? 1 : 0;
            continue;
        }
        const Slot& slot = slots[static_cast<std::size_t>(action.slot)];
        std::pair<int, bool>& previous = writes[static_cast<std::size_t>(action.slot)];
        if (previous.first >= 0 && previous.first != stepIndex && previous.second != value) {
            const CompiledGrafcet& g = grafcets[static_cast<std::size_t>(step.grafcet)];
            Event race;
            race.kind = EventKind::Race;
            race.stepId = step.source->id;
            const int a = g.numbers[static_cast<std::size_t>(previous.first)];
            const int b = g.numbers[static_cast<std::size_t>(stepIndex)];
            race.numbers = {std::min(a, b), std::max(a, b)};
            race.variable = slot.name;
            outcome.events.push_back(race);
        }
        if (previous.first < 0)
            writtenSlots.push_back(action.slot);
        previous = {stepIndex, value};
        work[static_cast<std::size_t>(layout.bools + slot.stateBit)] = value ? 1 : 0;
    }
}

void ProgramExplorer::Impl::computeOutputs(const CompiledGrafcet& g)
{
    const NestedGrafcet& nested = *g.source;
    std::vector<char>& values = outputValues;
    values.assign(nested.outputs.size(), 0);
    bool complete = work[static_cast<std::size_t>(layout.complete)] != 0;
    for (std::size_t o = 0; o < nested.outputs.size(); ++o) {
        bool value = false;
        for (const auto& [i, condition] : g.outputDrivers[o]) {
            if (!work[static_cast<std::size_t>(layout.x + i)])
                continue;
            if (!condition || eval(*condition, -1)) {
                value = true;
                break;
            }
        }
        if (nested.outputs[o].isComplete)
            complete = value;
        else
            values[o] = value;
    }
    for (std::size_t o = 0; o < values.size(); ++o)
        work[static_cast<std::size_t>(layout.outputs) + o] = values[o];
    work[static_cast<std::size_t>(layout.complete)] = complete ? 1 : 0;
}

void ProgramExplorer::Impl::initializationCall(const CompiledStep& step)
{
    const CompiledGrafcet& g = grafcets[static_cast<std::size_t>(step.grafcet)];
    ScanOutcome ignored;
    for (std::size_t i = 0; i < g.numbers.size(); ++i)
        work[static_cast<std::size_t>(layout.x) + i] = g.initial[i] ? 1 : 0;
    work[static_cast<std::size_t>(layout.complete)] = 0;
    for (std::size_t t = 0; t < g.timerStep.size(); ++t)
        setTimerState(static_cast<int>(t), 0);
    timerLog.initialized = true;
    for (std::size_t i = 0; i < g.numbers.size(); ++i) {
        if (g.initial[i])
            runStored(step, static_cast<int>(i), g.onActivation[i], ignored);
    }
    firstEvolution = false;
    computeOutputs(g);
    noteActive(step);
}

// One evolution (spec §4.2, rule 2): only the transitions leaving an active
// step are read, in transition order as the PLC's code reads them, so an
// evolution costs what is active, not the size of the GRAFCET.
bool ProgramExplorer::Impl::evolve(const CompiledStep& step, bool first, ScanOutcome& outcome)
{
    const CompiledGrafcet& g = grafcets[static_cast<std::size_t>(step.grafcet)];
    const auto u = [](int i) { return static_cast<std::size_t>(i); };
    pollInsideScan();
    firstEvolution = first;
    EvolutionScratch& e = evolution;
    e.candidates = g.transitionsWithoutUpstream;
    for (int i : e.active)
        e.candidates.insert(e.candidates.end(), g.transitionsFrom[u(i)].begin(), g.transitionsFrom[u(i)].end());
    std::sort(e.candidates.begin(), e.candidates.end());
    e.fired.clear();
    for (int t : e.candidates) {
        const CompiledNestedTransition& transition = g.transitions[u(t)];
        const bool enabled = std::all_of(transition.upstream.begin(), transition.upstream.end(),
                                         [&](int i) { return i >= 0 && work[u(layout.x + i)] != 0; });
        if (enabled && eval(*transition.receptivity, -1))
            e.fired.push_back(t);
    }
    if (e.fired.empty())
        return false;
    FlagSet& firedSeen = nestedFiredSeen[u(step.grafcet)];
    // e.firstFiringFrom: by upstream step index, the first fired transition leaving it (-1 none).
    e.deactivated.clear();
    e.activated.clear();
    for (int t : e.fired) {
        const int number = g.transitions[u(t)].source->number;
        firedSeen.add(t, number, firedSeen.list(result.firedNestedTransitions, step.source->id));
        for (int i : g.transitions[u(t)].upstream) {
            int& firstFrom = e.firstFiringFrom[u(i)];
            if (firstFrom >= 0) {
                Event together;
                together.kind = EventKind::SimultaneousBranches;
                together.stepId = step.source->id;
                together.numbers = {g.numbers[u(i)], g.transitions[u(firstFrom)].source->number, number};
                outcome.events.push_back(together);
            } else {
                firstFrom = t;
            }
            e.mark(e.deactivated, i, EvolutionScratch::kDeactivated);
        }
        for (int i : g.transitions[u(t)].downstream)
            e.mark(e.activated, i, EvolutionScratch::kActivated);
    }
    // Steps in index order, as the actions run: number order.
    std::sort(e.deactivated.begin(), e.deactivated.end());
    std::sort(e.activated.begin(), e.activated.end());
    e.left.clear();
    e.entered.clear();
    for (int i : e.deactivated) {
        if (!(e.stepMark[u(i)] & EvolutionScratch::kActivated))
            e.left.push_back(i);
    }
    for (int i : e.activated) {
        const bool active = work[u(layout.x + i)] != 0;
        if (!active)
            e.entered.push_back(i);
        if (active && !(e.stepMark[u(i)] & EvolutionScratch::kDeactivated)) {
            Event unsafe;
            unsafe.kind = EventKind::UnsafeStep;
            unsafe.stepId = step.source->id;
            unsafe.numbers = {g.numbers[u(i)]};
            outcome.events.push_back(unsafe);
        }
    }
    for (int i : e.deactivated) {
        e.stepMark[u(i)] = 0;
        e.firstFiringFrom[u(i)] = -1;
    }
    for (int i : e.activated)
        e.stepMark[u(i)] = 0;
    for (int i : e.left)
        work[u(layout.x + i)] = 0;
    for (int i : e.entered)
        work[u(layout.x + i)] = 1;
    e.updateActive();
    noteEntered(step, e.entered);
    firstEvolution = false;
    for (int i : e.left)
        runStored(step, i, g.onDeactivation[u(i)], outcome);
    for (int i : e.entered) {
        runStored(step, i, g.onActivation[u(i)], outcome);
        for (int timer : g.timersOfStep[u(i)]) {
            setTimerState(timer, 0);
            timerCache[u(timer)] = -1;
            if (logTimers)
                timerLog.reset[u(timer)] = 1;
        }
    }
    return true;
}

void ProgramExplorer::Impl::evolvingCall(const CompiledStep& step, ScanOutcome& outcome)
{
    const CompiledGrafcet& g = grafcets[static_cast<std::size_t>(step.grafcet)];
    // The TONs run once, before the first evolution, with Xn as the previous call left it.
    for (std::size_t t = 0; t < g.timerStep.size(); ++t) {
        const int i = g.timerStep[t];
        runTimer(g, static_cast<int>(t), i >= 0 && work[static_cast<std::size_t>(layout.x + i)] != 0);
    }
    evolution.active.clear();
    for (std::size_t i = 0; i < g.numbers.size(); ++i) {
        if (work[static_cast<std::size_t>(layout.x) + i])
            evolution.active.push_back(static_cast<int>(i));
    }
    const bool untilStable = g.source->rule == EvolutionRule::UntilStable;
    int evolutions = 0;
    bool fired = false;
    do {
        fired = evolve(step, evolutions == 0, outcome);
        ++evolutions;
    } while (untilStable && fired && evolutions < g.source->maxEvolutions);
    if (untilStable && fired) {
        Event unstable;
        unstable.kind = EventKind::Unstable;
        unstable.stepId = step.source->id;
        outcome.events.push_back(unstable);
    }
    firstEvolution = false;
    computeOutputs(g);
}

ScanOutcome ProgramExplorer::Impl::scan(const State& from, State& to)
{
    ScanOutcome outcome;
    work = from;
    if (abstractMachine)
        abstractMachine->restoreKey(std::string_view(from).substr(static_cast<std::size_t>(layout.size)));
    else if (machineState)
        machineState->restoreKey(std::string_view(from).substr(static_cast<std::size_t>(layout.size)));
    std::fill(boolCache.begin(), boolCache.end(), -1);
    std::fill(numberCache.begin(), numberCache.end(), -1);
    std::fill(numberPossible.begin(), numberPossible.end(), 0);
    std::fill(timerCache.begin(), timerCache.end(), -1);
    beginFaults();
    if (logTimers) {
        timerLog.in.assign(timerCache.size(), -1);
        timerLog.reset.assign(timerCache.size(), 0);
        timerLog.initialized = false;
    }
    opaqueCache.clear();
    for (int slot : writtenSlots)
        writes[static_cast<std::size_t>(slot)] = {-1, false};
    writtenSlots.clear();
    propertyPhase = false;
    activeGrafcet = nullptr;
    const auto u = [](int i) { return static_cast<std::size_t>(i); };
    const int active = stepIndexOf(work);
    newStep = active;
    if (active >= 0) {
        const CompiledStep& step = steps[u(active)];
        activeStep = &step;
        bool complete = false;
        if (step.nested) {
            if (step.grafcet >= 0) {
                activeGrafcet = &grafcets[u(step.grafcet)];
                if (work[2]) {
                    initializationCall(step);
                    work[2] = 0;
                    for (int t = 0; t < step.tokenCount; ++t)
                        work[u(layout.tokens + step.firstToken + t)] = 0;
                }
                evolvingCall(step, outcome);
                complete = work[u(layout.complete)] != 0;
            } else {
                if (work[2]) {
                    work[2] = 0;
                    for (int t = 0; t < step.tokenCount; ++t)
                        work[u(layout.tokens + step.firstToken + t)] = 0;
                }
                complete = step.freeComplete ? choose(Decision::Kind::Complete, active) : true;
            }
            outcome.completeTrue = complete;
        }
        firstEvolution = false;
        activeGrafcet = nullptr; // the GEMMA conditions read the globals, not the FB's outputs
        if (probe.step >= 0 && probe.step == active) {
            runProbe(step, complete);
            if (probe.only) {
                to = work;
                return outcome;
            }
        }
        for (const CompiledTransition& transition : step.transitions) {
            if (gated(transition, complete)) {
                newStep = transition.target;
                setStepIndex(work, newStep);
                work[2] = 1;
                outcome.firedTransition = transition.globalIndex;
                outcome.entersD1 = newStep >= 0 && newStep == d1Step;
                break;
            }
            if (transition.condition)
                failSeen[u(transition.globalIndex)] = 1;
        }
    }
    // After END_CASE: the continuous outputs, gated by the state and Entry.
    const bool entry = work[2] != 0;
    for (const OutputWrite& write : outputWrites) {
        bool value = false;
        for (const OutputWrite::Driver& driver : write.drivers) {
            if (newStep == driver.step && !entry && newStep == active)
                value = value || work[u(layout.outputs + driver.output)] != 0;
        }
        const Slot& slot = slots[u(write.slot)];
        if (slot.stateBit >= 0)
            work[u(layout.bools + slot.stateBit)] = value ? 1 : 0;
    }
    // The token updates, with the new State.
    if (newStep >= 0) {
        const CompiledStep& step = steps[u(newStep)];
        for (int t = step.firstToken; t < step.firstToken + step.tokenCount; ++t) {
            const CompiledToken& token = tokens[u(t)];
            // A token already captured stays so: its variable need not be read.
            if (token.slot >= 0 && !work[u(layout.tokens + t)] && readBool(token.slot) != token.normallyClosed)
                work[u(layout.tokens + t)] = 1;
        }
    }
    // What the user's properties and the D1 rule read: the end of the scan.
    propertyPhase = true;
    if (outcome.entersD1) {
        for (int s : outputsToCheckOnD1) {
            if (readBool(s)) {
                Event output;
                output.kind = EventKind::OutputOnD1;
                output.variable = slots[u(s)].name;
                outcome.events.push_back(output);
            }
        }
    }
    for (std::size_t p = 0; p < propertyInfos.size(); ++p) {
        if (!propertyInfos[p])
            continue;
        const bool holds = eval(*propertyInfos[p], -1);
        const bool violated = parsedProperties[p].kind == PropertyKind::Never ? holds : !holds;
        if (violated) {
            Event event;
            event.kind = EventKind::PropertyViolated;
            event.property = static_cast<int>(p);
            outcome.events.push_back(event);
        }
    }
    // The edge memories: every variable read under an edge, as the scan ends.
    for (std::size_t e = 0; e < edgeSlots.size(); ++e)
        work[u(layout.prev) + e] = readBool(edgeSlots[e]) ? 1 : 0;
    // Normal form: what is never read again is cleared.
    for (const auto& [at, initial] : writeOnlyBools)
        work[u(at)] = initial;
    const bool leftStep = newStep != active;
    if (leftStep || newStep < 0 || steps[u(newStep)].grafcet < 0) {
        std::fill(work.begin() + layout.x, work.begin() + layout.bools, '\0');
    }
    if (newStep >= 0 && steps[u(newStep)].nested && work[2]) {
        const CompiledStep& step = steps[u(newStep)];
        for (int t = 0; t < step.tokenCount; ++t)
            work[u(layout.tokens + step.firstToken + t)] = 0;
    }
    for (int s : stepsWithTokens) {
        const CompiledStep& step = steps[u(s)];
        if (s == newStep)
            continue;
        for (int t = 0; t < step.tokenCount; ++t)
            work[u(layout.tokens + step.firstToken + t)] = 0;
    }
    activeGrafcet = nullptr;
    propertyPhase = false;
    if (faultSignal >= 0 && faultKind == machine::FaultKind::Flicker)
        work[u(layout.fault + 4)] ^= 1; // the next scan reads the opposite
    advanceMachine();
    to = work;
    return outcome;
}

// Closed loop, after the scan: one machine cycle from the outputs as the
// scan left them; its state replaces the state's tail.
void ProgramExplorer::Impl::advanceMachine()
{
    if (!machineState)
        return;
    work.resize(static_cast<std::size_t>(layout.size));
    if (abstractMachine) {
        for (const auto& [signal, slot] : actuators)
            abstractMachine->setSignal(signal, readBool(slot));
        abstractMachine->cycle([&](int alternatives) {
            const int value = chooser.choose(alternatives);
            chooser.decisions.push_back({Decision::Kind::Machine, -1, value});
            return value;
        });
        abstractMachine->appendKey(work);
        return;
    }
    for (const auto& [signal, slot] : actuators)
        machineState->setSignal(signal, readBool(slot));
    machineState->cycle();
    machineState->appendKey(work);
}

// ---------------------------------------------------------------------------------------
// Exploring

bool ProgramExplorer::Impl::outOfBudget()
{
    if (options.cancelled && options.cancelled()) {
        result.cancelled = true;
        return true;
    }
    return store.size() >= options.maxStates || scansRun >= options.maxScansRun
        || std::chrono::steady_clock::now() > options.deadline;
}

std::string eventKey(const Event& event)
{
    if (event.kind == EventKind::AlwaysTrue)
        return std::to_string(static_cast<int>(event.kind)) + "|" + event.transition;
    std::string key = std::to_string(static_cast<int>(event.kind)) + "|" + event.stepId + "|" + event.variable + "|"
        + std::to_string(event.property);
    for (int n : event.numbers)
        key += "," + std::to_string(n);
    return key;
}

// The first state that shows an event is kept (the shortest run); among its
// scans, one where the GEMMA layer stays put is preferred, so the replay ends
// where the event is rather than in the step the scan leaves for.
void ProgramExplorer::Impl::addEvent(Event event, std::size_t state, bool gemmaFired)
{
    const std::string key = eventKey(event);
    auto known = eventAt.find(key);
    if (known != eventAt.end()) {
        Event& kept = result.events[known->second.first];
        if (kept.witness.state == state && known->second.second && !gemmaFired) {
            kept.witness.answers = chooser.answers();
            known->second.second = false;
        }
        return;
    }
    eventKeys.insert(key);
    noteSearched(key);
    event.witness.state = state;
    event.witness.answers = chooser.answers();
    eventAt.emplace(key, std::make_pair(result.events.size(), gemmaFired));
    result.events.push_back(std::move(event));
}

void ProgramExplorer::Impl::explore()
{
    started = std::chrono::steady_clock::now();
    (void)addState(initialState(), 0);
    std::vector<bool> reached(steps.size(), false);
    compileSearchedOverlaps();
    polling = true;
    State from;
    for (std::size_t next = 0; next < store.size(); ++next) {
        if ((next & 63) == 0 && outOfBudget()) {
            result.exhaustive = false;
            break;
        }
        store.decodeInto(next, from);
        if (const int s = stepOfState(next); s >= 0)
            reached[static_cast<std::size_t>(s)] = true;
        if (!exploreState(next, from)) {
            result.exhaustive = false;
            break;
        }
        if (!options.searchFor.empty()) {
            probeSearchedOverlaps(next);
            if (searchedFound == options.searchFor.size()) {
                result.exhaustive = false; // every run searched for is found: the rest is left unexplored
                break;
            }
        }
    }
    finishExploration(reached);
    polling = false;
}

// Adds `state`, found from state `from`, if it is new; its index.
std::uint32_t ProgramExplorer::Impl::addState(const State& state, std::size_t from)
{
    const auto [at, isNew] = store.insert(state);
    if (isNew) {
        const bool first = at == 0;
        parent.push_back(first ? 0 : static_cast<std::uint32_t>(from));
        depth.push_back(first ? 0 : depth[from] + 1);
        stepRaw.push_back(static_cast<std::uint16_t>(stepIndexOf(state) + 1));
        edges.addState();
        result.maxDepth = std::max<std::size_t>(result.maxDepth, depth.back());
    }
    return at;
}

// Every scan of one state; false when the budget ran out (or the run was
// cancelled) before they were all run.
bool ProgramExplorer::Impl::exploreState(std::size_t next, const State& from)
{
    chooser.reset();
    recentCount = 0;
    std::size_t leaves = 0;
    try {
        do {
            ++scansRun;
            if ((++leaves & 1023) == 0 && outOfBudget())
                break;
            chooser.restart(nullptr);
            ScanOutcome outcome = scan(from, successor);
            noteScan(next, reachedState(next), outcome);
        } while (chooser.advance());
    } catch (const Interrupted&) {
        return false;
    }
    return !(result.cancelled || ((leaves & 1023) == 0 && leaves > 0 && outOfBudget()));
}

// What one scan from state `next` to state `to` showed: the transition it
// fired, Complete, its edge and its events.
// The index of `successor`, the state the last scan from state `from` ended
// in, added to the store when new.
std::uint32_t ProgramExplorer::Impl::reachedState(std::size_t from)
{
    for (std::size_t k = 0; k < std::min(recentCount, kRecent); ++k) {
        if (recent[k].first == successor)
            return recent[k].second;
    }
    const std::uint32_t at = addState(successor, from);
    auto& slot = recent[recentCount++ % kRecent];
    slot.first.assign(successor);
    slot.second = at;
    return at;
}

void ProgramExplorer::Impl::noteScan(std::size_t next, std::uint32_t to, ScanOutcome& outcome)
{
    const int active = stepOfState(next);
    if (outcome.firedTransition >= 0) {
        const auto g = static_cast<std::size_t>(outcome.firedTransition);
        firedGlobal[g] = 1;
        if (!firstFire[g].seen)
            firstFire[g] = FirstFire{true, active, Witness{next, chooser.answers()}};
    }
    if (active >= 0 && outcome.completeTrue && steps[static_cast<std::size_t>(active)].grafcet >= 0) {
        char& seen = completeSeenByStep[static_cast<std::size_t>(active)];
        if (!seen)
            result.completeSeen[steps[static_cast<std::size_t>(active)].source->id] = true;
        seen = 1;
    }
    Edge edge;
    edge.to = to;
    edge.fired = outcome.firedTransition;
    edge.completeTrue = outcome.completeTrue ? 1 : 0;
    edge.entersD1 = outcome.entersD1 ? 1 : 0;
    const std::span<const Edge> out = edges.of(next);
    if (std::none_of(out.begin(), out.end(), [&](const Edge& e) {
            return e.to == edge.to && e.fired == edge.fired && e.completeTrue == edge.completeTrue;
        }))
        edges.add(next, edge);
    for (Event& event : outcome.events)
        addEvent(std::move(event), next, outcome.firedTransition >= 0);
}

void ProgramExplorer::Impl::finishExploration(const std::vector<bool>& reached)
{
    result.states = store.size();
    if (layout.fault >= 0) {
        const auto at = static_cast<std::size_t>(layout.fault);
        State state;
        for (std::size_t s = 0; s < store.size(); ++s) {
            store.decodeInto(s, state);
            result.faultedStates += (state[at] | state[at + 1] | state[at + 2] | state[at + 3]) != 0 ? 1 : 0;
        }
    }
    result.scans = edges.edges();
    for (std::size_t s = 0; s < steps.size(); ++s) {
        if (reached[s])
            result.reachableSteps.push_back(steps[s].source->id);
    }
    for (std::size_t t = 0; t < transitionIds.size(); ++t) {
        if (firedGlobal[t])
            result.fireableTransitions.push_back(transitionIds[t]);
    }
    for (auto& [id, list] : result.activeNestedSteps)
        std::sort(list.begin(), list.end());
    for (auto& [id, list] : result.firedNestedTransitions)
        std::sort(list.begin(), list.end());
    result.scansRun = scansRun;
    if (result.exhaustive) {
        if (options.decidePriorities)
            probePriorities();
        else
            result.prioritiesDecided = false;
        analyseGraph();
    } else {
        result.prioritiesDecided = false;
    }
    result.scansRun = scansRun;
}

// GV103 and GV104 on both layers. The plain scans already show most
// conditions FALSE somewhere; a state is probed only while its step has a
// fired transition never seen FALSE or a pair of fired transitions not yet seen
// holding together, and one enumeration of its inputs answers them all.
void ProgramExplorer::Impl::probePriorities()
{
    const auto u = [](auto i) { return static_cast<std::size_t>(i); };
    for (std::size_t s = 0; s < store.size() && result.prioritiesDecided; ++s) {
        const int active = stepOfState(s);
        if (active >= 0 && worthProbing(active, overlapFound))
            probeState(s, overlapFound);
    }
    chooser.reset();
    if (!result.prioritiesDecided) {
        result.overlaps.clear();
        result.events.erase(std::remove_if(result.events.begin(), result.events.end(),
                                           [](const Event& e) { return e.kind == EventKind::Overlap; }),
                            result.events.end());
        return;
    }
    for (std::size_t g = 0; g < transitionIds.size(); ++g) {
        if (!firedGlobal[g] || failSeen[g] || !transitionSources[g]->conditionUsable)
            continue;
        result.alwaysTrueTransitions.push_back(transitionIds[g]);
        const FirstFire& first = firstFire[g];
        const std::vector<CompiledTransition>& transitions = steps[u(first.step)].transitions;
        const auto position = std::find_if(transitions.begin(), transitions.end(), [&](const CompiledTransition& t) {
            return t.globalIndex == static_cast<int>(g);
        });
        Event event;
        event.kind = EventKind::AlwaysTrue;
        event.stepId = steps[u(first.step)].source->id;
        event.numbers = {static_cast<int>(position - transitions.begin())};
        event.transition = transitionIds[g];
        event.witness = first.witness;
        eventKeys.insert(eventKey(event));
        result.events.push_back(std::move(event));
    }
}

// A GV104 pair: the higher transition is not the family one (the emergency
// stop pre-empts by design) and both fire in some reachable scan (else GV102).
bool ProgramExplorer::Impl::worthProbing(
    int step, const std::set<std::pair<int, std::pair<std::size_t, std::size_t>>>& overlapFound) const
{
    const auto u = [](auto i) { return static_cast<std::size_t>(i); };
    const std::vector<CompiledTransition>& transitions = steps[u(step)].transitions;
    const auto fired = [&](const CompiledTransition& t) { return t.condition && firedGlobal[u(t.globalIndex)]; };
    for (std::size_t i = 0; i < transitions.size(); ++i) {
        if (!fired(transitions[i]))
            continue;
        if (!failSeen[u(transitions[i].globalIndex)])
            return true;
        if (transitions[i].source->family)
            continue;
        for (std::size_t j = i + 1; j < transitions.size(); ++j) {
            if (fired(transitions[j]) && !overlapFound.count({step, {i, j}}))
                return true;
        }
    }
    return false;
}

// Every scan of the state with the probe on its step; records the pairs that
// hold together, each with the first scan that shows it.
void ProgramExplorer::Impl::probeState(std::size_t state,
                                       std::set<std::pair<int, std::pair<std::size_t, std::size_t>>>& overlapFound)
{
    if (outOfBudget()) {
        result.prioritiesDecided = false;
        return;
    }
    probe = Probe{stepOfState(state), true};
    chooser.reset();
    std::size_t leaves = 0;
    try {
        probeScans(state, leaves, overlapFound);
    } catch (const Interrupted&) {
        result.prioritiesDecided = false;
    }
    probe = Probe{};
}

void ProgramExplorer::Impl::probeScans(std::size_t state, std::size_t& leaves,
                                       std::set<std::pair<int, std::pair<std::size_t, std::size_t>>>& overlapFound)
{
    const auto u = [](auto i) { return static_cast<std::size_t>(i); };
    const int active = probe.step;
    const std::vector<CompiledTransition>& transitions = steps[u(active)].transitions;
    const State from = store.at(state);
    do {
        ++scansRun;
        if ((++leaves & 1023) == 0 && outOfBudget()) {
            result.prioritiesDecided = false;
            break;
        }
        chooser.restart(nullptr);
        scan(from, successor);
        const auto first = std::find(probeTrue.begin(), probeTrue.end(), 1);
        if (first == probeTrue.end())
            continue;
        const std::size_t i = u(first - probeTrue.begin());
        const CompiledTransition& higher = transitions[i];
        if (higher.source->family || !firedGlobal[u(higher.globalIndex)])
            continue;
        for (std::size_t j = i + 1; j < transitions.size(); ++j) {
            const CompiledTransition& lower = transitions[j];
            if (!probeTrue[j] || !firedGlobal[u(lower.globalIndex)] || !overlapFound.insert({active, {i, j}}).second)
                continue;
            result.overlaps.emplace_back(higher.source->id, lower.source->id);
            Event event;
            event.kind = EventKind::Overlap;
            event.stepId = steps[u(active)].source->id;
            event.numbers = {static_cast<int>(i), static_cast<int>(j)};
            event.transition = higher.source->id;
            event.witness = Witness{state, chooser.answers()};
            const std::string key = eventKey(event);
            eventKeys.insert(key);
            noteSearched(key);
            result.events.push_back(std::move(event));
        }
    } while (chooser.advance());
}

void ProgramExplorer::Impl::noteSearched(const std::string& key)
{
    if (options.searchFor.count(key))
        ++searchedFound;
}

// By step index, the keys of the Overlap events Options::searchFor names.
void ProgramExplorer::Impl::compileSearchedOverlaps()
{
    searchedOverlaps.assign(steps.size(), {});
    if (options.searchFor.empty())
        return;
    for (std::size_t s = 0; s < steps.size(); ++s) {
        const std::size_t count = steps[s].transitions.size();
        for (std::size_t i = 0; i < count; ++i) {
            for (std::size_t j = i + 1; j < count; ++j) {
                Event event;
                event.kind = EventKind::Overlap;
                event.stepId = steps[s].source->id;
                event.numbers = {static_cast<int>(i), static_cast<int>(j)};
                event.transition = steps[s].transitions[i].source->id;
                const std::string key = eventKey(event);
                if (options.searchFor.count(key))
                    searchedOverlaps[s].push_back(key);
            }
        }
    }
}

// While searching: a state whose step has an Overlap searched for and not
// found yet is probed as soon as it is explored (the exploration may stop
// before probePriorities would run).
void ProgramExplorer::Impl::probeSearchedOverlaps(std::size_t state)
{
    const int active = stepOfState(state);
    if (active < 0)
        return;
    const std::vector<std::string>& keys = searchedOverlaps[static_cast<std::size_t>(active)];
    if (std::all_of(keys.begin(), keys.end(), [&](const std::string& key) { return eventKeys.count(key) > 0; }))
        return;
    probeState(state, overlapFound);
    result.prioritiesDecided = true; // decided, or not, by the whole exploration's probePriorities alone
}

// The graph properties: from which states of a step something can still happen.
void ProgramExplorer::Impl::analyseGraph()
{
    const std::size_t n = store.size();
    // The predecessors of each state, in one array (compressed rows): those
    // of s at reverse[reverseStart[s]] up to reverse[reverseStart[s + 1]].
    std::vector<std::uint32_t> reverseStart(n + 1, 0);
    for (std::size_t s = 0; s < n; ++s) {
        for (const Edge& e : edges.of(s))
            ++reverseStart[e.to + 1];
    }
    for (std::size_t s = 0; s < n; ++s)
        reverseStart[s + 1] += reverseStart[s];
    std::vector<std::uint32_t> reverse(edges.edges());
    {
        std::vector<std::uint32_t> filled(reverseStart.begin(), reverseStart.end() - 1);
        for (std::size_t s = 0; s < n; ++s) {
            for (const Edge& e : edges.of(s))
                reverse[filled[e.to]++] = static_cast<std::uint32_t>(s);
        }
    }
    auto stepOf = [&](std::size_t s) { return stepOfState(s); };
    // Backward closure from the states with a marked edge, along edges that satisfy `keep`.
    auto canReach = [&](auto marked, auto keep) {
        std::vector<char> good(n, 0);
        std::deque<std::uint32_t> queue;
        for (std::size_t s = 0; s < n; ++s) {
            for (const Edge& e : edges.of(s)) {
                if (marked(s, e)) {
                    good[s] = 1;
                    queue.push_back(static_cast<std::uint32_t>(s));
                    break;
                }
            }
        }
        while (!queue.empty()) {
            const std::uint32_t s = queue.front();
            queue.pop_front();
            for (std::uint32_t r = reverseStart[s]; r < reverseStart[s + 1]; ++r) {
                const std::uint32_t p = reverse[r];
                if (good[p])
                    continue;
                const std::span<const Edge> out = edges.of(p);
                const bool along
                    = std::any_of(out.begin(), out.end(), [&](const Edge& e) { return e.to == s && keep(p, e); });
                if (along) {
                    good[p] = 1;
                    queue.push_back(p);
                }
            }
        }
        return good;
    };
    auto staysInStep = [&](std::size_t s, const Edge& e) { return e.fired < 0 && stepOf(e.to) == stepOf(s); };
    auto report = [&](EventKind kind, std::size_t s) {
        Event event;
        event.kind = kind;
        event.stepId = steps[static_cast<std::size_t>(stepOf(s))].source->id;
        event.stateOnly = true;
        if (!eventKeys.insert(eventKey(event)).second)
            return;
        event.witness.state = s;
        result.events.push_back(std::move(event));
    };
    const std::vector<char> canLeave
        = canReach([&](std::size_t s, const Edge& e) { return e.fired >= 0 && stepOf(s) >= 0; }, staysInStep);
    std::vector<bool> stuckStep(steps.size(), false);
    for (std::size_t s = 0; s < n; ++s) {
        if (stepOf(s) >= 0 && !canLeave[s] && !steps[static_cast<std::size_t>(stepOf(s))].transitions.empty()) {
            stuckStep[static_cast<std::size_t>(stepOf(s))] = true;
            report(EventKind::Stuck, s);
        }
    }
    const std::vector<char> canComplete = canReach(
        [&](std::size_t s, const Edge& e) { return e.completeTrue && stepOf(s) >= 0; }, staysInStep);
    for (std::size_t s = 0; s < n; ++s) {
        const int step = stepOf(s);
        if (step < 0 || canComplete[s])
            continue;
        const CompiledStep& compiled = steps[static_cast<std::size_t>(step)];
        const bool waits = std::any_of(compiled.transitions.begin(), compiled.transitions.end(),
                                       [](const CompiledTransition& t) {
                                           return t.source->waitsForComplete && t.condition != nullptr;
                                       });
        if (compiled.grafcet >= 0 && compiled.source->type == StepType::Macro && waits)
            report(EventKind::StuckWithoutComplete, s);
    }
    const std::vector<char> canReturn = canReach(
        [&](std::size_t, const Edge& e) { return stepOf(e.to) == initialStep; }, [](std::size_t, const Edge&) { return true; });
    for (std::size_t s = 0; s < n; ++s) {
        const int step = stepOf(s);
        if (step >= 0 && step != initialStep && !canReturn[s] && !stuckStep[static_cast<std::size_t>(step)])
            report(EventKind::NoReturn, s);
    }
    if (d1Step >= 0) {
        for (std::size_t s = 0; s < n; ++s) {
            const int step = stepOf(s);
            if (step < 0 || steps[static_cast<std::size_t>(step)].source->id[0] != 'F')
                continue;
            const std::span<const Edge> out = edges.of(s);
            if (std::none_of(out.begin(), out.end(), [](const Edge& e) { return e.entersD1 != 0; }))
                report(EventKind::NoEmergencyStop, s);
        }
    }
}

// ---------------------------------------------------------------------------------------
// Counterexamples

std::vector<int> ProgramExplorer::Impl::answersTo(std::size_t from, std::size_t to) const
{
    auto* self = const_cast<Impl*>(this);
    self->chooser.reset();
    const State start = store.at(from);
    do {
        self->chooser.restart(nullptr);
        self->scan(start, self->successor);
        if (store.find(successor) == static_cast<std::int64_t>(to))
            return chooser.answers();
    } while (self->chooser.advance());
    return {};
}

// A scan of the path again, as counterexample() replays it, with its TONs logged.
void ProgramExplorer::Impl::replayScan(std::size_t from, const std::vector<int>& answers, const Event& event,
                                       bool witnessScan)
{
    chooser.restart(&answers);
    if (witnessScan && event.kind == EventKind::Overlap)
        probe = Probe{stepOfState(from), false};
    logTimers = true;
    State ignored;
    scan(store.at(from), ignored);
    logTimers = false;
    probe = Probe{};
}

// The runs with IN TRUE of each TON, counted as exact time counts them, after
// `scans` scans like the one just replayed (before the steps it enters reset them).
std::vector<std::int64_t> ProgramExplorer::Impl::countRuns(const std::vector<std::int64_t>& counts,
                                                           std::int64_t scans) const
{
    std::vector<std::int64_t> out(counts.size(), 0);
    for (std::size_t t = 0; t < counts.size(); ++t) {
        if (timerLog.in[t] > 0)
            out[t] = (timerLog.initialized ? 0 : counts[t]) + scans;
    }
    return out;
}

// A scan from `state` in which time passes and nothing else does: no TON
// elapses, and it ends in the same state or one that differs only by the
// TONs' states (a TON whose step was just entered starts running); a scan
// back to the state itself is preferred. The state it ends in, its answers.
std::optional<std::pair<std::size_t, std::vector<int>>> ProgramExplorer::Impl::stutter(std::size_t state)
{
    const State from = store.at(state);
    const auto timersOnly = [&](const State& next) {
        return std::equal(from.begin(), from.begin() + layout.timers, next.begin())
            && std::equal(from.begin() + layout.bools, from.end(), next.begin() + layout.bools);
    };
    std::optional<std::pair<std::size_t, std::vector<int>>> found;
    chooser.reset();
    do {
        chooser.restart(nullptr);
        State next;
        scan(from, next);
        const bool elapses = std::any_of(chooser.decisions.begin(), chooser.decisions.end(), [](const Decision& d) {
            return d.kind == Decision::Kind::Timer && d.value != 0;
        });
        if (elapses || next.size() != from.size() || !timersOnly(next))
            continue;
        const std::int64_t known = store.find(next);
        if (known < 0)
            continue;
        if (static_cast<std::size_t>(known) == state)
            return std::make_pair(state, chooser.answers());
        if (!found)
            found = std::make_pair(static_cast<std::size_t>(known), chooser.answers());
    } while (chooser.advance());
    return found;
}

// The TON runs still missing before the replayed scan's TONs may elapse as it chose.
std::int64_t ProgramExplorer::Impl::missingRuns(std::size_t from, const std::vector<std::int64_t>& counts) const
{
    const int step = stepOfState(from);
    const int grafcet = step >= 0 ? steps[static_cast<std::size_t>(step)].grafcet : -1;
    if (grafcet < 0 || timerLog.initialized)
        return 0;
    const std::vector<std::int64_t> runs = countRuns(counts, 1);
    std::int64_t missing = 0;
    for (const Decision& d : chooser.decisions) {
        if (d.kind == Decision::Kind::Timer && d.value != 0) {
            const auto t = static_cast<std::size_t>(d.slot);
            missing = std::max(missing, grafcets[static_cast<std::size_t>(grafcet)].timerRuns[t] - runs[t]);
        }
    }
    return missing;
}

// Under the timer abstraction a path may let a TON elapse at its second run,
// which the PLC's does only after its duration: before such a scan, scans in
// which only time passes (stutter) are inserted, as many as the TON still
// needs (up to kMaxStretch in all), so that the run can replay. The replay in
// the simulator still decides whether it does.
ProgramExplorer::Impl::Path ProgramExplorer::Impl::stretchForTimers(const Path& path, const Event& event)
{
    constexpr std::int64_t kMaxStretch = 100'000;
    if (options.exactTime || timerCache.empty())
        return path;
    Path out;
    std::vector<std::int64_t> counts(timerCache.size(), 0);
    std::int64_t inserted = 0;
    for (std::size_t k = 0; k < path.size(); ++k) {
        std::size_t from = path[k].first;
        const std::vector<int>& answers = path[k].second;
        const bool witnessScan = !event.stateOnly && k + 1 == path.size();
        replayScan(from, answers, event, witnessScan);
        for (std::int64_t missing = missingRuns(from, counts); missing > 0 && inserted + missing <= kMaxStretch;) {
            const auto wait = stutter(from);
            if (!wait)
                break;
            replayScan(from, wait->second, event, false);
            // A scan back to the same state stands for all the runs missing; another for one.
            const std::int64_t times = wait->first == from ? missing : 1;
            counts = countRuns(counts, times);
            out.insert(out.end(), static_cast<std::size_t>(times), {from, wait->second});
            inserted += times;
            from = wait->first;
            replayScan(from, answers, event, witnessScan);
            missing = missingRuns(from, counts);
        }
        counts = countRuns(counts, 1);
        for (std::size_t t = 0; t < counts.size(); ++t) {
            if (timerLog.reset[t])
                counts[t] = 0;
        }
        out.emplace_back(from, answers);
    }
    chooser.reset();
    return out;
}

std::vector<std::pair<std::size_t, std::vector<int>>> ProgramExplorer::Impl::pathTo(std::size_t state) const
{
    std::vector<std::size_t> chain;
    for (std::size_t s = state; s != 0; s = parent[s])
        chain.push_back(s);
    std::reverse(chain.begin(), chain.end());
    std::vector<std::pair<std::size_t, std::vector<int>>> path;
    std::size_t from = 0;
    for (std::size_t s : chain) {
        path.emplace_back(from, answersTo(from, s));
        from = s;
    }
    return path;
}

namespace {

std::string valueText(const cond::Value& value)
{
    if (std::holds_alternative<bool>(value))
        return std::get<bool>(value) ? "TRUE" : "FALSE";
    return cond::formatValue(value);
}

} // namespace

ProgramExplorer::ProgramExplorer(const Model& model, Options options)
    : m_impl(std::make_unique<Impl>(model, std::move(options)))
{
}

ProgramExplorer::~ProgramExplorer() = default;

const Exploration& ProgramExplorer::run()
{
    m_impl->explore();
    return m_impl->result;
}

const Exploration& ProgramExplorer::result() const
{
    return m_impl->result;
}

Counterexample ProgramExplorer::counterexample(const Event& event, const std::string& title) const
{
    Impl& impl = *m_impl;
    auto path = impl.pathTo(event.witness.state);
    if (!event.stateOnly)
        path.emplace_back(event.witness.state, event.witness.answers);
    path = impl.stretchForTimers(path, event);
    std::ostringstream text;
    text << "# " << title << "\n";
    if (impl.machineState)
        text << "# closed loop: replay it with the model's machine\n";
    std::map<int, std::string> current; // slot -> value text the simulator holds
    for (std::size_t i = 0; i < impl.slots.size(); ++i)
        current[static_cast<int>(i)] = valueText(impl.slots[i].replayInitial);
    std::int64_t scan = 0;
    State last;
    std::string firedAtEnd; // the GEMMA transition the last scan must fire (GV103, GV104)
    std::int64_t faultScan = 0; // single faults: the scan the fault begins before
    for (std::size_t k = 0; k < path.size(); ++k) {
        const auto& [from, answers] = path[k];
        ++scan;
        impl.chooser.restart(&answers);
        const bool witnessScan = !event.stateOnly && k + 1 == path.size();
        if (witnessScan && event.kind == EventKind::Overlap)
            impl.probe = Probe{impl.stepOfState(from), false}; // reads the inputs as the probe did
        State next;
        const ScanOutcome outcome = impl.scan(impl.store.at(from), next);
        impl.probe = Probe{};
        last = next;
        if (witnessScan && (event.kind == EventKind::Overlap || event.kind == EventKind::AlwaysTrue)
            && outcome.firedTransition >= 0)
            firedAtEnd = impl.transitionIds[static_cast<std::size_t>(outcome.firedTransition)];
        std::vector<std::string> sets;
        std::vector<Decision> decisions = impl.chooser.decisions;
        for (Decision& d : decisions) {
            if (d.kind != Decision::Kind::NumberTest)
                continue;
            // The value: the first representative the comparisons left.
            const std::uint64_t possible = impl.numberPossible[static_cast<std::size_t>(d.slot)];
            d.kind = Decision::Kind::Number;
            d.value = impl.numberCache[static_cast<std::size_t>(d.slot)] >= 0
                ? impl.numberCache[static_cast<std::size_t>(d.slot)]
                : std::countr_zero(possible);
        }
        for (const Decision& d : decisions) {
            if (d.kind == Decision::Kind::Bool || d.kind == Decision::Kind::Number) {
                const Slot& slot = impl.slots[static_cast<std::size_t>(d.slot)];
                if (slot.kind != VariableKind::Input)
                    continue; // abstracted: the replay shows whether the run holds
                const std::string value = d.kind == Decision::Kind::Bool
                    ? (d.value ? "TRUE" : "FALSE")
                    : valueText(slot.representatives[static_cast<std::size_t>(d.value)]);
                if (current[d.slot] != value) {
                    current[d.slot] = value;
                    sets.push_back(slot.name + " = " + value);
                }
            } else if (d.kind == Decision::Kind::Fault && d.value > 0) {
                const machine::Fault& fault = impl.faultChoices[static_cast<std::size_t>(d.value - 1)].fault;
                text << "at " << scan << ": fault " << machine::toText(fault) << "\n";
                faultScan = scan;
            } else if (d.kind == Decision::Kind::Complete) {
                text << "at " << scan << ": set complete " << impl.steps[static_cast<std::size_t>(d.slot)].source->id
                     << " = " << (d.value ? "TRUE" : "FALSE") << "\n";
            }
        }
        if (!sets.empty()) {
            text << "at " << scan << ": set ";
            for (std::size_t i = 0; i < sets.size(); ++i)
                text << (i ? ", " : "") << sets[i];
            text << "\n";
        }
    }
    impl.chooser.restart(nullptr);
    impl.chooser.reset();
    const State end = event.stateOnly ? impl.store.at(event.witness.state) : last;
    const int step = stepIndexOf(end);
    if (!firedAtEnd.empty())
        text << "at " << scan << ": expect fired " << firedAtEnd << "\n";
    if (scan > 0 && step >= 0) {
        const CompiledStep& compiled = impl.steps[static_cast<std::size_t>(step)];
        text << "at " << scan << ": expect step " << compiled.source->id << "\n";
        if (compiled.grafcet >= 0 && end[2] == 0) {
            const CompiledGrafcet& g = impl.grafcets[static_cast<std::size_t>(compiled.grafcet)];
            std::string active;
            for (std::size_t i = 0; i < g.numbers.size(); ++i) {
                if (end[static_cast<std::size_t>(impl.layout.x) + i])
                    active += (active.empty() ? "" : ", ") + std::to_string(g.numbers[i]);
            }
            text << "at " << scan << ": expect nested " << compiled.source->id << " steps "
                 << (active.empty() ? "none" : active) << "\n";
        }
    }
    Counterexample out;
    out.text = text.str();
    ScenarioParseResult parsed = parseScenario(out.text);
    out.scenario = parsed.scenario;
    out.scans = scan;
    if (!parsed.ok() || scan == 0)
        return out;
    // A copy of one simulator built once: it shares the compiled program
    // (building it for every run was a third of the replay), and every run
    // starts with reset().
    if (!impl.replaySimulator)
        impl.replaySimulator.emplace(impl.model);
    Simulator simulator(*impl.replaySimulator);
    if (!validateScenario(out.scenario, simulator,
                          impl.machineState ? FaultLines::CheckedByMachine : FaultLines::Refused)
             .empty())
        return out;
    std::optional<machine::MachineLoop> loop;
    if (impl.machineState) {
        loop.emplace(simulator, *impl.options.machine);
        if (!machine::validateClosedLoopScenario(out.scenario, *loop).empty())
            return out;
    }
    const ScenarioRunResult run
        = loop ? replayClosedLoop(out.scenario, *loop, scan) : runScenario(out.scenario, simulator, scan);
    out.confirmed = run.passed();
    if (out.confirmed && event.kind == EventKind::PropertyViolated && event.property >= 0) {
        // The property itself, read on the simulator after the last scan.
        const ParsedProperty& property = impl.parsedProperties[static_cast<std::size_t>(event.property)];
        out.confirmed = propertyViolatedOn(impl.model, property, simulator, faultScan);
    }
    return out;
}

} // namespace core::explore
