#pragma once

// Divisions whose divisor can be zero (`Count / 0`, `Count MOD Batch`,
// `Rate / 0.0`). On the PLC an integer division or MOD by zero is a run-time
// fault (CODESYS raises an exception and the task stops); a REAL division
// follows IEEE 754 (x / 0.0 is +-INF, 0.0 / 0.0 is NaN). The checks refuse a
// divisor that is the constant zero (GG215 in GEMMA conditions, GG408 in
// nested texts: the condition or action is unusable, as a type error makes
// it) and warn about one that reads a variable (GG216, GG409).

#include "core/condition/conditionsyntax.h"

#include <string>
#include <string_view>
#include <vector>

namespace core::cond {

struct DivisionByZeroRisk {
    int node = -1;          // the Binary / or MOD node
    Span span;              // the whole division
    Span divisorSpan;
    bool constantZero = false; // the divisor reads nothing and is 0 (or 0.0): always a division by zero
    // Otherwise the divisor reads a variable (or a step activity...) and is
    // zero for some of its values.
};

// In source order. Meant for expressions that type-check: an integer
// division that reads no variable and is zero is reported, so is a REAL one.
std::vector<DivisionByZeroRisk> divisionsByZero(const Expression& expression);

// True when the subtree at `root` divides (/ or MOD) by something that reads
// a variable: its value may be a fault on the PLC (integer) or INF / NaN
// (REAL), so the verifier reads a comparison over it as a free BOOL.
bool dividesByVariable(const Expression& expression, int root);

// The English detail of a diagnostic, `text` being the text parsed:
// "'Count / 0' divides by zero: ..." or "the divisor of 'Count / Batch' can be zero: ...".
std::string divisionByZeroMessage(const DivisionByZeroRisk& risk, std::string_view text);

} // namespace core::cond
