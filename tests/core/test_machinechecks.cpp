// The checks of the virtual machine (core/machine/machinechecks.h, GG601-GG608)
// and the Model carrying it (core/model/model.h).

#include "core/checks/checks.h"
#include "core/formats/modelfiles.h"
#include "core/machine/machinechecks.h"
#include "core/model/model.h"
#include "core/templates/packml/packmlmodel.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace test_machinechecks {

using namespace core;
using namespace core::machine;

namespace {

Model drillingCell()
{
    const auto loaded = loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    REQUIRE(loaded.model);
    return Model(*loaded.model);
}

Component clamp()
{
    Component c = makeComponent(ComponentKind::DoubleActingCylinder, "Clamp");
    c.setSignal("extend", "ClampOut");
    c.setSignal("retract", "ClampIn");
    c.setSignal("retracted", "Unclamped");
    c.setSignal("extended", "Clamped");
    return c;
}

std::vector<Diagnostic> machineFindings(const Model& model)
{
    std::vector<Diagnostic> all = checkModel(model);
    std::erase_if(all, [](const Diagnostic& d) { return d.target != Diagnostic::Target::MachineComponent; });
    return all;
}

const Diagnostic* find(const std::vector<Diagnostic>& diagnostics, const std::string& code)
{
    const auto found = std::find_if(diagnostics.begin(), diagnostics.end(),
                                    [&](const Diagnostic& d) { return d.code == code; });
    return found == diagnostics.end() ? nullptr : &*found;
}

} // namespace

TEST_CASE("A well-wired machine has no findings", "[machine][machine-checks]")
{
    Model model = drillingCell();
    REQUIRE(model.setMachine(Machine{{clamp()}}));
    CHECK(machineFindings(model).empty());
}

TEST_CASE("An unknown variable, a wrong kind and a wrong type are located errors", "[machine][machine-checks]")
{
    Model model = drillingCell();
    Component c = clamp();
    c.setSignal("extended", "Ghost");      // unknown
    c.setSignal("retracted", "ClampOut");  // an output wired as a sensor
    c.setSignal("retract", "BatchSize");   // an INT input wired as an actuator
    REQUIRE(model.setMachine(Machine{{c}}));
    const std::vector<Diagnostic> findings = machineFindings(model);

    const Diagnostic* unknown = find(findings, "GG601");
    REQUIRE(unknown);
    CHECK(unknown->severity == Severity::Error);
    CHECK(unknown->element == "Clamp");
    CHECK(unknown->field == "extended");
    CHECK(unknown->message == "Clamp's extended signal names 'Ghost', which is no variable of the model");
    CHECK(diagnosticElementLabel(*unknown) == "machine component Clamp");

    std::vector<const Diagnostic*> kinds;
    for (const Diagnostic& d : findings) {
        if (d.code == "GG602")
            kinds.push_back(&d);
    }
    REQUIRE(kinds.size() == 2);
    CHECK(kinds[0]->field == "retract");
    CHECK(kinds[0]->message == "Clamp's retract signal is BatchSize, an input variable; it needs an output");
    CHECK(kinds[1]->field == "retracted");
    CHECK(kinds[1]->arguments == std::vector<std::string>{"Clamp", "retracted", "ClampOut", "output", "input"});

    const Diagnostic* type = find(findings, "GG603");
    REQUIRE(type);
    CHECK(type->field == "retract");
    CHECK(type->message == "Clamp's retract signal is BatchSize, of type INT; a machine signal is BOOL");
}

TEST_CASE("A sensor wired to two components is an error", "[machine][machine-checks]")
{
    Model model = drillingCell();
    Component photocell = makeComponent(ComponentKind::DelayedSensor, "Photocell");
    photocell.setSignal("output", "ClampOut");
    photocell.setSignal("sensor", "Clamped");
    REQUIRE(model.setMachine(Machine{{clamp(), photocell}}));
    const std::vector<Diagnostic> findings = machineFindings(model);
    REQUIRE(findings.size() == 1);
    CHECK(findings[0].code == "GG604");
    CHECK(findings[0].element == "Photocell");
    CHECK(findings[0].message == "Clamped is wired to Photocell's sensor signal and to Clamp's extended signal: "
                                 "an input has one source");
}

TEST_CASE("An actuator no action drives is a warning", "[machine][machine-checks]")
{
    Model model = drillingCell();
    REQUIRE(model.addVariable(Variable{"Horn", IecType::Bool, "", "", VariableKind::Output}));
    Component horn = makeComponent(ComponentKind::Lamp, "Horn");
    horn.setSignal("lamp", "Horn");
    Component ready = makeComponent(ComponentKind::Lamp, "Ready");
    ready.setSignal("lamp", "ReadyLamp"); // S ReadyLamp in F2 step 4
    REQUIRE(model.setMachine(Machine{{horn, ready}}));
    const std::vector<Diagnostic> findings = machineFindings(model);
    REQUIRE(findings.size() == 1);
    CHECK(findings[0].code == "GG605");
    CHECK(findings[0].severity == Severity::Warning);
    CHECK(findings[0].message == "Horn's lamp signal Horn is driven by no action of the program: the component "
                                 "never moves");
}

TEST_CASE("Bad times, unwired roles and a source without conveyor are errors", "[machine][machine-checks]")
{
    Model model = drillingCell();
    Component c = clamp();
    c.setParameter("extendMs", 0);
    c.setParameter("retractMs", -5);
    c.setSignal("retract", "");
    Component source = makeComponent(ComponentKind::PartSource, "Magazine");
    source.conveyor = "Clamp"; // no conveyor
    Component delay = makeComponent(ComponentKind::DelayedSensor, "Hot");
    delay.setSignal("output", "Spindle");
    delay.setSignal("sensor", "PartPresent");
    delay.setParameter("onDelayMs", 0); // a zero delay is fine
    REQUIRE(model.setMachine(Machine{{c, source, delay}}));
    const std::vector<Diagnostic> findings = machineFindings(model);
    std::vector<std::string> codes;
    for (const Diagnostic& d : findings)
        codes.push_back(d.code + " " + d.element + " " + d.field);
    CHECK(codes == std::vector<std::string>{"GG607 Clamp retract", "GG606 Clamp extendMs", "GG606 Clamp retractMs",
                                            "GG608 Magazine conveyor"});
    CHECK(findings[1].message == "Clamp's extendMs is 0: a travel time is 1 to 3600000 ms");
    CHECK(findings[3].message == "Magazine feeds 'Clamp', which is no conveyor of the machine");
}

TEST_CASE("The model carries its machine", "[machine][model]")
{
    Model model = drillingCell();
    std::vector<ModelChange::Kind> changes;
    model.addObserver([&](const ModelChange& change) { changes.push_back(change.kind); });
    const std::uint64_t before = model.revision();
    REQUIRE(model.setMachine(Machine{{clamp()}}));
    CHECK(changes == std::vector<ModelChange::Kind>{ModelChange::Kind::Machine});
    CHECK(model.revision() == before + 1);
    REQUIRE(model.setMachine(Machine{{clamp()}})); // the same: no change
    CHECK(changes.size() == 1);

    // Undo is a setMachine of the previous description; copies and assign carry it.
    const Model copy(model);
    CHECK(copy.machine() == model.machine());
    CHECK(copy.sameContent(model));
    Model other = drillingCell();
    CHECK_FALSE(other.sameContent(model));
    other.assign(model);
    CHECK(other.machine() == model.machine());

    // A description with structural problems is refused, the model untouched.
    Machine twice{{clamp(), clamp()}};
    const Status refused = model.setMachine(twice);
    CHECK_FALSE(refused);
    CHECK(model.machine().components.size() == 1);
    CHECK(model.invariantViolations().empty());

    // Renaming a variable rewires the machine.
    REQUIRE(model.renameVariable("Clamped", "ClampExtended"));
    CHECK(model.machine().components[0].signal("extended") == "ClampExtended");
    CHECK(machineFindings(model).empty());

    // PackML models have none yet.
    Model packmlModel = packml::newModel();
    CHECK_FALSE(packmlModel.setMachine(Machine{{clamp()}}));
}

} // namespace test_machinechecks
