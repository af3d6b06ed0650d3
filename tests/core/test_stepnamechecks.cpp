// Variables named like GEMMA steps (a1, b0, d1 are the usual names of limit
// switches): only the instances and function blocks the generated code
// declares, those of visible macro-steps and enclosing steps, are taken.

#include <catch2/catch.hpp>

#include "core/checks/checks.h"
#include "core/codegen/stgenerator.h"
#include "core/model/iectypes.h"
#include "core/model/model.h"
#include "core/model/stepnames.h"

#include <algorithm>
#include <string>
#include <vector>

namespace test_stepnamechecks {

using namespace core;

namespace {

// The template with every condition `Go`, and `a1` read by A1->F4: no
// diagnostic while A1 is a simple step.
Model limitSwitchModel(const std::string& name = "a1")
{
    Model model;
    REQUIRE(model.addVariable({"Go", IecType::Bool, "", ""}));
    REQUIRE(model.addVariable({name, IecType::Bool, "", ""}));
    for (const Transition& transition : model.transitions())
        REQUIRE(model.setCondition(transition.id, "Go"));
    REQUIRE(model.setCondition("A1->F4", "Go AND " + name));
    return model;
}

std::vector<Diagnostic> withCode(const Model& model, const std::string& code)
{
    std::vector<Diagnostic> found;
    for (const Diagnostic& d : checkModel(model)) {
        if (d.code == code)
            found.push_back(d);
    }
    return found;
}

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

} // namespace

TEST_CASE("Step ids are free variable names for every rule that does not see the model", "[step-names]")
{
    for (const char* name : {"a1", "B0", "d1", "F1", "A1_FB", "f4_fb"}) {
        INFO(name);
        CHECK(identifierProblem(name) == IdentifierProblem::None);
        CHECK_FALSE(isGeneratorName(name));
    }
}

TEST_CASE("a1 is a valid variable while A1 is a simple step", "[step-names]")
{
    const Model model = limitSwitchModel();
    CHECK_FALSE(stepNameClash(model, "a1").has_value());
    CHECK(checkModel(model).empty());
    const std::string code = formatSingleFileIec(buildPlcProject(model, Dialect::Iec));
    CHECK(contains(code, "    a1 : BOOL := FALSE;"));
    CHECK(contains(code, "Go AND a1 THEN"));
}

TEST_CASE("GG306 and GG307: a variable named like the instance of a macro-step, on both elements, with the fix",
          "[step-names]")
{
    Model model = limitSwitchModel();
    REQUIRE(model.setStepType("A1", StepType::Macro));

    const std::vector<Diagnostic> onVariable = withCode(model, "GG306");
    REQUIRE(onVariable.size() == 1);
    CHECK(onVariable[0].severity == Severity::Error);
    CHECK(onVariable[0].target == Diagnostic::Target::Variable);
    CHECK(onVariable[0].element == "a1");
    CHECK(onVariable[0].field == "name");
    CHECK(onVariable[0].arguments == std::vector<std::string>{"a1", "A1", "instance", "macro", "a1_Sensor"});
    CHECK(contains(onVariable[0].message, "macro-step A1"));
    CHECK(contains(onVariable[0].message, "rename the variable (for example to 'a1_Sensor')"));

    const std::vector<Diagnostic> onStep = withCode(model, "GG307");
    REQUIRE(onStep.size() == 1);
    CHECK(onStep[0].severity == Severity::Error);
    CHECK(onStep[0].target == Diagnostic::Target::Step);
    CHECK(onStep[0].element == "A1");
    CHECK(onStep[0].arguments == std::vector<std::string>{"A1", "a1", "instance", "macro", "a1_Sensor"});
    CHECK(contains(onStep[0].message, "variable 'a1'"));
    CHECK(contains(onStep[0].message, "rename the variable (for example to 'a1_Sensor')"));

    // The suggestion is free: renaming as suggested clears both.
    REQUIRE(model.renameVariable("a1", "a1_Sensor"));
    CHECK(checkModel(model).empty());
}

TEST_CASE("GG306: the function block name of an enclosing step, and a suggestion that is really free",
          "[step-names]")
{
    Model model = limitSwitchModel("D3_FB");
    REQUIRE(model.addVariable({"D3_FB_Sensor", IecType::Bool, "", ""}));
    REQUIRE(model.setCondition("A1->F4", "Go AND D3_FB AND D3_FB_Sensor"));
    const std::vector<Diagnostic> onVariable = withCode(model, "GG306");
    REQUIRE(onVariable.size() == 1);
    CHECK(onVariable[0].arguments == std::vector<std::string>{"D3_FB", "D3", "function-block", "enclosing",
                                                                "D3_FB_Sensor2"});
    const std::vector<Diagnostic> onStep = withCode(model, "GG307");
    REQUIRE(onStep.size() == 1);
    CHECK(onStep[0].element == "D3");
    CHECK(contains(onStep[0].message, "function block D3_FB"));
}

TEST_CASE("A hidden macro-step reserves nothing until it is shown", "[step-names]")
{
    Model model = limitSwitchModel("F4");
    REQUIRE(model.setStepHidden("F4", true));
    CHECK(withCode(model, "GG306").empty());
    CHECK(withCode(model, "GG307").empty());
    REQUIRE(model.setStepHidden("F4", false));
    CHECK(withCode(model, "GG306").size() == 1);
    REQUIRE(withCode(model, "GG307").size() == 1);
    CHECK(withCode(model, "GG307")[0].element == "F4");
}

TEST_CASE("The generated code never declares a variable under a step instance's name", "[step-names]")
{
    Model model = limitSwitchModel();
    REQUIRE(model.setStepType("A1", StepType::Macro));
    for (Dialect dialect : {Dialect::Iec, Dialect::Codesys}) {
        INFO(dialectName(dialect));
        const PlcProject project = buildPlcProject(model, dialect);
        const std::string globals = formatGlobals(project);
        CHECK_FALSE(contains(globals, " a1 : BOOL"));
        CHECK(contains(globals, "Invalid_Name_2 : BOOL := FALSE; (* ERROR GG306: invalid variable name: 'a1' is the "
                                "instance of macro-step A1 in the generated code; rename the variable (for example "
                                "to 'a1_Sensor')"));
        const std::string gemma = formatPou(project.pous.front(), dialect);
        CHECK(contains(gemma, "A1 : A1_FB;"));
        CHECK(contains(gemma, "(* ERROR GG306: in the condition of A1->F4: invalid variable name: 'a1'"));
    }
}

} // namespace test_stepnamechecks
