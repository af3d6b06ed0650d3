#pragma once

#include "core/checks/diagnostic.h"

#include <vector>

namespace core {

class Model;

// Every check of spec §5 and more, in a stable order: model, steps (state
// order), transitions (template order), variables (declaration order). A
// PackML model gets its own checks (core/templates/packml/packmlchecks.h).
std::vector<Diagnostic> checkModel(const Model& model);

} // namespace core
