// MachineState::appendKey and restoreKey: a running machine as a few bytes,
// for a verifier that keeps its states in a hash table (docs/verification.md,
// "Closed loop (--machine)"). Every number is written as an unsigned LEB128
// varint, so a cylinder at rest or an empty conveyor costs one byte.

#include "core/machine/machinestate.h"

#include "core/formats/varint.h"

namespace core::machine {

namespace {

// Reads one varint at `at`, advancing it; false at a truncated or overlong one.
bool readVarint(std::string_view in, std::size_t& at, std::uint64_t& value)
{
    value = 0;
    for (int shift = 0; shift < 64 && at < in.size(); shift += 7) {
        const auto byte = static_cast<unsigned char>(in[at++]);
        value |= static_cast<std::uint64_t>(byte & 0x7F) << shift;
        if (!(byte & 0x80))
            return true;
    }
    return false;
}

std::uint64_t unsignedOf(std::int64_t value)
{
    return static_cast<std::uint64_t>(value);
}

} // namespace

// Per component, by kind: a cylinder's position; a conveyor's part position
// + 1 (0: no part); a delayed sensor's pending cycles x 2 + on; a part
// source's parts left + 1 (0: unlimited). Other kinds have no state.
void MachineState::appendKey(std::string& key) const
{
    for (const Runtime& r : m_components) {
        switch (r.kind) {
        case ComponentKind::DoubleActingCylinder:
        case ComponentKind::SingleActingCylinder: appendVarint(key, unsignedOf(r.position)); break;
        case ComponentKind::Conveyor: appendVarint(key, r.part ? unsignedOf(r.position) + 1 : 0); break;
        case ComponentKind::DelayedSensor: appendVarint(key, unsignedOf(r.pending) * 2 + (r.on ? 1 : 0)); break;
        case ComponentKind::PartSource: appendVarint(key, unsignedOf(r.partsLeft + 1)); break;
        default: break;
        }
    }
}

std::size_t MachineState::restoreKey(std::string_view key)
{
    std::vector<std::uint64_t> values;
    std::size_t at = 0;
    for (const Runtime& r : m_components) {
        switch (r.kind) {
        case ComponentKind::DoubleActingCylinder:
        case ComponentKind::SingleActingCylinder:
        case ComponentKind::Conveyor:
        case ComponentKind::DelayedSensor:
        case ComponentKind::PartSource: {
            std::uint64_t value = 0;
            if (!readVarint(key, at, value))
                return 0;
            values.push_back(value);
            break;
        }
        default: break;
        }
    }
    std::size_t next = 0;
    for (Runtime& r : m_components) {
        r.delivered = 0;
        switch (r.kind) {
        case ComponentKind::DoubleActingCylinder:
        case ComponentKind::SingleActingCylinder: r.position = static_cast<std::int64_t>(values[next++]); break;
        case ComponentKind::Conveyor: {
            const std::uint64_t value = values[next++];
            r.part = value != 0;
            r.position = r.part ? static_cast<std::int64_t>(value - 1) : 0;
            break;
        }
        case ComponentKind::DelayedSensor: {
            const std::uint64_t value = values[next++];
            r.on = (value & 1) != 0;
            r.pending = static_cast<std::int64_t>(value >> 1);
            break;
        }
        case ComponentKind::PartSource: r.partsLeft = static_cast<std::int64_t>(values[next++]) - 1; break;
        default: break;
        }
    }
    for (Runtime& r : m_components)
        writeSensors(r);
    return at;
}

} // namespace core::machine
