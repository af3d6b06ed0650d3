#pragma once

// Explores a PackML program scan by scan (spec packml.md §8,
// docs/packml.md "Verification"): every configuration the program can reach
// from its start, with the inputs free (packmlinputchoices.h). The scans are
// run by the simulator itself (one scan exactly, §6.5), so every path found
// is a run the simulator replays. A configuration is everything the next
// scans depend on: State, Mode, Entry, Resume, the R_TRIG and <V>_PREV
// memories the next scan can read (the others as FALSE), the variables the
// program writes, the situation of the instance that runs (and of Execute
// while it is paused) with its TONs, and the pause ghost of the GV138 check. Inputs are not part of it: they are
// set before every scan.
//
// Time: a TON longer than one cycle may or may not have elapsed from its
// second run on (packmltimerchoices.h): the key stores each TON as idle,
// running or elapsed, and a scan that reads such a TON is run once per
// answer. This only adds runs (a PLC's cycle may vary), so what the
// exploration never sees never happens; a run it finds may not exist at
// nominal time (the verifier replays it). With ExplorerLimits::exactTime
// time is counted in scans of the cycle time instead: the key stores each
// TON's time since it started, capped at its duration.

#include "core/templates/packml/packmlinputchoices.h"
#include "core/templates/packml/packmlscanchecks.h"
#include "core/templates/packml/packmlsimulator.h"
#include "core/templates/packml/packmltimerchoices.h"

#include <array>
#include <chrono>
#include <deque>
#include <unordered_map>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace core::packml {

struct ExplorerLimits {
    std::size_t maxStates = 200'000;
    std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
    std::function<bool()> cancelled;
    // VerificationOptions::exactTime: time counted in scans of the cycle
    // time is the semantics asked for, not an abstraction.
    bool exactTime = false;
    // Variables read at the end of every scan (the engineer's properties).
    std::vector<std::string> alwaysRead;
    // Called after every scan with the simulator as it ended; a true result
    // records a witness of the property with that index (ExploredWitness::property).
    std::function<std::vector<int>(const PackmlSimulator&)> violatedProperties;
};

struct ExploredEdge {
    std::uint32_t from = 0, to = 0;
    std::uint32_t choice = 0; // index into the choices of `from`
    bool stays = false;       // no transition fired and the mode did not change
    bool completes = false;   // an SC transition fired
    // The TONs the scan decided under the timer abstraction (none with exact time).
    std::uint16_t decisions = 0;
    bool decidedElapsed = false;    // some TON was taken as elapsed
    bool decidedRunning = false;    // some TON was taken as not elapsed
    std::int32_t decidedTimer = -1; // the one TON decided (its index), -2 when several
};

// The first scan that shows a finding (or a property's violation).
struct ExploredWitness {
    ScanFinding finding;
    int property = -1; // an engineer's property (finding.code empty)
    std::size_t node = 0;      // the configuration the scan starts from
    std::uint32_t choice = 0;
};

struct ExploredNode {
    PackmlSimulator simulator;
    PauseGhost ghost;
    std::uint32_t parent = 0;
    std::uint32_t parentChoice = 0;
    std::uint32_t depth = 0;
};

class PackmlExplorer {
public:
    // Explores `program` (the model's, or one built wrong for a test); the
    // checks compare with the model's configuration.
    PackmlExplorer(const Model& model, PackmlProgram program, ExplorerLimits limits);

    void run();

    const std::vector<ExploredNode>& nodes() const { return m_nodes; }
    const std::vector<ExploredEdge>& edges() const { return m_edges; }
    const std::vector<ExploredWitness>& witnesses() const { return m_witnesses; }
    // Commands that fired in some scan; (mode, state) pairs and modes active at the end of one.
    const std::set<Command>& firedCommands() const { return m_firedCommands; }
    const std::set<std::pair<int, State>>& reached() const { return m_reached; }
    bool exhaustive() const { return m_exhaustive; }
    bool budgetReached() const { return m_budgetReached; }
    bool cancelled() const { return m_cancelled; }
    std::size_t maxDepth() const { return m_maxDepth; }
    std::vector<std::string> abstractions() const;
    // Some TON is longer than one cycle and time is not exact: the runs are
    // a superset of the PLC's (never-claims hold, runs must be replayed).
    bool timeAbstracted() const { return m_timeAbstracted; }
    // Some runs were left out (numbers enumerated on some values only, too
    // many ways of setting the inputs): never-claims do not hold.
    bool runsLeftOut() const { return !runsLeftOutReasons().empty(); }
    std::vector<std::string> runsLeftOutReasons() const;
    // The configuration's key: two simulators with one key have the same futures.
    std::string key(const PackmlSimulator& simulator, const PauseGhost& ghost) const;
    const InputChoices& inputChoices() const { return m_choices; }
    const ScanReference& reference() const { return m_reference; }
    const PackmlProgram& program() const { return m_start.program(); }

    // The inputs of each scan from the start to `node`, then `lastChoice` (if any).
    std::vector<InputChoice> path(std::size_t node) const;
    // Runs one scan of `simulator` with `choice` set: the record and whether every value applied.
    static PackmlScanRecord runScan(PackmlSimulator& simulator, const InputChoice& choice);

private:
    // The scan as the exploration runs it: under the timer abstraction with
    // `answers` first for the TONs it reads (TimerChoices::start).
    PackmlScanRecord runScan(PackmlSimulator& simulator, const InputChoice& choice, const std::vector<char>& answers);
    void noteLiveMemories();
    void noteLivePrevious();
    void putSituation(std::string& key, const PackmlSimulator& simulator, const Situation& situation) const;
    void putGhost(std::string& key, const PackmlSimulator& simulator, const PauseGhost& ghost) const;
    void explore(std::size_t index, std::uint32_t choice, const InputChoice& inputs,
                 std::unordered_map<std::string, std::uint32_t>& known, std::deque<std::size_t>& queue);
    bool outOfBudget();

    PackmlSimulator m_start;
    ScanReference m_reference;
    InputChoices m_choices;
    ExplorerLimits m_limits;
    std::vector<ExploredNode> m_nodes;
    std::vector<ExploredEdge> m_edges;
    std::vector<ExploredWitness> m_witnesses;
    std::set<std::string> m_witnessKeys;
    std::set<Command> m_firedCommands;
    std::set<std::pair<int, State>> m_reached;
    bool m_exhaustive = true;
    bool m_cancelled = false;
    bool m_timers = false;
    bool m_timeAbstracted = false;
    bool m_stopped = false; // out of budget or cancelled
    TimerChoices m_timerChoices;
    // By state: whether the next scan can read each R_TRIG memory (a command
    // some mode accepts there, a request some grant allows there).
    std::array<std::vector<char>, kStateCount + 1> m_liveCommandMemory{};
    std::array<std::vector<char>, kStateCount + 1> m_liveRequestMemory{};
    // By state: whether the next scan can read each <V>_PREV (PackmlProgram::edgeVariables order).
    std::array<std::vector<char>, kStateCount + 1> m_livePrevious{};
    PackmlSimulator m_next; // the scan's simulator, assigned not copied: its buffers are reused
    bool m_truncated = false;
    bool m_budgetReached = false;
    std::size_t m_maxDepth = 0;
    std::size_t m_scans = 0;
};

} // namespace core::packml
