#include "core/verification/abstractmachine.h"

#include <algorithm>

namespace core::explore {

namespace {

using machine::ComponentKind;
namespace role = machine::role;
namespace parameter = machine::parameter;

// As MachineState counts a travel: no valid time is below 1 ms.
bool oneCycle(std::int64_t ms, int cycleTimeMs, std::int64_t lowest)
{
    return machine::MachineState::scansFor(std::clamp<std::int64_t>(ms, lowest, machine::kMaxMachineTimeMs),
                                           cycleTimeMs)
        == 1;
}

} // namespace

AbstractMachine::AbstractMachine(const machine::Machine& description, const machine::MachineState& exact,
                                 int cycleTimeMs,
                                 const std::function<int(std::string_view, machine::SignalDirection)>& wire)
{
    const std::vector<machine::SignalSlot>& table = exact.signalSlots();
    for (const machine::Component& component : description.components) {
        const machine::ComponentKindSpec& spec = machine::kindSpec(component.kind);
        Part p;
        p.kind = component.kind;
        p.contact = component.contact;
        for (std::size_t r = 0; r < spec.roles.size() && r < component.wires.size() && r < p.slot.size(); ++r) {
            const int variable = component.wires[r].empty() ? -1 : wire(component.wires[r], spec.roles[r].direction);
            const auto found = std::find_if(table.begin(), table.end(),
                                            [&](const machine::SignalSlot& s) { return s.variable == variable; });
            if (variable >= 0 && found != table.end())
                p.slot[r] = static_cast<int>(found - table.begin());
        }
        const auto value = [&](std::size_t index) {
            return index < component.parameters.size() ? component.parameters[index] : 0;
        };
        switch (component.kind) {
        case ComponentKind::DoubleActingCylinder:
        case ComponentKind::SingleActingCylinder:
            p.outInOne = oneCycle(value(parameter::kExtendMs), cycleTimeMs, 1);
            p.backInOne = oneCycle(value(parameter::kRetractMs), cycleTimeMs, 1);
            break;
        case ComponentKind::Conveyor: p.outInOne = oneCycle(value(parameter::kTravelMs), cycleTimeMs, 1); break;
        case ComponentKind::DelayedSensor:
            p.onInOne = oneCycle(value(parameter::kOnDelayMs), cycleTimeMs, 0);
            p.offInOne = oneCycle(value(parameter::kOffDelayMs), cycleTimeMs, 0);
            break;
        case ComponentKind::PartSource: {
            p.initialParts = std::max(value(parameter::kParts), machine::kUnlimitedParts);
            const machine::Component* conveyor = description.find(component.conveyor);
            if (conveyor && conveyor->kind == ComponentKind::Conveyor)
                p.conveyor = static_cast<int>(conveyor - description.components.data());
            break;
        }
        default: break;
        }
        m_parts.push_back(p);
    }
    m_signals.assign(table.size(), 0);
    reset();
}

void AbstractMachine::reset()
{
    std::fill(m_signals.begin(), m_signals.end(), 0);
    for (Part& p : m_parts) {
        p.phase = kAtStart;
        p.pending = false;
        p.on = false;
        p.partsLeft = p.initialParts;
        p.jammed = false;
    }
    for (Part& p : m_parts) {
        if (p.kind == ComponentKind::PartSource)
            feed(p);
    }
    for (const Part& p : m_parts) {
        writeSensors(p);
        if (machine::kindSpec(p.kind).hasContact)
            write(p, role::kOperatorInput, p.contact == machine::Contact::NormallyClosed);
    }
}

void AbstractMachine::cycle(const std::function<int(int)>& choose)
{
    for (Part& p : m_parts)
        move(p, choose);
    for (Part& p : m_parts) {
        if (p.kind == ComponentKind::PartSource)
            feed(p);
    }
    for (const Part& p : m_parts)
        writeSensors(p);
}

bool AbstractMachine::read(const Part& p, std::size_t r) const
{
    return p.slot[r] >= 0 && m_signals[static_cast<std::size_t>(p.slot[r])] != 0;
}

void AbstractMachine::write(const Part& p, std::size_t r, bool value)
{
    if (p.slot[r] >= 0)
        m_signals[static_cast<std::size_t>(p.slot[r])] = value ? 1 : 0;
}

void AbstractMachine::move(Part& p, const std::function<int(int)>& choose)
{
    // A travel towards `to`: there at once when a full one takes one cycle
    // (or there already), else between, and from between there when
    // `choose` says so.
    const auto travel = [&](Phase to, bool inOne) {
        if (p.phase == to)
            return;
        if (inOne || (p.phase == kBetween && choose(2) != 0))
            p.phase = to;
        else
            p.phase = kBetween;
    };
    if (p.jammed)
        return; // as MachineState::move: it does not move, whatever its outputs
    switch (p.kind) {
    case ComponentKind::DoubleActingCylinder: {
        const bool extend = read(p, role::kExtend);
        const bool retract = read(p, role::kRetract);
        if (extend && !retract)
            travel(kAtEnd, p.outInOne);
        else if (retract && !extend)
            travel(kAtStart, p.backInOne);
        break;
    }
    case ComponentKind::SingleActingCylinder:
        if (read(p, role::kExtend))
            travel(kAtEnd, p.outInOne);
        else
            travel(kAtStart, p.backInOne);
        break;
    case ComponentKind::Conveyor:
        if (p.phase == kAtEnd && read(p, role::kRun))
            p.phase = kAtStart; // past the sensor: off the conveyor's end
        else if (p.phase == kBetween && read(p, role::kRun) && (p.outInOne || choose(2) != 0))
            p.phase = kAtEnd;
        break;
    case ComponentKind::DelayedSensor: {
        if (read(p, role::kDelayedOutput) == p.on) {
            p.pending = false;
            break;
        }
        const bool inOne = p.on ? p.offInOne : p.onInOne;
        if (inOne || (p.pending && choose(2) != 0)) {
            p.on = !p.on;
            p.pending = false;
        } else {
            p.pending = true;
        }
        break;
    }
    default: break;
    }
}

void AbstractMachine::feed(Part& source)
{
    if (source.conveyor < 0 || source.partsLeft == 0)
        return;
    Part& conveyor = m_parts[static_cast<std::size_t>(source.conveyor)];
    if (conveyor.phase != kAtStart)
        return;
    conveyor.phase = kBetween; // on the entry, short of the sensor: a travel is at least one cycle
    if (source.partsLeft > 0)
        --source.partsLeft;
}

void AbstractMachine::writeSensors(const Part& p)
{
    switch (p.kind) {
    case ComponentKind::DoubleActingCylinder:
        write(p, role::kDoubleRetracted, p.phase == kAtStart);
        write(p, role::kDoubleExtended, p.phase == kAtEnd);
        break;
    case ComponentKind::SingleActingCylinder:
        write(p, role::kSingleRetracted, p.phase == kAtStart);
        write(p, role::kSingleExtended, p.phase == kAtEnd);
        break;
    case ComponentKind::Conveyor: write(p, role::kPartPresent, p.phase == kAtEnd); break;
    case ComponentKind::DelayedSensor: write(p, role::kDelayedSensor, p.on); break;
    case ComponentKind::PartSource: write(p, role::kSourceEmpty, p.partsLeft == 0); break;
    default: break;
    }
}

void AbstractMachine::appendKey(std::string& key) const
{
    for (const Part& p : m_parts) {
        switch (p.kind) {
        case ComponentKind::DoubleActingCylinder:
        case ComponentKind::SingleActingCylinder:
        case ComponentKind::Conveyor: key.push_back(static_cast<char>(p.phase)); break;
        case ComponentKind::DelayedSensor: key.push_back(static_cast<char>((p.on ? 1 : 0) | (p.pending ? 2 : 0))); break;
        case ComponentKind::PartSource: {
            // Parts left + 1 (0: unlimited), little-endian 7 bits a byte.
            auto value = static_cast<std::uint64_t>(p.partsLeft + 1);
            while (value >= 0x80) {
                key.push_back(static_cast<char>((value & 0x7F) | 0x80));
                value >>= 7;
            }
            key.push_back(static_cast<char>(value));
            break;
        }
        default: break;
        }
    }
}

std::size_t AbstractMachine::restoreKey(std::string_view key)
{
    std::size_t at = 0;
    for (Part& p : m_parts) {
        switch (p.kind) {
        case ComponentKind::DoubleActingCylinder:
        case ComponentKind::SingleActingCylinder:
        case ComponentKind::Conveyor:
            if (at >= key.size())
                return 0;
            p.phase = static_cast<Phase>(key[at++]);
            break;
        case ComponentKind::DelayedSensor:
            if (at >= key.size())
                return 0;
            p.on = (key[at] & 1) != 0;
            p.pending = (key[at++] & 2) != 0;
            break;
        case ComponentKind::PartSource: {
            std::uint64_t value = 0;
            int shift = 0;
            for (;; shift += 7) {
                if (at >= key.size() || shift >= 64)
                    return 0;
                const auto byte = static_cast<unsigned char>(key[at++]);
                value |= static_cast<std::uint64_t>(byte & 0x7F) << shift;
                if (!(byte & 0x80))
                    break;
            }
            p.partsLeft = static_cast<std::int64_t>(value) - 1;
            break;
        }
        default: break;
        }
    }
    for (const Part& p : m_parts)
        writeSensors(p);
    return at;
}

} // namespace core::explore
