#include "core/checks/checks.h"
#include "core/checks/grafcetchecks.h"
#include "core/condition/conditionevaluator.h"
#include "core/condition/conditionparser.h"
#include "core/model/model.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace test_grafcetchecks {

using namespace core;

namespace {

GrafcetStep step(int number, bool initial = false, std::vector<GrafcetAction> actions = {})
{
    GrafcetStep s;
    s.number = number;
    s.initial = initial;
    s.actions = std::move(actions);
    return s;
}

GrafcetTransition transition(int number, std::vector<int> upstream, std::vector<int> downstream,
                             std::string receptivity)
{
    GrafcetTransition t;
    t.number = number;
    t.upstream = std::move(upstream);
    t.downstream = std::move(downstream);
    t.receptivity = std::move(receptivity);
    return t;
}

GrafcetAction setComplete()
{
    return {ActionTiming::OnActivation, "S Complete"};
}

Model modelWith(const Grafcet& grafcet, const std::string& stepId = "F1")
{
    Model model;
    for (const char* name : {"A", "B", "Start"})
        REQUIRE(model.addVariable(Variable{name, IecType::Bool, "", ""}));
    REQUIRE(model.addVariable(Variable{"Level", IecType::Int, "", ""}));
    REQUIRE(model.setGrafcet(stepId, grafcet));
    return model;
}

// 1 --A--> 2 (sets Complete): a small correct GRAFCET.
Grafcet correctGrafcet()
{
    Grafcet g;
    REQUIRE(g.addStep(step(1, true)));
    REQUIRE(g.addStep(step(2, false, {setComplete()})));
    REQUIRE(g.addTransition(transition(1, {1}, {2}, "A")));
    return g;
}

std::vector<Diagnostic> withCode(const Model& model, const std::string& code)
{
    std::vector<Diagnostic> found;
    for (const Diagnostic& d : checkGrafcets(model)) {
        if (d.code == code)
            found.push_back(d);
    }
    return found;
}

} // namespace

TEST_CASE("A correct nested GRAFCET gives no finding", "[grafcet-checks]")
{
    CHECK(checkGrafcets(modelWith(correctGrafcet())).empty());
}

TEST_CASE("GG400: a nested GRAFCET without initial step", "[grafcet-checks]")
{
    Grafcet g = correctGrafcet();
    REQUIRE(g.setStepInitial(1, false));
    const auto found = withCode(modelWith(g), "GG400");
    REQUIRE(found.size() == 1);
    CHECK(found[0].severity == Severity::Error);
    CHECK(found[0].target == Diagnostic::Target::Step);
    CHECK(found[0].element == "F1");
    // Without initial steps nothing is reachable: no GG412 flood on top.
    CHECK(withCode(modelWith(g), "GG412").empty());
}

TEST_CASE("GG412: a step that no transition reaches", "[grafcet-checks]")
{
    Grafcet g = correctGrafcet();
    REQUIRE(g.addStep(step(3, false, {setComplete()})));
    REQUIRE(g.addStep(step(4)));
    // 4 needs 3 and 2 together; 3 is never activated.
    REQUIRE(g.addTransition(transition(2, {2, 3}, {4}, "B")));
    const auto found = withCode(modelWith(g), "GG412");
    REQUIRE(found.size() == 2);
    CHECK(found[0].target == Diagnostic::Target::GrafcetStep);
    CHECK(found[0].nestedNumber == 3);
    CHECK(found[1].nestedNumber == 4);
    CHECK(found[0].severity == Severity::Warning);
    CHECK(diagnosticElementLabel(found[0]) == "F1 step 3");
}

TEST_CASE("GG416: a macro-step whose GRAFCET never sets Complete", "[grafcet-checks]")
{
    Grafcet g;
    REQUIRE(g.addStep(step(1, true)));
    REQUIRE(g.addStep(step(2, false, {{ActionTiming::OnActivation, "R Complete"}})));
    REQUIRE(g.addTransition(transition(1, {1}, {2}, "A")));
    REQUIRE(g.addTransition(transition(2, {2}, {1}, "B")));
    Model model = modelWith(g);
    REQUIRE(model.setTransitionHidden("F1->A2", false));
    const auto found = withCode(model, "GG416");
    REQUIRE(found.size() == 1);
    CHECK(found[0].element == "F1");
    CHECK(found[0].message.find("F1->A2") != std::string::npos);

    // A continuous Complete counts as setting it.
    REQUIRE(g.addAction(2, {ActionTiming::Continuous, "Complete"}));
    CHECK(withCode(modelWith(g), "GG416").empty());
}

TEST_CASE("GG417: a selection whose receptivities can hold together, with the valuation", "[grafcet-checks]")
{
    Grafcet g = correctGrafcet();
    REQUIRE(g.addStep(step(3, false, {setComplete()})));
    REQUIRE(g.addTransition(transition(2, {1}, {3}, "B AND Level > 3")));
    Model model = modelWith(g);
    const auto found = withCode(model, "GG417");
    REQUIRE(found.size() == 1);
    CHECK(found[0].target == Diagnostic::Target::GrafcetTransition);
    CHECK(found[0].nestedNumber == 2);
    REQUIRE(found[0].arguments.size() == 5);
    const std::string& witness = found[0].arguments[4];
    CHECK(witness.find("A = TRUE") != std::string::npos);
    CHECK(witness.find("B = TRUE") != std::string::npos);

    // The valuation really makes both TRUE.
    const auto valueOf = [&](const std::string& name) -> cond::Value {
        const std::size_t at = witness.find(name + " = ");
        REQUIRE(at != std::string::npos);
        const std::string rest = witness.substr(at + name.size() + 3);
        const std::string text = rest.substr(0, rest.find(','));
        if (text == "TRUE" || text == "FALSE")
            return text == "TRUE";
        return static_cast<std::int64_t>(std::stoll(text));
    };
    for (const char* receptivity : {"A", "B AND Level > 3"}) {
        const cond::ParseResult parsed = cond::parse(receptivity, {cond::Context::Nested});
        REQUIRE(parsed.ok());
        const cond::Value value = cond::evaluate(parsed.expression, [&](int node) {
            return valueOf(parsed.expression.at(node).text);
        });
        CHECK(cond::isTrue(value));
    }
}

TEST_CASE("GG417 stays silent on exclusive selections, nested atoms included", "[grafcet-checks]")
{
    for (const auto& [first, second] : std::vector<std::pair<std::string, std::string>>{
             {"A", "NOT A"},
             {"Level < 3", "Level >= 3"},
             {"X2 AND A", "NOT X2"},
             {"RE Start", "NOT RE Start AND B"},
             {"5s/X1", "NOT 5s/X1"}}) {
        Grafcet g = correctGrafcet();
        REQUIRE(g.setReceptivity(1, first));
        REQUIRE(g.addStep(step(3, false, {setComplete()})));
        REQUIRE(g.addTransition(transition(2, {1}, {3}, second)));
        INFO(first << " / " << second);
        CHECK(withCode(modelWith(g), "GG417").empty());
    }
}

TEST_CASE("GG418: a dead end that does not set Complete", "[grafcet-checks]")
{
    Grafcet g = correctGrafcet();
    REQUIRE(g.addStep(step(3)));
    REQUIRE(g.addTransition(transition(2, {1}, {3}, "NOT A")));
    const auto found = withCode(modelWith(g), "GG418");
    REQUIRE(found.size() == 1);
    CHECK(found[0].nestedNumber == 3);
    CHECK(found[0].severity == Severity::Warning);
}

TEST_CASE("GG419: until stable, Complete written on a step always left in the same call", "[grafcet-checks]")
{
    // The case study's F1 pattern: 2 sets Complete and 2 -> 1 is always TRUE.
    Grafcet g = correctGrafcet();
    REQUIRE(g.addTransition(transition(2, {2}, {1}, "TRUE")));
    Model model = modelWith(g);
    CHECK(withCode(model, "GG419").empty()); // one evolution per scan: the GEMMA layer sees step 2
    model.setEvolutionRule(EvolutionRule::UntilStable);
    const auto found = withCode(model, "GG419");
    REQUIRE(found.size() == 1);
    CHECK(found[0].nestedNumber == 2);

    // A receptivity that may be FALSE keeps the step for a scan.
    REQUIRE(g.setReceptivity(2, "A OR B"));
    Model waiting = modelWith(g);
    waiting.setEvolutionRule(EvolutionRule::UntilStable);
    CHECK(withCode(waiting, "GG419").empty());
    REQUIRE(g.setReceptivity(2, "A OR NOT A"));
    Model tautology = modelWith(g);
    tautology.setEvolutionRule(EvolutionRule::UntilStable);
    CHECK(withCode(tautology, "GG419").size() == 1);
}

TEST_CASE("GG422: a GRAFCET kept on a hidden or simple step", "[grafcet-checks]")
{
    Model model = modelWith(correctGrafcet());
    REQUIRE(model.setStepHidden("F1", true));
    auto found = withCode(model, "GG422");
    REQUIRE(found.size() == 1);
    CHECK(found[0].severity == Severity::Info);
    CHECK(found[0].arguments == std::vector<std::string>{"F1", "hidden"});
    // Not effective: nothing else is checked in it.
    CHECK(checkGrafcets(model).size() == 1);

    REQUIRE(model.setStepHidden("F1", false));
    REQUIRE(model.setStepType("F1", StepType::Simple));
    found = withCode(model, "GG422");
    REQUIRE(found.size() == 1);
    CHECK(found[0].arguments[1] == "simple");
}

TEST_CASE("Variables used only by nested GRAFCETs are used", "[grafcet-checks]")
{
    Model model = modelWith(correctGrafcet());
    REQUIRE(model.addVariable(Variable{"Lamp", IecType::Bool, "", ""}));
    REQUIRE(model.setVariableKind("Lamp", VariableKind::Output));
    const auto unused = [&] {
        std::vector<std::string> names;
        for (const Diagnostic& d : checkModel(model)) {
            if (d.code == "GG305")
                names.push_back(d.element);
        }
        return names;
    };
    const std::vector<std::string> before = unused();
    CHECK(std::count(before.begin(), before.end(), "Lamp") == 1);
    REQUIRE(model.addGrafcetAction("F1", 2, {ActionTiming::Continuous, "N Lamp IF NOT B"}));
    const std::vector<std::string> after = unused();
    CHECK(std::count(after.begin(), after.end(), "Lamp") == 0);
    CHECK(std::count(after.begin(), after.end(), "B") == 0);
    CHECK(std::count(after.begin(), after.end(), "A") == 0);
}

TEST_CASE("GG420: user variables named like the nested GRAFCETs' generated names", "[grafcet-checks]")
{
    Grafcet g = correctGrafcet();
    REQUIRE(g.setReceptivity(1, "RE A"));
    Model model = modelWith(g);
    for (const char* name : {"X12", "unstable", "GG_Fire1", "A_PREV", "Xylophone", "B_PREV"})
        REQUIRE(model.addVariable(Variable{name, IecType::Bool, "", ""}));
    std::vector<std::string> flagged;
    for (const Diagnostic& d : withCode(model, "GG420"))
        flagged.push_back(d.element);
    CHECK(flagged == std::vector<std::string>{"X12", "unstable", "GG_Fire1", "A_PREV"});
    // Without an effective nested GRAFCET these names are free.
    REQUIRE(model.setStepHidden("F1", true));
    CHECK(withCode(model, "GG420").empty());
}

} // namespace test_grafcetchecks
