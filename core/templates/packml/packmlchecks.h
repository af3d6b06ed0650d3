#pragma once

// The checks of a PackML model (spec packml.md §7, PM001–PM019), with the
// GEMMA checks that apply to it: GG201–GG204 on the command and request
// conditions, GG301, GG302 and GG304 on the variables. core::checkModel
// gives these for a PackML model. The nested GRAFCETs' own checks (GG4xx)
// are not among them. The codes are documented in docs/packml.md.

#include "core/checks/diagnostic.h"

#include <vector>

namespace core {
class Model;
}

namespace core::packml {

// In a stable order: the model's settings, the command conditions (command
// order) and the request conditions (mode order), the commands as a whole,
// the modes (mode order; the mode, then its states), where paths and
// Complete lead, the variables (declaration order).
std::vector<Diagnostic> checkPackMLModel(const Model& model);

} // namespace core::packml
