#include "core/condition/conditionanalysis.h"

#include "core/model/model.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>

namespace core::cond {

namespace {

// The arena keeps children before their parent; an index that breaks this
// (a hand-built tree) is treated as missing, so no walk can loop or overflow.
bool isChild(const Expression& expression, int child, int parent)
{
    return child >= 0 && child < parent && static_cast<std::size_t>(parent) <= expression.nodes.size();
}

bool isRootValid(const Expression& expression)
{
    return expression.root >= 0 && static_cast<std::size_t>(expression.root) < expression.nodes.size();
}

bool isLogical(BinaryOp op)
{
    return op == BinaryOp::And || op == BinaryOp::Or || op == BinaryOp::Xor || op == BinaryOp::Implies;
}

bool isArithmetic(BinaryOp op)
{
    return op == BinaryOp::Add || op == BinaryOp::Subtract || op == BinaryOp::Multiply
        || op == BinaryOp::Divide;
}

bool isOrdering(BinaryOp op)
{
    return op == BinaryOp::Less || op == BinaryOp::Greater || op == BinaryOp::LessEqual
        || op == BinaryOp::GreaterEqual;
}

// Keyword operators are named bare in messages, symbols quoted.
std::string operatorLabel(BinaryOp op)
{
    if (isLogical(op) || op == BinaryOp::Modulo)
        return operatorText(op);
    return std::string("'") + operatorText(op) + "'";
}

// --- printing -------------------------------------------------------------------

class Printer {
public:
    Printer(const Expression& expression, const PrintOptions& options)
        : m_expression(expression), m_options(options)
    {
    }

    std::string run(int node)
    {
        m_out.reserve(m_expression.nodes.size() * 8);
        write(node, static_cast<int>(m_expression.nodes.size()));
        return std::move(m_out);
    }

private:
    bool isSubstituted(int index) const
    {
        return !m_options.substitutions.empty() && m_options.substitutions.count(index) > 0;
    }

    // Whether `child` needs parentheses as an operand of `parent`.
    bool needsParentheses(int child, const Node& parent, bool isRightOperand) const
    {
        if (isSubstituted(child))
            return false;
        const Node& node = m_expression.at(child);
        if (parent.kind == NodeKind::Unary)
            return node.kind == NodeKind::Unary || node.kind == NodeKind::Binary;
        if (node.kind != NodeKind::Binary)
            return false;
        // Same precedence on the right always keeps its parentheses: the tree
        // shape (and for - / MOD the value) depends on them.
        const int outer = precedence(parent.binaryOp);
        const int inner = precedence(node.binaryOp);
        // `->` groups to the right: there the left operand keeps them instead.
        const bool groupsRight = parent.binaryOp == cond::BinaryOp::Implies;
        return inner < outer || (isRightOperand != groupsRight && inner == outer);
    }

    void writeOperand(int child, int parent, bool isRightOperand)
    {
        if (!isChild(m_expression, child, parent)) {
            m_out += '?';
            return;
        }
        const bool parenthesise = needsParentheses(child, m_expression.at(parent), isRightOperand);
        if (parenthesise)
            m_out += '(';
        write(child, parent);
        if (parenthesise)
            m_out += ')';
    }

    void write(int index, int parent)
    {
        if (index < 0 || index >= parent) {
            m_out += '?';
            return;
        }
        if (isSubstituted(index)) {
            m_out += m_options.substitutions.at(index);
            return;
        }
        const Node& node = m_expression.at(index);
        switch (node.kind) {
        case NodeKind::Variable:
            m_out += m_options.variableName ? m_options.variableName(node) : node.text;
            break;
        case NodeKind::BoolLiteral: m_out += toUpperAscii(node.text); break;
        case NodeKind::IntegerLiteral:
        case NodeKind::RealLiteral: m_out += node.text; break;
        case NodeKind::Unary:
            m_out += unaryPrefix(node.unaryOp);
            writeOperand(node.operand, index, false);
            break;
        case NodeKind::StepActivity: m_out += "X" + std::to_string(node.number); break;
        case NodeKind::StepDuration: m_out += node.text; break;
        case NodeKind::Complete: m_out += "Complete"; break;
        case NodeKind::InStep: m_out += "in " + node.text; break;
        case NodeKind::NestedStepActivity: m_out += node.text + ".X" + std::to_string(node.number); break;
        case NodeKind::Binary:
            writeOperand(node.left, index, false);
            m_out += ' ';
            m_out += operatorText(node.binaryOp);
            m_out += ' ';
            writeOperand(node.right, index, true);
            break;
        }
    }

    static const char* unaryPrefix(UnaryOp op)
    {
        switch (op) {
        case UnaryOp::Not: return "NOT ";
        case UnaryOp::Negate: return "-";
        case UnaryOp::RisingEdge: return "RE ";
        case UnaryOp::FallingEdge: return "FE ";
        }
        return "?";
    }

    const Expression& m_expression;
    const PrintOptions& m_options;
    std::string m_out;
};

// A subexpression as a type error quotes it.
std::string shortSubexpression(const Expression& expression, int node)
{
    static const PrintOptions plain;
    constexpr std::size_t kMaxLength = 40;
    std::string text = Printer(expression, plain).run(node);
    if (text.size() > kMaxLength)
        text = text.substr(0, kMaxLength - 3) + "...";
    return text;
}

std::string valueType(ValueKind kind)
{
    switch (kind) {
    case ValueKind::Bool: return "BOOL";
    case ValueKind::Integer: return std::string(TypeError::kIntegerValue);
    case ValueKind::Real: return std::string(TypeError::kRealValue);
    case ValueKind::Unknown: break;
    }
    return std::string(TypeError::kUnknownValue);
}

// --- type checking ----------------------------------------------------------------

ValueKind kindOfType(IecType type)
{
    if (type == IecType::Bool)
        return ValueKind::Bool;
    return isRealType(type) ? ValueKind::Real : ValueKind::Integer;
}

bool isNumeric(ValueKind kind) { return kind == ValueKind::Integer || kind == ValueKind::Real; }

// The magnitude of an integer literal; nullopt beyond 2^64 - 1.
std::optional<std::uint64_t> integerMagnitude(std::string_view text)
{
    std::uint64_t value = 0;
    constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
    for (char c : text) {
        if (c < '0' || c > '9')
            continue; // the '_' separators
        const auto digit = static_cast<std::uint64_t>(c - '0');
        if (value > (kMax - digit) / 10)
            return std::nullopt;
        value = value * 10 + digit;
    }
    return value;
}

constexpr std::uint64_t kInt64MaxMagnitude = static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());

// Computes the kind of every node, children first; optionally records the
// issues. An operand already in error (Unknown) raises no further issue.
//
// Integers and reals mix freely (x + 1.5, x = 2, r < 10): IEC compilers
// accept an integer literal where a real is expected, and the checks cannot
// tell a literal from a variable of the wrong width anyway, so only BOOL
// versus number is an error.
class TypeChecker {
public:
    TypeChecker(const Expression& expression, const SymbolTable& symbols, std::vector<TypeIssue>* issues)
        : m_expression(expression), m_symbols(symbols), m_issues(issues)
    {
    }

    ValueKind kindUpTo(int last)
    {
        m_kinds.assign(static_cast<std::size_t>(last) + 1, ValueKind::Unknown);
        if (m_issues)
            computeNegatedLiterals(last);
        for (int i = 0; i <= last; ++i)
            m_kinds[static_cast<std::size_t>(i)] = compute(i);
        return m_kinds[static_cast<std::size_t>(last)];
    }

private:
    ValueKind kindOf(int child, int parent) const
    {
        return isChild(m_expression, child, parent) ? m_kinds[static_cast<std::size_t>(child)]
                                                    : ValueKind::Unknown;
    }

    void report(const char* code, std::string message, Span span)
    {
        if (m_issues)
            m_issues->push_back(TypeIssue{code, std::move(message), span, std::nullopt});
    }

    void report(TypeError error, Span span)
    {
        if (m_issues) {
            std::string message = toText(error);
            m_issues->push_back(TypeIssue{"GG204", std::move(message), span, std::move(error)});
        }
    }

    // A declared variable is named by its type, anything else by its kind of value.
    TypeError::Operand operandOf(int node) const
    {
        const Node& n = m_expression.at(node);
        std::string type;
        if (n.kind == NodeKind::Variable) {
            if (const Variable* variable = m_symbols.find(n.text))
                type = iecTypeName(variable->type);
        }
        if (type.empty())
            type = valueType(m_kinds[static_cast<std::size_t>(node)]);
        return {shortSubexpression(m_expression, node), std::move(type)};
    }

    void reportLiteral(TypeError::Kind kind, const Node& node)
    {
        TypeError error;
        error.kind = kind;
        error.first.text = node.text;
        report(std::move(error), node.span);
    }

    // -9223372036854775808 is a valid LINT: its literal may exceed INT64_MAX by one.
    void computeNegatedLiterals(int last)
    {
        m_negatedLiteral.assign(static_cast<std::size_t>(last) + 1, false);
        for (int i = 0; i <= last; ++i) {
            const Node& node = m_expression.at(i);
            if (node.kind == NodeKind::Unary && node.unaryOp == UnaryOp::Negate
                && isChild(m_expression, node.operand, i))
                m_negatedLiteral[static_cast<std::size_t>(node.operand)] = true;
        }
    }

    ValueKind compute(int index)
    {
        const Node& node = m_expression.at(index);
        switch (node.kind) {
        case NodeKind::Variable: return variableKind(node);
        case NodeKind::BoolLiteral: return ValueKind::Bool;
        case NodeKind::IntegerLiteral: checkIntegerLiteral(index); return ValueKind::Integer;
        case NodeKind::RealLiteral:
            if (m_issues && !parseRealLiteral(node.text))
                reportLiteral(TypeError::Kind::RealLiteralRange, node);
            return ValueKind::Real;
        case NodeKind::Unary: return unaryKind(index, node);
        case NodeKind::Binary: return binaryKind(index, node);
        case NodeKind::StepActivity:
        case NodeKind::StepDuration:
        case NodeKind::Complete:
        case NodeKind::InStep:
        case NodeKind::NestedStepActivity: return ValueKind::Bool;
        }
        return ValueKind::Unknown;
    }

    ValueKind variableKind(const Node& node)
    {
        if (const Variable* variable = m_symbols.find(node.text))
            return kindOfType(variable->type);
        report("GG203", "'" + node.text + "' is not a declared variable", node.span);
        return ValueKind::Unknown;
    }

    void checkIntegerLiteral(int index)
    {
        if (!m_issues)
            return;
        const Node& node = m_expression.at(index);
        const auto magnitude = integerMagnitude(node.text);
        const bool negated = m_negatedLiteral[static_cast<std::size_t>(index)];
        const std::uint64_t limit = negated ? kInt64MaxMagnitude + 1 : kInt64MaxMagnitude;
        if (!magnitude || *magnitude > limit)
            reportLiteral(TypeError::Kind::IntegerLiteralRange, node);
    }

    ValueKind unaryKind(int index, const Node& node)
    {
        if (node.unaryOp == UnaryOp::RisingEdge || node.unaryOp == UnaryOp::FallingEdge)
            return edgeKind(index, node);
        const ValueKind operand = kindOf(node.operand, index);
        if (operand == ValueKind::Unknown)
            return node.unaryOp == UnaryOp::Not ? ValueKind::Bool : ValueKind::Unknown;
        if (node.unaryOp == UnaryOp::Not) {
            if (operand != ValueKind::Bool)
                reportOperand(TypeError::Kind::NotBoolOperand, "NOT", node.operand);
            return ValueKind::Bool;
        }
        if (operand == ValueKind::Bool) {
            reportOperand(TypeError::Kind::NotNumericOperand, "'-'", node.operand);
            return ValueKind::Unknown;
        }
        return operand;
    }

    // An edge is BOOL; its operand must be a BOOL variable (GG410).
    ValueKind edgeKind(int index, const Node& node)
    {
        const ValueKind operand = kindOf(node.operand, index);
        if (operand != ValueKind::Unknown && operand != ValueKind::Bool && m_issues) {
            const Node& variable = m_expression.at(node.operand);
            const Variable* declared = m_symbols.find(variable.text);
            const std::string type = declared ? std::string(iecTypeName(declared->type)) : valueType(operand);
            report("GG410", "an edge applies to a BOOL variable; '" + variable.text + "' is " + type, node.span);
        }
        return ValueKind::Bool;
    }

    void reportOperand(TypeError::Kind kind, std::string op, int node)
    {
        if (!m_issues)
            return;
        TypeError error;
        error.kind = kind;
        error.op = std::move(op);
        error.first = operandOf(node);
        report(std::move(error), m_expression.at(node).span);
    }

    // Reports each operand that fails `accepts`; true when both pass.
    template<typename Accepts>
    bool checkOperands(int index, const Node& node, TypeError::Kind rule, Accepts accepts)
    {
        bool ok = true;
        for (int child : {node.left, node.right}) {
            const ValueKind kind = kindOf(child, index);
            if (kind == ValueKind::Unknown) {
                ok = false;
            } else if (!accepts(kind)) {
                reportOperand(rule, operatorLabel(node.binaryOp), child);
                ok = false;
            }
        }
        return ok;
    }

    ValueKind binaryKind(int index, const Node& node)
    {
        using Kind = TypeError::Kind;
        const BinaryOp op = node.binaryOp;
        if (isLogical(op)) {
            checkOperands(index, node, Kind::BoolOperands, [](ValueKind k) { return k == ValueKind::Bool; });
            return ValueKind::Bool;
        }
        if (isOrdering(op)) {
            checkOperands(index, node, Kind::NumericOperands, isNumeric);
            return ValueKind::Bool;
        }
        if (op == BinaryOp::Modulo) {
            const bool ok = checkOperands(index, node, Kind::IntegerOperands,
                                          [](ValueKind k) { return k == ValueKind::Integer; });
            return ok ? ValueKind::Integer : ValueKind::Unknown;
        }
        if (isArithmetic(op)) {
            if (!checkOperands(index, node, Kind::NumericOperands, isNumeric))
                return ValueKind::Unknown;
            const bool real = kindOf(node.left, index) == ValueKind::Real
                || kindOf(node.right, index) == ValueKind::Real;
            return real ? ValueKind::Real : ValueKind::Integer;
        }
        checkComparable(index, node);
        return ValueKind::Bool;
    }

    void checkComparable(int index, const Node& node)
    {
        const ValueKind left = kindOf(node.left, index);
        const ValueKind right = kindOf(node.right, index);
        if (left == ValueKind::Unknown || right == ValueKind::Unknown || !m_issues)
            return;
        if ((left == ValueKind::Bool) == (right == ValueKind::Bool))
            return;
        TypeError error;
        error.kind = TypeError::Kind::SameKindOperands;
        error.op = operatorLabel(node.binaryOp);
        error.first = operandOf(node.left);
        error.second = operandOf(node.right);
        report(std::move(error), node.span);
    }

    const Expression& m_expression;
    const SymbolTable& m_symbols;
    std::vector<TypeIssue>* m_issues;
    std::vector<ValueKind> m_kinds;
    std::vector<bool> m_negatedLiteral;
};

std::vector<int> parentsOf(const Expression& expression)
{
    std::vector<int> parents(expression.nodes.size(), -1);
    for (int i = 0; i < static_cast<int>(expression.nodes.size()); ++i) {
        const Node& node = expression.at(i);
        for (int child : {node.operand, node.left, node.right}) {
            if (isChild(expression, child, i))
                parents[static_cast<std::size_t>(child)] = i;
        }
    }
    return parents;
}

} // namespace

std::vector<TypeIssue> typeCheck(const Expression& expression, const SymbolTable& symbols)
{
    return typeCheck(expression, symbols, true);
}

std::vector<TypeIssue> typeCheckValue(const Expression& expression, const SymbolTable& symbols)
{
    return typeCheck(expression, symbols, false);
}

std::vector<TypeIssue> typeCheck(const Expression& expression, const SymbolTable& symbols, bool mustBeBool)
{
    std::vector<TypeIssue> issues;
    if (!isRootValid(expression))
        return issues;
    TypeChecker checker(expression, symbols, &issues);
    const ValueKind kind = checker.kindUpTo(expression.root);
    if (mustBeBool && kind != ValueKind::Bool && kind != ValueKind::Unknown) {
        // Named by its kind of value even when it is a variable: "'Temp' is a real number".
        TypeError error;
        error.kind = TypeError::Kind::NotBoolCondition;
        error.first = {shortSubexpression(expression, expression.root), valueType(kind)};
        std::string message = toText(error);
        issues.push_back(TypeIssue{"GG204", std::move(message), expression.rootNode().span, std::move(error)});
    }
    std::stable_sort(issues.begin(), issues.end(),
                     [](const TypeIssue& a, const TypeIssue& b) { return a.span.begin < b.span.begin; });
    return issues;
}

ValueKind valueKind(const Expression& expression, int node, const SymbolTable& symbols)
{
    if (node < 0 || static_cast<std::size_t>(node) >= expression.nodes.size())
        return ValueKind::Unknown;
    return TypeChecker(expression, symbols, nullptr).kindUpTo(node);
}


// Every variable occurrence is a literal, whatever its type or position: the
// checks decide which ones may carry a token (BOOL variables, spec §5).
namespace {

// The reachable nodes that pass `keep`, in source order: a pre-order walk
// with an explicit stack (no recursion on hostile trees), left operand first.
template<typename Keep>
std::vector<int> nodesInSourceOrder(const Expression& expression, Keep keep)
{
    std::vector<int> found;
    if (!isRootValid(expression))
        return found;
    std::vector<int> pending{expression.root};
    while (!pending.empty()) {
        const int index = pending.back();
        pending.pop_back();
        const Node& node = expression.at(index);
        if (keep(node))
            found.push_back(index);
        if (node.kind == NodeKind::Unary && isChild(expression, node.operand, index))
            pending.push_back(node.operand);
        else if (node.kind == NodeKind::Binary) {
            if (isChild(expression, node.right, index))
                pending.push_back(node.right);
            if (isChild(expression, node.left, index))
                pending.push_back(node.left);
        }
    }
    return found;
}

} // namespace

std::vector<int> variableNodes(const Expression& expression)
{
    return nodesOfKind(expression, NodeKind::Variable);
}

std::vector<int> nodesOfKind(const Expression& expression, NodeKind kind)
{
    return nodesInSourceOrder(expression, [kind](const Node& node) { return node.kind == kind; });
}

std::vector<int> edgeNodes(const Expression& expression)
{
    return nodesInSourceOrder(expression, [](const Node& node) {
        return node.kind == NodeKind::Unary
            && (node.unaryOp == UnaryOp::RisingEdge || node.unaryOp == UnaryOp::FallingEdge);
    });
}

std::vector<Literal> booleanLiterals(const Expression& expression)
{
    std::vector<Literal> literals;
    const std::vector<int> variables = variableNodes(expression);
    if (variables.empty())
        return literals;
    const std::vector<int> parents = parentsOf(expression);
    literals.reserve(variables.size());
    for (int variable : variables) {
        const int parent = parents[static_cast<std::size_t>(variable)];
        const bool underNot = parent >= 0 && expression.at(parent).kind == NodeKind::Unary
            && expression.at(parent).unaryOp == UnaryOp::Not;
        literals.push_back(Literal{underNot ? parent : variable, variable, underNot});
    }
    return literals;
}

std::string print(const Expression& expression, const PrintOptions& options)
{
    if (!isRootValid(expression))
        return {};
    return Printer(expression, options).run(expression.root);
}

bool needsParenthesesBeforeAnd(const Expression& expression)
{
    return needsParenthesesBeforeAnd(expression, PrintOptions{});
}

bool needsParenthesesBeforeAnd(const Expression& expression, const PrintOptions& options)
{
    if (!isRootValid(expression) || options.substitutions.count(expression.root) > 0)
        return false;
    const Node& root = expression.rootNode();
    return root.kind == NodeKind::Binary && (root.binaryOp == BinaryOp::Or || root.binaryOp == BinaryOp::Xor);
}

namespace {

bool isVariableNamed(const Expression& expression, int index, std::string_view name)
{
    const Node& node = expression.at(index);
    return node.kind == NodeKind::Variable && equalsIgnoreCase(node.text, name);
}

bool isEqualityOperand(const Expression& expression, int index, std::string_view name)
{
    const Node& node = expression.at(index);
    if (node.kind == NodeKind::Unary && node.unaryOp == UnaryOp::Not)
        return isVariableNamed(expression, node.operand, name);
    return isVariableNamed(expression, index, name);
}

} // namespace

bool isComparedWithEquality(const Expression& expression, std::string_view variableName)
{
    for (const Node& node : expression.nodes) {
        const bool equality = node.kind == NodeKind::Binary
            && (node.binaryOp == BinaryOp::Equal || node.binaryOp == BinaryOp::NotEqual);
        if (equality
            && (isEqualityOperand(expression, node.left, variableName)
                || isEqualityOperand(expression, node.right, variableName)))
            return true;
    }
    return false;
}

} // namespace core::cond
