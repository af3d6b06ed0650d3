#pragma once

// Why a condition does not parse, as data: the editor words it in the UI
// language, toText() gives the English text the command line, the
// generated code and tests use. Code fragments (tokens, words, characters)
// are kept as written: they are code in every language.

#include "core/model/span.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace core::cond {

struct ParseError {
    enum class Kind {
        Empty, // a blank text
        // A token the language does not have; found: its text.
        Comment,            // (* ... *) or // ...
        ColonEquals,        // :=
        DoubleEquals,       // ==
        BangEquals,         // !=
        Bang,               // !
        DoubleAmpersand,    // &&
        Pipe,               // || or |
        Power,              // **
        Semicolon,          // ;
        InvalidUtf8,        // a word with bytes that are not UTF-8
        NonAscii,           // a word with a non-ASCII letter
        TypedLiteral,       // 16#FF, T#5s
        QualifiedName,      // GVL.Start
        InvalidNumber,      // 1.5.3, 12abc
        IfThen,             // IF, THEN, ELSIF, ELSE, END_IF
        TypeName,           // TIME, INT...
        Keyword,            // another IEC 61131-3 keyword
        ControlCharacter,   // number: the byte
        UnexpectedCharacter, // @, $...
        // The structure.
        TooComplex,         // number: the limit of the tree height
        TooDeepParentheses, // number: the limit of nested parentheses
        TooDeepUnary,       // number: the limit of nested unary operators
        UnmatchedClose,     // a ')' that no '(' opens
        OperandBefore,      // the text starts with found, an operator
        EmptyParentheses,   // ( )
        OperandAfter,       // no operand after previous; found: what is there instead, empty at the end
        UnclosedAtEnd,      // number: the column of the '(' the text ends in
        Unclosed,           // found instead of ')'; number: the column of the '('
        AfterCondition,     // found after a complete condition
        MissingOperator,    // found, an operand, after a complete condition
        // Receptivities of nested GRAFCETs (the Nested context).
        EdgeOperand,        // an edge (RE, FE, ↑, ↓) not followed by a variable name; found: what follows
        DurationWithoutStep, // found, a duration, not followed by /X<n>
        DurationStepExpected, // found after the '/' of a duration instead of X<n>
        ZeroDuration,       // found, a duration of 0
        InvalidDuration,    // found, a malformed duration (T#5x, 1s2h)
        // Actions of nested GRAFCETs.
        EmptyAction,        // a blank action
        ActionTargetNotVariable, // found where the variable an action writes should be
        UnsupportedQualifier, // found, an IEC 60848 / 61131-3 qualifier GG Studio does not have (P, L, D, SD...)
        QualifierWithAssignment, // found, the qualifier of `S V := 1`
        StoredWithCondition, // found, the qualifier of `S V IF c`
        AssignmentWithoutValue, // `V :=` with nothing after it
        ConditionMissing,   // `V IF` with nothing after it
        EqualsForAssignment, // `V = 1`: found "="
        AfterAction,        // found after a complete action
        // Verification properties (the Property context).
        PropertyQuantifier, // found where `never` or `always` should start the property; empty for a blank one
        StepAfterIn,        // found after `in` instead of a step id; empty at the end
    };

    Kind kind = Kind::Empty;
    std::string found;      // the offending text as written; empty for missing input
    std::string previous;   // OperandAfter: the token before the missing operand
    std::size_t number = 0; // a 1-based column, a limit or a byte, as the kind says
    Span span;              // where; an empty span at the end for missing input
    std::string message;    // English: toText() of the above, names what was expected and what was found

    friend bool operator==(const ParseError&, const ParseError&) = default;
};

// The error with its English message filled in.
ParseError makeParseError(ParseError::Kind kind, Span span, std::string_view found = {},
                          std::string_view previous = {}, std::size_t number = 0);

// "expected an operand after 'AND', found ')'".
std::string toText(const ParseError& error);

// A stable name per kind for Diagnostic::arguments ("operand-after"), and back.
std::string_view kindName(ParseError::Kind kind);
std::optional<ParseError::Kind> parseErrorKind(std::string_view name);

// The error as GG201 appends it to Diagnostic::arguments (docs/diagnostics.md):
// kind name, found, previous, number. parseErrorFromArguments reads them
// back from position `first`; nullopt when they are missing or unknown.
void appendArguments(const ParseError& error, std::vector<std::string>& arguments);
std::optional<ParseError> parseErrorFromArguments(const std::vector<std::string>& arguments, std::size_t first);

} // namespace core::cond
