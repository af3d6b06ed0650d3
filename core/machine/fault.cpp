#include "core/machine/fault.h"

#include "core/model/iectypes.h"

#include <array>
#include <utility>

namespace core::machine {

namespace {

constexpr std::array<std::pair<FaultKind, std::string_view>, 5> kFaultWords{{
    {FaultKind::StuckTrue, "stuck TRUE"},
    {FaultKind::StuckFalse, "stuck FALSE"},
    {FaultKind::Flicker, "flicker"},
    {FaultKind::Jam, "jam"},
    {FaultKind::Clear, "clear"},
}};

std::string quote(const std::string& text)
{
    return "'" + text + "'";
}

} // namespace

std::string_view faultKindText(FaultKind kind)
{
    for (const auto& [candidate, text] : kFaultWords) {
        if (candidate == kind)
            return text;
    }
    return {};
}

std::optional<FaultKind> parseFaultKind(std::string_view text)
{
    for (const auto& [kind, words] : kFaultWords) {
        if (equalsIgnoreCase(words, text))
            return kind;
    }
    return std::nullopt;
}

std::string toText(const Fault& fault)
{
    return fault.target + " " + std::string(faultKindText(fault.kind));
}

bool canJam(ComponentKind kind)
{
    return kind == ComponentKind::DoubleActingCylinder || kind == ComponentKind::SingleActingCylinder
        || kind == ComponentKind::Conveyor;
}

std::string toText(const FaultRefusal& refusal)
{
    using Kind = FaultRefusal::Kind;
    const std::string& subject = refusal.subject;
    switch (refusal.kind) {
    case Kind::UnknownVariable: return "unknown variable " + quote(subject);
    case Kind::OperatorInput:
        return subject + " is an operator input of the machine's " + refusal.detail
            + ": the user drives it with set; a fault applies to the machine's sensors";
    case Kind::NotMachineSensor:
        return subject + " is no sensor of the machine: a fault applies to the inputs a component writes";
    case Kind::UnknownComponent: return "no component " + quote(subject) + " in the machine";
    case Kind::CannotJam:
        return subject + " is a " + refusal.detail + ": only cylinders and conveyors jam";
    case Kind::UnknownTarget: return quote(subject) + " is neither a sensor nor a component of the machine";
    }
    return {};
}

} // namespace core::machine
