#pragma once

// The findings of both layers (docs/verification.md, "Both layers"): runs the
// exploration of core/verification/programexplorer.h and turns what it found
// into findings GV110-GV122; for a model with nested GRAFCETs it also decides
// GV101, GV102 and GV105-GV107 with the real Complete, replacing those the
// GEMMA-layer analysis gave with Complete free.

#include "core/verification/verification.h"

#include <chrono>
#include <string>
#include <vector>

namespace core {

class Model;

// Whether the model needs the exploration: it has a nested GRAFCET or
// properties to check, or the run is closed loop.
bool needsBothLayers(const Model& model, const VerificationOptions& options);

// The properties a run checks: the model's, then the options'.
std::vector<std::string> propertiesToCheck(const Model& model, const VerificationOptions& options);

// Adds to (and, where said above, replaces in) `result`. `deadline` ends
// the explorations (the first, and the one with time counted in scans that
// re-searches what the timer abstraction found): the end of the whole run's
// time limit, so that the GEMMA layer and both layers share it.
void verifyBothLayers(const Model& model, const VerificationOptions& options, VerificationResult& result,
                      std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max());

} // namespace core
