#pragma once

// GV130, GV131 on an explored graph (docs/packml.md, "Verification"): from
// which configurations of an acting state a run that stays in it (no
// transition, no mode change) reaches a scan whose SC fires.
//
// Under the timer abstraction the graph has more runs than the PLC, so a
// path to SC in it may not exist (two TONs elapsing in the wrong order). The
// *sure* answer uses only scans that every configuration the node stands for
// can take: a scan that decides no TON, or one that takes one TON T as
// elapsed where the node has a waiting scan (it stays in the node, deciding
// nothing or T not elapsed): the PLC repeats the waiting scan until T has
// elapsed, then takes that one.

#include "core/templates/packml/packmlexplorer.h"

#include <vector>

namespace core::packml {

struct Completion {
    std::vector<char> possible; // by node: some explored run reaches SC
    std::vector<char> sure;     // by node: a run of the PLC does, from every configuration the node stands for
};

Completion completion(const PackmlExplorer& explorer);

} // namespace core::packml
