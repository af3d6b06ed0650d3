// The virtual machine's components and their one-cycle semantics
// (core/machine/machinestate.h, docs/simulation.md "The virtual machine").

#include "core/machine/machinestate.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace test_machine {

using namespace core::machine;

namespace {

// A machine on a table of named signals, as the closed loop drives it.
class Bench {
public:
    Bench(Machine machine, int cycleTimeMs)
        : m_state(machine, cycleTimeMs, [this](std::string_view name, SignalDirection) { return indexOf(name); })
    {
    }

    void set(const std::string& name, bool value)
    {
        for (std::size_t i = 0; i < m_state.signalSlots().size(); ++i) {
            if (m_names[static_cast<std::size_t>(m_state.signalSlots()[i].variable)] == name)
                m_state.setSignal(i, value);
        }
    }
    bool get(const std::string& name) const
    {
        for (std::size_t i = 0; i < m_state.signalSlots().size(); ++i) {
            if (m_names[static_cast<std::size_t>(m_state.signalSlots()[i].variable)] == name)
                return m_state.signal(i);
        }
        FAIL("no slot for " << name);
        return false;
    }
    // Cycles until `sensor` reads `value`; how many it took (-1: not within `limit`).
    int cyclesUntil(const std::string& sensor, bool value, int limit = 1000)
    {
        for (int n = 1; n <= limit; ++n) {
            m_state.cycle();
            if (get(sensor) == value)
                return n;
        }
        return -1;
    }
    MachineState& state() { return m_state; }

private:
    int indexOf(std::string_view name)
    {
        for (std::size_t i = 0; i < m_names.size(); ++i) {
            if (m_names[i] == name)
                return static_cast<int>(i);
        }
        m_names.emplace_back(name);
        return static_cast<int>(m_names.size() - 1);
    }

    std::vector<std::string> m_names;
    MachineState m_state;
};

Component cylinder(std::int64_t extendMs, std::int64_t retractMs)
{
    Component c = makeComponent(ComponentKind::DoubleActingCylinder, "Clamp");
    c.setSignal("extend", "Out");
    c.setSignal("retract", "In");
    c.setSignal("retracted", "AtHome");
    c.setSignal("extended", "AtEnd");
    c.setParameter("extendMs", extendMs);
    c.setParameter("retractMs", retractMs);
    return c;
}

} // namespace

TEST_CASE("Kinds, roles and contacts have stable names", "[machine]")
{
    for (ComponentKind kind : allComponentKinds()) {
        ComponentKind parsed{};
        REQUIRE(parseComponentKind(componentKindName(kind), parsed));
        CHECK(parsed == kind);
        CHECK(kindSpec(kind).kind == kind);
    }
    ComponentKind unknown{};
    CHECK_FALSE(parseComponentKind("robot", unknown));
    CHECK(componentKindName(ComponentKind::DoubleActingCylinder) == "double-acting-cylinder");
    CHECK(kindSpec(ComponentKind::DoubleActingCylinder).roles[role::kDoubleExtended].key == "extended");
    CHECK(kindSpec(ComponentKind::SingleActingCylinder).roles[role::kSingleExtended].key == "extended");
    CHECK(kindSpec(ComponentKind::Conveyor).roles[role::kPartPresent].key == "partPresent");
    CHECK(kindSpec(ComponentKind::DelayedSensor).parameters[parameter::kOffDelayMs].key == "offDelayMs");
    CHECK(makeComponent(ComponentKind::EmergencyStop, "E").contact == Contact::NormallyClosed);
    CHECK(makeComponent(ComponentKind::PushButton, "B").contact == Contact::NormallyOpen);
    Component lamp = makeComponent(ComponentKind::Lamp, "L");
    CHECK_FALSE(lamp.setSignal("extend", "X"));
    CHECK(lamp.setSignal("lamp", "X"));
    CHECK(lamp.signal("lamp") == "X");
}

TEST_CASE("Travel times are counted in cycles, rounded up", "[machine]")
{
    CHECK(MachineState::scansFor(200, 10) == 20);
    CHECK(MachineState::scansFor(205, 10) == 21);
    CHECK(MachineState::scansFor(1, 10) == 1);
    CHECK(MachineState::scansFor(0, 10) == 1); // a zero delay: the next scan
}

TEST_CASE("A double-acting cylinder travels each way in its own time", "[machine]")
{
    Bench bench(Machine{{cylinder(200, 305)}}, 10);
    CHECK(bench.get("AtHome")); // starts retracted
    CHECK_FALSE(bench.get("AtEnd"));
    bench.set("Out", true);
    CHECK(bench.cyclesUntil("AtHome", false) == 1); // left its home switch in the first cycle
    bench.set("Out", true);
    CHECK(bench.cyclesUntil("AtEnd", true) == 19); // 20 cycles in all
    bench.set("Out", false);
    bench.set("In", true);
    CHECK(bench.cyclesUntil("AtHome", true) == 31); // ceil(305 / 10)
}

TEST_CASE("A double-acting cylinder stays with both valves or neither", "[machine]")
{
    Bench bench(Machine{{cylinder(50, 50)}}, 10);
    bench.set("Out", true);
    bench.state().cycle();
    bench.state().cycle();
    const double midway = bench.state().position(0);
    CHECK(midway == Approx(0.4));
    bench.set("In", true); // both: the rod stays
    bench.state().cycle();
    CHECK(bench.state().position(0) == midway);
    bench.set("Out", false);
    bench.set("In", false); // neither: it stays too
    bench.state().cycle();
    CHECK(bench.state().position(0) == midway);
    bench.set("In", true); // a reversal takes back what it travelled
    CHECK(bench.cyclesUntil("AtHome", true) == 2);
}

TEST_CASE("A single-acting cylinder returns on its spring", "[machine]")
{
    Component c = makeComponent(ComponentKind::SingleActingCylinder, "Stop");
    c.setSignal("extend", "StopOut");
    c.setSignal("extended", "StopUp");
    c.setSignal("retracted", "StopDown");
    c.setParameter("extendMs", 30);
    c.setParameter("retractMs", 50);
    Bench bench(Machine{{c}}, 10);
    bench.set("StopOut", true);
    CHECK(bench.cyclesUntil("StopUp", true) == 3);
    bench.set("StopOut", false);
    CHECK(bench.cyclesUntil("StopDown", true) == 5);
}

TEST_CASE("A conveyor brings a part to its sensor and carries it off", "[machine]")
{
    Component belt = makeComponent(ComponentKind::Conveyor, "Belt");
    belt.setSignal("run", "Run");
    belt.setSignal("partPresent", "Part");
    belt.setParameter("travelMs", 40);
    Component source = makeComponent(ComponentKind::PartSource, "Magazine");
    source.conveyor = "Belt";
    source.setParameter("parts", 2);
    source.setSignal("empty", "MagazineEmpty");
    Bench bench(Machine{{belt, source}}, 10);
    CHECK(bench.state().hasPart(0)); // the source put the first part on the entry
    CHECK(bench.state().partsLeft(1) == 1);
    CHECK_FALSE(bench.get("Part"));
    bench.state().cycle(); // stopped: nothing moves
    CHECK(bench.state().position(0) == 0.0);
    bench.set("Run", true);
    CHECK(bench.cyclesUntil("Part", true) == 4);
    bench.set("Run", false);
    bench.state().cycle();
    CHECK(bench.get("Part")); // stays at the sensor while stopped
    bench.set("Run", true);
    CHECK(bench.cyclesUntil("Part", false) == 1); // one more cycle takes it past
    CHECK(bench.state().partsDelivered(0) == 1);
    CHECK(bench.state().hasPart(0)); // the source fed the next one at once
    CHECK(bench.get("MagazineEmpty"));
    CHECK(bench.cyclesUntil("Part", true) == 4);
    CHECK(bench.cyclesUntil("Part", false) == 1);
    CHECK_FALSE(bench.state().hasPart(0)); // no part left
    CHECK(bench.state().partsDelivered(0) == 2);
}

TEST_CASE("A delayed sensor follows its output after the on and off delays", "[machine]")
{
    Component d = makeComponent(ComponentKind::DelayedSensor, "Heater");
    d.setSignal("output", "Heat");
    d.setSignal("sensor", "Hot");
    d.setParameter("onDelayMs", 50);
    d.setParameter("offDelayMs", 0);
    Bench bench(Machine{{d}}, 10);
    bench.set("Heat", true);
    CHECK(bench.cyclesUntil("Hot", true) == 5);
    bench.set("Heat", false);
    CHECK(bench.cyclesUntil("Hot", false) == 1);
    bench.set("Heat", true); // a pulse shorter than the delay is not seen
    bench.state().cycle();
    bench.set("Heat", false);
    CHECK(bench.cyclesUntil("Hot", true, 20) == -1);
}

TEST_CASE("Operator inputs rest at their contact's value", "[machine]")
{
    Component stop = makeComponent(ComponentKind::EmergencyStop, "EStop");
    stop.setSignal("input", "EmergencyOk");
    Component start = makeComponent(ComponentKind::PushButton, "Start");
    start.setSignal("input", "StartButton");
    Component reset = makeComponent(ComponentKind::PushButton, "Reset");
    reset.setSignal("input", "ResetNC");
    reset.contact = Contact::NormallyClosed;
    Bench bench(Machine{{stop, start, reset}}, 10);
    CHECK(bench.get("EmergencyOk"));
    CHECK_FALSE(bench.get("StartButton"));
    CHECK(bench.get("ResetNC"));
    bench.set("StartButton", true); // the user's: a cycle leaves it
    bench.state().cycle();
    CHECK(bench.get("StartButton"));
    bench.state().reset();
    CHECK_FALSE(bench.get("StartButton"));
}

TEST_CASE("Structural problems of a machine description", "[machine]")
{
    Machine machine{{makeComponent(ComponentKind::Lamp, "L"), makeComponent(ComponentKind::Lamp, "l")}};
    REQUIRE(machine.structuralProblems().size() == 1);
    CHECK(machine.structuralProblems()[0] == "two machine components are named 'l' (ignoring case)");
    machine.components[1].name.clear();
    CHECK(machine.structuralProblems() == std::vector<std::string>{"a machine component has an empty name"});
    machine.components[1] = makeComponent(ComponentKind::Lamp, "M");
    machine.components[1].wires.push_back("Extra");
    CHECK(machine.structuralProblems().size() == 1);
    machine.components[1] = makeComponent(ComponentKind::Lamp, "M");
    machine.components[1].conveyor = "Belt";
    CHECK(machine.structuralProblems().size() == 1);
    machine.components[1].conveyor.clear();
    CHECK(machine.structuralProblems().empty());
    CHECK(machine.find("m") == &machine.components[1]);
}

} // namespace test_machine
