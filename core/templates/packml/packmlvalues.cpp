#include "core/templates/packml/packmlvalues.h"

#include "core/model/iectypes.h"

#include <cmath>

namespace core::packml {

std::int64_t integerOf(const cond::Value& value)
{
    if (const auto* integer = std::get_if<std::int64_t>(&value))
        return *integer;
    if (const auto* boolean = std::get_if<bool>(&value))
        return *boolean ? 1 : 0;
    const double real = std::get<double>(value);
    return std::isfinite(real) && std::fabs(real) < 9.0e18 ? static_cast<std::int64_t>(real) : 0;
}

cond::Value defaultValueOf(const Variable& variable)
{
    std::optional<cond::Value> value = cond::parseValue(variable.type, variable.defaultValue);
    if (!value) // a default that does not fit: the implicit one, as the generated code declares it
        value = cond::parseValue(variable.type, "");
    return value ? *value : cond::Value{false};
}

// The value as the variable holds it, or why it cannot.
std::optional<std::string> fitValue(const Variable& variable, cond::Value& value)
{
    const IecType type = variable.type;
    const std::string notOfType = variable.name + " is " + std::string(iecTypeName(type)) + ": "
        + cond::formatValue(value) + " is not a value of it";
    if (type == IecType::Bool)
        return std::holds_alternative<bool>(value) ? std::nullopt : std::optional(notOfType);
    if (isRealType(type)) {
        if (std::holds_alternative<bool>(value))
            return notOfType;
        if (const auto* integer = std::get_if<std::int64_t>(&value))
            value = static_cast<double>(*integer);
        const double limit = type == IecType::Real ? 3.4028234663852886e38 : 1.7976931348623157e308;
        const double real = std::get<double>(value);
        if (!(real >= -limit && real <= limit))
            return variable.name + ": " + cond::formatValue(value) + " is out of range for " + std::string(iecTypeName(type));
        return std::nullopt;
    }
    const auto* integer = std::get_if<std::int64_t>(&value);
    if (!integer)
        return notOfType;
    const cond::IntegerRange range = cond::integerRange(type);
    if (*integer < range.low || *integer > range.high)
        return variable.name + ": " + cond::formatValue(value) + " is out of range for " + std::string(iecTypeName(type));
    return std::nullopt;
}

} // namespace core::packml
