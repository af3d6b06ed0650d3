#include "core/model/stepnames.h"

#include "core/model/iectypes.h"
#include "core/model/model.h"

namespace core {

namespace {

constexpr std::string_view kFunctionBlockSuffix = "_FB";

bool declaresFunctionBlock(const Step& step)
{
    return !step.hidden && step.type != StepType::Simple;
}

std::string_view kindSuffix(VariableKind kind)
{
    switch (kind) {
    case VariableKind::Input: return "_Sensor";
    case VariableKind::Output: return "_Out";
    case VariableKind::Internal: return "_Mem";
    }
    return "_Var";
}

bool isFreeName(const Model& model, const std::string& name)
{
    return identifierProblem(name) == IdentifierProblem::None && !model.variable(name)
        && !stepNameClash(model, name);
}

} // namespace

std::optional<StepNameClash> stepNameClash(const Model& model, std::string_view name)
{
    const bool functionBlock = name.size() > kFunctionBlockSuffix.size()
        && equalsIgnoreCase(name.substr(name.size() - kFunctionBlockSuffix.size()), kFunctionBlockSuffix);
    const std::string_view stepId = functionBlock ? name.substr(0, name.size() - kFunctionBlockSuffix.size()) : name;
    for (const Step& step : model.steps()) {
        if (declaresFunctionBlock(step) && equalsIgnoreCase(step.id, stepId))
            return StepNameClash{&step, functionBlock};
    }
    return std::nullopt;
}

std::string_view clashedDeclaration(const StepNameClash& clash)
{
    return clash.functionBlock ? "function block" : "instance";
}

std::string_view clashedStepKind(const StepNameClash& clash)
{
    return clash.step->type == StepType::Enclosing ? "enclosing step" : "macro-step";
}

std::string stepNameClashDetail(const StepNameClash& clash, std::string_view name)
{
    return "'" + std::string(name) + "' is the " + std::string(clashedDeclaration(clash)) + " of "
        + std::string(clashedStepKind(clash)) + " " + clash.step->id + " in the generated code";
}

std::string suggestedVariableName(const Model& model, const Variable& variable)
{
    const std::string base = variable.name + std::string(kindSuffix(variable.kind));
    for (int number = 1; number < 1000; ++number) {
        const std::string candidate = number == 1 ? base : base + std::to_string(number);
        if (isFreeName(model, candidate))
            return candidate;
    }
    return base;
}

std::vector<std::string> stepNameClashArguments(const Model& model, const Variable& variable,
                                                const StepNameClash& clash)
{
    return {variable.name, clash.step->id, clash.functionBlock ? "function-block" : "instance",
            clash.step->type == StepType::Enclosing ? "enclosing" : "macro", suggestedVariableName(model, variable)};
}

std::string stepNameClashFix(const Model& model, const Variable& variable)
{
    return "rename the variable (for example to '" + suggestedVariableName(model, variable) + "')";
}

} // namespace core
