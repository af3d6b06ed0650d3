#include "core/templates/packml/packmldiagnostics.h"

#include <utility>

namespace core::packml {

namespace {

Diagnostic make(Diagnostic::Target target, std::string element, Finding finding)
{
    Diagnostic diagnostic;
    diagnostic.code = std::move(finding.code);
    diagnostic.severity = finding.severity;
    diagnostic.target = target;
    diagnostic.element = std::move(element);
    diagnostic.field = std::move(finding.field);
    diagnostic.message = std::move(finding.message);
    diagnostic.span = finding.span;
    diagnostic.arguments = std::move(finding.arguments);
    return diagnostic;
}

} // namespace

std::string modeLabel(const Mode& mode)
{
    const std::string_view name = mode.displayName();
    return name.empty() ? std::to_string(mode.number) : std::string(name);
}

Diagnostic modelDiagnostic(Finding finding)
{
    return make(Diagnostic::Target::Model, {}, std::move(finding));
}

Diagnostic modeDiagnostic(const Mode& mode, Finding finding)
{
    Diagnostic diagnostic = make(Diagnostic::Target::Mode, modeLabel(mode), std::move(finding));
    diagnostic.mode = mode.number;
    return diagnostic;
}

Diagnostic modeStateDiagnostic(const Mode& mode, State state, Finding finding)
{
    Diagnostic diagnostic = make(Diagnostic::Target::ModeState, modeLabel(mode), std::move(finding));
    diagnostic.mode = mode.number;
    diagnostic.state = std::string(stateName(state));
    return diagnostic;
}

Diagnostic commandDiagnostic(Command command, Finding finding)
{
    return make(Diagnostic::Target::Command, std::string(commandName(command)), std::move(finding));
}

Diagnostic requestDiagnostic(const Mode& mode, Finding finding)
{
    Diagnostic diagnostic = make(Diagnostic::Target::Request, modeLabel(mode), std::move(finding));
    diagnostic.mode = mode.number;
    return diagnostic;
}

Diagnostic variableDiagnostic(const std::string& name, Finding finding)
{
    return make(Diagnostic::Target::Variable, name, std::move(finding));
}

} // namespace core::packml
