#include "core/templates/packml/packmlexplorer.h"

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

// A situation with its TONs as time since they started, capped at their
// duration: what the next calls depend on, whatever the absolute time.
void putSituation(std::string& key, const PackmlSimulator& simulator, const Situation& situation)
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
        put(key, running ? std::min(simulator.simulatedTimeMs() - start, timers[t].durationMs) : -1);
    }
}

int instanceIndex(const PackmlProgram& program, int mode, State state)
{
    const ProgramInstance* instance = program.instance(mode, state);
    return instance ? static_cast<int>(instance - program.instances.data()) : -1;
}

} // namespace

PackmlExplorer::PackmlExplorer(const Model& model, PackmlProgram program, ExplorerLimits limits)
    : m_start(model, std::move(program))
    , m_reference(*model.packml())
    , m_choices(m_start.program(), limits.alwaysRead)
    , m_limits(std::move(limits))
{
    for (const ProgramGrafcet& g : m_start.program().grafcets)
        m_timers = m_timers || !g.grafcet.timers.empty();
}

std::vector<std::string> PackmlExplorer::abstractions() const
{
    std::vector<std::string> list = m_choices.abstractions();
    if (m_truncated) {
        list.push_back("some configuration reads more inputs than " + std::to_string(InputChoices::kMaxChoices)
                       + " ways of setting them: only the first were explored");
    }
    if (m_timers && !m_limits.exactTime) {
        list.push_back("time is counted in scans of the model's cycle time: a TON elapses when it would at that cycle, "
                       "not at a longer or varying one");
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
    for (std::size_t c = 0; c < program.commands.size(); ++c)
        key.push_back(s.commandMemory(c) ? '1' : '0');
    for (std::size_t m = 0; m < program.modes.size(); ++m)
        key.push_back(s.requestMemory(m) ? '1' : '0');
    for (const std::string& name : program.edgeVariables)
        key.push_back(s.previous(program.slotOf(name)) ? '1' : '0');
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
    key.push_back(ghost.paused ? '1' : '0');
    if (ghost.paused)
        putSituation(key, s, ghost.situation);
    return key;
}

PackmlScanRecord PackmlExplorer::runScan(PackmlSimulator& simulator, const InputChoice& choice)
{
    for (const InputValue& input : choice)
        simulator.setInput(input.slot, input.value);
    return simulator.scan();
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
    PackmlSimulator next = m_start;
    while (!queue.empty()) {
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
        for (std::uint32_t c = 0; c < choices.size(); ++c) {
            ++m_scans;
            if (outOfBudget()) {
                m_exhaustive = false;
                m_budgetReached = true;
                return;
            }
            next = m_nodes[index].simulator; // assigned, not copied: its buffers are reused
            PackmlScanRecord record = runScan(next, choices[c]);
            const ScanFacts facts = observeScan(m_nodes[index].simulator, next, std::move(record));
            const PauseGhost& ghost = m_nodes[index].ghost;
            for (ScanFinding& finding : checkScan(m_reference, ghost, facts)) {
                const std::string witnessKey = finding.code + "/" + std::to_string(finding.mode) + "/"
                                               + std::string(stateName(finding.state));
                if (m_witnessKeys.insert(witnessKey).second)
                    m_witnesses.push_back({std::move(finding), -1, index, c});
            }
            if (m_limits.violatedProperties)
                for (int property : m_limits.violatedProperties(next))
                    if (m_witnessKeys.insert("property/" + std::to_string(property)).second)
                        m_witnesses.push_back({{}, property, index, c});
            const PackmlScanRecord& r = facts.record;
            if (r.fired && r.fired->transition.trigger == Trigger::Command)
                m_firedCommands.insert(r.fired->transition.command);
            m_reached.insert({r.mode, r.state});
            PauseGhost nextGhostValue = nextGhost(ghost, facts);
            auto [found, inserted] = known.emplace(key(next, nextGhostValue), static_cast<std::uint32_t>(m_nodes.size()));
            ExploredEdge edge;
            edge.from = static_cast<std::uint32_t>(index);
            edge.to = found->second;
            edge.choice = c;
            edge.stays = !r.fired && !r.modeChanged();
            edge.completes = r.fired && r.fired->transition.trigger == Trigger::StateComplete;
            m_edges.push_back(edge);
            if (!inserted)
                continue;
            if (m_nodes.size() >= m_limits.maxStates) {
                m_exhaustive = false;
                m_budgetReached = true;
                return;
            }
            const std::uint32_t depth = m_nodes[index].depth + 1;
            m_maxDepth = std::max<std::size_t>(m_maxDepth, depth);
            m_nodes.push_back({next, std::move(nextGhostValue), static_cast<std::uint32_t>(index), c, depth});
            queue.push_back(m_nodes.size() - 1);
        }
    }
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
