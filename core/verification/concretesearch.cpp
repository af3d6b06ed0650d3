#include "core/verification/concretesearch.h"

#include "core/condition/conditionevaluator.h"
#include "core/condition/conditionparser.h"
#include "core/formats/varint.h"
#include "core/model/iectypes.h"
#include "core/model/model.h"
#include "core/simulation/scenario.h"
#include "core/simulation/simulator.h"
#include "core/verification/property.h"
#include "core/verification/propertyevaluation.h"
#include "core/verification/scanreads.h"

#include <cctype>
#include <cstdint>
#include <cstring>
#include <deque>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <variant>
#include <vector>

namespace core {

namespace {

// Past this many combinations of the inputs a scan reads, the state is not
// expanded: it would cost more scans than the budget allows for a useful depth.
constexpr std::size_t kMaxCombinationsPerScan = 4096;
// A SearchNode::choice for an input the scan does not read: it keeps its value.
constexpr std::size_t kKept = SIZE_MAX;
constexpr std::size_t kMaxValuesPerNumber = 8;

std::string valueText(const cond::Value& value)
{
    if (std::holds_alternative<bool>(value))
        return std::get<bool>(value) ? "TRUE" : "FALSE";
    return cond::formatValue(value);
}

// The numeric constants the model's conditions, receptivities, actions and
// the property are written with: the values where comparisons change.
std::vector<double> modelConstants(const Model& model, const std::string& property)
{
    std::set<double> constants;
    const auto collect = [&](const std::string& text, cond::Context context) {
        for (const cond::Token& token : cond::tokenize(text, cond::ParseOptions{context})) {
            if (token.kind != cond::TokenKind::IntegerLiteral && token.kind != cond::TokenKind::RealLiteral)
                continue;
            try {
                constants.insert(std::stod(std::string(token.text)));
            } catch (const std::exception&) {
                // A literal out of double's range compares with nothing the search can set.
            }
        }
    };
    for (const Transition& transition : model.transitions())
        collect(transition.condition, cond::Context::Gemma);
    for (const auto& [id, grafcet] : model.grafcets()) {
        for (const GrafcetTransition& transition : grafcet.transitions())
            collect(transition.receptivity, cond::Context::Nested);
        for (const GrafcetStep& step : grafcet.steps()) {
            for (const GrafcetAction& action : step.actions)
                collect(action.text, cond::Context::Nested);
        }
    }
    collect(property, cond::Context::Property);
    return {constants.begin(), constants.end()};
}

// The values an input takes at each scan: both for a BOOL; for a number its
// default, then each constant and its neighbours, those its type accepts.
std::vector<cond::Value> inputValues(Simulator probe, std::size_t index, const std::vector<double>& constants)
{
    const IecType type = probe.variableType(index);
    if (type == IecType::Bool)
        return {cond::Value{false}, cond::Value{true}};
    std::vector<cond::Value> values{probe.variableValue(index)};
    const auto add = [&](double number) {
        if (!isRealType(type) && !(number > -9.0e18 && number < 9.0e18))
            return; // no integer type holds it (and the conversion would be undefined)
        const cond::Value value = isRealType(type) ? cond::Value{number}
                                                   : cond::Value{static_cast<std::int64_t>(number)};
        if (values.size() >= kMaxValuesPerNumber || !probe.setVariableAt(index, value).ok)
            return;
        for (const cond::Value& known : values) {
            if (valueText(known) == valueText(value))
                return;
        }
        values.push_back(value);
    };
    for (double constant : constants) {
        add(constant);
        add(constant + 1);
        add(constant - 1);
    }
    return values;
}

std::string upperName(std::string text)
{
    for (char& c : text)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

// Appends `value` so that keys compare as the values do: a kind byte, then
// a BOOL's byte, an integer in LEB128 after zigzag (one or two bytes for the
// counters and set points of a machine) or a REAL's eight bytes.
void appendValue(std::string& key, const cond::Value& value)
{
    key += static_cast<char>('0' + value.index());
    if (const bool* flag = std::get_if<bool>(&value)) {
        key += *flag ? '1' : '0';
    } else if (const std::int64_t* integer = std::get_if<std::int64_t>(&value)) {
        appendVarint(key, zigzag(*integer));
    } else {
        char bytes[sizeof(double)];
        std::memcpy(bytes, &std::get<double>(value), sizeof bytes);
        key.append(bytes, sizeof bytes);
    }
}

// What decides the simulator's future: everything but the scan count and the
// inputs in `overwritten`, which every scan that reads them sets first. A
// byte string for the set of states seen, built in one buffer: the search
// makes one per successor.
std::string stateKey(const Simulator& simulator, const std::vector<bool>& overwritten)
{
    std::string key = std::to_string(simulator.activeStepNumber()) + (simulator.entry() ? "E" : "-");
    for (bool token : simulator.tokenValues())
        key += token ? '1' : '0';
    const std::string activeStep = simulator.activeStepId();
    for (const std::string& step : simulator.nestedSteps()) {
        // An inactive function block starts afresh when its step is entered
        // again (its Initialization call), and only the active step's
        // Complete is read: what the others froze does not decide the future.
        if (step != activeStep)
            continue;
        key += '|';
        key += simulator.complete(step) ? 'C' : '-';
        key += simulator.manualComplete(step) ? 'M' : '-';
        for (int active : simulator.activeNestedSteps(step))
            key += std::to_string(active) + ',';
        for (const NestedTimerState& timer : simulator.nestedTimers(step))
            key += 't' + std::to_string(timer.elapsedMs) + (timer.done ? 'Q' : '-');
        // A TON reads its step as the previous call left it: a step that has
        // just become active has a timer that has not started yet, with ET 0
        // as one that started in this scan. The transitions that fired tell them apart.
        for (int fired : simulator.firedNestedTransitions(step))
            key += 'f' + std::to_string(fired);
    }
    key += '|';
    for (std::size_t i = 0; i < overwritten.size(); ++i) {
        if (!overwritten[i])
            appendValue(key, simulator.variableValue(i));
    }
    return key;
}

// One scan of a run: the inputs set before it, the Complete chosen for its
// active step (when free), and the state it started from.
struct SearchNode {
    std::size_t parent = SIZE_MAX; // SIZE_MAX: the scan starts from reset
    std::vector<std::size_t> choice; // per searched input: index into its values, or kKept
    std::string freeStep;            // the free step without GRAFCET active in the scan, if any
    bool complete = false;
};

class ConcreteSearch {
public:
    ConcreteSearch(const Model& model, const std::string& property, const ConcreteSearchOptions& options)
        : m_model(model)
        , m_property(parseProperty(property))
        , m_options(options)
        , m_start(model)
    {
        for (const std::string& step : m_start.nestedSteps()) {
            if (m_start.hasGrafcet(step))
                continue;
            const auto assumed = options.complete.find(step);
            const bool automatic = assumed != options.complete.end() && assumed->second == CompleteAssumption::Automatic;
            m_start.setCompleteMode(step, automatic ? CompleteMode::Automatic : CompleteMode::Manual);
            if (!automatic)
                m_freeSteps.insert(step);
        }
        const std::vector<double> constants = modelConstants(model, property);
        std::set<std::string> edges;
        for (const std::string& name : m_start.program().edgeVariables)
            edges.insert(upperName(name));
        m_overwritten.assign(m_start.variableNames().size(), false);
        for (std::size_t i = 0; i < m_start.variableNames().size(); ++i) {
            if (m_start.variableKind(i) != VariableKind::Input)
                continue;
            m_inputs.push_back(i);
            m_inputUpperNames.push_back(upperName(m_start.variableNames()[i]));
            m_values.push_back(inputValues(m_start, i, constants));
            m_overwritten[i] = edges.count(upperName(m_start.variableNames()[i])) == 0;
        }
    }

    ConcreteSearchResult run(const std::string& title);

private:
    std::vector<std::size_t> readInputs(const Simulator& state) const;
    std::size_t combinations(const std::vector<std::size_t>& read) const;
    std::string scenarioText(std::size_t last, const std::string& title, std::int64_t& scans) const;
    std::optional<Counterexample> replayed(std::size_t last, const std::string& title) const;
    bool outOfTime() const;

    const Model& m_model;
    ParsedProperty m_property;
    const ConcreteSearchOptions& m_options;
    Simulator m_start;
    std::set<std::string> m_freeSteps;
    std::vector<std::size_t> m_inputs;             // variable indices of the inputs
    std::vector<std::string> m_inputUpperNames;    // per input, as scanReads names it
    std::vector<std::vector<cond::Value>> m_values; // per input, the values tried
    std::vector<bool> m_overwritten;                // per variable: an input not read under an edge
    std::vector<SearchNode> m_nodes;
};

// Positions in m_inputs of the inputs the next scan may read.
std::vector<std::size_t> ConcreteSearch::readInputs(const Simulator& state) const
{
    const std::set<std::string> reads = scanReads(state, m_property.expression);
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < m_inputs.size(); ++i) {
        if (reads.count(m_inputUpperNames[i]))
            out.push_back(i);
    }
    return out;
}

std::size_t ConcreteSearch::combinations(const std::vector<std::size_t>& read) const
{
    std::size_t product = 1;
    for (std::size_t i : read) {
        if (product > kMaxCombinationsPerScan)
            break;
        product *= m_values[i].size();
    }
    return product;
}

bool ConcreteSearch::outOfTime() const
{
    return std::chrono::steady_clock::now() >= m_options.deadline
        || (m_options.cancelled && m_options.cancelled());
}

ConcreteSearchResult ConcreteSearch::run(const std::string& title)
{
    ConcreteSearchResult result;
    if (!m_property.ok()) {
        result.reason = "the property does not parse";
        return result;
    }
    std::size_t unexpanded = 0; // states whose scan reads too many inputs
    std::unordered_set<std::string> seen{stateKey(m_start, m_overwritten)};
    std::deque<std::pair<std::size_t, Simulator>> frontier; // (node of the scan that led there, state)
    frontier.emplace_back(SIZE_MAX, m_start);
    while (!frontier.empty()) {
        auto [from, state] = std::move(frontier.front());
        frontier.pop_front();
        const std::string active = state.activeStepId();
        const bool chooseComplete = m_freeSteps.count(active) > 0;
        const std::vector<std::size_t> read = readInputs(state);
        const std::size_t perScan = combinations(read);
        if (perScan > kMaxCombinationsPerScan) {
            ++unexpanded;
            continue;
        }
        for (std::size_t combination = 0; combination < perScan; ++combination) {
            for (int complete = 0; complete <= (chooseComplete ? 1 : 0); ++complete) {
                if (outOfTime()) {
                    result.states = seen.size();
                    result.reason = "no violation found in " + std::to_string(seen.size())
                        + " states of the simulator's runs before the time limit";
                    return result;
                }
                SearchNode node;
                node.parent = from;
                Simulator next = state;
                std::size_t rest = combination;
                node.choice.assign(m_inputs.size(), kKept);
                for (std::size_t i : read) {
                    node.choice[i] = rest % m_values[i].size();
                    rest /= m_values[i].size();
                    next.setVariableAt(m_inputs[i], m_values[i][node.choice[i]]);
                }
                if (chooseComplete) {
                    node.freeStep = active;
                    node.complete = complete != 0;
                    next.setComplete(active, node.complete);
                }
                next.run(1);
                m_nodes.push_back(std::move(node));
                const std::size_t index = m_nodes.size() - 1;
                if (propertyViolatedOn(m_model, m_property, next)) {
                    result.states = seen.size();
                    result.counterexample = replayed(index, title);
                    if (!result.counterexample)
                        result.reason = "a violating run of the simulator was found but did not replay";
                    return result;
                }
                if (seen.size() < m_options.maxStates && seen.insert(stateKey(next, m_overwritten)).second)
                    frontier.emplace_back(index, std::move(next));
                else
                    m_nodes.pop_back(); // nothing will point to it
            }
        }
    }
    result.states = seen.size();
    result.reason = seen.size() >= m_options.maxStates
        ? "no violation found in the first " + std::to_string(seen.size()) + " states of the simulator's runs"
        : "no violation found in the " + std::to_string(seen.size())
            + " states of the simulator's runs with the input values tried";
    if (unexpanded > 0)
        result.reason += " (" + std::to_string(unexpanded) + " of them not searched further: their scan reads more than "
            + std::to_string(kMaxCombinationsPerScan) + " input combinations)";
    return result;
}

std::string ConcreteSearch::scenarioText(std::size_t last, const std::string& title, std::int64_t& scans) const
{
    std::vector<std::size_t> path;
    for (std::size_t n = last; n != SIZE_MAX; n = m_nodes[n].parent)
        path.push_back(n);
    std::ostringstream text;
    text << "# " << title << "\n";
    std::vector<std::string> current;
    for (std::size_t i = 0; i < m_inputs.size(); ++i)
        current.push_back(valueText(m_start.variableValue(m_inputs[i])));
    std::map<std::string, std::string> completeSet; // free step -> the value the scenario last set
    Simulator replay = m_start;
    scans = 0;
    for (auto it = path.rbegin(); it != path.rend(); ++it) {
        const SearchNode& node = m_nodes[*it];
        ++scans;
        std::string sets;
        for (std::size_t i = 0; i < m_inputs.size(); ++i) {
            if (node.choice[i] == kKept)
                continue;
            const std::string value = valueText(m_values[i][node.choice[i]]);
            if (value == current[i])
                continue;
            current[i] = value;
            sets += (sets.empty() ? "" : ", ") + m_start.variableNames()[m_inputs[i]] + " = " + value;
        }
        if (!sets.empty())
            text << "at " << scans << ": set " << sets << "\n";
        if (!node.freeStep.empty()) {
            const std::string value = node.complete ? "TRUE" : "FALSE";
            auto [entry, added] = completeSet.emplace(node.freeStep, value);
            if (added || entry->second != value) {
                entry->second = value;
                text << "at " << scans << ": set complete " << node.freeStep << " = " << value << "\n";
            }
        }
    }
    return text.str();
}

std::optional<Counterexample> ConcreteSearch::replayed(std::size_t last, const std::string& title) const
{
    Counterexample out;
    std::int64_t scans = 0;
    out.text = scenarioText(last, title, scans);
    // The state the violation is in, as the other counterexamples state it.
    Simulator check(m_model);
    ScenarioParseResult first = parseScenario(out.text);
    if (!first.ok() || !validateScenario(first.scenario, check).empty())
        return std::nullopt;
    (void)runScenario(first.scenario, check, scans);
    if (!check.activeStepId().empty())
        out.text += "at " + std::to_string(scans) + ": expect step " + check.activeStepId() + "\n";
    ScenarioParseResult parsed = parseScenario(out.text);
    if (!parsed.ok())
        return std::nullopt;
    out.scenario = std::move(parsed.scenario);
    out.scans = scans;
    Simulator simulator(m_model);
    if (!validateScenario(out.scenario, simulator).empty())
        return std::nullopt;
    out.confirmed = runScenario(out.scenario, simulator, scans).passed()
        && propertyViolatedOn(m_model, m_property, simulator);
    if (!out.confirmed)
        return std::nullopt;
    return out;
}

} // namespace

ConcreteSearchResult searchPropertyViolation(const Model& model, const std::string& property,
                                             const std::string& title, const ConcreteSearchOptions& options)
{
    return ConcreteSearch(model, property, options).run(title);
}

} // namespace core
