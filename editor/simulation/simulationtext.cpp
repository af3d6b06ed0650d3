#include "editor/simulation/simulationtext.h"

#include "editor/diagnostictext.h"
#include "editor/docks/elementlabels.h"

#include "core/diagnostic.h"

#include <QCoreApplication>
#include <QStringList>

namespace editor {

namespace {

// The translation context of the texts.
class SimulationText {
    Q_DECLARE_TR_FUNCTIONS(SimulationText)
};

QString fromStd(const std::string& text)
{
    return QString::fromStdString(text);
}

QString readingText(const core::ConditionReading& reading)
{
    const QString name = fromStd(reading.name);
    const QString value = fromStd(reading.value);
    if (reading.isToken())
        //: a token variable, its value, then the literal it stores ("NOT Stop")
        return SimulationText::tr("%1 = %2 (token of %3)").arg(name, value, fromStd(reading.tokenLiteral));
    return QStringLiteral("%1 = %2").arg(name, value); // code in every language
}

QString expressionText(const core::ExplanationReason& reason)
{
    const QString expression = fromStd(reason.subject);
    const QString value = fromStd(reason.value);
    if (reason.readings.empty())
        //: an IEC expression of a condition, then TRUE or FALSE
        return SimulationText::tr("%1 is %2").arg(expression, value);
    QStringList readings;
    for (const core::ConditionReading& reading : reason.readings)
        readings << readingText(reading);
    //: an IEC expression of a condition, TRUE or FALSE, then the values it reads ("Speed = 3")
    return SimulationText::tr("%1 is %2 (%3)").arg(expression, value, readings.join(QStringLiteral(", ")));
}

// The checks' diagnostic of the same code carries the same arguments.
QString unusableText(const core::ExplanationReason& reason)
{
    if (reason.code.empty() && reason.message.empty())
        return SimulationText::tr("The condition cannot be used: it is FALSE.");
    core::Diagnostic diagnostic;
    diagnostic.code = reason.code;
    diagnostic.target = core::Diagnostic::Target::Transition;
    diagnostic.field = "condition";
    diagnostic.message = reason.message;
    diagnostic.arguments = reason.arguments;
    if (!reason.arguments.empty())
        diagnostic.element = reason.arguments.front();
    return diagnosticText(diagnostic);
}

QString failureProblem(const core::ScenarioFailure& failure)
{
    using Kind = core::ScenarioFailure::Kind;
    const QString subject = fromStd(failure.subject);
    const QString expected = fromStd(failure.expected);
    const QString actual = fromStd(failure.actual);
    switch (failure.kind) {
    case Kind::CannotApply:
        //: %1: why, from the simulator (English)
        return SimulationText::tr("cannot apply: %1").arg(fromStd(failure.detail));
    case Kind::WrongStep: return SimulationText::tr("expected step %1, active step is %2").arg(expected, actual);
    case Kind::NoVisibleStep:
        return SimulationText::tr("expected step %1, no visible step is active (State = %2)").arg(expected, actual);
    case Kind::NothingFired: return SimulationText::tr("expected %1 to fire, no transition fired").arg(expected);
    case Kind::WrongFiring: return SimulationText::tr("expected %1 to fire, %2 fired").arg(expected, actual);
    case Kind::UnexpectedFiring: return SimulationText::tr("expected no transition to fire, %1 fired").arg(actual);
    case Kind::WrongToken:
        return SimulationText::tr("expected token %1 = %2, it is %3").arg(subject, expected, actual);
    case Kind::WrongVariable:
        //: a variable, the value expected, the value it has
        return SimulationText::tr("expected %1 = %2, it is %3").arg(subject, expected, actual);
    case Kind::UnknownVariable: return SimulationText::tr("unknown variable '%1'").arg(subject);
    case Kind::WrongEntry: return SimulationText::tr("expected Entry = %1, it is %2").arg(expected, actual);
    case Kind::WrongComplete:
        return SimulationText::tr("expected %1.Complete = %2, it is %3").arg(subject, expected, actual);
    }
    return {};
}

} // namespace

QString explanationReasonText(const core::ExplanationReason& reason)
{
    using Kind = core::ExplanationReason::Kind;
    switch (reason.kind) {
    case Kind::Reading: return reason.readings.empty() ? QString() : readingText(reason.readings.front());
    case Kind::Literal: return fromStd(reason.value);
    case Kind::Expression: return expressionText(reason);
    case Kind::CompleteFalse:
        //: a macro-step or enclosing step; the transition waits for its Complete
        return SimulationText::tr("%1.Complete = FALSE").arg(fromStd(reason.subject));
    case Kind::FiresFirst:
        //: a transition of higher priority whose condition holds
        return SimulationText::tr("%1 fires first").arg(transitionLabel(fromStd(reason.subject)));
    case Kind::Unusable: return unusableText(reason);
    }
    return {};
}

QString scenarioFailureText(const core::ScenarioFailure& failure)
{
    //: a scan number, then what differed
    return SimulationText::tr("scan %1: %2").arg(failure.scan).arg(failureProblem(failure));
}

} // namespace editor
