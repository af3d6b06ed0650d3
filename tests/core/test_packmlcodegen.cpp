// The generated code of PackML models (spec packml.md §6): the Capper of
// §6.6 against its golden file, and the parts of §6.2-§6.4 the Capper does
// not show.

#include "packmlcapper.h"

#include "core/codegen/stgenerator.h"
#include "core/templates/packml/packmlcodegen.h"
#include "core/templates/packml/packmlconfiguration.h"
#include "core/templates/packml/packmlmodel.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

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
