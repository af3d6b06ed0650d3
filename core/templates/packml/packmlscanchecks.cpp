#include "core/templates/packml/packmlscanchecks.h"

#include "core/model/messagetext.h"
#include "core/templates/packml/packmlrules.h"
#include "core/templates/packml/packmlsimulator.h"

#include <algorithm>

namespace core::packml {

namespace {

bool entersAbort(const PackmlScanRecord& record)
{
    return record.fired
           && (record.fired->destination.state == State::Aborting || record.fired->destination.state == State::Aborted);
}

// The outputs TRUE after the scan: driven by continuous actions, or written by stored ones.
void outputsAfter(const PackmlSimulator& simulator, ScanFacts& facts)
{
    const PackmlProgram& program = simulator.program();
    std::vector<int> continuous, stored;
    for (const ProgramGrafcet& g : program.grafcets) {
        for (const ContinuousOutput& output : g.grafcet.outputs)
            if (!output.isComplete)
                continuous.push_back(program.slotOf(output.variable));
        for (const std::string& name : g.grafcet.storedTargets) {
            const int slot = program.slotOf(name);
            if (slot >= 0 && program.variables[static_cast<std::size_t>(slot)].kind == VariableKind::Output)
                stored.push_back(slot);
        }
    }
    for (std::size_t slot = 0; slot < program.variables.size(); ++slot) {
        const Variable& variable = program.variables[slot];
        if (variable.type != IecType::Bool || !cond::isTrue(simulator.value(static_cast<int>(slot))))
            continue;
        const auto listed = [&](const std::vector<int>& slots) {
            return std::find(slots.begin(), slots.end(), static_cast<int>(slot)) != slots.end();
        };
        if (listed(continuous))
            facts.continuousOutputsTrue.push_back(variable.name);
        else if (listed(stored))
            facts.storedOutputsTrue.push_back(variable.name);
    }
}

} // namespace

bool inPauseLoop(State state)
{
    switch (state) {
    case State::Holding: case State::Held: case State::Unholding:
    case State::Suspending: case State::Suspended: case State::Unsuspending:
        return true;
    default:
        return false;
    }
}

Situation situationOf(const PackmlSimulator& simulator, int instance)
{
    Situation situation;
    situation.instance = instance;
    if (instance < 0)
        return situation;
    situation.complete = simulator.complete(instance);
    if (const NestedEngine* engine = simulator.engine(instance)) {
        situation.steps = engine->activeSteps();
        situation.complete = engine->complete();
        for (const NestedTimerState& timer : engine->timers())
            situation.timers.emplace_back(timer.running, timer.running ? timer.startMs : 0);
    }
    return situation;
}

ScanFacts observeScan(const PackmlSimulator& before, const PackmlSimulator& after, PackmlScanRecord record)
{
    ScanFacts facts;
    facts.entryBefore = before.entry();
    facts.record = std::move(record);
    const PackmlProgram& program = after.program();
    const auto executeOf = [&](int mode) {
        const ProgramInstance* instance = program.instance(mode, State::Execute);
        return instance ? static_cast<int>(instance - program.instances.data()) : -1;
    };
    if (facts.record.stateBefore == State::Execute)
        facts.executeBefore = situationOf(before, executeOf(facts.record.mode));
    if (inPauseLoop(facts.record.state))
        facts.executeAfter = situationOf(after, executeOf(facts.record.mode));
    if (entersAbort(facts.record))
        outputsAfter(after, facts);
    return facts;
}

ScanReference::ScanReference(const Configuration& configuration)
{
    for (const Mode& mode : configuration.modes) {
        m_enabled[mode.number] = enabledStates(mode.disabled).enabled;
        m_modeChange[mode.number] = mode.modeChange;
    }
}

StateSet ScanReference::enabled(int mode) const
{
    const auto found = m_enabled.find(mode);
    return found == m_enabled.end() ? StateSet{} : found->second;
}

StateSet ScanReference::grant(int from, int to) const
{
    const auto c = m_modeChange.find(from);
    const auto r = m_modeChange.find(to);
    if (from == to || c == m_modeChange.end() || r == m_modeChange.end())
        return {};
    return modeChangeStates(c->second, r->second, enabled(to));
}

std::vector<ScanFinding> checkScan(const ScanReference& reference, const PauseGhost& ghost, const ScanFacts& facts)
{
    std::vector<ScanFinding> findings;
    const PackmlScanRecord& r = facts.record;
    const std::string after = std::string(stateName(r.state));
    if (!reference.enabled(r.mode).contains(r.state))
        findings.push_back({"GV132", r.mode, r.state, {}, after + " is active in a mode that disables it"});
    if (r.modeChanged() && !reference.grant(r.modeBefore, r.mode).contains(r.stateBefore)) {
        findings.push_back({"GV133", r.modeBefore, r.stateBefore, {},
                            "the mode changed in " + std::string(stateName(r.stateBefore))
                                + ", a state where this change is not allowed"});
    }
    if (entersAbort(r) && !facts.continuousOutputsTrue.empty()) {
        findings.push_back({"GV136", r.mode, r.state, facts.continuousOutputsTrue,
                            "continuous outputs TRUE at the end of the scan that enters " + after + ": "
                                + joined(facts.continuousOutputsTrue)});
    }
    if (entersAbort(r) && !facts.storedOutputsTrue.empty()) {
        findings.push_back({"GV137", r.mode, r.state, facts.storedOutputsTrue,
                            "stored outputs still TRUE when " + after + " is entered: " + joined(facts.storedOutputsTrue)});
    }
    if (r.stateBefore == State::Execute && facts.entryBefore) {
        const bool resumeExpected = ghost.paused && !r.modeChanged();
        if (r.resumed != resumeExpected) {
            findings.push_back({"GV138", r.mode, State::Execute, {},
                                resumeExpected ? "Execute, entered from the Hold or Suspend loop, started afresh instead of resuming"
                                               : "Execute resumed where it should have started afresh"});
        } else if (r.resumed && facts.executeBefore != ghost.situation) {
            findings.push_back({"GV138", r.mode, State::Execute, {},
                                "Execute resumed in a situation other than the one it was paused in"});
        }
    }
    return findings;
}

PauseGhost nextGhost(const PauseGhost& ghost, const ScanFacts& facts)
{
    const PackmlScanRecord& r = facts.record;
    if (r.stateBefore == State::Execute && inPauseLoop(r.state))
        return PauseGhost{true, facts.executeAfter};
    const bool stillPaused = !r.modeChanged() && r.stateBefore != State::Execute
                             && (inPauseLoop(r.state) || r.state == State::Execute);
    return stillPaused ? ghost : PauseGhost{};
}

} // namespace core::packml
