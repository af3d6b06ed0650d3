#include "core/verification/scanreads.h"

#include "core/templates/gemma/gemmaprogram.h"
#include "core/simulation/simulator.h"

#include <algorithm>
#include <cctype>

namespace core {

namespace {

std::string upper(std::string text)
{
    for (char& c : text)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

void addReads(const cond::Expression& expression, std::set<std::string>& out)
{
    for (const cond::Node& node : expression.nodes) {
        if (node.kind == cond::NodeKind::Variable)
            out.insert(upper(node.text));
    }
}

void addActionReads(const NestedStep& step, std::set<std::string>& out)
{
    for (const auto* actions : {&step.onActivation, &step.onDeactivation, &step.continuous}) {
        for (const NestedAction& action : *actions) {
            if (!action.usable)
                continue;
            addReads(action.parsed.action.condition, out);
            addReads(action.parsed.action.value, out);
        }
    }
}

void addNestedReads(const Simulator& simulator, const GemmaStep& step, std::set<std::string>& out)
{
    const NestedGrafcet& grafcet = *step.nested;
    if (grafcet.rule == EvolutionRule::UntilStable) {
        for (const std::string& name : grafcet.readVariables)
            out.insert(upper(name));
        return;
    }
    std::set<int> active;
    if (simulator.entry()) {
        for (const NestedStep& nested : grafcet.steps) {
            if (nested.initial)
                active.insert(nested.number);
        }
    } else {
        for (int number : simulator.activeNestedSteps(step.id))
            active.insert(number);
    }
    std::set<int> concerned = active;
    for (const NestedTransition& transition : grafcet.transitions) {
        const bool candidate = std::any_of(transition.upstream.begin(), transition.upstream.end(),
                                           [&](int number) { return active.count(number) > 0; });
        if (!candidate || !transition.usable)
            continue;
        addReads(transition.receptivity.expression, out);
        concerned.insert(transition.downstream.begin(), transition.downstream.end());
    }
    for (int number : concerned) {
        if (const NestedStep* nested = grafcet.step(number))
            addActionReads(*nested, out);
    }
}

} // namespace

std::set<std::string> scanReads(const Simulator& simulator, const cond::Expression& property)
{
    std::set<std::string> out;
    addReads(property, out);
    const GemmaProgram& program = simulator.program();
    for (const std::string& name : program.edgeVariables)
        out.insert(upper(name));
    for (const GemmaStep& step : program.steps) {
        for (const GemmaToken& token : step.tokens)
            out.insert(upper(token.variable));
    }
    const GemmaStep* active = program.step(simulator.activeStepId());
    if (!active)
        return out;
    for (const GemmaTransition& transition : active->transitions) {
        if (transition.conditionUsable)
            addReads(transition.condition.expression, out);
    }
    if (active->nested)
        addNestedReads(simulator, *active, out);
    return out;
}

} // namespace core
