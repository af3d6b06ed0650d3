#include "core/diagnostic.h"

#include <algorithm>

namespace core {

std::string_view severityName(Severity severity)
{
    switch (severity) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Info: return "info";
    }
    return "?";
}

std::string diagnosticElementLabel(const Diagnostic& diagnostic)
{
    if (diagnostic.target == Diagnostic::Target::Model || diagnostic.element.empty())
        return "model";
    return diagnostic.element;
}

bool hasErrors(const std::vector<Diagnostic>& diagnostics)
{
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

} // namespace core
