#pragma once

// The left-to-right order of the branches of a divergence, which the user
// chooses (IEC 60848 gives it no meaning; the sheet shows it). A selection's
// branch order is the order of the transitions leaving its step in the
// GRAFCET's transition list (grafcet.h); a simultaneous divergence's is the
// order of its transition's downstream steps, and its convergence keeps its
// upstream steps in the same order.
//
// A branch is named by any step on it: the innermost divergence whose
// branches contain that step decides which branch moves. A divergence's
// branch holds the steps reached from its first transition (selection) or
// first step (simultaneous) before the join or convergence, that no other
// branch of it reaches and that are not above the divergence.

#include "core/model/grafcet.h"
#include "core/model/status.h"

#include <vector>

namespace core {

// The branch of the innermost divergence holding `step`.
struct BranchPlace {
    enum class Kind { Selection, Parallel };
    Kind kind = Kind::Selection;
    int divergence = 0;     // Selection: the step the branches leave; Parallel: the transition
    int index = 0;          // of the branch, left to right
    int count = 0;          // branches of the divergence
    std::vector<int> steps; // the branch's steps
};

// False when `step` is on no branch of a divergence.
bool findBranch(const Grafcet& grafcet, int step, BranchPlace& place);

// True when the branch holding `step` can move `offset` places (negative:
// left, positive: right) and stay among its divergence's branches.
bool canMoveBranch(const Grafcet& grafcet, int step, int offset);
// Moves that branch `offset` places (-1: one place left, +1: one place
// right); the other branches keep their relative order. Refused (GRAFCET
// untouched) when canMoveBranch is false.
Status moveBranch(Grafcet& grafcet, int step, int offset);

} // namespace core
