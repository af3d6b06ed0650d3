#pragma once

// The engineer's own verification properties (docs/verification.md,
// "Properties"): `never P` or `always P`, where P is a condition of the GEMMA
// language with state predicates:
//   in S     the GEMMA step S is the active one at the end of the scan;
//   S.Xn     S is active, its function block has run in the scan (Entry is
//            FALSE) and step n of its nested GRAFCET is active;
//   a -> b   implication, looser than OR, grouping to the right.
// With single faults (docs/verification.md, "Single faults (--faults single)"):
//   faulted      a machine fault is in effect (it began at this scan or before);
//   2s/faulted   it has been in effect at least 2 s (scans since the one it
//                began before, that one included, times the cycle time).
// P is read at the end of every reachable scan: the inputs as that scan read
// them, the variables as it left them.

#include "core/condition/conditionparseerror.h"
#include "core/condition/conditiontypeerror.h"
#include "core/condition/conditionsyntax.h"
#include "core/model/span.h"

#include <cstdint>
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
inline constexpr const char* kFaultedWithoutFaults = "GP007"; // `faulted`, `T/faulted` outside a run with faults
} // namespace property

// What a property may read beyond the model.
struct PropertyAtoms {
    bool faulted = false; // `faulted` and `T/faulted` (a run with --faults single)
};

// Whether the node is the `faulted` atom (a variable named so that the
// model does not declare) or `T/faulted` (a StepDuration of number 0).
bool isFaultedAtom(const Model& model, const cond::Node& node);

// Scans that `T/faulted` needs to be TRUE at a cycle time: T / cycle, rounded up, at least 1.
std::int64_t faultedScansFor(std::int64_t durationMs, int cycleTimeMs);

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
// The same, the atoms allowed (a GEMMA model only: PackML has no faults).
std::vector<PropertyProblem> checkProperty(const Model& model, std::string_view text, const PropertyAtoms& atoms);

// checkProperty for a GEMMA model.
std::vector<PropertyProblem> checkGemmaProperty(const Model& model, std::string_view text);
std::vector<PropertyProblem> checkGemmaProperty(const Model& model, std::string_view text, const PropertyAtoms& atoms);

// The GEMMA step `S` of `in S` / `S.Xn` names, as the model spells it; empty
// when there is no visible step of that id (case-insensitive).
std::string propertyStepId(const Model& model, std::string_view written);

} // namespace core
