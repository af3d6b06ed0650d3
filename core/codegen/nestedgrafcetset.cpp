#include "core/codegen/nestedgrafcetset.h"

#include "core/templates/gemma/gemmaprogram.h"
#include "core/condition/conditionanalysis.h"
#include "core/model/model.h"
#include "core/model/messagetext.h"

#include <algorithm>
#include <set>

namespace core {

namespace {

std::set<std::string> continuousOutputs(std::span<const OwnedGrafcet> grafcets) // upper case, Complete excluded
{
    std::set<std::string> continuous;
    for (const OwnedGrafcet& owned : grafcets) {
        for (const ContinuousOutput& output : owned.grafcet->outputs) {
            if (!output.isComplete)
                continuous.insert(toUpperAscii(output.variable));
        }
    }
    return continuous;
}

ProgramProblem storedWriteProblem(const OwnedGrafcet& owned, const NestedStep& step, const NestedAction& action)
{
    const std::string where = "action " + std::to_string(action.index + 1) + " of step " + std::to_string(step.number)
        + " of " + owned.label;
    ProgramProblem problem;
    problem.kind = ProgramProblem::Kind::Error;
    problem.code = "GG415";
    problem.element = owned.element;
    problem.message = "in " + where + ": " + quoted(action.target)
        + " is also driven by continuous actions; a variable has either continuous or stored actions (the stored "
          "one is not generated)";
    problem.arguments = {owned.label, where, action.target};
    problem.nestedStep = step.number;
    problem.actionIndex = action.index;
    problem.span = action.parsed.action.targetSpan;
    return problem;
}

} // namespace

void rejectStoredWritesOfContinuousOutputs(std::span<const OwnedGrafcet> grafcets,
                                           std::vector<ProgramProblem>& problems)
{
    const std::set<std::string> continuous = continuousOutputs(grafcets);
    for (const OwnedGrafcet& owned : grafcets) {
        NestedGrafcet& nested = *owned.grafcet;
        const bool completeContinuous = nested.output("Complete") != nullptr;
        for (NestedStep& nestedStep : nested.steps) {
            for (auto* list : {&nestedStep.onActivation, &nestedStep.onDeactivation}) {
                for (NestedAction& action : *list) {
                    const bool clash = action.targetIsComplete ? completeContinuous
                                                               : continuous.count(toUpperAscii(action.target)) > 0;
                    if (!action.usable || !clash)
                        continue;
                    action.usable = false;
                    problems.push_back(storedWriteProblem(owned, nestedStep, action));
                }
            }
        }
        auto& stored = nested.storedTargets;
        stored.erase(std::remove_if(stored.begin(), stored.end(),
                                    [&](const std::string& name) { return continuous.count(toUpperAscii(name)) > 0; }),
                     stored.end());
    }
}

std::vector<std::string> edgeVariablesOf(std::span<const Variable> variables,
                                         std::span<const NestedGrafcet* const> grafcets)
{
    const auto indexOf = [&](std::string_view name) -> std::ptrdiff_t {
        const auto found = std::find_if(variables.begin(), variables.end(),
                                        [&](const Variable& v) { return equalsIgnoreCase(v.name, name); });
        return found == variables.end() ? -1 : found - variables.begin();
    };
    std::vector<bool> edged(variables.size(), false);
    for (const NestedGrafcet* grafcet : grafcets) {
        for (const NestedTransition& t : grafcet->transitions) {
            if (!t.usable)
                continue;
            const cond::Expression& expression = t.receptivity.expression;
            for (int node : cond::edgeNodes(expression)) {
                if (const std::ptrdiff_t index = indexOf(expression.at(expression.at(node).operand).text); index >= 0)
                    edged[static_cast<std::size_t>(index)] = true;
            }
        }
    }
    std::vector<std::string> names;
    for (std::size_t i = 0; i < edged.size(); ++i) {
        if (edged[i])
            names.push_back(variables[i].name);
    }
    return names;
}

} // namespace core
