#pragma once

// Evaluates a condition the way the PLC does, for the simulator and the
// verifier (spec §6.6).

#include "core/condition/conditionsyntax.h"
#include "core/model/iectypes.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace core::cond {

using Value = std::variant<bool, std::int64_t, double>;

// The value of the expression, with `variableValue` giving the value of each
// Variable node (by node index) and, in the texts of nested GRAFCETs, of each
// StepActivity, StepDuration and Complete node and of each edge (the RE/FE
// Unary node as a whole: the evaluator does not look under an edge). ST semantics, computed in 64 bits (LINT /
// LREAL; a narrower PLC type differs only where it would overflow):
// - integer arithmetic wraps around instead of overflowing;
// - integer / truncates toward zero, MOD takes the sign of the dividend;
// - an integer division or MOD by zero is a fault on the PLC (the task
//   stops): evaluate() goes on with 0, the value the verifier's
//   over-approximation continues with, and reports the node to whoever
//   asks (the simulator stops the run there);
// - a REAL division follows IEEE 754 as the PLC does: x / 0.0 is +-INF,
//   0.0 / 0.0 is NaN, and every comparison with NaN is FALSE except <>;
// - an integer mixed with a real is converted to a real.
// The expression should pass typeCheck; otherwise numbers read as BOOL are
// TRUE when non-zero and BOOLs read as numbers are 1 or 0. An empty
// expression is FALSE.
Value evaluate(const Expression& expression, const std::function<Value(int node)>& variableValue);
// The same; `integerDivisionByZero` receives the index of the first / or MOD
// node that divided integers by zero, and is left unchanged when none did.
Value evaluate(const Expression& expression, const std::function<Value(int node)>& variableValue,
               int& integerDivisionByZero);

// IEEE 754 division, spelled out (a C++ division by zero is undefined).
double realDivision(double dividend, double divisor);

// TRUE, non-zero.
bool isTrue(const Value& value);

// The value of a variable's default (or of implicitDefault when empty), for
// a text defaultValueProblem accepts; nullopt otherwise. ULINT and UDINT
// values above 9223372036854775807 are clamped to it.
std::optional<Value> parseValue(IecType type, std::string_view text);

// The values an integer type holds, as the 64-bit values the evaluator
// computes with: ULINT and UDINT above 9223372036854775807 are clamped to it,
// as parseValue does. Non-integer types give the whole 64-bit range.
struct IntegerRange {
    std::int64_t low;
    std::int64_t high;
};
IntegerRange integerRange(IecType type);

// ST spelling: "TRUE", "-42", "1.5", "2.0".
std::string formatValue(const Value& value);

} // namespace core::cond
