#pragma once

// The syntax tree of a transition condition (spec §4). One parser
// (conditionparser.h) builds it; checking, code generation, renaming,
// simulation and analysis all read it.

#include "core/model/span.h"

#include <cstdint>
#include <string>
#include <vector>

namespace core::cond {

// RisingEdge, FallingEdge (`RE a` / `↑a`, `FE a` / `↓a`): nested GRAFCETs
// only; their operand is always a Variable node.
enum class UnaryOp { Not, Negate, RisingEdge, FallingEdge };

// Implies (`->`) exists only in verification properties (Context::Property
// of conditionparser.h); it binds loosest of all and groups to the right.
enum class BinaryOp {
    Or, Xor, And,
    Equal, NotEqual,
    Less, Greater, LessEqual, GreaterEqual,
    Add, Subtract,
    Multiply, Divide, Modulo,
    Implies,
};

// StepActivity (`X3`), StepDuration (`5s/X3`) and Complete exist only in
// the texts of nested GRAFCETs (Context::Nested of conditionparser.h).
// InStep (`in F1`: text is the GEMMA step id as written) and
// NestedStepActivity (`F1.X6`: text the GEMMA step id, number the nested
// step) exist only in verification properties (Context::Property).
enum class NodeKind {
    Variable, BoolLiteral, IntegerLiteral, RealLiteral, Unary, Binary,
    StepActivity, StepDuration, Complete,
    InStep, NestedStepActivity,
};

struct Node {
    NodeKind kind = NodeKind::BoolLiteral;
    Span span;          // the whole subexpression in the source text (parentheses excluded)
    std::string text;   // Variable: the name as written; literals: their text ("TRUE", "42", "1.5e3");
                        // StepActivity, StepDuration, Complete: as written ("X3", "5s/X3")
    UnaryOp unaryOp = UnaryOp::Not;
    BinaryOp binaryOp = BinaryOp::Or;
    int operand = -1;   // Unary: index of the operand in Expression::nodes
    int left = -1;      // Binary: indices of the operands
    int right = -1;
    int number = 0;              // StepActivity, StepDuration: the step number
    std::int64_t durationMs = 0; // StepDuration: the duration in milliseconds
};

// An arena of nodes; children always come before their parent.
struct Expression {
    std::vector<Node> nodes;
    int root = -1;

    bool empty() const { return root < 0; }
    const Node& rootNode() const { return nodes[static_cast<std::size_t>(root)]; }
    const Node& at(int index) const { return nodes[static_cast<std::size_t>(index)]; }
};

// ST spelling of an operator: "OR", "AND", "<=", "MOD", "NOT", "-".
const char* operatorText(BinaryOp op);
const char* operatorText(UnaryOp op);

// ST precedence, higher binds tighter: -> 0, OR 1, XOR 2, AND 3, = <> 4, < > <= >= 5,
// + - 6, * / MOD 7, unary 8.
int precedence(BinaryOp op);
inline constexpr int kUnaryPrecedence = 8;

} // namespace core::cond
