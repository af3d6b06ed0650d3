// The native file's "machine" key (core/formats/nativemachinejson.h) and its
// way through PLCopen, where the native model is embedded.

#include "filetestsupport.h"
#include "nativeloadchecks.h"

#include "core/codegen/plcopenwriter.h"
#include "core/codegen/stgenerator.h"
#include "core/formats/nativeformat.h"
#include "core/formats/plcopenreader.h"
#include "core/model/model.h"

#include <catch2/catch.hpp>

#include <string>

namespace test_machinefile {

using namespace core;
using namespace core::machine;
using filetests::loadError;
using filetests::loadOk;

namespace {

Model modelWithMachine()
{
    Model model;
    REQUIRE(model.addVariable(Variable{"Out", IecType::Bool, "", "", VariableKind::Output}));
    REQUIRE(model.addVariable(Variable{"AtEnd", IecType::Bool, "", "", VariableKind::Input}));
    REQUIRE(model.addVariable(Variable{"EStopOk", IecType::Bool, "TRUE", "", VariableKind::Input}));
    Component single = makeComponent(ComponentKind::SingleActingCylinder, "Pusher");
    single.setSignal("extend", "Out");
    single.setSignal("extended", "AtEnd");
    single.setParameter("extendMs", 250);
    single.setParameter("retractMs", 400);
    Component stop = makeComponent(ComponentKind::EmergencyStop, "EStop");
    stop.setSignal("input", "EStopOk");
    Component belt = makeComponent(ComponentKind::Conveyor, "Belt");
    belt.setSignal("run", "Out");
    Component source = makeComponent(ComponentKind::PartSource, "Magazine");
    source.conveyor = "Belt";
    source.setParameter("parts", 12);
    Component unlimited = makeComponent(ComponentKind::PartSource, "Hopper");
    unlimited.conveyor = "Belt";
    REQUIRE(model.setMachine(Machine{{single, stop, belt, source, unlimited}}));
    return model;
}

// A 2.0 file with this "machine" value.
std::string fileWithMachine(const std::string& machine)
{
    return "{\"format\": \"ggstudio-model\", \"version\": \"2.0\", \"variables\": [], \"machine\": " + machine + "}";
}

std::string componentError(const std::string& component)
{
    return loadError(fileWithMachine("{\"components\": [" + component + "]}")).toStringWithoutAdvice();
}

} // namespace

TEST_CASE("The machine is saved under \"machine\" and read back", "[machine][files]")
{
    const Model model = modelWithMachine();
    const std::string text = saveNativeJson(model);
    CHECK(text.find("\"version\": \"2.0\"") != std::string::npos);
    CHECK(text.find("      {\n        \"name\": \"Pusher\",\n        \"kind\": \"single-acting-cylinder\",\n"
                    "        \"extend\": \"Out\",\n        \"extended\": \"AtEnd\",\n        \"extendMs\": 250,\n"
                    "        \"retractMs\": 400\n      },")
          != std::string::npos);
    CHECK(text.find("\"contact\": \"normally-closed\"") != std::string::npos);
    CHECK(text.find("\"parts\": 12") != std::string::npos);
    CHECK(text.find("\"parts\": -1") == std::string::npos); // unlimited: no key
    const auto loaded = loadOk(text);
    CHECK(loaded->machine() == model.machine());
    CHECK(loaded->sameContent(model));
    CHECK(saveNativeJson(*loaded) == text);
}

TEST_CASE("A model without machine saves as before", "[machine][files]")
{
    Model model;
    const std::string text = saveNativeJson(model);
    CHECK(text.find("machine") == std::string::npos);
    CHECK(text.find("\"version\": \"1.0\"") != std::string::npos); // no 2.0 key needed
    CHECK(loadOk(text)->machine().empty());
}

TEST_CASE("The shipped drilling cell and its machine are written back byte for byte", "[machine][files][example]")
{
    const std::string text = filetests::readBinaryFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    const auto loaded = loadOk(text);
    REQUIRE(loaded->machine().components.size() == 9);
    CHECK(loaded->machine().components[3].conveyor == "Infeed");
    CHECK(saveNativeJson(*loaded) == text);
}

TEST_CASE("The machine survives the PLCopen round trip", "[machine][files][plcopen]")
{
    const Model model = modelWithMachine();
    const std::string xml = writePlcOpenXml(buildPlcProject(model, Dialect::Iec), model);
    auto loaded = readPlcOpenModel(xml, "machine.xml");
    REQUIRE(std::holds_alternative<std::unique_ptr<Model>>(loaded));
    const Model& back = *std::get<std::unique_ptr<Model>>(loaded);
    CHECK(back.machine() == model.machine());
    CHECK(back.sameContent(model));
}

TEST_CASE("The machine reader is strict and says where", "[machine][files]")
{
    CHECK(loadError("{\"format\": \"ggstudio-model\", \"version\": \"1.0\", \"machine\": {}}").location == "/machine");
    CHECK(loadError(fileWithMachine("[]")).toStringWithoutAdvice().find("/machine: expected an object")
          != std::string::npos);
    CHECK(loadError(fileWithMachine("{\"parts\": 1}")).toStringWithoutAdvice().find(
              "/machine/parts: unknown key \"parts\" in the machine; it knows \"components\"")
          != std::string::npos);
    CHECK(componentError("{\"name\": \"A\"}").find("/machine/components/0/kind: missing; a component needs its kind, "
                                                   "one of \"double-acting-cylinder\"")
          != std::string::npos);
    CHECK(componentError("{\"name\": \"A\", \"kind\": \"robot\"}").find(
              "/machine/components/0/kind: unknown component kind \"robot\"")
          != std::string::npos);
    CHECK(componentError("{\"name\": \"L\", \"kind\": \"lamp\", \"extend\": \"X\"}").find(
              "/machine/components/0/extend: unknown key \"extend\" in a lamp; it knows \"name\", \"kind\" and "
              "\"lamp\"")
          != std::string::npos);
    CHECK(componentError("{\"kind\": \"lamp\"}").find("/machine/components/0/name: missing") != std::string::npos);
    CHECK(componentError("{\"name\": \"\", \"kind\": \"lamp\"}").find("/machine/components/0/name: empty")
          != std::string::npos);
    CHECK(componentError("{\"name\": \"C\", \"kind\": \"conveyor\", \"travelMs\": -1}").find(
              "/machine/components/0/travelMs:")
          != std::string::npos);
    CHECK(componentError("{\"name\": \"C\", \"kind\": \"conveyor\", \"run\": 3}").find(
              "/machine/components/0/run: expected a string")
          != std::string::npos);
    CHECK(componentError("{\"name\": \"B\", \"kind\": \"push-button\", \"contact\": \"open\"}").find(
              "/machine/components/0/contact: unknown contact \"open\"")
          != std::string::npos);
    CHECK(componentError("{\"name\": \"L\", \"kind\": \"lamp\"}, {\"name\": \"l\", \"kind\": \"lamp\"}").find(
              "/machine/components/1/name: a second component named \"l\"")
          != std::string::npos);
    // A zero travel time reads: the checks name it (GG606).
    const auto zero = loadOk(fileWithMachine("{\"components\": [{\"name\": \"C\", \"kind\": \"conveyor\", "
                                             "\"travelMs\": 0}]}"));
    CHECK(zero->machine().components[0].parameter("travelMs") == 0);
}

} // namespace test_machinefile
