#pragma once

// The name a user mode may take in the editor (spec packml.md §3.1): an IEC
// identifier, not reserved by the generated code (§5.3), unique among the
// modes ignoring case. The model keeps any name (a file may hold a wrong
// one, PM002 reports it); the editor does not write a wrong one.

#include "core/model/model.h"

#include <string_view>

namespace editor {

// Success, or why mode `number` cannot be named `name` in this model.
core::Status modeNameProblem(const core::Model& model, int number, std::string_view name);

} // namespace editor
