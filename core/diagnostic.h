#pragma once

#include "core/span.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace core {

enum class Severity { Error, Warning, Info };
std::string_view severityName(Severity severity); // "error", "warning", "info"

// One finding of the checks (spec §5). The code is stable: the editor
// translates by code, tests and scripts match on it; the README lists them.
struct Diagnostic {
    enum class Target { Model, Step, Transition, Variable };

    std::string code;         // "GG201"
    Severity severity = Severity::Error;
    Target target = Target::Model;
    std::string element;      // step id, transition id, variable name; empty for the model
    std::string field;        // the field at fault: "condition", "tokens", "name", "default", ...
    std::string message;      // English
    std::optional<Span> span; // for conditions: where in the text
    std::vector<std::string> arguments; // the values the message names, for translation

    friend bool operator==(const Diagnostic&, const Diagnostic&) = default;
};

// "A1", "F1->A2", the variable name, or "model".
std::string diagnosticElementLabel(const Diagnostic& diagnostic);

bool hasErrors(const std::vector<Diagnostic>& diagnostics);

} // namespace core
