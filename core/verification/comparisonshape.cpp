#include "core/verification/comparisonshape.h"

namespace core::verification {

bool isConstantOperand(const cond::Expression& expression, int node)
{
    const cond::Node& n = expression.at(node);
    switch (n.kind) {
    case cond::NodeKind::IntegerLiteral:
    case cond::NodeKind::RealLiteral: return true;
    case cond::NodeKind::Unary:
        return n.unaryOp != cond::UnaryOp::RisingEdge && n.unaryOp != cond::UnaryOp::FallingEdge
            && isConstantOperand(expression, n.operand);
    case cond::NodeKind::Binary: return isConstantOperand(expression, n.left) && isConstantOperand(expression, n.right);
    default: return false;
    }
}

bool isVariableAgainstConstant(const cond::Expression& expression, int comparison)
{
    const cond::Node& n = expression.at(comparison);
    if (n.kind != cond::NodeKind::Binary)
        return false;
    const bool leftVariable = expression.at(n.left).kind == cond::NodeKind::Variable;
    const bool rightVariable = expression.at(n.right).kind == cond::NodeKind::Variable;
    return (leftVariable && isConstantOperand(expression, n.right))
        || (rightVariable && isConstantOperand(expression, n.left));
}

} // namespace core::verification
