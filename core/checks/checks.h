#pragma once

#include "core/checks/diagnostic.h"

#include <vector>

namespace core {

class Model;

// Every check of the model's template, in a stable order: GEMMA's
// (core/templates/gemma/gemmachecks.h) or PackML's
// (core/templates/packml/packmlchecks.h).
std::vector<Diagnostic> checkModel(const Model& model);

} // namespace core
