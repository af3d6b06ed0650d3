#pragma once

// The findings of both layers (docs/verification.md, "Both layers"): runs the
// exploration of core/verification/programexplorer.h and turns what it found
// into findings GV110-GV122; for a model with nested GRAFCETs it also decides
// GV101, GV102 and GV105-GV107 with the real Complete, replacing those the
// GEMMA-layer analysis gave with Complete free.

#include "core/verification/verification.h"

#include <string>
#include <vector>

namespace core {

class Model;

// Whether the model needs the exploration: it has a nested GRAFCET or
// properties to check.
bool needsBothLayers(const Model& model, const VerificationOptions& options);

// The properties a run checks: the model's, then the options'.
std::vector<std::string> propertiesToCheck(const Model& model, const VerificationOptions& options);

// Adds to (and, where said above, replaces in) `result`.
void verifyBothLayers(const Model& model, const VerificationOptions& options, VerificationResult& result);

} // namespace core
