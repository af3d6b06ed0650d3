#include "core/verification/promelamachine.h"

#include "core/machine/machinestate.h"
#include "core/model/iectypes.h"

#include <algorithm>
#include <set>

namespace core {

namespace {

using machine::ComponentKind;
using machine::SignalDirection;
namespace role = machine::role;
namespace parameter = machine::parameter;

class MachineWriter {
public:
    MachineWriter(const machine::Machine& machine, int cycleTimeMs, bool exactTime,
                  const std::function<bool(std::string_view, SignalDirection)>& wired,
                  const std::function<std::string(std::string_view)>& outputValue,
                  const std::function<std::string(std::size_t)>& jammed)
        : m_machine(machine), m_cycleMs(cycleTimeMs), m_exact(exactTime), m_wired(wired), m_outputValue(outputValue)
        , m_jammed(jammed)
    {
    }

    PromelaMachine run();

private:
    std::string name(std::size_t component) const { return "m" + std::to_string(component); }
    std::string actuator(const machine::Component& c, std::size_t r) const;
    void sensor(const machine::Component& c, std::size_t r, const std::string& expression);
    std::int64_t scans(std::int64_t ms, std::int64_t lowest) const
    {
        return machine::MachineState::scansFor(std::clamp<std::int64_t>(ms, lowest, machine::kMaxMachineTimeMs), m_cycleMs);
    }
    // Towards `to` from wherever it is, abstracted: at once in one cycle, else between, then maybe.
    std::string towards(const std::string& m, int to, bool inOne) const;
    void cylinder(std::size_t k, const machine::Component& c);
    void conveyor(std::size_t k, const machine::Component& c);
    void delayed(std::size_t k, const machine::Component& c);
    void source(std::size_t k, const machine::Component& c);

    const machine::Machine& m_machine;
    int m_cycleMs;
    bool m_exact;
    const std::function<bool(std::string_view, SignalDirection)>& m_wired;
    const std::function<std::string(std::string_view)>& m_outputValue;
    const std::function<std::string(std::size_t)>& m_jammed;
    // "!(jammed) && " before each condition that moves component k, or "".
    std::string moves(std::size_t k) const
    {
        const std::string jammed = m_jammed ? m_jammed(k) : std::string();
        return jammed.empty() ? std::string() : "!(" + jammed + ") && ";
    }
    std::set<std::string> m_operators; // upper names an operator role took first
    PromelaMachine m_out;
    std::vector<std::string> m_feeds;
    // The machine's reset (MachineState::reset): the sources, in order, put a
    // part on their empty conveyors. By component: a part on it; parts left.
    std::vector<bool> m_startPart;
    std::vector<std::int64_t> m_startParts;
};

std::string MachineWriter::actuator(const machine::Component& c, std::size_t r) const
{
    if (r >= c.wires.size() || c.wires[r].empty() || !m_wired(c.wires[r], SignalDirection::Actuator))
        return "0";
    return "(" + m_outputValue(c.wires[r]) + ")";
}

// As MachineState's signal table: the first role that names an input decides
// whether the machine drives it (a sensor) or the user (an operator input).
void MachineWriter::sensor(const machine::Component& c, std::size_t r, const std::string& expression)
{
    if (r >= c.wires.size() || c.wires[r].empty() || !m_wired(c.wires[r], SignalDirection::Sensor))
        return;
    const std::string upper = toUpperAscii(c.wires[r]);
    if (!m_operators.count(upper))
        m_out.sensors[upper] = "(" + expression + ")";
}

std::string MachineWriter::towards(const std::string& m, int to, bool inOne) const
{
    const std::string there = m + " = " + std::to_string(to);
    if (inOne)
        return there;
    return "if :: " + m + " == " + std::to_string(to) + " -> skip :: " + m + " == 1 -> if :: " + there
        + " :: skip fi :: else -> " + m + " = 1 fi";
}

void MachineWriter::cylinder(std::size_t k, const machine::Component& c)
{
    const bool doubleActing = c.kind == ComponentKind::DoubleActingCylinder;
    const std::int64_t out = scans(c.parameters.at(parameter::kExtendMs), 1);
    const std::int64_t back = scans(c.parameters.at(parameter::kRetractMs), 1);
    const std::string m = name(k);
    const std::string extend = actuator(c, role::kExtend);
    const std::string retract = doubleActing ? actuator(c, role::kRetract) : "(!" + extend + ")";
    const std::string stroke = std::to_string(out * back);
    m_out.declarations.push_back((m_exact ? "int " : "byte ") + m + "; /* " + c.name + ": "
                                 + (m_exact ? "0 retracted .. " + stroke + " extended" : "0 retracted, 1 between, 2 extended")
                                 + " */");
    const std::string end = m_exact ? stroke : "2";
    sensor(c, doubleActing ? role::kDoubleRetracted : role::kSingleRetracted, m + " == 0");
    sensor(c, doubleActing ? role::kDoubleExtended : role::kSingleExtended, m + " == " + end);
    std::string extendMove, retractMove;
    if (m_exact) {
        const std::string up = std::to_string(back), down = std::to_string(out);
        extendMove = m + " = (" + m + " + " + up + " < " + stroke + " -> " + m + " + " + up + " : " + stroke + ")";
        retractMove = m + " = (" + m + " > " + down + " -> " + m + " - " + down + " : 0)";
    } else {
        extendMove = towards(m, 2, out == 1);
        retractMove = towards(m, 0, back == 1);
    }
    m_out.cycle.push_back("if :: " + moves(k) + extend + " && !" + retract + " -> " + extendMove + " :: " + moves(k)
                          + retract + " && !" + extend + " -> " + retractMove + " :: else -> skip fi; /* " + c.name
                          + " */");
}

void MachineWriter::conveyor(std::size_t k, const machine::Component& c)
{
    const std::int64_t travel = scans(c.parameters.at(parameter::kTravelMs), 1);
    const std::string m = name(k);
    const std::string run = actuator(c, role::kRun);
    if (m_exact) {
        m_out.declarations.push_back("bit " + m + "_part = " + (m_startPart[k] ? "1" : "0") + "; int " + m + "; /* "
                                     + c.name + ": a part, its cycles from the entry */");
        sensor(c, role::kPartPresent, m + "_part && " + m + " == " + std::to_string(travel));
        m_out.cycle.push_back("if :: " + moves(k) + m + "_part && " + run + " -> " + m + "++; if :: " + m + " > "
                              + std::to_string(travel) + " -> " + m + "_part = 0; " + m
                              + " = 0 :: else -> skip fi :: else -> skip fi; /* " + c.name + " */");
        return;
    }
    m_out.declarations.push_back("byte " + m + " = " + (m_startPart[k] ? "1" : "0") + "; /* " + c.name
                                 + ": 0 no part, 1 travelling, 2 at the sensor */");
    sensor(c, role::kPartPresent, m + " == 2");
    const std::string arrive = travel == 1 ? m + " = 2" : "if :: " + m + " = 2 :: skip fi";
    m_out.cycle.push_back("if :: " + moves(k) + m + " == 2 && " + run + " -> " + m + " = 0 :: " + moves(k) + m
                          + " == 1 && " + run + " -> " + arrive + " :: else -> skip fi; /* " + c.name + " */");
}

void MachineWriter::delayed(std::size_t k, const machine::Component& c)
{
    const std::int64_t on = scans(c.parameters.at(parameter::kOnDelayMs), 0);
    const std::int64_t off = scans(c.parameters.at(parameter::kOffDelayMs), 0);
    const std::string m = name(k);
    const std::string output = actuator(c, role::kDelayedOutput);
    m_out.declarations.push_back("bit " + m + "_on; " + std::string(m_exact ? "int " : "bit ") + m + "; /* " + c.name
                                 + ": the sensor, " + (m_exact ? "cycles" : "whether") + " its output has differed */");
    sensor(c, role::kDelayedSensor, m + "_on");
    const std::string toggle = m + "_on = !" + m + "_on; " + m + " = 0";
    std::string differs;
    if (m_exact) {
        differs = m + "++; if :: " + m + " >= (" + m + "_on -> " + std::to_string(off) + " : " + std::to_string(on)
            + ") -> " + toggle + " :: else -> skip fi";
    } else {
        const auto branch = [&](std::int64_t delay) {
            return delay == 1 ? toggle : "if :: " + m + " -> if :: " + toggle + " :: skip fi :: else -> " + m + " = 1 fi";
        };
        differs = "if :: " + m + "_on -> " + branch(off) + " :: else -> " + branch(on) + " fi";
    }
    m_out.cycle.push_back("if :: " + output + " == " + m + "_on -> " + m + " = 0 :: else -> " + differs + " fi; /* "
                          + c.name + " */");
}

void MachineWriter::source(std::size_t k, const machine::Component& c)
{
    const std::string m = name(k);
    sensor(c, role::kSourceEmpty, m + " == 0");
    const machine::Component* target = m_machine.find(c.conveyor);
    std::string feed;
    if (target && target->kind == ComponentKind::Conveyor) {
        const std::string belt = name(static_cast<std::size_t>(target - m_machine.components.data()));
        const std::string empty = m_exact ? "!" + belt + "_part" : belt + " == 0";
        const std::string put = m_exact ? belt + "_part = 1; " + belt + " = 0" : belt + " = 1";
        feed = "if :: " + m + " != 0 && " + empty + " -> " + put + "; if :: " + m + " > 0 -> " + m
            + "-- :: else -> skip fi :: else -> skip fi; /* " + c.name + " feeds " + target->name + " */";
        m_feeds.push_back(feed);
    }
    m_out.declarations.push_back("int " + m + " = " + std::to_string(m_startParts[k]) + "; /* " + c.name
                                 + ": parts left, -1 unlimited */");
}

PromelaMachine MachineWriter::run()
{
    for (const machine::Component& c : m_machine.components) {
        const machine::ComponentKindSpec& spec = machine::kindSpec(c.kind);
        for (std::size_t r = 0; r < spec.roles.size() && r < c.wires.size(); ++r) {
            if (c.wires[r].empty() || spec.roles[r].direction == SignalDirection::Actuator)
                continue;
            const std::string upper = toUpperAscii(c.wires[r]);
            if (!m_wired(c.wires[r], spec.roles[r].direction) || m_out.sensors.count(upper) || m_operators.count(upper))
                continue;
            if (spec.roles[r].direction == SignalDirection::Operator)
                m_operators.insert(upper);
            else
                m_out.sensors[upper] = ""; // claimed: its expression follows
        }
    }
    const std::size_t count = m_machine.components.size();
    m_startPart.assign(count, false);
    m_startParts.assign(count, 0);
    for (std::size_t k = 0; k < count; ++k) {
        const machine::Component& c = m_machine.components[k];
        if (c.kind != ComponentKind::PartSource || c.parameters.size() != 1)
            continue;
        m_startParts[k] = std::max(c.parameters[parameter::kParts], machine::kUnlimitedParts);
        const machine::Component* target = m_machine.find(c.conveyor);
        if (!target || target->kind != ComponentKind::Conveyor || m_startParts[k] == 0)
            continue;
        const auto belt = static_cast<std::size_t>(target - m_machine.components.data());
        if (m_startPart[belt])
            continue;
        m_startPart[belt] = true;
        if (m_startParts[k] > 0)
            --m_startParts[k];
    }
    for (std::size_t k = 0; k < count; ++k) {
        const machine::Component& c = m_machine.components[k];
        if (c.parameters.size() != machine::kindSpec(c.kind).parameters.size())
            continue; // structurally broken: the checks refuse it
        switch (c.kind) {
        case ComponentKind::DoubleActingCylinder:
        case ComponentKind::SingleActingCylinder: cylinder(k, c); break;
        case ComponentKind::Conveyor: conveyor(k, c); break;
        case ComponentKind::DelayedSensor: delayed(k, c); break;
        case ComponentKind::PartSource: source(k, c); break;
        default: break;
        }
    }
    // After every component moved, the sources feed (MachineState::cycle).
    m_out.cycle.insert(m_out.cycle.end(), m_feeds.begin(), m_feeds.end());
    std::erase_if(m_out.sensors, [](const auto& entry) { return entry.second.empty(); });
    return std::move(m_out);
}

} // namespace

PromelaMachine buildPromelaMachine(const machine::Machine& machine, int cycleTimeMs, bool exactTime,
                                   const std::function<bool(std::string_view, SignalDirection)>& wired,
                                   const std::function<std::string(std::string_view)>& outputValue,
                                   const std::function<std::string(std::size_t)>& jammed)
{
    return MachineWriter(machine, cycleTimeMs, exactTime, wired, outputValue, jammed).run();
}

} // namespace core
