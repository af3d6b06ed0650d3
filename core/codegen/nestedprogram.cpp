#include "core/codegen/nestedprogram.h"

#include "core/templates/gemma/gemmaprogram.h"
#include "core/codegen/stgenerator.h"
#include "core/condition/blanktext.h"
#include "core/condition/conditionanalysis.h"
#include "core/condition/divisionanalysis.h"
#include "core/condition/symboltable.h"
#include "core/model/model.h"
#include "core/model/messagetext.h"

#include <algorithm>
#include <set>
#include <utility>

namespace core {

namespace {


// Builds one GRAFCET, collecting its problems.
class NestedBuilder {
public:
    NestedBuilder(const Model& model, const NestedScope& scope, const Grafcet& grafcet,
                  std::vector<ProgramProblem>& problems)
        : m_scope(scope)
        , m_grafcet(grafcet)
        , m_symbols(scope.symbols)
        , m_problems(problems)
    {
        m_result.stepId = scope.element;
        m_result.rule = model.settings().evolution;
    }

    NestedGrafcet build()
    {
        std::vector<const GrafcetStep*> steps;
        for (const GrafcetStep& s : m_grafcet.steps())
            steps.push_back(&s);
        std::sort(steps.begin(), steps.end(), [](auto a, auto b) { return a->number < b->number; });
        for (const GrafcetStep* s : steps)
            m_result.steps.push_back(buildStep(*s));
        collectOutputs();
        rejectConditionsOnOwnOutputs();
        std::vector<const GrafcetTransition*> transitions;
        for (const GrafcetTransition& t : m_grafcet.transitions())
            transitions.push_back(&t);
        std::sort(transitions.begin(), transitions.end(), [](auto a, auto b) { return a->number < b->number; });
        for (const GrafcetTransition* t : transitions)
            m_result.transitions.push_back(buildTransition(*t));
        assignTimers();
        collectVariables();
        m_result.maxEvolutions = static_cast<int>(m_result.transitions.size()) + 1;
        return std::move(m_result);
    }

private:
    // ---- problems ----

    // A variable the code declares under another name (unusableNameCode).
    // GG306 says which step's instance or function block took the name and
    // how to free it.
    std::string nameMessage(std::string_view code, const Variable& variable, const std::string& where) const
    {
        const std::string message = "in " + where + ": invalid variable name " + quoted(variable.name);
        return code == "GG306" ? message + ": " + m_scope.unusableNames.detail(variable.name) : message;
    }

    std::vector<std::string> nameArguments(std::string_view code, const Variable& variable,
                                           const std::string& where) const
    {
        if (code == "GG306")
            return m_scope.unusableNames.arguments(variable);
        return {m_scope.label, where, variable.name};
    }

    void problem(std::string code, std::string message, std::vector<std::string> arguments, int step, int transition,
                 int action, std::optional<Span> span)
    {
        ProgramProblem p;
        p.kind = ProgramProblem::Kind::Error;
        p.code = std::move(code);
        p.element = m_scope.element;
        p.message = std::move(message);
        p.arguments = std::move(arguments);
        p.nestedStep = step;
        p.nestedTransition = transition;
        p.actionIndex = action;
        p.span = span;
        m_problems.push_back(std::move(p));
    }

    std::string transitionLabel(int number) const
    {
        return "T" + std::to_string(number) + " of " + m_scope.label;
    }

    std::string actionLabel(int step, int index) const
    {
        return "action " + std::to_string(index + 1) + " of step " + std::to_string(step) + " of " + m_scope.label;
    }

    // An undeclared name as an undeclared action target: the GEMMA step, the
    // place, the name. Otherwise the excerpt and the English message, then
    // for a type error its data, as GG204 (the editor words it from them).
    std::vector<std::string> typeIssueArguments(const cond::TypeIssue& issue, const std::string& text,
                                                const std::string& where) const
    {
        if (issue.code == "GG203")
            return {m_scope.label, where, excerpt(text, issue.span)};
        std::vector<std::string> arguments{m_scope.label, where, excerpt(text, issue.span), issue.message};
        if (issue.error)
            cond::appendArguments(*issue.error, arguments);
        return arguments;
    }

    // What is wrong with an expression of the Nested context (type errors,
    // missing steps, undeclarable names, and in actions edges and durations).
    bool expressionUsable(const cond::Expression& expression, const std::string& text, bool inAction,
                          const std::string& where, int step, int transition, int action, bool mustBeBool = true)
    {
        const std::string typeCode = inAction ? "GG405" : "GG403";
        bool usable = true;
        for (cond::TypeIssue& issue : cond::typeCheck(expression, m_symbols, mustBeBool)) {
            const std::string code = issue.code == "GG410" ? "GG410" : typeCode;
            problem(code, "in " + where + ": " + issue.message, typeIssueArguments(issue, text, where), step,
                    transition, action, issue.span);
            usable = false;
        }
        for (cond::NodeKind kind : {cond::NodeKind::StepActivity, cond::NodeKind::StepDuration}) {
            for (int node : cond::nodesOfKind(expression, kind)) {
                const cond::Node& n = expression.at(node);
                if (m_grafcet.step(n.number))
                    continue;
                problem("GG406", "in " + where + ": " + n.text + " names step " + std::to_string(n.number)
                            + ", which " + m_scope.label + "'s GRAFCET does not have",
                        {m_scope.label, where, n.text, std::to_string(n.number)}, step, transition, action, n.span);
                usable = false;
            }
        }
        usable = durationsFit(expression, text, where, step, transition, action) && usable;
        if (usable)
            usable = divisorsNotZero(expression, text, where, step, transition, action);
        if (inAction) {
            std::vector<int> timeOrEdge = cond::edgeNodes(expression);
            for (int node : cond::nodesOfKind(expression, cond::NodeKind::StepDuration))
                timeOrEdge.push_back(node);
            for (int node : timeOrEdge) {
                const cond::Node& n = expression.at(node);
                problem("GG411", "in " + where + ": " + excerpt(text, n.span)
                            + " is for receptivities only: an action cannot read an edge or a step duration",
                        {m_scope.label, where, excerpt(text, n.span)}, step, transition, action, n.span);
                usable = false;
            }
        }
        for (int node : cond::variableNodes(expression)) {
            const Variable* variable = m_symbols.find(expression.at(node).text);
            if (const char* code = variable ? m_scope.unusableNames.code(variable->name) : nullptr) {
                problem(code, nameMessage(code, *variable, where), nameArguments(code, *variable, where), step,
                        transition, action, expression.at(node).span);
                usable = false;
            }
        }
        return usable;
    }

    // A TON preset is an IEC TIME, 32-bit milliseconds: a longer duration
    // cannot be written, and clamping it would make two different durations
    // one (both transitions would fire together on the PLC).
    bool durationsFit(const cond::Expression& expression, const std::string& text, const std::string& where, int step,
                      int transition, int action)
    {
        bool fit = true;
        for (int node : cond::nodesOfKind(expression, cond::NodeKind::StepDuration)) {
            const cond::Node& n = expression.at(node);
            if (n.durationMs <= cond::kMaxTimeMs)
                continue;
            const std::string longest = formatDuration(cond::kMaxTimeMs);
            problem("GG407", "in " + where + ": " + excerpt(text, n.span) + " is longer than " + longest
                        + ", the longest duration an IEC TIME (a TON preset) holds",
                    {m_scope.label, where, excerpt(text, n.span), longest}, step, transition, action, n.span);
            fit = false;
        }
        return fit;
    }

    // A constant zero divisor (GG408): the receptivity or action is unusable,
    // as a type error makes it (a divisor that reads a variable is only a
    // warning of the checks, GG409).
    bool divisorsNotZero(const cond::Expression& expression, const std::string& text, const std::string& where,
                         int step, int transition, int action)
    {
        bool none = true;
        for (const cond::DivisionByZeroRisk& risk : cond::divisionsByZero(expression)) {
            if (!risk.constantZero)
                continue;
            problem("GG408", "in " + where + ": " + cond::divisionByZeroMessage(risk, text),
                    {m_scope.label, where, excerpt(text, risk.span), excerpt(text, risk.divisorSpan)}, step, transition,
                    action, risk.span);
            none = false;
        }
        return none;
    }

    // ---- steps and actions ----

    NestedStep buildStep(const GrafcetStep& source)
    {
        NestedStep step;
        step.number = source.number;
        step.initial = source.initial;
        step.comment = source.comment;
        for (std::size_t i = 0; i < source.actions.size(); ++i) {
            NestedAction action = buildAction(source.number, static_cast<int>(i), source.actions[i]);
            switch (action.timing) {
            case ActionTiming::Continuous: step.continuous.push_back(std::move(action)); break;
            case ActionTiming::OnActivation: step.onActivation.push_back(std::move(action)); break;
            case ActionTiming::OnDeactivation: step.onDeactivation.push_back(std::move(action)); break;
            }
        }
        return step;
    }

    NestedAction buildAction(int stepNumber, int index, const GrafcetAction& source)
    {
        NestedAction action;
        action.timing = source.timing;
        action.index = index;
        action.text = source.text;
        action.parsed = cond::parseAction(source.text);
        const std::string where = actionLabel(stepNumber, index);
        if (!action.parsed.ok()) {
            const cond::ParseError& error = *action.parsed.error;
            std::vector<std::string> arguments{m_scope.label, where, excerpt(source.text, error.span), error.message};
            cond::appendArguments(error, arguments);
            problem("GG404", "syntax error in " + where + ": " + error.message, std::move(arguments), stepNumber, 0,
                    index, error.span);
            return action;
        }
        const cond::ActionSyntax& syntax = action.parsed.action;
        const bool continuous = source.timing == ActionTiming::Continuous;
        if (continuous != (syntax.form == cond::ActionForm::Continuous)) {
            const std::string why = continuous ? "a continuous action is N V or V IF <condition>"
                                               : "a stored action is S V, R V or V := <expression>";
            problem("GG405", "in " + where + ": " + why, {m_scope.label, where, why}, stepNumber, 0, index, std::nullopt);
            return action;
        }
        action.targetIsComplete = syntax.targetIsComplete;
        action.usable = targetUsable(action, stepNumber, index, where);
        if (!syntax.condition.empty())
            action.usable = expressionUsable(syntax.condition, source.text, true, where, stepNumber, 0, index)
                && action.usable;
        // The value is checked against the target only when the target is one
        // (an undeclared target has no type to fit: its own problem says so).
        if (!syntax.value.empty())
            action.usable = expressionUsable(syntax.value, source.text, true, where, stepNumber, 0, index, false)
                && action.usable && valueFits(action, stepNumber, index, where);
        return action;
    }

    bool targetUsable(NestedAction& action, int stepNumber, int index, const std::string& where)
    {
        const cond::ActionSyntax& syntax = action.parsed.action;
        const Span span = syntax.targetSpan;
        if (syntax.targetIsComplete) {
            action.target = "Complete";
            return true;
        }
        const Variable* variable = m_symbols.find(syntax.target);
        if (!variable) {
            problem("GG405", "in " + where + ": " + quoted(syntax.target) + " is not a declared variable",
                    {m_scope.label, where, syntax.target}, stepNumber, 0, index, span);
            return false;
        }
        action.target = variable->name;
        if (const char* code = m_scope.unusableNames.code(variable->name)) {
            problem(code, nameMessage(code, *variable, where), nameArguments(code, *variable, where), stepNumber, 0,
                    index, span);
            return false;
        }
        if (variable->kind == VariableKind::Input) {
            problem("GG413", "in " + where + ": " + quoted(variable->name)
                        + " is an input: it is read from the machine, actions never write it",
                    {m_scope.label, where, variable->name}, stepNumber, 0, index, span);
            return false;
        }
        const bool needsBool = syntax.form != cond::ActionForm::Assign;
        if (needsBool && variable->type != IecType::Bool) {
            const std::string code = syntax.form == cond::ActionForm::Continuous ? "GG414" : "GG405";
            problem(code, "in " + where + ": " + quoted(variable->name) + " is "
                        + std::string(iecTypeName(variable->type)) + "; this action needs a BOOL variable",
                    {m_scope.label, where, variable->name, std::string(iecTypeName(variable->type))}, stepNumber, 0, index,
                    span);
            return false;
        }
        return true;
    }

    // V := <value>: BOOL to BOOL, integers to integer types, numbers to REAL.
    bool valueFits(const NestedAction& action, int stepNumber, int index, const std::string& where)
    {
        const cond::ActionSyntax& syntax = action.parsed.action;
        const cond::ValueKind kind = cond::valueKind(syntax.value, syntax.value.root, m_symbols);
        const Variable* target = syntax.targetIsComplete ? nullptr : m_symbols.find(syntax.target);
        const IecType type = target ? target->type : IecType::Bool;
        bool fits = false;
        if (type == IecType::Bool)
            fits = kind == cond::ValueKind::Bool;
        else if (isRealType(type))
            fits = kind == cond::ValueKind::Integer || kind == cond::ValueKind::Real;
        else
            fits = kind == cond::ValueKind::Integer;
        if (fits)
            return true;
        const std::string typeName(iecTypeName(type));
        const std::string value = excerpt(action.text, syntax.value.rootNode().span);
        const std::string written = syntax.targetIsComplete ? action.target : quoted(action.target);
        problem("GG405",
                "in " + where + ": " + value + " is " + kindText(kind) + ", not " + article(typeName) + " " + typeName
                    + " value: it cannot be assigned to " + written + " (" + typeName + ")",
                {m_scope.label, where, action.target, typeName, value}, stepNumber, 0, index,
                syntax.value.rootNode().span);
        return false;
    }

    static std::string kindText(cond::ValueKind kind)
    {
        switch (kind) {
        case cond::ValueKind::Bool: return "a BOOL value";
        case cond::ValueKind::Integer: return "an integer";
        case cond::ValueKind::Real: return "a real number";
        case cond::ValueKind::Unknown: break;
        }
        return "of no known type";
    }

    // "an INT", "a UINT": as the names are spoken.
    static std::string article(std::string_view typeName)
    {
        return typeName == "INT" || typeName == "SINT" || typeName == "LINT" || typeName == "LREAL" ? "an" : "a";
    }

    // ---- continuous outputs ----

    void collectOutputs()
    {
        std::vector<ContinuousOutput> outputs;
        for (const NestedStep& step : m_result.steps) {
            for (std::size_t i = 0; i < step.continuous.size(); ++i) {
                const NestedAction& action = step.continuous[i];
                if (!action.usable)
                    continue;
                auto found = std::find_if(outputs.begin(), outputs.end(), [&](const ContinuousOutput& o) {
                    return equalsIgnoreCase(o.variable, action.target);
                });
                if (found == outputs.end()) {
                    outputs.push_back({action.target, action.targetIsComplete, {}});
                    found = outputs.end() - 1;
                }
                found->drivers.push_back({step.number, static_cast<int>(i)});
            }
        }
        // Each output's rank is looked up once, not in every comparison; the
        // sort sees the same comparisons, so the order is the same.
        std::vector<std::pair<std::size_t, ContinuousOutput>> ranked;
        ranked.reserve(outputs.size());
        for (ContinuousOutput& output : outputs)
            ranked.emplace_back(output.isComplete ? m_scope.variables.size() : indexOf(output.variable), std::move(output));
        std::sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        m_result.outputs.clear();
        for (auto& entry : ranked)
            m_result.outputs.push_back(std::move(entry.second));
    }

    // Spec §4.2 (4): the value of such a condition would depend on the
    // order of the statements that compute the outputs.
    void rejectConditionsOnOwnOutputs()
    {
        for (NestedStep& step : m_result.steps) {
            for (NestedAction& action : step.continuous) {
                if (!action.usable || action.parsed.action.condition.empty())
                    continue;
                const cond::Expression& condition = action.parsed.action.condition;
                for (int node : cond::variableNodes(condition)) {
                    const std::string& name = condition.at(node).text;
                    if (!m_result.output(name))
                        continue;
                    const std::string where = actionLabel(step.number, action.index);
                    problem("GG421", "in " + where + ": the condition reads " + quoted(name)
                                + ", a continuous output of the same GRAFCET",
                            {m_scope.label, where, name}, step.number, 0, action.index, condition.at(node).span);
                    action.usable = false;
                    break;
                }
            }
        }
        collectOutputs(); // without the actions just refused
    }

    // ---- transitions ----

    NestedTransition buildTransition(const GrafcetTransition& source)
    {
        NestedTransition transition;
        transition.number = source.number;
        transition.upstream = source.upstream;
        transition.downstream = source.downstream;
        transition.text = source.receptivity;
        transition.receptivity = cond::parse(source.receptivity, cond::kNestedOptions);
        const std::string where = "the receptivity of " + transitionLabel(source.number);
        if (isBlank(source.receptivity)) {
            problem("GG402", where + " is empty: write TRUE for a transition that is always ready", {m_scope.label, where},
                    0, source.number, -1, std::nullopt);
            return transition;
        }
        if (!transition.receptivity.ok()) {
            const cond::ParseError& error = *transition.receptivity.error;
            std::vector<std::string> arguments{m_scope.label, where, excerpt(source.receptivity, error.span), error.message};
            cond::appendArguments(error, arguments);
            problem("GG401", "syntax error in " + where + ": " + error.message, std::move(arguments), 0, source.number,
                    -1, error.span);
            return transition;
        }
        transition.usable = expressionUsable(transition.receptivity.expression, source.receptivity, false, where, 0,
                                             source.number, -1);
        return transition;
    }

    // One TON per step and duration, by step then duration.
    void assignTimers()
    {
        std::set<std::pair<int, std::int64_t>> wanted;
        for (const NestedTransition& t : m_result.transitions) {
            if (!t.usable)
                continue;
            for (int node : cond::nodesOfKind(t.receptivity.expression, cond::NodeKind::StepDuration)) {
                const cond::Node& n = t.receptivity.expression.at(node);
                wanted.insert({n.number, n.durationMs});
            }
        }
        for (const auto& [step, duration] : wanted)
            m_result.timers.push_back({step, duration, timerName(step, duration)});
        for (NestedTransition& t : m_result.transitions) {
            if (!t.usable)
                continue;
            for (int node : cond::nodesOfKind(t.receptivity.expression, cond::NodeKind::StepDuration)) {
                const cond::Node& n = t.receptivity.expression.at(node);
                const auto at = std::distance(wanted.begin(), wanted.find({n.number, n.durationMs}));
                t.timerOfNode[node] = static_cast<int>(at);
            }
        }
        for (std::size_t i = 0; i < m_result.timers.size(); ++i) {
            for (NestedStep& step : m_result.steps) {
                if (step.number == m_result.timers[i].step)
                    step.timers.push_back(static_cast<int>(i));
            }
        }
    }

    // ---- what the FB reads and writes ----

    // The declaration index of a variable (the symbol table's lookup, not
    // the model's linear one: the builder asks for every operand), or the
    // number of variables when none has this name.
    std::size_t indexOf(std::string_view name) const
    {
        const Variable* variable = m_symbols.find(name);
        return variable ? static_cast<std::size_t>(variable - m_scope.variables.data()) : m_scope.variables.size();
    }

    void collectVariables()
    {
        std::vector<bool> read(m_scope.variables.size(), false);
        std::vector<bool> stored(m_scope.variables.size(), false);
        const auto markRead = [&](const cond::Expression& expression) {
            for (int node : cond::variableNodes(expression)) {
                if (const std::size_t index = indexOf(expression.at(node).text); index < read.size())
                    read[index] = true;
            }
        };
        for (const NestedTransition& t : m_result.transitions) {
            if (t.usable)
                markRead(t.receptivity.expression);
        }
        for (const NestedStep& step : m_result.steps) {
            for (const auto* list : {&step.continuous, &step.onActivation, &step.onDeactivation}) {
                for (const NestedAction& action : *list) {
                    if (!action.usable)
                        continue;
                    markRead(action.parsed.action.condition);
                    markRead(action.parsed.action.value);
                    m_result.writesComplete = m_result.writesComplete || action.targetIsComplete;
                    if (action.timing != ActionTiming::Continuous && !action.targetIsComplete)
                        if (const std::size_t index = indexOf(action.target); index < stored.size())
                            stored[index] = true;
                }
            }
        }
        for (std::size_t i = 0; i < read.size(); ++i) {
            if (read[i])
                m_result.readVariables.push_back(m_scope.variables[i].name);
            if (stored[i])
                m_result.storedTargets.push_back(m_scope.variables[i].name);
        }
    }

    const NestedScope& m_scope;
    const Grafcet& m_grafcet;
    const SymbolTable& m_symbols;
    std::vector<ProgramProblem>& m_problems;
    NestedGrafcet m_result;
};

} // namespace

const NestedStep* NestedGrafcet::step(int number) const
{
    for (const NestedStep& s : steps) {
        if (s.number == number)
            return &s;
    }
    return nullptr;
}

const NestedTransition* NestedGrafcet::transition(int number) const
{
    for (const NestedTransition& t : transitions) {
        if (t.number == number)
            return &t;
    }
    return nullptr;
}

const ContinuousOutput* NestedGrafcet::output(std::string_view variable) const
{
    for (const ContinuousOutput& o : outputs) {
        if (equalsIgnoreCase(o.variable, variable))
            return &o;
    }
    return nullptr;
}

NestedGrafcet buildNestedGrafcet(const Model& model, const NestedScope& scope, const Grafcet& grafcet,
                                 std::vector<ProgramProblem>& problems)
{
    return NestedBuilder(model, scope, grafcet, problems).build();
}

std::string stepActivityName(int step)
{
    return "X" + std::to_string(step);
}

std::string timerName(int step, std::int64_t durationMs)
{
    return "GG_T" + std::to_string(step) + "_" + std::to_string(durationMs) + "ms";
}

std::string fireFlagName(int transition)
{
    return "GG_Fire" + std::to_string(transition);
}

std::string edgeMemoryName(const std::string& variable)
{
    return variable + "_PREV";
}

} // namespace core
