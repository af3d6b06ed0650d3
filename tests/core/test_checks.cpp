#include <catch2/catch.hpp>

#include "core/checks/checks.h"
#include "core/checks/diagnostic.h"
#include "core/model/model.h"

#include <algorithm>
#include <string>
#include <vector>

namespace test_checks {

using namespace core;

namespace {

// The template with every condition set to `Go` (a declared BOOL): no
// diagnostic at all, so each test can break one thing and look for it alone.
Model cleanModel()
{
    Model model;
    REQUIRE(model.addVariable({"Go", IecType::Bool, "", ""}));
    for (const Transition& transition : model.transitions())
        REQUIRE(model.setCondition(transition.id, "Go"));
    return model;
}

void addVariable(Model& model, std::string name, IecType type = IecType::Bool, std::string defaultValue = {})
{
    REQUIRE(model.addVariable({std::move(name), type, std::move(defaultValue), ""}));
}

std::vector<Diagnostic> withCode(const std::vector<Diagnostic>& diagnostics, std::string_view code)
{
    std::vector<Diagnostic> result;
    std::copy_if(diagnostics.begin(), diagnostics.end(), std::back_inserter(result),
                 [&](const Diagnostic& d) { return d.code == code; });
    return result;
}

// The single diagnostic with this code on this element; fails the test otherwise.
Diagnostic only(const std::vector<Diagnostic>& diagnostics, std::string_view code, std::string_view element)
{
    std::vector<Diagnostic> found;
    for (const Diagnostic& d : diagnostics) {
        if (d.code == code && d.element == element)
            found.push_back(d);
    }
    INFO("code " << code << " on " << element);
    REQUIRE(found.size() == 1);
    return found.front();
}

bool has(const std::vector<Diagnostic>& diagnostics, std::string_view code, std::string_view element)
{
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [&](const Diagnostic& d) { return d.code == code && d.element == element; });
}

std::vector<std::string> codes(const std::vector<Diagnostic>& diagnostics)
{
    std::vector<std::string> result;
    for (const Diagnostic& d : diagnostics)
        result.push_back(d.code + " " + d.element);
    return result;
}

bool mentions(const Diagnostic& diagnostic, std::string_view text)
{
    return diagnostic.message.find(text) != std::string::npos;
}

} // namespace

TEST_CASE("the plain template reports exactly one empty condition per transition", "[checks]")
{
    const Model model;
    const std::vector<Diagnostic> diagnostics = checkModel(model);
    REQUIRE(diagnostics.size() == model.transitions().size());
    for (std::size_t i = 0; i < diagnostics.size(); ++i) {
        const Diagnostic& d = diagnostics[i];
        CHECK(d.code == "GG202");
        CHECK(d.severity == Severity::Error);
        CHECK(d.target == Diagnostic::Target::Transition);
        CHECK(d.element == model.transitions()[i].id); // template order
        CHECK(d.field == "condition");
        CHECK(mentions(d, d.element));
        CHECK(d.arguments == std::vector<std::string>{d.element});
    }
    CHECK(hasErrors(diagnostics));
}

TEST_CASE("a fully specified template has no diagnostic", "[checks]")
{
    const Model model = cleanModel();
    const std::vector<Diagnostic> diagnostics = checkModel(model);
    INFO(Catch::Detail::stringify(codes(diagnostics)));
    CHECK(diagnostics.empty());
    CHECK_FALSE(hasErrors(diagnostics));
}

TEST_CASE("GG001: the initial step is hidden", "[checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setStepHidden("A6", true));
    std::vector<Diagnostic> diagnostics = checkModel(model);
    const Diagnostic d = only(diagnostics, "GG001", "A6");
    CHECK(d.severity == Severity::Error);
    CHECK(d.target == Diagnostic::Target::Step);
    CHECK(d.field == "initial");
    CHECK(mentions(d, "A6"));
    // Reachability from a hidden initial step means nothing: only GG001 explains it.
    CHECK(withCode(diagnostics, "GG103").empty());

    REQUIRE(model.setInitialStep("A1"));
    diagnostics = checkModel(model);
    CHECK(withCode(diagnostics, "GG001").empty());
}

TEST_CASE("GG101: a visible step without effective outgoing transition", "[checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setTransitionHidden("A3->A4", true));
    const Diagnostic d = only(checkModel(model), "GG101", "A3");
    CHECK(d.severity == Severity::Error);
    CHECK(d.field == "outgoing");
    CHECK(mentions(d, "step A3"));
    CHECK(d.arguments == std::vector<std::string>{"A3"});

    SECTION("fixed by showing the transition again")
    {
        REQUIRE(model.setTransitionHidden("A3->A4", false));
        CHECK(checkModel(model).empty());
    }
    SECTION("a transition to a hidden step is not effective")
    {
        REQUIRE(model.setTransitionHidden("A3->A4", false));
        REQUIRE(model.setStepHidden("A4", true));
        CHECK(has(checkModel(model), "GG101", "A3"));
    }
    SECTION("a hidden step is not checked")
    {
        REQUIRE(model.setStepHidden("A3", true));
        CHECK_FALSE(has(checkModel(model), "GG101", "A3"));
    }
}

TEST_CASE("GG101: the family transition is a way out of every F step", "[checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setTransitionHidden("F2->F1", true));
    CHECK_FALSE(has(checkModel(model), "GG101", "F2"));
    REQUIRE(model.setTransitionHidden("F->D1", true));
    CHECK(has(checkModel(model), "GG101", "F2"));
}

TEST_CASE("GG102: a visible step without effective incoming transition", "[checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setTransitionHidden("A1->F2", true));
    std::vector<Diagnostic> diagnostics = checkModel(model);
    const Diagnostic d = only(diagnostics, "GG102", "F2");
    CHECK(d.severity == Severity::Warning);
    CHECK(d.field == "incoming");
    CHECK(mentions(d, "step F2"));
    CHECK_FALSE(has(diagnostics, "GG103", "F2")); // GG102 already says it
    CHECK(diagnostics.size() == 1);

    REQUIRE(model.setTransitionHidden("A1->F2", false));
    CHECK(checkModel(model).empty());
}

TEST_CASE("GG102: the initial step needs no incoming transition", "[checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setInitialStep("A7"));
    REQUIRE(model.setTransitionHidden("A5->A7", true));
    const std::vector<Diagnostic> diagnostics = checkModel(model);
    CHECK_FALSE(has(diagnostics, "GG102", "A7"));
}

TEST_CASE("GG102: D1 entered only through the family transition needs a visible F step", "[checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setTransitionHidden("F1->D1", true));
    REQUIRE(model.setTransitionHidden("F6->D1", true));
    CHECK_FALSE(has(checkModel(model), "GG102", "D1")); // F->D1 from the visible F steps
    for (const char* id : {"F1", "F2", "F3", "F4", "F5", "F6"})
        REQUIRE(model.setStepHidden(id, true));
    CHECK(has(checkModel(model), "GG102", "D1"));
}

TEST_CASE("GG103: visible steps not reachable from the initial step", "[checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setTransitionHidden("A6->A1", true));
    const std::vector<Diagnostic> diagnostics = checkModel(model);
    CHECK(has(diagnostics, "GG101", "A6"));
    const std::vector<Diagnostic> unreachable = withCode(diagnostics, "GG103");
    REQUIRE(unreachable.size() == model.steps().size() - 1);
    for (const Diagnostic& d : unreachable) {
        CHECK(d.element != "A6");
        CHECK(d.severity == Severity::Warning);
        CHECK(d.target == Diagnostic::Target::Step);
        CHECK(d.arguments == std::vector<std::string>{d.element, "A6"});
        CHECK(mentions(d, "step " + d.element));
    }
    CHECK(unreachable.front().element == "A1"); // steps in state order
    CHECK(unreachable.back().element == "D3");

    REQUIRE(model.setTransitionHidden("A6->A1", false));
    CHECK(checkModel(model).empty());
}

TEST_CASE("GG201: syntax error in an effective condition, with its span", "[checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setCondition("A1->F4", "Go AND )"));
    std::vector<Diagnostic> diagnostics = checkModel(model);
    const Diagnostic d = only(diagnostics, "GG201", "A1->F4");
    CHECK(d.severity == Severity::Error);
    CHECK(d.field == "condition");
    REQUIRE(d.span.has_value());
    CHECK(*d.span == Span{7, 8});
    CHECK(mentions(d, "A1->F4"));
    // transition, text at the span, English detail, then the parse error's kind and pieces.
    REQUIRE(d.arguments.size() == 7);
    CHECK(d.arguments[0] == "A1->F4");
    CHECK(d.arguments[1] == ")");
    CHECK(d.arguments[2] == "expected an operand after 'AND', found ')'");
    CHECK(std::vector<std::string>(d.arguments.begin() + 3, d.arguments.end())
          == std::vector<std::string>{"operand-after", ")", "AND", "0"});
    CHECK(diagnostics.size() == 1);

    SECTION("not checked on a hidden transition")
    {
        REQUIRE(model.setTransitionHidden("A1->F4", true));
        CHECK(checkModel(model).empty());
    }
    SECTION("not checked when an end of the transition is hidden")
    {
        REQUIRE(model.setStepHidden("F4", true));
        CHECK_FALSE(has(checkModel(model), "GG201", "A1->F4"));
    }
    SECTION("fixed")
    {
        REQUIRE(model.setCondition("A1->F4", "Go AND (Go)"));
        CHECK(checkModel(model).empty());
    }
}

TEST_CASE("GG202: empty or blank condition on an effective transition only", "[checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setCondition("F3->A1", " \t "));
    const Diagnostic d = only(checkModel(model), "GG202", "F3->A1");
    CHECK(d.severity == Severity::Error);
    CHECK(d.field == "condition");
    CHECK(mentions(d, "F3->A1"));
    CHECK(mentions(d, "TRUE"));
    REQUIRE(model.setTransitionHidden("F3->A1", true));
    CHECK_FALSE(has(checkModel(model), "GG202", "F3->A1"));
}

TEST_CASE("GG203: undeclared variable in a condition, with its span", "[checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setCondition("A2->A1", "Go AND Missing"));
    std::vector<Diagnostic> diagnostics = checkModel(model);
    const Diagnostic d = only(diagnostics, "GG203", "A2->A1");
    CHECK(d.severity == Severity::Error);
    CHECK(d.field == "condition");
    REQUIRE(d.span.has_value());
    CHECK(*d.span == Span{7, 14});
    CHECK(mentions(d, "A2->A1"));
    CHECK(mentions(d, "Missing"));
    REQUIRE(d.arguments.size() == 3);
    CHECK(d.arguments[1] == "Missing");

    addVariable(model, "MISSING"); // names match case-insensitively
    CHECK(checkModel(model).empty());
}

TEST_CASE("GG204: type error in a condition, with its span", "[checks]")
{
    Model model = cleanModel();
    addVariable(model, "Speed", IecType::Int);
    REQUIRE(model.setCondition("A2->A1", "Go AND Speed + 1"));
    const Diagnostic d = only(checkModel(model), "GG204", "A2->A1");
    CHECK(d.severity == Severity::Error);
    REQUIRE(d.span.has_value());
    CHECK(d.span->begin >= 7);
    CHECK(d.span->end <= 16);
    CHECK(mentions(d, "A2->A1"));
    // transition, text at the span, English detail, then the type error's kind and pieces.
    CHECK(d.arguments == std::vector<std::string>{"A2->A1", "Speed + 1",
                                                  "AND needs BOOL operands, but 'Speed + 1' is an integer",
                                                  "bool-operands", "AND", "Speed + 1", "integer", "", ""});

    REQUIRE(model.setCondition("A2->A1", "Go AND Speed + 1 > 3"));
    CHECK(checkModel(model).empty());
}

TEST_CASE("GG205: negation of a transition out of a simple step", "[checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setNegated("A1->F4", true));
    const Diagnostic d = only(checkModel(model), "GG205", "A1->F4");
    CHECK(d.severity == Severity::Warning);
    CHECK(d.field == "negated");
    CHECK(d.arguments == std::vector<std::string>{"A1->F4", "A1"});
    CHECK(mentions(d, "A1->F4"));

    REQUIRE(model.setStepType("A1", StepType::Enclosing)); // now the negation means "wait for Complete"
    CHECK(checkModel(model).empty());
}

TEST_CASE("GG205 does not fire for the default negated F1->D1", "[checks]")
{
    Model model = cleanModel();
    REQUIRE(model.transition("F1->D1")->negated);
    CHECK(withCode(checkModel(model), "GG205").empty());
    REQUIRE(model.setStepType("F1", StepType::Simple));
    CHECK(has(checkModel(model), "GG205", "F1->D1"));
}

TEST_CASE("GG206: negated family transition", "[checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setNegated("F->D1", true));
    const Diagnostic d = only(checkModel(model), "GG206", "F->D1");
    CHECK(d.severity == Severity::Warning);
    CHECK(d.field == "negated");
    CHECK(mentions(d, "F->D1"));
    REQUIRE(model.setNegated("F->D1", false));
    CHECK(checkModel(model).empty());
}

TEST_CASE("tokens: a valid token gives no diagnostic", "[checks]")
{
    Model model = cleanModel();
    addVariable(model, "Stop");
    REQUIRE(model.setCondition("F1->A2", "NOT Stop"));
    REQUIRE(model.setTokens("F1->A2", {"Stop"}));
    CHECK(checkModel(model).empty());
    REQUIRE(model.setCondition("F1->A2", "Go AND stop")); // normally open, any case
    CHECK(checkModel(model).empty());
}

TEST_CASE("GG207: token on a non-BOOL variable", "[checks]")
{
    Model model = cleanModel();
    addVariable(model, "Speed", IecType::Int);
    REQUIRE(model.setCondition("F1->A2", "Go AND Speed > 3"));
    REQUIRE(model.setTokens("F1->A2", {"Speed"}));
    const Diagnostic d = only(checkModel(model), "GG207", "F1->A2");
    CHECK(d.severity == Severity::Error);
    CHECK(d.field == "tokens");
    CHECK(d.arguments == std::vector<std::string>{"F1->A2", "Speed", "INT"});
    CHECK(mentions(d, "F1->A2"));
    CHECK(mentions(d, "'Speed'"));
    CHECK(checkModel(model).size() == 1);
    REQUIRE(model.setTokens("F1->A2", {}));
    CHECK(checkModel(model).empty());
}

TEST_CASE("GG208: token on a variable absent from the condition", "[checks]")
{
    Model model = cleanModel();
    addVariable(model, "Stop");
    REQUIRE(model.setCondition("F1->A3", "Stop"));
    REQUIRE(model.setTokens("F1->A2", {"Stop"}));
    const Diagnostic d = only(checkModel(model), "GG208", "F1->A2");
    CHECK(d.severity == Severity::Error);
    CHECK(d.field == "tokens");
    CHECK(d.arguments == std::vector<std::string>{"F1->A2", "Stop"});
    CHECK(checkModel(model).size() == 1);
    REQUIRE(model.setCondition("F1->A2", "Go AND NOT Stop"));
    CHECK(checkModel(model).empty());
}

TEST_CASE("GG209: token on a variable used with both polarities", "[checks]")
{
    Model model = cleanModel();
    addVariable(model, "Stop");
    REQUIRE(model.setCondition("F1->A2", "(Go AND Stop) OR (NOT Go AND NOT Stop)"));
    REQUIRE(model.setTokens("F1->A2", {"Stop"}));
    const Diagnostic d = only(checkModel(model), "GG209", "F1->A2");
    CHECK(d.severity == Severity::Error);
    CHECK(d.field == "tokens");
    CHECK(mentions(d, "NOT Stop"));
    CHECK(checkModel(model).size() == 1);
    REQUIRE(model.setCondition("F1->A2", "(Go AND Stop) OR (NOT Go AND Stop)"));
    CHECK(checkModel(model).empty());
}

TEST_CASE("GG210: token on a transition whose source has no nested behaviour", "[checks]")
{
    Model model = cleanModel();
    addVariable(model, "Stop");
    REQUIRE(model.setCondition("A1->F4", "Stop"));
    REQUIRE(model.setTokens("A1->F4", {"Stop"}));
    REQUIRE(model.setCondition("F->D1", "Stop"));
    REQUIRE(model.setTokens("F->D1", {"Nothing"})); // ignored anyway: no GG211
    std::vector<Diagnostic> diagnostics = checkModel(model);
    const Diagnostic simple = only(diagnostics, "GG210", "A1->F4");
    CHECK(simple.severity == Severity::Warning);
    CHECK(simple.field == "tokens");
    CHECK(mentions(simple, "A1"));
    const Diagnostic family = only(diagnostics, "GG210", "F->D1");
    CHECK(family.arguments == std::vector<std::string>{"F->D1", "Nothing"});
    CHECK(diagnostics.size() == 2);

    REQUIRE(model.setStepType("A1", StepType::Macro));
    REQUIRE(model.setTokens("F->D1", {}));
    CHECK(checkModel(model).empty());
}

TEST_CASE("GG211: token on an undeclared variable", "[checks]")
{
    Model model = cleanModel();
    addVariable(model, "Stop");
    REQUIRE(model.setCondition("F1->A2", "NOT Stop"));
    REQUIRE(model.setTokens("F1->A2", {"Stop"}));
    REQUIRE(model.removeVariable("Stop")); // the model keeps the token
    const std::vector<Diagnostic> diagnostics = checkModel(model);
    const Diagnostic d = only(diagnostics, "GG211", "F1->A2");
    CHECK(d.severity == Severity::Error);
    CHECK(d.field == "tokens");
    CHECK(d.arguments == std::vector<std::string>{"F1->A2", "Stop"});
    CHECK(has(diagnostics, "GG203", "F1->A2"));
    addVariable(model, "Stop");
    CHECK(checkModel(model).empty());
}

TEST_CASE("GG212: token on a variable compared with = or <>", "[checks]")
{
    Model model = cleanModel();
    addVariable(model, "Stop");
    REQUIRE(model.setTokens("F1->A2", {"Stop"}));
    for (const char* condition : {"Go AND (Stop = Go)", "Stop <> FALSE", "NOT Stop = Go", "Stop AND (Go = Stop)"}) {
        INFO(condition);
        REQUIRE(model.setCondition("F1->A2", condition));
        const std::vector<Diagnostic> diagnostics = checkModel(model);
        const Diagnostic d = only(diagnostics, "GG212", "F1->A2");
        CHECK(d.severity == Severity::Error);
        CHECK(d.field == "tokens");
        CHECK(d.arguments == std::vector<std::string>{"F1->A2", "Stop"});
        CHECK(diagnostics.size() == 1);
    }
    REQUIRE(model.setCondition("F1->A2", "Stop AND (Go = TRUE)"));
    CHECK(checkModel(model).empty());
}

TEST_CASE("tokens are not matched against a condition that does not parse", "[checks]")
{
    Model model = cleanModel();
    addVariable(model, "Stop");
    REQUIRE(model.setCondition("F1->A2", "Go AND"));
    REQUIRE(model.setTokens("F1->A2", {"Stop"}));
    const std::vector<Diagnostic> diagnostics = checkModel(model);
    CHECK(has(diagnostics, "GG201", "F1->A2"));
    CHECK_FALSE(has(diagnostics, "GG208", "F1->A2"));
}

TEST_CASE("GG213: a TRUE condition that shadows lower-priority transitions", "[checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setCondition("A1->F4", "TRUE"));
    const Diagnostic d = only(checkModel(model), "GG213", "A1->F4");
    CHECK(d.severity == Severity::Warning);
    CHECK(d.field == "condition");
    CHECK(d.arguments == std::vector<std::string>{"A1->F4", "A1->F2, A1->F1, A1->F5"});
    CHECK(mentions(d, "A1->F2, A1->F1, A1->F5"));

    SECTION("the last transition shadows nothing")
    {
        REQUIRE(model.setCondition("A1->F4", "Go"));
        REQUIRE(model.setCondition("A1->F5", "true"));
        CHECK(checkModel(model).empty());
    }
    SECTION("hidden lower-priority transitions do not count")
    {
        for (const char* id : {"A1->F2", "A1->F1", "A1->F5"})
            REQUIRE(model.setTransitionHidden(id, true));
        CHECK_FALSE(has(checkModel(model), "GG213", "A1->F4"));
    }
    SECTION("a transition that waits for Complete shadows nothing")
    {
        REQUIRE(model.setStepType("A1", StepType::Macro));
        CHECK(checkModel(model).empty());
        REQUIRE(model.setNegated("A1->F4", true)); // a negated macro transition does not wait
        CHECK(has(checkModel(model), "GG213", "A1->F4"));
    }
}

TEST_CASE("GG213: a TRUE family transition shadows the own transitions of every F step", "[checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setCondition("F->D1", "TRUE"));
    REQUIRE(model.setStepHidden("F3", true));
    const Diagnostic d = only(checkModel(model), "GG213", "F->D1");
    REQUIRE(d.arguments.size() == 2);
    CHECK(d.arguments[1].find("F1->D1") == 0);
    CHECK(d.arguments[1].find("F2->F1") != std::string::npos);
    CHECK(d.arguments[1].find("F6->F1") != std::string::npos);
    CHECK(d.arguments[1].find("F3->") == std::string::npos);
    CHECK(d.arguments[1].find("F1->F3") == std::string::npos);
}

TEST_CASE("GG214: a FALSE condition never fires", "[checks]")
{
    Model model = cleanModel();
    REQUIRE(model.setCondition("D2->A5", "FALSE"));
    const Diagnostic d = only(checkModel(model), "GG214", "D2->A5");
    CHECK(d.severity == Severity::Warning);
    CHECK(d.field == "condition");
    CHECK(mentions(d, "D2->A5"));
    REQUIRE(model.setCondition("D2->A5", "Go AND FALSE = Go"));
    CHECK(checkModel(model).empty());
}

TEST_CASE("GG301..GG303: invalid and reserved variable names", "[checks]")
{
    Model model = cleanModel();
    addVariable(model, "Bad__Name");
    addVariable(model, "Motor_");
    addVariable(model, "2Fast");
    addVariable(model, "Vitesse_é");
    addVariable(model, "Bool");
    addVariable(model, "elsif");
    addVariable(model, "State");
    addVariable(model, "Stop_F1_3_MEM");
    addVariable(model, "Good_Name");
    std::string all;
    for (const Variable& v : model.variables())
        all += (all.empty() ? "" : " OR ") + v.name;
    REQUIRE(model.setCondition("A1->F4", all)); // used, and maybe not parseable
    const std::vector<Diagnostic> diagnostics = checkModel(model);

    for (const char* name : {"Bad__Name", "Motor_", "2Fast", "Vitesse_é"}) {
        const Diagnostic d = only(diagnostics, "GG301", name);
        CHECK(d.severity == Severity::Error);
        CHECK(d.target == Diagnostic::Target::Variable);
        CHECK(d.field == "name");
        CHECK(mentions(d, std::string("'") + name + "'"));
    }
    for (const char* name : {"Bool", "elsif"})
        CHECK(only(diagnostics, "GG302", name).field == "name");
    for (const char* name : {"State", "Stop_F1_3_MEM"})
        CHECK(only(diagnostics, "GG303", name).field == "name");
    for (const char* name : {"Go", "Good_Name"}) {
        INFO(name);
        CHECK(std::none_of(diagnostics.begin(), diagnostics.end(), [&](const Diagnostic& d) {
            return d.target == Diagnostic::Target::Variable && d.element == name;
        }));
    }
}

TEST_CASE("GG304: default value not a literal of the type or out of range", "[checks]")
{
    Model model = cleanModel();
    addVariable(model, "Small", IecType::Sint, "300");
    addVariable(model, "Flag", IecType::Bool, "yes");
    addVariable(model, "Count", IecType::Uint, "12");
    REQUIRE(model.setCondition("A1->F4", "Flag AND Small > 0 AND Count > 0"));
    std::vector<Diagnostic> diagnostics = checkModel(model);
    const Diagnostic d = only(diagnostics, "GG304", "Small");
    CHECK(d.severity == Severity::Error);
    CHECK(d.field == "default");
    // variable, default value, English detail, then the value problem's kind and pieces.
    CHECK(d.arguments == std::vector<std::string>{"Small", "300", "'300' is out of range for SINT (-128..127)",
                                                  "out-of-range", "300", "SINT", "-128", "127"});
    CHECK(mentions(d, "'Small'"));
    CHECK(has(diagnostics, "GG304", "Flag"));
    CHECK_FALSE(has(diagnostics, "GG304", "Count"));

    REQUIRE(model.setVariableDefault("Small", "-128"));
    REQUIRE(model.setVariableDefault("Flag", "TRUE"));
    CHECK(checkModel(model).empty());
}

TEST_CASE("GG305: variable unused by every effective condition", "[checks]")
{
    Model model = cleanModel();
    addVariable(model, "Spare");
    std::vector<Diagnostic> diagnostics = checkModel(model);
    const Diagnostic d = only(diagnostics, "GG305", "Spare");
    CHECK(d.severity == Severity::Warning);
    CHECK(d.field == "name");
    CHECK(mentions(d, "'Spare'"));
    CHECK(diagnostics.size() == 1);

    SECTION("a hidden transition does not count as a use")
    {
        REQUIRE(model.setCondition("A1->F4", "Spare"));
        REQUIRE(model.setTransitionHidden("A1->F4", true));
        CHECK(has(checkModel(model), "GG305", "Spare"));
    }
    SECTION("used in any case")
    {
        REQUIRE(model.setCondition("A1->F4", "SPARE"));
        CHECK(checkModel(model).empty());
    }
    SECTION("a condition being typed still counts as a use")
    {
        REQUIRE(model.setCondition("A1->F4", "Spare AND ("));
        diagnostics = checkModel(model);
        CHECK(has(diagnostics, "GG201", "A1->F4"));
        CHECK_FALSE(has(diagnostics, "GG305", "Spare"));
    }
}

TEST_CASE("diagnostics come model, steps, transitions, variables; by field within an element", "[checks]")
{
    Model model = cleanModel();
    addVariable(model, "Spare", IecType::Sint, "999");
    addVariable(model, "Speed", IecType::Int);
    REQUIRE(model.setTransitionHidden("A3->A4", true));       // GG101 A3
    REQUIRE(model.setTransitionHidden("A1->F2", true));       // GG102 F2
    REQUIRE(model.setCondition("F1->A2", "Go AND Speed"));  // GG204 F1->A2
    REQUIRE(model.setNegated("A4->F1", true));                // GG205 A4->F1
    REQUIRE(model.setTokens("F1->A2", {"Speed", "Ghost"}));  // GG207, GG211 F1->A2
    REQUIRE(model.setCondition("A6->A1", "Go OR"));           // GG201 A6->A1

    const std::vector<Diagnostic> diagnostics = checkModel(model);
    const std::vector<std::string> expected{
        "GG101 A3", "GG102 F2", "GG205 A4->F1", "GG201 A6->A1", "GG204 F1->A2", "GG207 F1->A2",
        "GG211 F1->A2", "GG304 Spare", "GG305 Spare",
    };
    CHECK(codes(diagnostics) == expected);
    for (const Diagnostic& d : diagnostics) {
        INFO(d.code << ": " << d.message);
        CHECK(mentions(d, d.element));
        CHECK_FALSE(d.arguments.empty());
        CHECK(d.arguments.front() == d.element);
    }
}

TEST_CASE("severity names, element labels and hasErrors", "[checks]")
{
    CHECK(severityName(Severity::Error) == "error");
    CHECK(severityName(Severity::Warning) == "warning");
    CHECK(severityName(Severity::Info) == "info");

    Diagnostic d;
    CHECK(diagnosticElementLabel(d) == "model");
    d.target = Diagnostic::Target::Transition;
    d.element = "F1->A2";
    CHECK(diagnosticElementLabel(d) == "F1->A2");

    d.severity = Severity::Warning;
    CHECK_FALSE(hasErrors({}));
    CHECK_FALSE(hasErrors({d}));
    Diagnostic error = d;
    error.severity = Severity::Error;
    CHECK(hasErrors({d, error}));
}

} // namespace test_checks
