#pragma once

// A PackML counterexample: the inputs of a run of the explorer written as
// scenario text (`set` lines, then `expect state` and `expect mode` at the
// last scan), and its replay in a fresh PackmlSimulator, which is what
// confirms a finding (packmlverifier.h).

#include "core/templates/packml/packmlinputchoices.h"
#include "core/templates/packml/packmlscanchecks.h"
#include "core/templates/packml/packmlsimulator.h"
#include "core/verification/verification.h"

#include <optional>
#include <string>
#include <vector>

namespace core::packml {

// `scans`: the inputs set before each scan, from the first. `title` is the
// leading comment.
Counterexample writeCounterexample(const PackmlSimulator& start, const std::vector<InputChoice>& scans,
                                   const std::string& title, const std::string& expectedModeName);

// The simulator around the last scan of a replay, the pause ghost before
// that scan and what the scan did.
struct Replay {
    PackmlSimulator before;
    PackmlSimulator after;
    PauseGhost ghost;
    ScanFacts facts;
};

// Replays the text on `simulator` (a fresh copy is used): nullopt when it
// does not parse or validate, an expectation fails, or the run faults first.
std::optional<Replay> replay(const PackmlSimulator& simulator, const Counterexample& counterexample);

} // namespace core::packml
