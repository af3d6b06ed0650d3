#include <catch2/catch.hpp>

#include "core/checks/checks.h"
#include "core/checks/diagnostic.h"
#include "core/templates/gemma/gemmaprogram.h"
#include "core/model/model.h"
#include "core/codegen/stgenerator.h"
#include "core/templates/gemma/gemmacodegen.h"
#include "core/formats/modelfiles.h"
#include "hostilemodels.h"
#include "modelfactory.h"
#include "samplemodels.h"
#include "stinterpreter.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace test_stgenerator {

using namespace core;

// Golden files live in tests/core/data/golden. Run the tests with
// GGSTUDIO_UPDATE_GOLDEN=1 to rewrite them, then read each against spec §6.

namespace {

std::string goldenPath(const std::string& name)
{
    return std::string(GGSTUDIO_TEST_DATA_DIR) + "/golden/" + name;
}

bool updatingGoldens()
{
    const char* value = std::getenv("GGSTUDIO_UPDATE_GOLDEN");
    return value != nullptr && std::string(value) == "1";
}

std::vector<std::string> splitLines(const std::string& text)
{
    std::vector<std::string> lines;
    std::string line;
    std::istringstream in(text);
    while (std::getline(in, line))
        lines.push_back(line);
    return lines;
}

void checkGolden(const std::string& name, const std::string& actual)
{
    const std::string path = goldenPath(name);
    if (updatingGoldens()) {
        std::ofstream out(path, std::ios::binary);
        REQUIRE(out);
        out << actual;
        WARN("rewrote " << path);
        return;
    }
    std::ifstream in(path, std::ios::binary);
    INFO("golden file " << path << " (GGSTUDIO_UPDATE_GOLDEN=1 writes it)");
    REQUIRE(in);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string expected = buffer.str();
    if (actual == expected)
        return;
    const std::vector<std::string> a = splitLines(actual);
    const std::vector<std::string> e = splitLines(expected);
    std::size_t line = 0;
    while (line < a.size() && line < e.size() && a[line] == e[line])
        ++line;
    INFO("first difference at line " << line + 1 << "\n  expected: "
                                     << (line < e.size() ? e[line] : "<end>") << "\n  actual:   "
                                     << (line < a.size() ? a[line] : "<end>"));
    CHECK(actual == expected);
}

void addBools(Model& model, std::initializer_list<const char*> names)
{
    for (const char* name : names)
        REQUIRE(model.addVariable({name, IecType::Bool, "", ""}));
}

// The template with only the given steps visible, the first one initial.
Model focusedModel(std::initializer_list<const char*> visible)
{
    Model model;
    REQUIRE(model.setInitialStep(*visible.begin()));
    for (const Step& step : model.steps()) {
        const bool keep = std::any_of(visible.begin(), visible.end(), [&](const char* id) { return step.id == id; });
        REQUIRE(model.setStepHidden(step.id, !keep));
    }
    return model;
}

void set(Model& model, const char* transition, const char* condition)
{
    REQUIRE(model.setCondition(transition, condition));
}

std::string gemmaText(const Model& model, Dialect dialect = Dialect::Iec)
{
    const PlcProject project = buildPlcProject(model, dialect);
    REQUIRE(!project.pous.empty());
    return formatPou(project.pous.front(), dialect);
}

std::string fullText(const Model& model, Dialect dialect)
{
    const PlcProject project = buildPlcProject(model, dialect);
    if (dialect == Dialect::Iec)
        return formatSingleFileIec(project);
    std::string text = "(* ---- " + project.globalListName + " ---- *)\n" + formatGlobals(project);
    for (const PlcPou& pou : project.pous)
        text += "\n(* ---- " + pou.name + " ---- *)\n" + formatPou(pou, dialect);
    return text;
}

bool hasLine(const std::string& text, const std::string& line)
{
    const std::vector<std::string> lines = splitLines(text);
    return std::find(lines.begin(), lines.end(), line) != lines.end();
}

// ---- the models of the golden files ----------------------------------------

// A1 (simple) with two effective transitions out of four (F4, F5 hidden);
// F2 simple leading to F1; F1 simple with no outgoing transition.
Model simpleBranchModel()
{
    Model model = focusedModel({"A1", "F1", "F2"});
    addBools(model, {"Start", "Auto"});
    REQUIRE(model.setStepType("F1", StepType::Simple));
    REQUIRE(model.setStepType("F2", StepType::Simple));
    set(model, "A1->F2", "Start AND NOT Auto");
    set(model, "A1->F1", "start and auto"); // keywords and names in any case
    set(model, "F2->F1", "Auto");
    return model;
}

// F1 macro: transitions wait for Complete; an OR condition is parenthesised,
// an AND one is not.
Model macroBranchModel()
{
    Model model = focusedModel({"F1", "A2", "F3", "A3"});
    addBools(model, {"Stop", "Fault", "EndOfSeries"});
    for (const char* id : {"A2", "F3", "A3"})
        REQUIRE(model.setStepType(id, StepType::Simple));
    set(model, "F1->A2", "Stop OR Fault");
    set(model, "F1->F3", "EndOfSeries AND Stop");
    set(model, "F1->A3", "NOT Fault");
    return model;
}

// F4 enclosing: transitions fire whatever the nested behaviour does.
Model enclosingBranchModel()
{
    Model model = focusedModel({"F4", "A6"});
    addBools(model, {"Verified", "Abort"});
    set(model, "F4->A6", "Verified OR Abort");
    return model;
}

// A negated transition out of a macro-step ignores Complete.
Model negatedMacroModel()
{
    Model model = focusedModel({"F1", "A2", "A3"});
    addBools(model, {"Stop", "Fault"});
    set(model, "F1->A2", "Stop");
    REQUIRE(model.setNegated("F1->A2", true));
    set(model, "F1->A3", "Fault");
    return model;
}

// A negated transition out of an enclosing step waits for Complete.
Model negatedEnclosingModel()
{
    Model model = focusedModel({"D3", "A2", "A3"});
    addBools(model, {"Repaired", "Bypass", "Fault"});
    set(model, "D3->A2", "Repaired XOR Bypass");
    REQUIRE(model.setNegated("D3->A2", true));
    set(model, "D3->A3", "Fault");
    return model;
}

// F->D1 is evaluated first by every visible F state and never waits.
Model familyModel()
{
    Model model = focusedModel({"F2", "F1", "D1"});
    addBools(model, {"EStop", "Ready", "Reset"});
    set(model, "F->D1", "EStop");
    REQUIRE(model.setTransitionHidden("F1->D1", true));
    set(model, "F2->F1", "Ready");
    set(model, "D1->D2", "Reset"); // D2 hidden: not effective
    return model;
}

// The spec's example (F1 -> A2, NOT Stop, token on Stop, priority 3: normally
// closed) and a normally open token on D3 -> A2.
Model tokensModel()
{
    Model model = focusedModel({"F1", "D1", "D3", "A2"});
    addBools(model, {"EStop", "Fault", "Stop", "Ack", "Repaired"});
    REQUIRE(model.setTransitionHidden("F->D1", true));
    set(model, "F1->D1", "EStop");
    set(model, "F1->D3", "Fault");
    set(model, "F1->A2", "NOT Stop");
    REQUIRE(model.setTokens("F1->A2", {"Stop"}));
    set(model, "D3->A2", "Ack AND Repaired");
    REQUIRE(model.setTokens("D3->A2", {"Ack"}));
    REQUIRE(model.setNegated("D3->A2", true));
    return model;
}

// The template with conditions, some steps and transitions hidden: hidden
// steps get no branch and no FB, hidden transitions no ELSIF, and the
// effective priorities close up.
Model hiddenModel()
{
    Model model;
    // One variable per transition, named after it: T_A1_F4 for A1->F4.
    for (const Transition& transition : model.transitions()) {
        const std::string name = "T_" + transition.source + "_" + transition.target;
        REQUIRE(model.addVariable({name, IecType::Bool, "", ""}));
        set(model, transition.id.c_str(), name.c_str());
    }
    for (const char* id : {"A3", "A7", "F3", "F5", "F6", "D2", "D3"})
        REQUIRE(model.setStepHidden(id, true));
    for (const char* id : {"A1->F2", "F1->A2", "F->D1"})
        REQUIRE(model.setTransitionHidden(id, true));
    return model;
}

// Every kind of problem the generator turns into a comment.
Model errorsModel()
{
    Model model = focusedModel({"F1", "A2", "A3", "F4", "F5", "F3", "D2"});
    addBools(model, {"Stop"});
    REQUIRE(model.addVariable({"Count", IecType::Int, "", "pieces *) in the batch (* so far"}));
    REQUIRE(model.addVariable({"Speed", IecType::Real, "12", ""}));
    REQUIRE(model.addVariable({"Limit", IecType::Sint, "300", "upper limit"}));
    REQUIRE(model.addVariable({"Enabled", IecType::Bool, "true", ""}));
    set(model, "F1->A2", "");                   // empty
    set(model, "F1->F4", "Stop AND (");         // syntax
    set(model, "F1->F5", "Stopp");              // undeclared
    set(model, "F1->F3", "Count + 1");          // not BOOL
    set(model, "F1->A3", "Stop AND Count > 3"); // fine, but the token is on a non-BOOL
    REQUIRE(model.setTokens("F1->A3", {"Count", "Enabled"}));
    set(model, "F5->F4", "TRUE");
    set(model, "F5->F1", "Stop");
    set(model, "F1->D2", "Stop OR NOT Stop AND Enabled AND Speed > Limit");
    REQUIRE(model.setTokens("F1->D2", {"Stop"})); // both polarities
    REQUIRE(model.setStepComment("F1", "fills *) bottles (* and caps them\nline two"));
    return model;
}

} // namespace

// ---- golden files -------------------------------------------------------------

TEST_CASE("the template with its defaults, IEC single file", "[stgen]")
{
    checkGolden("template_iec.st", fullText(Model(), Dialect::Iec));
}

TEST_CASE("the template with its defaults, CODESYS", "[stgen]")
{
    checkGolden("template_codesys.st", fullText(Model(), Dialect::Codesys));
}

TEST_CASE("branch of a simple step", "[stgen]")
{
    const std::string text = gemmaText(simpleBranchModel());
    checkGolden("branch_simple.st", text);
    CHECK(hasLine(text, "1: (* A1 Stop in initial state *)"));
    CHECK(hasLine(text, "    IF Start AND NOT Auto THEN"));
    CHECK(hasLine(text, "    ELSIF Start AND Auto THEN"));
    CHECK(hasLine(text, "    (* F1 has no outgoing transition *)"));
    CHECK(hasLine(text, "    State := 8;"));
}

TEST_CASE("branch of a macro-step", "[stgen]")
{
    const std::string text = gemmaText(macroBranchModel());
    checkGolden("branch_macro.st", text);
    CHECK(hasLine(text, "    IF (Stop OR Fault) AND F1.Complete THEN"));
    CHECK(hasLine(text, "    ELSIF EndOfSeries AND Stop AND F1.Complete THEN"));
    CHECK(hasLine(text, "    ELSIF NOT Fault AND F1.Complete THEN"));
}

TEST_CASE("branch of an enclosing step", "[stgen]")
{
    const std::string text = gemmaText(enclosingBranchModel());
    checkGolden("branch_enclosing.st", text);
    CHECK(hasLine(text, "    IF Verified OR Abort THEN"));
}

TEST_CASE("negated transition out of a macro-step ignores Complete", "[stgen]")
{
    const std::string text = gemmaText(negatedMacroModel());
    checkGolden("branch_negated_macro.st", text);
    CHECK(hasLine(text, "    IF Stop THEN"));
    CHECK(hasLine(text, "    ELSIF Fault AND F1.Complete THEN"));
}

TEST_CASE("negated transition out of an enclosing step waits for Complete", "[stgen]")
{
    const std::string text = gemmaText(negatedEnclosingModel());
    checkGolden("branch_negated_enclosing.st", text);
    CHECK(hasLine(text, "    IF (Repaired XOR Bypass) AND D3.Complete THEN"));
    CHECK(hasLine(text, "    ELSIF Fault THEN"));
}

TEST_CASE("family transition first in every visible F state", "[stgen]")
{
    const std::string text = gemmaText(familyModel());
    checkGolden("branch_family.st", text);
    const std::vector<std::string> lines = splitLines(text);
    CHECK(std::count(lines.begin(), lines.end(), "    IF EStop THEN") == 2);
    CHECK(text.find("EStop AND") == std::string::npos); // family transitions never wait
}

TEST_CASE("tokens normally open and normally closed, IEC and CODESYS", "[stgen]")
{
    const Model model = tokensModel();
    const std::string iec = gemmaText(model, Dialect::Iec);
    const std::string codesys = gemmaText(model, Dialect::Codesys);
    checkGolden("tokens_iec.st", iec);
    checkGolden("tokens_codesys.st", codesys);

    // The spec's example, character for character.
    CHECK(hasLine(iec, "    ELSIF Stop_F1_3_MEM AND F1.Complete THEN"));
    CHECK(hasLine(codesys, "    ELSIF Stop_F1_3_MEM AND F1.Complete THEN"));
    CHECK(hasLine(iec, "IF State = 8 AND NOT Stop THEN Stop_F1_3_MEM := TRUE; END_IF;"));
    CHECK(hasLine(codesys, "IF State = 8 AND NOT GVL.Stop THEN Stop_F1_3_MEM := TRUE; END_IF;"));
    CHECK(hasLine(iec, "    IF Ack_D3_1_MEM AND Repaired AND D3.Complete THEN"));
    CHECK(hasLine(iec, "IF State = 16 AND Ack THEN Ack_D3_1_MEM := TRUE; END_IF;"));
    CHECK(hasLine(iec, "        Stop_F1_3_MEM := FALSE;"));
    CHECK(hasLine(iec, "        Ack_D3_1_MEM := FALSE;"));
    CHECK(iec.find("    Stop_F1_3_MEM : BOOL := FALSE;") != std::string::npos);
}

TEST_CASE("hidden steps and hidden transitions generate nothing", "[stgen]")
{
    const Model model = hiddenModel();
    const std::string text = fullText(model, Dialect::Iec);
    checkGolden("hidden_iec.st", text);
    for (const char* id : {"A3", "A7", "F3", "F5", "F6", "D2", "D3"}) {
        INFO(id);
        CHECK(text.find(std::string("(* ") + id + " ") == std::string::npos);
        CHECK(text.find(std::string(id) + "_FB") == std::string::npos);
    }
    CHECK(text.find("State := 9;") == std::string::npos);  // A1 -> F2 hidden
    CHECK(text.find("State := 14;") != std::string::npos); // F1 -> D1 still there
}

TEST_CASE("models with errors still generate code, with comments at each problem", "[stgen]")
{
    const Model model = errorsModel();
    const std::string text = fullText(model, Dialect::Iec);
    checkGolden("errors_iec.st", text);
    CHECK(text.find("(* ERROR GG202: the condition of F1->A2 is empty") != std::string::npos);
    CHECK(text.find("(* ERROR GG201: syntax error in the condition of F1->F4") != std::string::npos);
    CHECK(text.find("(* WARNING GG207: the token on 'Count' in F1->A3 is not generated") != std::string::npos);
    CHECK(text.find("(* WARNING GG208: the token on 'Enabled' in F1->A3 is not generated") != std::string::npos);
    CHECK(text.find("(* WARNING GG209: the token on 'Stop' in F1->D2 is not generated") != std::string::npos);
    CHECK(text.find("_MEM") == std::string::npos);
    // Unusable conditions become FALSE; usable ones are kept.
    const std::vector<std::string> lines = splitLines(text);
    CHECK(std::count(lines.begin(), lines.end(), "    ELSIF FALSE THEN") + std::count(lines.begin(), lines.end(), "    IF FALSE THEN") == 4);
    CHECK(hasLine(text, "    ELSIF Stop AND Count > 3 AND F1.Complete THEN"));
    CHECK(hasLine(text, "    ELSIF (Stop OR NOT Stop AND Enabled AND Speed > Limit) AND F1.Complete THEN"));
    // Defaults: normalised, or the implicit one when invalid.
    CHECK(text.find("Speed : REAL := 12.0;") != std::string::npos);
    CHECK(text.find("Limit : SINT := 0; (* ERROR: default ") != std::string::npos);
    CHECK(text.find("Enabled : BOOL := TRUE;") != std::string::npos);
}

// ---- the rules IEC compilers enforce ------------------------------------------

namespace {

// The text with every (* *) comment replaced by a space; fails the test when
// a comment is not closed or another one opens inside it.
std::string withoutComments(const std::string& text)
{
    std::string out;
    std::size_t i = 0;
    while (i < text.size()) {
        if (text.compare(i, 2, "(*") == 0) {
            const std::size_t end = text.find("*)", i + 2);
            REQUIRE(end != std::string::npos);
            const std::string inside = text.substr(i + 2, end - i - 2);
            INFO("comment: " << inside);
            CHECK(inside.find("(*") == std::string::npos);
            CHECK(inside.find('\n') == std::string::npos);
            out += ' ';
            i = end + 2;
        } else {
            out += text[i++];
        }
    }
    return out;
}

std::string trimmed(const std::string& line)
{
    const std::size_t first = line.find_first_not_of(' ');
    if (first == std::string::npos)
        return {};
    return line.substr(first, line.find_last_not_of(' ') - first + 1);
}

bool isCaseLabel(const std::string& line)
{
    std::size_t i = 0;
    while (i < line.size() && std::isdigit(static_cast<unsigned char>(line[i])))
        ++i;
    return i > 0 && i < line.size() && line[i] == ':' && line.compare(i, 2, ":=") != 0;
}

std::vector<std::string> identifiersIn(const std::string& code)
{
    std::vector<std::string> words;
    std::string word;
    for (char c : code + " ") {
        if (std::isalnum(static_cast<unsigned char>(c)) || c == '_') {
            word += c;
        } else {
            if (!word.empty() && !std::isdigit(static_cast<unsigned char>(word[0])))
                words.push_back(word);
            word.clear();
        }
    }
    return words;
}

std::string upper(std::string text)
{
    for (char& c : text)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

// Each line of a declaration block is one declaration a compiler reads,
// `name : TYPE [:= literal];`, the name an identifier and no keyword: no
// user text can end the block, the declaration or a comment early.
void checkDeclarationLines(const std::string& code)
{
    static const std::regex declaration(R"(([A-Za-z_][A-Za-z0-9_]*) : ([A-Za-z_][A-Za-z0-9_]*))"
                                        R"(( := (TRUE|FALSE|[-+]?[0-9][0-9_]*(\.[0-9][0-9_]*)?([eE][-+]?[0-9_]+)?))?;)");
    static const std::set<std::string> blocks = {"VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_EXTERNAL", "VAR_GLOBAL"};
    bool inBlock = false;
    for (const std::string& raw : splitLines(code)) {
        const std::string line = trimmed(raw);
        INFO("line: " << raw);
        if (blocks.count(line)) {
            CHECK_FALSE(inBlock);
            inBlock = true;
        } else if (line == "END_VAR") {
            CHECK(inBlock);
            inBlock = false;
        } else if (inBlock && !line.empty()) {
            std::smatch match;
            REQUIRE(std::regex_match(line, match, declaration));
            CHECK_FALSE(isIecKeyword(match[1].str()));
            const std::string type = match[2].str();
            // An elementary type, a generated function block, or the standard TON.
            CHECK((parseIecType(type) || (type.size() > 3 && type.substr(type.size() - 3) == "_FB") || type == "TON"));
        }
    }
    CHECK_FALSE(inBlock);
}

// One name, one thing: within a POU (its externals included) and among the
// globals (the IEC VAR_EXTERNAL repeats a global, which is what it is for).
// A POU's inputs and locals never repeat a global; a nested function
// block's continuous outputs are named after the global the GEMMA program
// writes from them (spec grafcet-layer.md §4.3), which IEC allows since the
// block does not see that global: it is not among its externals.
void checkUniqueNames(const PlcProject& project)
{
    auto checkUnique = [](const std::vector<const std::vector<PlcVariable>*>& lists, std::set<std::string> seen) {
        for (const std::vector<PlcVariable>* list : lists) {
            for (const PlcVariable& variable : *list) {
                INFO("declared twice: " << variable.name);
                CHECK(seen.insert(upper(variable.name)).second);
            }
        }
    };
    checkUnique({&project.globals}, {});
    std::set<std::string> globals;
    for (const PlcVariable& variable : project.globals)
        globals.insert(upper(variable.name));
    for (const PlcPou& pou : project.pous) {
        INFO(pou.name);
        checkUnique({&pou.inputs, &pou.locals}, globals);
        checkUnique({&pou.inputs, &pou.outputs, &pou.locals, &pou.externals}, {});
        for (const PlcVariable& external : pou.externals)
            CHECK(globals.count(upper(external.name)) == 1);
    }
}

// Every rule of spec §7 an IEC compiler would reject the text for.
void checkIecRules(const PlcProject& project)
{
    const std::string text = formatSingleFileIec(project);
    const std::string code = withoutComments(text);
    checkDeclarationLines(code);
    checkUniqueNames(project);
    CHECK(std::all_of(code.begin(), code.end(), [](char c) { return static_cast<unsigned char>(c) < 0x80; }));
    CHECK(code.find("//") == std::string::npos);
    CHECK(upper(code).find("NOT NOT") == std::string::npos);
    CHECK(code.find(";;") == std::string::npos);

    const std::vector<std::string> lines = splitLines(code);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string line = trimmed(lines[i]);
        INFO("line " << i + 1 << ": " << lines[i]);
        CHECK(line != ";");
        const std::vector<std::string> words = identifiersIn(line);
        const bool hasEndIf = std::find(words.begin(), words.end(), "END_IF") != words.end();
        if (line.rfind("END_IF", 0) == 0 || line.rfind("END_CASE", 0) == 0)
            CHECK(line.back() == ';');
        if (hasEndIf) // the keyword, not an identifier that starts with it
            CHECK(line.substr(line.size() - 7) == "END_IF;");
        if (isCaseLabel(line)) { // no empty CASE branch
            REQUIRE(i + 1 < lines.size());
            const std::string next = trimmed(lines[i + 1]);
            CHECK(!isCaseLabel(next));
            CHECK(next != "END_CASE;");
        }
        if (line == "END_VAR") { // no empty declaration block
            const std::string previous = trimmed(lines[i - 1]);
            CHECK(previous.find(':') != std::string::npos);
            CHECK(previous.back() == ';');
        }
    }

    // No empty POU body: something between the last END_VAR and END_*.
    for (const PlcPou& pou : project.pous) {
        INFO(pou.name);
        CHECK(!trimmed(withoutComments(pou.body)).empty());
        const std::vector<std::string> bodyCode = splitLines(withoutComments(pou.body));
        CHECK(std::any_of(bodyCode.begin(), bodyCode.end(),
                          [](const std::string& l) { return l.find(';') != std::string::npos; }));
    }

    // Identifiers: no "__", no trailing "_", and no POU named like a variable.
    for (const std::string& word : identifiersIn(code)) {
        INFO(word);
        CHECK(word.find("__") == std::string::npos);
        CHECK(word.back() != '_');
    }
    std::set<std::string> pouNames;
    for (const PlcPou& pou : project.pous)
        pouNames.insert(upper(pou.name));
    auto checkNotPou = [&](const std::vector<PlcVariable>& variables) {
        for (const PlcVariable& variable : variables) {
            INFO(variable.name);
            CHECK(pouNames.count(upper(variable.name)) == 0);
        }
    };
    checkNotPou(project.globals);
    for (const PlcPou& pou : project.pous) {
        checkNotPou(pou.inputs);
        checkNotPou(pou.outputs);
        checkNotPou(pou.locals);
        checkNotPou(pou.externals);
    }
    CHECK(upper(project.programInstanceName) != "GEMMA");
    CHECK(pouNames.count(upper(project.programInstanceName)) == 0);
    CHECK(code.find("TASK " + project.taskName + "(INTERVAL := T#") != std::string::npos);
    CHECK(code.find("PROGRAM " + project.programInstanceName + " WITH " + project.taskName + " : GEMMA;")
          != std::string::npos);
}

} // namespace

TEST_CASE("generated code keeps the rules IEC compilers enforce", "[stgen]")
{
    Model nasty = errorsModel();
    REQUIRE(nasty.setStepComment("F4", "(*) *) (* ) \r\n\t end"));
    REQUIRE(nasty.setName("Line *) (* 2\nname"));
    Model notNot = macroBranchModel();
    set(notNot, "F1->A2", "NOT (NOT Stop)");
    set(notNot, "F1->F3", "NOT NOT Stop");
    Model allHidden;
    for (const Step& step : allHidden.steps())
        REQUIRE(allHidden.setStepHidden(step.id, true));

    const std::vector<std::pair<const char*, Model>> models = {
        {"template", Model()},           {"simple", simpleBranchModel()},
        {"macro", macroBranchModel()},   {"enclosing", enclosingBranchModel()},
        {"negated macro", negatedMacroModel()}, {"negated enclosing", negatedEnclosingModel()},
        {"family", familyModel()},       {"tokens", tokensModel()},
        {"hidden", hiddenModel()},       {"errors", errorsModel()},
        {"nasty comments", nasty},       {"NOT NOT", notNot},
        {"all hidden", allHidden},       {"realistic", factory::realisticModel()},
        {"case study", samples::caseStudyModel()}, {"stress", factory::stressModel()},
    };
    for (const auto& [name, model] : models) {
        INFO("model: " << name);
        checkIecRules(buildPlcProject(model, Dialect::Iec));
    }
    for (std::uint32_t seed = 1; seed <= 20; ++seed) {
        INFO("random model " << seed);
        checkIecRules(buildPlcProject(samples::randomModel(seed), Dialect::Iec));
    }
    // The function blocks of nested GRAFCETs: the shipped example, random
    // valid ones (TONs, REPEAT, edges, stored and continuous actions) and
    // random ones with mistakes (commented out, never generated).
    const LoadedModel example = loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    REQUIRE(example.ok());
    checkIecRules(buildPlcProject(*example.model, Dialect::Iec));
    for (std::uint32_t seed = 1; seed <= 20; ++seed) {
        INFO("random model with valid nested GRAFCETs " << seed);
        Model model = samples::randomModel(seed);
        std::mt19937 random(seed);
        samples::addValidRandomNestedGrafcets(model, random);
        if (seed % 2 == 0)
            model.setEvolutionRule(EvolutionRule::UntilStable);
        REQUIRE_FALSE(model.grafcets().empty());
        checkIecRules(buildPlcProject(model, Dialect::Iec));
    }
    for (std::uint32_t seed = 1; seed <= 10; ++seed) {
        INFO("random model with random nested GRAFCETs " << seed);
        Model model = samples::randomModel(seed);
        samples::addRandomNestedGrafcets(model, seed);
        checkIecRules(buildPlcProject(model, Dialect::Iec));
    }
}

TEST_CASE("a unary operator on a unary expression is parenthesised", "[stgen]")
{
    Model model = macroBranchModel();
    set(model, "F1->A2", "NOT (NOT Stop)");
    set(model, "F1->F3", "not not Stop");
    const std::string text = gemmaText(model);
    CHECK(hasLine(text, "    IF NOT (NOT Stop) AND F1.Complete THEN"));
    CHECK(hasLine(text, "    ELSIF NOT (NOT Stop) AND F1.Complete THEN"));
}

TEST_CASE("user text in comments cannot close or open a comment", "[stgen]")
{
    CHECK(escapeComment("a *) b") == "a * ) b");
    CHECK(escapeComment("a (* b") == "a ( * b");
    CHECK(escapeComment("(*)") == "( * )");
    CHECK(escapeComment("**)") == "** )");
    CHECK(escapeComment("line\r\nnext\tend") == "line  next end");
    CHECK(escapeComment("Arrêt") == "Arrêt");
    // Printable ASCII without a delimiter comes back as it is; DEL and the
    // delimiters at either end do not.
    CHECK(escapeComment(" ~a*b(c)d* (") == " ~a*b(c)d* (");
    CHECK(escapeComment("a\x7f") == "a?");
    CHECK(escapeComment("*)x") == "* )x");
    CHECK(escapeComment("x(*") == "x( *");

    Model model = errorsModel();
    REQUIRE(model.setStepComment("F1", "x *) State := 99; (* y"));
    const std::string code = withoutComments(fullText(model, Dialect::Iec));
    CHECK(code.find("State := 99") == std::string::npos);
    CHECK(code.find("in the batch") == std::string::npos);
}

// ---- user text that is not an identifier or a literal ------------------------

TEST_CASE("a variable the code cannot declare gets a generated name and is never read", "[stgen]")
{
    Model model = macroBranchModel();
    REQUIRE(model.addVariable({"X : BOOL; END_VAR State := 13; VAR Y", IecType::Bool, "", ""}));
    REQUIRE(model.addVariable({"Z := TRUE; (*", IecType::Int, "", "its own comment"}));
    REQUIRE(model.addVariable({"state", IecType::Bool, "TRUE; END_VAR Injected := 1;", ""}));
    REQUIRE(model.addVariable({"Invalid_Name_6", IecType::Bool, "", "a user name the generated one avoids"}));
    REQUIRE(model.addVariable({"F1.Complete", IecType::Bool, "", ""}));
    set(model, "F1->A2", "state OR Stop");
    set(model, "F1->F3", "F1.Complete");
    set(model, "F1->A3", "Fault");

    for (Dialect dialect : {Dialect::Iec, Dialect::Codesys}) {
        INFO(dialectName(dialect));
        const std::string text = fullText(model, dialect);
        const std::string code = withoutComments(text);
        CHECK(code.find("State := 13") == std::string::npos);
        CHECK(code.find("Injected") == std::string::npos);
        CHECK(code.find("Z := TRUE") == std::string::npos);
        checkDeclarationLines(code);
    }
    const PlcProject project = buildPlcProject(model, Dialect::Iec);
    checkIecRules(project);
    const std::string globals = formatGlobals(project);
    CHECK(globals.find("    Invalid_Name_4 : BOOL := FALSE; (* ERROR GG301: invalid variable name: 'X : BOOL; END_VAR "
                       "State := 13; VAR Y' is not a valid IEC 61131-3 identifier")
          != std::string::npos);
    CHECK(globals.find("; declared as Invalid_Name_4, and every condition that reads it is FALSE *)")
          != std::string::npos);
    CHECK(globals.find("    Invalid_Name_5 : INT := 0; (* ERROR GG301: ") != std::string::npos);
    CHECK(globals.find("FALSE. its own comment *)") != std::string::npos);
    // A generator name (GG303), with an invalid default as well; the next free name.
    CHECK(globals.find("    Invalid_Name_6_2 : BOOL := FALSE; (* ERROR GG303: invalid variable name: 'state' is a "
                       "name the generated code uses; declared as Invalid_Name_6_2")
          != std::string::npos);
    CHECK(globals.find("    Invalid_Name_6 : BOOL := FALSE; (* a user name the generated one avoids *)")
          != std::string::npos);
    CHECK(globals.find("    Invalid_Name_8 : BOOL := FALSE;") != std::string::npos);

    // Conditions that read them are FALSE, with the error above; the others stand.
    const std::string gemma = gemmaText(model);
    CHECK(hasLine(gemma, "    (* ERROR GG303: in the condition of F1->A2: invalid variable name: 'state' is a name the "
                         "generated code uses *)"));
    CHECK(hasLine(gemma, "    IF FALSE THEN"));
    CHECK(hasLine(gemma, "    ELSIF FALSE THEN"));
    CHECK(hasLine(gemma, "    ELSIF Fault AND F1.Complete THEN"));
    std::vector<std::string> externals;
    for (const PlcVariable& variable : project.pous.front().externals)
        externals.push_back(variable.name);
    CHECK(externals == std::vector<std::string>{"Fault"});
}

TEST_CASE("step comments and the model name cannot bring control characters into the code", "[stgen]")
{
    Model model = macroBranchModel();
    REQUIRE(model.setStepComment("F1", "title\x1b]0;owned\x07 \xe2\x80\xae reversed \xc2\x9b \xff end"));
    REQUIRE(model.setName("name\x1b[2J"));
    const std::string text = fullText(model, Dialect::Iec);
    CHECK(text.find('\x1b') == std::string::npos);
    CHECK(text.find("title?]0;owned? ? reversed ? ? end") != std::string::npos);
    CHECK(escapeComment("a\xe2\x80\xa8" "b\xe2\x81\xa6" "c") == "a b?c");
}

namespace {

// No control character (terminal escape, bidi override, C1, invalid UTF-8)
// anywhere in the text, comments included; line feeds end lines.
void checkPrintable(const std::string& text)
{
    std::string_view rest = text;
    while (!rest.empty()) {
        const Utf8Character character = decodeUtf8(rest);
        INFO("at offset " << text.size() - rest.size());
        REQUIRE(character.valid);
        if (character.codePoint != '\n')
            REQUIRE_FALSE(isControlCharacter(character.codePoint));
        rest.remove_prefix(character.length);
    }
}

} // namespace

TEST_CASE("forced code of models with hostile user text keeps the IEC rules", "[stgen][property]")
{
    for (std::uint32_t seed = 1; seed <= 150; ++seed) {
        INFO("hostile model " << seed);
        const Model model = samples::hostileModel(seed);
        const PlcProject iec = buildPlcProject(model, Dialect::Iec);
        checkIecRules(iec);
        const std::string single = formatSingleFileIec(iec);
        checkPrintable(single);
        CHECK(withoutComments(single).find(samples::kInjectedMarker) == std::string::npos);

        const std::string codesys = fullText(model, Dialect::Codesys);
        checkPrintable(codesys);
        const std::string codesysCode = withoutComments(codesys);
        CHECK(codesysCode.find(samples::kInjectedMarker) == std::string::npos);
        checkDeclarationLines(codesysCode);

        // The program and its globals read as declarations and statements, and run.
        sttest::StInterpreter plc(previewGemmaProgram(model, Dialect::Iec).text, formatGlobals(iec));
        REQUIRE(plc.error().empty());
        for (int scan = 0; scan < 3; ++scan)
            plc.scan();
        CHECK(plc.runtimeError().empty());
    }
}

// ---- declarations, globals, configuration -------------------------------------

TEST_CASE("the GEMMA locals follow spec 6.1", "[stgen]")
{
    const PlcProject project = buildPlcProject(tokensModel(), Dialect::Iec);
    const PlcPou& gemma = project.pous.front();
    REQUIRE(gemma.name == "GEMMA");
    REQUIRE(gemma.kind == PouKind::Program);
    std::vector<std::string> locals;
    for (const PlcVariable& variable : gemma.locals)
        locals.push_back(variable.name + " : " + variable.typeName + " := " + variable.initialValue);
    CHECK(locals == std::vector<std::string>{"State : UINT := 8", "Entry : BOOL := TRUE", "F1 : F1_FB := ",
                                             "D3 : D3_FB := ", "Stop_F1_3_MEM : BOOL := FALSE",
                                             "Ack_D3_1_MEM : BOOL := FALSE"});
    std::vector<std::string> pous;
    for (const PlcPou& pou : project.pous)
        pous.push_back(pou.name);
    CHECK(pous == std::vector<std::string>{"GEMMA", "F1_FB", "D3_FB"});
}

TEST_CASE("IEC externals are the globals GEMMA reads; CODESYS reads GVL", "[stgen]")
{
    Model model = tokensModel();
    REQUIRE(model.addVariable({"Unused", IecType::Int, "", ""}));
    REQUIRE(model.addVariable({"Level", IecType::Real, "", ""}));
    set(model, "F1->D3", "Fault AND level > 2.5");

    const PlcProject iec = buildPlcProject(model, Dialect::Iec);
    std::vector<std::string> externals;
    for (const PlcVariable& variable : iec.pous.front().externals)
        externals.push_back(variable.name + ":" + variable.typeName + ":" + variable.initialValue);
    CHECK(externals == std::vector<std::string>{"EStop:BOOL:", "Fault:BOOL:", "Stop:BOOL:", "Ack:BOOL:",
                                                "Repaired:BOOL:", "Level:REAL:"});
    CHECK(iec.globalListName.empty());
    CHECK(iec.globals.size() == model.variables().size());
    const std::string iecText = formatPou(iec.pous.front(), Dialect::Iec);
    CHECK(iecText.find("VAR_EXTERNAL\n    EStop : BOOL;\n") != std::string::npos);
    CHECK(hasLine(iecText, "    ELSIF Fault AND Level > 2.5 AND F1.Complete THEN"));

    const PlcProject codesys = buildPlcProject(model, Dialect::Codesys);
    CHECK(codesys.globalListName == "GVL");
    CHECK(codesys.pous.front().externals.empty());
    const std::string codesysText = formatPou(codesys.pous.front(), Dialect::Codesys);
    CHECK(codesysText.find("VAR_EXTERNAL") == std::string::npos);
    CHECK(hasLine(codesysText, "    ELSIF GVL.Fault AND GVL.Level > 2.5 AND F1.Complete THEN"));
    CHECK(hasLine(codesysText, "    IF GVL.EStop THEN"));
}

TEST_CASE("globals carry their default or the type's implicit value", "[stgen]")
{
    Model model;
    REQUIRE(model.addVariable({"Start", IecType::Bool, "", "push button *) S1"}));
    REQUIRE(model.addVariable({"Armed", IecType::Bool, "TRUE", ""}));
    REQUIRE(model.addVariable({"Count", IecType::Int, "-5", ""}));
    REQUIRE(model.addVariable({"Ratio", IecType::Lreal, "1e3", ""}));
    REQUIRE(model.addVariable({"Gain", IecType::Real, "", ""}));

    const PlcProject iec = buildPlcProject(model, Dialect::Iec);
    CHECK(formatGlobals(iec) == "VAR_GLOBAL\n"
                                "    Start : BOOL := FALSE; (* push button * ) S1 *)\n"
                                "    Armed : BOOL := TRUE;\n"
                                "    Count : INT := -5;\n"
                                "    Ratio : LREAL := 1.0e3;\n"
                                "    Gain : REAL := " + std::string(implicitDefault(IecType::Real)) + ";\n"
                                "END_VAR\n");
    const PlcProject codesys = buildPlcProject(model, Dialect::Codesys);
    const std::string gvl = formatGlobals(codesys);
    CHECK(gvl.rfind("{attribute 'qualified_only'}\nVAR_GLOBAL\n    Start : BOOL := FALSE;", 0) == 0);
    CHECK(gvl.substr(gvl.size() - 8) == "END_VAR\n");

    CHECK(formatGlobals(buildPlcProject(Model(), Dialect::Iec)).empty());
    CHECK(formatGlobals(buildPlcProject(Model(), Dialect::Codesys))
          == "{attribute 'qualified_only'}\nVAR_GLOBAL\nEND_VAR\n");
}

TEST_CASE("task intervals are IEC durations", "[stgen]")
{
    CHECK(formatDuration(20) == "T#20ms");
    CHECK(formatDuration(1) == "T#1ms");
    CHECK(formatDuration(1000) == "T#1s");
    CHECK(formatDuration(1500) == "T#1s500ms");
    CHECK(formatDuration(60'000) == "T#1m");
    CHECK(formatDuration(60'500) == "T#1m0s500ms");
    CHECK(formatDuration(61'000) == "T#1m1s");
    CHECK(formatDuration(3'600'000) == "T#1h");
    CHECK(formatDuration(3'601'000) == "T#1h0m1s");
    CHECK(formatDuration(0) == "T#0ms");

    Model model;
    REQUIRE(model.setCycleTimeMs(1500));
    const PlcProject project = buildPlcProject(model, Dialect::Iec);
    CHECK(project.cycleTimeMs == 1500);
    const std::string configuration = formatConfiguration(project);
    CHECK(configuration == "CONFIGURATION GemmaConfiguration\n"
                           "    RESOURCE GemmaResource ON PLC\n"
                           "        TASK MainTask(INTERVAL := T#1s500ms, PRIORITY := 1);\n"
                           "        PROGRAM GemmaInstance WITH MainTask : GEMMA;\n"
                           "    END_RESOURCE\n"
                           "END_CONFIGURATION\n");
}

TEST_CASE("the IEC configuration holds the globals, the CODESYS one does not", "[stgen]")
{
    const Model model = tokensModel();
    const std::string iec = formatConfiguration(buildPlcProject(model, Dialect::Iec));
    CHECK(iec.find("CONFIGURATION GemmaConfiguration\n    VAR_GLOBAL\n        EStop : BOOL := FALSE;\n")
          == 0);
    const PlcProject codesys = buildPlcProject(model, Dialect::Codesys);
    CHECK(formatConfiguration(codesys).find("VAR_GLOBAL") == std::string::npos);
    // The single IEC file always declares the globals.
    CHECK(formatSingleFileIec(codesys).find("VAR_GLOBAL") != std::string::npos);
}

TEST_CASE("function blocks follow spec 6.5", "[stgen]")
{
    Model model = macroBranchModel();
    REQUIRE(model.setStepComment("F1", "fills *) bottles"));
    const PlcProject project = buildPlcProject(model, Dialect::Iec);
    REQUIRE(project.pous.size() == 2);
    const PlcPou& fb = project.pous[1];
    CHECK(fb.name == "F1_FB");
    CHECK(fb.kind == PouKind::FunctionBlock);
    const std::string text = formatPou(fb, Dialect::Iec);
    checkGolden("function_block.st", text);
    CHECK(text.find("FUNCTION_BLOCK F1_FB\nVAR_INPUT\n    Initialization : BOOL;") != std::string::npos);
    CHECK(text.find("VAR_OUTPUT\n    Complete : BOOL;") != std::string::npos);
    CHECK(text.find("IF Initialization THEN\n    Complete := FALSE;\n") != std::string::npos);
    CHECK(hasLine(text, "Complete := TRUE;"));
    CHECK(text.substr(text.size() - 19) == "END_FUNCTION_BLOCK\n");
    CHECK(text.find("fills * ) bottles") != std::string::npos);
}

// ---- the intermediate form ----------------------------------------------------

TEST_CASE("GemmaProgram: visible steps, evaluation order, waiting", "[stgen]")
{
    Model model = familyModel();
    REQUIRE(model.setTransitionHidden("F1->D1", false));
    set(model, "F1->D1", "Ready");
    const GemmaProgram program = buildGemmaProgram(model);
    std::vector<std::string> steps;
    for (const GemmaStep& step : program.steps)
        steps.push_back(step.id);
    CHECK(steps == std::vector<std::string>{"F1", "F2", "D1"});
    CHECK(program.initialStepId == "F2");
    CHECK(program.initialNumber == 9);

    const GemmaStep* f1 = program.step("F1");
    REQUIRE(f1);
    CHECK(f1->name == "Normal production");
    CHECK(f1->type == StepType::Macro);
    REQUIRE(f1->transitions.size() == 2);
    CHECK(f1->transitions[0].id == "F->D1");
    CHECK(f1->transitions[0].family);
    CHECK_FALSE(f1->transitions[0].waitsForComplete);
    CHECK(f1->transitions[1].id == "F1->D1");
    CHECK(f1->transitions[1].priority == 1);
    CHECK(f1->transitions[1].negated);
    CHECK_FALSE(f1->transitions[1].waitsForComplete); // negated out of a macro-step
    CHECK(f1->transitions[1].targetNumber == 14);
    CHECK(f1->transitions[1].conditionUsable);
    CHECK(program.step("D1")->transitions.empty()); // D1 -> D2, D1 -> A5: targets hidden
    CHECK(program.problems.empty());
}

TEST_CASE("GemmaProgram: waitsForComplete for every source type and negation", "[stgen]")
{
    struct Case {
        StepType type;
        bool negated;
        bool waits;
    };
    for (const Case& c : {Case{StepType::Simple, false, false}, Case{StepType::Simple, true, false},
                          Case{StepType::Macro, false, true}, Case{StepType::Macro, true, false},
                          Case{StepType::Enclosing, false, false}, Case{StepType::Enclosing, true, true}}) {
        Model model = negatedMacroModel();
        REQUIRE(model.setStepType("F1", c.type));
        REQUIRE(model.setNegated("F1->A3", c.negated));
        const GemmaProgram program = buildGemmaProgram(model);
        const GemmaTransition& transition = program.step("F1")->transitions.back();
        REQUIRE(transition.id == "F1->A3");
        INFO(stepTypeName(c.type) << (c.negated ? " negated" : ""));
        CHECK(transition.waitsForComplete == c.waits);
        CHECK(hasLine(gemmaText(model), c.waits ? "    ELSIF Fault AND F1.Complete THEN" : "    ELSIF Fault THEN"));
    }
}

TEST_CASE("GemmaProgram: tokens and their substitutions", "[stgen]")
{
    const Model model = tokensModel();
    const GemmaProgram program = buildGemmaProgram(model);
    const GemmaStep* f1 = program.step("F1");
    REQUIRE(f1);
    REQUIRE(f1->tokens.size() == 1);
    const GemmaToken& stop = f1->tokens.front();
    CHECK(stop.name == "Stop_F1_3_MEM");
    CHECK(stop.variable == "Stop");
    CHECK(stop.polarity == TokenPolarity::NormallyClosed);
    CHECK(stop.transitionId == "F1->A2");
    const GemmaTransition& toA2 = f1->transitions[2];
    REQUIRE(toA2.id == "F1->A2");
    REQUIRE(stop.literalNodes.size() == 1);
    CHECK(toA2.condition.expression.root == stop.literalNodes.front()); // the NOT node: the whole literal
    CHECK(toA2.substitutions == std::map<int, std::string>{{stop.literalNodes.front(), "Stop_F1_3_MEM"}});

    const GemmaToken& ack = program.step("D3")->tokens.at(0);
    CHECK(ack.name == "Ack_D3_1_MEM");
    CHECK(ack.polarity == TokenPolarity::NormallyOpen);
    CHECK(program.problems.empty());
}

TEST_CASE("GemmaProgram: tokens in declared spelling, in condition order", "[stgen]")
{
    Model model = tokensModel();
    set(model, "F1->A2", "NOT stop AND ack AND (ACK OR Repaired)");
    REQUIRE(model.setTokens("F1->A2", {"ACK", "STOP"}));
    const GemmaProgram program = buildGemmaProgram(model);
    const GemmaStep* f1 = program.step("F1");
    REQUIRE(f1->tokens.size() == 2);
    CHECK(f1->tokens[0].name == "Stop_F1_3_MEM");
    CHECK(f1->tokens[1].name == "Ack_F1_3_MEM");
    CHECK(f1->tokens[1].literalNodes.size() == 2);
    CHECK(hasLine(gemmaText(model), "    ELSIF Stop_F1_3_MEM AND Ack_F1_3_MEM AND (Ack_F1_3_MEM OR Repaired) AND "
                                    "F1.Complete THEN"));
}

TEST_CASE("GemmaProgram: tokens that cannot take effect are ignored with a warning", "[stgen]")
{
    struct Case {
        const char* condition;
        const char* token;
        const char* code;
    };
    for (const Case& c : {Case{"Stop AND Fault", "Nobody", "GG211"}, Case{"Stop AND Fault", "Ack", "GG208"},
                          Case{"Stop = Fault", "Stop", "GG212"}, Case{"Stop OR NOT Stop", "Stop", "GG209"},
                          Case{"Stop AND (", "Stop", "GG201"}}) {
        INFO(c.condition << " / " << c.token);
        Model model = tokensModel();
        set(model, "F1->A2", c.condition);
        REQUIRE(model.setTokens("F1->A2", {c.token}));
        const GemmaProgram program = buildGemmaProgram(model);
        CHECK(program.step("F1")->tokens.empty());
        CHECK(program.step("F1")->transitions[2].substitutions.empty());
        REQUIRE(!program.problems.empty());
        CHECK(program.problems.front().code == c.code);
        CHECK(program.problems.front().element == "F1->A2");
    }
    Model simple = tokensModel();
    REQUIRE(simple.setStepType("F1", StepType::Simple));
    const GemmaProgram program = buildGemmaProgram(simple);
    CHECK(program.step("F1")->tokens.empty());
    REQUIRE(program.problems.size() == 1);
    CHECK(program.problems.front().code == "GG210");
    CHECK(program.problems.front().kind == ProgramProblem::Kind::Warning);
}

TEST_CASE("a token is generated exactly when the checks accept it", "[stgen]")
{
    struct Case {
        const char* condition;
        const char* token;
    };
    const Case cases[] = {
        {"NOT Stop", "Stop"},          {"Stop AND Fault", "Stop"},   {"Stop AND Fault", "Ack"},
        {"Stop = Fault", "Stop"},      {"Stop AND (Stop = Fault)", "Stop"}, {"Stop OR NOT Stop", "Stop"},
        {"NOT (NOT Stop)", "Stop"},    {"Stop AND (", "Stop"},       {"Stop AND Nobody", "Stop"},
        {"Stop AND Fault", "Nobody"},
    };
    for (const Case& c : cases) {
        INFO(c.condition << " / " << c.token);
        Model model = tokensModel();
        set(model, "F1->A2", c.condition);
        REQUIRE(model.setTokens("F1->A2", {c.token}));
        bool refused = false;
        for (const Diagnostic& diagnostic : checkModel(model)) {
            if (diagnostic.element == "F1->A2" && diagnostic.field == "tokens")
                refused = true;
        }
        const bool usable = buildGemmaProgram(model).step("F1")->transitions[2].conditionUsable;
        const bool generated = gemmaText(model).find("Stop_F1_3_MEM := TRUE;") != std::string::npos
                               || gemmaText(model).find("Ack_F1_3_MEM := TRUE;") != std::string::npos;
        // An unusable condition is FALSE in the code: no token, whatever the checks say of it.
        CHECK(generated == (!refused && usable));
    }
}

TEST_CASE("a hidden initial step is reported at the top of GEMMA", "[stgen]")
{
    Model model = simpleBranchModel();
    REQUIRE(model.setStepHidden("A1", true));
    const std::string text = gemmaText(model);
    CHECK(text.find("(* ERROR GG001: the initial step A1 is hidden") != std::string::npos);
    CHECK(hasLine(text, "    State : UINT := 1; (* code number of the active GEMMA state *)"));
}

// ---- preview ------------------------------------------------------------------

TEST_CASE("the preview is the GEMMA POU with the lines of each step and transition", "[stgen]")
{
    Model model = tokensModel();
    REQUIRE(model.setTransitionHidden("F->D1", false));
    set(model, "F->D1", "EStop");
    set(model, "F1->D3", ""); // a problem comment belongs to its transition
    for (Dialect dialect : {Dialect::Iec, Dialect::Codesys}) {
        const StPreview preview = previewGemmaProgram(model, dialect);
        CHECK(preview.text == gemmaText(model, dialect));
        const std::vector<std::string> lines = splitLines(preview.text);
        auto line = [&](int number) { return lines.at(static_cast<std::size_t>(number - 1)); };

        for (const char* id : {"F1", "D1", "D3", "A2"}) {
            INFO(id);
            REQUIRE(preview.ranges.count(id) == 1);
            const LineRange range = preview.ranges.at(id);
            CHECK(line(range.first).find(std::string(": (* ") + id + " ") != std::string::npos);
            CHECK(range.last >= range.first);
            CHECK(isCaseLabel(line(range.last + 1)) == (std::string(id) != "D3"));
        }
        const LineRange toA2 = preview.ranges.at("F1->A2");
        CHECK(line(toA2.first) == "    ELSIF Stop_F1_3_MEM AND F1.Complete THEN");
        CHECK(line(toA2.first + 1) == "        State := 2;");
        CHECK(line(toA2.last) == "        Entry := TRUE;");
        const LineRange toD3 = preview.ranges.at("F1->D3");
        CHECK(line(toD3.first).rfind("    (* ERROR GG202", 0) == 0);
        CHECK(line(toD3.first + 1) == "    ELSIF FALSE THEN");
        CHECK(preview.ranges.at("F->D1") == preview.ranges.at("F->D1@F1"));
        CHECK(line(preview.ranges.at("F->D1").first).find("IF ") == 4);
        CHECK(preview.ranges.count("F1->D1") == 1);
        CHECK(preview.ranges.count("F1->F4") == 0); // F4 hidden
    }
}

// ---- determinism and speed ------------------------------------------------------

TEST_CASE("generation is deterministic", "[stgen]")
{
    const Model model = errorsModel();
    const Model copy(model);
    for (Dialect dialect : {Dialect::Iec, Dialect::Codesys}) {
        const std::string first = fullText(model, dialect);
        CHECK(fullText(model, dialect) == first);
        CHECK(fullText(copy, dialect) == first);
    }
}

} // namespace test_stgenerator
