#pragma once

#include "core/checks/diagnostic.h"

#include <vector>

namespace core {

class Model;

// Every check of spec §5 and more, in a stable order: model, steps (state
// order), transitions (template order), variables (declaration order).
std::vector<Diagnostic> checkModel(const Model& model);

} // namespace core
