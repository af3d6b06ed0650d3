#pragma once

#include "core/condition/conditionparseerror.h"
#include "core/condition/conditionsyntax.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace core::cond {

enum class TokenKind {
    Identifier, IntegerLiteral, RealLiteral, True, False,
    Not, And, Or, Xor, Mod,
    Plus, Minus, Star, Slash,
    Equal, NotEqual, Less, Greater, LessEqual, GreaterEqual,
    LeftParen, RightParen,
    Invalid, // a character or word the language does not have
    End,
};

struct Token {
    TokenKind kind = TokenKind::End;
    Span span;
    std::string_view text; // points into the tokenized text
};

// Splits a condition into tokens; never fails (bad characters become Invalid
// tokens). The last token is always End.
std::vector<Token> tokenize(std::string_view text);

struct ParseResult {
    Expression expression;            // empty when error is set
    std::optional<ParseError> error;

    bool ok() const { return !error.has_value(); }
};

// Parses a whole condition. An empty or blank text is an error
// ("empty condition: write TRUE for a transition that is always ready").
ParseResult parse(std::string_view text);

// Replaces every identifier token equal (case-insensitively) to oldName by
// newName, leaving everything else byte for byte. Works on conditions that do
// not parse, since it only needs the tokens.
std::string renameIdentifier(std::string_view text, std::string_view oldName, std::string_view newName);

} // namespace core::cond
