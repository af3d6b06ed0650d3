#pragma once

// Why a condition does not type-check (GG204), as data: the editor words it
// in the UI language, toText() gives the English text the command line, the
// generated code and tests use. Code fragments (operators, subexpressions,
// literals, type names) are kept as written: they are code in every language.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace core::cond {

struct TypeError {
    enum class Kind {
        NotBoolCondition,     // the whole condition; first: it
        NotBoolOperand,       // NOT; first: its operand
        NotNumericOperand,    // unary '-'; first: its operand
        BoolOperands,         // AND, OR, XOR; first: the operand at fault
        NumericOperands,      // < > <= >= + - * /; first: the operand at fault
        IntegerOperands,      // MOD; first: the operand at fault
        SameKindOperands,     // = <>; first, second: both operands
        IntegerLiteralRange,  // first: the literal, beyond LINT
        RealLiteralRange,     // first: the literal, beyond LREAL
    };

    // A subexpression and what it is.
    struct Operand {
        std::string text; // as printed, shortened past 40 characters ("Speed + 1")
        // An IEC type name for a declared variable or a BOOL value ("INT",
        // "BOOL"); else kIntegerValue, kRealValue or kUnknownValue.
        std::string type;

        friend bool operator==(const Operand&, const Operand&) = default;
    };

    static constexpr std::string_view kIntegerValue = "integer";
    static constexpr std::string_view kRealValue = "real";
    static constexpr std::string_view kUnknownValue = "unknown";

    Kind kind = Kind::NotBoolCondition;
    // The operator as the message names it: keywords bare (AND, MOD, NOT),
    // symbols quoted ('<', '-'); empty for the condition and the literals.
    std::string op;
    Operand first;
    Operand second; // SameKindOperands only

    friend bool operator==(const TypeError&, const TypeError&) = default;
};

// "AND needs BOOL operands, but 'Speed' is INT".
std::string toText(const TypeError& error);

// "'Speed' is INT", "'Speed + 1' is an integer": how toText() describes an operand.
std::string toText(const TypeError::Operand& operand);

// A stable name per kind for Diagnostic::arguments ("bool-operands"), and back.
std::string_view kindName(TypeError::Kind kind);
std::optional<TypeError::Kind> typeErrorKind(std::string_view name);

// The error as GG204 appends it to Diagnostic::arguments (docs/diagnostics.md):
// kind name, operator, first operand text and type, second operand text and
// type. typeErrorFromArguments reads them back from position `first`;
// nullopt when they are missing or the kind is unknown.
void appendArguments(const TypeError& error, std::vector<std::string>& arguments);
std::optional<TypeError> typeErrorFromArguments(const std::vector<std::string>& arguments, std::size_t first);

} // namespace core::cond
