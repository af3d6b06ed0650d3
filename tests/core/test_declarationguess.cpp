// The quick fix of an undeclared name: which name a diagnostic reports, and
// the kind and type guessed from where the model uses it.

#include "samplemodels.h"

#include "core/checks/checks.h"
#include "core/checks/undeclaredvariable.h"
#include "core/condition/declarationguess.h"
#include "core/model/model.h"
#include "core/templates/packml/packmlmodel.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace test_declarationguess {

using namespace core;

namespace {

void require(const Status& status)
{
    INFO(status.message);
    REQUIRE(status.ok);
}

// nestedMachine with F1: 1 --RECEPTIVITY--> 2 (ACTIONS) --A--> 1, and a UINT input Level.
Model machineWith(std::string receptivity, std::vector<GrafcetAction> actions = {})
{
    Model model = samples::nestedMachine();
    require(model.addVariable(samples::variable("Level", IecType::Uint, VariableKind::Input)));
    actions.push_back({ActionTiming::OnActivation, "S Complete"});
    samples::addMachineStep(model, 1, true);
    samples::addMachineStep(model, 2, false, std::move(actions));
    samples::addMachineTransition(model, 1, {1}, {2}, std::move(receptivity));
    samples::addMachineTransition(model, 2, {2}, {1}, "A");
    return model;
}

DeclarationGuess guess(VariableKind kind, IecType type)
{
    return DeclarationGuess{kind, type};
}

std::vector<std::string> undeclaredNames(const Model& model)
{
    std::vector<std::string> names;
    for (const Diagnostic& d : checkModel(model)) {
        if (const std::optional<std::string> name = undeclaredVariable(model, d))
            names.push_back(d.code + " " + *name);
    }
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace

TEST_CASE("a name read in a receptivity or a GEMMA condition is a BOOL input", "[declarationguess]")
{
    CHECK(guessDeclaration(machineWith("Go"), "Go") == guess(VariableKind::Input, IecType::Bool));
    CHECK(guessDeclaration(machineWith("NOT go AND A"), "GO") == guess(VariableKind::Input, IecType::Bool));
    Model model = machineWith("A");
    require(model.setCondition("A2->A1", "Ready OR B"));
    CHECK(guessDeclaration(model, "Ready") == guess(VariableKind::Input, IecType::Bool));
}

TEST_CASE("a name read under an edge is a BOOL input", "[declarationguess]")
{
    CHECK(guessDeclaration(machineWith("RE Push"), "Push") == guess(VariableKind::Input, IecType::Bool));
    CHECK(guessDeclaration(machineWith("↓Push AND A"), "Push") == guess(VariableKind::Input, IecType::Bool));
}

TEST_CASE("a name compared with a number takes the number's type, or the other operand's", "[declarationguess]")
{
    CHECK(guessDeclaration(machineWith("Count > 3"), "Count") == guess(VariableKind::Input, IecType::Int));
    CHECK(guessDeclaration(machineWith("Speed >= 1.5"), "Speed") == guess(VariableKind::Input, IecType::Real));
    CHECK(guessDeclaration(machineWith("Count = Level"), "Count") == guess(VariableKind::Input, IecType::Uint));
    CHECK(guessDeclaration(machineWith("Count + 1 > 3"), "Count") == guess(VariableKind::Input, IecType::Int));
    // The declared operand's type says more than a BOOL context elsewhere.
    CHECK(guessDeclaration(machineWith("Height AND A", {{ActionTiming::Continuous, "N Lamp IF Height < Level"}}),
                           "Height")
          == guess(VariableKind::Input, IecType::Uint));
}

TEST_CASE("a name an action sets, resets or drives is a BOOL output", "[declarationguess]")
{
    CHECK(guessDeclaration(machineWith("A", {{ActionTiming::Continuous, "Valve"}}), "Valve")
          == guess(VariableKind::Output, IecType::Bool));
    CHECK(guessDeclaration(machineWith("A", {{ActionTiming::OnActivation, "S Motor"}}), "Motor")
          == guess(VariableKind::Output, IecType::Bool));
    CHECK(guessDeclaration(machineWith("A", {{ActionTiming::OnDeactivation, "R Motor"}}), "Motor")
          == guess(VariableKind::Output, IecType::Bool));
}

TEST_CASE("a name assigned a value takes the value's type", "[declarationguess]")
{
    CHECK(guessDeclaration(machineWith("A", {{ActionTiming::OnActivation, "Target := 5"}}), "Target")
          == guess(VariableKind::Output, IecType::Int));
    CHECK(guessDeclaration(machineWith("A", {{ActionTiming::OnActivation, "Target := Level"}}), "Target")
          == guess(VariableKind::Output, IecType::Uint));
    CHECK(guessDeclaration(machineWith("A", {{ActionTiming::OnActivation, "Lamp2 := A AND B"}}), "Lamp2")
          == guess(VariableKind::Output, IecType::Bool));
    // Read on the right of an assignment to a declared variable: that variable's type.
    CHECK(guessDeclaration(machineWith("A", {{ActionTiming::OnActivation, "Flag := Seen"}}), "Seen")
          == guess(VariableKind::Input, IecType::Bool));
}

TEST_CASE("a name written and read is an internal memory", "[declarationguess]")
{
    CHECK(guessDeclaration(machineWith("Count >= 3", {{ActionTiming::OnActivation, "Count := Count + 1"}}), "Count")
          == guess(VariableKind::Internal, IecType::Int));
    CHECK(guessDeclaration(machineWith("Memo", {{ActionTiming::OnActivation, "S Memo"}}), "Memo")
          == guess(VariableKind::Internal, IecType::Bool));
}

TEST_CASE("a name nothing uses, or used in a text that does not parse, is a BOOL input", "[declarationguess]")
{
    CHECK(guessDeclaration(machineWith("A"), "Nowhere") == guess(VariableKind::Input, IecType::Bool));
    CHECK(guessDeclaration(machineWith("Broken AND"), "Broken") == guess(VariableKind::Input, IecType::Bool));
}

TEST_CASE("the undeclared name of a GEMMA condition, a receptivity and an action", "[declarationguess]")
{
    Model model = machineWith("Go AND A", {{ActionTiming::Continuous, "N Horn IF Lid"}, {ActionTiming::OnActivation, "S Motor"}});
    require(model.setCondition("A2->A1", "Ready"));
    const std::vector<std::string> names = undeclaredNames(model);
    CHECK(names == std::vector<std::string>{"GG203 Ready", "GG403 Go", "GG405 Horn", "GG405 Lid", "GG405 Motor"});
}

TEST_CASE("no undeclared name for other problems, or once the name is declared", "[declarationguess]")
{
    // A type error on a declared variable, a step that does not exist, a syntax error.
    CHECK(undeclaredNames(machineWith("Level", {{ActionTiming::Continuous, "N Lamp IF X9"}})).empty());
    CHECK(undeclaredNames(machineWith("Go AND")).empty());
    Model model = machineWith("Go");
    REQUIRE(undeclaredNames(model) == std::vector<std::string>{"GG403 Go"});
    require(model.addVariable(samples::variable("Start2", IecType::Bool, VariableKind::Input)));
    require(model.setReceptivity("F1", 1, "Start2"));
    CHECK(undeclaredNames(model).empty());
}

TEST_CASE("the undeclared name of a PackML command or mode request condition", "[declarationguess]")
{
    Model model = packml::newModel(packml::Edition::Y2022);
    require(model.setCommandCondition(packml::Command::Start, "StartButton AND NOT Jammed"));
    require(model.setModeRequest(3, "Speed > 2.5"));
    const std::vector<std::string> names = undeclaredNames(model);
    CHECK(names == std::vector<std::string>{"GG203 Jammed", "GG203 Speed", "GG203 StartButton"});
    // Read in a command condition: a BOOL input; compared with a real number: REAL.
    CHECK(guessDeclaration(model, "StartButton") == guess(VariableKind::Input, IecType::Bool));
    CHECK(guessDeclaration(model, "Speed") == guess(VariableKind::Input, IecType::Real));

    require(model.addVariable(samples::variable("Speed", IecType::Real, VariableKind::Input)));
    CHECK(undeclaredNames(model) == std::vector<std::string>{"GG203 Jammed", "GG203 StartButton"});
}

} // namespace test_declarationguess
