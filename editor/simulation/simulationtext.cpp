#include "editor/simulation/simulationtext.h"

#include "editor/stdstring.h"
#include "editor/text/diagnostictext.h"
#include "editor/text/elementlabels.h"
#include "editor/text/valueproblemtext.h"

#include "core/checks/diagnostic.h"
#include "core/machine/closedloopscenario.h"
#include "core/simulation/scenario.h"

#include <QCoreApplication>
#include <QStringList>

namespace editor {

namespace {

// The translation context of the texts.
class SimulationText {
    Q_DECLARE_TR_FUNCTIONS(SimulationText)
};

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
    case Kind::WrongNestedSteps:
        //: %1: a GEMMA step; %2, %3: lists of nested step numbers
        return SimulationText::tr("expected the active steps of %1 to be %2, they are %3").arg(subject, expected, actual);
    case Kind::WrongUnstable:
        return SimulationText::tr("expected %1.Unstable = %2, it is %3").arg(subject, expected, actual);
    }
    return {};
}

// What a syntax error expected, then what it found: %1 is a word of the
// file in quotes, or "the end of the line".
QString syntaxErrorText(core::ScenarioError::Kind kind, const QString& found)
{
    using Kind = core::ScenarioError::Kind;
    switch (kind) {
    case Kind::ExpectedAt:
        //: %1: the word found in quotes, or "the end of the line"; 'at SCAN:' is scenario syntax
        return SimulationText::tr("expected 'at SCAN:' at the start of the line, found %1").arg(found);
    case Kind::ExpectedScanNumber:
        return SimulationText::tr("expected a scan number after 'at', found %1").arg(found);
    case Kind::ExpectedColon: return SimulationText::tr("expected ':' after the scan number, found %1").arg(found);
    case Kind::ExpectedSetOrExpect: return SimulationText::tr("expected 'set' or 'expect', found %1").arg(found);
    case Kind::ExpectedSetItem:
        return SimulationText::tr("expected a variable name or 'complete STEP', found %1").arg(found);
    case Kind::ExpectedStepAfterComplete:
        return SimulationText::tr("expected a step id after 'complete', found %1").arg(found);
    case Kind::ExpectedStepAfterStep:
        return SimulationText::tr("expected a step id after 'step', found %1").arg(found);
    case Kind::ExpectedTransition:
        return SimulationText::tr("expected a transition id or 'none' after 'fired', found %1").arg(found);
    case Kind::ExpectedToken: return SimulationText::tr("expected a token name after 'token', found %1").arg(found);
    case Kind::ExpectedVariable:
        return SimulationText::tr("expected a variable name after 'variable', found %1").arg(found);
    case Kind::ExpectedExpectItem:
        //: step, fired, token, variable, entry and complete are scenario syntax
        return SimulationText::tr(
                   "expected step, fired, token, variable, entry, complete or nested after 'expect', found %1")
            .arg(found);
    case Kind::ExpectedStepAfterNested:
        return SimulationText::tr("expected a step id after 'nested', found %1").arg(found);
    case Kind::ExpectedNestedItem:
        //: steps and unstable are scenario syntax
        return SimulationText::tr("expected 'steps' or 'unstable' after the step id, found %1").arg(found);
    case Kind::ExpectedStepNumber: return SimulationText::tr("expected a step number, found %1").arg(found);
    case Kind::ExpectedEqualsAfterStep:
        return SimulationText::tr("expected '=' after the step id, found %1").arg(found);
    case Kind::ExpectedEqualsAfterVariable:
        return SimulationText::tr("expected '=' after the variable name, found %1").arg(found);
    case Kind::ExpectedEqualsAfterToken:
        return SimulationText::tr("expected '=' after the token name, found %1").arg(found);
    case Kind::ExpectedEqualsAfterEntry: return SimulationText::tr("expected '=' after 'entry', found %1").arg(found);
    case Kind::ExpectedValue: return SimulationText::tr("expected a value after '=', found %1").arg(found);
    case Kind::ExpectedBool: return SimulationText::tr("expected TRUE or FALSE, found %1").arg(found);
    case Kind::ExpectedCompleteValue:
        //: auto is scenario syntax
        return SimulationText::tr("expected TRUE, FALSE or auto, found %1").arg(found);
    case Kind::ExpectedCommaOrEnd: return SimulationText::tr("expected ',' or the end of the line, found %1").arg(found);
    case Kind::ExpectedEnd: return SimulationText::tr("expected the end of the line, found %1").arg(found);
    case Kind::ExpectedCommand:
        //: 'command' is scenario syntax
        return SimulationText::tr("expected a command name after 'command', found %1").arg(found);
    case Kind::ExpectedMode:
        //: 'mode' is scenario syntax
        return SimulationText::tr("expected a mode name or number after 'mode', found %1").arg(found);
    case Kind::ExpectedState:
        //: 'state' is scenario syntax
        return SimulationText::tr("expected a state name after 'state', found %1").arg(found);
    case Kind::ExpectedFaultTarget:
        //: 'fault' is scenario syntax
        return SimulationText::tr("expected a sensor or component name after 'fault', found %1").arg(found);
    case Kind::ExpectedFaultKind:
        //: stuck, flicker, jam and clear are scenario syntax
        return SimulationText::tr("expected stuck, flicker, jam or clear after the name, found %1").arg(found);
    default: return {};
    }
}

// Two sets of one thing to different values in one scan.
QString conflictText(const core::ScenarioError& error)
{
    const QString parts[] = {fromStd(error.subject), QString::number(error.scan), fromStd(error.otherValue),
                             QString::number(error.otherLine), fromStd(error.found), QString::number(error.line)};
    if (error.kind == core::ScenarioError::Kind::ConflictingComplete)
        //: a step id, a scan number, then each value with the line that sets it
        return SimulationText::tr("%1's Complete is set to two values in scan %2: %3 on line %4, %5 on line %6")
            .arg(parts[0], parts[1], parts[2], parts[3], parts[4], parts[5]);
    //: a variable, a scan number, then each value with the line that sets it
    return SimulationText::tr("%1 is set to two values in scan %2: %3 on line %4, %5 on line %6")
        .arg(parts[0], parts[1], parts[2], parts[3], parts[4], parts[5]);
}

QString scenarioErrorMessage(const core::ScenarioError& error)
{
    using Kind = core::ScenarioError::Kind;
    const QString subject = fromStd(error.subject);
    switch (error.kind) {
    case Kind::ScanBelowOne: return SimulationText::tr("scans are numbered from 1");
    case Kind::ScanTooLarge:
        //: %2: the highest scan number a scenario may name
        return SimulationText::tr("scan number %1 is too large: a scenario runs at most %2 scans")
            .arg(subject)
            .arg(core::kMaxScenarioScan);
    case Kind::UnknownVariable: return SimulationText::tr("unknown variable '%1'").arg(subject);
    case Kind::InvalidValue:
        //: a variable, its IEC type (INT), then why the value does not fit it
        return SimulationText::tr("%1 is %2: %3")
            .arg(subject, fromStd(error.type), error.problem ? valueProblemText(*error.problem) : fromStd(error.detail));
    case Kind::HiddenStep: return SimulationText::tr("step %1 is hidden: it does not exist for the simulator").arg(subject);
    case Kind::UnknownStep: return SimulationText::tr("unknown step '%1'").arg(subject);
    case Kind::SimpleStep: return SimulationText::tr("step %1 is a simple step: it has no Complete").arg(subject);
    case Kind::NotAnInput:
        return error.detail == "output"
            ? SimulationText::tr("%1 is an output variable: the program writes it, a scenario sets only inputs").arg(subject)
            : SimulationText::tr("%1 is an internal variable: the program writes it, a scenario sets only inputs")
                  .arg(subject);
    case Kind::MachineSensor:
        //: %1: a variable; %2: the name of a component of the virtual machine ("Clamp")
        return SimulationText::tr("%1 is a sensor of the machine's %2: the machine sets it; set it by hand in open "
                                  "loop only")
            .arg(subject, fromStd(error.detail));
    case Kind::FaultInOpenLoop:
        return SimulationText::tr(
            "a fault needs the virtual machine: run the scenario in closed loop, on a model with a machine");
    case Kind::FaultOnOperatorInput:
        //: %1: a variable; %2: the name of a component of the virtual machine ("Start"); 'set' is scenario syntax
        return SimulationText::tr("%1 is an operator input of the machine's %2: the user drives it with set; a fault "
                                  "applies to the machine's sensors")
            .arg(subject, fromStd(error.detail));
    case Kind::FaultNotMachineSensor:
        return SimulationText::tr("%1 is no sensor of the machine: a fault applies to the inputs a component writes")
            .arg(subject);
    case Kind::FaultUnknownComponent: return SimulationText::tr("no component '%1' in the machine").arg(subject);
    case Kind::FaultCannotJam:
        //: %1: a component of the virtual machine; %2: its kind as the file spells it ("lamp", "push-button")
        return SimulationText::tr("%1 is a %2: only cylinders and conveyors jam").arg(subject, fromStd(error.detail));
    case Kind::FaultUnknownTarget:
        return SimulationText::tr("'%1' is neither a sensor nor a component of the machine").arg(subject);
    case Kind::NoGrafcet: return SimulationText::tr("step %1 has no nested GRAFCET").arg(subject);
    case Kind::CompleteFromGrafcet:
        return SimulationText::tr("the Complete of %1 comes from its nested GRAFCET: it cannot be set").arg(subject);
    case Kind::IneffectiveTransition:
        return SimulationText::tr("transition %1 is not effective (it or one of its steps is hidden)").arg(subject);
    case Kind::UnknownTransition: return SimulationText::tr("unknown transition '%1'").arg(subject);
    case Kind::UnknownToken: return SimulationText::tr("unknown token '%1'").arg(subject);
    case Kind::InvalidUtf8: return SimulationText::tr("invalid UTF-8: a scenario file must be UTF-8 text");
    case Kind::UnknownCommand: return SimulationText::tr("unknown command '%1'").arg(subject);
    case Kind::UnknownMode: return SimulationText::tr("unknown unit mode '%1'").arg(subject);
    case Kind::UnknownState: return SimulationText::tr("unknown state '%1'").arg(subject);
    case Kind::UnknownInstance:
        //: %1: a PackML function block instance (Production_Resetting)
        return SimulationText::tr("unknown instance '%1'").arg(subject);
    case Kind::PackMLOnly:
        //: %1: scenario syntax ("command", "expect state")
        return SimulationText::tr("'%1' is for PackML models only").arg(subject);
    case Kind::NotForPackML:
        //: %1: scenario syntax ("expect step", "set complete")
        return SimulationText::tr("'%1' is for GEMMA models only").arg(subject);
    case Kind::EdgeTooSoon:
        //: %1: "command" or "mode" (scenario syntax); %2: a scan number; %3: a line number
        return SimulationText::tr("a %1 in scan %2 right after the one of line %3 is not seen: the request must be "
                                  "FALSE for one scan in between")
            .arg(subject)
            .arg(error.scan)
            .arg(error.otherLine);
    case Kind::ConflictingValue:
    case Kind::ConflictingComplete: return conflictText(error);
    default: break;
    }
    const QString found = error.found.empty() ? SimulationText::tr("the end of the line")
                                              : QStringLiteral("'%1'").arg(fromStd(error.found));
    return syntaxErrorText(error.kind, found);
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
    case Kind::StepsInactive: {
        QStringList steps;
        for (int step : reason.steps)
            steps << QString::number(step);
        if (steps.size() == 1)
            //: an upstream step of a nested GRAFCET's transition
            return SimulationText::tr("step %1 is not active").arg(steps.front());
        //: the upstream steps of a nested GRAFCET's transition ("2, 3")
        return SimulationText::tr("steps %1 are not active").arg(steps.join(QStringLiteral(", ")));
    }
    case Kind::NoRisingEdge:
        //: %1: a BOOL variable; %2: its value now; %3: its value at the end of the previous scan
        return SimulationText::tr("no rising edge of %1 this scan (%1 = %2, at the end of the previous scan %3)")
            .arg(fromStd(reason.subject), fromStd(reason.value), fromStd(reason.previous));
    case Kind::NoFallingEdge:
        //: %1: a BOOL variable; %2: its value now; %3: its value at the end of the previous scan
        return SimulationText::tr("no falling edge of %1 this scan (%1 = %2, at the end of the previous scan %3)")
            .arg(fromStd(reason.subject), fromStd(reason.value), fromStd(reason.previous));
    case Kind::TimerNotElapsed:
        //: %1: a time-dependent receptivity ("5s/X2"); %2: its step; %3 of %4: elapsed and set time in ms
        return SimulationText::tr("%1 is FALSE: step %2 active for %3 ms of %4 ms")
            .arg(fromStd(reason.subject), reason.steps.empty() ? QString() : QString::number(reason.steps.front()))
            .arg(reason.elapsedMs)
            .arg(reason.durationMs);
    case Kind::NotCalled:
        //: a macro-step or enclosing step
        return SimulationText::tr("%1 is not the active step: its GRAFCET does not evolve in the next scan")
            .arg(fromStd(reason.subject));
    }
    return {};
}

QString stepNumbersText(const std::vector<int>& numbers)
{
    QStringList list;
    for (int number : numbers)
        list << QString::number(number);
    return list.join(QStringLiteral(", "));
}

QString scenarioFailureText(const core::ScenarioFailure& failure)
{
    //: a scan number, then what differed
    return SimulationText::tr("scan %1: %2").arg(failure.scan).arg(failureProblem(failure));
}

QString scenarioErrorText(const core::ScenarioError& error)
{
    const QString file = error.fileName.empty() ? QStringLiteral("scenario") : fromStd(error.fileName);
    // The location is written as compilers write it, in every language.
    return QStringLiteral("%1:%2:%3: %4")
        .arg(file, QString::number(error.line), QString::number(error.column), scenarioErrorMessage(error));
}

QString faultRefusalText(const core::machine::FaultRefusal& refusal)
{
    core::ScenarioError error;
    error.kind = core::machine::scenarioErrorKind(refusal.kind);
    error.subject = refusal.subject;
    error.detail = refusal.detail;
    return scenarioErrorMessage(error);
}

QString scenarioErrorListText(const std::vector<core::ScenarioError>& errors)
{
    constexpr std::size_t kMaxListed = 10;
    QStringList lines;
    for (std::size_t i = 0; i < errors.size() && i < kMaxListed; ++i)
        lines << scenarioErrorText(errors[i]);
    if (errors.size() > kMaxListed)
        lines << QCoreApplication::translate("editor::SimulationSession", "(%1 more)").arg(errors.size() - kMaxListed);
    return lines.join(QLatin1Char('\n'));
}

} // namespace editor
