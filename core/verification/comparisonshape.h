#pragma once

// Which numeric comparisons the exploration of both layers (and its Promela
// twin) decides on a variable's representative values. The representatives
// cover the regions that the constants of `variable <op> constant`
// comparisons cut the variable's type into, and nothing else: `Count >
// Count * 2` is TRUE exactly when Count < 0, a boundary no constant names, so
// such a comparison must be read as a free BOOL (docs/verification.md).

#include "core/condition/conditionsyntax.h"

namespace core::verification {

// The subexpression reads nothing (literals and the operators between them).
bool isConstantOperand(const cond::Expression& expression, int node);

// The comparison node is a bare variable against a constant operand
// (`Speed > 10`, `2 * 5 <= Speed`).
bool isVariableAgainstConstant(const cond::Expression& expression, int comparison);

} // namespace core::verification
