#include "core/checks/incrementalcheck.h"

#include "core/checks/checks.h"
#include "core/checks/grafcetchecks.h"
#include "core/codegen/nestedgrafcetset.h"
#include "core/machine/machinechecks.h"
#include "core/templates/gemma/gemmachecks.h"
#include "core/templates/gemma/gemmaprogram.h"

#include <algorithm>

namespace core {

namespace {

void appendAll(std::vector<Diagnostic>& to, const std::vector<Diagnostic>& from)
{
    to.insert(to.end(), from.begin(), from.end());
}

// A change inside the transitions of one nested GRAFCET, nothing else:
// its receptivities, upstream or downstream sets.
bool onlyGrafcetTransitions(const ModelChange& change)
{
    if (change.kind != ModelChange::Kind::Grafcet || change.grafcetChanges.empty())
        return false;
    return std::all_of(change.grafcetChanges.begin(), change.grafcetChanges.end(), [](const GrafcetChange& c) {
        return c.kind == GrafcetChange::Kind::Transition && c.number != 0;
    });
}

} // namespace

std::optional<NestedGrafcet> IncrementalCheck::computePart(const Model& model, GrafcetPart& part)
{
    const Step& step = *model.step(part.stepId);
    part.checks = checkStepGrafcet(model, step);
    std::vector<ProgramProblem> problems;
    std::optional<NestedGrafcet> nested = buildGemmaNestedGrafcet(model, step, problems);
    part.built = nested.has_value();
    part.problems = nestedProblemDiagnostics(problems);
    part.edgeVariables.clear();
    if (nested) {
        const NestedGrafcet* built[] = {&*nested};
        part.edgeVariables = edgeVariablesOf(model.variables(), built);
    }
    part.used.assign(model.variables().size(), false);
    if (const Grafcet* grafcet = model.effectiveGrafcet(step.id))
        markNestedUses(model, *grafcet, part.used);
    return nested;
}

const std::vector<Diagnostic>& IncrementalCheck::checkAll(const Model& model)
{
    m_lastIncremental = false;
    m_parts.clear();
    if (model.templateKind() != TemplateKind::Gemma) {
        m_model = nullptr; // nothing kept: the next update checks everything again
        m_result = checkModel(model);
        return m_result;
    }
    m_model = &model;
    GemmaElementChecks elements = checkGemmaElements(model);
    m_gemma = std::move(elements.diagnostics);
    m_conditionUses = std::move(elements.variableUsed);
    m_transitions = model.transitions();
    std::vector<std::optional<NestedGrafcet>> nested;
    for (const Step& step : model.steps()) {
        if (model.grafcet(step.id) == nullptr)
            continue;
        m_parts.push_back(GrafcetPart{step.id, {}, false, {}, {}, {}});
        nested.push_back(computePart(model, m_parts.back()));
    }
    // GG415 reads the actions of every GRAFCET, as buildGemmaProgram does
    // once they are all built.
    std::vector<OwnedGrafcet> owned;
    for (std::size_t i = 0; i < m_parts.size(); ++i) {
        if (nested[i])
            owned.push_back({m_parts[i].stepId, m_parts[i].stepId, &*nested[i]});
    }
    std::vector<ProgramProblem> storedWrites;
    rejectStoredWritesOfContinuousOutputs(owned, storedWrites);
    m_storedWrites = nestedProblemDiagnostics(storedWrites);
    m_machine = machine::checkMachine(model);
    assemble(model);
    return m_result;
}

bool IncrementalCheck::onlyConditionChanged(const Model& model, const std::string& transitionId) const
{
    const std::vector<Transition>& now = model.transitions();
    if (now.size() != m_transitions.size())
        return false;
    for (std::size_t i = 0; i < now.size(); ++i) {
        if (now[i].id != transitionId)
            continue;
        const Transition& before = m_transitions[i];
        return before.id == now[i].id && before.source == now[i].source && before.target == now[i].target
            && before.order == now[i].order && before.negated == now[i].negated && before.hidden == now[i].hidden
            && before.tokens == now[i].tokens;
    }
    return false;
}

bool IncrementalCheck::handledPrecisely(const Model& model, const std::vector<ModelChange>& changes,
                                        std::vector<std::size_t>& parts, bool& gemma) const
{
    if (m_model != &model || model.templateKind() != TemplateKind::Gemma || changes.empty()
        || m_conditionUses.size() != model.variables().size())
        return false;
    for (const ModelChange& change : changes) {
        if (change.kind == ModelChange::Kind::Transition) {
            if (!onlyConditionChanged(model, change.id))
                return false;
            gemma = true;
            continue;
        }
        if (!onlyGrafcetTransitions(change))
            return false;
        const auto part = std::find_if(m_parts.begin(), m_parts.end(),
                                       [&](const GrafcetPart& p) { return p.stepId == change.id; });
        if (part == m_parts.end() || model.grafcet(change.id) == nullptr)
            return false;
        const auto index = static_cast<std::size_t>(part - m_parts.begin());
        if (std::find(parts.begin(), parts.end(), index) == parts.end())
            parts.push_back(index);
    }
    return true;
}

const std::vector<Diagnostic>& IncrementalCheck::update(const Model& model, const std::vector<ModelChange>& changes)
{
    std::vector<std::size_t> parts;
    bool gemma = false;
    if (!handledPrecisely(model, changes, parts, gemma))
        return checkAll(model);
    if (gemma) {
        GemmaElementChecks elements = checkGemmaElements(model);
        m_gemma = std::move(elements.diagnostics);
        m_conditionUses = std::move(elements.variableUsed);
        m_transitions = model.transitions();
    }
    // The transitions of these GRAFCETs changed, nothing else: their own
    // checks and problems, what their texts name, what they read under an
    // edge. Their actions did not change, so neither did GG415 nor the
    // machine's checks; nor did the GEMMA steps and transitions.
    for (std::size_t index : parts)
        computePart(model, m_parts[index]);
    assemble(model);
    m_lastIncremental = true;
    return m_result;
}

void IncrementalCheck::assemble(const Model& model)
{
    m_result = m_gemma;
    for (const GrafcetPart& part : m_parts)
        appendAll(m_result, part.checks);
    const std::vector<Variable>& variables = model.variables();
    std::vector<bool> used = m_conditionUses;
    if (!model.grafcets().empty()) {
        bool anyBuilt = false;
        for (const GrafcetPart& part : m_parts) {
            appendAll(m_result, part.problems);
            anyBuilt = anyBuilt || part.built;
        }
        appendAll(m_result, m_storedWrites);
        // Every variable read under an edge somewhere, in declaration order.
        std::vector<std::string> edgeVariables;
        for (const Variable& variable : variables) {
            const bool edged = std::any_of(m_parts.begin(), m_parts.end(), [&](const GrafcetPart& part) {
                return std::find(part.edgeVariables.begin(), part.edgeVariables.end(), variable.name)
                    != part.edgeVariables.end();
            });
            if (edged)
                edgeVariables.push_back(variable.name);
        }
        appendAll(m_result, reservedNameDiagnostics(model, anyBuilt, edgeVariables));
    }
    for (const GrafcetPart& part : m_parts) {
        for (std::size_t i = 0; i < used.size(); ++i)
            used[i] = used[i] || part.used[i];
    }
    appendAll(m_result, checkGemmaVariables(model, used));
    appendAll(m_result, m_machine);
}

} // namespace core
