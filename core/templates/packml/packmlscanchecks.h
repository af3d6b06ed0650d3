#pragma once

// The properties of spec packml.md §8 that one scan shows (GV132, GV133,
// GV136, GV137, GV138), read on what the simulator did: the scan's record
// and the values and situations before and after it. They compare with a
// reference computed from the configuration by the rules of packmlrules.h,
// not with the program the simulator runs, so that a program built wrong is
// caught (the tests build some on purpose).

#include "core/templates/packml/packmlconfiguration.h"
#include "core/templates/packml/packmlscanrecord.h"

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace core::packml {

class PackmlSimulator;
struct PackmlProgram;

// An instance's situation as its FB keeps it between calls: active steps,
// Complete, and per TON whether it runs and since when.
struct Situation {
    int instance = -1;
    std::vector<int> steps;
    bool complete = false;
    std::vector<std::pair<bool, std::int64_t>> timers;
    friend bool operator==(const Situation&, const Situation&) = default;
};
Situation situationOf(const PackmlSimulator& simulator, int instance);

// Execute paused by the Hold or Suspend loop, tracked from the scans alone
// (spec §4), apart from the program's Resume flag.
struct PauseGhost {
    bool paused = false;
    Situation situation; // the one the scan that left Execute ended with
    friend bool operator==(const PauseGhost&, const PauseGhost&) = default;
};

// What a scan did, as the checks read it.
struct ScanFacts {
    PackmlScanRecord record;
    bool entryBefore = false;
    Situation executeBefore; // stateBefore Execute: the instance of (record.mode, Execute) before the scan
    Situation executeAfter;  // state after in Holding...Unsuspending: the instance of (record.mode, Execute) after it
    std::vector<std::string> continuousOutputsTrue; // declared names, declaration order
    std::vector<std::string> storedOutputsTrue;
};

// Reads a scan: `before` and `after` the simulator around it.
ScanFacts observeScan(const PackmlSimulator& before, const PackmlSimulator& after, PackmlScanRecord record);

// The enabled states and the grants S(c,r) the rules give each mode.
class ScanReference {
public:
    explicit ScanReference(const Configuration& configuration);
    StateSet enabled(int mode) const;
    StateSet grant(int from, int to) const;

private:
    std::map<int, StateSet> m_enabled;
    std::map<int, StateSet> m_modeChange;
};

struct ScanFinding {
    std::string code;   // "GV132"
    int mode = 0;       // the mode it concerns
    State state = State::Stopped; // GV132: the disabled state; GV138: Execute; others: the state entered
    std::vector<std::string> names; // GV136, GV137: the outputs
    std::string message; // English
};

std::vector<ScanFinding> checkScan(const ScanReference& reference, const PauseGhost& ghost, const ScanFacts& facts);

// The ghost after the scan.
PauseGhost nextGhost(const PauseGhost& ghost, const ScanFacts& facts);

// Holding, Held, Unholding, Suspending, Suspended, Unsuspending.
bool inPauseLoop(State state);

} // namespace core::packml
