#include "editor/diagnostictext.h"

#include "core/gemmatemplate.h"
#include "core/iectypes.h"

#include <QCoreApplication>
#include <QStyle>

#include <vector>

namespace editor {

namespace {

// The translation context of the messages.
class DiagnosticText {
    Q_DECLARE_TR_FUNCTIONS(DiagnosticText)
};

QString fromStd(const std::string& text)
{
    return QString::fromStdString(text);
}

// The English message as the UI shows sentences: capitalised.
QString fallback(const core::Diagnostic& diagnostic)
{
    QString text = fromStd(diagnostic.message);
    if (!text.isEmpty())
        text[0] = text[0].toUpper();
    return text;
}

// Source of a transition id ("F1->A2" -> "F1", "F->D1" -> "F").
QString sourceOf(const std::string& transitionId)
{
    const std::size_t arrow = transitionId.find("->");
    return fromStd(arrow == std::string::npos ? transitionId : transitionId.substr(0, arrow));
}

// The identifier rule a name breaks, in the UI language; the core's detail
// argument is English, so it is derived again from the name.
QString identifierDetail(const QString& name)
{
    switch (core::identifierProblem(name.toStdString())) {
    case core::IdentifierProblem::None:
        break;
    case core::IdentifierProblem::Empty:
        return DiagnosticText::tr("the name is empty");
    case core::IdentifierProblem::InvalidCharacter:
        return DiagnosticText::tr("'%1' is not a valid IEC 61131-3 identifier: use ASCII letters, digits and '_', "
                                  "not starting with a digit")
            .arg(name);
    case core::IdentifierProblem::DoubleUnderscore:
        return DiagnosticText::tr("'%1' contains '__', which IEC 61131-3 identifiers may not").arg(name);
    case core::IdentifierProblem::TrailingUnderscore:
        return DiagnosticText::tr("'%1' ends with '_', which IEC 61131-3 identifiers may not").arg(name);
    case core::IdentifierProblem::Keyword:
        return DiagnosticText::tr("'%1' is an IEC 61131-3 keyword or type name").arg(name);
    case core::IdentifierProblem::GeneratorName:
        return DiagnosticText::tr("'%1' is a name the generated code uses").arg(name);
    }
    return {};
}

QString tokenText(const std::string& code, const QString& transition, const QString& variable)
{
    if (code == "GG208")
        return DiagnosticText::tr("The token on '%2' in %1 is invalid: '%2' does not occur in the condition.")
            .arg(transition, variable);
    if (code == "GG209")
        return DiagnosticText::tr("The token on '%2' in %1 is ambiguous: the condition uses both %2 and NOT %2, so the "
                                  "token could be neither normally open nor normally closed.")
            .arg(transition, variable);
    if (code == "GG211")
        return DiagnosticText::tr("The token in %1 names '%2', which is not a declared variable.")
            .arg(transition, variable);
    if (code == "GG212")
        return DiagnosticText::tr(
            "The token on '%2' in %1 is invalid: '%2' is compared with '=' or '<>' in the condition, "
            "where it has no polarity; a token can only replace a literal %2 or NOT %2.")
            .arg(transition, variable);
    // GG210
    if (sourceOf(transition.toStdString())
        == QLatin1String(core::kFamilySource.data(), static_cast<qsizetype>(core::kFamilySource.size())))
        return DiagnosticText::tr(
            "The token on '%2' in %1 has no effect and is not generated: family transitions never "
            "wait for Complete.")
            .arg(transition, variable);
    return DiagnosticText::tr(
        "The token on '%2' in %1 has no effect and is not generated: its source %3 is a simple step.")
        .arg(transition, variable, sourceOf(transition.toStdString()));
}

// The translated text, or an empty string when the code has no template
// for this number of arguments.
QString translated(const core::Diagnostic& d)
{
    const std::vector<std::string>& a = d.arguments;
    const std::string& code = d.code;
    const auto arg = [&](std::size_t i) { return fromStd(a[i]); };
    const std::size_t n = a.size();

    if (n == 1) {
        if (code == "GG001")
            return DiagnosticText::tr("The initial step %1 is hidden: the PLC would start in a state that has no code.")
                .arg(arg(0));
        if (code == "GG101")
            return DiagnosticText::tr(
                "Step %1 has no visible outgoing transition: the machine would stay in it forever.")
                .arg(arg(0));
        if (code == "GG102")
            return DiagnosticText::tr("Step %1 has no visible incoming transition: it can never become active.")
                .arg(arg(0));
        if (code == "GG202")
            return DiagnosticText::tr("The condition of %1 is empty: write TRUE for a transition that is always ready.")
                .arg(arg(0));
        if (code == "GG206")
            return DiagnosticText::tr(
                "The family transition %1 is negated, which has no effect: family transitions never wait "
                "for Complete.")
                .arg(arg(0));
        if (code == "GG214")
            return DiagnosticText::tr("The condition of %1 is FALSE: the transition can never fire (hide it instead).")
                .arg(arg(0));
        if (code == "GG305")
            return DiagnosticText::tr("Variable '%1' is not used by any visible transition condition.").arg(arg(0));
    }
    if (n == 2) {
        if (code == "GG103")
            return DiagnosticText::tr(
                "Step %1 cannot be reached from the initial step %2 through visible transitions: it can "
                "never become active.")
                .arg(arg(0), arg(1));
        if (code == "GG205")
            return DiagnosticText::tr(
                "Transition %1 is negated, which has no effect: its source %2 is a simple step, and "
                "negation only changes transitions out of macro and enclosing steps.")
                .arg(arg(0), arg(1));
        if (code == "GG208" || code == "GG209" || code == "GG210" || code == "GG211" || code == "GG212")
            return tokenText(code, arg(0), arg(1));
        if (code == "GG213")
            return DiagnosticText::tr("The condition of %1 is TRUE and does not wait for Complete: the lower-priority "
                                      "transitions %2 can never fire.")
                .arg(arg(0), arg(1));
        if (code == "GG301" || code == "GG302" || code == "GG303") {
            const QString detail = identifierDetail(arg(0));
            return detail.isEmpty() ? QString() : DiagnosticText::tr("Invalid variable name: %1.").arg(detail);
        }
    }
    if (n == 3) {
        if (code == "GG201")
            return DiagnosticText::tr("Syntax error in the condition of %1: %2.").arg(arg(0), arg(2));
        if (code == "GG203")
            return DiagnosticText::tr("In the condition of %1: '%2' is not a declared variable.").arg(arg(0), arg(1));
        if (code == "GG204")
            return DiagnosticText::tr("Type error in the condition of %1: %2.").arg(arg(0), arg(2));
        if (code == "GG207")
            return DiagnosticText::tr(
                "The token on '%2' in %1 is invalid: '%2' is %3, and only BOOL variables can have a "
                "token.")
                .arg(arg(0), arg(1), arg(2));
        if (code == "GG304")
            return DiagnosticText::tr("The default value of variable '%1' is invalid: %2.").arg(arg(0), arg(2));
    }
    return {};
}

} // namespace

QString diagnosticText(const core::Diagnostic& diagnostic)
{
    const QString text = translated(diagnostic);
    return text.isEmpty() ? fallback(diagnostic) : text;
}

QString severityText(core::Severity severity)
{
    switch (severity) {
    case core::Severity::Error:
        return DiagnosticText::tr("Error");
    case core::Severity::Warning:
        return DiagnosticText::tr("Warning");
    case core::Severity::Info:
        return DiagnosticText::tr("Information");
    }
    return {};
}

QIcon severityIcon(core::Severity severity, const QStyle* style)
{
    switch (severity) {
    case core::Severity::Error:
        return style->standardIcon(QStyle::SP_MessageBoxCritical);
    case core::Severity::Warning:
        return style->standardIcon(QStyle::SP_MessageBoxWarning);
    case core::Severity::Info:
        return style->standardIcon(QStyle::SP_MessageBoxInformation);
    }
    return {};
}

} // namespace editor
