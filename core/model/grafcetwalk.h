#pragma once

// Walks along a nested GRAFCET's transitions, shared by the structured
// editing operations (grafcetediting.h) and the branch order
// (branchorder.h): both find a branch's steps as what a walk reaches.

#include "core/model/grafcet.h"

#include <set>
#include <vector>

namespace core {

// The steps reachable from `from` (included) along transitions, never
// entering a blocked step nor using the skipped transition (0: none).
std::set<int> reachableSteps(const Grafcet& grafcet, const std::vector<int>& from, const std::set<int>& blocked = {},
                             int skippedTransition = 0);

// Where walks start: the initial steps and the steps no transition reaches,
// less `except` (0: none).
std::vector<int> walkStarts(const Grafcet& grafcet, int except = 0);

} // namespace core
