#include "core/condition/conditionsyntax.h"

namespace core::cond {

const char* operatorText(BinaryOp op)
{
    switch (op) {
    case BinaryOp::Implies: return "->";
    case BinaryOp::Or: return "OR";
    case BinaryOp::Xor: return "XOR";
    case BinaryOp::And: return "AND";
    case BinaryOp::Equal: return "=";
    case BinaryOp::NotEqual: return "<>";
    case BinaryOp::Less: return "<";
    case BinaryOp::Greater: return ">";
    case BinaryOp::LessEqual: return "<=";
    case BinaryOp::GreaterEqual: return ">=";
    case BinaryOp::Add: return "+";
    case BinaryOp::Subtract: return "-";
    case BinaryOp::Multiply: return "*";
    case BinaryOp::Divide: return "/";
    case BinaryOp::Modulo: return "MOD";
    }
    return "?";
}

const char* operatorText(UnaryOp op)
{
    switch (op) {
    case UnaryOp::Not: return "NOT";
    case UnaryOp::Negate: return "-";
    case UnaryOp::RisingEdge: return "RE";
    case UnaryOp::FallingEdge: return "FE";
    }
    return "?";
}

int precedence(BinaryOp op)
{
    switch (op) {
    case BinaryOp::Implies: return 0;
    case BinaryOp::Or: return 1;
    case BinaryOp::Xor: return 2;
    case BinaryOp::And: return 3;
    case BinaryOp::Equal:
    case BinaryOp::NotEqual: return 4;
    case BinaryOp::Less:
    case BinaryOp::Greater:
    case BinaryOp::LessEqual:
    case BinaryOp::GreaterEqual: return 5;
    case BinaryOp::Add:
    case BinaryOp::Subtract: return 6;
    case BinaryOp::Multiply:
    case BinaryOp::Divide:
    case BinaryOp::Modulo: return 7;
    }
    return 1;
}

} // namespace core::cond
