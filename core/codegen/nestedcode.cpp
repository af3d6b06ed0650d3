#include "core/codegen/nestedcode.h"

#include "core/templates/gemma/gemmaprogram.h"
#include "core/codegen/stgenerator.h"
#include "core/condition/conditionanalysis.h"
#include "core/model/model.h"

#include <algorithm>
#include <limits>
#include <map>
#include <set>

namespace core {

namespace {

std::string comment(std::string_view text)
{
    return "(* " + escapeComment(std::string(text)) + " *)";
}

// Timers exist for usable receptivities only, whose durations fit TIME (GG407).
std::string duration(std::int64_t milliseconds)
{
    return formatDuration(milliseconds);
}

std::string leftFlag(int step)
{
    return "GG_Left" + std::to_string(step);
}

std::string enteredFlag(int step)
{
    return "GG_Entered" + std::to_string(step);
}

constexpr std::string_view kEvolution = "GG_Evolution";
constexpr std::string_view kFired = "GG_Fired";

class NestedWriter {
public:
    NestedWriter(const NestedCodeSource& source, const std::function<std::string(std::string_view)>& global,
                 const std::function<std::string(std::string_view)>& edgeMemory)
        : m_source(source)
        , m_grafcet(source.grafcet)
        , m_global(global)
        , m_edgeMemory(edgeMemory)
        , m_untilStable(source.evolution == EvolutionRule::UntilStable)
    {
        // Which usable transitions deactivate and activate each step, once:
        // every step asks for both.
        for (const NestedTransition& t : m_grafcet.transitions) {
            if (!t.usable)
                continue;
            for (int step : t.upstream)
                m_deactivatedBy[step].push_back(t.number);
            for (int step : t.downstream)
                m_activatedBy[step].push_back(t.number);
        }
    }

    NestedCode run()
    {
        declare();
        writeProblems();
        line(0, "IF Initialization THEN");
        writeInitialization();
        const std::string evolving = evolvingCall();
        if (!evolving.empty()) {
            line(0, "ELSE");
            m_code.body += evolving;
        }
        line(0, "END_IF;");
        writeContinuousOutputs();
        return std::move(m_code);
    }

private:
    void line(int indent, std::string_view text) { append(m_code.body, indent, text); }

    static void append(std::string& out, int indent, std::string_view text)
    {
        out.append(static_cast<std::size_t>(indent), ' ');
        out.append(text);
        out.push_back('\n');
    }

    // ---- declarations ----

    void declare()
    {
        for (const ContinuousOutput& output : m_grafcet.outputs) {
            if (!output.isComplete)
                m_code.outputs.push_back({output.variable, "BOOL", {}, "continuous action of " + std::string(m_source.label)});
        }
        if (m_untilStable)
            m_code.outputs.push_back({std::string(kUnstableName), "BOOL", {},
                                      "the last evolution allowed in this call still fired"});
        for (const NestedStep& s : m_grafcet.steps)
            m_code.locals.push_back({stepActivityName(s.number), "BOOL", "FALSE",
                                     "step " + std::to_string(s.number) + (s.comment.empty() ? "" : ": " + s.comment)});
        for (const NestedTimer& timer : m_grafcet.timers)
            m_code.locals.push_back({timer.name, "TON", {}, duration(timer.durationMs) + "/X" + std::to_string(timer.step)});
        for (const NestedTransition& t : m_grafcet.transitions) {
            if (t.usable)
                m_code.locals.push_back({fireFlagName(t.number), "BOOL", "FALSE", "T" + std::to_string(t.number) + " fires"});
        }
        for (const NestedStep& s : m_grafcet.steps) {
            if (!deactivatedBy(s.number).empty())
                m_code.locals.push_back({leftFlag(s.number), "BOOL", "FALSE", {}});
            if (!activatedBy(s.number).empty())
                m_code.locals.push_back({enteredFlag(s.number), "BOOL", "FALSE", {}});
        }
        if (m_untilStable) {
            m_code.locals.push_back({std::string(kEvolution), "INT", "0", "evolutions in this call"});
            m_code.locals.push_back({std::string(kFired), "BOOL", "FALSE", "a transition fired in the last evolution"});
        }
        for (const std::string& name : m_source.edgeVariables)
            if (readsEdgeOf(name))
                m_code.edgeMemories.push_back({edgeMemoryName(name), "BOOL", {}, {}});
    }

    bool readsEdgeOf(const std::string& name) const
    {
        for (const NestedTransition& t : m_grafcet.transitions) {
            if (!t.usable)
                continue;
            for (int node : cond::edgeNodes(t.receptivity.expression)) {
                const cond::Node& operand = t.receptivity.expression.at(t.receptivity.expression.at(node).operand);
                if (equalsIgnoreCase(operand.text, name))
                    return true;
            }
        }
        return false;
    }

    void writeProblems()
    {
        for (const ProgramProblem& problem : m_source.problems) {
            if (problem.element != m_source.element || (problem.nestedStep == 0 && problem.nestedTransition == 0))
                continue;
            line(0, comment("ERROR " + problem.code + ": " + problem.message + " (not generated)"));
        }
    }

    // ---- the structure ----

    // References, not copies: the writer asks for them several times per step.
    const std::vector<int>& deactivatedBy(int step) const { return firesOf(m_deactivatedBy, step); }
    const std::vector<int>& activatedBy(int step) const { return firesOf(m_activatedBy, step); }

    static const std::vector<int>& firesOf(const std::map<int, std::vector<int>>& fires, int step)
    {
        static const std::vector<int> none;
        const auto found = fires.find(step);
        return found == fires.end() ? none : found->second;
    }

    static std::string anyOf(const std::vector<int>& transitions)
    {
        std::string text;
        for (int t : transitions)
            text += (text.empty() ? "" : " OR ") + fireFlagName(t);
        return text;
    }

    // ---- expressions ----

    // A variable as this FB reads it: its own continuous outputs are its
    // VAR_OUTPUTs (the previous call's value, spec §4.2 (4)).
    std::string variable(std::string_view name) const
    {
        if (const ContinuousOutput* output = m_grafcet.output(name); output && !output->isComplete)
            return output->variable;
        return m_global(name);
    }

    std::string print(const cond::Expression& expression, const std::map<int, int>* timers = nullptr) const
    {
        cond::PrintOptions options;
        options.variableName = [this](const cond::Node& node) { return variable(node.text); };
        for (int node : cond::edgeNodes(expression)) {
            const cond::Node& edge = expression.at(node);
            const std::string name = expression.at(edge.operand).text;
            const std::string now = variable(name);
            const std::string before = m_edgeMemory(name);
            std::string text = edge.unaryOp == cond::UnaryOp::RisingEdge ? now + " AND NOT " + before
                                                                          : "NOT " + now + " AND " + before;
            if (m_untilStable)
                text += " AND " + std::string(kEvolution) + " = 0"; // edges hold in the first evolution only
            options.substitutions[node] = "(" + text + ")";
        }
        if (timers) {
            for (const auto& [node, index] : *timers) {
                const NestedTimer& timer = m_grafcet.timers[static_cast<std::size_t>(index)];
                options.substitutions[node] = "(" + stepActivityName(timer.step) + " AND " + timer.name + ".Q)";
            }
        }
        return cond::print(expression, options);
    }

    std::string target(const NestedAction& action) const
    {
        return action.targetIsComplete ? std::string("Complete") : m_global(action.target);
    }

    std::string storedStatement(const NestedAction& action) const
    {
        const cond::ActionSyntax& syntax = action.parsed.action;
        switch (syntax.form) {
        case cond::ActionForm::Set: return target(action) + " := TRUE;";
        case cond::ActionForm::Reset: return target(action) + " := FALSE;";
        case cond::ActionForm::Assign: return target(action) + " := " + print(syntax.value) + ";";
        case cond::ActionForm::Continuous: break;
        }
        return {};
    }

    void writeStoredActions(std::string& out, int indent, const std::vector<NestedAction>& actions) const
    {
        for (const NestedAction& action : actions) {
            if (action.usable)
                append(out, indent, storedStatement(action));
        }
    }

    void writeTimerResets(std::string& out, int indent, const NestedStep& step) const
    {
        for (int index : step.timers) {
            const NestedTimer& timer = m_grafcet.timers[static_cast<std::size_t>(index)];
            append(out, indent, timer.name + "(IN := FALSE, PT := " + duration(timer.durationMs) + ");");
        }
    }

    // ---- the calls ----

    void writeInitialization()
    {
        for (const NestedStep& s : m_grafcet.steps)
            line(4, stepActivityName(s.number) + " := " + (s.initial ? "TRUE;" : "FALSE;"));
        line(4, "Complete := FALSE;");
        if (m_untilStable)
            line(4, std::string(kUnstableName) + " := FALSE;");
        for (const NestedTimer& timer : m_grafcet.timers)
            line(4, timer.name + "(IN := FALSE, PT := " + duration(timer.durationMs) + ");");
        for (const NestedStep& s : m_grafcet.steps) {
            if (s.initial)
                writeStoredActions(m_code.body, 4, s.onActivation);
        }
    }

    std::string evolvingCall() const
    {
        std::string out;
        for (const NestedTimer& timer : m_grafcet.timers)
            append(out, 4, timer.name + "(IN := " + stepActivityName(timer.step) + ", PT := " + duration(timer.durationMs)
                               + ");");
        const std::string evolution = evolutionStatements(m_untilStable ? 8 : 4);
        if (evolution.empty())
            return out;
        if (!m_untilStable)
            return out + evolution;
        append(out, 4, std::string(kEvolution) + " := 0;");
        append(out, 4, "REPEAT");
        out += evolution;
        append(out, 8, std::string(kEvolution) + " := " + std::string(kEvolution) + " + 1;");
        append(out, 4, "UNTIL NOT " + std::string(kFired) + " OR " + std::string(kEvolution)
                           + " >= " + std::to_string(m_grafcet.maxEvolutions));
        append(out, 4, "END_REPEAT;");
        append(out, 4, std::string(kUnstableName) + " := " + std::string(kFired) + ";");
        return out;
    }

    // One evolution (IEC 60848 rules 2-5): every fireable transition fires,
    // on the situation before any of them.
    std::string evolutionStatements(int indent) const
    {
        std::string out;
        std::vector<int> fires;
        for (const NestedTransition& t : m_grafcet.transitions) {
            if (!t.usable)
                continue;
            fires.push_back(t.number);
            std::string enabled;
            for (int step : t.upstream)
                enabled += stepActivityName(step) + " AND ";
            std::string receptivity = print(t.receptivity.expression, &t.timerOfNode);
            if (cond::needsParenthesesBeforeAnd(t.receptivity.expression))
                receptivity = "(" + receptivity + ")";
            append(out, indent, fireFlagName(t.number) + " := " + enabled + receptivity + ";");
        }
        if (fires.empty())
            return m_untilStable ? std::string(static_cast<std::size_t>(indent), ' ') + std::string(kFired) + " := FALSE;\n"
                                 : std::string();
        if (m_untilStable)
            append(out, indent, std::string(kFired) + " := " + anyOf(fires) + ";");
        writeSituationChange(out, indent);
        return out;
    }

    void writeSituationChange(std::string& out, int indent) const
    {
        for (const NestedStep& s : m_grafcet.steps) {
            const std::vector<int>& leaving = deactivatedBy(s.number);
            const std::vector<int>& entering = activatedBy(s.number);
            const std::string x = stepActivityName(s.number);
            if (!leaving.empty())
                append(out, indent, leftFlag(s.number) + " := " + (entering.empty() ? "(" + anyOf(leaving) + ")"
                    : "(" + anyOf(leaving) + ") AND NOT (" + anyOf(entering) + ")") + ";");
            if (!entering.empty())
                append(out, indent, enteredFlag(s.number) + " := (" + anyOf(entering) + ") AND NOT " + x + ";");
        }
        for (const NestedStep& s : m_grafcet.steps) {
            const std::string x = stepActivityName(s.number);
            if (!deactivatedBy(s.number).empty())
                append(out, indent, x + " := " + x + " AND NOT " + leftFlag(s.number) + ";");
            if (!activatedBy(s.number).empty())
                append(out, indent, x + " := " + x + " OR " + enteredFlag(s.number) + ";");
        }
        for (const NestedStep& s : m_grafcet.steps)
            writeGuarded(out, indent, leftFlag(s.number), s.onDeactivation, nullptr,
                         !deactivatedBy(s.number).empty());
        for (const NestedStep& s : m_grafcet.steps)
            writeGuarded(out, indent, enteredFlag(s.number), s.onActivation, &s, !activatedBy(s.number).empty());
    }

    // IF flag THEN actions (and, for an entered step, its TONs reset) END_IF.
    void writeGuarded(std::string& out, int indent, const std::string& flag, const std::vector<NestedAction>& actions,
                      const NestedStep* entered, bool flagExists) const
    {
        if (!flagExists)
            return;
        std::string inner;
        writeStoredActions(inner, indent + 4, actions);
        if (entered)
            writeTimerResets(inner, indent + 4, *entered);
        if (inner.empty())
            return;
        append(out, indent, "IF " + flag + " THEN");
        out += inner;
        append(out, indent, "END_IF;");
    }

    // Spec §4.2 (3): once per call, on the situation it ends with.
    void writeContinuousOutputs()
    {
        for (const ContinuousOutput& output : m_grafcet.outputs) {
            std::string value;
            for (const ContinuousOutput::Driver& driver : output.drivers) {
                const NestedStep& s = *m_grafcet.step(driver.step);
                const NestedAction& action = s.continuous[static_cast<std::size_t>(driver.action)];
                std::string term = stepActivityName(driver.step);
                const cond::Expression& condition = action.parsed.action.condition;
                if (!condition.empty())
                    term = "(" + term + " AND (" + print(condition) + "))";
                value += (value.empty() ? "" : " OR ") + term;
            }
            line(0, (output.isComplete ? std::string("Complete") : output.variable) + " := " + value + ";");
        }
    }

    const NestedCodeSource& m_source;
    const NestedGrafcet& m_grafcet;
    const std::function<std::string(std::string_view)>& m_global;
    const std::function<std::string(std::string_view)>& m_edgeMemory;
    bool m_untilStable;
    std::map<int, std::vector<int>> m_deactivatedBy; // step -> usable transitions, in transition order
    std::map<int, std::vector<int>> m_activatedBy;
    NestedCode m_code;
};

} // namespace

NestedCode generateNestedCode(const NestedCodeSource& source,
                              const std::function<std::string(std::string_view)>& global,
                              const std::function<std::string(std::string_view)>& edgeMemory)
{
    return NestedWriter(source, global, edgeMemory).run();
}

NestedCode generateNestedCode(const GemmaStep& step, const GemmaProgram& program,
                              const std::function<std::string(std::string_view)>& global,
                              const std::function<std::string(std::string_view)>& edgeMemory)
{
    const NestedCodeSource source{*step.nested, step.id, step.id, program.evolution, program.edgeVariables,
                                  program.problems};
    return generateNestedCode(source, global, edgeMemory);
}

} // namespace core
