#pragma once

// The checks on what a nested GRAFCET does from one evolution to the next
// (spec grafcet-layer.md §4.1), as a teacher reviews a GRAFCET:
// - GG423: a BOOL input read by its level on a transition and again on a
//   transition that can fire right after it: holding it runs through the
//   step between (a step-by-step mode that reads StepButton everywhere);
// - GG424 (information): a selection none of whose branches fires for some
//   values of the variables its receptivities read; waiting may be intended.
// The codes are documented in docs/diagnostics.md.

#include "core/checks/diagnostic.h"
#include "core/condition/conditionparser.h"

#include <map>
#include <vector>

namespace core {

class Grafcet;
class GrafcetAdjacency;
class Model;
struct Step;

// Selections reading more variables than this are not examined (GG424).
inline constexpr std::size_t kMaxSelectionVariables = 12;

// `receptivities`: the parse of every transition's receptivity, by number;
// `adjacency`: the GRAFCET's.
std::vector<Diagnostic> checkGrafcetSequences(const Model& model, const Step& owner, const Grafcet& grafcet,
                                              const std::map<int, cond::ParseResult>& receptivities,
                                              const GrafcetAdjacency& adjacency);

} // namespace core
