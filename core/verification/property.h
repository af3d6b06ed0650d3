#pragma once

// The engineer's own verification properties (docs/verification.md,
// "Properties"): `never P` or `always P`, where P is a condition of the GEMMA
// language with state predicates:
//   in S     the GEMMA step S is the active one at the end of the scan;
//   S.Xn     S is active, its function block has run in the scan (Entry is
//            FALSE) and step n of its nested GRAFCET is active;
//   a -> b   implication, looser than OR, grouping to the right.
// P is read at the end of every reachable scan: the inputs as that scan read
// them, the variables as it left them.

#include "core/condition/conditionparseerror.h"
#include "core/condition/conditiontypeerror.h"
#include "core/condition/conditionsyntax.h"
#include "core/model/span.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace core {

class Model;

enum class PropertyKind { Never, Always };

struct ParsedProperty {
    PropertyKind kind = PropertyKind::Never;
    cond::Expression expression;           // the body; spans are offsets into the whole text
    std::optional<cond::ParseError> error; // the first syntax error, with its span
    bool ok() const { return !error.has_value(); }
};

ParsedProperty parseProperty(std::string_view text);

// Codes of property problems.
namespace property {
inline constexpr const char* kSyntax = "GP001";          // the text does not parse
inline constexpr const char* kUnknownVariable = "GP002"; // arguments: the name
inline constexpr const char* kUnknownStep = "GP003";     // `in S` or `S.Xn`: no visible step S; arguments: S
inline constexpr const char* kNoGrafcet = "GP004";       // `S.Xn`: S has no nested GRAFCET; arguments: S
inline constexpr const char* kUnknownNestedStep = "GP005"; // `S.Xn`: no step n in it; arguments: S, n
inline constexpr const char* kType = "GP006";            // a type error (the body is not BOOL, ...)
} // namespace property

struct PropertyProblem {
    Span span;
    std::string code;
    std::string message; // English
    std::vector<std::string> arguments;
    std::optional<cond::ParseError> syntax; // GP001: the error as data, for the UI's wording
    std::optional<cond::TypeError> type;    // GP006 (and some GP002): the type error as data
};

// Syntax first (one problem), then names and types against the model, by
// its template's rules. Empty when the property can be verified.
std::vector<PropertyProblem> checkProperty(const Model& model, std::string_view text);

// checkProperty for a GEMMA model.
std::vector<PropertyProblem> checkGemmaProperty(const Model& model, std::string_view text);

// The GEMMA step `S` of `in S` / `S.Xn` names, as the model spells it; empty
// when there is no visible step of that id (case-insensitive).
std::string propertyStepId(const Model& model, std::string_view written);

} // namespace core
