#include "core/condition/conditionevaluator.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace core::cond {

namespace {

constexpr std::int64_t kInt64Max = std::numeric_limits<std::int64_t>::max();
constexpr std::int64_t kInt64Min = std::numeric_limits<std::int64_t>::min();

// Magnitude of an integer literal (separators skipped), saturated at 2^64 - 1.
std::uint64_t literalMagnitude(std::string_view text)
{
    std::uint64_t value = 0;
    constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
    for (char c : text) {
        if (c < '0' || c > '9')
            continue;
        const auto digit = static_cast<std::uint64_t>(c - '0');
        if (value > (kMax - digit) / 10)
            return kMax;
        value = value * 10 + digit;
    }
    return value;
}

std::int64_t positiveLiteral(std::string_view text)
{
    const std::uint64_t magnitude = literalMagnitude(text);
    return magnitude > static_cast<std::uint64_t>(kInt64Max) ? kInt64Max : static_cast<std::int64_t>(magnitude);
}

// -magnitude, exact down to INT64_MIN, saturated below.
std::int64_t negativeLiteral(std::string_view text)
{
    const std::uint64_t magnitude = literalMagnitude(text);
    if (magnitude > static_cast<std::uint64_t>(kInt64Max))
        return kInt64Min;
    return -static_cast<std::int64_t>(magnitude);
}

// Two's complement wrap-around, without signed overflow.
std::int64_t wrap(std::uint64_t value)
{
    return static_cast<std::int64_t>(value);
}

std::int64_t toInteger(const Value& value)
{
    if (const bool* b = std::get_if<bool>(&value))
        return *b ? 1 : 0;
    if (const std::int64_t* i = std::get_if<std::int64_t>(&value))
        return *i;
    const double d = std::get<double>(value);
    if (std::isnan(d))
        return 0;
    if (d >= 9.2233720368547758e18)
        return kInt64Max;
    if (d <= -9.2233720368547758e18)
        return kInt64Min;
    return static_cast<std::int64_t>(d);
}

double toReal(const Value& value)
{
    if (const double* d = std::get_if<double>(&value))
        return *d;
    return static_cast<double>(toInteger(value));
}

bool isReal(const Value& value) { return std::holds_alternative<double>(value); }

Value integerArithmetic(BinaryOp op, std::int64_t a, std::int64_t b)
{
    const auto ua = static_cast<std::uint64_t>(a);
    const auto ub = static_cast<std::uint64_t>(b);
    switch (op) {
    case BinaryOp::Add: return wrap(ua + ub);
    case BinaryOp::Subtract: return wrap(ua - ub);
    case BinaryOp::Multiply: return wrap(ua * ub);
    case BinaryOp::Divide:
        if (b == 0)
            return std::int64_t{0};
        return (a == kInt64Min && b == -1) ? kInt64Min : a / b;
    default: // Modulo
        if (b == 0 || b == -1)
            return std::int64_t{0};
        return a % b;
    }
}

Value realArithmetic(BinaryOp op, double a, double b)
{
    switch (op) {
    case BinaryOp::Add: return a + b;
    case BinaryOp::Subtract: return a - b;
    case BinaryOp::Multiply: return a * b;
    case BinaryOp::Divide: return realDivision(a, b);
    default: return std::fmod(a, b); // NaN for a zero divisor (MOD of a REAL is a type error anyway)
    }
}

template<typename T>
bool compare(BinaryOp op, T a, T b)
{
    switch (op) {
    case BinaryOp::Equal: return a == b;
    case BinaryOp::NotEqual: return a != b;
    case BinaryOp::Less: return a < b;
    case BinaryOp::Greater: return a > b;
    case BinaryOp::LessEqual: return a <= b;
    default: return a >= b;
    }
}

bool dividesIntegersByZero(BinaryOp op, const Value& a, const Value& b)
{
    return (op == BinaryOp::Divide || op == BinaryOp::Modulo) && !isReal(a) && !isReal(b) && toInteger(b) == 0;
}

Value binary(BinaryOp op, const Value& a, const Value& b)
{
    switch (op) {
    case BinaryOp::Or: return isTrue(a) || isTrue(b);
    case BinaryOp::Xor: return isTrue(a) != isTrue(b);
    case BinaryOp::And: return isTrue(a) && isTrue(b);
    case BinaryOp::Implies: return !isTrue(a) || isTrue(b);
    case BinaryOp::Add:
    case BinaryOp::Subtract:
    case BinaryOp::Multiply:
    case BinaryOp::Divide:
    case BinaryOp::Modulo:
        if (isReal(a) || isReal(b))
            return realArithmetic(op, toReal(a), toReal(b));
        return integerArithmetic(op, toInteger(a), toInteger(b));
    default:
        if (std::holds_alternative<bool>(a) && std::holds_alternative<bool>(b))
            return compare(op, std::get<bool>(a), std::get<bool>(b));
        if (isReal(a) || isReal(b))
            return compare(op, toReal(a), toReal(b));
        return compare(op, toInteger(a), toInteger(b));
    }
}

class Evaluator {
public:
    Evaluator(const Expression& expression, const std::function<Value(int)>& variableValue, int* divisionByZero)
        : m_expression(expression), m_variableValue(variableValue), m_divisionByZero(divisionByZero)
    {
    }

    // `bound`: the index every child must stay below, so a malformed tree
    // cannot make the recursion loop.
    Value eval(int index, int bound) const
    {
        if (index < 0 || index >= bound)
            return false;
        const Node& node = m_expression.at(index);
        switch (node.kind) {
        case NodeKind::Variable:
        case NodeKind::StepActivity:
        case NodeKind::StepDuration:
        case NodeKind::Complete:
        case NodeKind::InStep:
        case NodeKind::NestedStepActivity: return m_variableValue ? m_variableValue(index) : Value{false};
        case NodeKind::BoolLiteral: return equalsIgnoreCase(node.text, "TRUE");
        case NodeKind::IntegerLiteral: return positiveLiteral(node.text);
        case NodeKind::RealLiteral: {
            const auto value = parseRealLiteral(node.text);
            return value ? *value : std::numeric_limits<double>::infinity();
        }
        case NodeKind::Unary: return unary(index, node);
        case NodeKind::Binary: {
            const Value left = eval(node.left, index);
            const Value right = eval(node.right, index);
            if (m_divisionByZero && *m_divisionByZero < 0 && dividesIntegersByZero(node.binaryOp, left, right))
                *m_divisionByZero = index;
            return binary(node.binaryOp, left, right);
        }
        }
        return false;
    }

private:
    Value unary(int index, const Node& node) const
    {
        if (node.unaryOp == UnaryOp::Not)
            return !isTrue(eval(node.operand, index));
        if (node.unaryOp == UnaryOp::RisingEdge || node.unaryOp == UnaryOp::FallingEdge)
            return m_variableValue ? Value{isTrue(m_variableValue(index))} : Value{false};
        // The literal of LINT's minimum exceeds INT64_MAX by one: negate it exactly.
        if (node.operand >= 0 && node.operand < index
            && m_expression.at(node.operand).kind == NodeKind::IntegerLiteral)
            return negativeLiteral(m_expression.at(node.operand).text);
        const Value operand = eval(node.operand, index);
        if (isReal(operand))
            return -std::get<double>(operand);
        return wrap(0 - static_cast<std::uint64_t>(toInteger(operand)));
    }

    const Expression& m_expression;
    const std::function<Value(int)>& m_variableValue;
    int* m_divisionByZero; // nullptr: nobody asks
};

} // namespace

Value evaluate(const Expression& expression, const std::function<Value(int node)>& variableValue)
{
    if (expression.root < 0 || static_cast<std::size_t>(expression.root) >= expression.nodes.size())
        return false;
    return Evaluator(expression, variableValue, nullptr)
        .eval(expression.root, static_cast<int>(expression.nodes.size()));
}

Value evaluate(const Expression& expression, const std::function<Value(int node)>& variableValue,
               int& integerDivisionByZero)
{
    if (expression.root < 0 || static_cast<std::size_t>(expression.root) >= expression.nodes.size())
        return false;
    int found = -1;
    const Value value = Evaluator(expression, variableValue, &found)
                            .eval(expression.root, static_cast<int>(expression.nodes.size()));
    if (found >= 0)
        integerDivisionByZero = found;
    return value;
}

double realDivision(double dividend, double divisor)
{
    if (divisor != 0.0)
        return dividend / divisor;
    if (dividend == 0.0 || std::isnan(dividend))
        return std::numeric_limits<double>::quiet_NaN();
    const bool negative = std::signbit(dividend) != std::signbit(divisor);
    return negative ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
}

bool isTrue(const Value& value)
{
    if (const bool* b = std::get_if<bool>(&value))
        return *b;
    if (const std::int64_t* i = std::get_if<std::int64_t>(&value))
        return *i != 0;
    return std::get<double>(value) != 0.0;
}

std::optional<Value> parseValue(IecType type, std::string_view text)
{
    if (text.empty())
        text = implicitDefault(type);
    if (!defaultValueProblem(type, text).empty())
        return std::nullopt;
    if (type == IecType::Bool)
        return Value{equalsIgnoreCase(text, "TRUE") || text == "1"};
    if (isRealType(type)) {
        const auto value = parseRealLiteral(text);
        return value ? std::optional<Value>(*value) : std::nullopt;
    }
    if (text.front() == '-')
        return Value{negativeLiteral(text.substr(1))};
    return Value{positiveLiteral(text)};
}

std::string formatValue(const Value& value)
{
    if (const bool* b = std::get_if<bool>(&value))
        return *b ? "TRUE" : "FALSE";
    if (const std::int64_t* i = std::get_if<std::int64_t>(&value))
        return std::to_string(*i);
    const double d = std::get<double>(value);
    char buffer[64];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, d);
    std::string text(buffer, error == std::errc() ? end : buffer);
    // A real must read as one in ST: 2 -> 2.0, 1e+20 -> 1.0e+20.
    if (std::isfinite(d) && text.find('.') == std::string::npos)
        text.insert(std::min(text.find('e'), text.size()), ".0");
    return text;
}

IntegerRange integerRange(IecType type)
{
    constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
    switch (type) {
    case IecType::Sint: return {-128, 127};
    case IecType::Int: return {-32768, 32767};
    case IecType::Dint: return {-2147483648LL, 2147483647LL};
    case IecType::Usint: return {0, 255};
    case IecType::Uint: return {0, 65535};
    case IecType::Udint: return {0, 4294967295LL};
    case IecType::Ulint: return {0, kMax};
    default: return {std::numeric_limits<std::int64_t>::min(), kMax};
    }
}

} // namespace core::cond
