#pragma once

// The closed loop: the GEMMA simulator and the model's virtual machine run
// together (docs/simulation.md, "The virtual machine"). The simulator is
// used as it is: after each scan K the loop reads the program's outputs, runs
// one machine cycle, and writes the sensors it produces into the program's
// inputs, which scan K+1 reads. Operator inputs stay the user's (setVariable
// on the simulator, a scenario's `set`): the machine only gives their rest
// value at reset.
//
// Only a variable of the right kind and type is wired: an actuator role to
// a BOOL output, a sensor or operator role to a BOOL input. Anything else is
// left unwired here and reported by the checks (machinechecks.h).

#include "core/machine/fault.h"
#include "core/machine/machinestate.h"
#include "core/simulation/simulator.h"

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace core::machine {

class MachineLoop {
public:
    // Keeps a reference to the simulator, which must outlive the loop; the
    // machine is copied into its running state. Resets both.
    MachineLoop(Simulator& simulator, const Machine& machine);

    // The simulator's start state, then the machine's (machinestate.h),
    // whose sensors and operator rest values are written into the inputs.
    void reset();
    // One scan of the program, then one machine cycle (none after a scan
    // that stopped on a run-time fault).
    ScanRecord step();
    void run(std::int64_t scans);
    // The machine cycle that follows a scan the caller ran on the simulator
    // itself (a scenario checks its expectations in between, so that they
    // see what the scan read); nothing after a run-time fault.
    void afterScan();

    // The inputs the machine's last cycle (or reset) changed, declaration
    // order, as the program reads them in the next scan.
    const std::vector<InputChange>& lastSensorChanges() const { return m_sensorChanges; }
    // Whether the machine writes this input at every cycle (a sensor role;
    // operator inputs are the user's). Case-insensitive.
    bool drivesVariable(std::string_view name) const;
    // The component whose sensor role writes the input; nullptr when none does.
    const Component* sensorOwner(std::string_view name) const;

    // Faults (fault.h; docs/simulation.md, "Faults"). nullopt when the
    // fault applies to this machine; else why not.
    std::optional<FaultRefusal> checkFault(const Fault& fault) const;
    // Applies a fault before the next scan: a sensor's new reading is
    // written into its input at once, so the next scan reads it; a jam or
    // its clearing holds from the machine cycle after that scan. False, and
    // nothing changed, when checkFault refuses it. reset() clears every fault.
    bool applyFault(const Fault& fault);
    // The fault a sensor is under; SensorFault::None when it is sound or no sensor.
    SensorFault sensorFault(std::string_view variable) const;

    Simulator& simulator() { return m_simulator; }
    const Simulator& simulator() const { return m_simulator; }
    const MachineState& state() const { return m_state; }

    // What the loop carries from one scan to the next besides the
    // simulator: the machine (jams included) and the sensor faults in
    // effect. The editor's history keeps one per scan.
    struct Snapshot {
        MachineState machine;
        std::vector<SensorFault> sensorFaults; // by signal slot
    };
    Snapshot snapshot() const { return {m_state, m_sensorFaults}; }
    // Puts the loop back as it was when `snapshot` was taken from it (the
    // simulator is restored beside it, so the inputs already hold the
    // readings of then).
    void restore(const Snapshot& snapshot);
    // The fault a sensor was under when `snapshot` was taken; None when sound or no sensor.
    SensorFault sensorFault(const Snapshot& snapshot, std::string_view variable) const;

private:
    void writeInputs(bool operatorsToo);
    int sensorSlot(std::string_view variable) const; // -1 when the machine writes no such input
    int componentIndex(std::string_view name) const; // -1 when no such component
    const Component* operatorOwner(std::string_view variable) const;
    void writeReading(std::size_t slot);

    Simulator& m_simulator;
    Machine m_machine;
    MachineState m_state;
    std::vector<InputChange> m_sensorChanges;
    std::vector<SensorFault> m_sensorFaults; // by signal slot
};

} // namespace core::machine
