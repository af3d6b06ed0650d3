#include "core/condition/conditionanalysis.h"
#include "core/condition/conditionevaluator.h"
#include "core/condition/conditionparser.h"
#include "core/model/model.h"
#include "core/condition/symboltable.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace test_condition {

using namespace core;
using namespace core::cond;

namespace {

// The tree as an S-expression: (AND (NOT a) b). Literals as written.
std::string shape(const Expression& e, int index)
{
    const Node& n = e.at(index);
    switch (n.kind) {
    case NodeKind::Variable:
    case NodeKind::IntegerLiteral:
    case NodeKind::RealLiteral:
    case NodeKind::StepActivity:
    case NodeKind::StepDuration:
    case NodeKind::Complete:
    case NodeKind::InStep:
    case NodeKind::NestedStepActivity: return n.text;
    case NodeKind::BoolLiteral: return toUpperAscii(n.text);
    case NodeKind::Unary: return std::string("(") + operatorText(n.unaryOp) + " " + shape(e, n.operand) + ")";
    case NodeKind::Binary:
        return std::string("(") + operatorText(n.binaryOp) + " " + shape(e, n.left) + " " + shape(e, n.right) + ")";
    }
    return "?";
}

std::string shape(const Expression& e)
{
    return e.empty() ? std::string("<empty>") : shape(e, e.root);
}

std::string shapeOf(std::string_view text)
{
    const ParseResult result = parse(text);
    if (!result.ok())
        return "error: " + result.error->message;
    return shape(result.expression);
}

Expression parsed(std::string_view text)
{
    ParseResult result = parse(text);
    INFO(text);
    REQUIRE(result.ok());
    return std::move(result.expression);
}

std::string printed(std::string_view text)
{
    return print(parsed(text));
}

ParseError errorOf(std::string_view text)
{
    const ParseResult result = parse(text);
    INFO(text);
    REQUIRE_FALSE(result.ok());
    REQUIRE(result.expression.empty());
    return *result.error;
}

std::vector<Variable> testVariables()
{
    return {
        {"Start", IecType::Bool, "", ""},
        {"Stop", IecType::Bool, "", ""},
        {"MOTOR_ON", IecType::Bool, "", ""},
        {"Speed", IecType::Int, "", ""},
        {"Count", IecType::Ulint, "", ""},
        {"Temp", IecType::Real, "", ""},
    };
}

std::vector<TypeIssue> issuesOf(std::string_view text)
{
    const std::vector<Variable> variables = testVariables();
    const SymbolTable symbols(variables);
    return typeCheck(parsed(text), symbols);
}

std::vector<TokenKind> kinds(std::string_view text)
{
    std::vector<TokenKind> result;
    for (const Token& token : tokenize(text))
        result.push_back(token.kind);
    return result;
}

} // namespace

// --- symbol table ---------------------------------------------------------------

TEST_CASE("The symbol table finds a variable in any case, the first of a name winning", "[condition]")
{
    std::vector<Variable> variables = testVariables();
    variables.push_back({"motor_on", IecType::Int, "", ""});
    variables.push_back({"Z_9", IecType::Bool, "", ""});
    const SymbolTable symbols(variables);
    REQUIRE(symbols.find("motor_ON") != nullptr);
    CHECK(symbols.find("motor_ON") == &variables[2]);
    CHECK(symbols.find("z_9") == &variables.back());
    CHECK(symbols.find("SPEED")->type == IecType::Int);
    CHECK(symbols.find("Spee") == nullptr);
    CHECK(symbols.find("Speed_") == nullptr);
    CHECK(symbols.find("") == nullptr);
    // Only ASCII letters fold: '{' is '[' + 32, not its lower case.
    const std::vector<Variable> bracket{{"a[", IecType::Bool, "", ""}};
    const SymbolTable withBracket(bracket);
    CHECK(withBracket.find("A[") == &bracket.front());
    CHECK(withBracket.find("A{") == nullptr);
}

// --- tokens ---------------------------------------------------------------------

TEST_CASE("names containing AND, OR, NOT are identifiers", "[condition]")
{
    using K = TokenKind;
    CHECK(kinds("MOTOR_ON AND NOTIFY") == std::vector<K>{K::Identifier, K::And, K::Identifier, K::End});
    CHECK(kinds("DOOR_CLOSED OR ORDER_OK") == std::vector<K>{K::Identifier, K::Or, K::Identifier, K::End});
    CHECK(kinds("ANDY XOR NOTX") == std::vector<K>{K::Identifier, K::Xor, K::Identifier, K::End});
    CHECK(kinds("a&b") == std::vector<K>{K::Identifier, K::And, K::Identifier, K::End});
    CHECK(kinds("not And oR xOr mod TRUE false")
          == std::vector<K>{K::Not, K::And, K::Or, K::Xor, K::Mod, K::True, K::False, K::End});
    CHECK(kinds("x<=1<>2>=3<4>5=6")
          == std::vector<K>{K::Identifier, K::LessEqual, K::IntegerLiteral, K::NotEqual, K::IntegerLiteral,
                            K::GreaterEqual, K::IntegerLiteral, K::Less, K::IntegerLiteral, K::Greater,
                            K::IntegerLiteral, K::Equal, K::IntegerLiteral, K::End});
    CHECK(shapeOf("MOTOR_ON AND NOTIFY OR NOT DOOR_CLOSED") == "(OR (AND MOTOR_ON NOTIFY) (NOT DOOR_CLOSED))");
}

TEST_CASE("tokens carry exact spans and views of the text", "[condition]")
{
    const std::string text = "  Speed >= 1_000\t";
    const auto tokens = tokenize(text);
    REQUIRE(tokens.size() == 4);
    CHECK(tokens[0].span == Span{2, 7});
    CHECK(tokens[0].text == "Speed");
    CHECK(tokens[1].span == Span{8, 10});
    CHECK(tokens[2].kind == TokenKind::IntegerLiteral);
    CHECK(tokens[2].text == "1_000");
    CHECK(tokens[3].kind == TokenKind::End);
    CHECK(tokens[3].span == Span{text.size(), text.size()});
}

TEST_CASE("number literals", "[condition]")
{
    using K = TokenKind;
    CHECK(kinds("42 1_000 1.5 1.5e3 2E-2 1e+5 0.25") == std::vector<K>{K::IntegerLiteral, K::IntegerLiteral,
                                                                       K::RealLiteral, K::RealLiteral,
                                                                       K::RealLiteral, K::RealLiteral,
                                                                       K::RealLiteral, K::End});
    // A minus after a number is an operator, not part of it.
    CHECK(kinds("1-2") == std::vector<K>{K::IntegerLiteral, K::Minus, K::IntegerLiteral, K::End});
    for (const char* bad : {"1__0", "1_", "1.", "1.5.3", "12abc", "1e", "16#FF", "1.5e+"})
        CHECK(tokenize(bad).front().kind == K::Invalid);
}

// --- grouping ---------------------------------------------------------------------

TEST_CASE("NOT binds tighter than AND", "[condition]")
{
    const Expression e = parsed("NOT a AND b");
    const Node& root = e.rootNode();
    REQUIRE(root.kind == NodeKind::Binary);
    CHECK(root.binaryOp == BinaryOp::And);
    CHECK(root.span == Span{0, 11});
    const Node& left = e.at(root.left);
    REQUIRE(left.kind == NodeKind::Unary);
    CHECK(left.unaryOp == UnaryOp::Not);
    CHECK(left.span == Span{0, 5});
    CHECK(e.at(left.operand).kind == NodeKind::Variable);
    CHECK(e.at(left.operand).text == "a");
    CHECK(e.at(root.right).text == "b");
    CHECK(e.at(root.right).span == Span{10, 11});
    CHECK(shapeOf("NOT (a AND b)") == "(NOT (AND a b))");
}

TEST_CASE("precedence and associativity follow ST", "[condition]")
{
    CHECK(shapeOf("a OR b AND c") == "(OR a (AND b c))");
    CHECK(shapeOf("a AND b OR c") == "(OR (AND a b) c)");
    CHECK(shapeOf("a OR b XOR c AND d") == "(OR a (XOR b (AND c d)))");
    CHECK(shapeOf("a & b XOR c") == "(XOR (AND a b) c)");
    CHECK(shapeOf("a = b AND c <> d") == "(AND (= a b) (<> c d))");
    CHECK(shapeOf("x + 1 > y * 2") == "(> (+ x 1) (* y 2))");
    CHECK(shapeOf("x < y = b") == "(= (< x y) b)");
    CHECK(shapeOf("a - b - c") == "(- (- a b) c)");
    CHECK(shapeOf("a - (b - c)") == "(- a (- b c))");
    CHECK(shapeOf("a / b * c MOD d") == "(MOD (* (/ a b) c) d)");
    CHECK(shapeOf("-x * y") == "(* (- x) y)");
    CHECK(shapeOf("x - -y") == "(- x (- y))");
    CHECK(shapeOf("NOT a = b") == "(= (NOT a) b)");
    CHECK(shapeOf("NOT NOT a") == "(NOT (NOT a))");
    CHECK(shapeOf("((a))") == "a");
    CHECK(shapeOf("a AND b AND c") == "(AND (AND a b) c)");
    CHECK(shapeOf("a AND (b AND c)") == "(AND a (AND b c))");
}

TEST_CASE("keywords and literals are case-insensitive", "[condition]")
{
    CHECK(shapeOf("not a and B Or c xor D") == "(OR (AND (NOT a) B) (XOR c D))");
    CHECK(shapeOf("x mod 3 = 0") == "(= (MOD x 3) 0)");
    CHECK(shapeOf("true") == "TRUE");
    CHECK(shapeOf("False OR TrUe") == "(OR FALSE TRUE)");
    const Expression e = parsed("true");
    CHECK(e.rootNode().kind == NodeKind::BoolLiteral);
    CHECK(e.rootNode().text == "true");
}

TEST_CASE("spans exclude the node's own parentheses", "[condition]")
{
    const Expression e = parsed("(a) AND (b OR c)");
    CHECK(e.rootNode().span == Span{0, 16});
    const Node& right = e.at(e.rootNode().right);
    CHECK(right.binaryOp == BinaryOp::Or);
    CHECK(right.span == Span{9, 15});
    CHECK(e.at(e.rootNode().left).span == Span{1, 2});
    const Expression n = parsed("NOT (x)");
    CHECK(n.rootNode().span == Span{0, 7});
}

TEST_CASE("comparisons and arithmetic", "[condition]")
{
    CHECK(shapeOf("Speed >= 100") == "(>= Speed 100)");
    CHECK(shapeOf("Temp <= 1.5e3 AND Temp > 2E-2") == "(AND (<= Temp 1.5e3) (> Temp 2E-2))");
    CHECK(shapeOf("Count MOD 2 <> 0") == "(<> (MOD Count 2) 0)");
    CHECK(shapeOf("(Speed + 10) * 2 / 3 - 1 < 1_000") == "(< (- (/ (* (+ Speed 10) 2) 3) 1) 1_000)");
}

// --- errors --------------------------------------------------------------------

TEST_CASE("malformed conditions give precise messages and spans", "[condition]")
{
    struct Case {
        std::string text;
        std::string message; // the message starts with this
        Span span;
    };
    const std::vector<Case> cases = {
        {"", "empty condition: write when the transition fires", {0, 0}},
        {"   ", "empty condition: write when the transition fires", {0, 3}},
        {"a AND", "expected an operand after 'AND'", {5, 5}},
        {"a AND OR b", "expected an operand after 'AND', found 'OR'", {6, 8}},
        {"AND b", "expected an operand before 'AND'", {0, 3}},
        {"(a AND b", "unmatched '(' at column 1: missing ')'", {0, 1}},
        {"a AND ((b)", "unmatched '(' at column 7: missing ')'", {6, 7}},
        {"a AND b)", "unmatched ')': no '(' opens it", {7, 8}},
        {")", "unmatched ')': no '(' opens it", {0, 1}},
        {"a b", "unexpected 'b' after a complete condition", {2, 3}},
        {"a AND b 3", "unexpected '3' after a complete condition", {8, 9}},
        {"(a b)", "unexpected 'b': expected an operator or ')' to close the '(' at column 1", {3, 4}},
        {"()", "empty parentheses", {0, 2}},
        {"a := b", "use = to compare; := is assignment", {2, 4}},
        {"IF a THEN", "'IF' is not allowed in a condition", {0, 2}},
        {"a THEN", "'THEN' is not allowed in a condition", {2, 6}},
        {"a AND Case", "'Case' is not allowed in a condition: it is an IEC 61131-3 keyword", {6, 10}},
        {"TIME > 5", "'TIME' is not allowed in a condition: it is a type name", {0, 4}},
        {"a == b", "use = to compare; == is not Structured Text", {2, 4}},
        {"a != b", "use <> for 'not equal'", {2, 4}},
        {"!a", "use NOT for negation", {0, 1}},
        {"a && b", "use AND", {2, 4}},
        {"a || b", "use OR", {2, 4}},
        {"a ** 2", "'**' (power) is not supported", {2, 4}},
        {"a;", "';' is not allowed in a condition", {1, 2}},
        {"a AND Temp\xC3\xA9rature", "'Temp\xC3\xA9rature' contains a non-ASCII character", {6, 18}},
        {"\xC3\xA9t\xC3\xA9", "'\xC3\xA9t\xC3\xA9' contains a non-ASCII character", {0, 5}},
        {"a AND \xFF", "the text contains bytes that are not valid UTF-8", {6, 7}},
        {"a AND \x01", "unexpected control character (byte 0x01)", {6, 7}},
        {"x = 16#FF", "'16#FF' is not supported", {4, 9}},
        {"x > T#5s", "'T#5s' is not supported", {4, 8}},
        {"x > 1.5.3", "'1.5.3' is not a valid number", {4, 9}},
        {"x > 12abc", "'12abc' is not a valid number", {4, 9}},
        {"x = 1.", "'1.' is not a valid number", {4, 6}},
        {"GVL.Start", "'GVL.Start': qualified names are not allowed", {0, 9}},
        {"a (* hi *) AND b", "comments are not allowed in a condition", {2, 10}},
        {"a // hi", "comments are not allowed in a condition", {2, 7}},
        {"a AND @", "unexpected character '@'", {6, 7}},
        {"NOT", "expected an operand after 'NOT'", {3, 3}},
        {"a AND -", "expected an operand after '-'", {7, 7}},
        {"a + + b", "expected an operand after '+', found '+'", {4, 5}},
        {"a AND (b OR)", "expected an operand after 'OR', found ')'", {11, 12}},
        {"x > 1 <", "expected an operand after '<'", {7, 7}},
    };
    for (const Case& c : cases) {
        INFO("condition: " << c.text);
        const ParseError error = errorOf(c.text);
        CHECK(error.message.rfind(c.message, 0) == 0);
        CHECK(error.span == c.span);
    }
    REQUIRE(cases.size() >= 20);
}

TEST_CASE("parse errors carry their kind and pieces, and the same English text", "[condition]")
{
    using Kind = ParseError::Kind;
    struct Case {
        std::string text;
        Kind kind;
        std::string found;
        std::string previous;
        std::size_t number;
        std::string message; // exact
    };
    std::string chain = "a";
    for (int i = 0; i < 1001; ++i)
        chain += " AND a";
    std::string nots;
    for (int i = 0; i < 201; ++i)
        nots += "NOT ";
    const std::vector<Case> cases = {
        {" ", Kind::Empty, "", "", 0, "empty condition: write when the transition fires (TRUE if it is always ready), or hide the transition if the machine does not need it"},
        {"a (* x *)", Kind::Comment, "(* x *)", "", 0, "comments are not allowed in a condition"},
        {"a := b", Kind::ColonEquals, ":=", "", 0, "use = to compare; := is assignment"},
        {"a == b", Kind::DoubleEquals, "==", "", 0, "use = to compare; == is not Structured Text"},
        {"a != b", Kind::BangEquals, "!=", "", 0, "use <> for 'not equal'"},
        {"!a", Kind::Bang, "!", "", 0, "use NOT for negation"},
        {"a && b", Kind::DoubleAmpersand, "&&", "", 0, "use AND (or &) for 'and'"},
        {"a | b", Kind::Pipe, "|", "", 0, "use OR for 'or'"},
        {"a ** 2", Kind::Power, "**", "", 0, "'**' (power) is not supported in a condition"},
        {"a;", Kind::Semicolon, ";", "", 0, "';' is not allowed in a condition: write only the expression"},
        {"a AND \xFF", Kind::InvalidUtf8, "\xFF", "", 0, "the text contains bytes that are not valid UTF-8"},
        {"Temp\xC3\xA9", Kind::NonAscii, "Temp\xC3\xA9", "", 0,
         "'Temp\xC3\xA9' contains a non-ASCII character: names use ASCII letters, digits and _ only"},
        {"x = 16#FF", Kind::TypedLiteral, "16#FF", "", 0,
         "'16#FF' is not supported: write plain decimal numbers, TRUE or FALSE (no typed, based or time literals)"},
        {"GVL.Start", Kind::QualifiedName, "GVL.Start", "", 0,
         "'GVL.Start': qualified names are not allowed, write the variable name alone"},
        {"x > 1.5.3", Kind::InvalidNumber, "1.5.3", "", 0, "'1.5.3' is not a valid number"},
        {"IF a", Kind::IfThen, "IF", "", 0,
         "'IF' is not allowed in a condition: write only the boolean expression, without IF ... THEN"},
        {"TIME > 5", Kind::TypeName, "TIME", "", 0, "'TIME' is not allowed in a condition: it is a type name"},
        {"a AND Case", Kind::Keyword, "Case", "", 0,
         "'Case' is not allowed in a condition: it is an IEC 61131-3 keyword"},
        {"a AND \x1B", Kind::ControlCharacter, "\x1B", "", 0x1B, "unexpected control character (byte 0x1B)"},
        {"a AND @", Kind::UnexpectedCharacter, "@", "", 0, "unexpected character '@'"},
        {chain, Kind::TooComplex, "AND", "", 1000,
         "condition too complex: operators nested more than 1000 levels deep"},
        {std::string(201, '(') + "a", Kind::TooDeepParentheses, "(", "", 200,
         "condition nested too deeply: more than 200 levels of parentheses"},
        {nots + "a", Kind::TooDeepUnary, "NOT", "", 200,
         "condition nested too deeply: more than 200 levels of unary operators"},
        {"a)", Kind::UnmatchedClose, ")", "", 0, "unmatched ')': no '(' opens it"},
        {"OR b", Kind::OperandBefore, "OR", "", 0, "expected an operand before 'OR'"},
        {"a AND ( )", Kind::EmptyParentheses, "", "", 0, "empty parentheses: expected an expression inside '( )'"},
        {"a AND", Kind::OperandAfter, "", "AND", 0, "expected an operand after 'AND'"},
        {"a AND (b OR)", Kind::OperandAfter, ")", "OR", 0, "expected an operand after 'OR', found ')'"},
        {"a AND ((b)", Kind::UnclosedAtEnd, "", "", 7, "unmatched '(' at column 7: missing ')'"},
        {"x OR (a b)", Kind::Unclosed, "b", "", 6,
         "unexpected 'b': expected an operator or ')' to close the '(' at column 6"},
        {"a b", Kind::MissingOperator, "b", "", 0, "unexpected 'b' after a complete condition (missing operator?)"},
    };
    for (const Case& c : cases) {
        INFO("condition: " << c.text.substr(0, 40));
        const ParseError error = errorOf(c.text);
        CHECK(error.kind == c.kind);
        CHECK(error.found == c.found);
        CHECK(error.previous == c.previous);
        CHECK(error.number == c.number);
        CHECK(error.message == c.message);
        CHECK(toText(error) == c.message);

        // The form GG201 appends to Diagnostic::arguments reads back to the same error.
        std::vector<std::string> arguments{"A1->F1"};
        appendArguments(error, arguments);
        REQUIRE(arguments.size() == 5);
        CHECK(arguments[1] == kindName(c.kind));
        const std::optional<ParseError> back = parseErrorFromArguments(arguments, 1);
        REQUIRE(back.has_value());
        CHECK(back->kind == c.kind);
        CHECK(back->message == c.message);
    }

    // No reachable input ends here today (every token after a condition is
    // an operator, ')' or an operand); the kind keeps its text.
    CHECK(toText(makeParseError(Kind::AfterCondition, Span{}, "x")) == "unexpected 'x' after a complete condition");

    // Every kind has its own name.
    std::set<std::string_view> names;
    for (int k = 0; k <= static_cast<int>(Kind::MissingOperator); ++k) {
        const std::string_view name = kindName(static_cast<Kind>(k));
        CHECK_FALSE(name.empty());
        CHECK(parseErrorKind(name) == static_cast<Kind>(k));
        names.insert(name);
    }
    CHECK(names.size() == static_cast<std::size_t>(Kind::MissingOperator) + 1);

    // Arguments from elsewhere (an older core, a bad number) are not read.
    CHECK_FALSE(parseErrorFromArguments({"unknown-kind", "", "", "0"}, 0));
    CHECK_FALSE(parseErrorFromArguments({"operand-after", "", "AND", "x"}, 0));
    CHECK_FALSE(parseErrorFromArguments({"operand-after", "", "AND"}, 0));
}

TEST_CASE("deep nesting is an error, not a stack overflow", "[condition]")
{
    const std::string ok = std::string(150, '(') + "a" + std::string(150, ')');
    CHECK(parse(ok).ok());

    const std::string deep = std::string(300, '(') + "a" + std::string(300, ')');
    const ParseError parens = errorOf(deep);
    CHECK(parens.message.find("nested too deeply") != std::string::npos);
    CHECK(parens.span == Span{200, 201});

    std::string nots;
    for (int i = 0; i < 100000; ++i)
        nots += "NOT ";
    CHECK(errorOf(nots + "a").message.find("nested too deeply") != std::string::npos);

    // A unary chain at the limit prints with a parenthesis per level
    // (-(-(... R))) and must parse again.
    std::string minuses = "t - ";
    for (int i = 0; i < 199; ++i)
        minuses += "-";
    const core::cond::ParseResult atLimit = parse(minuses + "R");
    REQUIRE(atLimit.ok());
    CHECK(parse(print(atLimit.expression)).ok());

    std::string chain = "a";
    for (int i = 0; i < 5000; ++i)
        chain += " AND a";
    CHECK(errorOf(chain).message.find("too complex") != std::string::npos);

    std::string longOk = "a";
    for (int i = 0; i < 500; ++i)
        longOk += " AND a";
    CHECK(parse(longOk).ok());
}

TEST_CASE("arbitrary bytes never crash the parser", "[condition]")
{
    std::mt19937 random(7);
    std::uniform_int_distribution<int> byte(0, 255);
    std::uniform_int_distribution<int> length(0, 40);
    const std::string alphabet = "ab()NOT AND OR XOR -+*/<>=&:;1._#\xC3\xA9";
    std::uniform_int_distribution<std::size_t> pick(0, alphabet.size() - 1);
    for (int i = 0; i < 3000; ++i) {
        std::string text;
        const int n = length(random);
        for (int k = 0; k < n; ++k)
            text += (i % 2) ? static_cast<char>(byte(random)) : alphabet[pick(random)];
        const ParseResult result = parse(text);
        if (result.ok()) {
            CHECK(parse(print(result.expression)).ok());
        } else {
            CHECK_FALSE(result.error->message.empty());
            CHECK(result.error->span.begin <= result.error->span.end);
            CHECK(result.error->span.end <= text.size());
        }
    }
}

// --- printing ------------------------------------------------------------------

TEST_CASE("print uses upper-case keywords, spaced operators and minimal parentheses", "[condition]")
{
    CHECK(printed("not a and b") == "NOT a AND b");
    CHECK(printed("NOT(a AND b)") == "NOT (a AND b)");
    CHECK(printed("a&b") == "a AND b");
    CHECK(printed("((a OR b)) AND c") == "(a OR b) AND c");
    CHECK(printed("a OR (b AND c)") == "a OR b AND c");
    CHECK(printed("(a AND b) AND c") == "a AND b AND c");
    CHECK(printed("a AND (b AND c)") == "a AND (b AND c)");
    CHECK(printed("(a - b) - c") == "a - b - c");
    CHECK(printed("a - (b - c)") == "a - (b - c)");
    CHECK(printed("a-(b+c)") == "a - (b + c)");
    CHECK(printed("x+1>=2*(y-3)") == "x + 1 >= 2 * (y - 3)");
    CHECK(printed("a/(b*c)") == "a / (b * c)");
    CHECK(printed("(a = b) = c") == "a = b = c");
    CHECK(printed("x mod 2 <> 0") == "x MOD 2 <> 0");
    CHECK(printed("true or False") == "TRUE OR FALSE");
    CHECK(printed("x = 1_000 AND r > 1.5e3") == "x = 1_000 AND r > 1.5e3");
    CHECK(printed("-x*y") == "-x * y");
    CHECK(printed("-(x*y)") == "-(x * y)");
    CHECK(printed("x - -y") == "x - -y");
}

TEST_CASE("a unary operator applied to a unary expression is parenthesised", "[condition]")
{
    CHECK(printed("NOT NOT x") == "NOT (NOT x)");
    CHECK(printed("NOT (NOT x)") == "NOT (NOT x)");
    CHECK(printed("- -x") == "-(-x)");
    CHECK(printed("--x") == "-(-x)");
    CHECK(printed("NOT -x") == "NOT (-x)");
    CHECK(printed("-NOT x") == "-(NOT x)");
    CHECK(printed("NOT NOT NOT x") == "NOT (NOT (NOT x))");
}

TEST_CASE("print maps variable names and substitutes subtrees", "[condition]")
{
    const Expression e = parsed("start AND NOT stop OR speed > 1");
    PrintOptions options;
    options.variableName = [](const Node& variable) {
        const std::string upper = toUpperAscii(variable.text);
        const std::string declared = upper == "START" ? "Start" : upper == "STOP" ? "Stop" : "Speed";
        return "GVL." + declared;
    };
    CHECK(print(e, options) == "GVL.Start AND NOT GVL.Stop OR GVL.Speed > 1");

    const auto literals = booleanLiterals(e);
    REQUIRE(literals.size() == 3);
    PrintOptions tokens;
    tokens.substitutions[literals[1].node] = "Stop_F1_3_MEM";
    CHECK(print(e, tokens) == "start AND Stop_F1_3_MEM OR speed > 1");

    // A substituted binary subtree is an atom: no parentheses added.
    const Expression sum = parsed("(a OR b) AND c");
    PrintOptions whole;
    whole.substitutions[sum.rootNode().left] = "X";
    CHECK(print(sum, whole) == "X AND c");
    const Expression twice = parsed("NOT (NOT x)");
    PrintOptions inner;
    inner.substitutions[twice.rootNode().operand] = "x_F1_1_MEM";
    CHECK(print(twice, inner) == "NOT x_F1_1_MEM");
    PrintOptions root;
    root.substitutions[twice.root] = "T";
    CHECK(print(twice, root) == "T");
}

TEST_CASE("print round trips keep the tree shape", "[condition]")
{
    for (const char* text :
         {"NOT a AND b", "a OR b AND c", "(a OR b) AND c", "a AND (b AND c)", "a - (b - c)", "NOT NOT x",
          "-(-x) > 3", "x * (y + 1) MOD 3 = 0 XOR b", "NOT (a = b)", "(a XOR b) XOR (c XOR d)",
          "-(x MOD 2) <= -1.5e3"}) {
        INFO(text);
        const Expression e = parsed(text);
        const std::string once = print(e);
        CHECK(shape(parsed(once)) == shape(e));
        CHECK(print(parsed(once)) == once);
    }
}

namespace {

// Builds a random expression tree directly, covering every operator.
class RandomTree {
public:
    explicit RandomTree(unsigned seed) : m_random(seed) {}

    Expression make()
    {
        Expression e;
        e.root = build(e, 0);
        return e;
    }

private:
    int uniform(int low, int high) { return std::uniform_int_distribution<int>(low, high)(m_random); }

    int add(Expression& e, Node node)
    {
        e.nodes.push_back(std::move(node));
        return static_cast<int>(e.nodes.size()) - 1;
    }

    int leaf(Expression& e)
    {
        static const char* const kTexts[] = {"a", "b", "Motor_On", "NOTIFY", "ORDER_OK", "x1", "_y", "0", "42",
                                             "1_000", "1.5", "2E-2", "3.25e3"};
        Node node;
        const int pick = uniform(0, 14);
        if (pick >= 13) {
            node.kind = NodeKind::BoolLiteral;
            node.text = pick == 13 ? "TRUE" : "false";
        } else {
            node.text = kTexts[pick];
            node.kind = pick < 7 ? NodeKind::Variable
                                 : (pick < 10 ? NodeKind::IntegerLiteral : NodeKind::RealLiteral);
        }
        return add(e, std::move(node));
    }

    int build(Expression& e, int depth)
    {
        const int choice = depth >= 6 ? 0 : uniform(0, 9);
        if (choice <= 2)
            return leaf(e);
        Node node;
        if (choice == 3) {
            node.kind = NodeKind::Unary;
            node.unaryOp = uniform(0, 1) ? UnaryOp::Not : UnaryOp::Negate;
            node.operand = build(e, depth + 1);
        } else {
            node.kind = NodeKind::Binary;
            node.binaryOp = static_cast<BinaryOp>(uniform(0, 13));
            node.left = build(e, depth + 1);
            node.right = build(e, depth + 1);
        }
        return add(e, std::move(node));
    }

    std::mt19937 m_random;
};

} // namespace

TEST_CASE("2,000 random expressions print and parse back to the same tree", "[condition]")
{
    RandomTree generator(20240601);
    for (int i = 0; i < 2000; ++i) {
        const Expression original = generator.make();
        const std::string text = print(original);
        INFO(text);
        const ParseResult result = parse(text);
        REQUIRE(result.ok());
        CHECK(shape(result.expression) == shape(original));
        CHECK(print(result.expression) == text);
    }
}

TEST_CASE("needsParenthesesBeforeAnd looks at the top-level operator", "[condition]")
{
    CHECK(needsParenthesesBeforeAnd(parsed("a OR b")));
    CHECK(needsParenthesesBeforeAnd(parsed("a XOR b")));
    CHECK(needsParenthesesBeforeAnd(parsed("(a OR b)")));
    CHECK(needsParenthesesBeforeAnd(parsed("a AND b OR c")));
    CHECK_FALSE(needsParenthesesBeforeAnd(parsed("a AND b")));
    CHECK_FALSE(needsParenthesesBeforeAnd(parsed("(a OR b) AND c")));
    CHECK_FALSE(needsParenthesesBeforeAnd(parsed("NOT (a OR b)")));
    CHECK_FALSE(needsParenthesesBeforeAnd(parsed("a")));
    CHECK_FALSE(needsParenthesesBeforeAnd(parsed("x = 1")));
    CHECK_FALSE(needsParenthesesBeforeAnd(Expression{}));
    const Expression e = parsed("a OR b");
    PrintOptions options;
    options.substitutions[e.root] = "T";
    CHECK_FALSE(needsParenthesesBeforeAnd(e, options));
    CHECK(needsParenthesesBeforeAnd(e, PrintOptions{}));
}

// --- analysis ------------------------------------------------------------------

TEST_CASE("variable nodes come in source order", "[condition]")
{
    const Expression e = parsed("(b OR NOT a) AND c > d * b");
    std::vector<std::string> names;
    for (int index : variableNodes(e))
        names.push_back(e.at(index).text);
    CHECK(names == std::vector<std::string>{"b", "a", "c", "d", "b"});
    CHECK(variableNodes(parsed("TRUE")).empty());
    CHECK(variableNodes(Expression{}).empty());
}

TEST_CASE("boolean literals and their polarity", "[condition]")
{
    const Expression e = parsed("Stop AND NOT Start OR NOT (NOT x)");
    const auto literals = booleanLiterals(e);
    REQUIRE(literals.size() == 3);

    CHECK(e.at(literals[0].variableNode).text == "Stop");
    CHECK_FALSE(literals[0].negated);
    CHECK(literals[0].node == literals[0].variableNode);

    CHECK(e.at(literals[1].variableNode).text == "Start");
    CHECK(literals[1].negated);
    const Node& notStart = e.at(literals[1].node);
    CHECK(notStart.kind == NodeKind::Unary);
    CHECK(notStart.operand == literals[1].variableNode);
    CHECK(notStart.span == Span{9, 18});

    // Only the NOT directly above the variable counts.
    CHECK(e.at(literals[2].variableNode).text == "x");
    CHECK(literals[2].negated);
    CHECK(e.at(literals[2].node).operand == literals[2].variableNode);
    CHECK(e.at(literals[2].node).span == Span{27, 32});

    const auto minus = booleanLiterals(parsed("-x > 0"));
    REQUIRE(minus.size() == 1);
    CHECK_FALSE(minus[0].negated);
}

TEST_CASE("type check accepts well-typed conditions", "[condition]")
{
    for (const char* ok :
         {"Start", "start AND NOT STOP", "Speed > 100 OR motor_on", "Temp >= 1.5 AND Speed + 1 < Temp * 2",
          "Speed = 2.0", "Count MOD 2 = 0", "Start = Stop", "Start <> TRUE", "-Speed < -9223372036854775808",
          "Speed / 3 * 2 - 1 <= 0", "TRUE", "Start XOR Stop & MOTOR_ON"}) {
        INFO(ok);
        CHECK(issuesOf(ok).empty());
    }
}

TEST_CASE("type check issues carry codes, messages and spans", "[condition]")
{
    struct Case {
        std::string text;
        std::string code;
        std::string message;
        Span span;
    };
    const std::vector<Case> cases = {
        {"Speed AND Start", "GG204", "AND needs BOOL operands, but 'Speed' is INT", {0, 5}},
        {"Start OR 5", "GG204", "OR needs BOOL operands, but '5' is an integer", {9, 10}},
        {"(Speed + 1) AND Start", "GG204", "AND needs BOOL operands, but 'Speed + 1' is an integer", {1, 10}},
        {"Unknown OR Start", "GG203", "'Unknown' is not a declared variable", {0, 7}},
        {"Speed + 1", "GG204", "a condition must be BOOL, but 'Speed + 1' is an integer", {0, 9}},
        {"Temp", "GG204", "a condition must be BOOL, but 'Temp' is a real number", {0, 4}},
        {"Start = Speed", "GG204", "'=' needs two operands of the same kind, but 'Start' is BOOL and 'Speed' is INT", {0, 13}},
        {"Speed MOD 2.5 > 1", "GG204", "MOD needs integer operands, but '2.5' is a real number", {10, 13}},
        {"Temp MOD 2 > 1", "GG204", "MOD needs integer operands, but 'Temp' is REAL", {0, 4}},
        {"NOT Speed", "GG204", "NOT needs a BOOL operand, but 'Speed' is INT", {4, 9}},
        {"-Start", "GG204", "unary '-' needs a numeric operand, but 'Start' is BOOL", {1, 6}},
        {"Start + 1 > 0", "GG204", "'+' needs numeric operands, but 'Start' is BOOL", {0, 5}},
        {"Stop AND Start < 3", "GG204", "'<' needs numeric operands, but 'Start' is BOOL", {9, 14}},
        {"Speed > 99999999999999999999", "GG204", "'99999999999999999999' is out of range", {8, 28}},
        {"Speed > 9223372036854775808", "GG204", "'9223372036854775808' is out of range", {8, 27}},
        {"Temp < 1e999", "GG204", "'1e999' is out of range for LREAL", {7, 12}},
    };
    for (const Case& c : cases) {
        INFO("condition: " << c.text);
        const auto issues = issuesOf(c.text);
        REQUIRE(issues.size() == 1);
        CHECK(issues[0].code == c.code);
        CHECK(issues[0].message.rfind(c.message, 0) == 0);
        CHECK(issues[0].span == c.span);
    }
}

TEST_CASE("type errors carry their kind and pieces, and the same English text", "[condition]")
{
    using Kind = TypeError::Kind;
    using Operand = TypeError::Operand;
    struct Case {
        std::string text;
        Kind kind;
        std::string op;
        Operand first;
        Operand second;
        std::string message; // exact
    };
    const std::vector<Case> cases = {
        {"Speed + 1", Kind::NotBoolCondition, "", {"Speed + 1", "integer"}, {},
         "a condition must be BOOL, but 'Speed + 1' is an integer"},
        {"Temp", Kind::NotBoolCondition, "", {"Temp", "real"}, {}, "a condition must be BOOL, but 'Temp' is a real number"},
        {"NOT Speed", Kind::NotBoolOperand, "NOT", {"Speed", "INT"}, {}, "NOT needs a BOOL operand, but 'Speed' is INT"},
        {"NOT 2.5", Kind::NotBoolOperand, "NOT", {"2.5", "real"}, {}, "NOT needs a BOOL operand, but '2.5' is a real number"},
        {"-Start", Kind::NotNumericOperand, "'-'", {"Start", "BOOL"}, {},
         "unary '-' needs a numeric operand, but 'Start' is BOOL"},
        {"Speed AND Start", Kind::BoolOperands, "AND", {"Speed", "INT"}, {},
         "AND needs BOOL operands, but 'Speed' is INT"},
        {"Start XOR (Speed + 1)", Kind::BoolOperands, "XOR", {"Speed + 1", "integer"}, {},
         "XOR needs BOOL operands, but 'Speed + 1' is an integer"},
        {"Start + 1 > 0", Kind::NumericOperands, "'+'", {"Start", "BOOL"}, {},
         "'+' needs numeric operands, but 'Start' is BOOL"},
        {"(Start AND Stop) <= 3", Kind::NumericOperands, "'<='", {"Start AND Stop", "BOOL"}, {},
         "'<=' needs numeric operands, but 'Start AND Stop' is BOOL"},
        {"Temp MOD 2 > 1", Kind::IntegerOperands, "MOD", {"Temp", "REAL"}, {},
         "MOD needs integer operands, but 'Temp' is REAL"},
        {"Start = Speed", Kind::SameKindOperands, "'='", {"Start", "BOOL"}, {"Speed", "INT"},
         "'=' needs two operands of the same kind, but 'Start' is BOOL and 'Speed' is INT"},
        {"2.5 <> Stop", Kind::SameKindOperands, "'<>'", {"2.5", "real"}, {"Stop", "BOOL"},
         "'<>' needs two operands of the same kind, but '2.5' is a real number and 'Stop' is BOOL"},
        {"Start AND (Count + Count + Count + Count + Count + 1)", Kind::BoolOperands, "AND",
         {"Count + Count + Count + Count + Count...", "integer"}, {},
         "AND needs BOOL operands, but 'Count + Count + Count + Count + Count...' is an integer"},
        {"Speed > 9223372036854775808", Kind::IntegerLiteralRange, "", {"9223372036854775808", ""}, {},
         "'9223372036854775808' is out of range: integer literals go up to 9223372036854775807 (LINT)"},
        {"Temp < 1e999", Kind::RealLiteralRange, "", {"1e999", ""}, {},
         "'1e999' is out of range for LREAL (-1.8E308..1.8E308)"},
    };
    for (const Case& c : cases) {
        INFO("condition: " << c.text);
        const auto issues = issuesOf(c.text);
        REQUIRE(issues.size() == 1);
        CHECK(issues[0].code == "GG204");
        REQUIRE(issues[0].error.has_value());
        const TypeError& error = *issues[0].error;
        CHECK(error.kind == c.kind);
        CHECK(error.op == c.op);
        CHECK(error.first == c.first);
        CHECK(error.second == c.second);
        CHECK(issues[0].message == c.message);
        CHECK(toText(error) == c.message);

        // The form GG204 appends to Diagnostic::arguments reads back to the same error.
        std::vector<std::string> arguments{"A1->F1"};
        appendArguments(error, arguments);
        REQUIRE(arguments.size() == 7);
        CHECK(arguments[1] == kindName(c.kind));
        const std::optional<TypeError> back = typeErrorFromArguments(arguments, 1);
        REQUIRE(back.has_value());
        CHECK(*back == error);
    }

    // An undeclared variable is GG203, with no type error.
    const auto undeclared = issuesOf("Unknown OR Start");
    REQUIRE(undeclared.size() == 1);
    CHECK_FALSE(undeclared[0].error.has_value());

    // No reachable operand is of unknown type today (an unknown operand raises
    // no further issue); the kind keeps its text.
    CHECK(toText(Operand{"x", "unknown"}) == "'x' is of unknown type");

    // Every kind has its own name.
    std::set<std::string_view> names;
    for (int k = 0; k <= static_cast<int>(Kind::RealLiteralRange); ++k) {
        const std::string_view name = kindName(static_cast<Kind>(k));
        CHECK_FALSE(name.empty());
        CHECK(typeErrorKind(name) == static_cast<Kind>(k));
        names.insert(name);
    }
    CHECK(names.size() == static_cast<std::size_t>(Kind::RealLiteralRange) + 1);

    // Arguments from elsewhere (an unknown kind, too few) are not read.
    CHECK_FALSE(typeErrorFromArguments({"unknown-kind", "", "", "", "", ""}, 0));
    CHECK_FALSE(typeErrorFromArguments({"bool-operands", "AND", "Speed", "INT", ""}, 0));
}

TEST_CASE("type errors do not cascade and come in source order", "[condition]")
{
    // The undeclared variable is reported once; the + and > above it stay quiet.
    const auto unknown = issuesOf("Foo + 1 > 2");
    REQUIRE(unknown.size() == 1);
    CHECK(unknown[0].code == "GG203");

    const auto several = issuesOf("Nope OR Speed AND (Temp < Start)");
    REQUIRE(several.size() == 3);
    CHECK(several[0].code == "GG203");
    CHECK(several[0].span == Span{0, 4});
    CHECK(several[1].message == "AND needs BOOL operands, but 'Speed' is INT");
    CHECK(several[2].message == "'<' needs numeric operands, but 'Start' is BOOL");
    CHECK(several[2].span == Span{26, 31});

    const auto both = issuesOf("Start < Stop");
    CHECK(both.size() == 2);
}

TEST_CASE("valueKind reports the kind of any node", "[condition]")
{
    const std::vector<Variable> variables = testVariables();
    const SymbolTable symbols(variables);
    const Expression e = parsed("Speed * Temp > Count + 1 AND Start");
    const Node& root = e.rootNode();
    CHECK(valueKind(e, e.root, symbols) == ValueKind::Bool);
    const Node& comparison = e.at(root.left);
    CHECK(valueKind(e, comparison.left, symbols) == ValueKind::Real);
    CHECK(valueKind(e, comparison.right, symbols) == ValueKind::Integer);
    CHECK(valueKind(e, root.right, symbols) == ValueKind::Bool);
    const Expression unknown = parsed("Foo + 1");
    CHECK(valueKind(unknown, unknown.root, symbols) == ValueKind::Unknown);
    CHECK(valueKind(unknown, 99, symbols) == ValueKind::Unknown);
}

// --- renaming ------------------------------------------------------------------

TEST_CASE("renameIdentifier replaces whole identifiers and keeps every other byte", "[condition]")
{
    CHECK(renameIdentifier("Start AND (start_2 OR  START)", "Start", "Go") == "Go AND (start_2 OR  Go)");
    CHECK(renameIdentifier("MyStart or Start_x", "Start", "Go") == "MyStart or Start_x");
    CHECK(renameIdentifier("  x>1\tAND\nx<5  ", "X", "Speed") == "  Speed>1\tAND\nSpeed<5  ");
    CHECK(renameIdentifier("NOTIFY AND NOT x", "x", "y") == "NOTIFY AND NOT y");
    // Text that does not parse is renamed all the same.
    CHECK(renameIdentifier("Start AND (", "start", "Go") == "Go AND (");
    CHECK(renameIdentifier("Start := 1", "Start", "Go") == "Go := 1");
    // A variable that was (wrongly) given a reserved name still follows the rename.
    CHECK(renameIdentifier("ON AND x", "on", "PowerOn") == "PowerOn AND x");
    // Operators and literals are never renamed.
    CHECK(renameIdentifier("a AND TRUE", "AND", "x") == "a AND TRUE");
    CHECK(renameIdentifier("a AND TRUE", "true", "x") == "a AND TRUE");
    CHECK(renameIdentifier("", "a", "b").empty());
}

// --- evaluation ----------------------------------------------------------------

namespace {

Value evaluateText(std::string_view text, const std::map<std::string, Value>& values = {})
{
    const Expression e = parsed(text);
    return evaluate(e, [&](int node) {
        const auto found = values.find(toUpperAscii(e.at(node).text));
        return found == values.end() ? Value{false} : found->second;
    });
}

std::string show(std::string_view text, const std::map<std::string, Value>& values = {})
{
    return formatValue(evaluateText(text, values));
}

} // namespace

TEST_CASE("evaluation follows ST semantics", "[condition]")
{
    // formatValue tells the kinds apart: 3 is an integer, 3.0 a real.
    CHECK(show("2 + 3 * 4") == "14");
    CHECK(show("7 / 2") == "3");
    CHECK(show("-7 / 2") == "-3");
    CHECK(show("-7 MOD 3") == "-1");
    CHECK(show("7 MOD -3") == "1");
    // An integer division by zero is a PLC fault: evaluate() goes on with 0
    // and names the node to whoever asks (the simulator stops there).
    CHECK(show("7 / 0") == "0");
    CHECK(show("7 MOD 0") == "0");
    int fault = -1;
    const Expression divides = parsed("1 + 7 MOD (3 - 3)");
    evaluate(divides, {}, fault);
    REQUIRE(fault >= 0);
    CHECK(divides.at(fault).binaryOp == BinaryOp::Modulo);
    fault = -1;
    evaluate(parsed("7 / 2 + 1.5 / 0"), {}, fault);
    CHECK(fault == -1); // a REAL division is no fault
    // REAL division is IEEE 754, as on the PLC.
    CHECK(std::get<double>(evaluateText("1.5 / 0")) == std::numeric_limits<double>::infinity());
    CHECK(std::get<double>(evaluateText("-1.5 / 0")) == -std::numeric_limits<double>::infinity());
    CHECK(std::isnan(std::get<double>(evaluateText("0.0 / 0.0"))));
    CHECK(show("0.0 / 0.0 = 0.0 / 0.0") == "FALSE");
    CHECK(show("0.0 / 0.0 < 1.0 OR 0.0 / 0.0 >= 1.0") == "FALSE");
    CHECK(show("0.0 / 0.0 <> 0.0 / 0.0") == "TRUE");
    CHECK(show("1.5 * 2") == "3.0");
    CHECK(show("3 / 2.0") == "1.5");
    CHECK(show("1_000 + 1") == "1001");
    CHECK(show("9223372036854775807 + 1") == "-9223372036854775808");
    CHECK(show("-9223372036854775808") == "-9223372036854775808");
    CHECK(show("-9223372036854775808 / -1") == "-9223372036854775808");
    CHECK(show("-9223372036854775808 MOD -1") == "0");
    CHECK(show("-(-9223372036854775808)") == "-9223372036854775808");
    CHECK(show("2 = 2.0") == "TRUE");
    CHECK(show("TRUE XOR true") == "FALSE");
    CHECK(show("FALSE < TRUE") == "TRUE");
    CHECK(show("NOT NOT TRUE") == "TRUE");
    CHECK(show("1.5e3 > 1_499") == "TRUE");
}

TEST_CASE("evaluation reads variables through the callback", "[condition]")
{
    const std::map<std::string, Value> values = {
        {"A", Value{false}}, {"B", Value{true}}, {"SPEED", Value{std::int64_t{120}}}, {"TEMP", Value{20.5}}};
    CHECK(show("NOT a AND b", values) == "TRUE");
    CHECK(show("NOT (a AND b)", values) == "TRUE");
    CHECK(show("a OR b AND FALSE", values) == "FALSE");
    CHECK(show("Speed > 100 AND Temp < 21", values) == "TRUE");
    CHECK(show("Speed * 2 + Temp", values) == "260.5");
    CHECK(show("-Speed MOD 7", values) == "-1");
    CHECK(isTrue(evaluateText("b", values)));
    CHECK_FALSE(isTrue(evaluate(Expression{}, {})));
}

TEST_CASE("default values convert to evaluator values", "[condition]")
{
    CHECK(parseValue(IecType::Bool, "") == Value{false});
    CHECK(parseValue(IecType::Bool, "true") == Value{true});
    CHECK(parseValue(IecType::Bool, "1") == Value{true});
    CHECK(parseValue(IecType::Int, "-32768") == Value{std::int64_t{-32768}});
    CHECK(parseValue(IecType::Dint, "1_000") == Value{std::int64_t{1000}});
    CHECK(parseValue(IecType::Lint, "-9223372036854775808") == Value{std::numeric_limits<std::int64_t>::min()});
    CHECK(parseValue(IecType::Ulint, "18446744073709551615") == Value{std::numeric_limits<std::int64_t>::max()});
    CHECK(parseValue(IecType::Real, "") == Value{0.0});
    CHECK(parseValue(IecType::Lreal, "-2.5E2") == Value{-250.0});
    CHECK(parseValue(IecType::Real, "3") == Value{3.0});
    CHECK_FALSE(parseValue(IecType::Sint, "300"));
    CHECK_FALSE(parseValue(IecType::Bool, "yes"));
}

TEST_CASE("values format as ST literals", "[condition]")
{
    CHECK(formatValue(Value{true}) == "TRUE");
    CHECK(formatValue(Value{false}) == "FALSE");
    CHECK(formatValue(Value{std::int64_t{-42}}) == "-42");
    CHECK(formatValue(Value{1.5}) == "1.5");
    CHECK(formatValue(Value{2.0}) == "2.0");
    CHECK(formatValue(Value{1e20}) == "1.0e+20");
}

} // namespace test_condition
