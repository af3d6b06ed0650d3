#include "core/checks/grafcetsequencechecks.h"

#include "core/checks/nestedsatisfiability.h"
#include "core/condition/conditionanalysis.h"
#include "core/condition/symboltable.h"
#include "core/model/grafcetadjacency.h"
#include "core/model/grafcetnumbers.h"
#include "core/model/model.h"
#include "core/verification/satisfiability.h"

#include <algorithm>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <utility>

namespace core {

namespace {


std::string joinedNumbers(const std::vector<int>& numbers, const std::string& prefix = {})
{
    std::string result;
    for (int number : numbers)
        result += (result.empty() ? "" : ", ") + prefix + std::to_string(number);
    return result;
}

// The nodes a receptivity is TRUE with whenever they are (with the rest
// TRUE): those reached from the root through AND and OR only, not under
// NOT, XOR, an edge or a comparison. Iterative: a long AND chain is as deep
// as it is long.
void forEachPositiveOperand(const cond::Expression& expression, const std::function<void(const cond::Node&)>& use)
{
    std::vector<int> pending{expression.root};
    while (!pending.empty()) {
        const cond::Node& node = expression.at(pending.back());
        pending.pop_back();
        const bool andOr = node.kind == cond::NodeKind::Binary
            && (node.binaryOp == cond::BinaryOp::And || node.binaryOp == cond::BinaryOp::Or);
        if (!andOr) {
            use(node);
            continue;
        }
        pending.push_back(node.right);
        pending.push_back(node.left);
    }
}

bool hasStep(const std::vector<int>& numbers, int number)
{
    return std::find(numbers.begin(), numbers.end(), number) != numbers.end();
}

class SequenceChecker {
public:
    SequenceChecker(const Model& model, const Step& owner, const Grafcet& grafcet,
                    const std::map<int, cond::ParseResult>& receptivities, const GrafcetAdjacency& adjacency)
        : m_model(model)
        , m_owner(owner)
        , m_grafcet(grafcet)
        , m_receptivities(receptivities)
        , m_adjacency(adjacency)
        , m_symbols(model.variables())
    {
    }

    std::vector<Diagnostic> run()
    {
        checkLevelRunaways();
        checkIncompleteSelections();
        return std::move(m_result);
    }

private:
    const cond::Expression* usableReceptivity(int number) const
    {
        const auto found = m_receptivities.find(number);
        if (found == m_receptivities.end() || !found->second.ok()
            || !cond::typeCheck(found->second.expression, m_symbols).empty())
            return nullptr;
        return &found->second.expression;
    }

    // ---- GG423: a level held through consecutive transitions ----

    // The BOOL inputs the receptivity reads positively: by level, and with
    // `risingEdges` also as ↑V (an edge then a level runs through as well).
    std::vector<const Variable*> positiveInputReads(const cond::Expression& expression, bool risingEdges) const
    {
        std::vector<const Variable*> result;
        if (expression.empty())
            return result;
        forEachPositiveOperand(expression, [&](const cond::Node& node) {
            const cond::Node* read = &node;
            if (risingEdges && node.kind == cond::NodeKind::Unary && node.unaryOp == cond::UnaryOp::RisingEdge)
                read = &expression.at(node.operand);
            if (read->kind != cond::NodeKind::Variable)
                return;
            const Variable* variable = m_symbols.find(read->text);
            if (variable && variable->type == IecType::Bool && variable->kind == VariableKind::Input
                && std::find(result.begin(), result.end(), variable) == result.end())
                result.push_back(variable);
        });
        return result;
    }

    // T2 can fire in the evolution right after T1: T1 activates every step
    // T2 needs.
    static bool follows(const GrafcetTransition& first, const GrafcetTransition& second)
    {
        return first.number != second.number && !second.upstream.empty()
            && std::all_of(second.upstream.begin(), second.upstream.end(),
                           [&](int step) { return hasStep(first.downstream, step); });
    }

    // Each receptivity is type-checked and read once, and each transition is
    // paired only with those leaving the steps it activates: a chain of
    // 10,000 steps is checked in linear time, not 10^8 pairs.
    void checkLevelRunaways()
    {
        std::map<int, const cond::Expression*> usable;
        for (const GrafcetTransition& t : m_grafcet.transitions())
            if (const cond::Expression* receptivity = usableReceptivity(t.number))
                usable.emplace(t.number, receptivity);
        std::set<std::pair<int, const Variable*>> reported;
        for (const GrafcetTransition& first : m_grafcet.transitions()) {
            const auto firstReceptivity = usable.find(first.number);
            if (firstReceptivity == usable.end())
                continue;
            std::vector<const Variable*> held;
            for (const GrafcetTransition* second : followers(first)) {
                const auto secondReceptivity = usable.find(second->number);
                if (secondReceptivity == usable.end())
                    continue;
                const std::vector<const Variable*> levels = positiveInputReads(*secondReceptivity->second, false);
                if (levels.empty())
                    continue;
                if (held.empty())
                    held = positiveInputReads(*firstReceptivity->second, true);
                for (const Variable* variable : held) {
                    if (!isAmong(levels, variable) || reported.count({second->number, variable}))
                        continue;
                    if (!runsThrough(*firstReceptivity->second, *secondReceptivity->second, *variable))
                        continue;
                    reported.insert({second->number, variable});
                    reportRunaway(first, *second, *variable);
                }
            }
        }
    }

    // The transitions that can fire in the evolution right after `first`,
    // in the order of the GRAFCET's transitions.
    std::vector<const GrafcetTransition*> followers(const GrafcetTransition& first) const
    {
        std::vector<const GrafcetTransition*> result;
        for (int step : first.downstream)
            for (const GrafcetTransition* second : m_adjacency.leaving(step))
                if (follows(first, *second) && std::find(result.begin(), result.end(), second) == result.end())
                    result.push_back(second);
        std::sort(result.begin(), result.end());
        return result;
    }

    static bool isAmong(const std::vector<const Variable*>& variables, const Variable* variable)
    {
        return std::find(variables.begin(), variables.end(), variable) != variables.end();
    }

    // With `held` TRUE, the rest of the receptivities lets both fire: with
    // the same values under until stable (the next evolution is in the same
    // scan), with values of their own under one evolution per scan (the
    // other inputs may change from scan to scan). Witnesses are evaluated,
    // so an opaque comparison never makes up a runaway.
    bool runsThrough(const cond::Expression& first, const cond::Expression& second, const Variable& held) const
    {
        FreeAtomSpace space(m_model.variables());
        const cond::Expression level = cond::parse(held.name, cond::kNestedOptions).expression;
        const cond::Expression a = conjunction(space.substitute(first), level);
        const cond::Expression b = conjunction(space.substitute(second), level);
        if (untilStable())
            return sat::findValuation(conjunction(a, b), space.variables()).has_value();
        return sat::findValuation(a, space.variables()).has_value()
            && sat::findValuation(b, space.variables()).has_value();
    }

    bool untilStable() const { return m_model.settings().evolution == EvolutionRule::UntilStable; }

    void reportRunaway(const GrafcetTransition& first, const GrafcetTransition& second, const Variable& held)
    {
        const std::string& id = m_owner.id;
        const std::string between = joinedNumbers(second.upstream);
        const std::string when = untilStable() ? "in the same scan" : "in consecutive scans";
        const std::string steps = second.upstream.size() == 1 ? "step " : "steps ";
        add("GG423", Severity::Warning, Diagnostic::Target::GrafcetTransition, second.number, "receptivity",
            held.name + " is read in " + grafcetnumbers::transitionLabel(first.number) + " and by its level in "
                + grafcetnumbers::transitionLabel(second.number) + ", which can fire right after it: while " + held.name
                + " stays TRUE, both fire " + when + " and " + steps + between + " of " + id
                + " is passed through; read its rising edge in " + grafcetnumbers::transitionLabel(second.number) + " (↑"
                + held.name + ") so that each press fires one transition",
            {id, held.name, grafcetnumbers::transitionLabel(first.number), grafcetnumbers::transitionLabel(second.number), between,
             std::string(evolutionRuleName(m_model.settings().evolution))});
    }

    // ---- GG424: selections that are not complete ----

    void checkIncompleteSelections()
    {
        for (const GrafcetStep& step : m_grafcet.steps())
            checkSelectionComplete(step.number);
    }

    // Only selections whose branches leave this step alone and read declared
    // variables only: step activities, durations and edges change by
    // themselves, so values of the inputs would not say when it waits.
    void checkSelectionComplete(int stepNumber)
    {
        const std::vector<const GrafcetTransition*>& leaving = m_adjacency.leaving(stepNumber);
        if (leaving.size() < 2)
            return;
        std::optional<cond::Expression> noneFires;
        std::vector<int> numbers;
        for (const GrafcetTransition* t : leaving) {
            const cond::Expression* receptivity = usableReceptivity(t->number);
            if (t->upstream.size() != 1 || !receptivity || FreeAtomSpace::readsNestedAtom(*receptivity))
                return;
            const cond::Expression blocked = negation(*receptivity);
            noneFires = noneFires ? conjunction(*noneFires, blocked) : blocked;
            numbers.push_back(t->number);
        }
        if (readVariableCount(*noneFires) > kMaxSelectionVariables)
            return;
        const std::optional<std::vector<cond::Value>> values = sat::findValuation(*noneFires, m_model.variables());
        if (!values)
            return;
        const std::string witness = describeValuation(*noneFires, m_model.variables(), *values);
        if (witness.empty())
            return;
        const std::string& id = m_owner.id;
        const std::string step = std::to_string(stepNumber);
        const std::string branches = joinedNumbers(numbers, "T");
        add("GG424", Severity::Info, Diagnostic::Target::GrafcetStep, stepNumber, "step",
            "the selection after step " + step + " of " + id + " is not complete: with " + witness + " none of "
                + branches + " fires and the GRAFCET waits in step " + step
                + "; add a branch for these values unless waiting is intended",
            {id, step, branches, witness});
    }

    std::size_t readVariableCount(const cond::Expression& expression) const
    {
        std::set<const Variable*> read;
        for (int node : cond::variableNodes(expression))
            read.insert(m_symbols.find(expression.at(node).text));
        return read.size();
    }

    // ---- results ----

    void add(std::string code, Severity severity, Diagnostic::Target target, int number, std::string field,
             std::string message, std::vector<std::string> arguments)
    {
        Diagnostic d;
        d.code = std::move(code);
        d.severity = severity;
        d.target = target;
        d.element = m_owner.id;
        d.field = std::move(field);
        d.message = std::move(message);
        d.arguments = std::move(arguments);
        d.nestedNumber = number;
        m_result.push_back(std::move(d));
    }

    const Model& m_model;
    const Step& m_owner;
    const Grafcet& m_grafcet;
    const std::map<int, cond::ParseResult>& m_receptivities;
    const GrafcetAdjacency& m_adjacency;
    SymbolTable m_symbols;
    std::vector<Diagnostic> m_result;
};

} // namespace

std::vector<Diagnostic> checkGrafcetSequences(const Model& model, const Step& owner, const Grafcet& grafcet,
                                              const std::map<int, cond::ParseResult>& receptivities,
                                              const GrafcetAdjacency& adjacency)
{
    return SequenceChecker(model, owner, grafcet, receptivities, adjacency).run();
}

} // namespace core
