#pragma once

#include "core/checks/diagnostic.h"

#include <QString>

namespace editor {

// The message of a check of the virtual machine (GG601-GG608,
// core/machine/machinechecks.h) in the UI language, filled with
// Diagnostic::arguments (docs/diagnostics.md); empty when the code is none of
// them or the arguments are not those it promises. Component, role and
// parameter names are the file's and stay as they are.
QString machineDiagnosticText(const core::Diagnostic& diagnostic);

} // namespace editor
