#pragma once

// The kinds of component a virtual machine is built from (docs/simulation.md,
// "The virtual machine"), and what each kind is wired to and parameterised
// with, as data: the file reader, the checks and the machine's cycle all read
// these tables, so a kind's roles are spelled in one place.

#include <cstdint>
#include <span>
#include <string_view>

namespace core::machine {

enum class ComponentKind {
    DoubleActingCylinder, // extend and retract outputs, two limit switches
    SingleActingCylinder, // one extend output, spring return
    Conveyor,             // a run output; a part reaches its sensor after a travel time
    Lamp,                 // shows an output
    PushButton,           // operator input, momentary
    Selector,             // operator input, maintained
    EmergencyStop,        // operator input, maintained, normally closed by default
    DelayedSensor,        // a sensor following an output after on and off delays
    PartSource,           // puts parts on a conveyor
};

std::string_view componentKindName(ComponentKind kind); // "double-acting-cylinder", ...
bool parseComponentKind(std::string_view name, ComponentKind& kind);

// How a wired variable and the machine relate.
enum class SignalDirection {
    Actuator, // a program output the machine reads
    Sensor,   // a program input the machine writes
    Operator, // a program input the user drives (the machine only gives its rest value)
};

// The contact of an operator input: what the variable reads while nobody touches it.
enum class Contact { NormallyOpen, NormallyClosed };
std::string_view contactName(Contact contact); // "normally-open", "normally-closed"
bool parseContact(std::string_view name, Contact& contact);

struct RoleSpec {
    std::string_view key; // the file's key and the checks' field: "extend", "retracted"
    SignalDirection direction;
    bool required;
};

enum class ParameterKind {
    TravelTime, // milliseconds, 1 to kMaxMachineTimeMs
    Delay,      // milliseconds, 0 to kMaxMachineTimeMs
    PartCount,  // 0 to kMaxParts, or kUnlimitedParts
};

struct ParameterSpec {
    std::string_view key; // "extendMs"
    ParameterKind kind;
    std::int64_t defaultValue; // what a new component and a file without the key hold
};

// One hour: longer travel times are no machine's, and the cycle's integer
// arithmetic (docs/simulation.md) stays far from overflow.
inline constexpr std::int64_t kMaxMachineTimeMs = 3'600'000;
inline constexpr std::int64_t kMaxParts = 1'000'000'000;
inline constexpr std::int64_t kUnlimitedParts = -1;

struct ComponentKindSpec {
    ComponentKind kind;
    std::span<const RoleSpec> roles;           // the order of Component::wires
    std::span<const ParameterSpec> parameters; // the order of Component::parameters
    bool hasContact;   // an operator input
    bool feedsConveyor; // names the conveyor it puts parts on
};

const ComponentKindSpec& kindSpec(ComponentKind kind);
std::span<const ComponentKind> allComponentKinds();

// Role indices, in kindSpec(kind).roles order, for the code that runs a kind.
namespace role {
inline constexpr std::size_t kExtend = 0;      // both cylinders
inline constexpr std::size_t kRetract = 1;     // double-acting cylinder
inline constexpr std::size_t kDoubleRetracted = 2;
inline constexpr std::size_t kDoubleExtended = 3;
inline constexpr std::size_t kSingleRetracted = 1; // single-acting cylinder
inline constexpr std::size_t kSingleExtended = 2;
inline constexpr std::size_t kRun = 0;         // conveyor
inline constexpr std::size_t kPartPresent = 1;
inline constexpr std::size_t kLamp = 0;
inline constexpr std::size_t kOperatorInput = 0; // push button, selector, emergency stop
inline constexpr std::size_t kDelayedOutput = 0;
inline constexpr std::size_t kDelayedSensor = 1;
inline constexpr std::size_t kSourceEmpty = 0;
} // namespace role

// Parameter indices, in kindSpec(kind).parameters order.
namespace parameter {
inline constexpr std::size_t kExtendMs = 0;  // both cylinders
inline constexpr std::size_t kRetractMs = 1;
inline constexpr std::size_t kTravelMs = 0;  // conveyor
inline constexpr std::size_t kOnDelayMs = 0; // delayed sensor
inline constexpr std::size_t kOffDelayMs = 1;
inline constexpr std::size_t kParts = 0;     // part source
} // namespace parameter

} // namespace core::machine
