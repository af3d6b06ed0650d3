#include "core/verification/verification.h"

#include "core/templates/templateverification.h"

#include "core/verification/bothlayers.h"

#include "core/model/model.h"
#include "core/simulation/simulator.h"
#include "core/verification/stepspace.h"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <queue>
#include <set>

namespace core {

using bdd::Ref;
using verify::CompiledStep;
using verify::StepSpace;

namespace {

VerificationFinding gemmaFinding(const char* findingCode, Severity severity, std::vector<std::string> elements)
{
    VerificationFinding finding;
    finding.code = findingCode;
    finding.severity = severity;
    finding.elements = std::move(elements);
    return finding;
}

namespace code = verification;

constexpr const char* kEmergencyStop = "D1";
constexpr std::size_t kUnreached = std::numeric_limits<std::size_t>::max();

std::string listed(const std::vector<std::string>& items, const std::string& last = " and ")
{
    std::string text;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i > 0)
            text += i + 1 == items.size() ? last : ", ";
        text += items[i];
    }
    return text;
}

// The comment lines first, then the `at N:` lines sorted by scan (stable).
std::string inScanOrder(const std::string& text)
{
    std::vector<std::string> comments;
    std::vector<std::pair<long long, std::string>> actions;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos)
            end = text.size();
        std::string line = text.substr(start, end - start);
        start = end + 1;
        if (line.rfind("at ", 0) == 0)
            actions.emplace_back(std::atoll(line.c_str() + 3), std::move(line));
        else if (!line.empty())
            comments.push_back(std::move(line));
    }
    std::stable_sort(actions.begin(), actions.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::string out;
    for (const std::string& line : comments)
        out += line + "\n";
    for (const auto& action : actions)
        out += action.second + "\n";
    return out;
}

// Compiles every transition of every visible step into formulas over one
// atom table, and groups each step's tokens by literal.
void compileStep(const GemmaStep& step, int index, const VerificationOptions& options, sat::AtomTable& atoms,
                 CompiledStep& out)
{
    out.step = &step;
    out.index = index;
    auto assumption = options.complete.find(step.id);
    out.freeComplete = assumption == options.complete.end() || assumption->second == CompleteAssumption::Free;
    for (const GemmaToken& token : step.tokens) {
        const int variable = atoms.variableIndex(token.variable);
        if (variable < 0)
            continue;
        const bool negated = token.polarity == TokenPolarity::NormallyClosed;
        int group = -1;
        for (std::size_t g = 0; g < out.groups.size(); ++g) {
            if (out.groups[g].variable == variable && out.groups[g].negated == negated)
                group = static_cast<int>(g);
        }
        if (group < 0) {
            out.groups.push_back(verify::TokenGroup{variable, negated, {}});
            group = static_cast<int>(out.groups.size()) - 1;
            atoms.booleanAtom(variable); // the update reads the variable itself
        }
        out.groups[static_cast<std::size_t>(group)].tokens.push_back(token.name);
        for (std::size_t t = 0; t < step.transitions.size(); ++t) {
            if (step.transitions[t].id != token.transitionId)
                continue;
            for (int node : token.literalNodes)
                out.leafGroup[{static_cast<int>(t), node}] = group;
        }
    }
    for (const GemmaTransition& transition : step.transitions) {
        verify::CompiledTransition compiled;
        compiled.transition = &transition;
        if (transition.conditionUsable) {
            std::set<int> leaves;
            for (const auto& [node, name] : transition.substitutions)
                leaves.insert(node);
            compiled.formula = sat::compileCondition(transition.condition.expression, leaves, atoms);
        } else {
            compiled.formula.nodes.push_back(sat::Formula::Node{sat::Formula::Op::False, -1, -1});
            compiled.formula.root = 0;
        }
        out.transitions.push_back(std::move(compiled));
    }
}

// A configuration of a step, with the scans it takes from the step's entry.
struct Configuration {
    int step = -1;
    bool entry = true;
    std::vector<bool> tokens;
    std::size_t depth = 0;
};

// One scan of a counterexample: the configuration it starts in and what the
// inputs must satisfy (over the step's diagram variables).
struct PlannedScan {
    int step = -1;
    std::vector<bool> tokens;
    Ref constraint = bdd::kTrue;
};

struct Occurrence {
    int step = -1;
    std::size_t transition = 0;
};

class Verifier {
public:
    Verifier(const Model& model, const VerificationOptions& options)
        : m_model(model), m_options(options), m_program(buildGemmaProgram(model)), m_atoms(model.variables())
    {
        m_budget.nodeLimit = options.maxDiagramNodes;
        if (options.timeLimit.count() > 0)
            m_budget.deadline = std::chrono::steady_clock::now() + options.timeLimit;
        m_steps.resize(m_program.steps.size());
        for (std::size_t i = 0; i < m_program.steps.size(); ++i)
            compileStep(m_program.steps[i], static_cast<int>(i), options, m_atoms, m_steps[i]);
        m_spaces.resize(m_steps.size());
        m_spaceFailure.resize(m_steps.size());
        m_possiblyReached.assign(m_steps.size(), false);
        m_distance.assign(m_steps.size(), kUnreached);
        m_parent.assign(m_steps.size(), Occurrence{});
        m_initial = stepIndex(m_program.initialStepId);
    }

    VerificationResult run();

private:
    int stepIndex(const std::string& id) const
    {
        for (std::size_t i = 0; i < m_program.steps.size(); ++i) {
            if (m_program.steps[i].id == id)
                return static_cast<int>(i);
        }
        return -1;
    }
    // Reached through decided steps: a shortest path to it is known.
    bool reached(int step) const { return step >= 0 && m_distance[static_cast<std::size_t>(step)] != kUnreached; }
    // Reached, or entered from a step whose space was not decided: it may be reachable.
    bool maybeReached(int step) const { return reached(step) || m_possiblyReached[static_cast<std::size_t>(step)]; }
    bool decided(int step) const { return m_spaces[static_cast<std::size_t>(step)] != nullptr; }
    StepSpace& space(int step) { return *m_spaces[static_cast<std::size_t>(step)]; }
    const GemmaTransition& transitionAt(const Occurrence& o) const
    {
        return *m_steps[static_cast<std::size_t>(o.step)].transitions[o.transition].transition;
    }
    StepSpace* ensureSpace(int step);

    // Runs one unit of the analysis with at most half of the budget left (so
    // that one hard step cannot starve the others); when the budget runs out,
    // notes that `code` was not decided for `element` and returns false.
    bool decide(const std::string& element, int order, const std::string& code, const std::function<void()>& unit);
    void noteUndecided(const std::string& element, int order, const std::string& code, const std::string& reason);
    std::string budgetReason(const bdd::BudgetExceeded& error) const;
    void reportUndecided(VerificationResult& result);

    void explore();
    void exploreUncertain();
    std::optional<Configuration> chooseConfiguration(int step, Ref tokenSet);
    std::vector<PlannedScan> pathTo(const Configuration& configuration);
    std::vector<PlannedScan> pathToEntry(int step);
    Ref defaultScan(int step, const Configuration& configuration);
    std::optional<Counterexample> counterexample(const std::string& title, const Configuration& configuration,
                                                 Ref finalConstraint);
    std::optional<Counterexample> counterexampleAt(const std::string& title, int step, Ref tokenSet,
                                                   const std::function<Ref(const Configuration&)>& finalScan);
    bool fireable(const Occurrence& o);

    // True when the properties of a step seen in a reachable configuration
    // can be decided: it is reached on a known path and was analysed;
    // otherwise notes `code` as undecided for it.
    bool analysable(int step, const std::string& code);
    void checkUnreachable();
    void checkTransitions();
    void checkTransition(const std::string& id, const std::vector<Occurrence>& occurrences, int order);
    void checkOverlaps();
    void checkOverlaps(int step);
    void checkStuck(int step);
    void checkEmergencyStop(int step);
    void checkStuck();
    void checkReturn();
    void checkEmergencyStop();
    void add(VerificationFinding finding, int order);
    void fillFacts(VerificationResult& result);

    const Model& m_model;
    const VerificationOptions& m_options;
    GemmaProgram m_program;
    sat::AtomTable m_atoms;
    std::vector<CompiledStep> m_steps;
    bdd::Budget m_budget;
    std::vector<std::unique_ptr<StepSpace>> m_spaces; // null: not built, or not decided (m_spaceFailure says why)
    std::vector<std::string> m_spaceFailure;
    std::vector<bool> m_possiblyReached; // entered only through undecided steps
    struct Undecided {
        std::string element;
        int order = 0;
        std::vector<std::string> codes;
        std::string reason;
    };
    std::vector<Undecided> m_undecided;
    std::string m_counterexampleCut; // why the last counterexampleAt ran out of budget; empty: it did not
    std::vector<std::size_t> m_distance; // scans from the start to the step's entry configuration
    std::vector<Occurrence> m_parent;    // the transition that enters the step on a shortest path
    int m_initial = -1;
    std::vector<std::pair<int, VerificationFinding>> m_findings;
    std::set<int> m_stuckSteps;
    std::unique_ptr<Simulator> m_simulator;
};

StepSpace* Verifier::ensureSpace(int step)
{
    const auto index = static_cast<std::size_t>(step);
    auto& slot = m_spaces[index];
    if (slot || !m_spaceFailure[index].empty())
        return slot.get();
    const std::string& id = m_steps[index].step->id;
    decide(id, step, "space", [&] {
        slot = std::make_unique<StepSpace>(m_steps[index], m_atoms, m_budget, m_options.cancelled);
    });
    if (!slot)
        m_spaceFailure[index] = m_undecided.back().reason;
    return slot.get();
}

std::string Verifier::budgetReason(const bdd::BudgetExceeded& error) const
{
    if (dynamic_cast<const bdd::TimeLimitExceeded*>(&error))
        return "the verification reached its time limit of " + std::to_string(m_options.timeLimit.count()) + " ms";
    return "the verification reached its limit of " + std::to_string(m_options.maxDiagramNodes)
        + " decision-diagram nodes";
}

bool Verifier::decide(const std::string& element, int order, const std::string& code,
                      const std::function<void()>& unit)
{
    const bdd::Budget whole = m_budget;
    const auto now = std::chrono::steady_clock::now();
    if (whole.deadline && now < *whole.deadline)
        m_budget.deadline = now + (*whole.deadline - now) / 2;
    m_budget.nodeLimit = whole.nodesUsed + (whole.nodeLimit - std::min(whole.nodesUsed, whole.nodeLimit)) / 2;
    bool done = false;
    try {
        unit();
        done = true;
    } catch (const bdd::BudgetExceeded& error) {
        // The half given to this unit, or the whole budget, is spent: which
        // one the user must raise is the whole.
        noteUndecided(element, order, code, budgetReason(error));
    }
    m_budget.deadline = whole.deadline;
    m_budget.nodeLimit = whole.nodeLimit;
    return done;
}

void Verifier::noteUndecided(const std::string& element, int order, const std::string& code,
                             const std::string& reason)
{
    auto entry = std::find_if(m_undecided.begin(), m_undecided.end(),
                              [&](const Undecided& u) { return u.element == element; });
    if (entry == m_undecided.end()) {
        m_undecided.push_back(Undecided{element, order, {}, reason});
        entry = m_undecided.end() - 1;
    }
    if (std::find(entry->codes.begin(), entry->codes.end(), code) == entry->codes.end())
        entry->codes.push_back(code);
}

// Scans after the step's entry until a configuration of the set is reached;
// the first such configuration (entry first, then by layer).
std::optional<Configuration> Verifier::chooseConfiguration(int step, Ref tokenSet)
{
    StepSpace& s = space(step);
    bdd::Manager& m = s.manager();
    if (m.conj(tokenSet, s.zero()) != bdd::kFalse)
        return Configuration{step, true, std::vector<bool>(s.step().groups.size(), false), 0};
    for (std::size_t layer = 0; layer < s.layers().size(); ++layer) {
        const Ref here = m.conj(tokenSet, s.layers()[layer]);
        if (here == bdd::kFalse)
            continue;
        std::vector<bool> assignment;
        m.pick(here, {}, assignment);
        return Configuration{step, false, s.tokensOf(assignment), layer + 1};
    }
    return std::nullopt;
}

// Shortest distances to every step's entry configuration: a step is entered
// only through its entry configuration, so distances between steps are the
// scans spent in the source (its shortest way to a configuration from which
// the transition fires) plus the firing scan.
void Verifier::explore()
{
    if (m_initial < 0)
        return;
    using Item = std::pair<std::size_t, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    m_distance[static_cast<std::size_t>(m_initial)] = 0;
    queue.push({0, m_initial});
    std::vector<bool> done(m_steps.size(), false);
    while (!queue.empty()) {
        // Named copies, not structured bindings: clang 14 (the fuzz build)
        // cannot capture bindings in the lambda below.
        const std::size_t distance = queue.top().first;
        const int step = queue.top().second;
        queue.pop();
        if (done[static_cast<std::size_t>(step)])
            continue;
        done[static_cast<std::size_t>(step)] = true;
        const CompiledStep& compiled = m_steps[static_cast<std::size_t>(step)];
        StepSpace* s = ensureSpace(step);
        std::vector<bool> relaxed(compiled.transitions.size(), false);
        if (s) {
            decide(compiled.step->id, step, "transitions", [&] {
                for (std::size_t t = 0; t < compiled.transitions.size(); ++t) {
                    const int target = stepIndex(compiled.transitions[t].transition->targetId);
                    if (target < 0) {
                        relaxed[t] = true;
                        continue;
                    }
                    const auto configuration = chooseConfiguration(step, s->possible(s->fires(t)));
                    relaxed[t] = true;
                    if (!configuration)
                        continue;
                    const std::size_t through = distance + configuration->depth + 1;
                    if (through < m_distance[static_cast<std::size_t>(target)]) {
                        m_distance[static_cast<std::size_t>(target)] = through;
                        m_parent[static_cast<std::size_t>(target)] = Occurrence{step, t};
                        queue.push({through, target});
                    }
                }
            });
        }
        // What an undecided step does is unknown: every target may be entered.
        for (std::size_t t = 0; t < compiled.transitions.size(); ++t) {
            const int target = stepIndex(compiled.transitions[t].transition->targetId);
            if (!relaxed[t] && target >= 0)
                m_possiblyReached[static_cast<std::size_t>(target)] = true;
        }
    }
    exploreUncertain();
}

// Steps entered only through undecided steps may be reachable, and so may
// the steps they lead to: "unreachable" stays a sound claim.
void Verifier::exploreUncertain()
{
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t st = 0; st < m_steps.size(); ++st) {
            const int step = static_cast<int>(st);
            if (reached(step) || !m_possiblyReached[st])
                continue;
            StepSpace* s = ensureSpace(step);
            for (std::size_t t = 0; t < m_steps[st].transitions.size(); ++t) {
                const int target = stepIndex(m_steps[st].transitions[t].transition->targetId);
                if (target < 0 || maybeReached(target))
                    continue;
                bool fires = true;
                if (s)
                    decide(m_steps[st].step->id, step, "transitions",
                           [&] { fires = fireable(Occurrence{step, t}); });
                if (fires) {
                    m_possiblyReached[static_cast<std::size_t>(target)] = true;
                    changed = true;
                }
            }
        }
    }
}

std::vector<PlannedScan> Verifier::pathToEntry(int step)
{
    if (step == m_initial)
        return {};
    const Occurrence parent = m_parent[static_cast<std::size_t>(step)];
    StepSpace& s = space(parent.step);
    const auto configuration = chooseConfiguration(parent.step, s.possible(s.fires(parent.transition)));
    if (!configuration)
        return {}; // cannot happen: explore() entered the step through this transition
    std::vector<PlannedScan> scans = pathTo(*configuration);
    scans.push_back(PlannedScan{parent.step, configuration->tokens,
                                s.manager().conj(s.fires(parent.transition), s.tokenCube(configuration->tokens, false))});
    return scans;
}

// The scans from the start to the configuration: to the step's entry, then
// back through the layers to the entry, played forward.
std::vector<PlannedScan> Verifier::pathTo(const Configuration& configuration)
{
    std::vector<PlannedScan> scans = pathToEntry(configuration.step);
    if (configuration.entry)
        return scans;
    StepSpace& s = space(configuration.step);
    bdd::Manager& m = s.manager();
    std::vector<std::vector<bool>> chain(configuration.depth + 1);
    chain[0] = std::vector<bool>(s.step().groups.size(), false);
    chain[configuration.depth] = configuration.tokens;
    for (std::size_t k = configuration.depth - 1; k >= 1; --k) {
        const Ref before = m.conj(s.preimage(s.tokenCube(chain[k + 1], false)), s.layers()[k - 1]);
        std::vector<bool> assignment;
        m.pick(before, {}, assignment);
        chain[k] = s.tokensOf(assignment);
    }
    for (std::size_t k = 0; k < configuration.depth; ++k) {
        const Ref move = m.conj(m.conj(s.noFire(), s.update()),
                                m.conj(s.tokenCube(chain[k], false), s.tokenCube(chain[k + 1], true)));
        scans.push_back(PlannedScan{configuration.step, chain[k], move});
    }
    return scans;
}

// A scan that shows the configuration as it is: nothing fires when the
// inputs allow it.
Ref Verifier::defaultScan(int step, const Configuration& configuration)
{
    StepSpace& s = space(step);
    bdd::Manager& m = s.manager();
    const Ref here = s.tokenCube(configuration.tokens, false);
    return m.conj(s.noFire(), here) != bdd::kFalse ? s.noFire() : s.theory();
}

std::optional<Counterexample> Verifier::counterexampleAt(const std::string& title, int step, Ref tokenSet,
                                                         const std::function<Ref(const Configuration&)>& finalScan)
{
    m_counterexampleCut.clear();
    // No known path to a step entered only through undecided steps.
    if (!reached(step))
        return std::nullopt;
    try {
        const auto configuration = chooseConfiguration(step, tokenSet);
        if (!configuration)
            return std::nullopt;
        return counterexample(title, *configuration,
                              finalScan ? finalScan(*configuration) : defaultScan(step, *configuration));
    } catch (const bdd::BudgetExceeded& error) {
        m_counterexampleCut = budgetReason(error);
        return std::nullopt;
    }
}

// Plays the planned scans forward, choosing input values (keeping the
// previous ones where they fit), writes the scenario and replays it.
std::optional<Counterexample> Verifier::counterexample(const std::string& title, const Configuration& configuration,
                                                       Ref finalConstraint)
{
    std::vector<PlannedScan> scans = pathTo(configuration);
    const std::size_t reachedAt = scans.size();
    scans.push_back(PlannedScan{configuration.step, configuration.tokens, finalConstraint});

    ScenarioRecording recording;
    recording.title = title + "\nReplay: ggstudio-cli simulate MODEL THIS_FILE";
    std::vector<cond::Value> values = m_atoms.initialValues();
    std::map<std::string, bool> manual;
    bool realisable = true;
    std::string extra;
    for (std::size_t n = 0; n < scans.size(); ++n) {
        const PlannedScan& scan = scans[n];
        StepSpace& s = space(scan.step);
        bdd::Manager& m = s.manager();
        const GemmaStep& step = *m_steps[static_cast<std::size_t>(scan.step)].step;
        std::vector<int> preferred = s.preferredAssignment(values);
        if (s.completeVariable() >= 0 && manual.count(step.id))
            preferred[static_cast<std::size_t>(s.completeVariable())] = manual[step.id] ? 1 : 0;
        std::vector<bool> assignment;
        if (!m.pick(m.conj(scan.constraint, s.tokenCube(scan.tokens, false)), preferred, assignment)) {
            realisable = false;
            break;
        }
        std::vector<std::pair<int, bool>> required;
        for (int atom : s.usedAtoms())
            required.emplace_back(atom, s.atomHolds(atom, assignment));
        RecordedScan recorded;
        recorded.scan = static_cast<std::int64_t>(n + 1);
        if (auto next = sat::concretize(m_atoms, required, values)) {
            for (std::size_t v = 0; v < values.size(); ++v) {
                if (!((*next)[v] == values[v]))
                    recorded.inputs.push_back(InputChange{m_atoms.variableName(static_cast<int>(v)), (*next)[v]});
            }
            values = std::move(*next);
        } else {
            realisable = false;
        }
        if (n == 0) {
            // Fix the Complete of every nested step the run visits, whatever
            // the simulator was left with.
            for (const CompiledStep& compiled : m_steps) {
                const bool visited = std::any_of(scans.begin(), scans.end(), [&](const PlannedScan& p) {
                    return p.step == compiled.index;
                });
                if (!compiled.step->hasNestedBehaviour() || !visited)
                    continue;
                if (compiled.freeComplete) {
                    manual[compiled.step->id] = false;
                    recorded.completes.push_back({compiled.step->id, false});
                } else {
                    recorded.completes.push_back({compiled.step->id, std::nullopt});
                }
            }
        }
        if (s.completeVariable() >= 0) {
            const bool complete = assignment[static_cast<std::size_t>(s.completeVariable())];
            if (manual[step.id] != complete) {
                manual[step.id] = complete;
                auto same = std::find_if(recorded.completes.begin(), recorded.completes.end(),
                                         [&](const auto& c) { return c.stepId == step.id; });
                if (same != recorded.completes.end())
                    same->manualValue = complete;
                else
                    recorded.completes.push_back({step.id, complete});
            }
        }
        ScanRecord record;
        record.scan = recorded.scan;
        record.stepBefore = step.id;
        record.stepAfter = step.id;
        for (std::size_t t = 0; t < s.step().transitions.size(); ++t) {
            if (m.evaluate(s.fires(t), assignment)) {
                record.fired = s.step().transitions[t].transition->id;
                record.stepAfter = s.step().transitions[t].transition->targetId;
                break;
            }
        }
        const std::string at = "at " + std::to_string(record.scan) + ": ";
        if (n + 1 == reachedAt && record.fired.empty())
            extra += at + "expect step " + step.id + "\n";
        if (n + 1 == scans.size() && record.fired.empty())
            extra += at + "expect fired none\n" + at + "expect step " + step.id + "\n";
        if (!recorded.inputs.empty() || !recorded.completes.empty())
            recording.changes.push_back(std::move(recorded));
        recording.records.push_back(std::move(record));
    }

    Counterexample result;
    result.text = inScanOrder(writeScenario(recording) + extra);
    ScenarioParseResult parsed = parseScenario(result.text);
    result.scenario = std::move(parsed.scenario);
    result.scans = result.scenario.lastScan();
    if (realisable && parsed.ok()) {
        if (!m_simulator)
            m_simulator = std::make_unique<Simulator>(m_model);
        result.confirmed = validateScenario(result.scenario, *m_simulator).empty()
            && runScenario(result.scenario, *m_simulator).passed();
    }
    return result;
}

bool Verifier::fireable(const Occurrence& o)
{
    StepSpace& s = space(o.step);
    return s.manager().conj(s.possible(s.fires(o.transition)), s.anyConfiguration()) != bdd::kFalse;
}

void Verifier::add(VerificationFinding finding, int order)
{
    if (finding.arguments.empty())
        finding.arguments = finding.elements;
    const bool needsPath = finding.code == code::kOverlap || finding.code == code::kNoReturn
        || finding.code == code::kStuck || finding.code == code::kNoEmergencyStop;
    if (needsPath && !finding.counterexample && !m_counterexampleCut.empty()) {
        // A configuration claimed reachable that could not be shown within
        // the budget: not claimed.
        noteUndecided(finding.elements.front(), order, finding.code, m_counterexampleCut);
        m_counterexampleCut.clear();
        return;
    }
    m_counterexampleCut.clear();
    if (needsPath && finding.counterexample && !finding.counterexample->confirmed) {
        // The configuration may exist only because an undecided comparison
        // was taken as free: say so rather than claim it.
        finding.severity = Severity::Info;
        finding.message += " (not confirmed: the condition uses a comparison the verifier cannot decide, and "
                           "the counterexample does not replay)";
    }
    m_findings.emplace_back(order, std::move(finding));
}

// --- GV101 ---------------------------------------------------------------------

void Verifier::checkUnreachable()
{
    for (std::size_t i = 0; i < m_steps.size(); ++i) {
        if (maybeReached(static_cast<int>(i)))
            continue;
        const std::string& id = m_steps[i].step->id;
        VerificationFinding finding = gemmaFinding(code::kUnreachableStep, Severity::Warning, {id});
        std::vector<std::string> incoming;
        Occurrence nearest;
        for (std::size_t s = 0; s < m_steps.size(); ++s) {
            for (std::size_t t = 0; t < m_steps[s].transitions.size(); ++t) {
                const GemmaTransition& transition = *m_steps[s].transitions[t].transition;
                if (transition.targetId != id)
                    continue;
                if (std::find(incoming.begin(), incoming.end(), transition.id) == incoming.end())
                    incoming.push_back(transition.id);
                if (reached(static_cast<int>(s)) && decided(static_cast<int>(s))
                    && (nearest.step < 0 || m_distance[s] < m_distance[static_cast<std::size_t>(nearest.step)]))
                    nearest = Occurrence{static_cast<int>(s), t};
            }
        }
        finding.elements.insert(finding.elements.end(), incoming.begin(), incoming.end());
        if (m_initial < 0) {
            finding.message = id + " can never become active: the initial step " + m_program.initialStepId
                + " is hidden, so the PLC starts in a state that has no code";
        } else if (incoming.empty()) {
            finding.message = id + " can never become active: no effective transition leads to it";
        } else {
            finding.message = id + " can never become active: " + listed(incoming, " and ")
                + (incoming.size() == 1 ? " never fires" : " never fire") + " in any situation reachable from "
                + m_program.initialStepId;
        }
        if (nearest.step >= 0) {
            StepSpace& s = space(nearest.step);
            Ref shown = bdd::kFalse;
            Ref where = bdd::kFalse;
            try {
                shown = s.manager().conj(s.theory(), s.gated(nearest.transition));
                where = s.manager().conj(s.possible(shown), s.anyConfiguration());
            } catch (const bdd::BudgetExceeded&) {
                where = bdd::kFalse; // show the source as it is
            }
            finding.counterexample = counterexampleAt(
                code::kUnreachableStep + std::string(": ") + finding.message, nearest.step,
                where != bdd::kFalse ? where : s.anyConfiguration(),
                [&](const Configuration& c) { return where != bdd::kFalse ? shown : defaultScan(nearest.step, c); });
        }
        add(std::move(finding), static_cast<int>(i));
    }
}

// --- GV102, GV103 ----------------------------------------------------------------

void Verifier::checkTransitions()
{
    // Each transition id once, in program order, with every step that evaluates it.
    std::vector<std::pair<std::string, std::vector<Occurrence>>> byId;
    for (std::size_t s = 0; s < m_steps.size(); ++s) {
        if (!maybeReached(static_cast<int>(s)))
            continue;
        for (std::size_t t = 0; t < m_steps[s].transitions.size(); ++t) {
            const std::string& id = m_steps[s].transitions[t].transition->id;
            auto found = std::find_if(byId.begin(), byId.end(), [&](const auto& entry) { return entry.first == id; });
            if (found == byId.end())
                found = byId.insert(byId.end(), {id, {}});
            found->second.push_back(Occurrence{static_cast<int>(s), t});
        }
    }
    // An entry, not structured bindings: clang 14 cannot capture those.
    for (const auto& entry : byId) {
        const std::string& id = entry.first;
        const std::vector<Occurrence>& occurrences = entry.second;
        const int order = occurrences.front().step * 1000 + static_cast<int>(occurrences.front().transition) + 1;
        const bool allDecided = std::all_of(occurrences.begin(), occurrences.end(),
                                            [&](const Occurrence& o) { return decided(o.step); });
        if (!allDecided) {
            const auto undecided = std::find_if(occurrences.begin(), occurrences.end(),
                                                [&](const Occurrence& o) { return !decided(o.step); });
            noteUndecided(id, order, code::kDeadTransition,
                          m_steps[static_cast<std::size_t>(undecided->step)].step->id + " was not analysed");
            noteUndecided(id, order, code::kAlwaysTrue, {});
            continue;
        }
        if (!decide(id, order, code::kDeadTransition, [&] { checkTransition(id, occurrences, order); }))
            noteUndecided(id, order, code::kAlwaysTrue, {});
    }
}

void Verifier::checkTransition(const std::string& id, const std::vector<Occurrence>& occurrences, int order)
{
    {
        const GemmaTransition& transition = transitionAt(occurrences.front());
        bool anyFires = false;
        for (const Occurrence& o : occurrences)
            anyFires = anyFires || fireable(o);
        if (!anyFires) {
            // GV102: true somewhere (then pre-empted), or never true.
            std::vector<std::string> covers;
            Occurrence shown;
            for (const Occurrence& o : occurrences) {
                StepSpace& s = space(o.step);
                bdd::Manager& m = s.manager();
                const Ref holds = m.conj(s.theory(), s.gated(o.transition));
                if (m.conj(s.possible(holds), s.anyConfiguration()) == bdd::kFalse)
                    continue;
                if (shown.step < 0 || m_distance[static_cast<std::size_t>(o.step)]
                                          < m_distance[static_cast<std::size_t>(shown.step)])
                    shown = o;
                for (std::size_t j = 0; j < o.transition; ++j) {
                    const Ref both = m.conj(holds, s.fires(j));
                    const std::string& cover = s.step().transitions[j].transition->id;
                    if (m.conj(s.possible(both), s.anyConfiguration()) != bdd::kFalse
                        && std::find(covers.begin(), covers.end(), cover) == covers.end())
                        covers.push_back(cover);
                }
            }
            VerificationFinding finding = gemmaFinding(code::kDeadTransition, Severity::Warning, {id});
            finding.elements.insert(finding.elements.end(), covers.begin(), covers.end());
            if (shown.step >= 0) {
                finding.message = id + " can never fire: whenever its condition holds, " + listed(covers, " or ")
                    + " fires first (higher priority)";
                StepSpace& s = space(shown.step);
                const Ref holds = s.manager().conj(s.theory(), s.gated(shown.transition));
                finding.counterexample = counterexampleAt(code::kDeadTransition + std::string(": ") + finding.message,
                                                          shown.step, s.possible(holds),
                                                          [&](const Configuration&) { return holds; });
            } else {
                const Occurrence first = *std::min_element(
                    occurrences.begin(), occurrences.end(), [&](const Occurrence& a, const Occurrence& b) {
                        return m_distance[static_cast<std::size_t>(a.step)] < m_distance[static_cast<std::size_t>(b.step)];
                    });
                StepSpace& s = space(first.step);
                bdd::Manager& m = s.manager();
                // Unsatisfiable whatever the tokens hold, or only with the tokens it can hold.
                const bool formulaUnsat = m.conj(s.theory(), s.gated(first.transition)) == bdd::kFalse;
                std::string problem;
                for (const ProgramProblem& p : transition.problems) {
                    if (p.kind == ProgramProblem::Kind::Error) {
                        problem = p.code;
                        break;
                    }
                }
                if (!transition.conditionUsable)
                    finding.message = id + " can never fire: its condition cannot be used"
                        + (problem.empty() ? std::string() : " (" + problem + ")")
                        + ", so the generated code reads it as FALSE";
                else if (formulaUnsat)
                    finding.message = id + " can never fire: no values of the variables make its condition TRUE";
                else
                    finding.message = id + " can never fire: its condition is never TRUE with the tokens "
                        + m_program.steps[static_cast<std::size_t>(first.step)].id + " can hold";
                finding.counterexample = counterexampleAt(code::kDeadTransition + std::string(": ") + finding.message,
                                                          first.step, s.anyConfiguration(), nullptr);
            }
            add(std::move(finding), order);
            return;
        }
        // GV103: TRUE in every reachable situation, with transitions after it.
        bool alwaysTrue = true;
        bool hasLater = false;
        std::vector<std::string> later;
        for (const Occurrence& o : occurrences) {
            StepSpace& s = space(o.step);
            bdd::Manager& m = s.manager();
            const Ref falseSometimes = m.conj(s.theory(), m.negate(s.gated(o.transition)));
            alwaysTrue = alwaysTrue && m.conj(s.possible(falseSometimes), s.anyConfiguration()) == bdd::kFalse;
            for (std::size_t j = o.transition + 1; j < s.step().transitions.size(); ++j) {
                hasLater = true;
                const std::string& after = s.step().transitions[j].transition->id;
                if (!transition.family && std::find(later.begin(), later.end(), after) == later.end())
                    later.push_back(after);
            }
        }
        if (alwaysTrue && hasLater) {
            VerificationFinding finding = gemmaFinding(code::kAlwaysTrue, Severity::Warning, {id});
            finding.elements.insert(finding.elements.end(), later.begin(), later.end());
            finding.message = transition.family
                ? "the condition of " + id + " is always TRUE: no own transition of an F step can ever fire"
                : "the condition of " + id + " is always TRUE when " + m_program.steps[static_cast<std::size_t>(
                      occurrences.front().step)].id + " is active: " + listed(later, " and ")
                      + (later.size() == 1 ? " can" : " can") + " never fire";
            const Occurrence o = occurrences.front();
            StepSpace& s = space(o.step);
            finding.counterexample = counterexampleAt(code::kAlwaysTrue + std::string(": ") + finding.message, o.step,
                                                      s.possible(s.fires(o.transition)),
                                                      [&](const Configuration&) { return s.fires(o.transition); });
            add(std::move(finding), order);
        }
    }
}

bool Verifier::analysable(int step, const std::string& findingCode)
{
    if (reached(step) && decided(step))
        return true;
    if (maybeReached(step)) {
        const std::size_t index = static_cast<std::size_t>(step);
        noteUndecided(m_steps[index].step->id, step * 1000, findingCode,
                      !decided(step) ? m_steps[index].step->id + " was not analysed"
                                     : "it is entered only through steps that were not analysed");
    }
    return false;
}

// --- GV104 -----------------------------------------------------------------------

void Verifier::checkOverlaps()
{
    for (std::size_t st = 0; st < m_steps.size(); ++st) {
        const int step = static_cast<int>(st);
        if (analysable(step, code::kOverlap))
            decide(m_steps[st].step->id, step * 1000, code::kOverlap, [&] { checkOverlaps(step); });
    }
}

void Verifier::checkOverlaps(int step)
{
    const auto st = static_cast<std::size_t>(step);
    {
        StepSpace& s = space(step);
        bdd::Manager& m = s.manager();
        const auto& transitions = m_steps[st].transitions;
        for (std::size_t i = 0; i < transitions.size(); ++i) {
            // The family transition pre-empts by design (emergency stop).
            if (transitions[i].transition->family || !fireable({step, i}))
                continue;
            for (std::size_t j = i + 1; j < transitions.size(); ++j) {
                if (!fireable({step, j}))
                    continue;
                const Ref both = m.conj(s.fires(i), s.gated(j));
                const Ref where = m.conj(s.possible(both), s.anyConfiguration());
                if (where == bdd::kFalse)
                    continue;
                const std::string& first = transitions[i].transition->id;
                const std::string& second = transitions[j].transition->id;
                VerificationFinding finding = gemmaFinding(code::kOverlap, Severity::Info, {first, second});
                finding.message = first + " and " + second + " can both be TRUE in the same scan: the priority decides, "
                    + first + " fires";
                finding.counterexample = counterexampleAt(code::kOverlap + std::string(": ") + finding.message, step,
                                                          where, [&](const Configuration&) { return both; });
                add(std::move(finding), static_cast<int>(st * 1000 + i * 32 + j));
            }
        }
    }
}

// --- GV106 -----------------------------------------------------------------------

void Verifier::checkStuck()
{
    for (std::size_t st = 0; st < m_steps.size(); ++st) {
        const int step = static_cast<int>(st);
        if (analysable(step, code::kStuck))
            decide(m_steps[st].step->id, step * 1000, code::kStuck, [&] { checkStuck(step); });
    }
}

void Verifier::checkStuck(int step)
{
    const auto st = static_cast<std::size_t>(step);
    {
        StepSpace& s = space(step);
        bdd::Manager& m = s.manager();
        Ref fireAny = bdd::kFalse;
        for (std::size_t t = 0; t < m_steps[st].transitions.size(); ++t)
            fireAny = m.disj(fireAny, s.fires(t));
        const Ref canLeave = s.canReach(s.possible(fireAny));
        const Ref stuck = m.conj(s.anyConfiguration(), m.negate(canLeave));
        if (stuck == bdd::kFalse)
            return;
        m_stuckSteps.insert(step);
        const std::string& id = m_steps[st].step->id;
        VerificationFinding finding = gemmaFinding(code::kStuck, Severity::Error, {id});
        if (m.conj(stuck, s.zero()) != bdd::kFalse)
            finding.message = "once " + id + " is active, no transition out of it can ever fire, whatever the inputs: "
                "the machine stays in " + id + " forever";
        else
            finding.message = id + " can get stuck: after some scans in it, its tokens are such that no transition "
                "out of it can ever fire, whatever the inputs";
        finding.counterexample =
            counterexampleAt(code::kStuck + std::string(": ") + finding.message, step, stuck, nullptr);
        add(std::move(finding), step);
    }
}

// --- GV105 -----------------------------------------------------------------------

void Verifier::checkReturn()
{
    if (m_initial < 0)
        return;
    // Steps whose entry configuration can lead back to the initial step,
    // grown until stable; with each, its configurations that can.
    // A step not decided, or whose set was not computed within the budget,
    // counts as leading back from everywhere: "never comes back" stays sound.
    std::vector<bool> good(m_steps.size(), false);
    std::vector<bool> failed(m_steps.size(), false);
    std::vector<Ref> goodSet(m_steps.size(), bdd::kFalse);
    good[static_cast<std::size_t>(m_initial)] = true;
    for (std::size_t st = 0; st < m_steps.size(); ++st)
        good[st] = good[st] || (maybeReached(static_cast<int>(st)) && !decided(static_cast<int>(st)));
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t st = 0; st < m_steps.size(); ++st) {
            const int step = static_cast<int>(st);
            if (!maybeReached(step) || !decided(step) || step == m_initial || failed[st])
                continue;
            const bool done = decide(m_steps[st].step->id, step * 1000, code::kNoReturn, [&] {
                StepSpace& s = space(step);
                bdd::Manager& m = s.manager();
                Ref leavesWell = bdd::kFalse;
                for (std::size_t t = 0; t < m_steps[st].transitions.size(); ++t) {
                    const int target = stepIndex(m_steps[st].transitions[t].transition->targetId);
                    if (target >= 0 && good[static_cast<std::size_t>(target)])
                        leavesWell = m.disj(leavesWell, s.fires(t));
                }
                goodSet[st] = s.canReach(s.possible(leavesWell));
                if (!good[st] && m.conj(goodSet[st], s.zero()) != bdd::kFalse) {
                    good[st] = true;
                    changed = true;
                }
            });
            if (!done) {
                failed[st] = true;
                changed = changed || !good[st];
                good[st] = true;
            }
        }
    }
    const std::string& initial = m_program.initialStepId;
    for (std::size_t st = 0; st < m_steps.size(); ++st) {
        const int step = static_cast<int>(st);
        if (step == m_initial || m_stuckSteps.count(step) || failed[st] || !analysable(step, code::kNoReturn))
            continue;
        StepSpace& s = space(step);
        bdd::Manager& m = s.manager();
        Ref bad = bdd::kFalse;
        if (!decide(m_steps[st].step->id, step * 1000, code::kNoReturn,
                    [&] { bad = m.conj(s.anyConfiguration(), m.negate(goodSet[st])); })
            || bad == bdd::kFalse)
            continue;
        const std::string& id = m_steps[st].step->id;
        VerificationFinding finding = gemmaFinding(code::kNoReturn, Severity::Warning, {id});
        finding.message = good[st]
            ? "after some scans in " + id + ", its tokens can be such that the initial step " + initial
                  + " can never become active again"
            : "once " + id + " is active, the initial step " + initial + " can never become active again";
        finding.counterexample =
            counterexampleAt(code::kNoReturn + std::string(": ") + finding.message, step, bad, nullptr);
        add(std::move(finding), step);
    }
}

// --- GV107 -----------------------------------------------------------------------

void Verifier::checkEmergencyStop()
{
    if (stepIndex(kEmergencyStop) < 0)
        return;
    for (std::size_t st = 0; st < m_steps.size(); ++st) {
        const int step = static_cast<int>(st);
        const GemmaStep& gemma = *m_steps[st].step;
        if (gemma.id.empty() || gemma.id[0] != 'F' || !analysable(step, code::kNoEmergencyStop))
            continue;
        decide(gemma.id, step * 1000, code::kNoEmergencyStop, [&] { checkEmergencyStop(step); });
    }
}

void Verifier::checkEmergencyStop(int step)
{
    const auto st = static_cast<std::size_t>(step);
    const GemmaStep& gemma = *m_steps[st].step;
    {
        StepSpace& s = space(step);
        bdd::Manager& m = s.manager();
        Ref toStop = bdd::kFalse;
        Ref stopHolds = bdd::kFalse;
        std::vector<std::string> ways;
        for (std::size_t t = 0; t < m_steps[st].transitions.size(); ++t) {
            const GemmaTransition& transition = *m_steps[st].transitions[t].transition;
            if (transition.targetId != kEmergencyStop)
                continue;
            ways.push_back(transition.id);
            toStop = m.disj(toStop, s.fires(t));
            stopHolds = m.disj(stopHolds, s.gated(t));
        }
        const Ref bad = m.conj(s.anyConfiguration(), m.negate(s.possible(toStop)));
        if (bad == bdd::kFalse)
            return;
        VerificationFinding finding = gemmaFinding(code::kNoEmergencyStop, Severity::Error, {gemma.id});
        finding.elements.insert(finding.elements.end(), ways.begin(), ways.end());
        if (ways.empty())
            finding.message = "the emergency stop D1 can never be entered from " + gemma.id
                + ": the family transition F->D1 is not effective and " + gemma.id + " has no transition to D1";
        else if (m.conj(bad, s.zero()) != bdd::kFalse)
            finding.message = "the emergency stop D1 cannot be entered from " + gemma.id
                + " in one scan, whatever the inputs: " + listed(ways, " and ") + " cannot fire there";
        else
            finding.message = "after some scans in " + gemma.id + ", the emergency stop D1 cannot be entered in one "
                "scan, whatever the inputs: " + listed(ways, " and ") + " cannot fire with the tokens it holds";
        const Ref show = m.conj(s.theory(), stopHolds);
        finding.counterexample = counterexampleAt(
            code::kNoEmergencyStop + std::string(": ") + finding.message, step, bad, [&](const Configuration& c) {
                return m.conj(show, s.tokenCube(c.tokens, false)) != bdd::kFalse ? show : defaultScan(step, c);
            });
        add(std::move(finding), step);
    }
}

void Verifier::fillFacts(VerificationResult& result)
{
    long double configurations = 0;
    for (std::size_t st = 0; st < m_steps.size(); ++st) {
        const int step = static_cast<int>(st);
        if (!reached(step))
            continue;
        result.reachableSteps.push_back(m_steps[st].step->id);
        if (!decided(step))
            continue;
        StepSpace& s = space(step);
        try {
            configurations += s.configurationCount();
            result.maxDepth = std::max(result.maxDepth, m_distance[st] + s.layers().size());
            for (std::size_t t = 0; t < m_steps[st].transitions.size(); ++t) {
                const std::string& id = m_steps[st].transitions[t].transition->id;
                if (fireable({step, t})
                    && std::find(result.fireableTransitions.begin(), result.fireableTransitions.end(), id)
                        == result.fireableTransitions.end())
                    result.fireableTransitions.push_back(id);
            }
        } catch (const bdd::BudgetExceeded&) {
            // Facts for cross-checks only, and the result is not exhaustive anyway.
        }
    }
    const auto limit = static_cast<long double>(std::numeric_limits<std::size_t>::max());
    result.configurations = configurations >= limit ? std::numeric_limits<std::size_t>::max()
                                                    : static_cast<std::size_t>(configurations);
}

// One GV100 per element with something undecided, saying what and why.
void Verifier::reportUndecided(VerificationResult& result)
{
    result.exhaustive = m_undecided.empty();
    for (const Undecided& entry : m_undecided) {
        std::vector<std::string> codes;
        bool space = false;
        bool transitions = false;
        bool rest = false;
        for (const std::string& c : entry.codes) {
            space = space || c == "space";
            transitions = transitions || c == "transitions";
            rest = rest || c == "rest";
            if (c.rfind("GV", 0) == 0)
                codes.push_back(c);
        }
        std::sort(codes.begin(), codes.end());
        VerificationFinding finding = gemmaFinding(code::kIncomplete, Severity::Warning, {});
        if (entry.element != "model")
            finding.elements.push_back(entry.element);
        if (rest) {
            finding.message = entry.reason + " while checking the properties: those not reported were not decided";
        } else if (space) {
            finding.message = entry.reason + " while exploring the configurations of " + entry.element
                + ": which of its transitions can fire, and GV102 to GV107 about it and its transitions, were "
                  "not decided; the steps it leads to are taken as reachable";
        } else {
            std::string what = listed(codes, " and ");
            if (transitions)
                what = "where its transitions lead" + std::string(codes.empty() ? "" : ", ") + what;
            finding.message = what + (codes.size() + (transitions ? 1 : 0) == 1 ? " was" : " were")
                + " not decided for " + entry.element + ": " + entry.reason;
        }
        finding.arguments = finding.elements;
        m_findings.emplace_back(entry.order, std::move(finding));
    }
}

VerificationResult Verifier::run()
{
    VerificationResult result;
    try {
        explore();
        checkUnreachable();
        checkTransitions();
        checkOverlaps();
        checkStuck();
        checkReturn();
        checkEmergencyStop();
        fillFacts(result);
    } catch (const bdd::BudgetExceeded& error) {
        // Every unit of the analysis is run by decide(); this is a safety net
        // that keeps the findings decided so far.
        noteUndecided("model", -1, "rest", budgetReason(error));
    } catch (const verify::Cancelled&) {
        result = VerificationResult{};
        result.cancelled = true;
        result.exhaustive = false;
        return result;
    }
    reportUndecided(result);
    std::stable_sort(m_findings.begin(), m_findings.end(), [](const auto& a, const auto& b) {
        return a.second.code != b.second.code ? a.second.code < b.second.code : a.first < b.first;
    });
    for (auto& entry : m_findings)
        result.findings.push_back(std::move(entry.second));
    return result;
}

// Closed loop: the GEMMA layer explored every input free. What it proved
// of every reachable configuration (GV101-GV103) still holds with the
// machine, which only narrows the inputs; what claims that some run exists
// (GV104-GV107) may not with the machine, and the runs of the rest set
// sensors the machine drives: both are left to the exploration with it.
void keepClosedLoopFindings(VerificationResult& result)
{
    const std::set<std::string> existential{verification::kOverlap, verification::kNoReturn, verification::kStuck,
                                            verification::kNoEmergencyStop};
    std::erase_if(result.findings, [&](const VerificationFinding& f) { return existential.count(f.code) > 0; });
    for (VerificationFinding& f : result.findings)
        f.counterexample.reset();
    result.closedLoop = true;
}

} // namespace

bool VerificationResult::violated() const
{
    return std::any_of(findings.begin(), findings.end(), [](const VerificationFinding& f) {
        return f.severity != Severity::Info && f.code != verification::kPropertyUndecided
            && f.code != verification::kIncomplete;
    });
}

bool VerificationResult::undecided() const
{
    if (!exhaustive)
        return true;
    return std::any_of(findings.begin(), findings.end(), [](const VerificationFinding& f) {
        return f.code == verification::kPropertyUndecided || f.code == verification::kIncomplete
            || (f.severity == Severity::Info && f.counterexample && !f.counterexample->confirmed);
    });
}

bool runsClosedLoop(const Model& model, const VerificationOptions& options)
{
    return options.closedLoop && !model.machine().empty() && model.templateKind() == TemplateKind::Gemma;
}

VerificationResult verifyModel(const Model& model, const VerificationOptions& options)
{
    return verificationEnginesOf(model).verifyModel(model, options);
}

VerificationResult verifyGemmaModel(const Model& model, const VerificationOptions& options)
{
    // One time limit for the whole run, both layers included.
    const auto deadline = options.timeLimit.count() > 0 ? std::chrono::steady_clock::now() + options.timeLimit
                                                         : std::chrono::steady_clock::time_point::max();
    Verifier verifier(model, options);
    VerificationResult result = verifier.run();
    if (runsClosedLoop(model, options) && !result.cancelled)
        keepClosedLoopFindings(result);
    if (!result.cancelled && needsBothLayers(model, options))
        verifyBothLayers(model, options, result, deadline);
    return result;
}

std::string verificationElementLabel(const VerificationFinding& finding)
{
    if (finding.property >= 0 && !finding.arguments.empty())
        return "property '" + finding.arguments.front() + "'";
    if (finding.elements.empty())
        return "model";
    std::string label;
    for (const std::string& element : finding.elements)
        label += (label.empty() ? "" : ", ") + element;
    return label;
}

} // namespace core
