#include "core/simulation/decidingoperands.h"

namespace core {

void visitDecidingOperands(const cond::Expression& expression, int node, const std::function<bool(int)>& isTrueAt,
                           const std::function<void(int)>& explainLeaf)
{
    const cond::Node& n = expression.at(node);
    if (n.kind == cond::NodeKind::Unary && n.unaryOp == cond::UnaryOp::Not) {
        visitDecidingOperands(expression, n.operand, isTrueAt, explainLeaf);
        return;
    }
    if (n.kind == cond::NodeKind::Binary && (n.binaryOp == cond::BinaryOp::And || n.binaryOp == cond::BinaryOp::Or)) {
        const bool deciding = n.binaryOp == cond::BinaryOp::Or; // the operand value that decides alone
        const bool onlyDeciding = isTrueAt(node) == deciding;
        for (int operand : {n.left, n.right}) {
            if (!onlyDeciding || isTrueAt(operand) == deciding)
                visitDecidingOperands(expression, operand, isTrueAt, explainLeaf);
        }
        return;
    }
    if (n.kind == cond::NodeKind::Binary && n.binaryOp == cond::BinaryOp::Xor) {
        visitDecidingOperands(expression, n.left, isTrueAt, explainLeaf);
        visitDecidingOperands(expression, n.right, isTrueAt, explainLeaf);
        return;
    }
    explainLeaf(node);
}

} // namespace core
