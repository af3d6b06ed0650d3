#include "core/templates/packml/packmlscanrecord.h"

namespace core::packml {

namespace {

std::string subjectOf(const DroppedEvent& event)
{
    switch (event.kind) {
    case DroppedEvent::Kind::StateComplete: return "the SC of " + std::string(stateName(event.state));
    case DroppedEvent::Kind::Command:
        return event.name.empty() ? "CntrlCmd = " + std::to_string(event.number) : event.name;
    case DroppedEvent::Kind::ModeRequest:
        return event.name.empty() ? "UnitMode = " + std::to_string(event.number) : event.name;
    }
    return {};
}

} // namespace

std::string toText(const DroppedEvent& event)
{
    const std::string subject = subjectOf(event);
    const std::string state(stateName(event.state));
    switch (event.reason) {
    case DropReason::NotAcceptedInState: return subject + " is not accepted in " + state;
    case DropReason::NotAcceptedInMode:
        return subject + " is not accepted in " + state + " in " + event.modeName
            + ": the mode disables where it leads";
    case DropReason::Preempted: return subject + " is pre-empted by " + event.preemptedBy;
    case DropReason::NoSuchCommand: return subject + " names no command";
    case DropReason::NotAllowedByCurrentMode:
        return subject + " is not granted in " + state + ": " + event.modeName + " allows no mode change there";
    case DropReason::NotAllowedByRequestedMode:
        return subject + " is not granted in " + state + ": " + event.name + " allows no mode change there";
    case DropReason::DisabledInRequestedMode:
        return subject + " is not granted in " + state + ": " + event.name + " disables it";
    case DropReason::ModePreempted:
        return subject + " is not granted: " + event.preemptedBy + ", lower-numbered, is granted in the same scan";
    case DropReason::AlreadyCurrent: return subject + " is requested: it is already the current mode";
    case DropReason::NoSuchMode: return subject + " names no unit mode";
    }
    return subject;
}

std::string transitionText(const ModeTransition& transition)
{
    const TemplateTransition& t = transition.transition;
    const std::string trigger = t.trigger == Trigger::StateComplete ? std::string("SC") : std::string(commandName(t.command));
    return std::string(stateName(t.source)) + "-" + trigger + "->" + std::string(stateName(transition.destination.state));
}

std::string summaryText(const PackmlScanRecord& record)
{
    std::string text;
    const auto add = [&text](const std::string& part) { text += (text.empty() ? "" : " ") + part; };
    if (record.modeChanged())
        add("mode " + std::to_string(record.modeBefore) + "->" + std::to_string(record.mode));
    if (record.fired)
        add("fired " + transitionText(*record.fired));
    if (record.resumed)
        add("resumed");
    return text;
}

} // namespace core::packml
