#pragma once

// The machine of a closed-loop exploration under the time abstraction
// (docs/verification.md, "Closed loop (--machine)"): what is between the
// ends of a travel or a delay is one value, and whether it ends at the next
// cycle is asked of the caller, like a TON that may or may not have elapsed.
// - a cylinder is retracted, between, or extended; a stroke that takes one
//   cycle ends at once, a longer one may or may not end at each cycle;
// - a conveyor has no part, a part travelling, or a part at its sensor;
// - a delayed sensor knows whether its output has differed for some cycles;
// - a part source counts its parts exactly (machinestate.h feeds them).
// Every cycle of core::machine::MachineState maps to one of these (a
// concrete position to its class): every run of the machine is a run here,
// so a "never" claim proved with it holds for the machine. Its runs may be
// shorter than the machine's: a counterexample is replayed, and searched
// again with the machine counted in scans when it does not replay.

#include "core/machine/machinestate.h"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace core::explore {

class AbstractMachine {
public:
    // The same signal table as `exact`'s (signalSlots order), wired by `wire` as it was.
    AbstractMachine(const machine::Machine& machine, const machine::MachineState& exact, int cycleTimeMs,
                    const std::function<int(std::string_view, machine::SignalDirection)>& wire);

    void reset();
    // One cycle from the actuator slots; `choose(2)` answers 1 where a travel
    // or delay under way ends at this cycle, 0 where it goes on.
    void cycle(const std::function<int(int)>& choose);

    // A jammed cylinder or conveyor does not move (fault.h): a cylinder
    // between its ends stays between, a part stays where it is. Not part of
    // the key: the caller keeps the fault and sets it before each cycle.
    void setJammed(std::size_t component, bool jammed) { m_parts.at(component).jammed = jammed; }

    bool signal(std::size_t slot) const { return m_signals[slot] != 0; }
    void setSignal(std::size_t slot, bool value) { m_signals[slot] = value ? 1 : 0; }

    // As MachineState's: the state in a few bytes, and back (0: not a key of this machine).
    void appendKey(std::string& key) const;
    std::size_t restoreKey(std::string_view key);

private:
    enum Phase : std::uint8_t { kAtStart = 0, kBetween = 1, kAtEnd = 2 }; // conveyors: no part, travelling, at the sensor
    struct Part {
        machine::ComponentKind kind = machine::ComponentKind::Lamp;
        std::array<int, 4> slot{-1, -1, -1, -1};
        machine::Contact contact = machine::Contact::NormallyOpen;
        bool outInOne = false;  // cylinders: a full extension takes one cycle; conveyors: the travel does
        bool backInOne = false; // cylinders: a full retraction takes one cycle
        bool onInOne = false, offInOne = false; // delayed sensors
        std::int64_t initialParts = machine::kUnlimitedParts;
        int conveyor = -1;
        Phase phase = kAtStart;
        bool pending = false, on = false;
        bool jammed = false;
        std::int64_t partsLeft = machine::kUnlimitedParts;
    };

    bool read(const Part& p, std::size_t role) const;
    void write(const Part& p, std::size_t role, bool value);
    void move(Part& p, const std::function<int(int)>& choose);
    void feed(Part& source);
    void writeSensors(const Part& p);

    std::vector<Part> m_parts;
    std::vector<char> m_signals;
};

} // namespace core::explore
