#include "core/machine/machinestate.h"

#include <algorithm>

namespace core::machine {

namespace {

// Cylinders and conveyors: no valid time is below 1 ms; an invalid one
// (the checks refuse it) still runs, as the shortest travel.
std::int64_t travelScans(std::int64_t ms, int cycleTimeMs)
{
    return MachineState::scansFor(std::clamp<std::int64_t>(ms, 1, kMaxMachineTimeMs), cycleTimeMs);
}

} // namespace

std::int64_t MachineState::scansFor(std::int64_t ms, int cycleTimeMs)
{
    const std::int64_t cycle = std::max(cycleTimeMs, 1);
    const std::int64_t time = std::clamp<std::int64_t>(ms, 0, kMaxMachineTimeMs);
    return std::max<std::int64_t>(1, (time + cycle - 1) / cycle);
}

MachineState::MachineState(const Machine& machine, int cycleTimeMs,
                           const std::function<int(std::string_view, SignalDirection)>& wire)
{
    for (const Component& component : machine.components) {
        const ComponentKindSpec& spec = kindSpec(component.kind);
        Runtime r;
        r.kind = component.kind;
        r.contact = component.contact;
        for (std::size_t role = 0; role < spec.roles.size() && role < component.wires.size(); ++role) {
            const std::string& name = component.wires[role];
            const int variable = name.empty() ? -1 : wire(name, spec.roles[role].direction);
            if (variable < 0)
                continue;
            auto found = std::find_if(m_slots.begin(), m_slots.end(),
                                      [&](const SignalSlot& s) { return s.variable == variable; });
            if (found == m_slots.end())
                found = m_slots.insert(m_slots.end(), SignalSlot{variable, spec.roles[role].direction});
            r.slot[role] = static_cast<int>(found - m_slots.begin());
        }
        const auto parameter = [&](std::size_t index) {
            return index < component.parameters.size() ? component.parameters[index] : 0;
        };
        switch (component.kind) {
        case ComponentKind::DoubleActingCylinder:
        case ComponentKind::SingleActingCylinder:
            r.retractStep = travelScans(parameter(parameter::kExtendMs), cycleTimeMs);
            r.extendStep = travelScans(parameter(parameter::kRetractMs), cycleTimeMs);
            r.stroke = r.extendStep * r.retractStep;
            break;
        case ComponentKind::Conveyor:
            r.travelScans = travelScans(parameter(parameter::kTravelMs), cycleTimeMs);
            break;
        case ComponentKind::DelayedSensor:
            r.onScans = scansFor(parameter(parameter::kOnDelayMs), cycleTimeMs);
            r.offScans = scansFor(parameter(parameter::kOffDelayMs), cycleTimeMs);
            break;
        case ComponentKind::PartSource: {
            r.initialParts = std::max(parameter(parameter::kParts), kUnlimitedParts);
            const Component* conveyor = machine.find(component.conveyor);
            if (conveyor && conveyor->kind == ComponentKind::Conveyor)
                r.conveyor = static_cast<int>(conveyor - machine.components.data());
            break;
        }
        default:
            break;
        }
        m_components.push_back(r);
    }
    m_signals.assign(m_slots.size(), 0);
    reset();
}

void MachineState::reset()
{
    std::fill(m_signals.begin(), m_signals.end(), 0);
    for (Runtime& r : m_components) {
        r.position = 0;
        r.part = false;
        r.delivered = 0;
        r.pending = 0;
        r.on = false;
        r.partsLeft = r.initialParts;
        r.jammed = false;
    }
    for (Runtime& r : m_components) {
        if (r.kind == ComponentKind::PartSource)
            feed(r);
    }
    for (Runtime& r : m_components) {
        writeSensors(r);
        if (kindSpec(r.kind).hasContact)
            write(r, role::kOperatorInput, r.contact == Contact::NormallyClosed);
    }
}

void MachineState::cycle()
{
    for (Runtime& r : m_components)
        move(r);
    for (Runtime& r : m_components) {
        if (r.kind == ComponentKind::PartSource)
            feed(r);
    }
    for (Runtime& r : m_components)
        writeSensors(r);
}

bool MachineState::read(const Runtime& r, std::size_t role) const
{
    const int slot = r.slot[role];
    return slot >= 0 && m_signals[static_cast<std::size_t>(slot)] != 0;
}

void MachineState::write(const Runtime& r, std::size_t role, bool value)
{
    const int slot = r.slot[role];
    if (slot >= 0)
        m_signals[static_cast<std::size_t>(slot)] = value ? 1 : 0;
}

void MachineState::move(Runtime& r)
{
    if (r.jammed)
        return;
    switch (r.kind) {
    case ComponentKind::DoubleActingCylinder: {
        // Both valves energised, or neither: the rod stays where it is.
        const bool extend = read(r, role::kExtend);
        const bool retract = read(r, role::kRetract);
        if (extend && !retract)
            r.position = std::min(r.stroke, r.position + r.extendStep);
        else if (retract && !extend)
            r.position = std::max<std::int64_t>(0, r.position - r.retractStep);
        break;
    }
    case ComponentKind::SingleActingCylinder:
        if (read(r, role::kExtend))
            r.position = std::min(r.stroke, r.position + r.extendStep);
        else
            r.position = std::max<std::int64_t>(0, r.position - r.retractStep);
        break;
    case ComponentKind::Conveyor:
        if (r.part && read(r, role::kRun) && ++r.position > r.travelScans) {
            r.part = false; // past the sensor: off the conveyor's end
            r.position = 0;
            ++r.delivered;
        }
        break;
    case ComponentKind::DelayedSensor:
        if (read(r, role::kDelayedOutput) == r.on) {
            r.pending = 0;
        } else if (++r.pending >= (r.on ? r.offScans : r.onScans)) {
            r.on = !r.on;
            r.pending = 0;
        }
        break;
    default:
        break;
    }
}

void MachineState::feed(Runtime& source)
{
    if (source.conveyor < 0 || source.partsLeft == 0)
        return;
    Runtime& conveyor = m_components[static_cast<std::size_t>(source.conveyor)];
    if (conveyor.part)
        return;
    conveyor.part = true;
    conveyor.position = 0;
    if (source.partsLeft > 0)
        --source.partsLeft;
}

void MachineState::writeSensors(Runtime& r)
{
    switch (r.kind) {
    case ComponentKind::DoubleActingCylinder:
        write(r, role::kDoubleRetracted, r.position == 0);
        write(r, role::kDoubleExtended, r.position == r.stroke);
        break;
    case ComponentKind::SingleActingCylinder:
        write(r, role::kSingleRetracted, r.position == 0);
        write(r, role::kSingleExtended, r.position == r.stroke);
        break;
    case ComponentKind::Conveyor:
        write(r, role::kPartPresent, r.part && r.position == r.travelScans);
        break;
    case ComponentKind::DelayedSensor:
        write(r, role::kDelayedSensor, r.on);
        break;
    case ComponentKind::PartSource:
        write(r, role::kSourceEmpty, r.partsLeft == 0);
        break;
    default:
        break;
    }
}

double MachineState::position(std::size_t component) const
{
    const Runtime& r = m_components.at(component);
    switch (r.kind) {
    case ComponentKind::DoubleActingCylinder:
    case ComponentKind::SingleActingCylinder:
        return static_cast<double>(r.position) / static_cast<double>(r.stroke);
    case ComponentKind::Conveyor:
        return r.part ? static_cast<double>(r.position) / static_cast<double>(r.travelScans) : 0.0;
    default:
        return 0.0;
    }
}

bool MachineState::hasPart(std::size_t component) const
{
    return m_components.at(component).part;
}

std::int64_t MachineState::partsDelivered(std::size_t component) const
{
    return m_components.at(component).delivered;
}

std::int64_t MachineState::partsLeft(std::size_t component) const
{
    return m_components.at(component).partsLeft;
}

bool MachineState::sensorOn(std::size_t component) const
{
    return m_components.at(component).on;
}

} // namespace core::machine
