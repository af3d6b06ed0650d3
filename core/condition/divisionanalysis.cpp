#include "core/condition/divisionanalysis.h"

#include "core/condition/conditionevaluator.h"

#include <algorithm>

namespace core::cond {

std::vector<DivisionByZeroRisk> divisionsByZero(const Expression& expression)
{
    std::vector<DivisionByZeroRisk> risks;
    for (std::size_t i = 0; i < expression.nodes.size(); ++i) {
        const Node& node = expression.nodes[i];
        if (node.kind != NodeKind::Binary || (node.binaryOp != BinaryOp::Divide && node.binaryOp != BinaryOp::Modulo))
            continue;
        bool readsSomething = false;
        const Value divisor = evaluate(Expression{expression.nodes, node.right}, [&](int) {
            readsSomething = true;
            return Value{std::int64_t{1}};
        });
        DivisionByZeroRisk risk;
        risk.node = static_cast<int>(i);
        risk.span = node.span;
        risk.divisorSpan = expression.at(node.right).span;
        risk.constantZero = !readsSomething && !isTrue(divisor);
        if (readsSomething || risk.constantZero)
            risks.push_back(risk);
    }
    // Children come before their parent in the arena: sort by where they start.
    std::stable_sort(risks.begin(), risks.end(),
                     [](const DivisionByZeroRisk& a, const DivisionByZeroRisk& b) { return a.span.begin < b.span.begin; });
    return risks;
}

namespace {

bool readsSomething(const Expression& expression, int root)
{
    std::vector<int> pending{root};
    while (!pending.empty()) {
        const Node& node = expression.at(pending.back());
        pending.pop_back();
        switch (node.kind) {
        case NodeKind::BoolLiteral:
        case NodeKind::IntegerLiteral:
        case NodeKind::RealLiteral: break;
        case NodeKind::Unary: pending.push_back(node.operand); break;
        case NodeKind::Binary:
            pending.push_back(node.left);
            pending.push_back(node.right);
            break;
        default: return true;
        }
    }
    return false;
}

} // namespace

bool dividesByVariable(const Expression& expression, int root)
{
    std::vector<int> pending{root};
    while (!pending.empty()) {
        const Node& node = expression.at(pending.back());
        pending.pop_back();
        if (node.kind == NodeKind::Unary) {
            pending.push_back(node.operand);
        } else if (node.kind == NodeKind::Binary) {
            if ((node.binaryOp == BinaryOp::Divide || node.binaryOp == BinaryOp::Modulo)
                && readsSomething(expression, node.right))
                return true;
            pending.push_back(node.left);
            pending.push_back(node.right);
        }
    }
    return false;
}

std::string divisionByZeroMessage(const DivisionByZeroRisk& risk, std::string_view text)
{
    const std::string division = "'" + excerpt(text, risk.span) + "'";
    if (risk.constantZero)
        return division + " divides by zero: on the PLC an integer division or MOD by zero stops the task with a "
                          "fault and a REAL one gives INF or NaN";
    return "the divisor of " + division + " can be zero: an integer division or MOD by zero stops the PLC with a "
                                          "fault (and the simulation), a REAL one gives INF or NaN";
}

} // namespace core::cond
