#include "core/checks/nestedsatisfiability.h"

#include "core/condition/conditionanalysis.h"

#include <algorithm>
#include <set>

namespace core {

FreeAtomSpace::FreeAtomSpace(const std::vector<Variable>& declared)
    : m_variables(declared)
{
}

cond::Expression FreeAtomSpace::substitute(const cond::Expression& expression)
{
    cond::Expression result = expression;
    for (cond::Node& node : result.nodes) {
        const std::optional<std::string> name = atomName(expression, node);
        if (!name)
            continue;
        declare(*name);
        node = cond::Node{cond::NodeKind::Variable, node.span, *name};
    }
    return result;
}

bool FreeAtomSpace::readsNestedAtom(const cond::Expression& expression)
{
    return std::any_of(expression.nodes.begin(), expression.nodes.end(),
                       [&](const cond::Node& node) { return atomName(expression, node).has_value(); });
}

std::optional<std::string> FreeAtomSpace::atomName(const cond::Expression& expression, const cond::Node& node)
{
    switch (node.kind) {
    case cond::NodeKind::StepActivity: return "X" + std::to_string(node.number);
    case cond::NodeKind::StepDuration:
        return std::to_string(node.durationMs) + "ms/X" + std::to_string(node.number);
    case cond::NodeKind::Complete: return std::string("Complete");
    case cond::NodeKind::Unary:
        if (node.unaryOp == cond::UnaryOp::RisingEdge || node.unaryOp == cond::UnaryOp::FallingEdge)
            return (node.unaryOp == cond::UnaryOp::RisingEdge ? "RE " : "FE ") + expression.at(node.operand).text;
        return std::nullopt;
    default: return std::nullopt;
    }
}

void FreeAtomSpace::declare(const std::string& name)
{
    const bool known = std::any_of(m_variables.begin(), m_variables.end(),
                                   [&](const Variable& v) { return equalsIgnoreCase(v.name, name); });
    if (!known)
        m_variables.push_back(Variable{name, IecType::Bool, "", ""});
}

cond::Expression conjunction(const cond::Expression& a, const cond::Expression& b)
{
    cond::Expression result = a;
    const int offset = static_cast<int>(a.nodes.size());
    for (cond::Node node : b.nodes) {
        for (int* child : {&node.operand, &node.left, &node.right}) {
            if (*child >= 0)
                *child += offset;
        }
        result.nodes.push_back(node);
    }
    cond::Node both;
    both.kind = cond::NodeKind::Binary;
    both.binaryOp = cond::BinaryOp::And;
    both.left = a.root;
    both.right = b.root + offset;
    result.nodes.push_back(both);
    result.root = static_cast<int>(result.nodes.size()) - 1;
    return result;
}

cond::Expression negation(const cond::Expression& a)
{
    cond::Expression result = a;
    cond::Node notNode;
    notNode.kind = cond::NodeKind::Unary;
    notNode.unaryOp = cond::UnaryOp::Not;
    notNode.operand = a.root;
    result.nodes.push_back(notNode);
    result.root = static_cast<int>(result.nodes.size()) - 1;
    return result;
}

std::string describeValuation(const cond::Expression& expression, const std::vector<Variable>& variables,
                              const std::vector<cond::Value>& values)
{
    std::string result;
    std::set<std::size_t> shown;
    for (int node : cond::variableNodes(expression)) {
        const std::string& name = expression.at(node).text;
        for (std::size_t i = 0; i < variables.size() && i < values.size(); ++i) {
            if (equalsIgnoreCase(variables[i].name, name) && shown.insert(i).second)
                result += (result.empty() ? "" : ", ") + variables[i].name + " = " + cond::formatValue(values[i]);
        }
    }
    return result;
}

} // namespace core
