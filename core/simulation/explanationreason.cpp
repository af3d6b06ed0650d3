#include "core/simulation/explanationreason.h"

namespace core {

namespace {

std::string stepList(const std::vector<int>& steps)
{
    std::string text;
    for (std::size_t i = 0; i < steps.size(); ++i)
        text += (i ? ", " : "") + std::to_string(steps[i]);
    return text;
}

} // namespace

std::string toText(const ConditionReading& reading)
{
    std::string text = reading.name + " = " + reading.value;
    if (reading.isToken())
        text += " (token of " + reading.tokenLiteral + ")";
    return text;
}

std::string toText(const ExplanationReason& reason)
{
    using Kind = ExplanationReason::Kind;
    switch (reason.kind) {
    case Kind::Reading: return reason.readings.empty() ? std::string() : toText(reason.readings.front());
    case Kind::Literal: return reason.value;
    case Kind::Expression: {
        std::string text = reason.subject + " is " + reason.value;
        for (std::size_t i = 0; i < reason.readings.size(); ++i)
            text += (i ? ", " : " (") + toText(reason.readings[i]);
        if (!reason.readings.empty())
            text += ")";
        return text;
    }
    case Kind::CompleteFalse: return reason.subject + ".Complete = FALSE";
    case Kind::FiresFirst: return reason.subject + " fires first";
    case Kind::Unusable:
        return reason.message.empty() ? std::string("the condition cannot be used: it is FALSE") : reason.message;
    case Kind::StepsInactive:
        return reason.steps.size() == 1 ? "step " + stepList(reason.steps) + " is not active"
                                        : "steps " + stepList(reason.steps) + " are not active";
    case Kind::NoRisingEdge:
    case Kind::NoFallingEdge:
        return std::string(reason.kind == Kind::NoRisingEdge ? "no rising" : "no falling") + " edge of "
             + reason.subject + " this scan (" + reason.subject + " = " + reason.value
             + ", at the end of the previous scan " + reason.previous + ")";
    case Kind::TimerNotElapsed:
        return reason.subject + " is FALSE: step " + stepList(reason.steps) + " active for "
             + std::to_string(reason.elapsedMs) + " ms of " + std::to_string(reason.durationMs) + " ms";
    case Kind::NotCalled:
        return reason.subject + " is not the active step: its GRAFCET does not evolve in the next scan";
    }
    return {};
}

} // namespace core
