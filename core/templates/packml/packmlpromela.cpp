#include "core/templates/packml/packmlpromela.h"

#include "core/model/iectypes.h"
#include "core/model/model.h"
#include "core/templates/packml/packmlpromelawriter.h"
#include "core/templates/packml/packmlrules.h"
#include "core/templates/packml/packmlvalues.h"
#include "core/verification/promela.h"

#include <algorithm>

namespace core::packml {

namespace promela {

namespace {

std::string number(State state)
{
    return std::to_string(static_cast<int>(state));
}

bool entersAbort(State state)
{
    return state == State::Aborting || state == State::Aborted;
}

} // namespace

Writer::Writer(const Model& model, const PackmlProgram& program)
    : m_model(model)
    , m_program(program)
    , m_choices(program, {})
    , m_reference(*model.packml())
    , m_names(program, model.settings().cycleTimeMs)
{
    m_cntrlCmd = program.slotOf("CntrlCmd");
    m_cmdChangeRequest = program.slotOf("CmdChangeRequest");
    m_unitMode = program.slotOf("UnitMode");
    m_unitModeChangeRequest = program.slotOf("UnitModeChangeRequest");
    for (const ProgramMode& mode : program.modes) {
        for (const ProgramState& state : mode.states)
            for (const ModeTransition& t : state.transitions) {
                std::vector<Command>& accepted = m_accepted[static_cast<std::size_t>(state.state)];
                if (t.transition.trigger == Trigger::Command
                    && std::find(accepted.begin(), accepted.end(), t.transition.command) == accepted.end())
                    accepted.push_back(t.transition.command);
            }
        for (const ModeGrant& grant : mode.grants)
            for (State state : grant.states.list())
                for (std::size_t r = 0; r < program.modes.size(); ++r)
                    if (program.modes[r].number == grant.targetMode)
                        addOnce(m_grantable[static_cast<std::size_t>(state)], static_cast<int>(r));
    }
    for (const ProgramGrafcet& g : program.grafcets) {
        m_maxTransitions = std::max(m_maxTransitions, g.grafcet.transitions.size());
        m_maxSteps = std::max(m_maxSteps, g.grafcet.steps.size());
        m_maxOutputs = std::max(m_maxOutputs, g.grafcet.outputs.size());
    }
}

PackmlPromela Writer::run()
{
    PackmlPromela result;
    try {
        for (int tag : {m_cntrlCmd, m_cmdChangeRequest, m_unitMode, m_unitModeChangeRequest})
            for (const ProgramGrafcet& g : m_program.grafcets)
                for (const std::string& name : g.grafcet.readVariables)
                    if (equalsIgnoreCase(name, m_program.variables[static_cast<std::size_t>(tag)].name))
                        throw Unsupported("a GRAFCET reads the PackTags request " + name);
        writeProcess();
        writeHeader();
        writeDeclarations();
    } catch (const Unsupported& why) {
        result.unsupported = why.what();
        return result;
    }
    const std::string& head = m_declarations.text();
    const int offset = static_cast<int>(std::count(head.begin(), head.end(), '\n'));
    result.text = head + m_process.text();
    result.markers = std::move(m_markers);
    for (PackmlMarker& m : result.markers)
        m.line += offset;
    return result;
}

void Writer::writeHeader()
{
    const std::string run = std::string(kSpinGenerate) + " FILE && " + kSpinCompile + " && " + kSpinRun;
    for (const std::string& text : std::vector<std::string>{
             "/*",
             " * The PackML program of \"" + comment(m_model.settings().name) + "\" as a Promela model for SPIN,",
             " * written by GG Studio (docs/packml.md, \"SPIN cross-check\").",
             " * One iteration of the do loop is one scan of the generated PROGRAM (spec §6.5);",
             " * inputs are chosen as the PackML verifier chooses them; TONs are counted in scans.",
             " *",
             " * Run:  " + run,
             " * Then read pan's list \"unreached in proctype scan\": a line that ends with",
             " * a marker comment is listed iff what the comment names never happens.",
             " */",
         })
        m_declarations.line(text);
}

void Writer::writeDeclarations()
{
    Lines& d = m_declarations;
    d.line("/* State, Mode, Entry, Resume and the R_TRIG memories */");
    d.line("byte gState = " + number(m_program.initialState) + ";");
    d.line("byte gMode = " + std::to_string(m_program.initialMode) + ";");
    d.line("bool gEntry = 1;");
    d.line("bool gResume = 0;");
    d.line("bool mCmd = 0; bool mMode = 0;");
    for (std::size_t i = 0; i < m_program.commands.size(); ++i)
        d.line("bool mc" + std::to_string(i) + " = 0; /* " + m_program.commands[i].name + " */");
    for (std::size_t r = 0; r < m_program.modes.size(); ++r)
        if (m_program.modes[r].requestGenerated)
            d.line("bool mr" + std::to_string(r) + " = 0; /* request of " + comment(m_program.modes[r].name) + " */");
    d.line("/* the variables: v stored, i inputs (chosen in each scan), p <V>_PREV */");
    for (std::size_t slot = 0; slot < m_program.variables.size(); ++slot) {
        const Variable& variable = m_program.variables[slot];
        if (!m_names.holds(variable))
            continue; // never read nor written: Names and writeStored refuse it otherwise
        const std::string type = m_names.type(variable);
        const int s = static_cast<int>(slot);
        if (variable.kind == VariableKind::Input)
            d.line(type + " " + Names::input(s) + " = 0; /* " + comment(variable.name) + " */");
        else
            d.line(type + " " + Names::stored(s) + " = " + valueText(defaultValueOf(variable)) + "; /* "
                   + comment(variable.name) + " */");
    }
    for (const std::string& name : m_program.edgeVariables)
        d.line("bool " + Names::previous(m_program.slotOf(name)) + " = 0;");
    d.line("/* the instances that run a GRAFCET */");
    for (std::size_t k = 0; k < m_program.instances.size(); ++k)
        declareInstance(static_cast<int>(k));
    d.line("/* within one scan only */");
    std::string scratch = "bool mark, tq, cc, chg, fd, fa, comp, any; byte g, fc; int ci;";
    for (const ProgramCommand& command : m_program.commands)
        scratch += " bool e" + std::to_string(static_cast<int>(command.command)) + ";";
    d.line(scratch);
    std::string more;
    for (std::size_t r = 0; r < m_program.modes.size(); ++r)
        more += "bool q" + std::to_string(r) + "; bool rv" + std::to_string(r) + "; ";
    for (std::size_t i = 0; i < m_program.commands.size(); ++i)
        more += "bool cv" + std::to_string(i) + "; ";
    for (std::size_t t = 0; t < m_maxTransitions; ++t)
        more += "bool f" + std::to_string(t) + "; ";
    for (std::size_t s = 0; s < m_maxSteps; ++s)
        more += "bool lv" + std::to_string(s) + "; bool en" + std::to_string(s) + "; ";
    for (std::size_t o = 0; o < m_maxOutputs; ++o)
        more += "bool no" + std::to_string(o) + "; ";
    d.line(more + "bool nc;");
    d.line("/* the scan */");
}

std::string Writer::condition(const ProgramCondition& c) const
{
    return c.usable ? m_names.expression(c.parsed.expression, Place{}) : "0";
}

std::string Writer::stateIn(const std::vector<State>& states) const
{
    std::string test;
    for (State state : states)
        test += (test.empty() ? "" : " || ") + ("gState == " + number(state));
    return test.empty() ? "0" : "(" + test + ")";
}

void Writer::marker(PackmlMarker m, const std::string& what)
{
    m.line = m_process.line("mark = 1; /* " + comment(what) + " */");
    m_markers.push_back(m);
}

void Writer::markIf(const std::string& test, PackmlMarker m, const std::string& what)
{
    m_process.line("if");
    m_process.line(":: " + test + " ->");
    m_process.in();
    marker(m, what);
    m_process.out();
    m_process.line(":: else -> skip;");
    m_process.line("fi;");
}

void Writer::writeProcess()
{
    Lines& p = m_process;
    p.line("active proctype scan()");
    p.line("{");
    p.in();
    p.line("do");
    p.line(":: atomic {");
    p.in();
    writeReachMarkers();
    writeInputs();
    writeCommands();
    writeModeManager();
    writeStateMachine();
    writeEndOfScan();
    writeCheckMarkers();
    writeForget();
    p.out();
    p.line("}");
    p.line("od");
    p.out();
    p.line("}");
}

void Writer::writeReachMarkers()
{
    m_process.line("/* the configuration this scan starts in */");
    m_process.line("if");
    for (const ProgramMode& mode : m_program.modes)
        for (const StateInfo& info : states()) {
            m_process.line(":: gMode == " + std::to_string(mode.number) + " && gState == " + number(info.state) + " ->");
            m_process.in();
            PackmlMarker m;
            m.kind = PackmlMarkerKind::Reach;
            m.mode = mode.number;
            m.state = info.state;
            marker(m, mode.name + " " + std::string(info.name) + " reached");
            m_process.out();
        }
    m_process.line(":: else -> skip;");
    m_process.line("fi;");
}

// Step 1: every generated command through its R_TRIG; CntrlCmd at an edge of CmdChangeRequest.
void Writer::writeCommands()
{
    Lines& p = m_process;
    p.line("/* 1. the commands */");
    p.line("cc = " + Names::input(m_cmdChangeRequest) + " && !mCmd; mCmd = " + Names::input(m_cmdChangeRequest) + ";");
    for (std::size_t i = 0; i < m_program.commands.size(); ++i) {
        const ProgramCommand& command = m_program.commands[i];
        const std::string value = m_choices.commandCollapsed(i) ? "cv" + std::to_string(i) : condition(command.condition);
        const std::string memory = "mc" + std::to_string(i);
        const std::string event = "e" + std::to_string(static_cast<int>(command.command));
        p.line("tq = " + value + "; " + event + " = tq && !" + memory + "; " + memory + " = tq; /* " + command.name + " */");
        p.line("if :: cc && " + Names::input(m_cntrlCmd) + " == " + std::to_string(static_cast<int>(command.command))
               + " -> " + event + " = 1; :: else -> skip; fi;");
    }
}

// Step 2: the first grantable request in mode order, on the state at the start of the scan.
void Writer::writeModeManager()
{
    Lines& p = m_process;
    p.line("/* 2. the mode manager */");
    p.line("chg = " + Names::input(m_unitModeChangeRequest) + " && !mMode; mMode = " + Names::input(m_unitModeChangeRequest)
           + ";");
    for (std::size_t r = 0; r < m_program.modes.size(); ++r) {
        const ProgramMode& mode = m_program.modes[r];
        const std::string q = "q" + std::to_string(r);
        if (mode.requestGenerated) {
            const std::string value = m_choices.requestCollapsed(r) ? "rv" + std::to_string(r) : condition(mode.request);
            const std::string memory = "mr" + std::to_string(r);
            p.line("tq = " + value + "; " + q + " = tq && !" + memory + "; " + memory + " = tq;");
        }
        p.line(q + " = " + q + " || (chg && " + Names::input(m_unitMode) + " == " + std::to_string(mode.number) + ");");
    }
    p.line("g = 0;");
    for (std::size_t r = 0; r < m_program.modes.size(); ++r) {
        const ProgramMode& requested = m_program.modes[r];
        std::string grantable;
        for (const ProgramMode& current : m_program.modes)
            for (const ModeGrant& grant : current.grants)
                if (grant.targetMode == requested.number)
                    grantable += (grantable.empty() ? "" : " || ") + ("(gMode == " + std::to_string(current.number)
                                                                      + " && " + stateIn(grant.states.list()) + ")");
        if (grantable.empty())
            continue;
        p.line("if :: g == 0 && q" + std::to_string(r) + " && gMode != " + std::to_string(requested.number) + " && ("
               + grantable + ") -> g = " + std::to_string(requested.number) + "; :: else -> skip; fi;");
    }
    // GV133: a grant the rules' S(c, r) does not allow.
    for (const ProgramMode& current : m_program.modes)
        for (const ModeGrant& grant : current.grants)
            for (State state : grant.states.list()) {
                if (m_reference.grant(current.number, grant.targetMode).contains(state))
                    continue;
                PackmlMarker m;
                m.kind = PackmlMarkerKind::ModeChange;
                m.mode = current.number;
                m.state = state;
                markIf("g == " + std::to_string(grant.targetMode) + " && gMode == " + std::to_string(current.number)
                           + " && gState == " + number(state),
                       m, "GV133: mode " + current.name + " changes in " + std::string(stateName(state)));
            }
    p.line("if :: g != 0 -> gMode = g; gEntry = 1; gResume = 0; :: else -> skip; fi;");
}

// Step 3: the branch of State in the current Mode.
void Writer::writeStateMachine()
{
    Lines& p = m_process;
    p.line("/* 3. the branch of State in Mode */");
    p.line("ci = -1;");
    p.line("if");
    for (const ProgramMode& mode : m_program.modes)
        for (const ProgramState& state : mode.states) {
            p.line(":: gMode == " + std::to_string(mode.number) + " && gState == " + number(state.state) + " -> /* "
                   + comment(mode.name) + " " + std::string(stateName(state.state)) + " */");
            p.in();
            writeBranch(state);
            p.out();
        }
    p.line(":: else -> skip; /* no branch: nothing runs */");
    p.line("fi;");
}

void Writer::writeBranch(const ProgramState& state)
{
    Lines& p = m_process;
    const int k = state.instance;
    if (k >= 0) {
        p.line("ci = " + std::to_string(k) + ";");
        const bool execute = state.state == State::Execute;
        const bool runsGrafcet = grafcetOf(k) != nullptr;
        p.line("if");
        p.line(":: gEntry ->");
        p.in();
        if (runsGrafcet) {
            if (execute) {
                p.line("if");
                p.line(":: gResume -> skip; /* resumes where it was paused */");
                p.line(":: else ->");
                p.in();
                writeInitializationCall(k);
                p.out();
                p.line("fi;");
            } else {
                writeInitializationCall(k);
            }
        }
        p.line(std::string("gEntry = 0;") + (execute ? " gResume = 0;" : ""));
        p.out();
        p.line(":: else -> skip;");
        p.line("fi;");
        if (runsGrafcet) {
            writeOrdinaryCall(k);
            p.line("comp = " + Names::complete(k) + ";");
        } else {
            // The skeleton: an acting state's body sets Complete at once, Execute's never.
            p.line(std::string("comp = ") + (isActing(state.state) ? "1" : "0") + ";");
        }
    }
    p.line("fd = 0;");
    for (const ModeTransition& transition : state.transitions) {
        const TemplateTransition& t = transition.transition;
        const std::string holds = t.trigger == Trigger::StateComplete ? "comp" : "e" + std::to_string(static_cast<int>(t.command));
        p.line("if");
        p.line(":: !fd && " + holds + " ->");
        p.in();
        writeFire(transition);
        p.out();
        p.line(":: else -> skip;");
        p.line("fi;");
    }
}

void Writer::writeFire(const ModeTransition& transition)
{
    std::string text = "fd = 1; gState = " + number(transition.destination.state) + "; gEntry = 1;";
    switch (resumeEffect(transition)) {
    case ResumeEffect::Set: text += " gResume = 1;"; break;
    case ResumeEffect::Clear: text += " gResume = 0;"; break;
    case ResumeEffect::None: break;
    }
    if (transition.transition.trigger == Trigger::Command)
        text += " fc = " + std::to_string(static_cast<int>(transition.transition.command)) + ";";
    if (entersAbort(transition.destination.state))
        text += " fa = 1;";
    m_process.line(text);
}

// Steps 4-6: the continuous outputs, StateCurrent, UnitModeCurrent, <V>_PREV.
void Writer::writeEndOfScan()
{
    Lines& p = m_process;
    p.line("/* 4. the continuous outputs of the instance of (Mode, State) */");
    std::vector<int> order;
    std::map<int, std::string> drivers;
    for (std::size_t k = 0; k < m_program.instances.size(); ++k) {
        const NestedGrafcet* grafcet = grafcetOf(static_cast<int>(k));
        if (!grafcet)
            continue;
        const ProgramInstance& instance = m_program.instances[k];
        std::size_t index = 0;
        for (const ContinuousOutput& output : grafcet->outputs) {
            if (output.isComplete)
                continue;
            const int slot = m_program.slotOf(output.variable);
            if (!drivers.count(slot))
                order.push_back(slot);
            std::string& text = drivers[slot];
            text += (text.empty() ? "" : " || ") + ("(gMode == " + std::to_string(instance.mode) + " && gState == "
                                                    + number(instance.state) + " && !gEntry && "
                                                    + Names::output(static_cast<int>(k), index++) + ")");
        }
    }
    for (int slot : order)
        p.line(m_names.read(slot) + " = " + drivers[slot] + ";");
    p.line("/* 5. StateCurrent, UnitModeCurrent; 6. the <V>_PREV memories */");
    p.line(Names::stored(m_program.slotOf("StateCurrent")) + " = gState;");
    p.line(Names::stored(m_program.slotOf("UnitModeCurrent")) + " = gMode;");
    for (const std::string& name : m_program.edgeVariables) {
        const int slot = m_program.slotOf(name);
        p.line(Names::previous(slot) + " = " + m_names.read(slot) + ";");
    }
    writeTimersAging();
}

void Writer::writeCheckMarkers()
{
    Lines& p = m_process;
    p.line("/* what the scan did, as the checks read it */");
    for (const ProgramCommand& command : m_program.commands) {
        PackmlMarker m;
        m.kind = PackmlMarkerKind::CommandFires;
        m.command = command.command;
        markIf("fc == " + std::to_string(static_cast<int>(command.command)), m, command.name + " fires");
    }
    for (const ProgramMode& mode : m_program.modes)
        for (const StateInfo& info : states()) {
            if (m_reference.enabled(mode.number).contains(info.state))
                continue;
            PackmlMarker m;
            m.kind = PackmlMarkerKind::DisabledState;
            m.mode = mode.number;
            m.state = info.state;
            markIf("gMode == " + std::to_string(mode.number) + " && gState == " + number(info.state), m,
                   "GV132: " + mode.name + " ends a scan in " + std::string(info.name));
        }
    std::vector<int> continuous, stored;
    for (const ProgramGrafcet& g : m_program.grafcets) {
        for (const ContinuousOutput& output : g.grafcet.outputs)
            if (!output.isComplete)
                addOnce(continuous, m_program.slotOf(output.variable));
        for (const std::string& name : g.grafcet.storedTargets)
            addOnce(stored, m_program.slotOf(name));
    }
    std::string continuousTrue, storedTrue;
    for (std::size_t slot = 0; slot < m_program.variables.size(); ++slot) {
        const Variable& variable = m_program.variables[slot];
        const int s = static_cast<int>(slot);
        if (variable.type != IecType::Bool)
            continue;
        if (std::find(continuous.begin(), continuous.end(), s) != continuous.end())
            continuousTrue += (continuousTrue.empty() ? "" : " || ") + m_names.read(s);
        else if (variable.kind == VariableKind::Output && std::find(stored.begin(), stored.end(), s) != stored.end())
            storedTrue += (storedTrue.empty() ? "" : " || ") + m_names.read(s);
    }
    for (const ProgramMode& mode : m_program.modes)
        for (State state : {State::Aborting, State::Aborted}) {
            const std::string where = "fa && gMode == " + std::to_string(mode.number) + " && gState == " + number(state);
            const std::string label = mode.name + " enters " + std::string(stateName(state));
            PackmlMarker m;
            m.mode = mode.number;
            m.state = state;
            m.kind = PackmlMarkerKind::ContinuousOnAbort;
            if (!continuousTrue.empty())
                markIf(where + " && (" + continuousTrue + ")", m, "GV136: a continuous output TRUE as " + label);
            m.kind = PackmlMarkerKind::StoredOnAbort;
            if (!storedTrue.empty())
                markIf(where + " && (" + storedTrue + ")", m, "GV137: a stored output TRUE as " + label);
        }
}

// What is not kept between scans: the inputs and the scan's own flags.
void Writer::writeForget()
{
    std::string reset = "d_step { mark = 0; tq = 0; cc = 0; chg = 0; fd = 0; fa = 0; comp = 0; any = 0; g = 0; fc = 0; ci = 0; nc = 0; ";
    for (const ProgramCommand& command : m_program.commands)
        reset += "e" + std::to_string(static_cast<int>(command.command)) + " = 0; ";
    for (std::size_t r = 0; r < m_program.modes.size(); ++r)
        reset += "q" + std::to_string(r) + " = 0; rv" + std::to_string(r) + " = 0; ";
    for (std::size_t i = 0; i < m_program.commands.size(); ++i)
        reset += "cv" + std::to_string(i) + " = 0; ";
    for (std::size_t t = 0; t < m_maxTransitions; ++t)
        reset += "f" + std::to_string(t) + " = 0; ";
    for (std::size_t s = 0; s < m_maxSteps; ++s)
        reset += "lv" + std::to_string(s) + " = 0; en" + std::to_string(s) + " = 0; ";
    for (std::size_t o = 0; o < m_maxOutputs; ++o)
        reset += "no" + std::to_string(o) + " = 0; ";
    for (std::size_t slot = 0; slot < m_program.variables.size(); ++slot) {
        const Variable& variable = m_program.variables[slot];
        if (variable.kind == VariableKind::Input && m_names.holds(variable))
            reset += Names::input(static_cast<int>(slot)) + " = 0; ";
    }
    m_process.line(reset + "}");
}

} // namespace promela

PackmlPromela buildPackmlPromela(const Model& model)
{
    return buildPackmlPromela(model, buildPackmlProgram(model));
}

PackmlPromela buildPackmlPromela(const Model& model, const PackmlProgram& program)
{
    return promela::Writer(model, program).run();
}

} // namespace core::packml
