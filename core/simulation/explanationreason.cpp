#include "core/simulation/explanationreason.h"

namespace core {

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
    }
    return {};
}

} // namespace core
