#include "core/condition/conditionparseerror.h"

#include "core/model/enumnames.h"
#include "core/model/messagetext.h"

#include <charconv>
#include <cstdio>

namespace core::cond {

namespace {

using ParseKind = ParseError::Kind;

// The names are part of the arguments' contract: never rename one.
constexpr EnumName<ParseKind> kParseKindNames[] = {
    {ParseKind::Empty, "empty"},
    {ParseKind::Comment, "comment"},
    {ParseKind::ColonEquals, "colon-equals"},
    {ParseKind::DoubleEquals, "double-equals"},
    {ParseKind::BangEquals, "bang-equals"},
    {ParseKind::Bang, "bang"},
    {ParseKind::DoubleAmpersand, "double-ampersand"},
    {ParseKind::Pipe, "pipe"},
    {ParseKind::Power, "power"},
    {ParseKind::Semicolon, "semicolon"},
    {ParseKind::InvalidUtf8, "invalid-utf8"},
    {ParseKind::NonAscii, "non-ascii"},
    {ParseKind::TypedLiteral, "typed-literal"},
    {ParseKind::QualifiedName, "qualified-name"},
    {ParseKind::InvalidNumber, "invalid-number"},
    {ParseKind::IfThen, "if-then"},
    {ParseKind::TypeName, "type-name"},
    {ParseKind::Keyword, "keyword"},
    {ParseKind::ControlCharacter, "control-character"},
    {ParseKind::UnexpectedCharacter, "unexpected-character"},
    {ParseKind::TooComplex, "too-complex"},
    {ParseKind::TooDeepParentheses, "too-deep-parentheses"},
    {ParseKind::TooDeepUnary, "too-deep-unary"},
    {ParseKind::UnmatchedClose, "unmatched-close"},
    {ParseKind::OperandBefore, "operand-before"},
    {ParseKind::EmptyParentheses, "empty-parentheses"},
    {ParseKind::OperandAfter, "operand-after"},
    {ParseKind::UnclosedAtEnd, "unclosed-at-end"},
    {ParseKind::Unclosed, "unclosed"},
    {ParseKind::AfterCondition, "after-condition"},
    {ParseKind::MissingOperator, "missing-operator"},
    {ParseKind::EdgeOperand, "edge-operand"},
    {ParseKind::DurationWithoutStep, "duration-without-step"},
    {ParseKind::DurationStepExpected, "duration-step-expected"},
    {ParseKind::ZeroDuration, "zero-duration"},
    {ParseKind::InvalidDuration, "invalid-duration"},
    {ParseKind::EmptyAction, "empty-action"},
    {ParseKind::ActionTargetNotVariable, "action-target-not-variable"},
    {ParseKind::UnsupportedQualifier, "unsupported-qualifier"},
    {ParseKind::QualifierWithAssignment, "qualifier-with-assignment"},
    {ParseKind::StoredWithCondition, "stored-with-condition"},
    {ParseKind::AssignmentWithoutValue, "assignment-without-value"},
    {ParseKind::ConditionMissing, "condition-missing"},
    {ParseKind::EqualsForAssignment, "equals-for-assignment"},
    {ParseKind::AfterAction, "after-action"},
    {ParseKind::PropertyQuantifier, "property-quantifier"},
    {ParseKind::StepAfterIn, "step-after-in"},
};

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
    case ParseKind::Comment: return "comments are not allowed in a condition";
    case ParseKind::ColonEquals: return "use = to compare; := is assignment";
    case ParseKind::DoubleEquals: return "use = to compare; == is not Structured Text";
    case ParseKind::BangEquals: return "use <> for 'not equal'";
    case ParseKind::Bang: return "use NOT for negation";
    case ParseKind::DoubleAmpersand: return "use AND (or &) for 'and'";
    case ParseKind::Pipe: return "use OR for 'or'";
    case ParseKind::Power: return "'**' (power) is not supported in a condition";
    case ParseKind::Semicolon: return "';' is not allowed in a condition: write only the expression";
    case ParseKind::InvalidUtf8: return "the text contains bytes that are not valid UTF-8";
    case ParseKind::NonAscii:
        return quoted(e.found) + " contains a non-ASCII character: names use ASCII letters, digits and _ only";
    case ParseKind::TypedLiteral:
        return quoted(e.found) + " is not supported: write plain decimal numbers, TRUE or FALSE"
                                 " (no typed, based or time literals)";
    case ParseKind::QualifiedName: return quoted(e.found) + ": qualified names are not allowed, write the variable name alone";
    case ParseKind::InvalidNumber: return quoted(e.found) + " is not a valid number";
    case ParseKind::IfThen: return notAllowed(e, "write only the boolean expression, without IF ... THEN");
    case ParseKind::TypeName: return notAllowed(e, "it is a type name");
    case ParseKind::Keyword: return notAllowed(e, "it is an IEC 61131-3 keyword");
    case ParseKind::ControlCharacter: return "unexpected control character (byte " + byteText(e.number) + ")";
    case ParseKind::UnexpectedCharacter: return "unexpected character " + quoted(e.found);
    default: return {};
    }
}

std::string nestedText(const ParseError& e)
{
    switch (e.kind) {
    case ParseKind::EdgeOperand:
        return "an edge (RE, FE, ↑, ↓) applies to a variable name" + (e.found.empty() ? "" : ", not to " + quoted(e.found));
    case ParseKind::DurationWithoutStep:
        return "the duration " + quoted(e.found) + " must be followed by /X<step>, as in " + e.found + "/X3";
    case ParseKind::DurationStepExpected:
        return "expected a step activity X<step> after '/' of the duration" + (e.found.empty() ? "" : ", found " + quoted(e.found));
    case ParseKind::ZeroDuration: return "the duration " + quoted(e.found) + " is zero: write a positive duration";
    case ParseKind::InvalidDuration:
        return quoted(e.found) + " is not a valid duration: write for example 200ms, 5s, 1m30s or T#5s (units d, h, m, s, ms, largest first)";
    case ParseKind::EmptyAction: return "empty action: write for example Valve, S Valve, R Valve or Count := Count + 1";
    case ParseKind::ActionTargetNotVariable:
        return "an action writes a variable: " + quoted(e.found) + " is not a variable name";
    case ParseKind::UnsupportedQualifier:
        return "the qualifier " + quoted(e.found) + " is not supported: use N (or none), S, R or an assignment V := value";
    case ParseKind::QualifierWithAssignment:
        return "an assignment takes no qualifier: write V := value, without " + quoted(e.found);
    case ParseKind::StoredWithCondition:
        return "a stored action (" + e.found + ") takes no IF condition: only continuous actions are conditional";
    case ParseKind::AssignmentWithoutValue: return "expected a value after ':='";
    case ParseKind::ConditionMissing: return "expected a condition after IF";
    case ParseKind::EqualsForAssignment: return "use := to assign a value; = compares";
    case ParseKind::AfterAction: return "unexpected " + quoted(e.found) + " after a complete action";
    case ParseKind::PropertyQuantifier:
        return e.found.empty() ? "a property starts with never or always"
                               : "a property starts with never or always, not " + quoted(e.found);
    case ParseKind::StepAfterIn:
        return e.found.empty() ? "expected a GEMMA step after 'in'"
                               : "expected a GEMMA step after 'in', found " + quoted(e.found);
    default: return {};
    }
}

std::string structureText(const ParseError& e)
{
    const std::string number = std::to_string(e.number);
    switch (e.kind) {
    case ParseKind::Empty: return "empty condition: write when the transition fires (TRUE if it is always ready), or hide the transition if the machine does not need it";
    case ParseKind::TooComplex: return "condition too complex: operators nested more than " + number + " levels deep";
    case ParseKind::TooDeepParentheses: return "condition nested too deeply: more than " + number + " levels of parentheses";
    case ParseKind::TooDeepUnary: return "condition nested too deeply: more than " + number + " levels of unary operators";
    case ParseKind::UnmatchedClose: return "unmatched ')': no '(' opens it";
    case ParseKind::OperandBefore: return "expected an operand before " + quoted(e.found);
    case ParseKind::EmptyParentheses: return "empty parentheses: expected an expression inside '( )'";
    case ParseKind::OperandAfter:
        return "expected an operand after " + quoted(e.previous) + (e.found.empty() ? "" : ", found " + quoted(e.found));
    case ParseKind::UnclosedAtEnd: return "unmatched '(' at column " + number + ": missing ')'";
    case ParseKind::Unclosed:
        return "unexpected " + quoted(e.found) + ": expected an operator or ')' to close the '(' at column " + number;
    case ParseKind::AfterCondition: return "unexpected " + quoted(e.found) + " after a complete condition";
    case ParseKind::MissingOperator: return "unexpected " + quoted(e.found) + " after a complete condition (missing operator?)";
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
    return nameIn(kParseKindNames, kind);
}

std::optional<ParseError::Kind> parseErrorKind(std::string_view name)
{
    return valueIn(kParseKindNames, name);
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
    const std::optional<ParseKind> kind = parseErrorKind(arguments[first]);
    const std::string& numberText = arguments[first + 3];
    std::size_t number = 0;
    const auto [end, status] = std::from_chars(numberText.data(), numberText.data() + numberText.size(), number);
    if (!kind || status != std::errc() || end != numberText.data() + numberText.size())
        return std::nullopt;
    return makeParseError(*kind, Span{}, arguments[first + 1], arguments[first + 2], number);
}

} // namespace core::cond
