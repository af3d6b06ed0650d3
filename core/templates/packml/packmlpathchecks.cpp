#include "core/templates/packml/packmlpathchecks.h"

#include "core/condition/actionparser.h"
#include "core/model/model.h"
#include "core/templates/packml/packmldiagnostics.h"
#include "core/templates/packml/packmlrules.h"

#include <array>
#include <deque>
#include <string>
#include <unordered_map>

namespace core::packml {

namespace {

// Without StateSet::list's vector: every mode asks it of every other mode.
void insertAll(StateSet& into, const StateSet& states)
{
    for (int n = 1; n <= kStateCount; ++n)
        if (states.contains(static_cast<State>(n)))
            into.insert(static_cast<State>(n));
}

// Which actions of a GRAFCET write Complete, and whether one makes it TRUE
// (`S Complete`, `Complete := ...`, a continuous `Complete`).
struct CompleteWrites {
    bool makesTrue = false;
    bool writes = false;
};

CompleteWrites completeWrites(const Grafcet& grafcet)
{
    CompleteWrites result;
    for (const GrafcetStep& step : grafcet.steps())
        for (const GrafcetAction& action : step.actions) {
            const cond::ActionParseResult parsed = cond::parseAction(action.text);
            if (!parsed.ok() || !parsed.action.targetIsComplete)
                continue;
            result.writes = true;
            if (parsed.action.form != cond::ActionForm::Reset) {
                result.makesTrue = true;
                return result;
            }
        }
    return result;
}

// What the GRAFCETs write, parsed once per GRAFCET: the modes that run a
// procedure "same as" another share its GRAFCET, and the path walk asks the
// same question of it for every transition it follows.
class CompleteWriters {
public:
    const CompleteWrites& of(const Grafcet& grafcet)
    {
        const auto found = m_known.find(&grafcet);
        if (found != m_known.end())
            return found->second;
        return m_known.emplace(&grafcet, completeWrites(grafcet)).first->second;
    }

private:
    std::unordered_map<const Grafcet*, CompleteWrites> m_known;
};

class PathChecker {
public:
    PathChecker(const Model& model, const Mode& mode, CompleteWriters& writers)
        : m_model(model)
        , m_configuration(*model.packml())
        , m_mode(mode)
        , m_enabled(enabledStates(mode.disabled).enabled)
        , m_writers(writers)
    {
    }

    void run(std::vector<Diagnostic>& result)
    {
        const StateSet begin = beginStates();
        const StateSet reached = begin.empty() ? StateSet{} : reachableFrom(begin);
        const std::string label = modeLabel(m_mode);
        if (!begin.empty() && !reached.contains(State::Execute))
            result.push_back(modeDiagnostic(
                m_mode, {"PM008", Severity::Warning, "disabled",
                         "in mode " + label + ", no sequence of transitions leads to Execute from where the mode "
                             + "begins (counting a State Complete only where the state's GRAFCET writes Complete)",
                         {label}}));
        for (const State state : m_enabled.list()) {
            const std::string name(stateName(state));
            if (!begin.empty() && state != State::Execute && !reached.contains(state))
                result.push_back(modeStateDiagnostic(
                    m_mode, state, {"PM009", Severity::Warning, "disabled",
                                    "in mode " + label + ", no sequence of transitions reaches " + name
                                        + " from where the mode begins: it is never active",
                                    {label, name}}));
            checkComplete(state, result);
        }
    }

private:
    // The initial state for the initial mode, and the states where another
    // mode may change into this one.
    StateSet beginStates() const
    {
        StateSet begin;
        if (m_mode.number == m_configuration.initialMode)
            begin.insert(m_configuration.initialState);
        for (const Mode& other : m_configuration.modes)
            if (other.number != m_mode.number)
                insertAll(begin, modeChangeStates(other.modeChange, m_mode.modeChange, m_enabled));
        return begin;
    }

    // Looked up once per state: the walk asks at every transition it follows.
    const Grafcet* grafcetOf(State state) const
    {
        const auto index = static_cast<std::size_t>(state);
        if (!m_grafcetKnown[index]) {
            m_grafcets[index] = m_model.effectiveGrafcet(grafcetKey(m_mode.number, state));
            m_grafcetKnown[index] = true;
        }
        return m_grafcets[index];
    }

    // An acting state without GRAFCET completes at once through its skeleton;
    // Execute's skeleton never completes (spec §4).
    bool completes(State state) const
    {
        if (!holdsGrafcet(state))
            return false;
        const Grafcet* grafcet = grafcetOf(state);
        return grafcet ? m_writers.of(*grafcet).makesTrue : isActing(state);
    }

    StateSet reachableFrom(const StateSet& begin) const
    {
        StateSet reached = begin;
        std::deque<State> pending;
        for (const State state : begin.list())
            pending.push_back(state);
        while (!pending.empty()) {
            const State state = pending.front();
            pending.pop_front();
            for (const ModeTransition& transition : modeTransitionsFrom(state, m_enabled, m_configuration.options)) {
                const bool fires = transition.transition.trigger == Trigger::Command || completes(state);
                const State next = transition.destination.state;
                if (fires && !reached.contains(next)) {
                    reached.insert(next);
                    pending.push_back(next);
                }
            }
        }
        return reached;
    }

    void checkComplete(State state, std::vector<Diagnostic>& result) const
    {
        const Grafcet* grafcet = holdsGrafcet(state) ? grafcetOf(state) : nullptr;
        if (grafcet == nullptr)
            return;
        const std::string label = modeLabel(m_mode);
        const std::string name(stateName(state));
        if (isActing(state) && !m_writers.of(*grafcet).makesTrue) {
            const bool aborting = state == State::Aborting;
            result.push_back(modeStateDiagnostic(
                m_mode, state,
                {"PM010", aborting ? Severity::Error : Severity::Warning, "grafcet",
                 "the GRAFCET of " + label + ": " + name + " never writes Complete: "
                     + (aborting ? "nothing leaves Aborting, so the unit can never reach Aborted"
                                 : "only Stop or Abort leave the state"),
                 {label, name}}));
        }
        if (state == State::Execute && m_configuration.options.edition == Edition::Y2022
            && m_writers.of(*grafcet).writes)
            result.push_back(modeStateDiagnostic(
                m_mode, state,
                {"PM016", Severity::Warning, "grafcet",
                 "the GRAFCET of " + label
                     + ": Execute writes Complete, which nothing reads in the 2022 edition: use the Complete command",
                 {label}}));
    }

    const Model& m_model;
    const Configuration& m_configuration;
    const Mode& m_mode;
    StateSet m_enabled;
    CompleteWriters& m_writers;
    mutable std::array<const Grafcet*, kStateCount + 1> m_grafcets{};
    mutable std::array<bool, kStateCount + 1> m_grafcetKnown{};
};

} // namespace

bool setsComplete(const Grafcet& grafcet)
{
    return completeWrites(grafcet).makesTrue;
}

std::vector<Diagnostic> checkPaths(const Model& model)
{
    std::vector<Diagnostic> result;
    CompleteWriters writers;
    for (const Mode& mode : model.packml()->modes)
        PathChecker(model, mode, writers).run(result);
    return result;
}

} // namespace core::packml
