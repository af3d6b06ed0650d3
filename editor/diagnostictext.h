#pragma once

#include "core/diagnostic.h"

#include <QIcon>
#include <QString>

class QStyle;

namespace editor {

// The message of a diagnostic in the UI language: a translated template per
// code (docs/diagnostics.md), filled with Diagnostic::arguments. Falls back
// to the core's English message when the arguments are not what the code
// promises (a newer core, a code without a template).
QString diagnosticText(const core::Diagnostic& diagnostic);

// "Error", "Warning", "Information".
QString severityText(core::Severity severity);

// The standard message-box icon of the severity, from the given style.
QIcon severityIcon(core::Severity severity, const QStyle* style);

} // namespace editor
