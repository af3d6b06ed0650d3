#pragma once

// The checks that look at a nested GRAFCET as a whole (spec grafcet-layer.md
// §3): initial steps, reachability, dead ends, Complete, selections that are
// not exclusive, transient steps under "until stable". What is wrong with one
// receptivity or action on its own is found where the code generator reads
// them (core/codegen/nestedprogram.h) and reported by checkModel from there.
// The codes are documented in docs/diagnostics.md.

#include "core/checks/diagnostic.h"

#include <functional>
#include <string_view>
#include <vector>

namespace core {

class Model;

// In a stable order: GEMMA steps in state order, then per GRAFCET the
// GRAFCET itself, its steps by number, its transitions by number.
std::vector<Diagnostic> checkGrafcets(const Model& model);

// Calls `use` with every identifier the effective nested GRAFCETs' texts
// mention (receptivities and actions, parsed or not), so that a variable used
// only there does not count as unused.
void forEachNestedIdentifier(const Model& model, const std::function<void(std::string_view)>& use);

} // namespace core
