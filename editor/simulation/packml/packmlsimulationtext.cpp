#include "editor/simulation/packml/packmlsimulationtext.h"

#include "editor/stdstring.h"

#include "core/simulation/simulationfault.h"

#include <QCoreApplication>
#include <QStringList>

namespace editor {

namespace {

using core::packml::DroppedEvent;
using core::packml::DropReason;

// The translation context of the texts.
class PackmlSimulationText {
    Q_DECLARE_TR_FUNCTIONS(PackmlSimulationText)
};

QString stateText(core::packml::State state)
{
    return fromStd(std::string(core::packml::stateName(state)));
}

// The command or mode an event is about, "CntrlCmd = 12" when its number names none.
QString subjectText(const DroppedEvent& event)
{
    if (!event.name.empty())
        return fromStd(event.name);
    const QString tag = event.kind == DroppedEvent::Kind::ModeRequest ? QStringLiteral("UnitMode") : QStringLiteral("CntrlCmd");
    return QStringLiteral("%1 = %2").arg(tag).arg(event.number); // code in every language
}

// The states where the current mode grants a change to the requested one
// (spec §3.3's S(c, r)): "Stopped, Idle, Aborted".
QString grantedStatesText(const DroppedEvent& event, const core::packml::PackmlProgram& program)
{
    QStringList names;
    for (const core::packml::ProgramMode& mode : program.modes) {
        if (mode.name != event.modeName)
            continue;
        for (const core::packml::ModeGrant& grant : mode.grants) {
            if (grant.targetMode != event.number)
                continue;
            for (core::packml::State state : grant.states.list())
                names << stateText(state);
        }
    }
    return names.join(QStringLiteral(", "));
}

// Why a mode request was refused in its state, and where it would be granted.
QString refusedModeText(const DroppedEvent& event, const core::packml::PackmlProgram& program, const QString& why)
{
    const QString subject = subjectText(event);
    const QString granted = grantedStatesText(event, program);
    const QString refusal =
        //: %1: a unit mode (Manual), %2: a PackML state (Execute), %3: why
        PackmlSimulationText::tr("%1 cannot be entered in %2: %3").arg(subject, stateText(event.state), why);
    if (granted.isEmpty())
        //: %1: a refusal, %2: the current unit mode
        return PackmlSimulationText::tr("%1; %2 grants it in no state").arg(refusal, fromStd(event.modeName));
    //: %1: a refusal, %2: PackML states ("Stopped, Idle, Aborted")
    return PackmlSimulationText::tr("%1; it can be entered in %2").arg(refusal, granted);
}

QString droppedModeText(const DroppedEvent& event, const core::packml::PackmlProgram& program)
{
    const QString subject = subjectText(event);
    switch (event.reason) {
    case DropReason::NotAllowedByCurrentMode:
        return refusedModeText(event, program,
                               PackmlSimulationText::tr("%1 allows no mode change there").arg(fromStd(event.modeName)));
    case DropReason::NotAllowedByRequestedMode:
        return refusedModeText(event, program, PackmlSimulationText::tr("%1 allows no mode change there").arg(subject));
    case DropReason::DisabledInRequestedMode:
        return refusedModeText(event, program, PackmlSimulationText::tr("%1 disables this state").arg(subject));
    case DropReason::ModePreempted:
        //: %2: the unit mode granted instead
        return PackmlSimulationText::tr("%1 is not granted: %2, lower-numbered, is granted in the same scan")
            .arg(subject, fromStd(event.preemptedBy));
    case DropReason::AlreadyCurrent: return PackmlSimulationText::tr("%1 is requested: it is already the current mode").arg(subject);
    case DropReason::NoSuchMode: return PackmlSimulationText::tr("%1 names no unit mode").arg(subject);
    default: break;
    }
    return subject;
}

QString droppedCommandText(const DroppedEvent& event)
{
    const QString subject = event.kind == DroppedEvent::Kind::StateComplete
        //: the State Complete of a PackML state
        ? PackmlSimulationText::tr("the SC of %1").arg(stateText(event.state))
        : subjectText(event);
    const QString state = stateText(event.state);
    switch (event.reason) {
    case DropReason::NotAcceptedInState:
        //: %1: a PackML command (Hold), %2: a state (Idle)
        return PackmlSimulationText::tr("%1 is not accepted in %2").arg(subject, state);
    case DropReason::NotAcceptedInMode:
        //: %1: a command, %2: a state, %3: a unit mode
        return PackmlSimulationText::tr("%1 is not accepted in %2 in %3: the mode disables where it leads")
            .arg(subject, state, fromStd(event.modeName));
    case DropReason::Preempted:
        //: %2: the transition that fired instead ("Execute-Stop->Stopped")
        return PackmlSimulationText::tr("%1 is pre-empted by %2").arg(subject, fromStd(event.preemptedBy));
    case DropReason::NoSuchCommand: return PackmlSimulationText::tr("%1 names no command").arg(subject);
    default: break;
    }
    return subject;
}

// Where a fault happened, worded from its parts: a nested GRAFCET's
// receptivity or action (stepId names the instance), else a command's or a
// mode's condition, whose name only the core's English place carries.
QString packmlFaultPlaceText(const core::SimulationFault& fault)
{
    const QString owner = fromStd(fault.stepId);
    if (fault.place.empty() || fault.nestedTransition > 0 || fault.actionIndex >= 0) {
        if (fault.actionIndex < 0)
            //: %1: a transition number of a nested GRAFCET, %2: its function block instance
            return PackmlSimulationText::tr("the receptivity of T%1 of %2").arg(fault.nestedTransition).arg(owner);
        //: %1: an action's position, %2: a step number, %3: a function block instance
        return PackmlSimulationText::tr("action %1 of step %2 of %3").arg(fault.actionIndex + 1).arg(fault.nestedStep).arg(owner);
    }
    const QString place = fromStd(fault.place);
    const QString commandPrefix = QStringLiteral("the condition of the ");
    const QString commandSuffix = QStringLiteral(" command");
    const QString modePrefix = QStringLiteral("the request condition of mode ");
    if (place.startsWith(commandPrefix) && place.endsWith(commandSuffix))
        //: %1: a PackML command (Start)
        return PackmlSimulationText::tr("the condition of the %1 command")
            .arg(place.mid(commandPrefix.size(), place.size() - commandPrefix.size() - commandSuffix.size()));
    if (place.startsWith(modePrefix))
        //: %1: a unit mode (Manual)
        return PackmlSimulationText::tr("the request condition of mode %1").arg(place.mid(modePrefix.size()));
    return place;
}

} // namespace

QString packmlTransitionText(const core::packml::ModeTransition& transition)
{
    return fromStd(core::packml::transitionText(transition)); // PackTags names and SC in every language
}

QString packmlDroppedText(const DroppedEvent& event, const core::packml::PackmlProgram& program)
{
    return event.kind == DroppedEvent::Kind::ModeRequest ? droppedModeText(event, program) : droppedCommandText(event);
}

QString packmlScenarioFailureText(const core::packml::PackmlScenarioFailure& failure)
{
    using Kind = core::packml::PackmlScenarioFailure::Kind;
    const QString expected = fromStd(failure.expected);
    const QString actual = fromStd(failure.actual);
    QString problem;
    switch (failure.kind) {
    case Kind::CannotApply:
        //: %1: a variable or instance, %2: why (from the simulator)
        problem = PackmlSimulationText::tr("cannot set %1: %2").arg(fromStd(failure.subject), fromStd(failure.detail));
        break;
    case Kind::WrongState: problem = PackmlSimulationText::tr("expected state %1, the state is %2").arg(expected, actual); break;
    case Kind::WrongMode: problem = PackmlSimulationText::tr("expected mode %1, the mode is %2").arg(expected, actual); break;
    case Kind::WrongVariable:
        problem = PackmlSimulationText::tr("expected %1 = %2, it is %3").arg(fromStd(failure.subject), expected, actual);
        break;
    case Kind::NothingFired: problem = PackmlSimulationText::tr("expected %1 to fire, no transition fired").arg(expected); break;
    case Kind::WrongFiring: problem = PackmlSimulationText::tr("expected %1 to fire, %2 fired").arg(expected, actual); break;
    case Kind::UnexpectedFiring: problem = PackmlSimulationText::tr("expected no transition to fire, %1 fired").arg(actual); break;
    }
    //: %1: a scan number, %2: what did not hold
    return PackmlSimulationText::tr("scan %1: %2").arg(QString::number(static_cast<qlonglong>(failure.scan)), problem);
}

QString packmlFaultText(const core::SimulationFault& fault)
{
    //: %1: a scan number, %2: where (a condition, a receptivity, an action), %3: the division as written, %4: the text
    return PackmlSimulationText::tr("Stopped at scan %1: integer division by zero in %2 (%3 in '%4'). On the PLC the "
                                    "task stops with a fault; Reset to run again.")
        .arg(QString::number(static_cast<qlonglong>(fault.scan)), packmlFaultPlaceText(fault), fromStd(fault.division),
             fromStd(fault.text));
}

QString packmlModeName(const core::packml::PackmlProgram& program, int number)
{
    const core::packml::ProgramMode* mode = program.mode(number);
    return mode ? fromStd(mode->name) : QString::number(number);
}

QString packmlRequestOutcomeText(PackmlRequestKind kind, int number, const core::packml::PackmlScanRecord& record,
                                 const core::packml::PackmlProgram& program)
{
    const auto wanted = kind == PackmlRequestKind::Mode ? DroppedEvent::Kind::ModeRequest : DroppedEvent::Kind::Command;
    for (const DroppedEvent& event : record.dropped)
        if (event.kind == wanted && event.number == number)
            return packmlDroppedText(event, program);
    if (kind == PackmlRequestKind::Mode) {
        const QString mode = packmlModeName(program, number);
        if (record.modeChanged() && record.mode == number)
            //: a unit mode request that the mode manager granted
            return PackmlSimulationText::tr("%1: granted").arg(mode);
        return PackmlSimulationText::tr("%1: not granted").arg(mode);
    }
    const auto command = static_cast<core::packml::Command>(number);
    const QString name = fromStd(std::string(core::packml::commandName(command)));
    if (record.fired && record.fired->transition.trigger == core::packml::Trigger::Command
        && record.fired->transition.command == command)
        //: %1: a command, %2: the transition it fired ("Idle-Start->Execute")
        return PackmlSimulationText::tr("%1: fired %2").arg(name, packmlTransitionText(*record.fired));
    return PackmlSimulationText::tr("%1: no transition fired").arg(name);
}

} // namespace editor
