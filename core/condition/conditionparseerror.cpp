#include "core/condition/conditionparseerror.h"

#include "core/model/enumnames.h"

#include <charconv>
#include <cstdio>

namespace core::cond {

namespace {

using Kind = ParseError::Kind;

// The names are part of the arguments' contract: never rename one.
constexpr EnumName<Kind> kKindNames[] = {
    {Kind::Empty, "empty"},
    {Kind::Comment, "comment"},
    {Kind::ColonEquals, "colon-equals"},
    {Kind::DoubleEquals, "double-equals"},
    {Kind::BangEquals, "bang-equals"},
    {Kind::Bang, "bang"},
    {Kind::DoubleAmpersand, "double-ampersand"},
    {Kind::Pipe, "pipe"},
    {Kind::Power, "power"},
    {Kind::Semicolon, "semicolon"},
    {Kind::InvalidUtf8, "invalid-utf8"},
    {Kind::NonAscii, "non-ascii"},
    {Kind::TypedLiteral, "typed-literal"},
    {Kind::QualifiedName, "qualified-name"},
    {Kind::InvalidNumber, "invalid-number"},
    {Kind::IfThen, "if-then"},
    {Kind::TypeName, "type-name"},
    {Kind::Keyword, "keyword"},
    {Kind::ControlCharacter, "control-character"},
    {Kind::UnexpectedCharacter, "unexpected-character"},
    {Kind::TooComplex, "too-complex"},
    {Kind::TooDeepParentheses, "too-deep-parentheses"},
    {Kind::TooDeepUnary, "too-deep-unary"},
    {Kind::UnmatchedClose, "unmatched-close"},
    {Kind::OperandBefore, "operand-before"},
    {Kind::EmptyParentheses, "empty-parentheses"},
    {Kind::OperandAfter, "operand-after"},
    {Kind::UnclosedAtEnd, "unclosed-at-end"},
    {Kind::Unclosed, "unclosed"},
    {Kind::AfterCondition, "after-condition"},
    {Kind::MissingOperator, "missing-operator"},
    {Kind::EdgeOperand, "edge-operand"},
    {Kind::DurationWithoutStep, "duration-without-step"},
    {Kind::DurationStepExpected, "duration-step-expected"},
    {Kind::ZeroDuration, "zero-duration"},
    {Kind::InvalidDuration, "invalid-duration"},
    {Kind::EmptyAction, "empty-action"},
    {Kind::ActionTargetNotVariable, "action-target-not-variable"},
    {Kind::UnsupportedQualifier, "unsupported-qualifier"},
    {Kind::QualifierWithAssignment, "qualifier-with-assignment"},
    {Kind::StoredWithCondition, "stored-with-condition"},
    {Kind::AssignmentWithoutValue, "assignment-without-value"},
    {Kind::ConditionMissing, "condition-missing"},
    {Kind::EqualsForAssignment, "equals-for-assignment"},
    {Kind::AfterAction, "after-action"},
    {Kind::PropertyQuantifier, "property-quantifier"},
    {Kind::StepAfterIn, "step-after-in"},
};

std::string quoted(std::string_view text)
{
    return "'" + std::string(text) + "'";
}

std::string byteText(std::size_t byte)
{
    char buffer[8];
    std::snprintf(buffer, sizeof buffer, "0x%02X", static_cast<unsigned>(byte & 0xFF));
    return buffer;
}

std::string notAllowed(const ParseError& e, std::string_view why)
{
    return quoted(e.found) + " is not allowed in a condition: " + std::string(why);
}

// The texts of the tokens the language does not have.
std::string tokenText(const ParseError& e)
{
    switch (e.kind) {
    case Kind::Comment: return "comments are not allowed in a condition";
    case Kind::ColonEquals: return "use = to compare; := is assignment";
    case Kind::DoubleEquals: return "use = to compare; == is not Structured Text";
    case Kind::BangEquals: return "use <> for 'not equal'";
    case Kind::Bang: return "use NOT for negation";
    case Kind::DoubleAmpersand: return "use AND (or &) for 'and'";
    case Kind::Pipe: return "use OR for 'or'";
    case Kind::Power: return "'**' (power) is not supported in a condition";
    case Kind::Semicolon: return "';' is not allowed in a condition: write only the expression";
    case Kind::InvalidUtf8: return "the text contains bytes that are not valid UTF-8";
    case Kind::NonAscii:
        return quoted(e.found) + " contains a non-ASCII character: names use ASCII letters, digits and _ only";
    case Kind::TypedLiteral:
        return quoted(e.found) + " is not supported: write plain decimal numbers, TRUE or FALSE"
                                 " (no typed, based or time literals)";
    case Kind::QualifiedName: return quoted(e.found) + ": qualified names are not allowed, write the variable name alone";
    case Kind::InvalidNumber: return quoted(e.found) + " is not a valid number";
    case Kind::IfThen: return notAllowed(e, "write only the boolean expression, without IF ... THEN");
    case Kind::TypeName: return notAllowed(e, "it is a type name");
    case Kind::Keyword: return notAllowed(e, "it is an IEC 61131-3 keyword");
    case Kind::ControlCharacter: return "unexpected control character (byte " + byteText(e.number) + ")";
    case Kind::UnexpectedCharacter: return "unexpected character " + quoted(e.found);
    default: return {};
    }
}

std::string nestedText(const ParseError& e)
{
    switch (e.kind) {
    case Kind::EdgeOperand:
        return "an edge (RE, FE, ↑, ↓) applies to a variable name" + (e.found.empty() ? "" : ", not to " + quoted(e.found));
    case Kind::DurationWithoutStep:
        return "the duration " + quoted(e.found) + " must be followed by /X<step>, as in " + e.found + "/X3";
    case Kind::DurationStepExpected:
        return "expected a step activity X<step> after '/' of the duration" + (e.found.empty() ? "" : ", found " + quoted(e.found));
    case Kind::ZeroDuration: return "the duration " + quoted(e.found) + " is zero: write a positive duration";
    case Kind::InvalidDuration:
        return quoted(e.found) + " is not a valid duration: write for example 200ms, 5s, 1m30s or T#5s (units d, h, m, s, ms, largest first)";
    case Kind::EmptyAction: return "empty action: write for example Valve, S Valve, R Valve or Count := Count + 1";
    case Kind::ActionTargetNotVariable:
        return "an action writes a variable: " + quoted(e.found) + " is not a variable name";
    case Kind::UnsupportedQualifier:
        return "the qualifier " + quoted(e.found) + " is not supported: use N (or none), S, R or an assignment V := value";
    case Kind::QualifierWithAssignment:
        return "an assignment takes no qualifier: write V := value, without " + quoted(e.found);
    case Kind::StoredWithCondition:
        return "a stored action (" + e.found + ") takes no IF condition: only continuous actions are conditional";
    case Kind::AssignmentWithoutValue: return "expected a value after ':='";
    case Kind::ConditionMissing: return "expected a condition after IF";
    case Kind::EqualsForAssignment: return "use := to assign a value; = compares";
    case Kind::AfterAction: return "unexpected " + quoted(e.found) + " after a complete action";
    case Kind::PropertyQuantifier:
        return e.found.empty() ? "a property starts with never or always"
                               : "a property starts with never or always, not " + quoted(e.found);
    case Kind::StepAfterIn:
        return e.found.empty() ? "expected a GEMMA step after 'in'"
                               : "expected a GEMMA step after 'in', found " + quoted(e.found);
    default: return {};
    }
}

std::string structureText(const ParseError& e)
{
    const std::string number = std::to_string(e.number);
    switch (e.kind) {
    case Kind::Empty: return "empty condition: write when the transition fires (TRUE if it is always ready), or hide the transition if the machine does not need it";
    case Kind::TooComplex: return "condition too complex: operators nested more than " + number + " levels deep";
    case Kind::TooDeepParentheses: return "condition nested too deeply: more than " + number + " levels of parentheses";
    case Kind::TooDeepUnary: return "condition nested too deeply: more than " + number + " levels of unary operators";
    case Kind::UnmatchedClose: return "unmatched ')': no '(' opens it";
    case Kind::OperandBefore: return "expected an operand before " + quoted(e.found);
    case Kind::EmptyParentheses: return "empty parentheses: expected an expression inside '( )'";
    case Kind::OperandAfter:
        return "expected an operand after " + quoted(e.previous) + (e.found.empty() ? "" : ", found " + quoted(e.found));
    case Kind::UnclosedAtEnd: return "unmatched '(' at column " + number + ": missing ')'";
    case Kind::Unclosed:
        return "unexpected " + quoted(e.found) + ": expected an operator or ')' to close the '(' at column " + number;
    case Kind::AfterCondition: return "unexpected " + quoted(e.found) + " after a complete condition";
    case Kind::MissingOperator: return "unexpected " + quoted(e.found) + " after a complete condition (missing operator?)";
    default: return {};
    }
}

} // namespace

ParseError makeParseError(ParseError::Kind kind, Span span, std::string_view found, std::string_view previous,
                          std::size_t number)
{
    ParseError error;
    error.kind = kind;
    error.found = std::string(found);
    error.previous = std::string(previous);
    error.number = number;
    error.span = span;
    error.message = toText(error);
    return error;
}

std::string toText(const ParseError& error)
{
    std::string text = structureText(error);
    if (text.empty())
        text = nestedText(error);
    return text.empty() ? tokenText(error) : text;
}

std::string_view kindName(ParseError::Kind kind)
{
    return nameIn(kKindNames, kind);
}

std::optional<ParseError::Kind> parseErrorKind(std::string_view name)
{
    return valueIn(kKindNames, name);
}

void appendArguments(const ParseError& error, std::vector<std::string>& arguments)
{
    arguments.emplace_back(kindName(error.kind));
    arguments.push_back(error.found);
    arguments.push_back(error.previous);
    arguments.push_back(std::to_string(error.number));
}

std::optional<ParseError> parseErrorFromArguments(const std::vector<std::string>& arguments, std::size_t first)
{
    if (arguments.size() < first + 4)
        return std::nullopt;
    const std::optional<Kind> kind = parseErrorKind(arguments[first]);
    const std::string& numberText = arguments[first + 3];
    std::size_t number = 0;
    const auto [end, status] = std::from_chars(numberText.data(), numberText.data() + numberText.size(), number);
    if (!kind || status != std::errc() || end != numberText.data() + numberText.size())
        return std::nullopt;
    return makeParseError(*kind, Span{}, arguments[first + 1], arguments[first + 2], number);
}

} // namespace core::cond
