#pragma once

// The checks that look at a nested GRAFCET as a whole (spec grafcet-layer.md
// §3): initial steps, reachability, dead ends, Complete, selections that are
// not exclusive, transient steps under "until stable". What is wrong with one
// receptivity or action on its own is found where the code generator reads
// them (core/codegen/nestedprogram.h) and reported by checkModel from there.
// The codes are documented in docs/diagnostics.md.

#include "core/checks/diagnostic.h"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace core {

class Grafcet;
class Model;
struct ProgramProblem;
struct Step;

// In a stable order: GEMMA steps in state order, then per GRAFCET the
// GRAFCET itself, its steps by number, its transitions by number.
std::vector<Diagnostic> checkGrafcets(const Model& model);

// The parts of checkGrafcets, for core/checks/incrementalcheck.h, which
// recomputes them one GRAFCET at a time:
// - what the first section says about the GRAFCET of `step` (nothing when it
//   has none; GG422 when it is kept but not used);
// - the nested problems among the code generator's (core/codegen/nestedprogram.h),
//   as diagnostics, in their order;
// - GG420, the variables named like what the nested GRAFCETs' code declares.
std::vector<Diagnostic> checkStepGrafcet(const Model& model, const Step& step);
std::vector<Diagnostic> nestedProblemDiagnostics(const std::vector<ProgramProblem>& problems);
std::vector<Diagnostic> reservedNameDiagnostics(const Model& model, bool hasNestedGrafcets,
                                                const std::vector<std::string>& edgeVariables);

// Calls `use` with every identifier the GRAFCET's texts mention.
void forEachGrafcetIdentifier(const Grafcet& grafcet, const std::function<void(std::string_view)>& use);

// Calls `use` with every identifier the effective nested GRAFCETs' texts
// mention (receptivities and actions, parsed or not), so that a variable used
// only there does not count as unused.
void forEachNestedIdentifier(const Model& model, const std::function<void(std::string_view)>& use);

} // namespace core
