#pragma once

#include "core/checks/diagnostic.h"

#include <QString>

namespace editor {

// Where a PackML diagnostic points, in the UI language: "mode Manual",
// "command Hold", "Manual: Execute", "request of mode Manual"; empty for
// the other targets. State, command and base mode names are PackTags' and
// stay as they are.
QString packmlElementText(const core::Diagnostic& diagnostic);

// Does the diagnostic concern a PackML command or request condition (its
// first argument then names the element in English)?
bool isPackMLCondition(const core::Diagnostic& diagnostic);

// The message of a PackML check (PM001-PM019, and GG202 on a command) in the
// UI language, filled with Diagnostic::arguments (docs/packml.md); empty
// when the code is none of them or the arguments are not those it promises.
QString packmlDiagnosticText(const core::Diagnostic& diagnostic);

} // namespace editor
