#pragma once

// The body of S_FB for a step with a nested GRAFCET (spec grafcet-layer.md
// §4.2): the Initialization call, the evolution (one per call, or repeated
// until stable), the actions, the TONs of the time-dependent receptivities and
// the continuous outputs. core/simulation runs the same NestedGrafcet with the
// same semantics; tests/core/test_nestedagreement.cpp holds them together.

#include "core/codegen/plcproject.h"

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace core {

struct GemmaStep;
struct GemmaProgram;
struct ProgramProblem;
struct NestedGrafcet;
enum class EvolutionRule;

struct NestedCode {
    std::vector<PlcVariable> outputs; // after Complete: the continuous outputs, then Unstable (until stable)
    std::vector<PlcVariable> locals;  // step activities, TONs, the evolution's flags
    std::vector<PlcVariable> edgeMemories; // the <V>_PREV globals it reads (IEC: VAR_EXTERNAL)
    std::string body;
};

// One nested GRAFCET and what its code needs of the program around it,
// whichever template owns it (a GEMMA macro-step, a PackML (mode, state)).
struct NestedCodeSource {
    const NestedGrafcet& grafcet;
    std::string_view element; // the problems located here become comments of the body
    std::string_view label;   // how the declarations' comments name it: "F1", "Production Execute"
    EvolutionRule evolution;
    std::span<const std::string> edgeVariables; // the program's <V>_PREV, slot order
    std::span<const ProgramProblem> problems;     // the program's
};

NestedCode generateNestedCode(const NestedCodeSource& source,
                              const std::function<std::string(std::string_view)>& global,
                              const std::function<std::string(std::string_view)>& edgeMemory);

// `global` spells a declared variable as the POU reads it ("Start" or
// "GVL.Start") and records the read; `edgeMemory` the same for "Start_PREV".
NestedCode generateNestedCode(const GemmaStep& step, const GemmaProgram& program,
                              const std::function<std::string(std::string_view)>& global,
                              const std::function<std::string(std::string_view)>& edgeMemory);

} // namespace core
