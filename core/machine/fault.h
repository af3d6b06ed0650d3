#pragma once

// Faults injected into a running virtual machine (docs/simulation.md,
// "Faults"): a sensor stuck at TRUE or FALSE or flickering, a cylinder or
// conveyor jammed, and the repair that clears them. A fault is an event
// applied before a scan (a scenario's `at N: fault ...`, `simulate
// --fault`); machineloop.h keeps the faults in effect as per-slot and
// per-component flags, so a cycle does no lookup.

#include "core/machine/componentkind.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace core::machine {

enum class FaultKind {
    StuckTrue,  // the sensor reads TRUE whatever the machine does
    StuckFalse, // the sensor reads FALSE whatever the machine does
    Flicker,    // the sensor reads the opposite of the value it had, then toggles at every scan
    Jam,        // the cylinder or conveyor stops where it is whatever its outputs
    Clear,      // the sensor reads the machine again, the component moves again
};

// The words of a scenario line after the target: "stuck TRUE", "stuck
// FALSE", "flicker", "jam", "clear".
std::string_view faultKindText(FaultKind kind);
// The inverse of faultKindText, case-insensitive ("stuck  false" is not: one space).
std::optional<FaultKind> parseFaultKind(std::string_view text);

struct Fault {
    FaultKind kind = FaultKind::StuckFalse;
    // A sensor variable (stuck, flicker), a component (jam), either (clear).
    std::string target;

    friend bool operator==(const Fault&, const Fault&) = default;
};

// "Clamped stuck FALSE", as a scenario's fault line spells it after `fault`.
std::string toText(const Fault& fault);

// What a sensor's fault makes the program read, kept per signal slot.
enum class SensorFault : std::uint8_t { None, StuckTrue, StuckFalse, Flicker };

// The reading under `fault`: `machineValue` is what the machine gives,
// `previousReading` what the program read in the scan before.
inline bool faultedReading(SensorFault fault, bool machineValue, bool previousReading)
{
    switch (fault) {
    case SensorFault::None: return machineValue;
    case SensorFault::StuckTrue: return true;
    case SensorFault::StuckFalse: return false;
    case SensorFault::Flicker: return !previousReading;
    }
    return machineValue;
}

// Whether a component of the kind moves, so that it can jam: cylinders and conveyors.
bool canJam(ComponentKind kind);

// Why a fault does not apply to a machine, as data (closedloopscenario.h
// turns it into a located scenario error, the command line into a message).
struct FaultRefusal {
    enum class Kind {
        UnknownVariable,  // stuck, flicker: subject as written
        OperatorInput,    // subject: the variable as declared; detail: its component (the user drives it)
        NotMachineSensor, // subject: the variable as declared: no component writes it
        UnknownComponent, // jam: subject as written
        CannotJam,        // subject: the component; detail: its kind ("lamp")
        UnknownTarget,    // clear: neither a sensor nor a component; subject as written
    };
    Kind kind = Kind::UnknownVariable;
    std::string subject;
    std::string detail;
};

// "StartButton is an operator input of the machine's Start: the user drives it; a fault applies to the machine's sensors".
std::string toText(const FaultRefusal& refusal);

} // namespace core::machine
