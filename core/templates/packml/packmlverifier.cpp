#include "core/templates/packml/packmlverifier.h"

#include "core/model/model.h"
#include "core/templates/packml/packmlcompletion.h"
#include "core/templates/packml/packmlcounterexample.h"
#include "core/templates/packml/packmldiagnostics.h"
#include "core/templates/packml/packmlexplorer.h"
#include "core/templates/packml/packmlproperty.h"
#include "core/verification/bothlayers.h"

#include <algorithm>
#include <memory>
#include <set>

namespace core::packml {

namespace {

// Each explored configuration keeps a copy of the simulator (a few kB):
// this bounds the memory whatever VerificationOptions::maxProgramStates says.
constexpr std::size_t kMaxExploredConfigurations = 100'000;

Severity severityOf(const std::string& code)
{
    if (code == verification::kStoredOutputOnAbort)
        return Severity::Info;
    if (code == verification::kNeverActive || code == verification::kNeverAccepted || code == core::verification::kIncomplete)
        return Severity::Warning;
    return Severity::Error;
}

class PackmlVerifier {
public:
    PackmlVerifier(const Model& model, PackmlProgram program, const VerificationOptions& options)
        : m_model(model)
        , m_configuration(*model.packml())
        , m_texts(propertiesToCheck(model, options))
        , m_limits(limits(options, m_texts, m_properties))
        , m_explorer(model, std::move(program), m_limits)
    {
        for (const std::string& text : m_texts) {
            m_problems.push_back(checkPackmlProperty(model, text));
            m_properties.push_back(parsePackmlProperty(text, m_explorer.program()));
        }
    }

    VerificationResult run();

private:
    ExplorerLimits limits(const VerificationOptions& options, const std::vector<std::string>& texts,
                          const std::vector<PackmlProperty>& properties) const;
    void reportProperties();
    std::string modeName(int number) const;
    VerificationFinding finding(const std::string& code, std::string message, Diagnostic location) const;
    Diagnostic modeLocation(int mode, std::optional<State> state, const std::string& code, const std::string& message) const;
    void reportWitness(const ExploredWitness& witness);
    static void appendScanArguments(VerificationFinding& f, const ScanFinding& s);
    void reportStuck();
    void reportNeverActive();
    void reportNeverAccepted();
    void reportUndecided();
    Counterexample counterexampleTo(const PackmlExplorer& explorer, std::size_t node, const std::vector<InputChoice>& lastScan,
                                    const std::string& title, int expectedMode) const;
    // Never-claims hold: every run was explored (the timer abstraction only adds runs).
    bool neverSound() const { return m_explorer.exhaustive() && !m_explorer.runsLeftOut(); }
    // Time counted in scans: searches the PLC's runs for what the abstraction found (built once).
    const PackmlExplorer& exactExplorer();
    // The exact search was exhaustive: what it did not see does not happen.
    bool exactSearchDecides() { return exactExplorer().exhaustive() && !exactExplorer().runsLeftOut(); }
    std::optional<ExploredWitness> exactWitness(const ExploredWitness& witness);
    bool confirmScan(const PackmlExplorer& explorer, const ExploredWitness& witness, VerificationFinding& f,
                     const std::string& title);
    bool replaysToNode(const PackmlExplorer& explorer, std::size_t node, const Counterexample& counterexample) const;
    VerificationFinding stuckFinding(const PackmlExplorer& explorer, std::size_t node) const;

    const Model& m_model;
    const Configuration& m_configuration;
    std::vector<std::string> m_texts;               // the model's properties, then the options'
    std::vector<std::vector<PropertyProblem>> m_problems; // per property: why it cannot be checked
    std::vector<PackmlProperty> m_properties;
    ExplorerLimits m_limits;
    PackmlExplorer m_explorer;
    std::unique_ptr<PackmlExplorer> m_exact;
    std::set<std::pair<int, State>> m_stuckUndecided; // GV130/GV131 neither shown nor excluded
    VerificationResult m_result;
};

ExplorerLimits PackmlVerifier::limits(const VerificationOptions& options, const std::vector<std::string>& texts,
                                      const std::vector<PackmlProperty>& properties) const
{
    ExplorerLimits limits;
    // The properties are parsed once the explorer's program exists; the
    // callback reads them when the run starts.
    for (const std::string& text : texts) {
        const ParsedProperty parsed = parseProperty(text);
        for (const cond::Node& node : parsed.expression.nodes)
            if (node.kind == cond::NodeKind::Variable)
                limits.alwaysRead.push_back(node.text);
    }
    limits.violatedProperties = [this, &properties](const PackmlSimulator& simulator) {
        std::vector<int> violated;
        for (std::size_t i = 0; i < properties.size(); ++i)
            if (m_problems[i].empty() && packmlPropertyViolated(properties[i], simulator))
                violated.push_back(static_cast<int>(i));
        return violated;
    };
    limits.maxStates = std::min(options.maxProgramStates, kMaxExploredConfigurations);
    if (options.timeLimit.count() > 0)
        limits.deadline = std::chrono::steady_clock::now() + options.timeLimit;
    limits.cancelled = options.cancelled;
    limits.exactTime = options.exactTime;
    return limits;
}

std::string PackmlVerifier::modeName(int number) const
{
    const Mode* mode = m_configuration.mode(number);
    return mode ? modeLabel(*mode) : std::to_string(number);
}

Diagnostic PackmlVerifier::modeLocation(int mode, std::optional<State> state, const std::string& code,
                                        const std::string& message) const
{
    const Mode* found = m_configuration.mode(mode);
    Finding f{code, severityOf(code), "", message, {modeName(mode)}};
    if (!found)
        return modelDiagnostic(std::move(f));
    if (state) {
        f.arguments.push_back(std::string(stateName(*state)));
        return modeStateDiagnostic(*found, *state, std::move(f));
    }
    return modeDiagnostic(*found, std::move(f));
}

VerificationFinding PackmlVerifier::finding(const std::string& code, std::string message, Diagnostic location) const
{
    VerificationFinding f;
    f.code = code;
    f.severity = severityOf(code);
    f.elements = {diagnosticElementLabel(location)};
    f.message = std::move(message);
    f.arguments = location.arguments;
    f.origin = FindingOrigin::PackML;
    f.location = std::move(location);
    return f;
}

Counterexample PackmlVerifier::counterexampleTo(const PackmlExplorer& explorer, std::size_t node,
                                                const std::vector<InputChoice>& lastScan, const std::string& title,
                                                int expectedMode) const
{
    std::vector<InputChoice> scans = explorer.path(node);
    scans.insert(scans.end(), lastScan.begin(), lastScan.end());
    return writeCounterexample(explorer.nodes().front().simulator, scans, title, modeName(expectedMode));
}

const PackmlExplorer& PackmlVerifier::exactExplorer()
{
    if (!m_exact) {
        ExplorerLimits limits = m_limits;
        limits.exactTime = true;
        m_exact = std::make_unique<PackmlExplorer>(m_model, m_explorer.program(), std::move(limits));
        m_exact->run();
    }
    return *m_exact;
}

std::optional<ExploredWitness> PackmlVerifier::exactWitness(const ExploredWitness& witness)
{
    for (const ExploredWitness& w : exactExplorer().witnesses())
        if (w.property == witness.property && w.finding.code == witness.finding.code
            && w.finding.mode == witness.finding.mode && w.finding.state == witness.finding.state)
            return w;
    return std::nullopt;
}

// The counterexample to the scan of `witness` in `explorer`'s run, and
// whether it replays to the same finding (or property violation).
bool PackmlVerifier::confirmScan(const PackmlExplorer& explorer, const ExploredWitness& witness, VerificationFinding& f,
                                 const std::string& title)
{
    const ExploredNode& from = explorer.nodes()[witness.node];
    const InputChoice choice = explorer.inputChoices().choices(from.simulator)[witness.choice];
    PackmlSimulator after = from.simulator;
    const int mode = PackmlExplorer::runScan(after, choice).mode; // the mode manager reads no TON
    f.counterexample = counterexampleTo(explorer, witness.node, std::vector<InputChoice>{choice}, title, mode);
    const std::optional<Replay> replayed = replay(explorer.nodes().front().simulator, *f.counterexample);
    bool confirmed = false;
    if (replayed && witness.property >= 0) {
        confirmed = packmlPropertyViolated(m_properties[static_cast<std::size_t>(witness.property)], replayed->after);
    } else if (replayed) {
        const ScanFinding& s = witness.finding;
        for (const ScanFinding& again : checkScan(explorer.reference(), replayed->ghost, replayed->facts))
            confirmed = confirmed || (again.code == s.code && again.mode == s.mode && again.state == s.state);
    }
    f.counterexample->confirmed = confirmed;
    return confirmed;
}

// What the editor's wording needs besides the mode (and GV132's state):
// GV133 the state the mode changed in; GV136, GV137 the state entered and
// the outputs; GV138 which rule broke ("afresh", "resumed", "situation").
void PackmlVerifier::appendScanArguments(VerificationFinding& f, const ScanFinding& s)
{
    if (s.code == verification::kModeChangeOutside) {
        f.arguments.push_back(std::string(stateName(s.state)));
    } else if (s.code == verification::kOutputOnAbort || s.code == verification::kStoredOutputOnAbort) {
        std::string outputs;
        for (const std::string& name : s.names)
            outputs += (outputs.empty() ? "" : ", ") + name;
        f.arguments.push_back(std::string(stateName(s.state)));
        f.arguments.push_back(outputs);
    } else if (s.code == verification::kExecuteEntry) {
        const bool afresh = s.message.find("afresh instead") != std::string::npos;
        const bool resumed = s.message.find("resumed where") != std::string::npos;
        f.arguments.push_back(afresh ? "afresh" : resumed ? "resumed" : "situation");
    }
}

// A run found under the timer abstraction may let a TON elapse sooner than
// the PLC's: when it does not replay, the PLC's runs (time counted in scans)
// are searched. One found replaces it; none in an exhaustive search drops
// the finding; otherwise it is reported as info, "(not confirmed: ...)".
void PackmlVerifier::reportWitness(const ExploredWitness& witness)
{
    const ScanFinding& s = witness.finding;
    const bool located = s.code == verification::kDisabledStateActive;
    const std::string& message = s.message; // the location names the mode
    VerificationFinding f = finding(s.code, message, modeLocation(s.mode, located ? std::optional<State>(s.state) : std::nullopt,
                                                                 s.code, message));
    appendScanArguments(f, s);
    const std::string title = s.code + ": " + modeName(s.mode) + ": " + message;
    bool confirmed = confirmScan(m_explorer, witness, f, title);
    if (!confirmed && m_explorer.timeAbstracted()) {
        if (const std::optional<ExploredWitness> exact = exactWitness(witness))
            confirmed = confirmScan(exactExplorer(), *exact, f, title);
        else if (exactSearchDecides())
            return; // counted in scans, no run shows it: the timer abstraction alone made it
    }
    if (!confirmed) {
        f.severity = Severity::Info;
        f.message += m_explorer.timeAbstracted()
                         ? " (not confirmed: its counterexample does not replay in the simulator, and no run with time "
                           "counted in scans was found within the budget)"
                         : " (not confirmed: its counterexample does not replay to it in the simulator)";
        if (m_explorer.timeAbstracted())
            f.counterexample.reset(); // as for GEMMA: a run that may not exist is not offered
    }
    m_result.findings.push_back(std::move(f));
}

// The counterexample replays to a configuration with the node's key: one
// the node stands for, so what the graph says of the node's futures holds of it.
bool PackmlVerifier::replaysToNode(const PackmlExplorer& explorer, std::size_t node, const Counterexample& counterexample) const
{
    const std::optional<Replay> replayed = replay(explorer.nodes().front().simulator, counterexample);
    if (!replayed)
        return false;
    const ExploredNode& target = explorer.nodes()[node];
    return explorer.key(replayed->after, nextGhost(replayed->ghost, replayed->facts)) == explorer.key(target.simulator, target.ghost);
}

// GV130, GV131: configurations of an acting state from which no run that
// stays in it (no transition, no mode change) reaches a scan whose SC fires.
// The claim needs a real configuration: one its counterexample replays to.
// Where a path to SC exists only under the timer abstraction
// (packmlcompletion.h), or the stuck configuration does not replay, the
// state is decided with time counted in scans when that search is
// exhaustive, and left undecided otherwise.
void PackmlVerifier::reportStuck()
{
    const Completion found = completion(m_explorer);
    std::set<std::pair<int, State>> candidates;
    std::vector<VerificationFinding> unconfirmed;
    for (std::size_t n = 0; n < m_explorer.nodes().size(); ++n) { // shortest first: breadth-first order
        const PackmlSimulator& s = m_explorer.nodes()[n].simulator;
        if (!isActing(s.state()) || s.fault() || found.sure[n])
            continue;
        const std::pair<int, State> at{s.mode(), s.state()};
        if (found.possible[n] || !candidates.insert(at).second)
            continue;
        VerificationFinding f = stuckFinding(m_explorer, n);
        if (f.severity == Severity::Error) {
            m_result.findings.push_back(std::move(f));
        } else {
            m_stuckUndecided.insert(at); // not shown on a real run
            unconfirmed.push_back(std::move(f));
        }
    }
    for (std::size_t n = 0; n < m_explorer.nodes().size(); ++n) {
        const PackmlSimulator& s = m_explorer.nodes()[n].simulator;
        if (isActing(s.state()) && !s.fault() && found.possible[n] && !found.sure[n] && !candidates.count({s.mode(), s.state()}))
            m_stuckUndecided.insert({s.mode(), s.state()});
    }
    if (m_stuckUndecided.empty() || !m_explorer.timeAbstracted() || !exactSearchDecides()) {
        for (VerificationFinding& f : unconfirmed)
            m_result.findings.push_back(std::move(f));
        return;
    }
    // Counted in scans, every run was seen: it decides each state left open.
    const PackmlExplorer& exact = exactExplorer();
    const Completion counted = completion(exact);
    for (std::size_t n = 0; n < exact.nodes().size(); ++n) {
        const PackmlSimulator& s = exact.nodes()[n].simulator;
        if (isActing(s.state()) && !s.fault() && !counted.possible[n] && m_stuckUndecided.erase({s.mode(), s.state()}))
            m_result.findings.push_back(stuckFinding(exact, n));
    }
    m_stuckUndecided.clear();
}

// The GV130 or GV131 finding of `explorer`'s node, an error when its
// counterexample replays to that node's configuration (or it is the start).
VerificationFinding PackmlVerifier::stuckFinding(const PackmlExplorer& explorer, std::size_t node) const
{
    const PackmlSimulator& s = explorer.nodes()[node].simulator;
    const bool aborting = s.state() == State::Aborting;
    const std::string code = aborting ? verification::kAbortingStuck : verification::kStuckGrafcet;
    const std::string message = (aborting ? std::string("Aborting can reach a situation from which Aborted is never reached: nothing leaves it")
                    : std::string(stateName(s.state())) + "'s GRAFCET can reach a situation from which Complete never "
                          "becomes TRUE: only Stop or Abort leave it");
    VerificationFinding f = finding(code, message, modeLocation(s.mode(), aborting ? std::nullopt : std::optional(s.state()),
                                                                 code, message));
    f.counterexample = counterexampleTo(explorer, node, {}, code + ": " + modeName(s.mode()) + ": " + message, s.mode());
    if (f.counterexample->scans == 0) {
        f.counterexample.reset(); // the start itself
        return f;
    }
    f.counterexample->confirmed = replaysToNode(explorer, node, *f.counterexample);
    if (!f.counterexample->confirmed) {
        f.severity = Severity::Info;
        f.message += " (not confirmed: its counterexample does not replay to that situation in the simulator)";
        if (explorer.timeAbstracted())
            f.counterexample.reset(); // as for GEMMA: a run that may not exist is not offered
    }
    return f;
}

void PackmlVerifier::reportNeverActive()
{
    const auto& reached = m_explorer.reached();
    for (const Mode& mode : m_configuration.modes) {
        const bool current = std::any_of(reached.begin(), reached.end(), [&](const auto& r) { return r.first == mode.number; });
        if (!current) {
            const std::string message = modeName(mode.number) + " is never the current mode";
            m_result.findings.push_back(finding(verification::kNeverActive, message,
                                                modeLocation(mode.number, std::nullopt, verification::kNeverActive, message)));
            continue;
        }
        for (State state : m_explorer.reference().enabled(mode.number).list()) {
            if (reached.count({mode.number, state}))
                continue;
            const std::string message = std::string(stateName(state)) + " is enabled but never active in this mode";
            m_result.findings.push_back(finding(verification::kNeverActive, message,
                                                modeLocation(mode.number, state, verification::kNeverActive, message)));
        }
    }
}

void PackmlVerifier::reportNeverAccepted()
{
    for (const ProgramCommand& command : m_explorer.nodes().front().simulator.program().commands) {
        if (m_explorer.firedCommands().count(command.command))
            continue;
        const std::string message = "the " + command.name + " command is accepted in no reachable configuration";
        Diagnostic location = commandDiagnostic(command.command, Finding{verification::kNeverAccepted, Severity::Warning, "",
                                                                         message, {command.name}});
        m_result.findings.push_back(finding(verification::kNeverAccepted, message, std::move(location)));
    }
}

void PackmlVerifier::reportUndecided()
{
    std::string why;
    if (m_explorer.budgetReached())
        why = "the exploration stopped at its budget (" + std::to_string(m_explorer.nodes().size())
              + " configurations, or the time limit) before it had seen every configuration";
    for (const std::string& reason : m_explorer.runsLeftOutReasons())
        why += (why.empty() ? "" : "; ") + reason;
    std::string message;
    std::vector<std::string> arguments; // the editor's wording: "stuck" and the states when only those are open
    if (!why.empty()) {
        message = "not exhaustive: " + why
                  + ". GV130, GV131, GV134 and GV135 were not decided, and the absence of the other findings is not a proof";
    } else if (!m_stuckUndecided.empty()) {
        std::string states;
        for (const auto& [mode, state] : m_stuckUndecided)
            states += (states.empty() ? "" : ", ") + modeName(mode) + " " + std::string(stateName(state));
        arguments = {"stuck", states};
        message = "GV130 and GV131 were not decided in " + states
                  + ": timers longer than one cycle may or may not have elapsed, and the runs to Complete found from "
                    "some situations let TONs elapse in an order the PLC's may not";
    } else {
        return;
    }
    m_result.findings.push_back(finding(core::verification::kIncomplete, message,
                                        modelDiagnostic(Finding{core::verification::kIncomplete, Severity::Warning, "",
                                                                message, std::move(arguments)})));
}

void PackmlVerifier::reportProperties()
{
    const bool exact = neverSound();
    for (std::size_t i = 0; i < m_texts.size(); ++i) {
        const std::string& text = m_texts[i];
        VerificationFinding f;
        f.property = static_cast<int>(i);
        f.arguments = {text};
        f.origin = FindingOrigin::PackML;
        f.location = modelDiagnostic(Finding{"", Severity::Info, "", "", {text}});
        PropertyVerdict verdict;
        const auto witness = std::find_if(m_explorer.witnesses().begin(), m_explorer.witnesses().end(),
                                          [&](const ExploredWitness& w) { return w.property == static_cast<int>(i); });
        if (!m_problems[i].empty()) {
            f.code = core::verification::kPropertyUnusable;
            f.severity = Severity::Warning;
            f.message = "the property cannot be checked: " + m_problems[i].front().message;
            verdict.reason = f.message;
        } else if (witness != m_explorer.witnesses().end()) {
            f.code = core::verification::kPropertyViolated;
            f.severity = Severity::Error;
            f.message = "the property is violated at the end of a reachable scan";
            const std::string title = f.code + ": property '" + text + "' violated";
            bool confirmed = confirmScan(m_explorer, *witness, f, title);
            bool dropped = false;
            if (!confirmed && m_explorer.timeAbstracted()) {
                if (const std::optional<ExploredWitness> exact = exactWitness(*witness))
                    confirmed = confirmScan(exactExplorer(), *exact, f, title);
                else
                    dropped = exactSearchDecides();
            }
            if (dropped) {
                // Counted in scans, no run violates it: the timer abstraction alone made the run.
                f.code = core::verification::kPropertyHolds;
                f.severity = Severity::Info;
                f.message = "the property holds at the end of every reachable scan";
                f.counterexample.reset();
                verdict.outcome = PropertyOutcome::Holds;
            } else if (confirmed) {
                verdict.outcome = PropertyOutcome::Violated;
            } else {
                f.severity = Severity::Info;
                f.message += " (not confirmed: its counterexample does not replay to it in the simulator)";
                verdict.reason = "its counterexample does not replay";
                if (m_explorer.timeAbstracted())
                    f.counterexample.reset(); // as for GEMMA: a run that may not exist is not offered
            }
        } else if (exact) {
            f.code = core::verification::kPropertyHolds;
            f.severity = Severity::Info;
            f.message = "the property holds at the end of every reachable scan";
            verdict.outcome = PropertyOutcome::Holds;
        } else {
            f.code = core::verification::kPropertyUndecided;
            f.severity = Severity::Warning;
            f.message = "the property was neither proved nor shown violated: the exploration was not exhaustive (GV100)";
            verdict.reason = "the exploration was not exhaustive";
        }
        f.location->code = f.code;
        f.location->severity = f.severity;
        f.location->message = f.message;
        m_result.properties.push_back(text);
        m_result.propertyHolds.push_back(verdict.outcome == PropertyOutcome::Holds);
        m_result.propertyVerdicts.push_back(verdict);
        m_result.findings.push_back(std::move(f));
    }
}

VerificationResult PackmlVerifier::run()
{
    m_explorer.run();
    m_result.cancelled = m_explorer.cancelled();
    if (m_result.cancelled) {
        m_result.exhaustive = false;
        return m_result;
    }
    for (const ExploredWitness& witness : m_explorer.witnesses())
        if (witness.property < 0)
            reportWitness(witness);
    reportProperties();
    if (neverSound()) {
        reportStuck();
        reportNeverActive();
        reportNeverAccepted();
    }
    reportUndecided();
    m_result.exhaustive = neverSound() && m_stuckUndecided.empty();
    m_result.configurations = m_explorer.nodes().size();
    m_result.programStates = m_explorer.nodes().size();
    m_result.maxDepth = m_explorer.maxDepth();
    m_result.abstractions = m_explorer.abstractions();
    m_result.bothLayers = true;
    std::stable_sort(m_result.findings.begin(), m_result.findings.end(),
                     [](const VerificationFinding& a, const VerificationFinding& b) { return a.code < b.code; });
    return m_result;
}

} // namespace

VerificationResult verifyPackmlProgram(const Model& model, PackmlProgram program, const VerificationOptions& options)
{
    PackmlVerifier verifier(model, std::move(program), options);
    return verifier.run();
}

VerificationResult verifyPackmlModel(const Model& model, const VerificationOptions& options)
{
    return verifyPackmlProgram(model, buildPackmlProgram(model), options);
}

} // namespace core::packml
