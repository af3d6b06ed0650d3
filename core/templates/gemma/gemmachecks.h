#pragma once

#include "core/checks/diagnostic.h"

#include <vector>

namespace core {

class Model;

// Every check of spec §5 and more on a GEMMA model, in a stable order:
// model, steps (state order), transitions (template order), variables
// (declaration order). core::checkModel gives these for a GEMMA model.
std::vector<Diagnostic> checkGemmaModel(const Model& model);

} // namespace core
