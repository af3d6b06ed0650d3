// The intermediate form of nested GRAFCETs and the code generated from it
// (spec grafcet-layer.md §4).

#include "core/checks/checks.h"
#include "core/templates/gemma/gemmaprogram.h"
#include "core/codegen/stgenerator.h"
#include "core/templates/gemma/gemmacodegen.h"
#include "core/formats/modelfiles.h"
#include "core/model/model.h"
#include "samplemodels.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace test_nestedcode {

using namespace core;

namespace {

// F1: 1 --RE Start--> 2 (N Lamp, Count := Count + 1) --5s/X2--> 3 (S Complete).
Model smallModel()
{
    return samples::lampGrafcetModel();
}

std::string functionBlock(const Model& model, const std::string& name, Dialect dialect = Dialect::Iec)
{
    const PlcProject project = buildPlcProject(model, dialect);
    for (const PlcPou& pou : project.pous) {
        if (pou.name == name)
            return formatPou(pou, dialect);
    }
    FAIL("no POU " << name);
    return {};
}

// The codes of the nested GRAFCETs' problems (the template's empty GEMMA
// conditions have theirs).
std::vector<std::string> codes(const GemmaProgram& program)
{
    std::vector<std::string> result;
    for (const ProgramProblem& problem : program.problems) {
        if (problem.nestedStep != 0 || problem.nestedTransition != 0)
            result.push_back(problem.code);
    }
    return result;
}

const ProgramProblem& firstNested(const GemmaProgram& program)
{
    for (const ProgramProblem& problem : program.problems) {
        if (problem.nestedStep != 0 || problem.nestedTransition != 0)
            return problem;
    }
    FAIL("no nested problem");
    return program.problems.front();
}

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

} // namespace

TEST_CASE("The intermediate form of a nested GRAFCET", "[nested-program]")
{
    const GemmaProgram program = buildGemmaProgram(smallModel());
    CHECK(codes(program).empty());
    const GemmaStep* f1 = program.step("F1");
    REQUIRE(f1);
    REQUIRE(f1->nested);
    const NestedGrafcet& nested = *f1->nested;
    REQUIRE(nested.steps.size() == 3);
    CHECK(nested.steps[1].continuous.size() == 1);
    CHECK(nested.steps[1].onActivation.size() == 1);
    REQUIRE(nested.timers.size() == 1);
    CHECK(nested.timers[0].name == "GG_T2_5000ms");
    CHECK(nested.steps[1].timers == std::vector<int>{0});
    REQUIRE(nested.outputs.size() == 1);
    CHECK(nested.outputs[0].variable == "Lamp");
    CHECK(nested.storedTargets == std::vector<std::string>{"Count"});
    CHECK(nested.readVariables == std::vector<std::string>{"Start", "Count"});
    CHECK(nested.writesComplete);
    CHECK(nested.maxEvolutions == 3);
    CHECK(program.edgeVariables == std::vector<std::string>{"Start"});
    CHECK_FALSE(program.step("F2")->nested); // no GRAFCET: the skeleton stays
}

TEST_CASE("Unusable receptivities and actions are reported with their place", "[nested-program]")
{
    Model model = smallModel();
    REQUIRE(model.addVariable(samples::variable("Level", IecType::Int, VariableKind::Input)));
    const std::vector<std::pair<std::string, std::string>> actions = {
        {"S Start", "GG413"},            // an input
        {"N Count", "GG414"},            // continuous on INT
        {"Lamp := 3", "GG405"},          // the value does not fit
        {"S Nope", "GG405"},             // undeclared
        {"Count := 5s/X1", "GG411"},     // durations are for receptivities
        {"S Lamp", "GG415"},             // Lamp also has a continuous action
        {"N Lamp IF", "GG404"},          // syntax
    };
    for (const auto& [text, code] : actions) {
        Model copy(model);
        REQUIRE(copy.addGrafcetAction("F1", 3, {text.rfind("N ", 0) == 0 ? ActionTiming::Continuous
                                                                         : ActionTiming::OnActivation,
                                                text}));
        const GemmaProgram program = buildGemmaProgram(copy);
        INFO(text);
        REQUIRE(codes(program) == std::vector<std::string>{code});
        CHECK(firstNested(program).nestedStep == 3);
        CHECK(firstNested(program).element == "F1");
    }
    const std::vector<std::pair<std::string, std::string>> receptivities = {
        {"", "GG402"}, {"Start AND", "GG401"}, {"Level", "GG403"}, {"X9", "GG406"}, {"RE Level", "GG410"},
    };
    for (const auto& [text, code] : receptivities) {
        Model copy(model);
        REQUIRE(copy.setReceptivity("F1", 1, text));
        const GemmaProgram program = buildGemmaProgram(copy);
        INFO(text);
        REQUIRE(codes(program) == std::vector<std::string>{code});
        CHECK(firstNested(program).nestedTransition == 1);
        CHECK_FALSE(program.step("F1")->nested->transitions[0].usable);
    }
    // The checks show them on the nested element.
    Model broken(model);
    REQUIRE(broken.setReceptivity("F1", 1, "Start AND"));
    const std::vector<Diagnostic> diagnostics = checkModel(broken);
    const auto found = std::find_if(diagnostics.begin(), diagnostics.end(),
                                    [](const Diagnostic& d) { return d.code == "GG401"; });
    REQUIRE(found != diagnostics.end());
    CHECK(found->target == Diagnostic::Target::GrafcetTransition);
    CHECK(diagnosticElementLabel(*found) == "F1 T1");
    REQUIRE(found->span.has_value());
    CHECK(found->span->begin == 9);
}

TEST_CASE("A continuous condition may not read the FB's own continuous outputs", "[nested-program]")
{
    Model model = smallModel();
    REQUIRE(model.addVariable(samples::variable("Horn", IecType::Bool, VariableKind::Output)));
    REQUIRE(model.addGrafcetAction("F1", 3, {ActionTiming::Continuous, "Horn IF NOT Lamp"}));
    const GemmaProgram program = buildGemmaProgram(model);
    CHECK(codes(program) == std::vector<std::string>{"GG421"});
}

TEST_CASE("One evolution per scan: the function block", "[nested-code]")
{
    const std::string fb = functionBlock(smallModel(), "F1_FB");
    CHECK(contains(fb, "VAR_OUTPUT\n    Complete : BOOL;"));
    CHECK(contains(fb, "    Lamp : BOOL; (* continuous action of F1 *)\n"));
    CHECK(contains(fb, "VAR_EXTERNAL\n    Start : BOOL;\n    Count : INT;\n    Start_PREV : BOOL;\nEND_VAR"));
    CHECK(contains(fb, "    GG_T2_5000ms : TON;"));
    CHECK_FALSE(contains(fb, "Unstable"));
    // The Initialization call: the initial situation, Complete, the TONs, no evolution.
    CHECK(contains(fb, "IF Initialization THEN\n    X1 := TRUE;\n    X2 := FALSE;\n    X3 := FALSE;\n"
                       "    Complete := FALSE;\n    GG_T2_5000ms(IN := FALSE, PT := T#5s);\nELSE\n"));
    // The TONs run before the evolution, edges compare with the previous scan.
    CHECK(contains(fb, "ELSE\n    GG_T2_5000ms(IN := X2, PT := T#5s);\n    GG_Fire1 := X1 AND (Start AND NOT Start_PREV);\n"
                       "    GG_Fire2 := X2 AND (X2 AND GG_T2_5000ms.Q);\n"));
    // Deactivations, activations, then on-activation actions and the TON reset of the entered step.
    CHECK(contains(fb, "    IF GG_Entered2 THEN\n        Count := Count + 1;\n        GG_T2_5000ms(IN := FALSE, PT := T#5s);\n    END_IF;\n"));
    CHECK(contains(fb, "    IF GG_Entered3 THEN\n        Complete := TRUE;\n    END_IF;\n"));
    // Continuous outputs once per call, after the evolution.
    CHECK(contains(fb, "END_IF;\nLamp := X2;\nEND_FUNCTION_BLOCK\n"));

    const std::string codesys = functionBlock(smallModel(), "F1_FB", Dialect::Codesys);
    CHECK(contains(codesys, "GG_Fire1 := X1 AND (GVL.Start AND NOT GVL.Start_PREV);"));
    CHECK(contains(codesys, "GVL.Count := GVL.Count + 1;"));
    CHECK_FALSE(contains(codesys, "VAR_EXTERNAL"));
}

TEST_CASE("Until stable: the bounded search and Unstable", "[nested-code]")
{
    Model model = smallModel();
    model.setEvolutionRule(EvolutionRule::UntilStable);
    const std::string fb = functionBlock(model, "F1_FB");
    CHECK(contains(fb, "    Unstable : BOOL;"));
    CHECK(contains(fb, "    Unstable := FALSE;\n"));
    CHECK(contains(fb, "    GG_Evolution := 0;\n    REPEAT\n"));
    CHECK(contains(fb, "        GG_Fire1 := X1 AND (Start AND NOT Start_PREV AND GG_Evolution = 0);\n"));
    CHECK(contains(fb, "        GG_Fired := GG_Fire1 OR GG_Fire2;\n"));
    CHECK(contains(fb, "    UNTIL NOT GG_Fired OR GG_Evolution >= 3\n    END_REPEAT;\n    Unstable := GG_Fired;\n"));
}

TEST_CASE("The GEMMA program writes each continuous output once and keeps the edge memories", "[nested-code]")
{
    Model model = smallModel();
    REQUIRE(model.addGrafcetStep("F2", {1, true, "", {{ActionTiming::Continuous, "Lamp"}}}));
    const std::string gemma = functionBlock(model, "GEMMA");
    CHECK(contains(gemma, "END_CASE;\n(* Continuous outputs of the nested GRAFCETs: one writer each *)\n"
                          "Lamp := (State = 8 AND NOT Entry AND F1.Lamp) OR (State = 9 AND NOT Entry AND F2.Lamp);\n"));
    CHECK(contains(gemma, "(* Edge memories: the values at the end of this scan *)\nStart_PREV := Start;\nEND_PROGRAM"));
    const PlcProject project = buildPlcProject(model, Dialect::Iec);
    const auto prev = std::find_if(project.globals.begin(), project.globals.end(),
                                   [](const PlcVariable& v) { return v.name == "Start_PREV"; });
    REQUIRE(prev != project.globals.end());
    CHECK(prev->initialValue == "FALSE");
}

TEST_CASE("Nested GRAFCETs leave the CASE branches of the GEMMA program unchanged", "[nested-code]")
{
    Model plain = smallModel();
    for (const char* step : {"F1"})
        REQUIRE(plain.removeGrafcet(step));
    const std::string without = previewGemmaProgram(plain, Dialect::Iec).text;
    const std::string with = previewGemmaProgram(smallModel(), Dialect::Iec).text;
    const auto caseOf = [](const std::string& text) {
        return text.substr(text.find("CASE State OF"), text.find("END_CASE;") - text.find("CASE State OF"));
    };
    CHECK(caseOf(with) == caseOf(without));
}

// Spec grafcet-layer.md §4: the F1 branch of the paper's Figure 8 (the case
// study's GEMMA program, gemma-grafcet.md §6.3) comes out byte for byte
// whatever nested GRAFCETs the model has.
TEST_CASE("The case study's F1 branch is unchanged by nested GRAFCETs", "[nested-code]")
{
    const Model caseStudy = samples::caseStudyModel();
    const auto branchOf = [](const std::string& text, const std::string& state) {
        const std::size_t begin = text.find("\n" + state + ": (*");
        REQUIRE(begin != std::string::npos);
        const std::size_t end = text.find(": (*", begin + state.size() + 3);
        return text.substr(begin, text.rfind('\n', end) - begin);
    };
    const std::string plain = previewGemmaProgram(caseStudy, Dialect::Iec).text;
    const std::string f1 = branchOf(plain, "8");
    // Figure 8's shape: the entry block, the second call, the token, Complete.
    CHECK(f1.find("    IF Entry THEN\n        F1(Initialization := Entry);\n        Entry := FALSE;\n") != std::string::npos);
    CHECK(f1.find("\n    F1(Initialization := Entry);\n") != std::string::npos);
    CHECK(f1.find("ELSIF Stop_F1_3_MEM AND F1.Complete THEN") != std::string::npos);
    int withF1 = 0;
    for (std::uint32_t seed = 1; seed <= 20; ++seed) {
        INFO("seed " << seed);
        Model nested = caseStudy;
        std::mt19937 random(seed);
        REQUIRE(samples::addValidRandomNestedGrafcets(nested, random) > 0);
        withF1 += nested.effectiveGrafcet("F1") ? 1 : 0;
        if (seed % 2 == 0)
            nested.setEvolutionRule(EvolutionRule::UntilStable);
        CHECK(branchOf(previewGemmaProgram(nested, Dialect::Iec).text, "8") == f1);
    }
    CHECK(withF1 >= 5); // F1 itself has a GRAFCET in enough of them
}

TEST_CASE("The shipped example is clean and generates every layer", "[nested-code][example]")
{
    const auto loaded = loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    REQUIRE(loaded.model);
    const Model& model = *loaded.model;
    CHECK(checkModel(model).empty());
    int grafcets = 0;
    for (const Step& step : model.steps())
        grafcets += model.effectiveGrafcet(step.id) ? 1 : 0;
    CHECK(grafcets >= 4);
    for (const Variable& v : model.variables())
        CHECK_FALSE(v.comment.empty());
    const std::string fb = functionBlock(model, "F1_FB");
    CHECK(contains(fb, "GG_T5_2000ms(IN := X5, PT := T#2s);"));
    CHECK(contains(fb, "PartCount := PartCount + 1;"));
}

TEST_CASE("The faulty copy of the example shows the nested checks", "[nested-code][example]")
{
    const auto loaded = loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell-faulty.ggstudio.json");
    REQUIRE(loaded.model);
    std::vector<std::string> found;
    for (const Diagnostic& d : checkModel(*loaded.model)) {
        if (d.code.rfind("GG4", 0) == 0 && std::find(found.begin(), found.end(), d.code) == found.end())
            found.push_back(d.code);
    }
    std::sort(found.begin(), found.end());
    // GG419 needs the until-stable rule: tests/core/test_grafcetchecks.cpp shows it.
    CHECK(found == std::vector<std::string>{"GG400", "GG401", "GG402", "GG403", "GG404", "GG405", "GG406",
                                            "GG410", "GG411", "GG412", "GG413", "GG414", "GG415", "GG416",
                                            "GG417", "GG418", "GG420", "GG421", "GG422"});
}

TEST_CASE("An assigned value that does not fit names the variable and the value", "[nested-program]")
{
    Model model = smallModel();
    REQUIRE(model.addVariable(samples::variable("S", IecType::Bool, VariableKind::Output)));
    struct Case {
        std::string action;
        std::string message;
    };
    const std::vector<Case> cases = {
        {"S := 3", "in action 2 of step 3 of F1: 3 is an integer, not a BOOL value: it cannot be assigned to 'S' (BOOL)"},
        {"Count := 1.5",
         "in action 2 of step 3 of F1: 1.5 is a real number, not an INT value: it cannot be assigned to 'Count' (INT)"},
        {"Complete := Count + 1", "in action 2 of step 3 of F1: Count + 1 is an integer, not a BOOL value: it cannot "
                                  "be assigned to Complete (BOOL)"},
        // An undeclared target has no type: only that is reported (it used to
        // add "the value does not fit '' (BOOL)").
        {"Nope := 3", "in action 2 of step 3 of F1: 'Nope' is not a declared variable"},
    };
    for (const Case& c : cases) {
        Model copy(model);
        REQUIRE(copy.addGrafcetAction("F1", 3, {ActionTiming::OnActivation, c.action}));
        const GemmaProgram program = buildGemmaProgram(copy);
        INFO(c.action);
        REQUIRE(codes(program) == std::vector<std::string>{"GG405"});
        CHECK(firstNested(program).message == c.message);
        CHECK(firstNested(program).actionIndex == 1);
    }
    Model assigned(model);
    REQUIRE(assigned.addGrafcetAction("F1", 3, {ActionTiming::OnActivation, "S := 3"}));
    const ProgramProblem problem = firstNested(buildGemmaProgram(assigned));
    CHECK(problem.arguments == std::vector<std::string>{"F1", "action 2 of step 3 of F1", "S", "BOOL", "3"});
    REQUIRE(problem.span.has_value());
    CHECK(*problem.span == Span{5, 6});
}

} // namespace test_nestedcode
