#include "core/machine/machineloop.h"

#include "core/model/iectypes.h"

#include <algorithm>
#include <utility>

namespace core::machine {

namespace {

// The simulator's index of a variable the role may use, or -1.
int wiredIndex(const Simulator& simulator, std::string_view name, SignalDirection direction)
{
    const int index = simulator.variableIndex(name);
    if (index < 0)
        return -1;
    const auto at = static_cast<std::size_t>(index);
    const VariableKind wanted = direction == SignalDirection::Actuator ? VariableKind::Output : VariableKind::Input;
    if (simulator.variableType(at) != IecType::Bool || simulator.variableKind(at) != wanted)
        return -1;
    return index;
}

} // namespace

MachineLoop::MachineLoop(Simulator& simulator, const Machine& machine)
    : m_simulator(simulator)
    , m_machine(machine)
    , m_state(machine, simulator.cycleTimeMs(),
              [&simulator](std::string_view name, SignalDirection direction) {
                  return wiredIndex(simulator, name, direction);
              })
{
    m_sensorFaults.assign(m_state.signalSlots().size(), SensorFault::None);
    reset();
}

void MachineLoop::reset()
{
    m_simulator.reset();
    m_state.reset();
    std::fill(m_sensorFaults.begin(), m_sensorFaults.end(), SensorFault::None);
    writeInputs(true);
}

ScanRecord MachineLoop::step()
{
    ScanRecord record = m_simulator.step();
    afterScan();
    return record;
}

void MachineLoop::run(std::int64_t scans)
{
    for (std::int64_t i = 0; i < scans && !m_simulator.fault(); ++i) {
        m_simulator.run(1);
        afterScan();
    }
}

void MachineLoop::restore(const Snapshot& snapshot)
{
    m_state = snapshot.machine;
    m_sensorFaults = snapshot.sensorFaults;
    m_sensorChanges.clear();
}

bool MachineLoop::drivesVariable(std::string_view name) const
{
    const int index = m_simulator.variableIndex(name);
    for (const SignalSlot& slot : m_state.signalSlots()) {
        if (slot.variable == index && slot.direction == SignalDirection::Sensor)
            return index >= 0;
    }
    return false;
}

const Component* MachineLoop::sensorOwner(std::string_view name) const
{
    if (!drivesVariable(name))
        return nullptr;
    for (const Component& component : m_machine.components) {
        const ComponentKindSpec& spec = kindSpec(component.kind);
        for (std::size_t i = 0; i < spec.roles.size() && i < component.wires.size(); ++i) {
            if (spec.roles[i].direction == SignalDirection::Sensor && equalsIgnoreCase(component.wires[i], name)
                && wiredIndex(m_simulator, name, SignalDirection::Sensor) >= 0)
                return &component;
        }
    }
    return nullptr;
}

void MachineLoop::afterScan()
{
    if (m_simulator.fault())
        return;
    const std::vector<SignalSlot>& table = m_state.signalSlots();
    for (std::size_t i = 0; i < table.size(); ++i) {
        if (table[i].direction == SignalDirection::Actuator)
            m_state.setSignal(i, cond::isTrue(m_simulator.variableValue(static_cast<std::size_t>(table[i].variable))));
    }
    m_state.cycle();
    writeInputs(false);
}

// Operator inputs are written at reset only: between resets they are the user's.
void MachineLoop::writeInputs(bool operatorsToo)
{
    m_sensorChanges.clear();
    std::vector<std::size_t> changed;
    const std::vector<SignalSlot>& table = m_state.signalSlots();
    for (std::size_t i = 0; i < table.size(); ++i) {
        const bool sensor = table[i].direction == SignalDirection::Sensor;
        if (!sensor && !(operatorsToo && table[i].direction == SignalDirection::Operator))
            continue;
        const auto index = static_cast<std::size_t>(table[i].variable);
        const bool reading = cond::isTrue(m_simulator.variableValue(index));
        const bool value = faultedReading(m_sensorFaults[i], m_state.signal(i), reading);
        if (reading == value)
            continue;
        m_simulator.setVariableAt(index, cond::Value{value});
        if (sensor)
            changed.push_back(index);
    }
    std::sort(changed.begin(), changed.end());
    for (std::size_t index : changed)
        m_sensorChanges.push_back({m_simulator.variableNames()[index], m_simulator.variableValue(index)});
}

// --- Faults ---------------------------------------------------------------------

int MachineLoop::sensorSlot(std::string_view variable) const
{
    const int index = m_simulator.variableIndex(variable);
    const std::vector<SignalSlot>& table = m_state.signalSlots();
    for (std::size_t i = 0; index >= 0 && i < table.size(); ++i) {
        if (table[i].variable == index && table[i].direction == SignalDirection::Sensor)
            return static_cast<int>(i);
    }
    return -1;
}

int MachineLoop::componentIndex(std::string_view name) const
{
    const Component* component = m_machine.find(name);
    return component ? static_cast<int>(component - m_machine.components.data()) : -1;
}

const Component* MachineLoop::operatorOwner(std::string_view variable) const
{
    for (const Component& component : m_machine.components) {
        const ComponentKindSpec& spec = kindSpec(component.kind);
        for (std::size_t i = 0; i < spec.roles.size() && i < component.wires.size(); ++i) {
            if (spec.roles[i].direction == SignalDirection::Operator && equalsIgnoreCase(component.wires[i], variable))
                return &component;
        }
    }
    return nullptr;
}

std::optional<FaultRefusal> MachineLoop::checkFault(const Fault& fault) const
{
    using Kind = FaultRefusal::Kind;
    const auto refuse = [](Kind kind, std::string subject, std::string detail = {}) {
        return std::optional<FaultRefusal>(FaultRefusal{kind, std::move(subject), std::move(detail)});
    };
    switch (fault.kind) {
    case FaultKind::Jam: {
        const Component* component = m_machine.find(fault.target);
        if (!component)
            return refuse(Kind::UnknownComponent, fault.target);
        if (!canJam(component->kind))
            return refuse(Kind::CannotJam, component->name, std::string(componentKindName(component->kind)));
        return std::nullopt;
    }
    case FaultKind::Clear:
        if (sensorSlot(fault.target) >= 0 || componentIndex(fault.target) >= 0)
            return std::nullopt;
        return refuse(Kind::UnknownTarget, fault.target);
    case FaultKind::StuckTrue:
    case FaultKind::StuckFalse:
    case FaultKind::Flicker:
        break;
    }
    if (sensorSlot(fault.target) >= 0)
        return std::nullopt;
    const int index = m_simulator.variableIndex(fault.target);
    if (index < 0)
        return refuse(Kind::UnknownVariable, fault.target);
    const std::string& declared = m_simulator.variableNames()[static_cast<std::size_t>(index)];
    if (const Component* owner = operatorOwner(fault.target))
        return refuse(Kind::OperatorInput, declared, owner->name);
    return refuse(Kind::NotMachineSensor, declared);
}

bool MachineLoop::applyFault(const Fault& fault)
{
    if (checkFault(fault))
        return false;
    const int slot = sensorSlot(fault.target);
    const int component = componentIndex(fault.target);
    switch (fault.kind) {
    case FaultKind::StuckTrue: m_sensorFaults[static_cast<std::size_t>(slot)] = SensorFault::StuckTrue; break;
    case FaultKind::StuckFalse: m_sensorFaults[static_cast<std::size_t>(slot)] = SensorFault::StuckFalse; break;
    case FaultKind::Flicker: m_sensorFaults[static_cast<std::size_t>(slot)] = SensorFault::Flicker; break;
    case FaultKind::Jam: m_state.setJammed(static_cast<std::size_t>(component), true); return true;
    case FaultKind::Clear:
        if (component >= 0)
            m_state.setJammed(static_cast<std::size_t>(component), false);
        if (slot < 0)
            return true;
        m_sensorFaults[static_cast<std::size_t>(slot)] = SensorFault::None;
        break;
    }
    writeReading(static_cast<std::size_t>(slot));
    return true;
}

// The slot's reading under its fault, written into its input for the next scan.
void MachineLoop::writeReading(std::size_t slot)
{
    const auto index = static_cast<std::size_t>(m_state.signalSlots()[slot].variable);
    const bool reading = cond::isTrue(m_simulator.variableValue(index));
    const bool value = faultedReading(m_sensorFaults[slot], m_state.signal(slot), reading);
    if (value != reading)
        m_simulator.setVariableAt(index, cond::Value{value});
}

SensorFault MachineLoop::sensorFault(std::string_view variable) const
{
    const int slot = sensorSlot(variable);
    return slot < 0 ? SensorFault::None : m_sensorFaults[static_cast<std::size_t>(slot)];
}

SensorFault MachineLoop::sensorFault(const Snapshot& snapshot, std::string_view variable) const
{
    const int slot = sensorSlot(variable);
    const bool known = slot >= 0 && static_cast<std::size_t>(slot) < snapshot.sensorFaults.size();
    return known ? snapshot.sensorFaults[static_cast<std::size_t>(slot)] : SensorFault::None;
}

} // namespace core::machine
