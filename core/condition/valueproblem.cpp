#include "core/condition/valueproblem.h"

#include "core/model/enumnames.h"
#include "core/model/messagetext.h"

namespace core {

namespace {

using ProblemKind = ValueProblem::Kind;

// The names are part of the arguments' contract: never rename one.
constexpr EnumName<ProblemKind> kProblemKindNames[] = {
    {ProblemKind::Spaces, "spaces"},
    {ProblemKind::NotBool, "not-bool"},
    {ProblemKind::NotInteger, "not-integer"},
    {ProblemKind::NotReal, "not-real"},
    {ProblemKind::OutOfRange, "out-of-range"},
};

constexpr std::size_t kArgumentCount = 5;

} // namespace

std::string toText(const ValueProblem& problem)
{
    const std::string value = quoted(problem.value);
    switch (problem.kind) {
    case ProblemKind::Spaces: return value + " has leading or trailing spaces";
    case ProblemKind::NotBool: return value + " is not a BOOL literal (TRUE or FALSE)";
    case ProblemKind::NotInteger:
        return value + " is not " + (problem.type == "INT" ? "an " : "a ") + problem.type
            + " literal: write a whole number such as 42";
    case ProblemKind::NotReal:
        return value + " is not a " + problem.type + " literal: write a decimal number such as 1.5 or 2.0E3";
    case ProblemKind::OutOfRange:
        return value + " is out of range for " + problem.type + " (" + problem.low + ".." + problem.high + ")";
    }
    return {};
}

std::string_view kindName(ValueProblem::Kind kind)
{
    return nameIn(kProblemKindNames, kind);
}

std::optional<ValueProblem::Kind> valueProblemKind(std::string_view name)
{
    return valueIn(kProblemKindNames, name);
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
    const std::optional<ProblemKind> kind = valueProblemKind(arguments[first]);
    if (!kind)
        return std::nullopt;
    return ValueProblem{*kind, arguments[first + 1], arguments[first + 2], arguments[first + 3],
                        arguments[first + 4]};
}

} // namespace core
