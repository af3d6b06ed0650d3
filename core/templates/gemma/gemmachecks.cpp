#include "core/templates/gemma/gemmachecks.h"

#include "core/checks/grafcetchecks.h"
#include "core/condition/blanktext.h"
#include "core/machine/machinechecks.h"
#include "core/model/messagetext.h"

#include "core/condition/conditionanalysis.h"
#include "core/condition/conditionparser.h"
#include "core/condition/divisionanalysis.h"
#include "core/model/iectypes.h"
#include "core/model/model.h"
#include "core/model/stepnames.h"
#include "core/condition/symboltable.h"

#include <algorithm>
#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// The codes are documented in docs/diagnostics.md; keep both in step.

namespace core {

namespace {

// Spec §6.3: macro-steps wait unless negated, enclosing steps wait only when
// negated, family transitions never wait.
bool waitsForComplete(const Transition& transition, const Step* source)
{
    if (transition.isFamilyTransition() || source == nullptr)
        return false;
    switch (source->type) {
    case StepType::Simple: return false;
    case StepType::Macro: return !transition.negated;
    case StepType::Enclosing: return transition.negated;
    }
    return false;
}

bool isBoolConstant(const cond::Expression& expression, std::string_view value)
{
    if (expression.empty())
        return false;
    const cond::Node& root = expression.rootNode();
    return root.kind == cond::NodeKind::BoolLiteral && equalsIgnoreCase(root.text, value);
}

// Within one element: by field, then without span before with span, then by
// span; equal keys keep the order the checks produced them in.
bool fieldThenSpanLess(const Diagnostic& a, const Diagnostic& b)
{
    if (a.field != b.field)
        return a.field < b.field;
    if (a.span.has_value() != b.span.has_value())
        return !a.span.has_value();
    if (!a.span.has_value())
        return false;
    if (a.span->begin != b.span->begin)
        return a.span->begin < b.span->begin;
    return a.span->end < b.span->end;
}

// The effective transitions as edges between steps (indices into
// Model::steps()). The family transition becomes one edge from every visible
// F step, since it applies to each of them (spec §1).
struct StepGraph {
    std::vector<std::vector<std::size_t>> successors;
    std::vector<int> incomingCount;
    std::vector<bool> reachable; // from the initial step; all false when it is hidden
};

std::optional<std::size_t> stepIndex(const std::vector<Step>& steps, std::string_view id)
{
    for (std::size_t i = 0; i < steps.size(); ++i) {
        if (steps[i].id == id)
            return i;
    }
    return std::nullopt;
}

void addEdge(StepGraph& graph, std::size_t from, std::size_t to)
{
    graph.successors[from].push_back(to);
    ++graph.incomingCount[to];
}

void markReachable(const std::vector<Step>& steps, StepGraph& graph)
{
    const auto initial = std::find_if(steps.begin(), steps.end(), [](const Step& s) { return s.initial; });
    if (initial == steps.end() || initial->hidden)
        return;
    std::deque<std::size_t> pending{static_cast<std::size_t>(initial - steps.begin())};
    graph.reachable[pending.front()] = true;
    while (!pending.empty()) {
        const std::size_t current = pending.front();
        pending.pop_front();
        for (std::size_t next : graph.successors[current]) {
            if (!graph.reachable[next]) {
                graph.reachable[next] = true;
                pending.push_back(next);
            }
        }
    }
}

StepGraph buildStepGraph(const Model& model, const std::vector<bool>& effective)
{
    const std::vector<Step>& steps = model.steps();
    StepGraph graph;
    graph.successors.resize(steps.size());
    graph.incomingCount.assign(steps.size(), 0);
    graph.reachable.assign(steps.size(), false);
    const std::vector<Transition>& transitions = model.transitions();
    for (std::size_t i = 0; i < transitions.size(); ++i) {
        const Transition& transition = transitions[i];
        if (!effective[i])
            continue;
        const auto target = stepIndex(steps, transition.target);
        if (!target)
            continue;
        if (!transition.isFamilyTransition()) {
            if (const auto source = stepIndex(steps, transition.source))
                addEdge(graph, *source, *target);
            continue;
        }
        for (std::size_t i = 0; i < steps.size(); ++i) {
            if (steps[i].family == Family::F && !steps[i].hidden)
                addEdge(graph, i, *target);
        }
    }
    markReachable(steps, graph);
    return graph;
}

// How a token's variable occurs in a parsed condition.
struct TokenUse {
    bool occurs = false;
    bool normallyOpen = false;   // as a literal X
    bool normallyClosed = false; // as a literal NOT X
    bool compared = false;       // as an operand of = or <>, where it has no polarity
};

bool isVariableNamed(const cond::Expression& expression, int index, std::string_view name)
{
    const cond::Node& node = expression.at(index);
    return node.kind == cond::NodeKind::Variable && equalsIgnoreCase(node.text, name);
}

TokenUse tokenUse(const cond::Expression& expression, const std::vector<cond::Literal>& literals,
                  std::string_view name)
{
    TokenUse use;
    for (const cond::Literal& literal : literals) {
        if (isVariableNamed(expression, literal.variableNode, name))
            (literal.negated ? use.normallyClosed : use.normallyOpen) = true;
    }
    for (int index : cond::variableNodes(expression))
        use.occurs = use.occurs || isVariableNamed(expression, index, name);
    use.compared = cond::isComparedWithEquality(expression, name);
    return use;
}

class Checker {
public:
    explicit Checker(const Model& model)
        : m_model(model)
        , m_symbols(model.variables())
        , m_variableUsed(model.variables().size(), false)
    {
        for (const Transition& transition : model.transitions())
            m_effective.push_back(model.isEffective(transition));
    }

    // The steps, then the transitions; the variables their conditions read.
    GemmaElementChecks runElements()
    {
        parseConditions();
        const StepGraph graph = buildStepGraph(m_model, m_effective);
        const std::vector<Step>& steps = m_model.steps();
        for (std::size_t i = 0; i < steps.size(); ++i)
            checkStep(steps[i], i, graph);
        const std::vector<Transition>& transitions = m_model.transitions();
        for (std::size_t i = 0; i < transitions.size(); ++i)
            checkTransition(transitions[i], m_effective[i], m_conditions[i]);
        return {std::move(m_result), std::move(m_variableUsed)};
    }

    std::vector<Diagnostic> runVariables(const std::vector<bool>& used)
    {
        const std::vector<Variable>& variables = m_model.variables();
        for (std::size_t i = 0; i < variables.size(); ++i)
            checkVariable(variables[i], used[i]);
        return std::move(m_result);
    }

private:
    // The parsed condition of every effective transition, once; nullopt for
    // ineffective transitions (they generate no code, so they are not checked)
    // and for blank conditions.
    void parseConditions()
    {
        const std::vector<Transition>& transitions = m_model.transitions();
        m_conditions.resize(transitions.size());
        for (std::size_t i = 0; i < transitions.size(); ++i) {
            const Transition& transition = transitions[i];
            if (!m_effective[i] || isBlank(transition.condition))
                continue;
            m_conditions[i] = cond::parse(transition.condition);
            markUsedVariables(transition.condition, *m_conditions[i]);
        }
    }

    void markUsed(std::string_view name)
    {
        if (const Variable* variable = m_symbols.find(name))
            m_variableUsed[static_cast<std::size_t>(variable - m_model.variables().data())] = true;
    }

    // A condition being typed is often briefly invalid: its identifiers still
    // count as uses, or every keystroke would flash "unused variable".
    void markUsedVariables(std::string_view text, const cond::ParseResult& parsed)
    {
        if (parsed.ok()) {
            for (int node : cond::variableNodes(parsed.expression))
                markUsed(parsed.expression.at(node).text);
            return;
        }
        for (const cond::Token& token : cond::tokenize(text)) {
            if (token.kind == cond::TokenKind::Identifier)
                markUsed(token.text);
        }
    }

    void add(std::string code, Severity severity, Diagnostic::Target target, std::string element,
             std::string field, std::string message, std::vector<std::string> arguments,
             std::optional<Span> span = std::nullopt)
    {
        m_pending.push_back(Diagnostic{std::move(code), severity, target, std::move(element),
                                       std::move(field), std::move(message), span,
                                       std::move(arguments)});
    }

    // Moves the current element's diagnostics to the result in field/span order.
    void flush()
    {
        std::stable_sort(m_pending.begin(), m_pending.end(), fieldThenSpanLess);
        for (Diagnostic& diagnostic : m_pending)
            m_result.push_back(std::move(diagnostic));
        m_pending.clear();
    }

    // ---- steps ------------------------------------------------------------

    void checkStep(const Step& step, std::size_t index, const StepGraph& graph)
    {
        if (step.initial && step.hidden)
            addStep("GG001", Severity::Error, step, "initial",
                    "the initial step " + step.id + " is hidden: the PLC would start in a state that has no code",
                    {step.id});
        if (!step.hidden) {
            if (graph.successors[index].empty())
                addStep("GG101", Severity::Error, step, "outgoing",
                        "step " + step.id
                            + " has no visible outgoing transition: the machine would stay in it forever",
                        {step.id});
            checkStepReachable(step, index, graph);
            checkStepDeclarations(step);
        }
        flush();
    }

    // GG307, the step's side of GG306: the generated code declares the
    // step's instance and function block (visible macro/enclosing steps
    // only), and a variable already has one of those names.
    void checkStepDeclarations(const Step& step)
    {
        for (const Variable& variable : m_model.variables()) {
            if (identifierProblem(variable.name) != IdentifierProblem::None)
                continue;
            const std::optional<StepNameClash> clash = stepNameClash(m_model, variable.name);
            if (!clash || clash->step != &step)
                continue;
            const std::vector<std::string> clashArguments = stepNameClashArguments(m_model, variable, *clash);
            addStep("GG307", Severity::Error, step, "type",
                    std::string(clashedStepKind(*clash)) + " " + step.id + " declares its "
                        + std::string(clashedDeclaration(*clash)) + " " + (clash->functionBlock ? step.id + "_FB" : step.id)
                        + " in the generated code, and variable " + quoted(variable.name) + " has that name: "
                        + stepNameClashFix(m_model, variable) + ", or make " + step.id + " a simple step",
                    {step.id, variable.name, clashArguments[2], clashArguments[3], clashArguments[4]});
        }
    }

    void checkStepReachable(const Step& step, std::size_t index, const StepGraph& graph)
    {
        if (step.initial)
            return;
        if (graph.incomingCount[index] == 0) {
            addStep("GG102", Severity::Warning, step, "incoming",
                    "step " + step.id + " has no visible incoming transition: it can never become active",
                    {step.id});
            return;
        }
        const Step& initial = m_model.initialStep();
        if (!initial.hidden && !graph.reachable[index])
            addStep("GG103", Severity::Warning, step, "incoming",
                    "step " + step.id + " cannot be reached from the initial step " + initial.id
                        + " through visible transitions: it can never become active",
                    {step.id, initial.id});
    }

    void addStep(std::string code, Severity severity, const Step& step, std::string field,
                 std::string message, std::vector<std::string> arguments)
    {
        add(std::move(code), severity, Diagnostic::Target::Step, step.id, std::move(field),
            std::move(message), std::move(arguments));
    }

    // ---- transitions ------------------------------------------------------

    void checkTransition(const Transition& transition, bool effective,
                         const std::optional<cond::ParseResult>& parsed)
    {
        if (effective) {
            const Step* source = m_model.step(transition.source);
            checkCondition(transition, source, parsed);
            checkNegation(transition, source);
            checkTokens(transition, source, parsed);
        }
        flush();
    }

    void checkCondition(const Transition& transition, const Step* source,
                        const std::optional<cond::ParseResult>& parsed)
    {
        const std::string& id = transition.id;
        if (!parsed) {
            addTransition("GG202", Severity::Error, id, "condition",
                          "the condition of " + id + " is empty: write TRUE for a transition that is always ready",
                          {id});
            return;
        }
        if (!parsed->ok()) {
            const cond::ParseError& error = *parsed->error;
            std::vector<std::string> arguments{id, excerpt(transition.condition, error.span), error.message};
            cond::appendArguments(error, arguments);
            addTransition("GG201", Severity::Error, id, "condition",
                          "syntax error in the condition of " + id + ": " + error.message, std::move(arguments),
                          error.span);
            return;
        }
        const std::vector<cond::TypeIssue> issues = cond::typeCheck(parsed->expression, m_symbols);
        for (const cond::TypeIssue& issue : issues) {
            std::vector<std::string> arguments{id, excerpt(transition.condition, issue.span), issue.message};
            if (issue.error)
                cond::appendArguments(*issue.error, arguments);
            addTransition(issue.code, Severity::Error, id, "condition",
                          "in the condition of " + id + ": " + issue.message, std::move(arguments), issue.span);
        }
        if (!issues.empty())
            return;
        checkConstantCondition(transition, source, parsed->expression);
        checkDivisions(transition, parsed->expression);
    }

    // A constant zero divisor is an error (the generated code and the
    // simulator use FALSE for the condition); a divisor that reads a variable
    // a warning: on the PLC an integer division by zero is a fault.
    void checkDivisions(const Transition& transition, const cond::Expression& expression)
    {
        const std::string& id = transition.id;
        for (const cond::DivisionByZeroRisk& risk : cond::divisionsByZero(expression)) {
            const std::string detail = cond::divisionByZeroMessage(risk, transition.condition);
            addTransition(risk.constantZero ? "GG215" : "GG216",
                          risk.constantZero ? Severity::Error : Severity::Warning, id, "condition",
                          "in the condition of " + id + ": " + detail,
                          {id, excerpt(transition.condition, risk.span), excerpt(transition.condition, risk.divisorSpan)},
                          risk.span);
        }
    }

    void checkConstantCondition(const Transition& transition, const Step* source,
                                const cond::Expression& expression)
    {
        const std::string& id = transition.id;
        if (isBoolConstant(expression, "FALSE")) {
            addTransition("GG214", Severity::Warning, id, "condition",
                          "the condition of " + id + " is FALSE: the transition can never fire (hide it instead)",
                          {id});
            return;
        }
        if (!isBoolConstant(expression, "TRUE") || waitsForComplete(transition, source))
            return;
        std::vector<std::string> shadowed = lowerPriorityTransitions(transition);
        if (shadowed.empty())
            return;
        const std::string list = joined(shadowed);
        addTransition("GG213", Severity::Warning, id, "condition",
                      "the condition of " + id + " is TRUE and does not wait for Complete: "
                          + "the lower-priority transitions " + list + " can never fire",
                      {id, list});
    }

    // The effective transitions evaluated after this one from the same state;
    // after a family transition, that is every own transition of the visible
    // F steps as well.
    std::vector<std::string> lowerPriorityTransitions(const Transition& transition) const
    {
        std::vector<std::string> result;
        appendAfter(m_model.effectiveOutgoing(transition.source), transition, result);
        if (!transition.isFamilyTransition())
            return result;
        for (const Step& step : m_model.steps()) {
            if (step.family == Family::F && !step.hidden)
                appendAfter(m_model.effectiveOutgoing(step.id), transition, result);
        }
        return result;
    }

    static void appendAfter(const std::vector<const Transition*>& ordered, const Transition& transition,
                            std::vector<std::string>& result)
    {
        auto position = std::find(ordered.begin(), ordered.end(), &transition);
        auto first = position == ordered.end() ? ordered.begin() : position + 1;
        for (auto it = first; it != ordered.end(); ++it)
            result.push_back((*it)->id);
    }

    void checkNegation(const Transition& transition, const Step* source)
    {
        if (!transition.negated)
            return;
        const std::string& id = transition.id;
        if (transition.isFamilyTransition())
            addTransition("GG206", Severity::Warning, id, "negated",
                          "the family transition " + id
                              + " is negated, which has no effect: family transitions never wait for Complete",
                          {id});
        else if (source != nullptr && source->type == StepType::Simple)
            addTransition("GG205", Severity::Warning, id, "negated",
                          "transition " + id + " is negated, which has no effect: its source " + source->id
                              + " is a simple step, and negation only changes transitions out of macro and"
                              + " enclosing steps",
                          {id, source->id});
    }

    void checkTokens(const Transition& transition, const Step* source,
                     const std::optional<cond::ParseResult>& parsed)
    {
        if (transition.tokens.empty())
            return;
        const bool tokensApply = source != nullptr && hasNestedBehaviour(source->type);
        const cond::Expression* expression = parsed && parsed->ok() ? &parsed->expression : nullptr;
        std::vector<cond::Literal> literals;
        if (tokensApply && expression != nullptr)
            literals = cond::booleanLiterals(*expression);
        for (const std::string& name : transition.tokens) {
            if (tokensApply)
                checkToken(transition, name, expression, literals);
            else
                addIneffectiveToken(transition, name);
        }
    }

    void addIneffectiveToken(const Transition& transition, const std::string& name)
    {
        const std::string& id = transition.id;
        const std::string why = transition.isFamilyTransition()
            ? "family transitions never wait for Complete"
            : "its source " + transition.source + " is a simple step";
        addTransition("GG210", Severity::Warning, id, "tokens",
                      "the token on " + quoted(name) + " in " + id + " has no effect and is not generated: " + why,
                      {id, name});
    }

    void checkToken(const Transition& transition, const std::string& name, const cond::Expression* expression,
                    const std::vector<cond::Literal>& literals)
    {
        const std::string& id = transition.id;
        const Variable* variable = m_symbols.find(name);
        if (variable == nullptr) {
            addTransition("GG211", Severity::Error, id, "tokens",
                          "the token in " + id + " names " + quoted(name) + ", which is not a declared variable",
                          {id, name});
            return;
        }
        const std::string& declared = variable->name;
        if (variable->type != IecType::Bool) {
            const std::string type(iecTypeName(variable->type));
            addTransition("GG207", Severity::Error, id, "tokens",
                          "the token on " + quoted(declared) + " in " + id + " is invalid: " + quoted(declared)
                              + " is " + type + ", and only BOOL variables can have a token",
                          {id, declared, type});
            return;
        }
        // An unparsable condition is reported on its own; what it contains is unknown.
        if (expression != nullptr)
            checkTokenUse(id, declared, tokenUse(*expression, literals, declared));
    }

    void checkTokenUse(const std::string& id, const std::string& name, const TokenUse& use)
    {
        const std::string subject = "the token on " + quoted(name) + " in " + id;
        if (!use.occurs)
            addTransition("GG208", Severity::Error, id, "tokens",
                          subject + " is invalid: " + quoted(name) + " does not occur in the condition",
                          {id, name});
        else if (use.compared)
            addTransition("GG212", Severity::Error, id, "tokens",
                          subject + " is invalid: " + quoted(name)
                              + " is compared with '=' or '<>' in the condition, where it has no polarity;"
                              + " a token can only replace a literal " + name + " or NOT " + name,
                          {id, name});
        else if (use.normallyOpen && use.normallyClosed)
            addTransition("GG209", Severity::Error, id, "tokens",
                          subject + " is ambiguous: the condition uses both " + name + " and NOT " + name
                              + ", so the token could be neither normally open nor normally closed",
                          {id, name});
    }

    void addTransition(std::string code, Severity severity, const std::string& id, std::string field,
                       std::string message, std::vector<std::string> arguments,
                       std::optional<Span> span = std::nullopt)
    {
        add(std::move(code), severity, Diagnostic::Target::Transition, id, std::move(field),
            std::move(message), std::move(arguments), span);
    }

    // ---- variables --------------------------------------------------------

    void checkVariable(const Variable& variable, bool used)
    {
        checkVariableName(variable);
        if (const std::optional<ValueProblem> problem = valueProblem(variable.type, variable.defaultValue)) {
            const std::string detail = toText(*problem);
            std::vector<std::string> arguments{variable.name, variable.defaultValue, detail};
            appendArguments(*problem, arguments);
            addVariable("GG304", Severity::Error, variable, "default",
                        "the default value of variable " + quoted(variable.name) + " is invalid: " + detail,
                        std::move(arguments));
        }
        if (!used)
            addVariable("GG305", Severity::Warning, variable, "name",
                        "variable " + quoted(variable.name)
                            + " is used by no condition, receptivity or action that generates code",
                        {variable.name});
        flush();
    }

    void checkVariableName(const Variable& variable)
    {
        const IdentifierProblem problem = identifierProblem(variable.name);
        if (problem == IdentifierProblem::None) {
            checkStepNameClash(variable);
            return;
        }
        const char* code = problem == IdentifierProblem::Keyword ? "GG302"
            : problem == IdentifierProblem::GeneratorName        ? "GG303"
                                                                 : "GG301";
        const std::string detail = identifierProblemMessage(problem, variable.name);
        addVariable(code, Severity::Error, variable, "name",
                    "invalid variable name: " + detail,
                    {variable.name, detail});
    }

    // GG306, the variable's side of GG307.
    void checkStepNameClash(const Variable& variable)
    {
        const std::optional<StepNameClash> clash = stepNameClash(m_model, variable.name);
        if (!clash)
            return;
        addVariable("GG306", Severity::Error, variable, "name",
                    "variable " + quoted(variable.name) + " has the name of the " + std::string(clashedDeclaration(*clash))
                        + " of " + std::string(clashedStepKind(*clash)) + " " + clash->step->id
                        + " in the generated code: " + stepNameClashFix(m_model, variable),
                    stepNameClashArguments(m_model, variable, *clash));
    }

    void addVariable(std::string code, Severity severity, const Variable& variable, std::string field,
                     std::string message, std::vector<std::string> arguments)
    {
        add(std::move(code), severity, Diagnostic::Target::Variable, variable.name, std::move(field),
            std::move(message), std::move(arguments));
    }

    const Model& m_model;
    SymbolTable m_symbols;
    std::vector<bool> m_effective;    // by transition index
    std::vector<bool> m_variableUsed; // by declaration index
    std::vector<std::optional<cond::ParseResult>> m_conditions; // by transition index
    std::vector<Diagnostic> m_pending; // the element being checked
    std::vector<Diagnostic> m_result;
};

} // namespace

GemmaElementChecks checkGemmaElements(const Model& model)
{
    return Checker(model).runElements();
}

std::vector<Diagnostic> checkGemmaVariables(const Model& model, const std::vector<bool>& used)
{
    return Checker(model).runVariables(used);
}

void markNestedUses(const Model& model, const Grafcet& grafcet, std::vector<bool>& used)
{
    const SymbolTable symbols(model.variables());
    forEachGrafcetIdentifier(grafcet, [&](std::string_view name) {
        if (const Variable* variable = symbols.find(name))
            used[static_cast<std::size_t>(variable - model.variables().data())] = true;
    });
}

std::vector<Diagnostic> checkGemmaModel(const Model& model)
{
    GemmaElementChecks elements = checkGemmaElements(model);
    std::vector<Diagnostic> diagnostics = std::move(elements.diagnostics);
    for (Diagnostic& diagnostic : checkGrafcets(model))
        diagnostics.push_back(std::move(diagnostic));
    for (const auto& [stepId, grafcet] : model.grafcets()) {
        if (model.effectiveGrafcet(stepId))
            markNestedUses(model, grafcet, elements.variableUsed);
    }
    for (Diagnostic& diagnostic : checkGemmaVariables(model, elements.variableUsed))
        diagnostics.push_back(std::move(diagnostic));
    for (Diagnostic& diagnostic : machine::checkMachine(model))
        diagnostics.push_back(std::move(diagnostic));
    return diagnostics;
}

} // namespace core
