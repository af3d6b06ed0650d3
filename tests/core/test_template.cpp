#include "core/templates/gemma/gemmatemplate.h"

#include <catch2/catch.hpp>

#include <map>
#include <set>
#include <string>

namespace test_template {

using namespace core;

TEST_CASE("The template has the 16 GEMMA states of the spec", "[template]")
{
    const auto states = templateStates();
    REQUIRE(states.size() == 16);
    int initialCount = 0;
    for (std::size_t i = 0; i < states.size(); ++i) {
        CHECK(states[i].number == static_cast<int>(i) + 1);
        initialCount += states[i].defaultInitial ? 1 : 0;
    }
    CHECK(initialCount == 1);
    CHECK(findTemplateState("A6")->defaultInitial);
    CHECK(findTemplateState("A7")->defaultType == StepType::Macro);
    CHECK(findTemplateState("F4")->defaultType == StepType::Enclosing);
    CHECK(findTemplateState("F6")->defaultType == StepType::Enclosing);
    CHECK(findTemplateState("D3")->defaultType == StepType::Enclosing);
    CHECK(findTemplateState("D1")->family == Family::D);
    CHECK(findTemplateState("D1")->number == 14);
    CHECK(findTemplateState("F1")->englishName == "Normal production");
    CHECK(findTemplateState("X9") == nullptr);
}

TEST_CASE("The template has the 34 transitions with priorities 1..n per source", "[template]")
{
    const auto transitions = templateTransitions();
    REQUIRE(transitions.size() == 34);
    std::map<std::string, std::set<int>> priorities;
    std::set<std::string> ids;
    int negated = 0;
    for (const TemplateTransition& t : transitions) {
        priorities[std::string(t.source)].insert(t.defaultPriority);
        ids.insert(makeTransitionId(t.source, t.target));
        CHECK(findTemplateState(t.target) != nullptr);
        CHECK((t.source == kFamilySource || findTemplateState(t.source) != nullptr));
        negated += t.defaultNegated ? 1 : 0;
    }
    CHECK(ids.size() == 34);
    CHECK(negated == 1);
    CHECK(ids.count("F->D1") == 1);
    for (const auto& [source, set] : priorities) {
        INFO(source);
        CHECK(*set.begin() == 1);
        CHECK(*set.rbegin() == static_cast<int>(set.size()));
    }
    CHECK(priorities["F1"].size() == 9);
    CHECK(priorities["A1"].size() == 4);
}

} // namespace test_template
