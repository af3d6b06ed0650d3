#pragma once

// A virtual machine running: the positions, parts and delays of its
// components, moved one cycle time at a time (docs/simulation.md, "The
// virtual machine"). It knows no simulator: it reads and writes a table of
// signals, one slot per wired variable, and machineloop.h couples the table
// with the program's variables.
//
// Travel times and delays are counted in cycles: ceil(time / cycle time),
// at least 1. A cylinder's stroke is an integer counter from 0 (retracted)
// to extendScans x retractScans (extended): a cycle of extension adds
// retractScans, a cycle of retraction removes extendScans, so a full stroke
// takes exactly extendScans (retractScans) cycles each way and a reversal
// mid-stroke takes back the same fraction of it.

#include "core/machine/machine.h"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace core::machine {

// A wired variable: the caller's index of it and what the machine does with it.
struct SignalSlot {
    int variable = -1;
    SignalDirection direction = SignalDirection::Sensor;
};

class MachineState {
public:
    // `wire` gives the caller's index of a role's variable, or -1 to leave
    // the role unwired (an unknown variable, or one of the wrong kind or
    // type: the checks report those). Times use `cycleTimeMs` (at least 1).
    MachineState(const Machine& machine, int cycleTimeMs,
                 const std::function<int(std::string_view variable, SignalDirection direction)>& wire);

    // The start state: cylinders retracted, conveyors empty, then every part
    // source puts a part on its conveyor's entry; delayed sensors off;
    // sensor slots from that state, operator slots at their rest values.
    void reset();
    // One cycle time: reads the actuator slots (setSignal), moves the
    // components, then the part sources feed empty conveyors, then every
    // sensor slot is written from the new state.
    void cycle();

    const std::vector<SignalSlot>& signalSlots() const { return m_slots; }
    bool signal(std::size_t slot) const { return m_signals[slot] != 0; }
    void setSignal(std::size_t slot, bool value) { m_signals[slot] = value ? 1 : 0; }

    // Inspection, by component index (Machine::components order).
    // Cylinders: 0 retracted .. 1 extended; conveyors: the part's way from
    // the entry (0) to the sensor (1), 0 without a part; 0 otherwise.
    double position(std::size_t component) const;
    bool hasPart(std::size_t component) const;                // conveyors
    std::int64_t partsDelivered(std::size_t component) const; // conveyors: parts that left past the sensor
    std::int64_t partsLeft(std::size_t component) const;      // part sources; kUnlimitedParts when unlimited
    bool sensorOn(std::size_t component) const;               // delayed sensors
    // A jammed component (fault.h) does not move in a cycle, whatever its
    // outputs; its sensors keep giving its position. reset() frees them all.
    void setJammed(std::size_t component, bool jammed) { m_components.at(component).jammed = jammed; }
    bool jammed(std::size_t component) const { return m_components.at(component).jammed; }
    std::size_t componentCount() const { return m_components.size(); }

    // Cycles a travel or delay of `ms` takes: ceil(ms / cycle), at least 1.
    static std::int64_t scansFor(std::int64_t ms, int cycleTimeMs);

    // The state that decides every later cycle and sensor (positions, parts
    // on conveyors, delays under way, parts left), appended to `key` in a few
    // bytes (machinestatekey.cpp): equal keys, equal futures. The parts
    // delivered are left out, no sensor reads them: a verifier keying its
    // states on this stays finite with an unlimited part source.
    void appendKey(std::string& key) const;
    // The state of a key appendKey wrote for this machine, sensor slots
    // rewritten from it (parts delivered: 0). The bytes read; 0 when the key
    // is not one of this machine's (nothing changed then).
    std::size_t restoreKey(std::string_view key);

private:
    static constexpr int kMaxRoles = 4;
    struct Runtime {
        ComponentKind kind = ComponentKind::Lamp;
        std::array<int, kMaxRoles> slot{-1, -1, -1, -1}; // by role; -1 unwired
        Contact contact = Contact::NormallyOpen;
        std::int64_t extendStep = 1;  // cylinders: units per cycle of extension (retract scans)
        std::int64_t retractStep = 1; // units per cycle of retraction (extend scans)
        std::int64_t stroke = 1;      // cylinders: the extended position
        std::int64_t position = 0;    // cylinders: 0..stroke; conveyors: the part's cycles from the entry
        std::int64_t travelScans = 1; // conveyors: entry to sensor
        bool part = false;            // conveyors
        std::int64_t delivered = 0;   // conveyors
        std::int64_t onScans = 1;     // delayed sensors
        std::int64_t offScans = 1;
        std::int64_t pending = 0;     // delayed sensors: cycles the output has differed from the sensor
        bool on = false;              // delayed sensors
        std::int64_t initialParts = kUnlimitedParts; // part sources
        std::int64_t partsLeft = kUnlimitedParts;
        int conveyor = -1;            // part sources: the conveyor's component index
        bool jammed = false;          // a fault: the component does not move
    };

    bool read(const Runtime& r, std::size_t role) const;
    void write(const Runtime& r, std::size_t role, bool value);
    void move(Runtime& r);
    void feed(Runtime& source);
    void writeSensors(Runtime& r);

    std::vector<Runtime> m_components;
    std::vector<SignalSlot> m_slots;
    std::vector<char> m_signals;
};

} // namespace core::machine
