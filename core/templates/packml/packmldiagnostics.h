#pragma once

// How the PackML checks (packmlchecks.h) address what they report: the
// Diagnostic targets of a unit mode, a command, a state in a mode and a
// mode's request condition, filled alike by every check.

#include "core/checks/diagnostic.h"
#include "core/templates/packml/packmlconfiguration.h"

#include <optional>
#include <string>
#include <vector>

namespace core::packml {

// What a diagnostic says besides where: its code, severity, field, English
// message and the arguments the editor translates it from.
struct Finding {
    std::string code;
    Severity severity = Severity::Error;
    std::string field;
    std::string message;
    std::vector<std::string> arguments;
    std::optional<Span> span = std::nullopt;
};

// The name a mode goes by in messages: its display name, or its number when
// a user mode has none (PM002 says so).
std::string modeLabel(const Mode& mode);

Diagnostic modelDiagnostic(Finding finding);
Diagnostic modeDiagnostic(const Mode& mode, Finding finding);
Diagnostic modeStateDiagnostic(const Mode& mode, State state, Finding finding);
Diagnostic commandDiagnostic(Command command, Finding finding);
Diagnostic requestDiagnostic(const Mode& mode, Finding finding);
Diagnostic variableDiagnostic(const std::string& name, Finding finding);

} // namespace core::packml
