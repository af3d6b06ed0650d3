#include "core/templates/packml/packmlverifier.h"

#include "core/model/model.h"
#include "core/templates/packml/packmlcounterexample.h"
#include "core/templates/packml/packmldiagnostics.h"
#include "core/templates/packml/packmlexplorer.h"
#include "core/templates/packml/packmlproperty.h"
#include "core/verification/bothlayers.h"

#include <algorithm>
#include <deque>
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
        , m_explorer(model, std::move(program), limits(options, m_texts, m_properties))
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
    Counterexample counterexampleTo(std::size_t node, const std::vector<InputChoice>& lastScan, const std::string& title,
                                    int expectedMode) const;

    const Model& m_model;
    const Configuration& m_configuration;
    std::vector<std::string> m_texts;               // the model's properties, then the options'
    std::vector<std::vector<PropertyProblem>> m_problems; // per property: why it cannot be checked
    std::vector<PackmlProperty> m_properties;
    PackmlExplorer m_explorer;
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

Counterexample PackmlVerifier::counterexampleTo(std::size_t node, const std::vector<InputChoice>& lastScan,
                                                const std::string& title, int expectedMode) const
{
    std::vector<InputChoice> scans = m_explorer.path(node);
    scans.insert(scans.end(), lastScan.begin(), lastScan.end());
    return writeCounterexample(m_explorer.nodes().front().simulator, scans, title, modeName(expectedMode));
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

void PackmlVerifier::reportWitness(const ExploredWitness& witness)
{
    const ScanFinding& s = witness.finding;
    const ExploredNode& from = m_explorer.nodes()[witness.node];
    const InputChoice choice = m_explorer.inputChoices().choices(from.simulator)[witness.choice];
    PackmlSimulator after = from.simulator;
    const PackmlScanRecord record = PackmlExplorer::runScan(after, choice);
    const bool located = s.code == verification::kDisabledStateActive;
    const std::string& message = s.message; // the location names the mode
    VerificationFinding f = finding(s.code, message, modeLocation(s.mode, located ? std::optional<State>(s.state) : std::nullopt,
                                                                 s.code, message));
    appendScanArguments(f, s);
    f.counterexample = counterexampleTo(witness.node, std::vector<InputChoice>{choice},
                                        s.code + ": " + modeName(s.mode) + ": " + message, record.mode);
    // Confirmed when the scenario replays to the same violation.
    if (const std::optional<Replay> replayed = replay(m_explorer.nodes().front().simulator, *f.counterexample)) {
        for (const ScanFinding& again : checkScan(m_explorer.reference(), replayed->ghost, replayed->facts))
            f.counterexample->confirmed = f.counterexample->confirmed
                                          || (again.code == s.code && again.mode == s.mode && again.state == s.state);
    }
    if (!f.counterexample->confirmed) {
        f.severity = Severity::Info;
        f.message += " (not confirmed: its counterexample does not replay to it in the simulator)";
    }
    m_result.findings.push_back(std::move(f));
}

// GV130, GV131: configurations of an acting state from which no run that
// stays in it (no transition, no mode change) reaches a scan whose SC fires.
void PackmlVerifier::reportStuck()
{
    const auto& nodes = m_explorer.nodes();
    const auto& edges = m_explorer.edges();
    std::vector<std::vector<std::uint32_t>> staysInto(nodes.size());
    std::vector<char> canComplete(nodes.size(), 0);
    std::deque<std::uint32_t> queue;
    for (const ExploredEdge& edge : edges) {
        if (edge.stays)
            staysInto[edge.to].push_back(edge.from);
        if (edge.completes && !canComplete[edge.from]) {
            canComplete[edge.from] = 1;
            queue.push_back(edge.from);
        }
    }
    while (!queue.empty()) {
        const std::uint32_t n = queue.front();
        queue.pop_front();
        for (std::uint32_t from : staysInto[n])
            if (!canComplete[from]) {
                canComplete[from] = 1;
                queue.push_back(from);
            }
    }
    std::set<std::pair<int, State>> reported;
    for (std::size_t n = 0; n < nodes.size(); ++n) { // shortest first: nodes are in breadth-first order
        const PackmlSimulator& s = nodes[n].simulator;
        if (canComplete[n] || !isActing(s.state()) || s.fault() || !reported.insert({s.mode(), s.state()}).second)
            continue;
        const bool aborting = s.state() == State::Aborting;
        const std::string code = aborting ? verification::kAbortingStuck : verification::kStuckGrafcet;
        const std::string message = (aborting ? std::string("Aborting can reach a situation from which Aborted is never reached: nothing leaves it")
                        : std::string(stateName(s.state())) + "'s GRAFCET can reach a situation from which Complete never "
                              "becomes TRUE: only Stop or Abort leave it");
        VerificationFinding f = finding(code, message, modeLocation(s.mode(), aborting ? std::nullopt : std::optional(s.state()),
                                                                     code, message));
        f.counterexample = counterexampleTo(n, {}, code + ": " + modeName(s.mode()) + ": " + message, s.mode());
        if (f.counterexample->scans == 0) {
            f.counterexample.reset();
        } else if (const std::optional<Replay> replayed = replay(nodes.front().simulator, *f.counterexample)) {
            const int instance = replayed->after.program().instance(s.mode(), s.state())
                                     ? static_cast<int>(replayed->after.program().instance(s.mode(), s.state())
                                                        - replayed->after.program().instances.data())
                                     : -1;
            f.counterexample->confirmed = replayed->after.state() == s.state() && replayed->after.mode() == s.mode()
                                          && situationOf(replayed->after, instance) == situationOf(s, instance);
        }
        m_result.findings.push_back(std::move(f));
    }
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
    for (const std::string& abstraction : m_explorer.abstractions())
        why += (why.empty() ? "" : "; ") + abstraction;
    if (why.empty())
        return;
    const std::string message = "not exhaustive: " + why
        + ". GV130, GV131, GV134 and GV135 were not decided, and the absence of the other findings is not a proof";
    m_result.findings.push_back(finding(core::verification::kIncomplete, message,
                                        modelDiagnostic(Finding{core::verification::kIncomplete, Severity::Warning, "",
                                                                message, {}})));
}

void PackmlVerifier::reportProperties()
{
    const bool exact = m_explorer.exhaustive() && m_explorer.abstractions().empty();
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
            const ExploredNode& from = m_explorer.nodes()[witness->node];
            const InputChoice choice = m_explorer.inputChoices().choices(from.simulator)[witness->choice];
            PackmlSimulator after = from.simulator;
            const int mode = PackmlExplorer::runScan(after, choice).mode;
            f.counterexample = counterexampleTo(witness->node, std::vector<InputChoice>{choice},
                                                f.code + ": property '" + text + "' violated", mode);
            if (const std::optional<Replay> replayed = replay(m_explorer.nodes().front().simulator, *f.counterexample))
                f.counterexample->confirmed = packmlPropertyViolated(m_properties[i], replayed->after);
            if (f.counterexample->confirmed) {
                verdict.outcome = PropertyOutcome::Violated;
            } else {
                f.severity = Severity::Info;
                f.message += " (not confirmed: its counterexample does not replay to it in the simulator)";
                verdict.reason = "its counterexample does not replay";
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
    const bool exact = m_explorer.exhaustive() && m_explorer.abstractions().empty();
    reportProperties();
    if (exact) {
        reportStuck();
        reportNeverActive();
        reportNeverAccepted();
    }
    reportUndecided();
    m_result.exhaustive = exact;
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
