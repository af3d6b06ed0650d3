#include "core/templates/packml/packmlexplorer.h"

#include "core/condition/conditionanalysis.h"
#include "core/model/model.h"

#include <algorithm>
#include <cstring>
#include <deque>
#include <unordered_map>

namespace core::packml {

namespace {

void put(std::string& key, std::int64_t value)
{
    char bytes[sizeof value];
    std::memcpy(bytes, &value, sizeof value);
    key.append(bytes, sizeof value);
}

void putValue(std::string& key, const cond::Value& value)
{
    key.push_back(static_cast<char>(value.index()));
    if (const bool* b = std::get_if<bool>(&value))
        key.push_back(*b ? '1' : '0');
    else if (const std::int64_t* i = std::get_if<std::int64_t>(&value))
        put(key, *i);
    else {
        const double d = std::get<double>(value);
        std::int64_t bits = 0;
        std::memcpy(&bits, &d, sizeof bits);
        put(key, bits);
    }
}

int instanceIndex(const PackmlProgram& program, int mode, State state)
{
    const ProgramInstance* instance = program.instance(mode, state);
    return instance ? static_cast<int>(instance - program.instances.data()) : -1;
}

// What a TON's Q can still do: -1 idle, 1 running, 2 elapsed.
std::int64_t abstractTimer(const NestedTimerState& timer)
{
    return !timer.running ? -1 : timer.done ? 2 : 1;
}

} // namespace

PackmlExplorer::PackmlExplorer(const Model& model, PackmlProgram program, ExplorerLimits limits)
    : m_start(model, std::move(program))
    , m_reference(*model.packml())
    , m_choices(m_start.program(), limits.alwaysRead)
    , m_limits(std::move(limits))
    , m_timerChoices(model.settings().cycleTimeMs)
    , m_next(m_start)
{
    noteLiveMemories();
    noteLivePrevious();
    for (const ProgramGrafcet& g : m_start.program().grafcets)
        for (const NestedTimer& timer : g.grafcet.timers) {
            m_timers = true;
            m_timeAbstracted = m_timeAbstracted || (!m_limits.exactTime && timer.durationMs > model.settings().cycleTimeMs);
        }
}

// A command's R_TRIG memory is read by the next scan only to make its
// event, which acts only where some mode accepts the command; a request's
// only where some grant allows it. Elsewhere the scan overwrites the memory
// with the condition's value before anything reads it, so two
// configurations that differ only there have the same futures.
void PackmlExplorer::noteLiveMemories()
{
    const PackmlProgram& program = m_start.program();
    for (auto& live : m_liveCommandMemory)
        live.assign(program.commands.size(), 0);
    for (auto& live : m_liveRequestMemory)
        live.assign(program.modes.size(), 0);
    for (const ProgramMode& mode : program.modes) {
        for (const ProgramState& state : mode.states)
            for (const ModeTransition& transition : state.transitions)
                for (std::size_t c = 0; c < program.commands.size(); ++c)
                    if (transition.transition.trigger == Trigger::Command
                        && transition.transition.command == program.commands[c].command)
                        m_liveCommandMemory[static_cast<std::size_t>(state.state)][c] = 1;
        for (const ModeGrant& grant : mode.grants)
            for (State state : grant.states.list())
                for (std::size_t r = 0; r < program.modes.size(); ++r)
                    if (program.modes[r].number == grant.targetMode)
                        m_liveRequestMemory[static_cast<std::size_t>(state)][r] = 1;
    }
}

// <V>_PREV is read by the next scan only through an edge of V: in a command
// or request condition (every scan), or in the GRAFCET of an instance of the
// state. An edge variable is set before every scan (an input is enumerated,
// anything else is in the key), so elsewhere the scan overwrites the memory
// before anything reads it.
void PackmlExplorer::noteLivePrevious()
{
    const PackmlProgram& program = m_start.program();
    const std::size_t edges = program.edgeVariables.size();
    std::vector<char> always(edges, 0);
    const auto noteCondition = [&](const ProgramCondition& condition) {
        for (int node : cond::variableNodes(condition.parsed.expression))
            for (std::size_t e = 0; e < edges; ++e)
                if (program.slotOf(condition.parsed.expression.at(node).text) == program.slotOf(program.edgeVariables[e]))
                    always[e] = 1;
    };
    for (const ProgramCommand& command : program.commands)
        noteCondition(command.condition);
    for (const ProgramMode& mode : program.modes)
        noteCondition(mode.request);
    for (auto& live : m_livePrevious)
        live = always;
    for (const ProgramInstance& instance : program.instances) {
        if (instance.isSkeleton())
            continue;
        const NestedGrafcet& grafcet = program.grafcets[static_cast<std::size_t>(instance.grafcet)].grafcet;
        for (const std::string& name : grafcet.readVariables)
            for (std::size_t e = 0; e < edges; ++e)
                if (program.slotOf(name) == program.slotOf(program.edgeVariables[e]))
                    m_livePrevious[static_cast<std::size_t>(instance.state)][e] = 1;
    }
}

// A situation with its TONs as what their Q can still do (time abstracted)
// or as time since they started, capped at their duration (exact time):
// what the next calls depend on, whatever the absolute time.
void PackmlExplorer::putSituation(std::string& key, const PackmlSimulator& simulator, const Situation& situation) const
{
    put(key, situation.instance);
    put(key, static_cast<std::int64_t>(situation.steps.size()));
    for (int step : situation.steps)
        put(key, step);
    key.push_back(situation.complete ? '1' : '0');
    const NestedEngine* engine = situation.instance >= 0 ? simulator.engine(situation.instance) : nullptr;
    const std::vector<NestedTimerState> timers = engine ? engine->timers() : std::vector<NestedTimerState>{};
    for (std::size_t t = 0; t < situation.timers.size() && t < timers.size(); ++t) {
        const auto& [running, start] = situation.timers[t];
        if (m_timeAbstracted)
            put(key, abstractTimer(timers[t]));
        else
            put(key, running ? std::min(simulator.simulatedTimeMs() - start, timers[t].durationMs) : -1);
    }
}

// The situation Execute was paused in, as GV138 compares it with Execute's
// when it resumes. Time abstracted: its TONs' start times are not kept, so
// each TON says whether it ran and whether Execute's still has its start.
void PackmlExplorer::putGhost(std::string& key, const PackmlSimulator& simulator, const PauseGhost& ghost) const
{
    key.push_back(ghost.paused ? '1' : '0');
    if (!ghost.paused)
        return;
    if (!m_timeAbstracted) {
        putSituation(key, simulator, ghost.situation);
        return;
    }
    const Situation& paused = ghost.situation;
    put(key, paused.instance);
    put(key, static_cast<std::int64_t>(paused.steps.size()));
    for (int step : paused.steps)
        put(key, step);
    key.push_back(paused.complete ? '1' : '0');
    const Situation now = situationOf(simulator, paused.instance);
    for (std::size_t t = 0; t < paused.timers.size(); ++t) {
        key.push_back(paused.timers[t].first ? '1' : '0');
        key.push_back(t < now.timers.size() && now.timers[t] == paused.timers[t] ? '=' : '#');
    }
}

std::vector<std::string> PackmlExplorer::abstractions() const
{
    std::vector<std::string> list = runsLeftOutReasons();
    if (m_timeAbstracted)
        list.push_back("timers longer than one cycle may or may not have elapsed from their second run on");
    return list;
}

std::vector<std::string> PackmlExplorer::runsLeftOutReasons() const
{
    std::vector<std::string> list = m_choices.abstractions();
    if (m_truncated) {
        list.push_back("some configuration reads more inputs than " + std::to_string(InputChoices::kMaxChoices)
                       + " ways of setting them: only the first were explored");
    }
    return list;
}

std::string PackmlExplorer::key(const PackmlSimulator& s, const PauseGhost& ghost) const
{
    const PackmlProgram& program = s.program();
    std::string key;
    key.reserve(64 + program.variables.size() * 4);
    put(key, static_cast<int>(s.state()));
    put(key, s.mode());
    key.push_back(s.entry() ? '1' : '0');
    key.push_back(s.resume() ? '1' : '0');
    key.push_back(s.fault() ? '1' : '0');
    key.push_back(s.cmdChangeMemory() ? '1' : '0');
    key.push_back(s.modeChangeMemory() ? '1' : '0');
    const auto state = static_cast<std::size_t>(s.state());
    for (std::size_t c = 0; c < program.commands.size(); ++c)
        key.push_back(m_liveCommandMemory[state][c] && s.commandMemory(c) ? '1' : '0');
    for (std::size_t m = 0; m < program.modes.size(); ++m)
        key.push_back(m_liveRequestMemory[state][m] && s.requestMemory(m) ? '1' : '0');
    for (std::size_t e = 0; e < program.edgeVariables.size(); ++e)
        key.push_back(m_livePrevious[state][e] && s.previous(program.slotOf(program.edgeVariables[e])) ? '1' : '0');
    for (std::size_t slot = 0; slot < program.variables.size(); ++slot)
        if (program.variables[slot].kind != VariableKind::Input)
            putValue(key, s.value(static_cast<int>(slot)));
    // The instance that runs next (its situation matters unless it starts
    // afresh), and Execute while a resume is pending.
    const bool fresh = s.entry() && !(s.state() == State::Execute && s.resume());
    if (!fresh)
        putSituation(key, s, situationOf(s, instanceIndex(program, s.mode(), s.state())));
    if (inPauseLoop(s.state()) && s.resume())
        putSituation(key, s, situationOf(s, instanceIndex(program, s.mode(), State::Execute)));
    putGhost(key, s, ghost);
    return key;
}

PackmlScanRecord PackmlExplorer::runScan(PackmlSimulator& simulator, const InputChoice& choice)
{
    for (const InputValue& input : choice)
        simulator.setInput(input.slot, input.value);
    return simulator.scan();
}

PackmlScanRecord PackmlExplorer::runScan(PackmlSimulator& simulator, const InputChoice& choice,
                                         const std::vector<char>& answers)
{
    if (!m_timeAbstracted)
        return runScan(simulator, choice);
    m_timerChoices.start(answers);
    simulator.setTimerOracle(&m_timerChoices);
    PackmlScanRecord record = runScan(simulator, choice);
    simulator.setTimerOracle(nullptr);
    return record;
}

bool PackmlExplorer::outOfBudget()
{
    if ((m_scans & 255u) != 0)
        return false;
    if (m_limits.cancelled && m_limits.cancelled()) {
        m_cancelled = true;
        return true;
    }
    return std::chrono::steady_clock::now() >= m_limits.deadline;
}

void PackmlExplorer::run()
{
    m_nodes.clear();
    m_edges.clear();
    PackmlSimulator start = m_start;
    start.reset();
    m_reached.insert({start.mode(), start.state()});
    std::unordered_map<std::string, std::uint32_t> known;
    known.emplace(key(start, PauseGhost{}), 0);
    m_nodes.push_back({std::move(start), PauseGhost{}, 0, 0, 0});
    std::deque<std::size_t> queue{0};
    while (!queue.empty() && !m_stopped) {
        const std::size_t index = queue.front();
        queue.pop_front();
        bool truncated = false;
        const std::vector<InputChoice> choices = m_choices.choices(m_nodes[index].simulator, &truncated);
        if (m_nodes[index].simulator.fault())
            continue; // the PLC stopped: no scan follows
        if (truncated) {
            m_exhaustive = false;
            m_truncated = true;
        }
        for (std::uint32_t c = 0; c < choices.size() && !m_stopped; ++c)
            explore(index, c, choices[c], known, queue);
    }
}

// The scans from node `index` with the inputs `inputs`: one, or under the
// timer abstraction one per way of answering the TONs it reads.
void PackmlExplorer::explore(std::size_t index, std::uint32_t c, const InputChoice& inputs,
                             std::unordered_map<std::string, std::uint32_t>& known, std::deque<std::size_t>& queue)
{
    std::vector<char> answers;
    do {
        ++m_scans;
        if (outOfBudget()) {
            m_exhaustive = false;
            m_budgetReached = true;
            m_stopped = true;
            return;
        }
        m_next = m_nodes[index].simulator; // assigned, not copied: its buffers are reused
        PackmlScanRecord record = runScan(m_next, inputs, answers);
        const ScanFacts facts = observeScan(m_nodes[index].simulator, m_next, std::move(record));
        const PauseGhost& ghost = m_nodes[index].ghost;
        for (ScanFinding& finding : checkScan(m_reference, ghost, facts)) {
            const std::string witnessKey = finding.code + "/" + std::to_string(finding.mode) + "/"
                                           + std::string(stateName(finding.state));
            if (m_witnessKeys.insert(witnessKey).second)
                m_witnesses.push_back({std::move(finding), -1, index, c});
        }
        if (m_limits.violatedProperties)
            for (int property : m_limits.violatedProperties(m_next))
                if (m_witnessKeys.insert("property/" + std::to_string(property)).second)
                    m_witnesses.push_back({{}, property, index, c});
        const PackmlScanRecord& r = facts.record;
        if (r.fired && r.fired->transition.trigger == Trigger::Command)
            m_firedCommands.insert(r.fired->transition.command);
        m_reached.insert({r.mode, r.state});
        PauseGhost nextGhostValue = nextGhost(ghost, facts);
        auto [found, inserted] = known.emplace(key(m_next, nextGhostValue), static_cast<std::uint32_t>(m_nodes.size()));
        ExploredEdge edge;
        edge.from = static_cast<std::uint32_t>(index);
        edge.to = found->second;
        edge.choice = c;
        edge.stays = !r.fired && !r.modeChanged();
        edge.completes = r.fired && r.fired->transition.trigger == Trigger::StateComplete;
        if (m_timeAbstracted) {
            const std::vector<TimerDecision>& decisions = m_timerChoices.decisions();
            edge.decisions = static_cast<std::uint16_t>(std::min<std::size_t>(decisions.size(), UINT16_MAX));
            for (const TimerDecision& d : decisions) {
                (d.elapsed ? edge.decidedElapsed : edge.decidedRunning) = true;
                const auto timer = static_cast<std::int32_t>(d.timer);
                edge.decidedTimer = edge.decidedTimer == -1 || edge.decidedTimer == timer ? timer : -2;
            }
        }
        m_edges.push_back(edge);
        if (inserted) {
            if (m_nodes.size() >= m_limits.maxStates) {
                m_exhaustive = false;
                m_budgetReached = true;
                m_stopped = true;
                return;
            }
            const std::uint32_t depth = m_nodes[index].depth + 1;
            m_maxDepth = std::max<std::size_t>(m_maxDepth, depth);
            m_nodes.push_back({m_next, std::move(nextGhostValue), static_cast<std::uint32_t>(index), c, depth});
            queue.push_back(m_nodes.size() - 1);
        }
    } while (m_timeAbstracted && m_timerChoices.advance(answers));
}

std::vector<InputChoice> PackmlExplorer::path(std::size_t node) const
{
    std::vector<std::size_t> chain;
    for (std::size_t n = node; n != 0; n = m_nodes[n].parent)
        chain.push_back(n);
    std::vector<InputChoice> result;
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
        const ExploredNode& child = m_nodes[*it];
        result.push_back(m_choices.choices(m_nodes[child.parent].simulator)[child.parentChoice]);
    }
    return result;
}

} // namespace core::packml
