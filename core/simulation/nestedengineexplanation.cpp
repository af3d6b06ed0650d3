// NestedEngine's explanations of its next call (Simulator::explain() and
// `simulate --explain` for a nested GRAFCET): why each transition fires or
// not. Apart from nestedengine.cpp, which runs the calls.

#include "core/simulation/nestedengine.h"

#include "core/simulation/decidingoperands.h"

#include "core/condition/conditionanalysis.h"
#include "core/model/model.h"

#include <algorithm>
#include <map>
#include <string>
#include <vector>

namespace core {

std::string_view nestedTransitionStatusName(NestedTransitionStatus status)
{
    switch (status) {
    case NestedTransitionStatus::Fires: return "fires";
    case NestedTransitionStatus::UpstreamInactive: return "upstream step not active";
    case NestedTransitionStatus::ReceptivityFalse: return "receptivity false";
    case NestedTransitionStatus::Unusable: return "unusable receptivity";
    case NestedTransitionStatus::NotCalled: return "not called";
    }
    return "";
}

std::string NestedEngine::declaredName(const std::string& written) const
{
    for (const std::string& name : m_grafcet->readVariables) {
        if (equalsIgnoreCase(name, written))
            return name;
    }
    for (const std::string& name : m_shape->outputNames) {
        if (equalsIgnoreCase(name, written))
            return name;
    }
    return written;
}

// Why the subtree at `node` has the value it has, as Simulator::explain()
// words a GEMMA condition: logical operators descend to the operands that
// decide (visitDecidingOperands), an edge or a time-dependent receptivity
// says what it compared, everything else gives its text, its value and the
// variables it reads.
void NestedEngine::explainNode(const cond::Expression& expression, int node, const std::map<int, int>& timers,
                               const NestedGlobals& globals, std::vector<ExplanationReason>& reasons) const
{
    const auto isTrueAt = [&](int at) {
        cond::Expression sub = expression;
        sub.root = at;
        return cond::isTrue(evaluate(sub, &timers, globals, true));
    };
    visitDecidingOperands(expression, node, isTrueAt,
                          [&](int leaf) { explainLeaf(expression, leaf, timers, globals, reasons); });
}

void NestedEngine::explainLeaf(const cond::Expression& expression, int node, const std::map<int, int>& timers,
                               const NestedGlobals& globals, std::vector<ExplanationReason>& reasons) const
{
    const cond::Node& n = expression.at(node);
    auto valueAt = [&](int at) {
        cond::Expression sub = expression;
        sub.root = at;
        return evaluate(sub, &timers, globals, true);
    };
    ExplanationReason reason;
    switch (n.kind) {
    case cond::NodeKind::Variable:
    case cond::NodeKind::StepActivity:
    case cond::NodeKind::Complete: {
        ConditionReading reading;
        reading.name = n.kind == cond::NodeKind::Variable  ? declaredName(n.text)
            : n.kind == cond::NodeKind::StepActivity ? stepActivityName(n.number)
                                                     : std::string("Complete");
        reading.value = cond::formatValue(atom(expression, node, &timers, globals, true));
        reason.kind = ExplanationReason::Kind::Reading;
        reason.readings.push_back(std::move(reading));
        reasons.push_back(std::move(reason));
        return;
    }
    case cond::NodeKind::BoolLiteral:
        reason.kind = ExplanationReason::Kind::Literal;
        reason.value = toUpperAscii(n.text);
        reasons.push_back(std::move(reason));
        return;
    case cond::NodeKind::StepDuration: {
        const bool value = cond::isTrue(atom(expression, node, &timers, globals, true));
        if (!value && !active(n.number)) { // the step is not active: its X reads FALSE
            reason.kind = ExplanationReason::Kind::Reading;
            reason.readings.push_back({stepActivityName(n.number), "FALSE", {}});
        } else if (!value && timers.count(node)) {
            const auto timer = static_cast<std::size_t>(timers.at(node));
            reason.kind = ExplanationReason::Kind::TimerNotElapsed;
            reason.subject = n.text; // as written: "5s/X2"
            reason.steps = {n.number};
            reason.elapsedMs = m_timers[timer].elapsed;
            reason.durationMs = m_grafcet->timers[timer].durationMs;
        } else {
            reason.kind = ExplanationReason::Kind::Expression;
            reason.subject = n.text;
            reason.value = cond::formatValue(value);
        }
        reasons.push_back(std::move(reason));
        return;
    }
    case cond::NodeKind::Unary: {
        if (n.unaryOp == cond::UnaryOp::RisingEdge || n.unaryOp == cond::UnaryOp::FallingEdge) {
            const cond::Node& operand = expression.at(n.operand);
            const int s = slot(operand.text);
            const bool value = cond::isTrue(atom(expression, node, &timers, globals, true));
            const std::string name = declaredName(operand.text);
            // What the edge compares, as atom() reads it: an own continuous output is the VAR_OUTPUT.
            const int own = ownOutput(operand.text);
            const std::string now = own >= 0 ? cond::formatValue(cond::Value{m_outputs[std::size_t(own)] != 0})
                                  : s >= 0   ? cond::formatValue(globals.read(s))
                                             : std::string("FALSE");
            if (!value) {
                reason.kind = n.unaryOp == cond::UnaryOp::RisingEdge ? ExplanationReason::Kind::NoRisingEdge
                                                                     : ExplanationReason::Kind::NoFallingEdge;
                reason.subject = name;
                reason.value = now;
                reason.previous = cond::formatValue(s >= 0 && globals.previous(s));
            } else {
                reason.kind = ExplanationReason::Kind::Expression;
                reason.subject = std::string(n.unaryOp == cond::UnaryOp::RisingEdge ? "RE " : "FE ") + name;
                reason.value = "TRUE";
                reason.readings.push_back({name, now, {}});
            }
            reasons.push_back(std::move(reason));
            return;
        }
        break;
    }
    default: break;
    }
    // A comparison (or anything else): "Depth >= 12 is FALSE (Depth = 3)".
    cond::Expression sub = expression;
    sub.root = node;
    cond::PrintOptions options;
    options.variableName = [this](const cond::Node& variable) { return declaredName(variable.text); };
    reason.kind = ExplanationReason::Kind::Expression;
    reason.subject = cond::print(sub, options);
    reason.value = cond::formatValue(valueAt(node));
    for (int v : cond::variableNodes(sub)) {
        ConditionReading operand{declaredName(sub.at(v).text),
                                 cond::formatValue(atom(sub, v, &timers, globals, true)), {}};
        if (std::find(reason.readings.begin(), reason.readings.end(), operand) == reason.readings.end())
            reason.readings.push_back(std::move(operand));
    }
    reasons.push_back(std::move(reason));
}

namespace {

// The transition's identity in an explanation; status and reasons to come.
NestedTransitionExplanation explanationOf(const NestedTransition& transition)
{
    NestedTransitionExplanation explanation;
    explanation.number = transition.number;
    explanation.upstream = transition.upstream;
    explanation.downstream = transition.downstream;
    explanation.receptivity = transition.text;
    return explanation;
}

} // namespace

std::vector<NestedTransitionExplanation> NestedEngine::explainNotCalled(const std::string& stepId) const
{
    ExplanationReason notCalled;
    notCalled.kind = ExplanationReason::Kind::NotCalled;
    notCalled.subject = stepId;
    std::vector<NestedTransitionExplanation> result;
    for (const NestedTransition& transition : m_grafcet->transitions) {
        NestedTransitionExplanation explanation = explanationOf(transition);
        explanation.status = NestedTransitionStatus::NotCalled;
        explanation.reasons.push_back(notCalled);
        result.push_back(std::move(explanation));
    }
    return result;
}

std::vector<NestedTransitionExplanation> NestedEngine::explainNextCall(bool initialization, std::int64_t nowMs,
                                                                       NestedGlobals& globals,
                                                                       std::vector<int>* situation) const
{
    // The call as call() runs it, up to the first evolution's evaluation.
    NestedEngine next(*this);
    if (initialization)
        next.call(true, nowMs, globals);
    for (std::size_t t = 0; t < next.m_timers.size(); ++t)
        next.runTon(t, next.active(m_grafcet->timers[t].step), nowMs);
    if (situation)
        *situation = next.activeSteps();

    std::vector<NestedTransitionExplanation> result;
    for (const NestedTransition& transition : m_grafcet->transitions) {
        NestedTransitionExplanation explanation = explanationOf(transition);
        ExplanationReason inactive;
        inactive.kind = ExplanationReason::Kind::StepsInactive;
        for (int step : transition.upstream) {
            if (!next.active(step))
                inactive.steps.push_back(step);
        }
        if (!transition.usable) {
            explanation.status = NestedTransitionStatus::Unusable;
        } else if (!inactive.steps.empty()) {
            explanation.status = NestedTransitionStatus::UpstreamInactive;
            explanation.reasons.push_back(std::move(inactive));
        } else if (cond::isTrue(next.evaluate(transition.receptivity.expression, &transition.timerOfNode, globals, true))) {
            explanation.status = NestedTransitionStatus::Fires;
        } else {
            explanation.status = NestedTransitionStatus::ReceptivityFalse;
            if (!transition.receptivity.expression.empty())
                next.explainNode(transition.receptivity.expression, transition.receptivity.expression.root,
                                 transition.timerOfNode, globals, explanation.reasons);
        }
        result.push_back(std::move(explanation));
    }
    return result;
}

} // namespace core
