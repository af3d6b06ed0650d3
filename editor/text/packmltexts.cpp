#include "editor/text/packmltexts.h"

#include <QCoreApplication>

namespace editor::packmltext {

namespace {

using core::packml::Command;
using core::packml::State;

QString fromView(std::string_view text)
{
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

QString translated(const char* text)
{
    return QCoreApplication::translate("PackmlTexts", text);
}

} // namespace

QString stateName(State state)
{
    return fromView(core::packml::stateName(state));
}

QString commandName(Command command)
{
    return fromView(core::packml::commandName(command));
}

QString stateKindName(core::packml::StateKind kind)
{
    switch (kind) {
    case core::packml::StateKind::Wait: return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Wait state"));
    case core::packml::StateKind::Acting: return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Acting state"));
    case core::packml::StateKind::Dual:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Dual state: acts and waits for a command"));
    }
    return {};
}

QString stateMeaning(State state)
{
    switch (state) {
    case State::Clearing:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Clears the faults that led to Aborted, then goes to Stopped."));
    case State::Stopped:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Powered and stationary; waits for Reset."));
    case State::Starting:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Prepares the unit to produce, then goes to Execute."));
    case State::Idle:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Reset and ready; waits for Start."));
    case State::Suspended:
        return translated(
            QT_TRANSLATE_NOOP("PackmlTexts", "Paused by a condition outside the unit (starved, blocked); waits for Unsuspend."));
    case State::Execute:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Produces; waits for Hold, Suspend or the end of the batch."));
    case State::Stopping:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Brings the unit to a controlled stop, then goes to Stopped."));
    case State::Aborting:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Brings the unit to a quick safe stop, then goes to Aborted."));
    case State::Aborted:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Stopped after an abort; waits for Clear."));
    case State::Holding:
        return translated(
            QT_TRANSLATE_NOOP("PackmlTexts", "Brings production to a controlled pause for an internal reason, then goes to Held."));
    case State::Held:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Paused for an internal reason; waits for Unhold."));
    case State::Unholding:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Prepares to resume production after Held, then goes to Execute."));
    case State::Suspending:
        return translated(
            QT_TRANSLATE_NOOP("PackmlTexts", "Brings production to a controlled pause for an outside reason, then goes to Suspended."));
    case State::Unsuspending:
        return translated(
            QT_TRANSLATE_NOOP("PackmlTexts", "Prepares to resume production after Suspended, then goes to Execute."));
    case State::Resetting:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Brings the unit to its ready state, then goes to Idle."));
    case State::Completing:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Ends the batch in order, then goes to Complete."));
    case State::Complete:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "The batch is complete; waits for Reset."));
    }
    return {};
}

QString commandMeaning(Command command)
{
    switch (command) {
    case Command::Reset:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Reset: make the unit ready to start again."));
    case Command::Start: return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Start: begin producing."));
    case Command::Stop:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Stop: bring the unit to a controlled stop."));
    case Command::Hold:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Hold: pause production for an internal reason."));
    case Command::Unhold:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Unhold: resume production after a Hold."));
    case Command::Suspend:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Suspend: pause production for an outside reason."));
    case Command::Unsuspend:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Unsuspend: resume production after a Suspend."));
    case Command::Abort:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Abort: stop the unit at once, safely."));
    case Command::Clear:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Clear: clear the faults after an Abort."));
    case Command::Complete:
        return translated(QT_TRANSLATE_NOOP("PackmlTexts", "Complete: end the batch."));
    }
    return {};
}

} // namespace editor::packmltext
