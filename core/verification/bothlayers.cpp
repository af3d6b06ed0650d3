#include "core/verification/bothlayers.h"

#include "core/templates/gemma/gemmaprogram.h"
#include "core/model/model.h"
#include "core/model/messagetext.h"
#include "core/verification/concretesearch.h"
#include "core/verification/programexplorer.h"
#include "core/verification/property.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <set>

namespace core {

namespace {

// Said of a run that does not replay when its search counted in scans was cut.
constexpr const char* kReplaySearchCut
    = ", and the search for one with time counted in scans stopped at the time or size limit";

namespace code = verification;
using explore::Event;
using explore::EventKind;
using explore::eventKey;

std::string nestedStep(const std::string& stepId, int number)
{
    return stepId + "/" + std::to_string(number);
}

std::string nestedTransition(const std::string& stepId, int number)
{
    return stepId + "/T" + std::to_string(number);
}


bool hasLongTimers(const GemmaProgram& program, int cycleMs)
{
    for (const GemmaStep& step : program.steps) {
        if (!step.nested)
            continue;
        for (const NestedTimer& timer : step.nested->timers) {
            if (timer.durationMs > cycleMs)
                return true;
        }
    }
    return false;
}

class BothLayers {
public:
    BothLayers(const Model& model, const VerificationOptions& options, VerificationResult& result,
               std::chrono::steady_clock::time_point deadline)
        : m_model(model)
        , m_options(options)
        , m_result(result)
        , m_deadline(deadline)
        , m_program(buildGemmaProgram(model))
        , m_properties(propertiesToCheck(model, options))
        , m_closedLoop(runsClosedLoop(model, options))
    {
    }

    void run();

private:
    explore::Options explorationOptions(bool exactTime) const;
    void refine();
    void replaceGemmaFindings();
    void addNestedFacts();
    void addEvents();
    void addProperties();
    bool confirmPropertyViolation(VerificationFinding& f, bool exactSearchCut);
    void addUndecided(std::size_t property, const std::string& reason);
    void add(VerificationFinding finding, const Event* event);
    VerificationFinding finding(const Event& event) const;
    std::vector<std::string> waitingTransitions(const std::string& stepId) const;
    std::vector<std::string> laterTransitions(const std::string& transitionId) const;
    bool isFamily(const std::string& transitionId) const;
    bool isContinuousOutput(const std::string& variable) const;

    const Model& m_model;
    const VerificationOptions& m_options;
    VerificationResult& m_result;
    std::chrono::steady_clock::time_point m_deadline; // the whole run's: both explorations share it
    GemmaProgram m_program;
    std::vector<std::string> m_properties;
    // With the machine, the exploration decides every finding that claims a
    // run (GV101, GV102, GV105-GV107, and GV103, GV104 when it decides them)
    // with or without nested GRAFCETs: the GEMMA layer had every input free.
    bool m_closedLoop = false;
    std::unique_ptr<explore::ProgramExplorer> m_explorer;
    std::unique_ptr<explore::ProgramExplorer> m_exact; // the refinement with exact time, when it ran
    std::set<std::string> m_exactKeys;
    std::vector<VerificationFinding> m_added;
    std::set<int> m_violated;
    std::map<int, std::string> m_undecided; // property -> why its abstract violation was not shown real
};

explore::Options BothLayers::explorationOptions(bool exactTime) const
{
    explore::Options options;
    options.complete = m_options.complete;
    options.properties = m_properties;
    options.exactTime = exactTime;
    options.decidePriorities = m_program.hasNestedGrafcets() || m_closedLoop;
    options.machine = m_closedLoop ? &m_model.machine() : nullptr;
    options.singleFaults = m_closedLoop && m_options.faults == VerificationOptions::Faults::Single;
    options.maxStates = m_options.maxProgramStates;
    options.hideWriteOnlyVariables = m_options.hideWriteOnlyVariables;
    options.cancelled = m_options.cancelled;
    options.deadline = m_deadline;
    return options;
}

void BothLayers::run()
{
    m_explorer = std::make_unique<explore::ProgramExplorer>(m_model, explorationOptions(m_options.exactTime));
    const explore::Exploration& e = m_explorer->run();
    m_result.bothLayers = true;
    m_result.programStates = e.states;
    m_result.singleFaults = m_closedLoop && m_options.faults == VerificationOptions::Faults::Single;
    m_result.faultChoices = e.faultChoices;
    m_result.faultedStates = e.faultedStates;
    m_result.abstractions = e.abstractions;
    m_result.properties = m_properties;
    if (e.cancelled) {
        m_result.cancelled = true;
        m_result.exhaustive = false;
        return;
    }
    if (!e.exhaustive) {
        m_result.exhaustive = false;
        VerificationFinding undecided;
        undecided.code = code::kIncomplete;
        undecided.severity = Severity::Warning;
        undecided.elements = {"model"};
        undecided.arguments = {"model"};
        undecided.message = "the exploration of both layers stopped after " + std::to_string(e.states)
            + " states (its time or size limit): what it found is reported, nothing about the nested GRAFCETs or "
              "the properties is proved";
        m_added.push_back(undecided);
    }
    refine();
    if (e.exhaustive && (m_program.hasNestedGrafcets() || m_closedLoop))
        replaceGemmaFindings();
    addNestedFacts();
    addEvents();
    addProperties();
    for (VerificationFinding& f : m_added) {
        f.origin = FindingOrigin::BothLayers;
        if (f.arguments.empty())
            f.arguments = f.elements; // as the GEMMA-layer findings: what the message names
        m_result.findings.push_back(std::move(f));
    }
    std::stable_sort(m_result.findings.begin(), m_result.findings.end(),
                     [](const VerificationFinding& a, const VerificationFinding& b) { return a.code < b.code; });
}

// Under the timer abstraction a run may let a TON elapse sooner than the PLC
// would: such counterexamples do not replay. Exploring again with time
// counted in scans finds the real run, or shows there is none. That
// exploration is a search for the runs that do not replay: it stops once
// it has found them all (counting time in scans multiplies the states by
// the TONs' durations in scans), and runs to the end only when one of them
// has no real run.
void BothLayers::refine()
{
    // In closed loop the machine's travels are abstracted as the TONs are.
    if (m_options.exactTime || (!m_closedLoop && !hasLongTimers(m_program, m_model.settings().cycleTimeMs)))
        return;
    const std::vector<Event>& events = m_explorer->result().events;
    const bool anyPath
        = std::any_of(events.begin(), events.end(), [](const Event& event) { return !event.stateOnly; });
    if (!anyPath)
        return;
    // add() looks for a run counted in scans only where the abstract one does
    // not replay; an AlwaysTrue's run only illustrates it and is never sought.
    std::set<std::string> unconfirmed;
    for (const Event& event : events) {
        if (event.kind != EventKind::AlwaysTrue && !m_explorer->counterexample(event, "replay").confirmed)
            unconfirmed.insert(eventKey(event));
    }
    if (unconfirmed.empty())
        return;
    explore::Options options = explorationOptions(true);
    if (!m_options.wholeExactTimeExploration)
        options.searchFor = std::move(unconfirmed);
    m_exact = std::make_unique<explore::ProgramExplorer>(m_model, std::move(options));
    const explore::Exploration& exact = m_exact->run();
    for (const Event& event : exact.events)
        m_exactKeys.insert(eventKey(event));
}

void BothLayers::replaceGemmaFindings()
{
    const explore::Exploration& e = m_explorer->result();
    std::set<std::string> replaced{code::kUnreachableStep, code::kDeadTransition, code::kNoReturn, code::kStuck,
                                   code::kNoEmergencyStop};
    if (e.prioritiesDecided) {
        replaced.insert(code::kAlwaysTrue);
        replaced.insert(code::kOverlap);
    }
    std::vector<VerificationFinding> kept;
    for (VerificationFinding& f : m_result.findings) {
        if (replaced.count(f.code))
            continue;
        f.origin = FindingOrigin::GemmaLayerKept;
        // Only when the budget ran out while probing both layers: GV103 and
        // GV104 stay decided on the GEMMA layer, where a nested GRAFCET's
        // Complete is free, so their runs may not exist on both.
        if (f.counterexample && !f.counterexample->confirmed) {
            if (const std::size_t note = f.message.find(" (not confirmed:"); note != std::string::npos)
                f.message.erase(note);
            f.message += " (decided on the GEMMA layer with Complete free: the run does not replay on both layers)";
        }
        kept.push_back(std::move(f));
    }
    m_result.findings = std::move(kept);
    m_result.reachableSteps = e.reachableSteps;
    m_result.fireableTransitions = e.fireableTransitions;
    m_result.maxDepth = e.maxDepth;
    for (const GemmaStep& step : m_program.steps) {
        if (std::find(e.reachableSteps.begin(), e.reachableSteps.end(), step.id) != e.reachableSteps.end())
            continue;
        VerificationFinding f;
        f.code = code::kUnreachableStep;
        f.elements = {step.id};
        for (const Transition* incoming : m_model.incoming(step.id)) {
            if (m_model.isEffective(*incoming))
                f.elements.push_back(incoming->id);
        }
        f.message = f.elements.size() == 1 ? "no effective transition leads to " + step.id
                                           : "no situation reachable from the initial step lets a transition into "
                                                 + step.id + " fire (both layers explored)";
        m_added.push_back(f);
    }
    std::set<std::string> seen;
    for (const GemmaStep& step : m_program.steps) {
        if (std::find(e.reachableSteps.begin(), e.reachableSteps.end(), step.id) == e.reachableSteps.end())
            continue;
        for (const GemmaTransition& t : step.transitions) {
            if (!seen.insert(t.id).second
                || std::find(e.fireableTransitions.begin(), e.fireableTransitions.end(), t.id)
                    != e.fireableTransitions.end())
                continue;
            VerificationFinding f;
            f.code = code::kDeadTransition;
            f.elements = {t.id};
            f.message = t.id + " can never fire: no reachable scan of both layers fires it";
            m_added.push_back(f);
        }
    }
}

void BothLayers::addNestedFacts()
{
    const explore::Exploration& e = m_explorer->result();
    m_result.reachableNestedSteps = e.activeNestedSteps;
    m_result.fireableNestedTransitions = e.firedNestedTransitions;
    for (const GemmaStep& step : m_program.steps) {
        if (!step.nested)
            continue;
        const bool reached = std::find(e.reachableSteps.begin(), e.reachableSteps.end(), step.id) != e.reachableSteps.end();
        m_result.reachableNestedSteps[step.id];
        m_result.fireableNestedTransitions[step.id];
        if (!e.exhaustive || !reached)
            continue; // an unreachable GEMMA step is GV101: its GRAFCET is not blamed
        const std::vector<int>& active = m_result.reachableNestedSteps[step.id];
        for (const NestedStep& s : step.nested->steps) {
            if (std::binary_search(active.begin(), active.end(), s.number))
                continue;
            VerificationFinding f;
            f.code = code::kNestedStepNeverActive;
            f.gemmaStep = step.id;
            f.elements = {nestedStep(step.id, s.number)};
            f.arguments = {step.id, std::to_string(s.number)};
            f.message = "step " + std::to_string(s.number) + " of the GRAFCET of " + step.id
                + " can never become active";
            m_added.push_back(f);
        }
        const std::vector<int>& fired = m_result.fireableNestedTransitions[step.id];
        for (const NestedTransition& t : step.nested->transitions) {
            if (std::binary_search(fired.begin(), fired.end(), t.number))
                continue;
            VerificationFinding f;
            f.code = code::kNestedTransitionDead;
            f.gemmaStep = step.id;
            f.elements = {nestedTransition(step.id, t.number)};
            f.arguments = {step.id, std::to_string(t.number)};
            f.message = "transition " + std::to_string(t.number) + " of the GRAFCET of " + step.id
                + " can never fire";
            m_added.push_back(f);
        }
        if (!e.completeSeen.count(step.id)) {
            for (const std::string& id : waitingTransitions(step.id)) {
                VerificationFinding f;
                f.code = code::kWaitsForNoComplete;
                f.elements = {id};
                f.arguments = {id, step.id};
                f.message = id + " waits for the Complete of " + step.id + ", which never becomes TRUE";
                m_added.push_back(f);
            }
        }
    }
}

std::vector<std::string> BothLayers::waitingTransitions(const std::string& stepId) const
{
    std::vector<std::string> ids;
    if (const GemmaStep* step = m_program.step(stepId)) {
        for (const GemmaTransition& t : step->transitions) {
            if (t.waitsForComplete && t.conditionUsable)
                ids.push_back(t.id);
        }
    }
    return ids;
}

// The transitions evaluated after it by the reachable steps that evaluate it.
std::vector<std::string> BothLayers::laterTransitions(const std::string& transitionId) const
{
    const std::vector<std::string>& reachable = m_explorer->result().reachableSteps;
    std::vector<std::string> later;
    for (const GemmaStep& step : m_program.steps) {
        if (std::find(reachable.begin(), reachable.end(), step.id) == reachable.end())
            continue;
        bool after = false;
        for (const GemmaTransition& t : step.transitions) {
            if (after && std::find(later.begin(), later.end(), t.id) == later.end())
                later.push_back(t.id);
            after = after || t.id == transitionId;
        }
    }
    return later;
}

bool BothLayers::isFamily(const std::string& transitionId) const
{
    for (const GemmaStep& step : m_program.steps) {
        for (const GemmaTransition& t : step.transitions) {
            if (t.id == transitionId)
                return t.family;
        }
    }
    return false;
}

bool BothLayers::isContinuousOutput(const std::string& variable) const
{
    for (const GemmaStep& step : m_program.steps) {
        if (step.nested && step.nested->output(variable))
            return true;
    }
    return false;
}

VerificationFinding BothLayers::finding(const Event& event) const
{
    VerificationFinding f;
    f.gemmaStep = event.stepId;
    const std::string& s = event.stepId;
    const auto n = [&](std::size_t i) { return std::to_string(event.numbers[i]); };
    switch (event.kind) {
    case EventKind::UnsafeStep:
        f.code = code::kUnsafeNestedStep;
        f.elements = {nestedStep(s, event.numbers[0])};
        f.arguments = {s, n(0)};
        f.message = "step " + n(0) + " of the GRAFCET of " + s
            + " can be activated while it is already active (the GRAFCET is not safe)";
        break;
    case EventKind::Unstable:
        f.code = code::kUnstableReachable;
        f.elements = {s};
        f.arguments = {s};
        f.message = "the GRAFCET of " + s + " can be Unstable: its evolutions do not settle within one scan";
        break;
    case EventKind::SimultaneousBranches:
        f.code = code::kBranchesTogether;
        f.elements = {nestedTransition(s, event.numbers[1]), nestedTransition(s, event.numbers[2])};
        f.arguments = {s, n(0), n(1), n(2)};
        f.message = "transitions " + n(1) + " and " + n(2) + " of the GRAFCET of " + s + " can fire together from step "
            + n(0) + ": both branches of the selection start";
        break;
    case EventKind::Race:
        f.code = code::kStoredRace;
        f.elements = {nestedStep(s, event.numbers[0]), nestedStep(s, event.numbers[1])};
        f.arguments = {s, n(0), n(1), event.variable};
        f.message = "steps " + n(0) + " and " + n(1) + " of the GRAFCET of " + s + " can write different values to "
            + event.variable + " in the same scan: the result depends on the order of the actions";
        break;
    case EventKind::OutputOnD1:
        f.gemmaStep.clear();
        f.elements = {"D1"};
        f.arguments = {"D1", event.variable};
        if (isContinuousOutput(event.variable)) {
            f.code = code::kOutputOnEmergencyStop;
            f.severity = Severity::Error;
            f.message = "the continuous output " + event.variable
                + " can still be TRUE in the scan in which D1 is entered";
        } else {
            f.code = code::kStoredOutputOnEmergencyStop;
            f.severity = Severity::Info;
            f.message = "the stored output " + event.variable
                + " can still be TRUE in the scan in which D1 is entered: stored actions are memories, only "
                  "continuous outputs drop with the state";
        }
        break;
    case EventKind::PropertyViolated: {
        f.gemmaStep.clear();
        f.code = code::kPropertyViolated;
        f.severity = Severity::Error;
        f.property = event.property;
        const std::string& text = m_properties[static_cast<std::size_t>(event.property)];
        f.arguments = {text};
        f.message = "the property " + quoted(text) + " does not hold";
        break;
    }
    case EventKind::StuckWithoutComplete: {
        f.code = code::kNeverComplete;
        f.severity = Severity::Error;
        f.elements = {s};
        f.arguments = {s};
        for (const std::string& id : waitingTransitions(s)) {
            f.elements.push_back(id);
            f.arguments.push_back(id);
        }
        f.message = "once " + s + " is active, the inputs can lead its GRAFCET to a situation from which Complete "
            + "never becomes TRUE: the transitions that wait for it can no longer fire";
        break;
    }
    case EventKind::Stuck:
        f.gemmaStep.clear();
        f.code = code::kStuck;
        f.severity = Severity::Error;
        f.elements = {s};
        f.message = "the machine can get stuck in " + s + ": from some reachable situation of both layers no "
            + "transition out of it can ever fire";
        break;
    case EventKind::NoReturn:
        f.gemmaStep.clear();
        f.code = code::kNoReturn;
        f.elements = {s};
        f.message = "once " + s + " is active, the inputs can lead to a situation from which the initial step can "
            + "never become active again";
        break;
    case EventKind::AlwaysTrue: {
        f.gemmaStep.clear();
        f.code = code::kAlwaysTrue;
        f.elements = {event.transition};
        const std::vector<std::string> later = laterTransitions(event.transition);
        if (isFamily(event.transition)) {
            f.message = "the condition of " + event.transition
                + " is always TRUE: no own transition of an F step can ever fire";
            break;
        }
        f.elements.insert(f.elements.end(), later.begin(), later.end());
        std::string named;
        for (std::size_t i = 0; i < later.size(); ++i)
            named += (i ? " and " : "") + later[i];
        f.message = "the condition of " + event.transition + " is always TRUE when " + s + " is active: " + named
            + " can never fire";
        break;
    }
    case EventKind::Overlap: {
        f.gemmaStep.clear();
        f.code = code::kOverlap;
        f.severity = Severity::Info;
        const GemmaStep* step = m_program.step(s);
        const std::string& higher = step->transitions[static_cast<std::size_t>(event.numbers[0])].id;
        const std::string& lower = step->transitions[static_cast<std::size_t>(event.numbers[1])].id;
        f.elements = {higher, lower};
        f.message = higher + " and " + lower + " can both be TRUE in the same scan: the priority decides, " + higher
            + " fires";
        break;
    }
    case EventKind::NoEmergencyStop:
        f.gemmaStep.clear();
        f.code = code::kNoEmergencyStop;
        f.severity = Severity::Error;
        f.elements = {s, "F->D1"};
        f.message = "in some situation of both layers in " + s + " no scan can enter the emergency stop D1";
        break;
    }
    if (f.arguments.empty())
        f.arguments = f.elements;
    return f;
}

void BothLayers::add(VerificationFinding f, const Event* event)
{
    if (event) {
        const explore::ProgramExplorer* explorer = m_explorer.get();
        const Event* witness = event;
        Event exactEvent;
        bool exactSearchCut = false;
        Counterexample counterexample = explorer->counterexample(*event, f.code + " " + f.message);
        if (event->kind == EventKind::AlwaysTrue) {
            // A "never FALSE" claim: the run that fires it only illustrates it.
            if (counterexample.confirmed)
                f.counterexample = std::move(counterexample);
            m_added.push_back(std::move(f));
            return;
        }
        if (!counterexample.confirmed && m_exact) {
            const std::string key = eventKey(*event);
            for (const Event& candidate : m_exact->result().events) {
                if (eventKey(candidate) == key) {
                    exactEvent = candidate;
                    witness = &exactEvent;
                    counterexample = m_exact->counterexample(exactEvent, f.code + " " + f.message);
                    break;
                }
            }
            if (witness == event && m_exact->result().exhaustive && !m_exactKeys.count(key)) {
                // Counted in scans, no run shows it: the time abstraction (of the TONs, of the machine) alone made it.
                return;
            }
            // Counted in scans, the search stopped at the run's limit before it met a run that shows it.
            exactSearchCut = witness == event && !m_exact->result().exhaustive;
        }
        f.counterexample = std::move(counterexample);
        if (f.code == code::kPropertyViolated && !f.counterexample->confirmed
            && !confirmPropertyViolation(f, exactSearchCut))
            return;
        if (!f.counterexample->confirmed) {
            f.severity = Severity::Info;
            f.replaySearchCut = exactSearchCut;
            f.message += std::string(" (not confirmed: the run found under the abstractions does not replay in the "
                                     "simulator")
                + (exactSearchCut ? kReplaySearchCut : "") + ")";
        }
    }
    if (f.code == code::kPropertyViolated && f.severity != Severity::Info)
        m_violated.insert(f.property);
    m_added.push_back(std::move(f));
}

// The exploration's run of a violation does not replay (numeric memories
// take any value there, ...): the simulator's own runs are searched for a
// real one. Without it the property is undecided, never violated nor holding.
bool BothLayers::confirmPropertyViolation(VerificationFinding& f, bool exactSearchCut)
{
    // Not "does not replay" when the search was cut: given more time it may find the run.
    const std::string cut = exactSearchCut ? kReplaySearchCut : "";
    if (m_closedLoop) {
        // The simulator's search runs open loop: its runs could set what the machine drives.
        m_undecided[f.property] = "the violation the exploration with the machine found rests on its abstractions "
                                  "and does not replay in the simulator with the machine"
            + cut;
        return false;
    }
    ConcreteSearchOptions options;
    options.complete = m_options.complete;
    options.maxStates = m_options.maxConcreteStates;
    options.cancelled = m_options.cancelled;
    if (m_options.timeLimit.count() > 0)
        options.deadline = std::chrono::steady_clock::now() + m_options.timeLimit;
    const std::string& text = m_properties[static_cast<std::size_t>(f.property)];
    ConcreteSearchResult search = searchPropertyViolation(m_model, text, f.code + " " + f.message, options);
    if (search.counterexample) {
        f.counterexample = std::move(search.counterexample);
        return true;
    }
    m_undecided[f.property] = "the violation the exploration found rests on its abstractions and does not replay "
                              "in the simulator"
        + cut + "; " + search.reason;
    return false;
}

void BothLayers::addUndecided(std::size_t property, const std::string& reason)
{
    const std::string& text = m_properties[property];
    m_result.propertyVerdicts[property] = PropertyVerdict{PropertyOutcome::Undecided, reason};
    VerificationFinding f;
    f.code = code::kPropertyUndecided;
    f.severity = Severity::Warning;
    f.property = static_cast<int>(property);
    f.arguments = {text, reason};
    f.message = "the property " + quoted(text) + " is undecided: " + reason;
    m_added.push_back(f);
}

void BothLayers::addEvents()
{
    const explore::Exploration& e = m_explorer->result();
    for (const Event& event : e.events) {
        if (!m_program.hasNestedGrafcets() && !m_closedLoop
            && (event.kind == EventKind::Stuck || event.kind == EventKind::NoReturn
                || event.kind == EventKind::NoEmergencyStop))
            continue; // the GEMMA-layer analysis decides these without nested GRAFCETs
        if (event.kind == EventKind::AlwaysTrue || event.kind == EventKind::Overlap) {
            if (!e.exhaustive || !e.prioritiesDecided)
                continue; // the GEMMA layer's stay (replaceGemmaFindings)
            if (event.kind == EventKind::AlwaysTrue && laterTransitions(event.transition).empty())
                continue; // always TRUE, but nothing comes after it to block
        }
        VerificationFinding f = finding(event);
        if (event.kind == EventKind::UnsafeStep)
            m_result.unsafeNestedSteps[event.stepId].push_back(event.numbers[0]);
        if (event.kind == EventKind::Unstable)
            m_result.unstableSteps.push_back(event.stepId);
        add(std::move(f), &event);
    }
    for (auto& [id, list] : m_result.unsafeNestedSteps)
        std::sort(list.begin(), list.end());
    std::sort(m_result.unstableSteps.begin(), m_result.unstableSteps.end());
}

void BothLayers::addProperties()
{
    const explore::Exploration& e = m_explorer->result();
    m_result.propertyHolds.assign(m_properties.size(), false);
    m_result.propertyVerdicts.assign(m_properties.size(), PropertyVerdict{});
    for (std::size_t p = 0; p < m_properties.size(); ++p) {
        const std::string& text = m_properties[p];
        const int index = static_cast<int>(p);
        if (!e.propertyChecked[p]) {
            const std::vector<PropertyProblem> problems
                = checkProperty(m_model, text, PropertyAtoms{m_result.singleFaults});
            const std::string why = problems.empty() ? std::string("it is empty") : problems.front().message;
            m_result.propertyVerdicts[p] = PropertyVerdict{PropertyOutcome::Undecided, "it cannot be checked: " + why};
            VerificationFinding f;
            f.code = code::kPropertyUnusable;
            f.property = index;
            f.arguments = {text, problems.empty() ? std::string() : problems.front().message};
            f.message = "the property " + quoted(text) + " cannot be checked: " + why;
            m_added.push_back(f);
            continue;
        }
        if (m_violated.count(index)) {
            m_result.propertyVerdicts[p] = PropertyVerdict{PropertyOutcome::Violated, {}};
            continue;
        }
        if (const auto undecided = m_undecided.find(index); undecided != m_undecided.end()) {
            addUndecided(p, undecided->second);
            continue;
        }
        if (!e.exhaustive) {
            addUndecided(p, "the exploration of both layers stopped at its time or size limit before deciding it");
            continue;
        }
        m_result.propertyHolds[p] = true;
        m_result.propertyVerdicts[p] = PropertyVerdict{PropertyOutcome::Holds, {}};
        VerificationFinding f;
        f.code = code::kPropertyHolds;
        f.severity = Severity::Info;
        f.property = index;
        f.arguments = {text};
        f.message = "the property " + quoted(text) + " holds in every reachable scan";
        if (!e.abstractions.empty())
            f.message += " (with the abstractions listed)";
        m_added.push_back(f);
    }
}

} // namespace

bool needsBothLayers(const Model& model, const VerificationOptions& options)
{
    return !model.grafcets().empty() || !propertiesToCheck(model, options).empty() || runsClosedLoop(model, options);
}

std::vector<std::string> propertiesToCheck(const Model& model, const VerificationOptions& options)
{
    std::vector<std::string> texts;
    for (const UserProperty& property : model.properties())
        texts.push_back(property.text);
    for (const std::string& text : options.properties)
        texts.push_back(text);
    return texts;
}

void verifyBothLayers(const Model& model, const VerificationOptions& options, VerificationResult& result,
                      std::chrono::steady_clock::time_point deadline)
{
    BothLayers(model, options, result, deadline).run();
}

} // namespace core
