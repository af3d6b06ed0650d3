#include "core/templates/gemma/gemmaprogram.h"

#include "core/codegen/nestedgrafcetset.h"
#include "core/condition/blanktext.h"
#include "core/condition/conditionanalysis.h"
#include "core/condition/divisionanalysis.h"
#include "core/model/model.h"
#include "core/model/messagetext.h"
#include "core/model/stepnames.h"
#include "core/condition/symboltable.h"

#include <algorithm>
#include <set>
#include <string_view>

namespace core {

namespace {

// Codes and wording shared with the checks (core/templates/gemma/gemmachecks.cpp), so a comment
// in the generated code names the same finding as the checks panel.
constexpr const char* kInitialHiddenCode = "GG001";
constexpr const char* kConditionSyntaxCode = "GG201";
constexpr const char* kConditionEmptyCode = "GG202";
constexpr const char* kTokenNotBoolCode = "GG207";
constexpr const char* kTokenAbsentCode = "GG208";
constexpr const char* kTokenBothPolaritiesCode = "GG209";
constexpr const char* kTokenNoEffectCode = "GG210";
constexpr const char* kTokenUndeclaredCode = "GG211";
constexpr const char* kTokenNoLiteralCode = "GG212";

struct BuildContext {
    const Model& model;
    SymbolTable symbols;
};

ProgramProblem makeProblem(ProgramProblem::Kind kind, std::string code, const std::string& element, std::string message,
                         std::vector<std::string> arguments = {})
{
    ProgramProblem problem;
    problem.kind = kind;
    problem.code = std::move(code);
    problem.element = element;
    problem.message = std::move(message);
    problem.arguments = std::move(arguments);
    return problem;
}

bool waitsForComplete(StepType sourceType, bool negated, bool family)
{
    if (family)
        return false;
    switch (sourceType) {
    case StepType::Simple: return false;
    case StepType::Macro: return !negated;
    case StepType::Enclosing: return negated;
    }
    return false;
}

// A condition that reads a variable the code declares under another name
// (unusableNameCode) is unusable: printing the name would write user text
// into the code, printing the other name would read a variable the user
// never named.
void rejectUndeclarableNames(const BuildContext& context, GemmaTransition& transition)
{
    const std::string& id = transition.id;
    const cond::Expression& expression = transition.condition.expression;
    std::vector<const Variable*> reported;
    for (int node : cond::variableNodes(expression)) {
        const Variable* variable = context.symbols.find(expression.at(node).text);
        if (!variable || std::find(reported.begin(), reported.end(), variable) != reported.end())
            continue;
        const char* code = unusableNameCode(variable->name, context.model);
        if (!code)
            continue;
        reported.push_back(variable);
        const std::string detail = unusableNameDetail(variable->name, context.model);
        transition.problems.push_back(makeProblem(ProgramProblem::Kind::Error, code, id,
                                                  "in the condition of " + id + ": invalid variable name: " + detail,
                                                  unusableNameArguments(*variable, context.model)));
        transition.conditionUsable = false;
    }
}

// A constant zero divisor (GG215): the PLC would fault (integer) or compute
// INF or NaN (REAL) at every evaluation; the condition is unusable, FALSE in
// the code, the simulator and the verifier alike.
void rejectConstantZeroDivisors(GemmaTransition& transition)
{
    const std::string& id = transition.id;
    for (const cond::DivisionByZeroRisk& risk : cond::divisionsByZero(transition.condition.expression)) {
        if (!risk.constantZero)
            continue;
        transition.problems.push_back(makeProblem(
            ProgramProblem::Kind::Error, "GG215", id,
            "in the condition of " + id + ": " + cond::divisionByZeroMessage(risk, transition.conditionText),
            {id, excerpt(transition.conditionText, risk.span), excerpt(transition.conditionText, risk.divisorSpan)}));
        transition.conditionUsable = false;
    }
}

// Parses and type-checks the condition; records why it cannot be used.
void analyseCondition(const BuildContext& context, GemmaTransition& transition)
{
    const std::string& id = transition.id;
    transition.condition = cond::parse(transition.conditionText);
    if (isBlank(transition.conditionText)) {
        transition.problems.push_back(makeProblem(ProgramProblem::Kind::Error, kConditionEmptyCode, id,
                                                  "the condition of " + id
                                                      + " is empty: write TRUE for a transition that is always ready",
                                                  {id}));
        return;
    }
    if (!transition.condition.ok()) {
        const cond::ParseError& error = *transition.condition.error;
        std::vector<std::string> arguments{id, excerpt(transition.conditionText, error.span), error.message};
        cond::appendArguments(error, arguments);
        transition.problems.push_back(makeProblem(ProgramProblem::Kind::Error, kConditionSyntaxCode, id,
                                                  "syntax error in the condition of " + id + ": " + error.message,
                                                  std::move(arguments)));
        return;
    }
    std::vector<cond::TypeIssue> issues = cond::typeCheck(transition.condition.expression, context.symbols);
    for (cond::TypeIssue& issue : issues) {
        std::vector<std::string> arguments{id, excerpt(transition.conditionText, issue.span), issue.message};
        if (issue.error)
            cond::appendArguments(*issue.error, arguments);
        transition.problems.push_back(makeProblem(ProgramProblem::Kind::Error, std::move(issue.code), id,
                                                  "in the condition of " + id + ": " + issue.message,
                                                  std::move(arguments)));
    }
    transition.conditionUsable = issues.empty();
    if (transition.conditionUsable)
        rejectConstantZeroDivisors(transition);
    rejectUndeclarableNames(context, transition);
}

// How one variable occurs in the condition, or why it cannot carry a token.
struct TokenLiterals {
    std::vector<int> nodes;
    bool negated = false;
    const char* problemCode = nullptr;
    std::string problem;
};

TokenLiterals findTokenLiterals(const BuildContext& context, const GemmaTransition& transition,
                                const Variable& variable)
{
    TokenLiterals result;
    const cond::Expression& expression = transition.condition.expression;
    bool occurs = false;
    for (int node : cond::variableNodes(expression))
        occurs = occurs || context.symbols.find(expression.at(node).text) == &variable;
    bool sawOpen = false;
    bool sawClosed = false;
    for (const cond::Literal& literal : cond::booleanLiterals(expression)) {
        if (context.symbols.find(expression.at(literal.variableNode).text) != &variable)
            continue;
        result.nodes.push_back(literal.node);
        (literal.negated ? sawClosed : sawOpen) = true;
    }
    const std::string name = quoted(variable.name);
    if (!occurs) {
        result.problemCode = kTokenAbsentCode;
        result.problem = name + " does not occur in the condition";
    } else if (cond::isComparedWithEquality(expression, variable.name)) {
        result.problemCode = kTokenNoLiteralCode;
        result.problem = name + " is compared with '=' or '<>' in the condition, where it has no polarity";
    } else if (result.nodes.empty()) {
        result.problemCode = kTokenNoLiteralCode;
        result.problem = name + " occurs in the condition only inside a comparison or other operation, never as a "
                         "boolean literal";
    } else if (sawOpen && sawClosed) {
        result.problemCode = kTokenBothPolaritiesCode;
        result.problem = "the condition uses both " + variable.name + " and NOT " + variable.name;
    }
    result.negated = sawClosed;
    return result;
}

// Turns the transition's token names into tokens, ignoring (with a warning)
// those that cannot take effect; the checks report the same cases as errors.
void resolveTokens(const BuildContext& context, const Step& source, int priority, GemmaTransition& transition,
                   const std::vector<std::string>& tokenNames, std::vector<GemmaToken>& tokens)
{
    std::vector<const Variable*> done;
    for (const std::string& tokenName : tokenNames) {
        auto ignore = [&](const char* code, const std::string& why) {
            transition.problems.push_back(makeProblem(ProgramProblem::Kind::Warning, code ? code : "", transition.id,
                                                      "the token on " + quoted(tokenName) + " in " + transition.id
                                                          + " is not generated: " + why));
        };
        if (!hasNestedBehaviour(source.type)) {
            ignore(kTokenNoEffectCode, "its source " + source.id + " is a simple step");
            continue;
        }
        const Variable* variable = context.symbols.find(tokenName);
        if (!variable) {
            ignore(kTokenUndeclaredCode, quoted(tokenName) + " is not a declared variable");
            continue;
        }
        if (std::find(done.begin(), done.end(), variable) != done.end())
            continue; // the same variable listed twice: one token
        if (variable->type != IecType::Bool) {
            ignore(kTokenNotBoolCode, quoted(variable->name) + " is " + std::string(iecTypeName(variable->type))
                                          + ", and only BOOL variables can have a token");
            continue;
        }
        if (!transition.conditionUsable) {
            ignore(nullptr, "the condition cannot be used");
            continue;
        }
        TokenLiterals literals = findTokenLiterals(context, transition, *variable);
        if (literals.problemCode) {
            ignore(literals.problemCode, literals.problem);
            continue;
        }
        done.push_back(variable);
        GemmaToken token;
        token.name = tokenVariableName(variable->name, source.id, priority);
        token.variable = variable->name;
        token.polarity = literals.negated ? TokenPolarity::NormallyClosed : TokenPolarity::NormallyOpen;
        token.transitionId = transition.id;
        token.literalNodes = std::move(literals.nodes);
        for (int node : token.literalNodes)
            transition.substitutions[node] = token.name;
        tokens.push_back(std::move(token));
    }
}

// Tokens in the order of their first literal in the condition, whatever the
// order the user listed them in.
void sortTokensBySourcePosition(const GemmaTransition& transition, std::vector<GemmaToken>::iterator first,
                                std::vector<GemmaToken>::iterator last)
{
    const cond::Expression& expression = transition.condition.expression;
    std::stable_sort(first, last, [&](const GemmaToken& a, const GemmaToken& b) {
        return expression.at(a.literalNodes.front()).span.begin < expression.at(b.literalNodes.front()).span.begin;
    });
}

GemmaTransition makeTransition(const BuildContext& context, const Transition& transition, int priority)
{
    GemmaTransition result;
    result.id = transition.id;
    result.targetId = transition.target;
    if (const Step* target = context.model.step(transition.target))
        result.targetNumber = target->number;
    result.priority = priority;
    result.family = transition.isFamilyTransition();
    result.negated = transition.negated;
    result.conditionText = transition.condition;
    analyseCondition(context, result);
    return result;
}

// The family transitions every visible F state evaluates first: visible and
// leading to a visible step.
std::vector<GemmaTransition> familyTransitions(const BuildContext& context)
{
    std::vector<const Transition*> family;
    for (const Transition& transition : context.model.transitions()) {
        if (!transition.isFamilyTransition() || transition.hidden)
            continue;
        const Step* target = context.model.step(transition.target);
        if (target && !target->hidden)
            family.push_back(&transition);
    }
    std::stable_sort(family.begin(), family.end(),
                     [](const Transition* a, const Transition* b) { return a->order < b->order; });
    std::vector<GemmaTransition> result;
    int priority = 0;
    for (const Transition* transition : family) {
        result.push_back(makeTransition(context, *transition, ++priority));
        if (!transition->tokens.empty()) {
            result.back().problems.push_back(makeProblem(ProgramProblem::Kind::Warning, kTokenNoEffectCode,
                                                         transition->id,
                                                         "the tokens in " + transition->id + " are not generated: "
                                                         "family transitions never wait for Complete"));
        }
    }
    return result;
}

GemmaStep makeStep(const BuildContext& context, const Step& step, const std::vector<GemmaTransition>& family)
{
    GemmaStep result;
    result.id = step.id;
    result.number = step.number;
    if (const TemplateState* state = findTemplateState(step.id))
        result.name = std::string(state->englishName);
    result.type = step.type;
    result.initial = step.initial;
    if (step.family == Family::F)
        result.transitions = family;
    int priority = 0;
    for (const Transition* transition : context.model.effectiveOutgoing(step.id)) {
        ++priority;
        GemmaTransition own = makeTransition(context, *transition, priority);
        own.waitsForComplete = waitsForComplete(step.type, transition->negated, false);
        std::size_t firstToken = result.tokens.size();
        resolveTokens(context, step, priority, own, transition->tokens, result.tokens);
        sortTokensBySourcePosition(own, result.tokens.begin() + static_cast<std::ptrdiff_t>(firstToken),
                                   result.tokens.end());
        result.transitions.push_back(std::move(own));
    }
    return result;
}

// The GEMMA model's reserved names (gemmaprogram.h's free functions) for
// the nested GRAFCETs' builder.
class GemmaUnusableNames final : public UnusableNames {
public:
    explicit GemmaUnusableNames(const Model& model)
        : m_model(model)
    {
    }
    const char* code(std::string_view name) const override { return unusableNameCode(name, m_model); }
    std::string detail(std::string_view name) const override { return unusableNameDetail(name, m_model); }
    std::vector<std::string> arguments(const Variable& variable) const override
    {
        return unusableNameArguments(variable, m_model);
    }

private:
    const Model& m_model;
};

NestedGrafcet buildStepNestedGrafcet(const BuildContext& context, const UnusableNames& names, const Step& step,
                                     const Grafcet& grafcet, std::vector<ProgramProblem>& problems)
{
    const NestedScope scope{step.id, step.id, context.model.variables(), context.symbols, names};
    return buildNestedGrafcet(context.model, scope, grafcet, problems);
}

// GG415 and the edge memories, once every nested GRAFCET is built.
void finishNestedGrafcets(const Model& model, GemmaProgram& program)
{
    std::vector<OwnedGrafcet> owned;
    std::vector<const NestedGrafcet*> built;
    for (GemmaStep& step : program.steps) {
        if (!step.nested)
            continue;
        owned.push_back({step.id, step.id, &*step.nested});
        built.push_back(&*step.nested);
    }
    rejectStoredWritesOfContinuousOutputs(owned, program.problems);
    program.edgeVariables = edgeVariablesOf(model.variables(), built);
}

} // namespace

bool GemmaProgram::hasNestedGrafcets() const
{
    return std::any_of(steps.begin(), steps.end(), [](const GemmaStep& s) { return s.nested.has_value(); });
}

const GemmaStep* GemmaProgram::step(const std::string& id) const
{
    for (const GemmaStep& candidate : steps) {
        if (candidate.id == id)
            return &candidate;
    }
    return nullptr;
}

const char* unusableNameCode(std::string_view name, const Model& model)
{
    switch (identifierProblem(name)) {
    case IdentifierProblem::None: return stepNameClash(model, name) ? "GG306" : nullptr;
    case IdentifierProblem::Keyword: return "GG302";
    case IdentifierProblem::GeneratorName: return "GG303";
    default: return "GG301"; // the codes of core/templates/gemma/gemmachecks.cpp
    }
}

std::string unusableNameDetail(std::string_view name, const Model& model)
{
    if (const IdentifierProblem problem = identifierProblem(name); problem != IdentifierProblem::None)
        return identifierProblemMessage(problem, name);
    const std::optional<StepNameClash> clash = stepNameClash(model, name);
    if (!clash)
        return {};
    const Variable* variable = model.variable(name);
    return stepNameClashDetail(*clash, name) + (variable ? "; " + stepNameClashFix(model, *variable) : "");
}

std::vector<std::string> unusableNameArguments(const Variable& variable, const Model& model)
{
    if (identifierProblem(variable.name) == IdentifierProblem::None) {
        if (const std::optional<StepNameClash> clash = stepNameClash(model, variable.name))
            return stepNameClashArguments(model, variable, *clash);
    }
    return {variable.name, unusableNameDetail(variable.name, model)};
}

std::string tokenVariableName(const std::string& variable, const std::string& sourceStepId, int priority)
{
    return variable + "_" + sourceStepId + "_" + std::to_string(priority) + "_MEM";
}

std::optional<NestedGrafcet> buildGemmaNestedGrafcet(const Model& model, const Step& step,
                                                     std::vector<ProgramProblem>& problems)
{
    const Grafcet* grafcet = model.effectiveGrafcet(step.id);
    if (step.hidden || grafcet == nullptr)
        return std::nullopt;
    const BuildContext context{model, SymbolTable(model.variables())};
    return buildStepNestedGrafcet(context, GemmaUnusableNames(model), step, *grafcet, problems);
}

GemmaProgram buildGemmaProgram(const Model& model)
{
    BuildContext context{model, SymbolTable(model.variables())};
    GemmaProgram program;
    const Step& initial = model.initialStep();
    program.initialStepId = initial.id;
    program.initialNumber = initial.number;
    if (initial.hidden) {
        program.problems.push_back(makeProblem(ProgramProblem::Kind::Error, kInitialHiddenCode, initial.id,
                                               "the initial step " + initial.id
                                                   + " is hidden: the PLC would start in a state that has no code"));
    }

    const std::vector<GemmaTransition> family = familyTransitions(context);
    const GemmaUnusableNames names(model);
    bool familyProblemsReported = false;
    for (const Step& step : model.steps()) {
        if (step.hidden)
            continue;
        program.steps.push_back(makeStep(context, step, family));
        for (const GemmaTransition& transition : program.steps.back().transitions) {
            if (transition.family && familyProblemsReported)
                continue;
            program.problems.insert(program.problems.end(), transition.problems.begin(), transition.problems.end());
        }
        if (step.family == Family::F)
            familyProblemsReported = true;
        if (const Grafcet* grafcet = model.effectiveGrafcet(step.id))
            program.steps.back().nested = buildStepNestedGrafcet(context, names, step, *grafcet, program.problems);
    }
    program.evolution = model.settings().evolution;
    finishNestedGrafcets(model, program);
    return program;
}

} // namespace core
