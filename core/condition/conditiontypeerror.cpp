#include "core/condition/conditiontypeerror.h"

#include "core/model/enumnames.h"
#include "core/model/messagetext.h"

namespace core::cond {

namespace {

using TypeKind = TypeError::Kind;

// The names are part of the arguments' contract: never rename one.
constexpr EnumName<TypeKind> kTypeKindNames[] = {
    {TypeKind::NotBoolCondition, "not-bool-condition"},
    {TypeKind::NotBoolOperand, "not-bool-operand"},
    {TypeKind::NotNumericOperand, "not-numeric-operand"},
    {TypeKind::BoolOperands, "bool-operands"},
    {TypeKind::NumericOperands, "numeric-operands"},
    {TypeKind::IntegerOperands, "integer-operands"},
    {TypeKind::SameKindOperands, "same-kind-operands"},
    {TypeKind::IntegerLiteralRange, "integer-literal-range"},
    {TypeKind::RealLiteralRange, "real-literal-range"},
};

constexpr std::size_t kArgumentCount = 6;

std::string typeText(std::string_view type)
{
    if (type == TypeError::kIntegerValue)
        return "an integer";
    if (type == TypeError::kRealValue)
        return "a real number";
    if (type == TypeError::kUnknownValue)
        return "of unknown type";
    return std::string(type);
}

} // namespace

std::string toText(const TypeError::Operand& operand)
{
    return quoted(operand.text) + " is " + typeText(operand.type);
}

std::string toText(const TypeError& error)
{
    const std::string operand = toText(error.first);
    switch (error.kind) {
    case TypeKind::NotBoolCondition: return "a condition must be BOOL, but " + operand;
    case TypeKind::NotBoolOperand: return error.op + " needs a BOOL operand, but " + operand;
    case TypeKind::NotNumericOperand: return "unary " + error.op + " needs a numeric operand, but " + operand;
    case TypeKind::BoolOperands: return error.op + " needs BOOL operands, but " + operand;
    case TypeKind::NumericOperands: return error.op + " needs numeric operands, but " + operand;
    case TypeKind::IntegerOperands: return error.op + " needs integer operands, but " + operand;
    case TypeKind::SameKindOperands:
        return error.op + " needs two operands of the same kind, but " + operand + " and " + toText(error.second);
    case TypeKind::IntegerLiteralRange:
        return quoted(error.first.text) + " is out of range: integer literals go up to 9223372036854775807 (LINT)";
    case TypeKind::RealLiteralRange: return quoted(error.first.text) + " is out of range for LREAL (-1.8E308..1.8E308)";
    }
    return {};
}

std::string_view kindName(TypeError::Kind kind)
{
    return nameIn(kTypeKindNames, kind);
}

std::optional<TypeError::Kind> typeErrorKind(std::string_view name)
{
    return valueIn(kTypeKindNames, name);
}

void appendArguments(const TypeError& error, std::vector<std::string>& arguments)
{
    arguments.emplace_back(kindName(error.kind));
    arguments.push_back(error.op);
    arguments.push_back(error.first.text);
    arguments.push_back(error.first.type);
    arguments.push_back(error.second.text);
    arguments.push_back(error.second.type);
}

std::optional<TypeError> typeErrorFromArguments(const std::vector<std::string>& arguments, std::size_t first)
{
    if (arguments.size() < first + kArgumentCount)
        return std::nullopt;
    const std::optional<TypeKind> kind = typeErrorKind(arguments[first]);
    if (!kind)
        return std::nullopt;
    TypeError error;
    error.kind = *kind;
    error.op = arguments[first + 1];
    error.first = {arguments[first + 2], arguments[first + 3]};
    error.second = {arguments[first + 4], arguments[first + 5]};
    return error;
}

} // namespace core::cond
