#pragma once

#include "core/condition/conditionparseerror.h"
#include "core/condition/conditionsyntax.h"

#include <cstdint>
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
    // Context::Nested only.
    RisingEdge,  // RE, ↑
    FallingEdge, // FE, ↓
    Duration,    // 5s, 200ms, 1m30s, T#5s
    // Context::Property only.
    Implies,     // ->
    In,          // in (before a step id)
    NestedStep,  // F1.X6
    End,
};

// Where a text is read. The texts of nested GRAFCETs (receptivities, action
// conditions and values) add step activities X<n>, durations t/X<n>, edges
// and Complete to the GEMMA condition language; in the Gemma context all of
// these are what they always were (X3 a variable, T#5s an error).
// Verification properties (core/verification/property.h) read their body in
// the Property context: the GEMMA language plus `in S` (S is the active GEMMA
// step), `S.Xn` (step n of S's nested GRAFCET is active) and `->`.
enum class Context { Gemma, Nested, Property };

struct ParseOptions {
    Context context = Context::Gemma;
};

// A nested GRAFCET's receptivities and actions (spec grafcet-layer.md).
inline constexpr ParseOptions kNestedOptions{Context::Nested};

struct Token {
    TokenKind kind = TokenKind::End;
    Span span;
    std::string_view text; // points into the tokenized text
};

// Splits a condition into tokens; never fails (bad characters become Invalid
// tokens). The last token is always End.
std::vector<Token> tokenize(std::string_view text, const ParseOptions& options = {});

struct ParseResult {
    Expression expression;            // empty when error is set
    std::optional<ParseError> error;

    bool ok() const { return !error.has_value(); }
};

// Parses a whole condition. An empty or blank text is an error
// ("empty condition: write when the transition fires (TRUE if it is always ready), or hide the transition if the machine does not need it").
ParseResult parse(std::string_view text, const ParseOptions& options = {});

// Parses the tokens [first, last) of a text tokenized in the given context
// (last excluded; an End token is supplied): the expressions inside an
// action. Spans stay offsets into the whole text.
ParseResult parseTokens(std::string_view text, const std::vector<Token>& tokens, std::size_t first,
                        std::size_t last, const ParseOptions& options);

// A duration literal in milliseconds: 200ms, 5s, 1m30s, 1.5s, T#5s, TIME#1h
// (units d, h, m, s, ms, largest first, each at most once; only the last may
// have a fraction). nullopt when malformed; a well-formed duration beyond
// 64 bits gives INT64_MAX, so that it parses and the checks can say it is too
// long (every duration above kMaxTimeMs is refused by them, GG407); 0 is
// returned as 0 (the parser refuses it).
std::optional<std::int64_t> parseDurationMs(std::string_view text);

// The longest duration IEC TIME holds (32-bit milliseconds), the longest TON
// preset the generated code can write: T#24d20h31m23s647ms.
inline constexpr std::int64_t kMaxTimeMs = 2'147'483'647;

// "X3" -> 3 in the Nested context: X (any case) and a step number without
// sign that fits an int; 0 otherwise.
int stepActivityNumber(std::string_view name);

// Replaces every identifier token equal (case-insensitively) to oldName by
// newName, leaving everything else byte for byte. Works on conditions that do
// not parse, since it only needs the tokens.
std::string renameIdentifier(std::string_view text, std::string_view oldName, std::string_view newName,
                             const ParseOptions& options = {});

} // namespace core::cond
