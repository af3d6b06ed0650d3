#pragma once

// The function block of one nested GRAFCET as the editor previews it, with
// the lines that belong to each of its steps and transitions, so that the
// Structured Text dock can highlight the selected one.

#include "core/codegen/stgenerator.h"

#include <string_view>

namespace core {

// text: exactly formatPou of the POU "<stepId>_FB"; empty when the model
// generates none for that step (it is hidden, simple, or has no GRAFCET).
// Keys of the ranges, each a run of consecutive lines:
//   "X3": step 3 (its activity's declaration and assignments, its Left and
//         Entered flags and the IF blocks of its stored actions);
//   "T2": transition 2 (its fire flag's declaration and its firing condition).
// An element with several runs has its first under its key, the next ones
// under "X3@2", "X3@3"...
StPreview previewNestedFunctionBlock(const Model& model, std::string_view stepId, Dialect dialect);

// The same for a function block POU of any template (a PackML GRAFCET's
// "<Owner>_<State>_FB" as core/templates/packml/packmlpreview.h finds it).
StPreview previewFunctionBlockPou(const PlcPou& pou, Dialect dialect);

} // namespace core
