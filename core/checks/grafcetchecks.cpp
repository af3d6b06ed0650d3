#include "core/checks/grafcetchecks.h"

#include "core/checks/grafcetsequencechecks.h"
#include "core/checks/nestedsatisfiability.h"
#include "core/templates/gemma/gemmaprogram.h"
#include "core/condition/actionparser.h"
#include "core/condition/conditionanalysis.h"
#include "core/condition/conditionevaluator.h"
#include "core/condition/conditionparser.h"
#include "core/condition/divisionanalysis.h"
#include "core/condition/symboltable.h"
#include "core/model/grafcetadjacency.h"
#include "core/model/grafcetnumbers.h"
#include "core/model/messagetext.h"
#include "core/model/model.h"
#include "core/verification/satisfiability.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <string>

namespace core {

namespace {


// A step's action that makes Complete TRUE at some point: `S Complete`,
// `Complete := ...` or a continuous `Complete`.
bool setsComplete(const cond::ActionParseResult& action)
{
    return action.ok() && action.action.targetIsComplete && action.action.form != cond::ActionForm::Reset;
}

bool writesComplete(const cond::ActionParseResult& action)
{
    return action.ok() && action.action.targetIsComplete;
}

// The texts of one effective GRAFCET, parsed once.
struct ParsedGrafcet {
    const Step& owner;
    const Grafcet& grafcet;
    const GrafcetAdjacency adjacency;
    std::map<int, cond::ParseResult> receptivities;             // by transition number
    std::map<int, std::vector<cond::ActionParseResult>> actions; // by step number, in list order

    ParsedGrafcet(const Step& step, const Grafcet& g)
        : owner(step)
        , grafcet(g)
        , adjacency(g)
    {
        for (const GrafcetTransition& t : g.transitions())
            receptivities.emplace(t.number, cond::parse(t.receptivity, cond::kNestedOptions));
        for (const GrafcetStep& s : g.steps()) {
            std::vector<cond::ActionParseResult>& parsed = actions[s.number];
            for (const GrafcetAction& action : s.actions)
                parsed.push_back(cond::parseAction(action.text));
        }
    }

    bool stepSetsComplete(int number) const
    {
        const auto& list = actions.at(number);
        return std::any_of(list.begin(), list.end(), setsComplete);
    }

    bool stepWritesComplete(int number) const
    {
        const auto& list = actions.at(number);
        return std::any_of(list.begin(), list.end(), writesComplete);
    }

    bool anyStepSetsComplete() const
    {
        return std::any_of(grafcet.steps().begin(), grafcet.steps().end(),
                           [&](const GrafcetStep& s) { return stepSetsComplete(s.number); });
    }
};

// ---- the checker ------------------------------------------------------------------

class GrafcetChecker {
public:
    explicit GrafcetChecker(const Model& model)
        : m_model(model)
        , m_symbols(model.variables())
    {
    }

    std::vector<Diagnostic> run()
    {
        for (const Step& step : m_model.steps())
            checkStep(step);
        return std::move(m_result);
    }

    std::vector<Diagnostic> runStep(const Step& step)
    {
        checkStep(step);
        return std::move(m_result);
    }

private:
    void checkStep(const Step& step)
    {
        const Grafcet* grafcet = m_model.grafcet(step.id);
        if (!grafcet)
            return;
        if (!m_model.effectiveGrafcet(step.id)) {
            checkKept(step, *grafcet);
            return;
        }
        const ParsedGrafcet parsed(step, *grafcet);
        checkGrafcet(parsed);
        checkSteps(parsed);
        checkSelections(parsed);
        checkDivisors(parsed);
        for (Diagnostic& d : checkGrafcetSequences(m_model, step, *grafcet, parsed.receptivities, parsed.adjacency))
            m_result.push_back(std::move(d));
    }


private:
    void checkKept(const Step& step, const Grafcet& grafcet)
    {
        if (grafcet.steps().empty())
            return;
        const std::string why = step.hidden ? "hidden" : "a simple step";
        addStepLevel("GG422", Severity::Info, step.id,
                     "the nested GRAFCET of " + step.id + " is kept but not used: " + step.id + " is " + why
                         + " (make it a visible macro-step or enclosing step to use it again)",
                     {step.id, step.hidden ? "hidden" : "simple"});
    }

    // ---- the GRAFCET as a whole ----

    void checkGrafcet(const ParsedGrafcet& parsed)
    {
        const std::string& id = parsed.owner.id;
        if (parsed.grafcet.initialSteps().empty())
            addStepLevel("GG400", Severity::Error, id,
                         "the nested GRAFCET of " + id + " has no initial step: it would never do anything",
                         {id});
        const std::vector<std::string> waiting = transitionsWaitingForComplete(parsed.owner);
        if (!waiting.empty() && !parsed.anyStepSetsComplete())
            addStepLevel("GG416", Severity::Warning, id,
                         "the nested GRAFCET of " + id + " never sets Complete, so " + joined(waiting)
                             + ", which wait for it, can never fire",
                         {id, joined(waiting)});
    }

    std::vector<std::string> transitionsWaitingForComplete(const Step& step) const
    {
        std::vector<std::string> waiting;
        for (const Transition* t : m_model.effectiveOutgoing(step.id)) {
            const bool waits = step.type == StepType::Macro ? !t->negated : t->negated;
            if (waits)
                waiting.push_back(t->id);
        }
        return waiting;
    }

    // ---- steps ----

    void checkSteps(const ParsedGrafcet& parsed)
    {
        const std::set<int> reachable = reachableSteps(parsed.grafcet);
        const bool anyInitial = !parsed.grafcet.initialSteps().empty();
        const bool untilStable = m_model.settings().evolution == EvolutionRule::UntilStable;
        for (const GrafcetStep& step : parsed.grafcet.steps()) {
            if (anyInitial && !reachable.count(step.number))
                addNestedStep("GG412", Severity::Warning, parsed.owner.id, step.number,
                              "step " + std::to_string(step.number) + " of " + parsed.owner.id
                                  + " cannot be reached from the initial steps through transitions: it can never "
                                    "become active",
                              {parsed.owner.id, std::to_string(step.number)});
            if (parsed.adjacency.leaving(step.number).empty() && !parsed.stepSetsComplete(step.number))
                addNestedStep("GG418", Severity::Warning, parsed.owner.id, step.number,
                              "step " + std::to_string(step.number) + " of " + parsed.owner.id
                                  + " has no outgoing transition and does not set Complete: the GRAFCET stops "
                                    "there for good",
                              {parsed.owner.id, std::to_string(step.number)});
            if (untilStable && parsed.stepWritesComplete(step.number))
                checkTransient(parsed, step.number);
        }
    }

    // Structural reachability: a transition can fire once all its upstream
    // steps can be active; its downstream steps then can be.
    static std::set<int> reachableSteps(const Grafcet& grafcet)
    {
        const std::vector<int> initial = grafcet.initialSteps();
        std::set<int> reachable(initial.begin(), initial.end());
        for (bool grew = true; grew;) {
            grew = false;
            for (const GrafcetTransition& t : grafcet.transitions()) {
                const bool enabled = std::all_of(t.upstream.begin(), t.upstream.end(),
                                                 [&](int n) { return reachable.count(n) > 0; });
                if (!enabled)
                    continue;
                for (int n : t.downstream)
                    grew = reachable.insert(n).second || grew;
            }
        }
        return reachable;
    }

    // Until stable: a step left through a transition of its own whose
    // receptivity is always TRUE is left in the evolution after the one that
    // entered it, in the same call; the GEMMA layer never sees it active.
    void checkTransient(const ParsedGrafcet& parsed, int stepNumber)
    {
        for (const GrafcetTransition* t : parsed.adjacency.leaving(stepNumber)) {
            if (t->upstream.size() != 1 || !alwaysTrue(parsed.receptivities.at(t->number)))
                continue;
            const std::string step = std::to_string(stepNumber);
            addNestedStep("GG419", Severity::Warning, parsed.owner.id, stepNumber,
                          "under the until-stable rule, step " + step + " of " + parsed.owner.id
                              + " is left in the call that enters it (" + grafcetnumbers::transitionLabel(t->number)
                              + " is always TRUE): the GEMMA layer never sees what it does to Complete",
                          {parsed.owner.id, step, grafcetnumbers::transitionLabel(t->number)});
            return;
        }
    }

    bool usable(const cond::ParseResult& parsed) const
    {
        return parsed.ok() && cond::typeCheck(parsed.expression, m_symbols).empty();
    }

    bool alwaysTrue(const cond::ParseResult& parsed) const
    {
        if (!usable(parsed))
            return false;
        FreeAtomSpace space(m_model.variables());
        const cond::Expression free = space.substitute(parsed.expression);
        return sat::isValid(free, space.variables());
    }

    // ---- selection divergences ----

    // IEC 60848 fires every transition that can fire: two branches of a
    // selection whose receptivities hold together both start.
    void checkSelections(const ParsedGrafcet& parsed)
    {
        std::set<std::pair<int, int>> reported;
        for (const GrafcetStep& step : parsed.grafcet.steps()) {
            const std::vector<const GrafcetTransition*>& leaving = parsed.adjacency.leaving(step.number);
            for (std::size_t i = 0; i < leaving.size(); ++i) {
                for (std::size_t j = i + 1; j < leaving.size(); ++j) {
                    const auto pair = std::make_pair(leaving[i]->number, leaving[j]->number);
                    if (reported.count(pair) == 0 && checkExclusive(parsed, step.number, *leaving[i], *leaving[j]))
                        reported.insert(pair);
                }
            }
        }
    }

    // True when it reported the pair.
    bool checkExclusive(const ParsedGrafcet& parsed, int stepNumber, const GrafcetTransition& first,
                        const GrafcetTransition& second)
    {
        const cond::ParseResult& a = parsed.receptivities.at(first.number);
        const cond::ParseResult& b = parsed.receptivities.at(second.number);
        if (!usable(a) || !usable(b))
            return false;
        FreeAtomSpace space(m_model.variables());
        const cond::Expression both = conjunction(space.substitute(a.expression), space.substitute(b.expression));
        const std::optional<std::vector<cond::Value>> valuation = sat::findValuation(both, space.variables());
        if (!valuation)
            return false;
        const std::string& id = parsed.owner.id;
        const std::string witness = describeValuation(both, space.variables(), *valuation);
        const std::string step = std::to_string(stepNumber);
        addNestedTransition("GG417", Severity::Warning, id, second.number,
                            "the selection after step " + step + " of " + id + " is not exclusive: "
                                + grafcetnumbers::transitionLabel(first.number) + " and " + grafcetnumbers::transitionLabel(second.number)
                                + " can both fire (" + (witness.empty() ? "always" : "with " + witness)
                                + "), and both branches then start",
                            {id, step, grafcetnumbers::transitionLabel(first.number), grafcetnumbers::transitionLabel(second.number), witness});
        return true;
    }

    // ---- results ----

    void addStepLevel(std::string code, Severity severity, const std::string& stepId, std::string message,
                      std::vector<std::string> arguments)
    {
        Diagnostic d;
        d.code = std::move(code);
        d.severity = severity;
        d.target = Diagnostic::Target::Step;
        d.element = stepId;
        d.field = "grafcet";
        d.message = std::move(message);
        d.arguments = std::move(arguments);
        m_result.push_back(std::move(d));
    }

    void addNestedStep(std::string code, Severity severity, const std::string& stepId, int number,
                       std::string message, std::vector<std::string> arguments)
    {
        addStepLevel(std::move(code), severity, stepId, std::move(message), std::move(arguments));
        m_result.back().target = Diagnostic::Target::GrafcetStep;
        m_result.back().nestedNumber = number;
        m_result.back().field = "step";
    }

    void addNestedTransition(std::string code, Severity severity, const std::string& stepId, int number,
                             std::string message, std::vector<std::string> arguments)
    {
        addStepLevel(std::move(code), severity, stepId, std::move(message), std::move(arguments));
        m_result.back().target = Diagnostic::Target::GrafcetTransition;
        m_result.back().nestedNumber = number;
        m_result.back().field = "receptivity";
    }

    // ---- divisors that read variables ----

    // GG409: a divisor that can be zero. A constant zero one makes the text
    // unusable and is reported with the other such problems (GG408).
    void checkDivisors(const ParsedGrafcet& parsed)
    {
        const std::string& id = parsed.owner.id;
        for (const GrafcetTransition& t : parsed.grafcet.transitions()) {
            const cond::ParseResult& receptivity = parsed.receptivities.at(t.number);
            const std::string where = "the receptivity of " + grafcetnumbers::transitionLabel(t.number) + " of " + id;
            for (const cond::DivisionByZeroRisk& risk : variableDivisors(receptivity.ok(), receptivity.expression)) {
                addNestedTransition("GG409", Severity::Warning, id, t.number,
                                    divisorMessage(where, risk, t.receptivity),
                                    divisorArguments(id, where, risk, t.receptivity));
                m_result.back().span = risk.span;
            }
        }
        for (const GrafcetStep& step : parsed.grafcet.steps()) {
            const std::vector<cond::ActionParseResult>& actions = parsed.actions.at(step.number);
            for (std::size_t i = 0; i < actions.size(); ++i) {
                const std::string where = "action " + std::to_string(i + 1) + " of step " + std::to_string(step.number)
                    + " of " + id;
                const std::string& text = step.actions[i].text;
                for (const cond::Expression* expression : {&actions[i].action.condition, &actions[i].action.value}) {
                    for (const cond::DivisionByZeroRisk& risk : variableDivisors(actions[i].ok(), *expression)) {
                        addNestedStep("GG409", Severity::Warning, id, step.number, divisorMessage(where, risk, text),
                                      divisorArguments(id, where, risk, text));
                        m_result.back().field = "action";
                        m_result.back().actionIndex = static_cast<int>(i);
                        m_result.back().span = risk.span;
                    }
                }
            }
        }
    }

    static std::vector<cond::DivisionByZeroRisk> variableDivisors(bool parsed, const cond::Expression& expression)
    {
        std::vector<cond::DivisionByZeroRisk> result;
        if (!parsed || expression.empty())
            return result;
        for (const cond::DivisionByZeroRisk& risk : cond::divisionsByZero(expression)) {
            if (!risk.constantZero)
                result.push_back(risk);
        }
        return result;
    }

    static std::string divisorMessage(const std::string& where, const cond::DivisionByZeroRisk& risk,
                                      const std::string& text)
    {
        return "in " + where + ": " + cond::divisionByZeroMessage(risk, text);
    }

    static std::vector<std::string> divisorArguments(const std::string& id, const std::string& where,
                                                     const cond::DivisionByZeroRisk& risk, const std::string& text)
    {
        return {id, where, excerpt(text, risk.span), excerpt(text, risk.divisorSpan)};
    }

    const Model& m_model;
    SymbolTable m_symbols;
    std::vector<Diagnostic> m_result;
};

} // namespace

// The problems of single receptivities and actions, as the code generator
// found them (it uses FALSE for such a receptivity and skips such an action).
std::vector<Diagnostic> nestedProblemDiagnostics(const std::vector<ProgramProblem>& problems)
{
    std::vector<Diagnostic> result;
    for (ProgramProblem problem : problems) {
        if (problem.nestedStep == 0 && problem.nestedTransition == 0)
            continue;
        Diagnostic d;
        d.code = std::move(problem.code);
        d.severity = problem.kind == ProgramProblem::Kind::Error ? Severity::Error : Severity::Warning;
        d.element = std::move(problem.element);
        const bool onTransition = problem.nestedTransition != 0;
        d.target = onTransition ? Diagnostic::Target::GrafcetTransition : Diagnostic::Target::GrafcetStep;
        d.nestedNumber = onTransition ? problem.nestedTransition : problem.nestedStep;
        d.actionIndex = problem.actionIndex;
        d.field = onTransition ? "receptivity" : "action";
        d.message = std::move(problem.message);
        d.span = problem.span;
        d.arguments = std::move(problem.arguments);
        result.push_back(std::move(d));
    }
    return result;
}

// Spec §4.5: the names the code of nested GRAFCETs declares.
namespace {

std::optional<std::string> reservedNestedName(const Variable& variable, const std::vector<std::string>& edgeVariables)
{
    const std::string& name = variable.name;
    if (cond::stepActivityNumber(name) > 0)
        return "X followed by a number is a step activity";
    if (equalsIgnoreCase(name, kUnstableName))
        return "Unstable is an output of the function blocks";
    if (name.size() > 3 && equalsIgnoreCase(std::string_view(name).substr(0, 3), "GG_"))
        return "names starting with GG_ are the generated code's";
    for (const std::string& edged : edgeVariables) {
        if (equalsIgnoreCase(name, edgeMemoryName(edged)))
            return "it is the edge memory of " + edged;
    }
    return std::nullopt;
}

} // namespace

std::vector<Diagnostic> reservedNameDiagnostics(const Model& model, bool hasNestedGrafcets,
                                                const std::vector<std::string>& edgeVariables)
{
    std::vector<Diagnostic> result;
    if (!hasNestedGrafcets)
        return result;
    for (const Variable& variable : model.variables()) {
        const std::optional<std::string> why = reservedNestedName(variable, edgeVariables);
        if (!why)
            continue;
        Diagnostic d;
        d.code = "GG420";
        d.target = Diagnostic::Target::Variable;
        d.element = variable.name;
        d.field = "name";
        d.message = "variable '" + variable.name + "' has a name the code of the nested GRAFCETs uses: " + *why;
        d.arguments = {variable.name, *why};
        result.push_back(std::move(d));
    }
    return result;
}

std::vector<Diagnostic> checkGrafcets(const Model& model)
{
    std::vector<Diagnostic> result = GrafcetChecker(model).run();
    if (model.grafcets().empty())
        return result;
    // One build of the intermediate form for both: the code generator's view.
    const GemmaProgram program = buildGemmaProgram(model);
    for (Diagnostic& d : nestedProblemDiagnostics(program.problems))
        result.push_back(std::move(d));
    for (Diagnostic& d : reservedNameDiagnostics(model, program.hasNestedGrafcets(), program.edgeVariables))
        result.push_back(std::move(d));
    return result;
}

std::vector<Diagnostic> checkStepGrafcet(const Model& model, const Step& step)
{
    return GrafcetChecker(model).runStep(step);
}

void forEachGrafcetIdentifier(const Grafcet& grafcet, const std::function<void(std::string_view)>& use)
{
    const auto useTokens = [&](std::string_view text) {
        for (const cond::Token& token : cond::tokenize(text, cond::kNestedOptions)) {
            if (token.kind == cond::TokenKind::Identifier)
                use(token.text);
        }
    };
    for (const GrafcetTransition& t : grafcet.transitions())
        useTokens(t.receptivity);
    for (const GrafcetStep& s : grafcet.steps()) {
        for (const GrafcetAction& action : s.actions)
            useTokens(action.text);
    }
}

void forEachNestedIdentifier(const Model& model, const std::function<void(std::string_view)>& use)
{
    for (const auto& [stepId, grafcet] : model.grafcets()) {
        if (model.effectiveGrafcet(stepId))
            forEachGrafcetIdentifier(grafcet, use);
    }
}

} // namespace core
