#include "core/templates/packml/packmlsimulator.h"

#include "core/condition/conditionanalysis.h"
#include "core/model/span.h"
#include "core/model/iectypes.h"
#include "core/templates/packml/packmlconfiguration.h"
#include "core/templates/packml/packmlmodel.h"
#include "core/templates/packml/packmlvalues.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace core::packml {

namespace {

// IEC R_TRIG: Q is TRUE in the call that sees CLK rise; a CLK TRUE at the
// first call is an edge (the memory starts FALSE).
bool trigger(bool clk, bool& memory)
{
    const bool q = clk && !memory;
    memory = clk;
    return q;
}

bool trigger(bool clk, char& memory)
{
    bool remembered = memory != 0;
    const bool q = trigger(clk, remembered);
    memory = remembered ? 1 : 0;
    return q;
}

// The globals as an instance's function block reads and writes them.
class SimulatorGlobals final : public NestedGlobals {
public:
    SimulatorGlobals(std::vector<cond::Value>& values, const std::vector<char>& previous)
        : m_values(values)
        , m_previous(previous)
    {
    }
    cond::Value read(int slot) const override { return m_values[static_cast<std::size_t>(slot)]; }
    void write(int slot, const cond::Value& value) override { m_values[static_cast<std::size_t>(slot)] = value; }
    bool previous(int slot) const override { return m_previous[static_cast<std::size_t>(slot)] != 0; }

private:
    std::vector<cond::Value>& m_values;
    const std::vector<char>& m_previous;
};

} // namespace

// What scan() reads and never changes, shared by copies.
struct PackmlSimulator::Compiled {
    PackmlProgram program;
    int cycleTimeMs = 0;
    std::vector<cond::Value> defaults;                   // by slot
    std::unordered_map<std::string, int> slotByUpperName; // the first variable of a name wins, as slotOf
    std::vector<std::vector<int>> commandSlots;          // by command: expression node -> slot
    std::vector<std::vector<int>> requestSlots;          // by mode
    // Where a division by zero stops the run, by command and by mode: spelled
    // once here rather than in every scan that may never need it.
    std::vector<std::string> commandPlaces;
    std::vector<std::string> requestPlaces;
    std::vector<StateSet> modeChange;                    // by mode: the states listed, as configured
    struct Driver {
        int instance = 0;
        std::size_t output = 0; // index into the instance engine's outputs
    };
    struct OutputWrite {
        int slot = 0;
        std::vector<Driver> drivers;
    };
    std::vector<OutputWrite> outputs;
    std::vector<int> edgeSlots;
    int cntrlCmd = -1, cmdChangeRequest = -1, unitMode = -1, unitModeChangeRequest = -1;
    int stateCurrent = -1, unitModeCurrent = -1;

    Compiled(const Model& model, PackmlProgram built);
    int slot(std::string_view name) const
    {
        const auto found = slotByUpperName.find(toUpperAscii(name));
        return found == slotByUpperName.end() ? -1 : found->second;
    }
    std::vector<int> nodeSlots(const ProgramCondition& condition) const
    {
        std::vector<int> slots(condition.parsed.expression.nodes.size(), -1);
        if (!condition.usable)
            return slots;
        for (int node : cond::variableNodes(condition.parsed.expression))
            slots[static_cast<std::size_t>(node)] = slot(condition.parsed.expression.at(node).text);
        return slots;
    }
    int modeIndex(int number) const
    {
        for (std::size_t i = 0; i < program.modes.size(); ++i)
            if (program.modes[i].number == number)
                return static_cast<int>(i);
        return -1;
    }
};

PackmlSimulator::Compiled::Compiled(const Model& model, PackmlProgram built)
    : program(std::move(built))
    , cycleTimeMs(model.settings().cycleTimeMs)
{
    for (std::size_t slot = 0; slot < program.variables.size(); ++slot) {
        defaults.push_back(defaultValueOf(program.variables[slot]));
        slotByUpperName.emplace(toUpperAscii(program.variables[slot].name), static_cast<int>(slot));
    }
    for (const ProgramCommand& command : program.commands) {
        commandSlots.push_back(nodeSlots(command.condition));
        commandPlaces.push_back("the condition of the " + command.name + " command");
    }
    const Configuration& configuration = *model.packml();
    for (const ProgramMode& mode : program.modes) {
        requestSlots.push_back(nodeSlots(mode.request));
        requestPlaces.push_back("the request condition of mode " + mode.name);
        modeChange.push_back(configuration.mode(mode.number)->modeChange);
    }
    for (std::size_t i = 0; i < program.instances.size(); ++i) {
        const ProgramInstance& instance = program.instances[i];
        if (instance.isSkeleton())
            continue;
        std::size_t output = 0;
        for (const ContinuousOutput& driven : program.grafcets[static_cast<std::size_t>(instance.grafcet)].grafcet.outputs) {
            if (driven.isComplete)
                continue;
            const int target = slot(driven.variable);
            auto write = std::find_if(outputs.begin(), outputs.end(), [&](const OutputWrite& w) { return w.slot == target; });
            if (write == outputs.end())
                write = outputs.insert(outputs.end(), OutputWrite{target, {}});
            write->drivers.push_back({static_cast<int>(i), output++});
        }
    }
    for (const std::string& name : program.edgeVariables)
        edgeSlots.push_back(slot(name));
    cntrlCmd = slot("CntrlCmd");
    cmdChangeRequest = slot("CmdChangeRequest");
    unitMode = slot("UnitMode");
    unitModeChangeRequest = slot("UnitModeChangeRequest");
    stateCurrent = slot("StateCurrent");
    unitModeCurrent = slot("UnitModeCurrent");
}

// The events of step 1, by command number (the edition's commands).
struct PackmlSimulator::Events {
    std::array<bool, kCommandCount + 1> command{};
    std::optional<std::int64_t> strayCntrlCmd; // CntrlCmd issued naming no command of the edition
};

PackmlSimulator::PackmlSimulator(const Model& model)
    : PackmlSimulator(model, buildPackmlProgram(model))
{
}

PackmlSimulator::PackmlSimulator(const Model& model, PackmlProgram built)
    : m_compiled(std::make_shared<const Compiled>(model, std::move(built)))
{
    const Compiled* shared = m_compiled.get();
    const std::function<int(std::string_view)> slotOf = [shared](std::string_view name) { return shared->slot(name); };
    const std::function<IecType(int)> typeOf = [shared](int slot) {
        return shared->program.variables[static_cast<std::size_t>(slot)].type;
    };
    for (const ProgramInstance& instance : program().instances) {
        m_engines.emplace_back();
        if (!instance.isSkeleton())
            m_engines.back().emplace(program().grafcets[static_cast<std::size_t>(instance.grafcet)].grafcet, slotOf, typeOf);
    }
    m_manualComplete.assign(m_engines.size(), std::nullopt);
    reset();
}

Status PackmlSimulator::setManualComplete(int instance, std::optional<bool> complete)
{
    if (instance < 0 || static_cast<std::size_t>(instance) >= m_engines.size())
        return Status::failure("simulation.unknown-instance", "no instance has index " + std::to_string(instance));
    const ProgramInstance& programInstance = program().instances[static_cast<std::size_t>(instance)];
    if (!programInstance.isSkeleton()) {
        return Status::failure("simulation.complete-from-grafcet",
                               "the Complete of " + programInstance.name + " comes from its nested GRAFCET");
    }
    m_manualComplete[static_cast<std::size_t>(instance)] = complete;
    return Status::success();
}

std::optional<bool> PackmlSimulator::manualComplete(int instance) const
{
    if (instance < 0 || static_cast<std::size_t>(instance) >= m_manualComplete.size())
        return std::nullopt;
    return m_manualComplete[static_cast<std::size_t>(instance)];
}

const PackmlProgram& PackmlSimulator::program() const
{
    return m_compiled->program;
}

void PackmlSimulator::reset()
{
    m_values = m_compiled->defaults;
    m_previous.assign(m_values.size(), 0);
    for (std::size_t slot = 0; slot < m_values.size(); ++slot)
        m_previous[slot] = std::holds_alternative<bool>(m_values[slot]) && std::get<bool>(m_values[slot]);
    m_state = program().initialState;
    m_mode = program().initialMode;
    m_entry = true;
    m_resume = false;
    m_scanCount = 0;
    m_fault.reset();
    m_cmdChangeMemory = false;
    m_modeChangeMemory = false;
    m_commandMemory.assign(program().commands.size(), 0);
    m_requestMemory.assign(program().modes.size(), 0);
    for (std::optional<NestedEngine>& engine : m_engines) {
        if (engine) {
            engine->reset();
            engine->clearDivisionFault();
        }
    }
    m_complete.assign(m_engines.size(), 0);
}

std::int64_t PackmlSimulator::simulatedTimeMs() const
{
    return m_scanCount * m_compiled->cycleTimeMs;
}

std::optional<cond::Value> PackmlSimulator::value(std::string_view name) const
{
    const int slot = m_compiled->slot(name);
    return slot < 0 ? std::nullopt : std::optional(m_values[static_cast<std::size_t>(slot)]);
}

const NestedEngine* PackmlSimulator::engine(int instance) const
{
    const std::optional<NestedEngine>& engine = m_engines[static_cast<std::size_t>(instance)];
    return engine ? &*engine : nullptr;
}

Status PackmlSimulator::setInput(std::string_view name, const cond::Value& value)
{
    const int slot = m_compiled->slot(name);
    if (slot < 0)
        return Status::failure("simulation.unknown-variable", "no variable is named '" + std::string(name) + "'");
    return setInput(slot, value);
}

Status PackmlSimulator::setInput(int slot, const cond::Value& value)
{
    if (slot < 0 || static_cast<std::size_t>(slot) >= m_values.size())
        return Status::failure("simulation.unknown-variable", "no variable has slot " + std::to_string(slot));
    const Variable& variable = program().variables[static_cast<std::size_t>(slot)];
    if (variable.kind != VariableKind::Input)
        return Status::failure("simulation.not-an-input", variable.name + " is not an input: the program writes it");
    cond::Value fitted = value;
    if (std::optional<std::string> problem = fitValue(variable, fitted))
        return Status::failure("simulation.bad-value", *problem);
    m_values[static_cast<std::size_t>(slot)] = fitted;
    return Status::success();
}

Status PackmlSimulator::setInputText(std::string_view name, std::string_view text)
{
    const int slot = m_compiled->slot(name);
    if (slot < 0)
        return Status::failure("simulation.unknown-variable", "no variable is named '" + std::string(name) + "'");
    const Variable& variable = program().variables[static_cast<std::size_t>(slot)];
    const std::optional<cond::Value> value = text.empty() ? std::nullopt : cond::parseValue(variable.type, text);
    if (!value) {
        return Status::failure("simulation.bad-value", variable.name + " is " + std::string(iecTypeName(variable.type))
                                                           + ": " + defaultValueProblem(variable.type, text));
    }
    return setInput(name, *value);
}

bool PackmlSimulator::evaluate(const ProgramCondition& condition, const std::vector<int>& nodeSlots,
                               const std::string& place)
{
    if (!condition.usable || m_fault)
        return false; // the code writes FALSE for an unusable condition
    int division = -1;
    const cond::Value result = cond::evaluate(
        condition.parsed.expression,
        [&](int node) {
            const int slot = nodeSlots[static_cast<std::size_t>(node)];
            return slot < 0 ? cond::Value{false} : m_values[static_cast<std::size_t>(slot)];
        },
        division);
    if (division < 0)
        return cond::isTrue(result);
    SimulationFault fault;
    fault.scan = m_scanCount;
    fault.stepId = std::string(stateName(m_state));
    fault.place = place;
    fault.text = condition.text;
    fault.division = excerpt(condition.text, condition.parsed.expression.at(division).span);
    m_fault = std::move(fault);
    return false;
}

// Step 1: the commands, sampled at the start of the scan.
PackmlSimulator::Events PackmlSimulator::commandEvents()
{
    Events events;
    const Compiled& compiled = *m_compiled;
    const bool cmdChange = trigger(cond::isTrue(value(compiled.cmdChangeRequest)), m_cmdChangeMemory);
    for (std::size_t i = 0; i < program().commands.size(); ++i) {
        const ProgramCommand& command = program().commands[i];
        const bool edge = trigger(evaluate(command.condition, compiled.commandSlots[i], compiled.commandPlaces[i]),
                                  m_commandMemory[i]);
        if (m_fault)
            return events; // the PLC stops in the middle of section 1
        events.command[static_cast<std::size_t>(command.command)] = edge;
    }
    if (cmdChange) {
        const std::int64_t number = integerOf(value(compiled.cntrlCmd));
        const bool known = number >= 1 && number <= kCommandCount
            && commandInEdition(static_cast<Command>(number), program().options.edition);
        if (known)
            events.command[static_cast<std::size_t>(number)] = true;
        else
            events.strayCntrlCmd = number;
    }
    return events;
}

// Step 2: the mode manager, on the state at the start of the scan.
void PackmlSimulator::runModeManager(PackmlScanRecord& record)
{
    const Compiled& compiled = *m_compiled;
    const std::vector<ProgramMode>& modes = program().modes;
    const bool change = trigger(cond::isTrue(value(compiled.unitModeChangeRequest)), m_modeChangeMemory);
    const std::int64_t unitMode = integerOf(value(compiled.unitMode));
    std::vector<std::size_t> requested; // mode order
    for (std::size_t i = 0; i < modes.size(); ++i) {
        bool edge = false;
        if (modes[i].requestGenerated) {
            edge = trigger(evaluate(modes[i].request, compiled.requestSlots[i], compiled.requestPlaces[i]),
                           m_requestMemory[i]);
            if (m_fault)
                return;
        }
        if (edge || (change && unitMode == modes[i].number))
            requested.push_back(i);
    }
    const bool knownMode = unitMode >= kMinModeNumber && unitMode <= kMaxModeNumber
        && compiled.modeIndex(static_cast<int>(unitMode)) >= 0;
    if (change && !knownMode) {
        const auto number = static_cast<int>(std::clamp<std::int64_t>(unitMode, INT32_MIN, INT32_MAX));
        record.dropped.push_back({DroppedEvent::Kind::ModeRequest, DropReason::NoSuchMode, number, {}, m_state,
                                  modeName(m_mode), {}});
    }
    const ProgramMode* granted = nullptr;
    for (std::size_t i : requested)
        if (!granted && modes[i].number != m_mode && grantable(modes[i].number))
            granted = &modes[i];
    for (std::size_t i : requested)
        if (&modes[i] != granted)
            record.dropped.push_back(refusedRequest(i, granted));
    if (granted) {
        m_mode = granted->number;
        m_entry = true;
        m_resume = false;
    }
}

bool PackmlSimulator::grantable(int requestedMode) const
{
    const ProgramMode* current = program().mode(m_mode);
    if (!current)
        return false;
    return std::any_of(current->grants.begin(), current->grants.end(), [&](const ModeGrant& grant) {
        return grant.targetMode == requestedMode && grant.states.contains(m_state);
    });
}

// Why the request of modes[index] is not granted (spec §3.4, §6.5).
DroppedEvent PackmlSimulator::refusedRequest(std::size_t index, const ProgramMode* granted) const
{
    const Compiled& compiled = *m_compiled;
    const ProgramMode& requested = program().modes[index];
    DroppedEvent event{DroppedEvent::Kind::ModeRequest, DropReason::AlreadyCurrent, requested.number, requested.name,
                       m_state, modeName(m_mode), {}};
    const int current = compiled.modeIndex(m_mode);
    if (requested.number == m_mode) {
        event.reason = DropReason::AlreadyCurrent;
    } else if (grantable(requested.number)) {
        event.reason = DropReason::ModePreempted;
        event.preemptedBy = granted ? granted->name : std::string();
    } else if (current < 0 || !mayAllowModeChange(m_state)
               || !compiled.modeChange[static_cast<std::size_t>(current)].contains(m_state)) {
        event.reason = DropReason::NotAllowedByCurrentMode;
    } else if (!compiled.modeChange[index].contains(m_state)) {
        event.reason = DropReason::NotAllowedByRequestedMode;
    } else {
        event.reason = DropReason::DisabledInRequestedMode;
    }
    return event;
}

std::string PackmlSimulator::modeName(int number) const
{
    const ProgramMode* mode = program().mode(number);
    return mode ? mode->name : std::to_string(number);
}

// Step 3: the branch of State in the current mode.
void PackmlSimulator::runStateMachine(const Events& events, PackmlScanRecord& record)
{
    const ProgramMode* mode = program().mode(m_mode);
    const ProgramState* programState = mode ? mode->state(m_state) : nullptr;
    if (!programState) { // no branch (a state the mode disables): nothing runs, as on the PLC
        dropCommands(events, nullptr, false, nullptr, record);
        return;
    }
    const bool complete = programState->instance >= 0 && callInstance(programState->instance, record);
    if (programState->instance >= 0 && instanceFaulted(programState->instance))
        return;
    const ModeTransition* fired = nullptr;
    for (const ModeTransition& transition : programState->transitions) {
        const TemplateTransition& t = transition.transition;
        const bool holds = t.trigger == Trigger::StateComplete ? complete
                                                               : events.command[static_cast<std::size_t>(t.command)];
        if (holds) {
            fired = &transition;
            break;
        }
    }
    dropCommands(events, programState, complete, fired, record);
    if (fired) {
        record.fired = *fired;
        fire(*fired);
    }
}

// The entry block and the ordinary call (spec §6.4); returns Complete.
bool PackmlSimulator::callInstance(int instance, PackmlScanRecord& record)
{
    record.calledInstance = instance;
    const bool execute = program().instances[static_cast<std::size_t>(instance)].state == State::Execute;
    if (m_entry) {
        if (execute && m_resume)
            record.resumed = true; // no Initialization call: the instance goes on where it was paused
        else
            callFunctionBlock(instance, true);
        m_entry = false;
        if (execute)
            m_resume = false;
    }
    callFunctionBlock(instance, false);
    return m_complete[static_cast<std::size_t>(instance)] != 0;
}

// The engine went on with 0 for the quotient to the end of its call; the
// scan stops after it, before the transitions.
bool PackmlSimulator::instanceFaulted(int instance)
{
    std::optional<NestedEngine>& engine = m_engines[static_cast<std::size_t>(instance)];
    if (!engine || !engine->divisionFault())
        return false;
    m_fault = *engine->divisionFault();
    engine->clearDivisionFault();
    m_fault->scan = m_scanCount;
    m_fault->stepId = program().instances[static_cast<std::size_t>(instance)].name;
    return true;
}

void PackmlSimulator::setTimerOracle(TimerOracle* oracle)
{
    for (std::optional<NestedEngine>& engine : m_engines)
        if (engine)
            engine->setTimerOracle(oracle);
}

void PackmlSimulator::callFunctionBlock(int instance, bool initialization)
{
    const auto index = static_cast<std::size_t>(instance);
    if (std::optional<NestedEngine>& engine = m_engines[index]) {
        SimulatorGlobals globals(m_values, m_previous);
        engine->call(initialization, simulatedTimeMs(), globals);
        m_complete[index] = engine->complete();
        return;
    }
    // The skeleton: Initialization clears Complete; an acting state's body
    // sets it at once, Execute's never does (spec §4). A manual Complete is
    // written by the body instead.
    if (initialization)
        m_complete[index] = 0;
    if (const std::optional<bool>& manual = m_manualComplete[index])
        m_complete[index] = *manual ? 1 : 0;
    else if (isActing(program().instances[index].state))
        m_complete[index] = 1;
}

void PackmlSimulator::fire(const ModeTransition& transition)
{
    m_state = transition.destination.state;
    m_entry = true;
    switch (resumeEffect(transition)) {
    case ResumeEffect::Set: m_resume = true; break;
    case ResumeEffect::Clear: m_resume = false; break;
    case ResumeEffect::None: break;
    }
}

void PackmlSimulator::dropCommands(const Events& events, const ProgramState* programState, bool complete,
                                   const ModeTransition* fired, PackmlScanRecord& record) const
{
    const auto accepts = [&](Command command) {
        return programState && std::any_of(programState->transitions.begin(), programState->transitions.end(),
                                           [&](const ModeTransition& t) {
                                               return t.transition.trigger == Trigger::Command
                                                   && t.transition.command == command;
                                           });
    };
    // The template's transitions are listed only for a command the state
    // drops, not in every scan.
    std::optional<std::vector<TemplateTransition>> inTemplate;
    const auto templateAccepts = [&](Command command) {
        if (!inTemplate)
            inTemplate = transitionsFrom(m_state, program().options);
        return std::any_of(inTemplate->begin(), inTemplate->end(), [&](const TemplateTransition& t) {
            return t.trigger == Trigger::Command && t.command == command;
        });
    };
    for (int number = 1; number <= kCommandCount; ++number) {
        const auto command = static_cast<Command>(number);
        if (!events.command[static_cast<std::size_t>(number)])
            continue;
        if (fired && fired->transition.trigger == Trigger::Command && fired->transition.command == command)
            continue;
        DroppedEvent event{DroppedEvent::Kind::Command, DropReason::NotAcceptedInState, number,
                           std::string(commandName(command)), m_state, modeName(m_mode), {}};
        if (accepts(command)) {
            event.reason = DropReason::Preempted;
            event.preemptedBy = fired ? transitionText(*fired) : std::string();
        } else if (templateAccepts(command)) {
            event.reason = DropReason::NotAcceptedInMode;
        }
        record.dropped.push_back(std::move(event));
    }
    if (events.strayCntrlCmd) {
        const auto number = static_cast<int>(std::clamp<std::int64_t>(*events.strayCntrlCmd, INT32_MIN, INT32_MAX));
        record.dropped.push_back({DroppedEvent::Kind::Command, DropReason::NoSuchCommand, number, {}, m_state,
                                  modeName(m_mode), {}});
    }
    const bool hasSc = programState && std::any_of(programState->transitions.begin(), programState->transitions.end(),
                                                   [](const ModeTransition& t) {
                                                       return t.transition.trigger == Trigger::StateComplete;
                                                   });
    if (hasSc && complete && fired && fired->transition.trigger != Trigger::StateComplete) {
        record.dropped.push_back({DroppedEvent::Kind::StateComplete, DropReason::Preempted, 0, {}, m_state,
                                  modeName(m_mode), transitionText(*fired)});
    }
}

// Step 4: one writer per continuous output.
void PackmlSimulator::writeOutputs()
{
    for (const Compiled::OutputWrite& write : m_compiled->outputs) {
        bool on = false;
        for (const Compiled::Driver& driver : write.drivers) {
            const ProgramInstance& instance = program().instances[static_cast<std::size_t>(driver.instance)];
            on = on
                || (instance.mode == m_mode && instance.state == m_state && !m_entry
                    && m_engines[static_cast<std::size_t>(driver.instance)]->output(driver.output));
        }
        m_values[static_cast<std::size_t>(write.slot)] = on;
    }
}

PackmlScanRecord PackmlSimulator::scan()
{
    const Compiled& compiled = *m_compiled;
    PackmlScanRecord record;
    record.stateBefore = record.state = m_state;
    record.modeBefore = record.mode = m_mode;
    record.scan = m_scanCount;
    if (m_fault)
        return record; // the PLC stopped: no scan runs
    record.scan = ++m_scanCount;
    const Events events = commandEvents();
    if (!m_fault)
        runModeManager(record);
    if (!m_fault)
        runStateMachine(events, record);
    record.state = m_state;
    record.mode = m_mode;
    if (m_fault)
        return record;
    writeOutputs();
    if (compiled.stateCurrent >= 0)
        m_values[static_cast<std::size_t>(compiled.stateCurrent)] = std::int64_t{static_cast<int>(m_state)};
    if (compiled.unitModeCurrent >= 0)
        m_values[static_cast<std::size_t>(compiled.unitModeCurrent)] = std::int64_t{m_mode};
    for (int slot : compiled.edgeSlots)
        m_previous[static_cast<std::size_t>(slot)] = cond::isTrue(m_values[static_cast<std::size_t>(slot)]);
    return record;
}

} // namespace core::packml
