// The PROGRAM as spec packml.md §6.2-§6.4 writes it, character for
// character where the spec gives the text (tests/core/data/packml-capper.st).
// Every statement of a transition stands on its IF/ELSIF line, as the spec's
// examples do, so a state's branch reads as its table of transitions.
//
// An unusable command or request condition is FALSE, with its problems as
// `(* ERROR ... *)` comments above the call of its R_TRIG, as GEMMA does for
// a transition's condition.

#include "core/templates/packml/packmlprogrampou.h"

#include "core/codegen/stgenerator.h"
#include "core/condition/conditionanalysis.h"
#include "core/model/iectypes.h"
#include "core/templates/packml/packmlcodenaming.h"
#include "core/templates/packml/packtags.h"

#include <algorithm>

namespace core::packml {

namespace {

std::string comment(std::string_view text)
{
    return "(* " + escapeComment(std::string(text)) + " *)";
}

std::string number(State state)
{
    return std::to_string(static_cast<int>(state));
}

std::string number(Command command)
{
    return std::to_string(static_cast<int>(command));
}

class BodyWriter {
public:
    BodyWriter(const PackmlProgram& program, PackmlNaming& naming)
        : m_program(program)
        , m_naming(naming)
    {
    }

    std::string write()
    {
        writeCommands();
        writeModeManager();
        writeStateMachine();
        writeContinuousOutputs();
        writeStatus();
        writeEdgeMemories();
        return std::move(m_text);
    }

private:
    void line(int indent, std::string_view text)
    {
        m_text.append(static_cast<std::size_t>(indent), ' ');
        m_text.append(text);
        m_text.push_back('\n');
    }

    void writeProblems(const std::string& element)
    {
        for (const ProgramProblem& problem : m_program.problems) {
            if (problem.element != element)
                continue;
            std::string text = problem.kind == ProgramProblem::Kind::Error ? "ERROR" : "WARNING";
            if (!problem.code.empty())
                text += " " + problem.code;
            line(0, comment(text + ": " + problem.message));
        }
    }

    std::string condition(const ProgramCondition& condition)
    {
        if (!condition.usable)
            return "FALSE";
        cond::PrintOptions options;
        options.variableName = [this](const cond::Node& node) { return m_naming.global(node.text); };
        const std::string text = cond::print(condition.parsed.expression, options);
        return cond::needsParenthesesBeforeAnd(condition.parsed.expression, options) ? "(" + text + ")" : text;
    }

    // ---- 1. Commands ----

    void writeCommands()
    {
        line(0, comment("1. Commands: rising edge of each command condition, or CntrlCmd at a rising edge of "
                        "CmdChangeRequest"));
        line(0, "Trig_CmdChange(CLK := " + m_naming.global("CmdChangeRequest") + ");");
        const std::string cntrlCmd = m_naming.global("CntrlCmd");
        for (const ProgramCommand& command : m_program.commands) {
            writeProblems(command.name);
            if (command.condition.text.find_first_not_of(" \t\r\n") == std::string::npos)
                line(0, comment("ERROR GG202: the condition of the " + command.name
                                + " command is empty: write FALSE for a command that comes only through CntrlCmd"));
            line(0, "Trig_" + command.name + "(CLK := " + condition(command.condition) + ");");
            line(0, "Ev_" + command.name + " := Trig_" + command.name + ".Q OR (Trig_CmdChange.Q AND " + cntrlCmd
                        + " = " + number(command.command) + ");");
        }
    }

    // ---- 2. Unit mode manager ----

    void writeModeManager()
    {
        line(0, comment("2. Unit mode manager"));
        line(0, "Trig_ModeChange(CLK := " + m_naming.global("UnitModeChangeRequest") + ");");
        for (const ProgramMode& mode : m_program.modes) {
            if (!mode.requestGenerated)
                continue;
            writeProblems(std::to_string(mode.number));
            line(0, "Trig_" + mode.name + "(CLK := " + condition(mode.request) + ");");
        }
        bool anyGrant = false;
        for (const ProgramMode& mode : m_program.modes)
            anyGrant = anyGrant || !mode.grants.empty();
        if (!anyGrant) {
            line(0, comment("no mode change is possible"));
            return;
        }
        line(0, "CASE Mode OF");
        for (const ProgramMode& mode : m_program.modes)
            writeGrants(mode);
        line(0, "END_CASE;");
    }

    // Written in place: 31 modes make 930 grants.
    void writeGrants(const ProgramMode& mode)
    {
        if (mode.grants.empty())
            return;
        line(0, std::to_string(mode.number) + ": " + comment(mode.name));
        const std::string unitMode = m_naming.global("UnitMode");
        bool first = true;
        for (const ModeGrant& grant : mode.grants) {
            const ProgramMode& target = *m_program.mode(grant.targetMode);
            const std::string targetNumber = std::to_string(grant.targetMode);
            m_text.append(first ? "    IF " : "    ELSIF ");
            if (target.requestGenerated)
                m_text += '(';
            m_text.append("(Trig_ModeChange.Q AND ").append(unitMode).append(" = ").append(targetNumber).append(")");
            if (target.requestGenerated)
                m_text.append(" OR Trig_").append(target.name).append(".Q)");
            m_text.append(" AND ");
            appendStatesCondition(grant.states);
            m_text.append(" THEN Mode := ").append(targetNumber).append("; Entry := TRUE; Resume := FALSE;\n");
            first = false;
        }
        line(4, "END_IF;");
    }

    void appendStatesCondition(const StateSet& states)
    {
        const bool several = states.size() != 1;
        if (several)
            m_text += '(';
        bool first = true;
        for (const State state : states.list()) {
            if (!first)
                m_text.append(" OR ");
            first = false;
            m_text.append("State = ").append(number(state));
        }
        if (several)
            m_text += ')';
    }

    // ---- 3. State machine ----

    void writeStateMachine()
    {
        line(0, comment("3. State machine of the current unit mode"));
        line(0, "CASE Mode OF");
        for (const ProgramMode& mode : m_program.modes) {
            line(0, std::to_string(mode.number) + ": " + comment(mode.name));
            line(4, "CASE State OF");
            for (const ProgramState& state : mode.states)
                writeState(state);
            line(4, "END_CASE;");
        }
        line(0, "END_CASE;");
    }

    const ProgramInstance* instanceOf(const ProgramState& state) const
    {
        return state.instance < 0 ? nullptr : &m_program.instances[static_cast<std::size_t>(state.instance)];
    }

    void writeState(const ProgramState& state)
    {
        line(4, number(state.state) + ": " + comment(stateName(state.state)));
        if (const ProgramInstance* instance = instanceOf(state))
            writeEntryBlock(state.state, instance->name);
        bool first = true;
        for (const ModeTransition& transition : state.transitions) {
            line(8, std::string(first ? "IF " : "ELSIF ") + transitionCondition(state, transition) + " THEN "
                        + transitionStatements(transition));
            first = false;
        }
        if (!first)
            line(8, "END_IF;");
    }

    // Spec §6.4: GEMMA's entry block; Execute resumes without the
    // Initialization call when it comes back from the Hold or Suspend loop.
    void writeEntryBlock(State state, const std::string& instance)
    {
        const std::string call = instance + "(Initialization := Entry);";
        if (state == State::Execute)
            line(8, "IF Entry THEN IF NOT Resume THEN " + call + " END_IF; Entry := FALSE; Resume := FALSE; END_IF;");
        else
            line(8, "IF Entry THEN " + call + " Entry := FALSE; END_IF;");
        line(8, call);
    }

    std::string transitionCondition(const ProgramState& state, const ModeTransition& transition) const
    {
        if (transition.transition.trigger == Trigger::StateComplete)
            return instanceOf(state)->name + ".Complete";
        return "Ev_" + std::string(commandName(transition.transition.command));
    }

    static std::string transitionStatements(const ModeTransition& transition)
    {
        const TemplateTransition& t = transition.transition;
        std::string text = "State := " + number(transition.destination.state) + "; Entry := TRUE;";
        switch (resumeEffect(transition)) {
        case ResumeEffect::Set: text += " Resume := TRUE;"; break;
        case ResumeEffect::Clear: text += " Resume := FALSE;"; break;
        case ResumeEffect::None: break;
        }
        const bool sc = t.trigger == Trigger::StateComplete;
        if (transition.destination.skipped)
            text += " " + comment(std::string(sc ? "SC: " : "") + std::string(stateName(*transition.destination.skipped))
                                  + " skipped");
        else if (sc)
            text += " " + comment("SC");
        return text;
    }

    // ---- 4. Continuous outputs ----

    // Which output of each own GRAFCET writes each user variable (Complete
    // excluded), looked up once per GRAFCET rather than once per instance:
    // the modes that run a procedure "same as" another share its GRAFCET.
    using OutputsBySlot = std::vector<const ContinuousOutput*>;

    std::vector<OutputsBySlot> outputsOfGrafcets(std::size_t userCount) const
    {
        std::vector<OutputsBySlot> result;
        result.reserve(m_program.grafcets.size());
        for (const ProgramGrafcet& grafcet : m_program.grafcets) {
            OutputsBySlot& bySlot = result.emplace_back(userCount, nullptr);
            if (grafcet.grafcet.outputs.empty())
                continue;
            for (std::size_t slot = 0; slot < userCount; ++slot) {
                const ContinuousOutput* output = grafcet.grafcet.output(m_program.variables[slot].name);
                if (output && !output->isComplete)
                    bySlot[slot] = output;
            }
        }
        return result;
    }

    // Each statement is written in place: section 4 of a large program is
    // most of its text.
    void writeContinuousOutputs()
    {
        bool any = false;
        const std::size_t userCount = m_program.variables.size() - packTags().size();
        const std::vector<OutputsBySlot> outputs = outputsOfGrafcets(userCount);
        for (std::size_t slot = 0; slot < userCount; ++slot) {
            if (!isDriven(slot, outputs))
                continue;
            if (!any)
                line(0, comment("4. Continuous outputs of the nested GRAFCETs: one writer each"));
            any = true;
            m_text.append(m_naming.global(m_program.variables[slot].name)).append(" := ");
            appendContinuousValue(slot, outputs);
            m_text.append(";\n");
        }
    }

    bool isDriven(std::size_t slot, const std::vector<OutputsBySlot>& outputs) const
    {
        return std::any_of(m_program.instances.begin(), m_program.instances.end(), [&](const ProgramInstance& instance) {
            return !instance.isSkeleton() && outputs[static_cast<std::size_t>(instance.grafcet)][slot] != nullptr;
        });
    }

    void appendContinuousValue(std::size_t slot, const std::vector<OutputsBySlot>& outputs)
    {
        bool first = true;
        for (const ProgramInstance& instance : m_program.instances) {
            if (instance.isSkeleton())
                continue;
            const ContinuousOutput* output = outputs[static_cast<std::size_t>(instance.grafcet)][slot];
            if (!output)
                continue;
            if (!first)
                m_text += " OR ";
            first = false;
            m_text.append("(Mode = ").append(std::to_string(instance.mode)).append(" AND State = ");
            m_text.append(number(instance.state)).append(" AND NOT Entry AND ").append(instance.name);
            m_text.append(".").append(output->variable).append(")");
        }
    }

    // ---- 5, 6 ----

    void writeStatus()
    {
        line(0, comment("5. PackTags status"));
        line(0, m_naming.global("StateCurrent") + " := State;");
        line(0, m_naming.global("UnitModeCurrent") + " := Mode;");
    }

    void writeEdgeMemories()
    {
        if (m_program.edgeVariables.empty())
            return;
        line(0, comment("6. Edge memories of the nested receptivities"));
        for (const std::string& name : m_program.edgeVariables)
            line(0, m_naming.edgeMemory(name) + " := " + m_naming.global(name) + ";");
    }

    const PackmlProgram& m_program;
    PackmlNaming& m_naming;
    std::string m_text;
};

PlcVariable local(std::string name, std::string typeName, std::string initialValue = {}, std::string note = {})
{
    return PlcVariable{std::move(name), std::move(typeName), std::move(initialValue), std::move(note)};
}

std::vector<PlcVariable> programLocals(const PackmlProgram& program)
{
    std::vector<PlcVariable> locals;
    locals.push_back(local("State", "DINT", number(program.initialState), "PackTags number of the current state"));
    locals.push_back(local("Mode", "DINT", std::to_string(program.initialMode), "current unit mode"));
    locals.push_back(local("Entry", "BOOL", "TRUE", "TRUE until the first scan of a state has run"));
    locals.push_back(local("Resume", "BOOL", "FALSE", "Execute left by Hold or Suspend: its next entry resumes it"));
    locals.push_back(local("Trig_CmdChange", "R_TRIG"));
    for (const ProgramCommand& command : program.commands)
        locals.push_back(local("Trig_" + command.name, "R_TRIG"));
    for (const ProgramCommand& command : program.commands)
        locals.push_back(local("Ev_" + command.name, "BOOL"));
    locals.push_back(local("Trig_ModeChange", "R_TRIG"));
    for (const ProgramMode& mode : program.modes)
        if (mode.requestGenerated)
            locals.push_back(local("Trig_" + mode.name, "R_TRIG"));
    for (const ProgramInstance& instance : program.instances)
        locals.push_back(local(instance.name, instance.typeName));
    return locals;
}

// Spec §6.2: the user variables it reads or writes, the six PackTags, the
// edge memories.
std::vector<PlcVariable> programExternals(const PackmlProgram& program, const std::vector<std::string>& declared,
                                          const PackmlNaming& naming)
{
    const std::size_t userCount = program.variables.size() - packTags().size();
    std::vector<PlcVariable> externals = naming.readUserVariables(userCount);
    for (std::size_t slot = userCount; slot < program.variables.size(); ++slot)
        externals.push_back(local(declared[slot], std::string(iecTypeName(program.variables[slot].type))));
    for (const std::string& name : program.edgeVariables)
        externals.push_back(local(edgeMemoryName(name), "BOOL"));
    return externals;
}

} // namespace

PlcPou buildPackmlProgramPou(const PackmlProgram& program, const std::vector<std::string>& declared, Dialect dialect)
{
    PlcPou pou;
    pou.name = program.programName;
    pou.kind = PouKind::Program;
    PackmlNaming naming(program, declared, dialect);
    pou.body = BodyWriter(program, naming).write();
    pou.locals = programLocals(program);
    if (dialect == Dialect::Iec)
        pou.externals = programExternals(program, declared, naming);
    return pou;
}

} // namespace core::packml
