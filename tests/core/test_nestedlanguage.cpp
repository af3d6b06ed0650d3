// The language of nested GRAFCETs: receptivities (the condition language in
// the Nested context) and actions.

#include "core/condition/actionparser.h"
#include "core/condition/conditionanalysis.h"
#include "core/condition/conditionevaluator.h"
#include "core/condition/conditionparser.h"
#include "core/condition/symboltable.h"
#include "core/model/grafcet.h"
#include "core/model/model.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

namespace test_nestedlanguage {

using namespace core;
using namespace core::cond;

namespace {

const ParseOptions kNested{Context::Nested};

ParseResult nested(std::string_view text)
{
    return parse(text, kNested);
}

std::string printed(std::string_view text)
{
    const ParseResult result = nested(text);
    REQUIRE(result.ok());
    return print(result.expression);
}

std::vector<Variable> declared()
{
    return {Variable{"A", IecType::Bool, "", ""}, Variable{"B", IecType::Bool, "", ""},
            Variable{"Count", IecType::Int, "", ""}, Variable{"Valve", IecType::Bool, "", ""}};
}

} // namespace

TEST_CASE("Receptivities read step activities, durations, edges and Complete", "[nested-condition]")
{
    const ParseResult x = nested("X3 AND A");
    REQUIRE(x.ok());
    const Node& step = x.expression.at(x.expression.rootNode().left);
    CHECK(step.kind == NodeKind::StepActivity);
    CHECK(step.number == 3);

    const ParseResult timed = nested("5s/X12");
    REQUIRE(timed.ok());
    CHECK(timed.expression.rootNode().kind == NodeKind::StepDuration);
    CHECK(timed.expression.rootNode().number == 12);
    CHECK(timed.expression.rootNode().durationMs == 5000);
    CHECK(timed.expression.rootNode().span.begin == 0);
    CHECK(timed.expression.rootNode().span.end == 6);

    const ParseResult edge = nested("\xE2\x86\x91" "A OR FE B");
    REQUIRE(edge.ok());
    const std::vector<int> edges = edgeNodes(edge.expression);
    REQUIRE(edges.size() == 2);
    CHECK(edge.expression.at(edges[0]).unaryOp == UnaryOp::RisingEdge);
    CHECK(edge.expression.at(edges[1]).unaryOp == UnaryOp::FallingEdge);
    CHECK(variableNodes(edge.expression).size() == 2);

    const ParseResult complete = nested("NOT complete");
    REQUIRE(complete.ok());
    CHECK(nodesOfKind(complete.expression, NodeKind::Complete).size() == 1);

    CHECK(printed("x3 and re a") == "X3 AND RE a");
    CHECK(printed("\xE2\x86\x93" "Valve") == "FE Valve");
    CHECK(printed("T#1m30s/X2 OR 200ms/X1") == "T#1m30s/X2 OR 200ms/X1");
    CHECK(printed("NOT (RE A)") == "NOT (RE A)");
}

TEST_CASE("Durations follow IEC 61131-3", "[nested-condition]")
{
    CHECK(parseDurationMs("200ms") == 200);
    CHECK(parseDurationMs("5s") == 5000);
    CHECK(parseDurationMs("1m30s") == 90000);
    CHECK(parseDurationMs("1h") == 3600000);
    CHECK(parseDurationMs("2d") == 172800000);
    CHECK(parseDurationMs("1.5s") == 1500);
    CHECK(parseDurationMs("T#5s") == 5000);
    CHECK(parseDurationMs("t#1m30s") == 90000);
    CHECK(parseDurationMs("TIME#5S") == 5000);
    CHECK(parseDurationMs("1s2h") == std::nullopt);     // largest unit first
    CHECK(parseDurationMs("1s1s") == std::nullopt);     // no unit twice
    CHECK(parseDurationMs("1.5s2ms") == std::nullopt);  // only the last part has a fraction
    CHECK(parseDurationMs("5") == std::nullopt);
    CHECK(parseDurationMs("X#5s") == std::nullopt);
    CHECK(parseDurationMs("99999999999999999999d") == std::numeric_limits<std::int64_t>::max()); // GG407 says why
}

TEST_CASE("The GEMMA context is unchanged", "[nested-condition]")
{
    const ParseResult x = parse("X3");
    REQUIRE(x.ok());
    CHECK(x.expression.rootNode().kind == NodeKind::Variable);
    REQUIRE_FALSE(parse("T#5s/X3").ok());
    CHECK(parse("T#5s/X3").error->kind == ParseError::Kind::TypedLiteral);
    CHECK(parse("RE A").error->kind == ParseError::Kind::MissingOperator);
    CHECK(parse("Complete").expression.rootNode().kind == NodeKind::Variable);
}

TEST_CASE("Type checking of the nested atoms", "[nested-condition]")
{
    const std::vector<Variable> variables = declared();
    const SymbolTable symbols(variables);
    CHECK(typeCheck(nested("X1 AND 5s/X2 AND RE A AND NOT Complete").expression, symbols).empty());
    const std::vector<TypeIssue> onInt = typeCheck(nested("RE Count").expression, symbols);
    REQUIRE(onInt.size() == 1);
    CHECK(onInt[0].code == "GG410");
    CHECK(onInt[0].message == "an edge applies to a BOOL variable; 'Count' is INT");
    const std::vector<TypeIssue> undeclared = typeCheck(nested("FE Nope").expression, symbols);
    REQUIRE(undeclared.size() == 1);
    CHECK(undeclared[0].code == "GG203");
    CHECK_FALSE(typeCheck(nested("X1 + 1 > 0").expression, symbols).empty()); // X1 is BOOL
}

TEST_CASE("The evaluator asks for the value of every nested atom", "[nested-condition]")
{
    const ParseResult result = nested("X2 AND 5s/X2 AND RE A AND NOT Complete AND B");
    REQUIRE(result.ok());
    std::vector<NodeKind> asked;
    const Value value = evaluate(result.expression, [&](int node) -> Value {
        const Node& n = result.expression.at(node);
        asked.push_back(n.kind);
        return n.kind != NodeKind::Complete;
    });
    CHECK(isTrue(value));
    std::sort(asked.begin(), asked.end());
    CHECK(asked == std::vector<NodeKind>{NodeKind::Variable, NodeKind::Unary, NodeKind::StepActivity,
                                         NodeKind::StepDuration, NodeKind::Complete});
}

TEST_CASE("Each action form", "[action]")
{
    const ActionParseResult bare = parseAction("A_Plus");
    REQUIRE(bare.ok());
    CHECK(bare.action.form == ActionForm::Continuous);
    CHECK_FALSE(bare.action.qualifierWritten);
    CHECK(bare.action.target == "A_Plus");

    const ActionParseResult n = parseAction("N Valve IF Count < 10 AND X3");
    REQUIRE(n.ok());
    CHECK(n.action.form == ActionForm::Continuous);
    CHECK(n.action.qualifierWritten);
    CHECK(n.action.target == "Valve");
    CHECK(n.action.targetSpan.begin == 2);
    CHECK(print(n.action.condition) == "Count < 10 AND X3");
    CHECK(n.action.condition.rootNode().span.begin == 11); // offsets into the whole action

    const ActionParseResult conditional = parseAction("Valve IF NOT A");
    REQUIRE(conditional.ok());
    CHECK_FALSE(conditional.action.condition.empty());

    const ActionParseResult set = parseAction("s Complete");
    REQUIRE(set.ok());
    CHECK(set.action.form == ActionForm::Set);
    CHECK(set.action.targetIsComplete);

    CHECK(parseAction("R Valve").action.form == ActionForm::Reset);

    const ActionParseResult assign = parseAction("Count := Count + 1");
    REQUIRE(assign.ok());
    CHECK(assign.action.form == ActionForm::Assign);
    CHECK(print(assign.action.value) == "Count + 1");

    // S, N and R are also variables when no name follows.
    const ActionParseResult variableS = parseAction("S := 3");
    REQUIRE(variableS.ok());
    CHECK(variableS.action.form == ActionForm::Assign);
    CHECK(variableS.action.target == "S");
    const ActionParseResult lone = parseAction("R");
    REQUIRE(lone.ok());
    CHECK(lone.action.target == "R");
    CHECK(lone.action.form == ActionForm::Continuous);

    const ActionParseResult alarm = parseAction("S Alarm := NOT (CP1 AND CP2 AND CP3)"); // the case study's spelling
    CHECK(alarm.action.form == ActionForm::Assign);
    REQUIRE(alarm.ok());
    CHECK(print(alarm.action.value) == "NOT (CP1 AND CP2 AND CP3)");
}

TEST_CASE("Twenty malformed receptivities and actions, with their messages and spans", "[action][nested-condition]")
{
    struct Case {
        bool action;
        std::string text;
        std::string message;
        std::size_t begin;
        std::size_t end;
    };
    const std::vector<Case> cases = {
        {false, "RE (A)", "an edge (RE, FE, ↑, ↓) applies to a variable name, not to '('", 3, 4},
        {false, "FE", "an edge (RE, FE, ↑, ↓) applies to a variable name", 0, 2},
        {false, "RE X3", "an edge (RE, FE, ↑, ↓) applies to a variable name, not to 'X3'", 3, 5},
        {false, "5s AND A", "the duration '5s' must be followed by /X<step>, as in 5s/X3", 0, 2},
        {false, "5s/A", "expected a step activity X<step> after '/' of the duration, found 'A'", 3, 4},
        {false, "0s/X1", "the duration '0s' is zero: write a positive duration", 0, 2},
        {false, "T#5q/X1",
         "'T#5q' is not a valid duration: write for example 200ms, 5s, 1m30s or T#5s (units d, h, m, s, ms, "
         "largest first)",
         0, 4},
        {false, "5s/", "expected a step activity X<step> after '/' of the duration", 3, 3},
        {false, "X3 AND", "expected an operand after 'AND'", 6, 6},
        {true, "", "empty action: write for example Valve, S Valve, R Valve or Count := Count + 1", 0, 0},
        {true, "   ", "empty action: write for example Valve, S Valve, R Valve or Count := Count + 1", 0, 3},
        {true, "S TRUE", "an action writes a variable: 'TRUE' is not a variable name", 2, 6},
        {true, "S X3", "an action writes a variable: 'X3' is not a variable name", 2, 4},
        {true, "P Valve",
         "the qualifier 'P' is not supported: use N (or none), S, R or an assignment V := value", 0, 1},
        {true, "SD Valve",
         "the qualifier 'SD' is not supported: use N (or none), S, R or an assignment V := value", 0, 2},
        {true, "R Count := 1", "an assignment takes no qualifier: write V := value, without 'R'", 0, 1},
        {true, "R Valve IF A", "a stored action (R) takes no IF condition: only continuous actions are conditional",
         0, 1},
        {true, "Count :=", "expected a value after ':='", 6, 8},
        {true, "Valve IF", "expected a condition after IF", 6, 8},
        {true, "Count = 1", "use := to assign a value; = compares", 6, 7},
        {true, "Valve Pump", "unexpected 'Pump' after a complete action", 6, 10},
        {true, "N Valve IF A AND", "expected an operand after 'AND'", 16, 16},
        {true, "Count := 5s/X1 +", "expected an operand after '+'", 16, 16},
        {true, "42", "an action writes a variable: '42' is not a variable name", 0, 2},
    };
    REQUIRE(cases.size() >= 20);
    for (const Case& c : cases) {
        INFO((c.action ? "action: " : "receptivity: ") << c.text);
        const std::optional<ParseError> error = c.action ? parseAction(c.text).error : nested(c.text).error;
        REQUIRE(error.has_value());
        CHECK(error->message == c.message);
        CHECK(error->span.begin == c.begin);
        CHECK(error->span.end == c.end);
        // The kind survives the arguments the editor translates from.
        std::vector<std::string> arguments;
        appendArguments(*error, arguments);
        const std::optional<ParseError> again = parseErrorFromArguments(arguments, 0);
        REQUIRE(again.has_value());
        CHECK(again->message == error->message);
    }
}

TEST_CASE("Renaming reaches into actions and durations", "[action]")
{
    CHECK(renameIdentifier("S Valve", "valve", "Inlet", kNested) == "S Inlet");
    CHECK(renameIdentifier("Count := Count + 1", "Count", "Parts", kNested) == "Parts := Parts + 1");
    CHECK(renameIdentifier("N A IF B", "B", "Ready", kNested) == "N A IF Ready");
    CHECK(renameIdentifier("\xE2\x86\x91" "A AND 5s/X3", "A", "Start", kNested) == "\xE2\x86\x91" "Start AND 5s/X3");
    CHECK(renameIdentifier("5s/X3 OR X3", "X3", "X7", kNested) == "5s/X7 OR X7");

    Grafcet grafcet;
    REQUIRE(grafcet.addStep({3, true, "", {{ActionTiming::Continuous, "N Valve IF NOT X3"}}}));
    REQUIRE(grafcet.addStep({4, false, "", {}}));
    REQUIRE(grafcet.addTransition({1, {3}, {4}, "2s/X3 AND RE A"}));
    REQUIRE(grafcet.renumberStep(3, 30));
    CHECK(grafcet.transition(1)->receptivity == "2s/X30 AND RE A");
    CHECK(grafcet.step(30)->actions[0].text == "N Valve IF NOT X30");
}

TEST_CASE("Hostile nested texts are refused, not recursed into", "[action][nested-condition]")
{
    std::string edges;
    for (int i = 0; i < 10000; ++i)
        edges += "\xE2\x86\x91";
    CHECK_FALSE(nested(edges + "A").ok());
    CHECK_FALSE(parseAction("Count := " + std::string(100000, '(') + "1").ok());
    const std::string longAction = "N Valve IF " + std::string(1'000'000, 'A');
    CHECK(parseAction(longAction).ok()); // one long identifier: fine
}

} // namespace test_nestedlanguage
