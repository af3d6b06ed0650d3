#include "core/machine/machineloop.h"

#include "core/model/iectypes.h"

#include <algorithm>

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
    reset();
}

void MachineLoop::reset()
{
    m_simulator.reset();
    m_state.reset();
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

void MachineLoop::restoreState(const MachineState& state)
{
    m_state = state;
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
        const bool value = m_state.signal(i);
        if (cond::isTrue(m_simulator.variableValue(index)) == value)
            continue;
        m_simulator.setVariableAt(index, cond::Value{value});
        if (sensor)
            changed.push_back(index);
    }
    std::sort(changed.begin(), changed.end());
    for (std::size_t index : changed)
        m_sensorChanges.push_back({m_simulator.variableNames()[index], m_simulator.variableValue(index)});
}

} // namespace core::machine
