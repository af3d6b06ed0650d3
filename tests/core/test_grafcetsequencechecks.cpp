// GG423 (a push button read by its level on consecutive transitions) and
// GG424 (a selection that is not complete): core/checks/grafcetsequencechecks.h.

#include "core/checks/checks.h"
#include "core/checks/grafcetchecks.h"
#include "core/checks/grafcetsequencechecks.h"
#include "core/model/model.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace test_grafcetsequencechecks {

using namespace core;

namespace {

GrafcetStep step(int number, bool initial = false)
{
    GrafcetStep s;
    s.number = number;
    s.initial = initial;
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

// 1 -T1-> 2 -T2-> 3 ..., the last step setting Complete.
Grafcet sequence(const std::vector<std::string>& receptivities)
{
    Grafcet g;
    const int last = static_cast<int>(receptivities.size()) + 1;
    for (int number = 1; number <= last; ++number) {
        GrafcetStep s = step(number, number == 1);
        if (number == last)
            s.actions.push_back(setComplete());
        REQUIRE(g.addStep(s));
    }
    for (int number = 1; number < last; ++number)
        REQUIRE(g.addTransition(transition(number, {number}, {number + 1},
                                           receptivities[static_cast<std::size_t>(number - 1)])));
    return g;
}

// Step 1 with one branch per receptivity, each to a step that sets Complete.
Grafcet selection(const std::vector<std::string>& receptivities)
{
    Grafcet g;
    REQUIRE(g.addStep(step(1, true)));
    for (std::size_t i = 0; i < receptivities.size(); ++i) {
        const int number = static_cast<int>(i) + 2;
        GrafcetStep s = step(number);
        s.actions.push_back(setComplete());
        REQUIRE(g.addStep(s));
        REQUIRE(g.addTransition(transition(static_cast<int>(i) + 1, {1}, {number}, receptivities[i])));
    }
    return g;
}

Model modelWith(const Grafcet& grafcet, EvolutionRule rule = EvolutionRule::OneEvolutionPerScan)
{
    Model model;
    for (const char* name : {"StepButton", "A", "a0", "a1", "CP1", "CP2", "CP3"})
        REQUIRE(model.addVariable(Variable{name, IecType::Bool, "", ""}));
    REQUIRE(model.addVariable(Variable{"Level", IecType::Int, "", ""}));
    REQUIRE(model.addVariable(Variable{"Cycle", IecType::Bool, "", "", VariableKind::Internal}));
    model.setEvolutionRule(rule);
    REQUIRE(model.setGrafcet("F1", grafcet));
    return model;
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

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

} // namespace

TEST_CASE("GG423: a step-by-step mode whose every transition reads StepButton by its level", "[grafcet-sequences]")
{
    const Model model = modelWith(sequence({"StepButton", "StepButton", "StepButton"}));
    const std::vector<Diagnostic> found = withCode(model, "GG423");
    REQUIRE(found.size() == 2);
    for (std::size_t i = 0; i < found.size(); ++i) {
        const Diagnostic& d = found[i];
        const std::string first = "T" + std::to_string(i + 1);
        const std::string second = "T" + std::to_string(i + 2);
        CHECK(d.severity == Severity::Warning);
        CHECK(d.target == Diagnostic::Target::GrafcetTransition);
        CHECK(d.element == "F1");
        CHECK(d.nestedNumber == static_cast<int>(i) + 2);
        CHECK(d.field == "receptivity");
        CHECK(d.arguments
              == std::vector<std::string>{"F1", "StepButton", first, second, std::to_string(i + 2), "one-per-scan"});
        CHECK(contains(d.message, "in consecutive scans"));
        CHECK(contains(d.message, "(\u2191StepButton)"));
    }
}

TEST_CASE("GG423: an edge then a level runs through too", "[grafcet-sequences]")
{
    const std::vector<Diagnostic> found = withCode(modelWith(sequence({"\u2191StepButton", "StepButton AND A"})),
                                                   "GG423");
    REQUIRE(found.size() == 1);
    CHECK(found[0].nestedNumber == 2);
}

TEST_CASE("GG423 stays silent on sensor sequences, edges, negations and memories", "[grafcet-sequences]")
{
    for (const std::vector<std::string>& receptivities : std::vector<std::vector<std::string>>{
             {"a1", "a0", "a1"},
             {"\u2191StepButton", "\u2191StepButton", "RE StepButton"},
             {"StepButton", "NOT StepButton", "StepButton"},
             {"StepButton", "A XOR StepButton"},
             {"StepButton", "StepButton = A"},
             {"Cycle", "Cycle"},
             {"StepButton AND A", "StepButton AND FALSE"}}) {
        INFO(receptivities[0] << " / " << receptivities[1]);
        CHECK(withCode(modelWith(sequence(receptivities)), "GG423").empty());
    }
}

TEST_CASE("GG423 under until stable: one scan runs through, with the same values for both", "[grafcet-sequences]")
{
    const Grafcet held = sequence({"StepButton", "StepButton"});
    const std::vector<Diagnostic> found = withCode(modelWith(held, EvolutionRule::UntilStable), "GG423");
    REQUIRE(found.size() == 1);
    CHECK(found[0].arguments.back() == "until-stable");
    CHECK(contains(found[0].message, "in the same scan"));

    // A changes between scans, not within one.
    const Grafcet exclusive = sequence({"StepButton AND A", "StepButton AND NOT A"});
    CHECK(withCode(modelWith(exclusive), "GG423").size() == 1);
    CHECK(withCode(modelWith(exclusive, EvolutionRule::UntilStable), "GG423").empty());
}

// The F2 figure's selection after step 3: CP1, CP2, CP3 say which parts are there.
const std::vector<std::string> kF2Selection = {"CP1 AND NOT CP2", "CP1 AND CP2 AND NOT CP3", "NOT CP1",
                                               "CP1 AND CP2 AND CP3"};

TEST_CASE("GG424: no information on a complete selection", "[grafcet-sequences]")
{
    CHECK(withCode(modelWith(selection(kF2Selection)), "GG424").empty());
    CHECK(withCode(modelWith(selection({"Level < 3", "Level >= 3"})), "GG424").empty());
}

TEST_CASE("GG424: a selection that is not complete, with the values under which it waits", "[grafcet-sequences]")
{
    std::vector<std::string> branches = kF2Selection;
    branches.erase(branches.begin() + 1);
    const std::vector<Diagnostic> found = withCode(modelWith(selection(branches)), "GG424");
    REQUIRE(found.size() == 1);
    const Diagnostic& d = found[0];
    CHECK(d.severity == Severity::Info);
    CHECK(d.target == Diagnostic::Target::GrafcetStep);
    CHECK(d.nestedNumber == 1);
    CHECK(d.arguments == std::vector<std::string>{"F1", "1", "T1, T2, T3", "CP1 = TRUE, CP2 = TRUE, CP3 = FALSE"});
    CHECK(contains(d.message, "with CP1 = TRUE, CP2 = TRUE, CP3 = FALSE none of T1, T2, T3 fires"));

    // Numbers: the one value both comparisons leave out.
    const std::vector<Diagnostic> gap = withCode(modelWith(selection({"Level < 3", "Level > 3"})), "GG424");
    REQUIRE(gap.size() == 1);
    CHECK(gap[0].arguments[3] == "Level = 3");
}

TEST_CASE("GG424 leaves out what input values cannot decide, and selections too large", "[grafcet-sequences]")
{
    CHECK(withCode(modelWith(selection({"A AND 2s/X1", "NOT A"})), "GG424").empty());
    CHECK(withCode(modelWith(selection({"\u2191A", "CP1"})), "GG424").empty());

    Model model = modelWith(selection({"A", "CP1"}));
    CHECK(withCode(model, "GG424").size() == 1);
    std::vector<std::string> many;
    for (std::size_t i = 1; i <= kMaxSelectionVariables + 1; ++i) {
        const std::string name = "Part" + std::to_string(i);
        REQUIRE(model.addVariable(Variable{name, IecType::Bool, "", ""}));
        many.push_back(name);
    }
    REQUIRE(model.setGrafcet("F1", selection(many)));
    CHECK(withCode(model, "GG424").empty());
}

} // namespace test_grafcetsequencechecks
