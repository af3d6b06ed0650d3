#pragma once

// What holds across the nested GRAFCETs of one program, whichever template
// owns them (GEMMA's macro-steps, PackML's (mode, state) instances): one
// writer per variable (GG415), and the edge memories <V>_PREV the program
// keeps for the variables read under an edge.

#include "core/codegen/nestedprogram.h"

#include <span>
#include <string>
#include <vector>

namespace core {

struct ProgramProblem;
struct Variable;

// One nested GRAFCET of a program, with the names its problems use
// (NestedScope::element and label).
struct OwnedGrafcet {
    std::string element;
    std::string label;
    NestedGrafcet* grafcet = nullptr;
};

// Spec §3: a variable driven by continuous actions in any GRAFCET and
// written by stored ones has no defined value (IEC 60848); the continuous
// actions win and the stored ones are refused (GG415), so every variable
// keeps one writer. Marks the stored actions unusable, drops them from
// storedTargets and appends a problem for each, in GRAFCET order.
void rejectStoredWritesOfContinuousOutputs(std::span<const OwnedGrafcet> grafcets,
                                           std::vector<ProgramProblem>& problems);

// The BOOL variables read under an edge by a usable receptivity of any of
// the GRAFCETs, spelled as declared, in the order of `variables`.
std::vector<std::string> edgeVariablesOf(std::span<const Variable> variables,
                                         std::span<const NestedGrafcet* const> grafcets);

} // namespace core
