#pragma once

#include "core/checks/diagnostic.h"
#include "core/verification/verification.h"

#include <QString>

namespace editor {

// The message of a diagnostic in the UI language: a translated template per
// code (docs/diagnostics.md), filled with Diagnostic::arguments. Falls back
// to the core's English message when the arguments are not what the code
// promises (a newer core, a code without a template).
QString diagnosticText(const core::Diagnostic& diagnostic);

// The message of a verification finding in the UI language, the same way:
// a template per GV code (docs/verification.md) filled with
// VerificationFinding::arguments (the element, then the elements it names).
// Where the core words one code several ways, the template states what they
// share. Falls back to the core's English message for an unknown code.
QString verificationText(const core::VerificationFinding& finding);

// Why `name` is no valid variable name (the identifier rules of spec §3),
// in the UI language; empty when it is one.
QString identifierProblemText(const QString& name);

// "Error", "Warning", "Information".
QString severityText(core::Severity severity);

} // namespace editor
