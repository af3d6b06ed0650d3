#pragma once

#include "core/condition/conditionsyntax.h"

#include <functional>

namespace core {

// Where an explanation of a condition looks for what decides its value:
// NOT passes to its operand; AND and OR to the operands that decide the
// result (an AND that is FALSE: its FALSE operands; an OR that is TRUE: its
// TRUE operands; otherwise all of them); XOR to both. Every other node is a
// leaf, handed to `explainLeaf`. The GEMMA simulator and the nested engine
// share this walk, each with its own readings of the leaves.
void visitDecidingOperands(const cond::Expression& expression, int node, const std::function<bool(int)>& isTrueAt,
                           const std::function<void(int)>& explainLeaf);

} // namespace core
