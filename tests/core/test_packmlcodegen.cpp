// The generated code of PackML models (spec packml.md §6): the Capper of
// §6.6 against its golden file, and the parts of §6.2-§6.4 the Capper does
// not show.

#include "packmlcapper.h"
#include "stinterpreter.h"

#include "core/codegen/plcopenwriter.h"
#include "core/codegen/stgenerator.h"
#include "core/formats/nativeformat.h"
#include "core/formats/plcopenreader.h"
#include "core/templates/packml/packmlcodegen.h"
#include "core/templates/packml/packmlconfiguration.h"
#include "core/templates/packml/packmlmodel.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <unistd.h>
#include <variant>

namespace test_packmlcodegen {

using namespace core;
using namespace core::packml;

namespace {

// tests/core/data/packml-capper.st; GGSTUDIO_UPDATE_GOLDEN=1 rewrites it,
// then read it against spec §6.3, §6.4, §6.6.
void checkGolden(const std::string& name, const std::string& actual)
{
    const std::string path = std::string(GGSTUDIO_TEST_DATA_DIR) + "/" + name;
    const char* update = std::getenv("GGSTUDIO_UPDATE_GOLDEN");
    if (update && std::string(update) == "1") {
        std::ofstream(path, std::ios::binary) << actual;
        WARN("rewrote " << path);
        return;
    }
    std::ifstream in(path, std::ios::binary);
    INFO("golden file " << path << " (GGSTUDIO_UPDATE_GOLDEN=1 writes it)");
    REQUIRE(in);
    std::stringstream expected;
    expected << in.rdbuf();
    CHECK(actual == expected.str());
}

} // namespace

TEST_CASE("PackML code: the Capper of spec 6.6 in the IEC dialect", "[packml-codegen]")
{
    const auto capper = packmltests::loadCapper();
    checkGolden("packml-capper.st", formatSingleFileIec(buildPlcProject(*capper, Dialect::Iec)));
}

namespace {

const PlcPou& programPou(const PlcProject& project)
{
    REQUIRE_FALSE(project.pous.empty());
    REQUIRE(project.pous.back().kind == PouKind::Program);
    return project.pous.back();
}

std::string programText(const Model& model, Dialect dialect = Dialect::Iec)
{
    return formatPou(programPou(buildPlcProject(model, dialect)), dialect);
}

std::vector<std::string> pouNames(const PlcProject& project)
{
    std::vector<std::string> names;
    for (const PlcPou& pou : project.pous)
        names.push_back(pou.name);
    return names;
}

// The lines between `first` (included) and the next line at its indent.
std::string branchOf(const std::string& text, const std::string& first)
{
    const std::size_t start = text.find(first);
    REQUIRE(start != std::string::npos);
    const std::size_t indent = first.find_first_not_of(' ');
    std::size_t end = start + first.size();
    for (;;) {
        end = text.find('\n', end);
        if (end == std::string::npos || end + 1 >= text.size())
            return text.substr(start);
        const std::size_t next = end + 1;
        const std::size_t nextIndent = text.find_first_not_of(' ', next) - next;
        if (nextIndent <= indent)
            return text.substr(start, next - start);
        end = next;
    }
}

void addOwnGrafcet(Model& model, int mode, State state, const std::string& action)
{
    REQUIRE(model.setGrafcetChoice(mode, state, GrafcetChoice::own()));
    GrafcetStep step;
    step.number = 1;
    step.initial = true;
    step.actions.push_back(GrafcetAction{ActionTiming::Continuous, action});
    REQUIRE(model.addGrafcetStep(grafcetKey(mode, state), step));
}

Variable output(const std::string& name)
{
    Variable variable;
    variable.name = name;
    variable.kind = VariableKind::Output;
    return variable;
}

} // namespace

TEST_CASE("PackML code: edition 2022, Execute leaves on the Complete command, not on its SC", "[packml-codegen]")
{
    const Model model = newModel(Edition::Y2022);
    const std::string text = programText(model);
    // Every state enabled; holdInSuspended is on by default in 2022.
    CHECK(branchOf(text, "    6: (* Execute *)\n")
          == "    6: (* Execute *)\n"
             "        IF Entry THEN IF NOT Resume THEN Production_Execute(Initialization := Entry); END_IF; Entry := FALSE; Resume := FALSE; END_IF;\n"
             "        Production_Execute(Initialization := Entry);\n"
             "        IF Ev_Abort THEN State := 8; Entry := TRUE;\n"
             "        ELSIF Ev_Stop THEN State := 7; Entry := TRUE;\n"
             "        ELSIF Ev_Hold THEN State := 10; Entry := TRUE; Resume := TRUE;\n"
             "        ELSIF Ev_Suspend THEN State := 13; Entry := TRUE; Resume := TRUE;\n"
             "        ELSIF Ev_Complete THEN State := 16; Entry := TRUE;\n"
             "        END_IF;\n");
    CHECK(branchOf(text, "    3: (* Starting *)\n").find(
              "ELSIF Production_Starting.Complete THEN State := 6; Entry := TRUE; Resume := FALSE; (* SC *)\n")
          != std::string::npos);
    CHECK(branchOf(text, "    5: (* Suspended *)\n").find("ELSIF Ev_Hold THEN State := 10; Entry := TRUE;\n")
          != std::string::npos);
    CHECK(text.find("Trig_Complete(CLK := Cmd_Complete);\n"
                    "Ev_Complete := Trig_Complete.Q OR (Trig_CmdChange.Q AND CntrlCmd = 10);\n")
          != std::string::npos);
    CHECK(text.find("    Ev_Complete : BOOL;\n") != std::string::npos);

    // No GRAFCET: every instance runs its state's skeleton, one each, in state order.
    const PlcProject project = buildPlcProject(model, Dialect::Iec);
    CHECK(pouNames(project)
          == std::vector<std::string>{"Clearing_FB", "Starting_FB", "Execute_FB", "Stopping_FB", "Aborting_FB",
                                      "Holding_FB", "Unholding_FB", "Suspending_FB", "Unsuspending_FB",
                                      "Resetting_FB", "Completing_FB", "PackML"});
    CHECK(formatPou(project.pous[1], Dialect::Iec)
          == "FUNCTION_BLOCK Starting_FB\n"
             "VAR_INPUT\n"
             "    Initialization : BOOL; (* TRUE in the first scan of the state *)\n"
             "END_VAR\n"
             "VAR_OUTPUT\n"
             "    Complete : BOOL; (* State Complete (SC) *)\n"
             "END_VAR\n"
             "IF Initialization THEN\n"
             "    Complete := FALSE;\n"
             "    (* initialization actions *)\n"
             "END_IF;\n"
             "(* The behaviour of Starting goes here; it sets Complete := TRUE when the state is complete (SC). *)\n"
             "(* Until it is written, the state completes at once: *)\n"
             "Complete := TRUE;\n"
             "END_FUNCTION_BLOCK\n");
}

TEST_CASE("PackML code: a user mode sharing Production's GRAFCET, its output driven by both instances",
          "[packml-codegen]")
{
    Model model = newModel();
    REQUIRE(model.addVariable(output("Pump")));
    Variable key;
    key.name = "KeyClean";
    REQUIRE(model.addVariable(key));
    REQUIRE(model.addMode(4, "Cleaning"));
    REQUIRE(model.setModeRequest(4, "KeyClean"));
    addOwnGrafcet(model, 1, State::Execute, "N Pump");
    REQUIRE(model.setGrafcetChoice(4, State::Execute, GrafcetChoice::sameAs(1)));
    const PlcProject project = buildPlcProject(model, Dialect::Iec);
    const std::vector<std::string> names = pouNames(project);
    // One function block for the shared GRAFCET, skeletons for the others.
    CHECK(std::count(names.begin(), names.end(), "Production_Execute_FB") == 1);
    CHECK(std::count(names.begin(), names.end(), "Cleaning_Execute_FB") == 0);
    CHECK(names.back() == "PackML");
    const std::string text = formatPou(programPou(project), Dialect::Iec);
    CHECK(text.find("    Cleaning_Execute : Production_Execute_FB;\n") != std::string::npos);
    CHECK(text.find("    Trig_Cleaning : R_TRIG;\n") != std::string::npos);
    CHECK(text.find("Trig_Cleaning(CLK := KeyClean);\n") != std::string::npos);
    CHECK(text.find("(* 4. Continuous outputs of the nested GRAFCETs: one writer each *)\n"
                    "Pump := (Mode = 1 AND State = 6 AND NOT Entry AND Production_Execute.Pump) OR "
                    "(Mode = 4 AND State = 6 AND NOT Entry AND Cleaning_Execute.Pump);\n")
          != std::string::npos);
    // Production may change to Maintenance, Manual and Cleaning in Stopped, Idle, Aborted.
    CHECK(branchOf(text, "1: (* Production *)\n    IF (")
          == "1: (* Production *)\n"
             "    IF (Trig_ModeChange.Q AND UnitMode = 2) AND (State = 2 OR State = 4 OR State = 9) THEN Mode := 2; Entry := TRUE; Resume := FALSE;\n"
             "    ELSIF (Trig_ModeChange.Q AND UnitMode = 3) AND (State = 2 OR State = 4 OR State = 9) THEN Mode := 3; Entry := TRUE; Resume := FALSE;\n"
             "    ELSIF ((Trig_ModeChange.Q AND UnitMode = 4) OR Trig_Cleaning.Q) AND (State = 2 OR State = 4 OR State = 9) THEN Mode := 4; Entry := TRUE; Resume := FALSE;\n"
             "    END_IF;\n");
    CHECK(text.find("4: (* Cleaning *)\n    CASE State OF\n") != std::string::npos);
}

TEST_CASE("PackML code: no mode change possible, and a mode change in one state only", "[packml-codegen]")
{
    Model model = newModel();
    for (int mode : {1, 2, 3})
        REQUIRE(model.setModeChangeStates(mode, StateSet{}));
    std::string text = programText(model);
    CHECK(text.find("(* 2. Unit mode manager *)\n"
                    "Trig_ModeChange(CLK := UnitModeChangeRequest);\n"
                    "(* no mode change is possible *)\n"
                    "(* 3. State machine of the current unit mode *)\n")
          != std::string::npos);

    REQUIRE(model.setModeChangeStates(1, StateSet{State::Idle}));
    REQUIRE(model.setModeChangeStates(3, StateSet{State::Idle, State::Stopped}));
    text = programText(model);
    CHECK(text.find("CASE Mode OF\n"
                    "1: (* Production *)\n"
                    "    IF (Trig_ModeChange.Q AND UnitMode = 3) AND State = 4 THEN Mode := 3; Entry := TRUE; Resume := FALSE;\n"
                    "    END_IF;\n"
                    "3: (* Manual *)\n"
                    "    IF (Trig_ModeChange.Q AND UnitMode = 1) AND State = 4 THEN Mode := 1; Entry := TRUE; Resume := FALSE;\n"
                    "    END_IF;\n"
                    "END_CASE;\n"
                    "(* 3. State machine")
          != std::string::npos);
}

TEST_CASE("PackML code: an unusable condition is FALSE with its error", "[packml-codegen]")
{
    Model model = newModel();
    REQUIRE(model.setCommandCondition(Command::Start, "Cmd_Start AND"));
    REQUIRE(model.setCommandCondition(Command::Hold, ""));
    const std::string text = programText(model);
    const std::size_t start = text.find("Trig_Start(CLK := FALSE);\n");
    REQUIRE(start != std::string::npos);
    const std::size_t error = text.rfind("(* ERROR GG201: syntax error in the condition of the Start command", start);
    REQUIRE(error != std::string::npos);
    CHECK(text.find('\n', error) + 1 == start);
    CHECK(text.find("(* ERROR GG202: the condition of the Hold command is empty: write FALSE for a command that comes "
                    "only through CntrlCmd *)\nTrig_Hold(CLK := FALSE);\n")
          != std::string::npos);
}

TEST_CASE("PackML code: section 6 keeps the edge memories the nested receptivities read", "[packml-codegen]")
{
    Model model = newModel();
    REQUIRE(model.addVariable(output("Pump")));
    addOwnGrafcet(model, 1, State::Starting, "N Pump");
    const std::string key = grafcetKey(1, State::Starting);
    GrafcetStep done;
    done.number = 2;
    done.actions.push_back(GrafcetAction{ActionTiming::OnActivation, "S Complete"});
    REQUIRE(model.addGrafcetStep(key, done));
    REQUIRE(model.addGrafcetTransition(key, GrafcetTransition{1, {1}, {2}, "RE Cmd_Start"}));
    const PlcProject project = buildPlcProject(model, Dialect::Iec);
    const std::string text = formatPou(programPou(project), Dialect::Iec);
    CHECK(text.find("UnitModeCurrent := Mode;\n"
                    "(* 6. Edge memories of the nested receptivities *)\n"
                    "Cmd_Start_PREV := Cmd_Start;\n"
                    "END_PROGRAM\n")
          != std::string::npos);
    CHECK(text.find("    UnitModeCurrent : DINT;\n    Cmd_Start_PREV : BOOL;\nEND_VAR\n") != std::string::npos);
    const std::string globals = formatGlobals(project);
    CHECK(globals.find("    UnitModeCurrent : DINT := 1;\n    Cmd_Start_PREV : BOOL := FALSE;\nEND_VAR\n")
          != std::string::npos);
    const std::string fb = formatPou(project.pous[project.pous.size() - 2], Dialect::Iec);
    CHECK(fb.find("FUNCTION_BLOCK Production_Starting_FB\n") != std::string::npos);
    CHECK(fb.find("GG_Fire1 := X1 AND (Cmd_Start AND NOT Cmd_Start_PREV);") != std::string::npos);
}

TEST_CASE("PackML code: the CODESYS dialect reads every global in GVL", "[packml-codegen]")
{
    const auto capper = packmltests::loadCapper();
    const PlcProject project = buildPlcProject(*capper, Dialect::Codesys);
    CHECK(project.globalListName == "GVL");
    const std::string program = formatPou(programPou(project), Dialect::Codesys);
    CHECK(program.find("VAR_EXTERNAL") == std::string::npos);
    for (const char* line : {"Trig_CmdChange(CLK := GVL.CmdChangeRequest);\n",
                             "Trig_Abort(CLK := (GVL.Cmd_Abort OR NOT GVL.EStopOK));\n",
                             "Ev_Abort := Trig_Abort.Q OR (Trig_CmdChange.Q AND GVL.CntrlCmd = 8);\n",
                             "Trig_ModeChange(CLK := GVL.UnitModeChangeRequest);\n",
                             "Trig_Production(CLK := NOT GVL.KeyManual);\n",
                             "    IF ((Trig_ModeChange.Q AND GVL.UnitMode = 3) OR Trig_Manual.Q) AND (State = 2 OR State = 4 OR State = 9) THEN",
                             "GVL.Cap := (Mode = 1 AND State = 6 AND NOT Entry AND Production_Execute.Cap);\n",
                             "GVL.StateCurrent := State;\nGVL.UnitModeCurrent := Mode;\n",
                             "    Trig_Reset : R_TRIG;\n"})
        CHECK(program.find(line) != std::string::npos);
    const PlcPou& execute = project.pous[1];
    REQUIRE(execute.name == "Production_Execute_FB");
    CHECK(execute.externals.empty());
    CHECK(execute.body.find("GG_Fire1 := X1 AND GVL.Capped;") != std::string::npos);
    const std::string globals = formatGlobals(project);
    CHECK(globals.rfind("{attribute 'qualified_only'}\nVAR_GLOBAL\n    Cmd_Reset : BOOL := FALSE;\n", 0) == 0);
    CHECK(globals.find("    StateCurrent : DINT := 2;\n    UnitModeCurrent : DINT := 1;\nEND_VAR\n") != std::string::npos);
    // The configuration runs the PROGRAM under PackML's names; CODESYS keeps the globals in the GVL.
    CHECK(formatConfiguration(project)
          == "CONFIGURATION PackMLConfiguration\n"
             "    RESOURCE PackMLResource ON PLC\n"
             "        TASK MainTask(INTERVAL := T#20ms, PRIORITY := 1);\n"
             "        PROGRAM PackMLInstance WITH MainTask : Capper;\n"
             "    END_RESOURCE\n"
             "END_CONFIGURATION\n");
}

namespace {

// xmllint against the TC6 v2.01 schema, as tests/core/test_plcopen.cpp does
// (CODESYS files after the namespace swap: their structure is the same).
bool validatesAgainstSchema(std::string text, const std::string& fileName)
{
    const std::string from(kPlcOpenNamespace200);
    if (const std::size_t at = text.find(from); at != std::string::npos)
        text.replace(at, from.size(), std::string(kPlcOpenNamespace201));
    const auto folder = std::filesystem::temp_directory_path() / ("ggstudio-packml-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    const auto file = folder / fileName;
    std::ofstream(file, std::ios::binary) << text;
    const std::string command = "xmllint --noout --nonet --schema '" GGSTUDIO_REFERENCE_DIR
                                "/plcopen/tc6_xml_v201.xsd' '" + file.string() + "' 2>'" + file.string() + ".log'";
    const int status = std::system(command.c_str());
    if (status != 0) {
        std::ifstream log(file.string() + ".log");
        for (std::string line; std::getline(log, line);)
            UNSCOPED_INFO(line);
    }
    std::filesystem::remove_all(folder);
    return status == 0;
}

PlcOpenOptions fixedClock()
{
    PlcOpenOptions options;
    options.now = [] { return std::string("2026-12-06T10:00:00"); };
    return options;
}

} // namespace

TEST_CASE("PackML code: PLCopen XML of the Capper validates, carries the 3.0 model and opens again", "[packml-codegen]")
{
    const auto capper = packmltests::loadCapper();
    for (const Dialect dialect : {Dialect::Iec, Dialect::Codesys}) {
        const PlcProject project = buildPlcProject(*capper, dialect);
        const std::string xml = writePlcOpenXml(project, *capper, fixedClock());
        INFO(dialectName(dialect));
        CHECK(validatesAgainstSchema(xml, "capper.xml"));
        CHECK(xml.find("<pou name=\"Execute_FB\" pouType=\"functionBlock\">") != std::string::npos);
        CHECK(xml.find("<pou name=\"Capper\" pouType=\"program\">") != std::string::npos);
        CHECK(xml.find("<derived name=\"R_TRIG\"/>") != std::string::npos);
        CHECK(xml.find("<configuration name=\"PackMLConfiguration\">") != std::string::npos);
        CHECK(xml.find(saveNativeJson(*capper)) != std::string::npos);
        CHECK(xml.find("\"version\": \"3.0\"") != std::string::npos);

        std::vector<LoadWarning> warnings;
        auto loaded = readPlcOpenModel(xml, "capper.xml", &warnings);
        REQUIRE(std::holds_alternative<std::unique_ptr<Model>>(loaded));
        CHECK(std::get<std::unique_ptr<Model>>(loaded)->sameContent(*capper));
        CHECK(warnings.empty()); // the code in the file is the code of its model
    }
}

TEST_CASE("PackML code: a PLCopen file whose code was changed opens with a warning", "[packml-codegen]")
{
    const auto capper = packmltests::loadCapper();
    std::string xml = writePlcOpenXml(buildPlcProject(*capper, Dialect::Iec), *capper, fixedClock());
    const std::string edited = "Ev_Hold := Trig_Hold.Q OR (Trig_CmdChange.Q AND CntrlCmd = 4);";
    const std::size_t at = xml.find(edited);
    REQUIRE(at != std::string::npos);
    xml.replace(at, edited.size(), "Ev_Hold := FALSE;");
    std::vector<LoadWarning> warnings;
    auto loaded = readPlcOpenModel(xml, "capper.xml", &warnings);
    REQUIRE(std::holds_alternative<std::unique_ptr<Model>>(loaded));
    CHECK_FALSE(warnings.empty());
}

TEST_CASE("PackML code: a variable named as the code's own names is declared under another name", "[packml-codegen]")
{
    Model model = newModel();
    Variable clash;
    clash.name = "Entry";
    REQUIRE(model.addVariable(clash));
    REQUIRE(model.setCommandCondition(Command::Start, "Entry"));
    const PlcProject project = buildPlcProject(model, Dialect::Iec);
    const std::string position = std::to_string(model.variables().size());
    const std::string globals = formatGlobals(project);
    CHECK(globals.find("    Invalid_Name_" + position + " : BOOL := FALSE; (* ERROR: 'Entry' cannot be declared as it "
                       "is named; every condition that reads it is FALSE *)\n")
          != std::string::npos);
    const std::string text = formatPou(programPou(project), Dialect::Iec);
    CHECK(text.find("Trig_Start(CLK := FALSE);\n") != std::string::npos);
    CHECK(text.find("Invalid_Name_") == std::string::npos); // nothing reads it
}

TEST_CASE("PackML code: the Capper's generated IEC code runs the trace of spec 6.6", "[packml-codegen]")
{
    // The code as a PLC runs it, by the tests' ST interpreter (no IEC compiler in the suite).
    const auto capper = packmltests::loadCapper();
    const PlcProject project = buildPlcProject(*capper, Dialect::Iec);
    std::vector<std::string> functionBlocks;
    for (const PlcPou& pou : project.pous)
        if (pou.kind == PouKind::FunctionBlock)
            functionBlocks.push_back(formatPou(pou, Dialect::Iec));
    sttest::StInterpreter plc(formatPou(programPou(project), Dialect::Iec), formatGlobals(project), functionBlocks);
    REQUIRE(plc.error().empty());

    using Inputs = std::vector<std::pair<std::string, cond::Value>>;
    const std::map<int, Inputs> scenario{
        {1, {{"Cmd_Reset", true}}},
        {2, {{"Cmd_Reset", false}}},
        {4, {{"Homed", true}}},
        {5, {{"Cmd_Start", true}}},
        {6, {{"Cmd_Start", false}}},
        {7, {{"KeyManual", true}, {"Capped", true}}},
        {8, {{"Cmd_Hold", true}}},
        {9, {{"Cmd_Hold", false}, {"Capped", false}}},
        {10, {{"Cmd_Unhold", true}}},
        {11, {{"Cmd_Unhold", false}}},
        {12, {{"Cmd_Stop", true}}},
        {13, {{"Cmd_Stop", false}, {"KeyManual", false}}},
        {14, {{"KeyManual", true}, {"Cmd_Reset", true}}},
        {15, {{"EStopOK", false}}},
        {16, {{"EStopOK", true}, {"Cmd_Reset", false}}},
        {17, {{"CntrlCmd", std::int64_t{9}}, {"CmdChangeRequest", true}}},
        {18, {{"UnitMode", std::int64_t{1}}, {"UnitModeChangeRequest", true}}},
    };
    // Scan 0 is the start; then State, UnitModeCurrent, HomeAxis Cap Eject at the end of each scan.
    const std::vector<std::string> expected{
        "2 1 000", "15 1 000", "15 1 100", "15 1 100", "4 1 000", "6 1 000", "6 1 010", "6 1 001", "11 1 000", "11 1 000",
        "6 1 000", "6 1 001", "2 1 000",   "2 1 000",  "4 3 000", "9 3 000", "9 3 000", "2 3 000", "2 1 000"};
    auto bit = [&plc](const char* name) { return cond::isTrue(plc.value(name)) ? "1" : "0"; };
    std::vector<std::string> trace;
    for (int scan = 0; scan < static_cast<int>(expected.size()); ++scan) {
        if (scan > 0) {
            if (const auto inputs = scenario.find(scan); inputs != scenario.end())
                for (const auto& [name, value] : inputs->second)
                    plc.setInput(name, value);
            plc.scan();
        }
        trace.push_back(std::to_string(std::get<std::int64_t>(plc.value("StateCurrent"))) + " "
                        + std::to_string(std::get<std::int64_t>(plc.value("UnitModeCurrent"))) + " " + bit("HomeAxis")
                        + bit("Cap") + bit("Eject"));
    }
    CHECK(trace == expected);
    CHECK(plc.runtimeError().empty());
}

} // namespace test_packmlcodegen
