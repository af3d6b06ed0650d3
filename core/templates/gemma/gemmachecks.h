#pragma once

#include "core/checks/diagnostic.h"

#include <vector>

namespace core {

class Grafcet;
class Model;

// Every check of spec §5 and more on a GEMMA model, in a stable order:
// model, steps (state order), transitions (template order), variables
// (declaration order). core::checkModel gives these for a GEMMA model.
std::vector<Diagnostic> checkGemmaModel(const Model& model);

// The sections of checkGemmaModel, for core/checks/incrementalcheck.h. It is
// their concatenation: checkGemmaElements' diagnostics, checkGrafcets,
// checkGemmaVariables with `used` the elements' variableUsed plus
// markNestedUses of every effective GRAFCET, then the machine's checks.
struct GemmaElementChecks {
    std::vector<Diagnostic> diagnostics; // the steps (state order), then the transitions (template order)
    std::vector<bool> variableUsed;      // by declaration index: read by a condition that generates code
};
GemmaElementChecks checkGemmaElements(const Model& model);
// Marks the variables the GRAFCET's texts name (parsed or not).
void markNestedUses(const Model& model, const Grafcet& grafcet, std::vector<bool>& used);
// `used`: by declaration index.
std::vector<Diagnostic> checkGemmaVariables(const Model& model, const std::vector<bool>& used);

} // namespace core
