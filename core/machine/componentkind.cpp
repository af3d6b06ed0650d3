#include "core/machine/componentkind.h"

#include <array>

namespace core::machine {

namespace {

using enum SignalDirection;

constexpr std::array kDoubleActingRoles{
    RoleSpec{"extend", Actuator, true},
    RoleSpec{"retract", Actuator, true},
    RoleSpec{"retracted", Sensor, false},
    RoleSpec{"extended", Sensor, false},
};
constexpr std::array kSingleActingRoles{
    RoleSpec{"extend", Actuator, true},
    RoleSpec{"retracted", Sensor, false},
    RoleSpec{"extended", Sensor, false},
};
constexpr std::array kConveyorRoles{
    RoleSpec{"run", Actuator, true},
    RoleSpec{"partPresent", Sensor, false},
};
constexpr std::array kLampRoles{RoleSpec{"lamp", Actuator, true}};
constexpr std::array kOperatorRoles{RoleSpec{"input", Operator, true}};
constexpr std::array kDelayedSensorRoles{
    RoleSpec{"output", Actuator, true},
    RoleSpec{"sensor", Sensor, true},
};
constexpr std::array kSourceRoles{RoleSpec{"empty", Sensor, false}};

constexpr std::array kCylinderParameters{
    ParameterSpec{"extendMs", ParameterKind::TravelTime, 1000},
    ParameterSpec{"retractMs", ParameterKind::TravelTime, 1000},
};
constexpr std::array kConveyorParameters{ParameterSpec{"travelMs", ParameterKind::TravelTime, 1000}};
constexpr std::array kDelayParameters{
    ParameterSpec{"onDelayMs", ParameterKind::Delay, 0},
    ParameterSpec{"offDelayMs", ParameterKind::Delay, 0},
};
constexpr std::array kSourceParameters{ParameterSpec{"parts", ParameterKind::PartCount, kUnlimitedParts}};

const std::array<ComponentKindSpec, 9> kSpecs{{
    {ComponentKind::DoubleActingCylinder, kDoubleActingRoles, kCylinderParameters, false, false},
    {ComponentKind::SingleActingCylinder, kSingleActingRoles, kCylinderParameters, false, false},
    {ComponentKind::Conveyor, kConveyorRoles, kConveyorParameters, false, false},
    {ComponentKind::Lamp, kLampRoles, {}, false, false},
    {ComponentKind::PushButton, kOperatorRoles, {}, true, false},
    {ComponentKind::Selector, kOperatorRoles, {}, true, false},
    {ComponentKind::EmergencyStop, kOperatorRoles, {}, true, false},
    {ComponentKind::DelayedSensor, kDelayedSensorRoles, kDelayParameters, false, false},
    {ComponentKind::PartSource, kSourceRoles, kSourceParameters, false, true},
}};

constexpr std::array kKinds{
    ComponentKind::DoubleActingCylinder, ComponentKind::SingleActingCylinder, ComponentKind::Conveyor,
    ComponentKind::Lamp, ComponentKind::PushButton, ComponentKind::Selector,
    ComponentKind::EmergencyStop, ComponentKind::DelayedSensor, ComponentKind::PartSource,
};

} // namespace

std::string_view componentKindName(ComponentKind kind)
{
    switch (kind) {
    case ComponentKind::DoubleActingCylinder: return "double-acting-cylinder";
    case ComponentKind::SingleActingCylinder: return "single-acting-cylinder";
    case ComponentKind::Conveyor: return "conveyor";
    case ComponentKind::Lamp: return "lamp";
    case ComponentKind::PushButton: return "push-button";
    case ComponentKind::Selector: return "selector";
    case ComponentKind::EmergencyStop: return "emergency-stop";
    case ComponentKind::DelayedSensor: return "delayed-sensor";
    case ComponentKind::PartSource: return "part-source";
    }
    return "lamp";
}

bool parseComponentKind(std::string_view name, ComponentKind& kind)
{
    for (ComponentKind candidate : kKinds) {
        if (componentKindName(candidate) == name) {
            kind = candidate;
            return true;
        }
    }
    return false;
}

std::string_view contactName(Contact contact)
{
    return contact == Contact::NormallyClosed ? "normally-closed" : "normally-open";
}

bool parseContact(std::string_view name, Contact& contact)
{
    for (Contact candidate : {Contact::NormallyOpen, Contact::NormallyClosed}) {
        if (contactName(candidate) == name) {
            contact = candidate;
            return true;
        }
    }
    return false;
}

const ComponentKindSpec& kindSpec(ComponentKind kind)
{
    return kSpecs[static_cast<std::size_t>(kind)];
}

std::span<const ComponentKind> allComponentKinds()
{
    return kKinds;
}

} // namespace core::machine
