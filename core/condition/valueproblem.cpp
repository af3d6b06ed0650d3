#include "core/condition/valueproblem.h"

#include "core/model/enumnames.h"

namespace core {

namespace {

using Kind = ValueProblem::Kind;

// The names are part of the arguments' contract: never rename one.
constexpr EnumName<Kind> kKindNames[] = {
    {Kind::Spaces, "spaces"},
    {Kind::NotBool, "not-bool"},
    {Kind::NotInteger, "not-integer"},
    {Kind::NotReal, "not-real"},
    {Kind::OutOfRange, "out-of-range"},
};

constexpr std::size_t kArgumentCount = 5;

std::string quoted(std::string_view value)
{
    return "'" + std::string(value) + "'";
}

} // namespace

std::string toText(const ValueProblem& problem)
{
    const std::string value = quoted(problem.value);
    switch (problem.kind) {
    case Kind::Spaces: return value + " has leading or trailing spaces";
    case Kind::NotBool: return value + " is not a BOOL literal (TRUE or FALSE)";
    case Kind::NotInteger:
        return value + " is not " + (problem.type == "INT" ? "an " : "a ") + problem.type
            + " literal: write a whole number such as 42";
    case Kind::NotReal:
        return value + " is not a " + problem.type + " literal: write a decimal number such as 1.5 or 2.0E3";
    case Kind::OutOfRange:
        return value + " is out of range for " + problem.type + " (" + problem.low + ".." + problem.high + ")";
    }
    return {};
}

std::string_view kindName(ValueProblem::Kind kind)
{
    return nameIn(kKindNames, kind);
}

std::optional<ValueProblem::Kind> valueProblemKind(std::string_view name)
{
    return valueIn(kKindNames, name);
}

void appendArguments(const ValueProblem& problem, std::vector<std::string>& arguments)
{
    arguments.emplace_back(kindName(problem.kind));
    arguments.push_back(problem.value);
    arguments.push_back(problem.type);
    arguments.push_back(problem.low);
    arguments.push_back(problem.high);
}

std::optional<ValueProblem> valueProblemFromArguments(const std::vector<std::string>& arguments, std::size_t first)
{
    if (arguments.size() < first + kArgumentCount)
        return std::nullopt;
    const std::optional<Kind> kind = valueProblemKind(arguments[first]);
    if (!kind)
        return std::nullopt;
    return ValueProblem{*kind, arguments[first + 1], arguments[first + 2], arguments[first + 3],
                        arguments[first + 4]};
}

} // namespace core
