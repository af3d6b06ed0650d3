#pragma once

// The PackML code as the editor's Structured Text dock previews it (spec
// packml.md §6): the PROGRAM with the lines of each unit mode and each state
// of it, and the function block of one GRAFCET with its steps' and
// transitions' lines, so that the dock follows the selection.

#include "core/codegen/stgenerator.h"

#include <string_view>

namespace core::packml {

// text: exactly formatPou of the PROGRAM. Keys of the ranges, in section 3
// (the state machine of the current unit mode):
//   "1": the branch of mode 1;
//   "1/Execute": the branch of Execute in mode 1 (a grafcetKey).
StPreview previewPackmlProgram(const Model& model, Dialect dialect);

// The function block of the GRAFCET stored under `key` (a grafcetKey), as
// previewNestedFunctionBlock gives it ("X3", "T2"); empty when the model
// has no GRAFCET there.
StPreview previewPackmlFunctionBlock(const Model& model, std::string_view key, Dialect dialect);

} // namespace core::packml
