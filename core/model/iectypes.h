#pragma once

#include "core/condition/valueproblem.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace core {

// The elementary IEC 61131-3 types a GEMMA variable may have (spec §3).
enum class IecType { Bool, Sint, Int, Dint, Lint, Usint, Uint, Udint, Ulint, Real, Lreal };

// All types, in the order the spec lists them.
const std::vector<IecType>& allIecTypes();

// Upper-case IEC spelling: "BOOL", "UINT", ...
std::string_view iecTypeName(IecType type);

// Case-insensitive; nullopt when the text names no supported type.
std::optional<IecType> parseIecType(std::string_view name);

bool isIntegerType(IecType type);
bool isRealType(IecType type);
bool isNumericType(IecType type);

// Why a default value does not fit its type; nullopt when it fits or is empty.
std::optional<ValueProblem> valueProblem(IecType type, std::string_view value);

// valueProblem() in English; empty when the value fits or is empty.
// Examples: "'300' is out of range for SINT (-128..127)", "'yes' is not a BOOL literal".
std::string defaultValueProblem(IecType type, std::string_view value);

// The value of an IEC decimal literal: [+|-] digits ['.' digits] [E [+|-] digits],
// '_' digit separators allowed, read without the C locale. nullopt when the text
// is not one or exceeds a double; values too small for a double read as 0.
std::optional<double> parseRealLiteral(std::string_view text);

// The value the PLC starts with when no default is given ("FALSE", "0", "0.0").
std::string_view implicitDefault(IecType type);

// Identifier rules of spec §3, case-insensitive where IEC is.
enum class IdentifierProblem {
    None,
    Empty,
    InvalidCharacter, // not [A-Za-z_][A-Za-z0-9_]*, or non-ASCII
    DoubleUnderscore,
    TrailingUnderscore,
    Keyword,          // an IEC 61131-3 keyword or type name
    GeneratorName,    // a fixed name of the generated code (GEMMA, State, a token, ...); the
                      // step instances depend on the model (core/model/stepnames.h)
};

IdentifierProblem identifierProblem(std::string_view name);
std::string identifierProblemMessage(IdentifierProblem problem, std::string_view name);
bool isIecKeyword(std::string_view word);
bool isGeneratorName(std::string_view word);

// IEC integer digits, digit {['_'] digit}, from `from`: the position after
// them, or `from` when there are none. The condition lexer and the literal
// checks read numbers the same way.
std::size_t scanIecDigits(std::string_view text, std::size_t from);

// ASCII case-insensitive comparison, as IEC identifiers compare.
bool equalsIgnoreCase(std::string_view a, std::string_view b);
std::string toUpperAscii(std::string_view text);

} // namespace core
