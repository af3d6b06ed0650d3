#include "core/simulation/nestedengine.h"

#include "core/condition/conditionanalysis.h"
#include "core/model/model.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace core {

namespace {

// `numbers` ascending: the index of `number`, -1 when absent.
int stepIndexIn(const std::vector<int>& numbers, int number)
{
    const auto found = std::lower_bound(numbers.begin(), numbers.end(), number);
    return found != numbers.end() && *found == number ? static_cast<int>(found - numbers.begin()) : -1;
}

} // namespace

NestedEngine::NestedEngine(const NestedGrafcet& grafcet, const std::function<int(std::string_view)>& slotOf,
                           const std::function<IecType(int)>& typeOf)
    : m_grafcet(&grafcet)
    , m_shape(makeShape(grafcet, slotOf, typeOf))
{
    m_emitting.assign(m_shape->continuousActions, 0);
    reset();
}

std::shared_ptr<const NestedEngine::Shape> NestedEngine::makeShape(const NestedGrafcet& grafcet,
                                                                   const std::function<int(std::string_view)>& slotOf,
                                                                   const std::function<IecType(int)>& typeOf)
{
    auto shape = std::make_shared<Shape>();
    shape->slotOf = slotOf;
    shape->targetTypes = typeOf;
    shape->untilStable = grafcet.rule == EvolutionRule::UntilStable;
    std::size_t continuous = 0;
    for (const NestedStep& step : grafcet.steps) {
        shape->stepNumbers.push_back(step.number);
        shape->continuousStart.push_back(continuous);
        continuous += step.continuous.size();
    }
    shape->continuousActions = continuous;
    for (const ContinuousOutput& output : grafcet.outputs) {
        if (output.isComplete) {
            shape->outputOf.push_back(-1);
            continue;
        }
        shape->outputOf.push_back(static_cast<int>(shape->outputNames.size()));
        shape->outputNames.push_back(output.variable);
        shape->outputSlots.push_back(slotOf(output.variable));
    }
    shape->following.resize(grafcet.steps.size());
    for (std::size_t t = 0; t < grafcet.transitions.size(); ++t) {
        const NestedTransition& transition = grafcet.transitions[t];
        std::vector<std::size_t> upstream, downstream;
        bool known = true;
        const auto indices = [&](const std::vector<int>& numbers, std::vector<std::size_t>& into) {
            for (int number : numbers) {
                const int index = stepIndexIn(shape->stepNumbers, number);
                known = known && index >= 0;
                if (index >= 0)
                    into.push_back(static_cast<std::size_t>(index));
            }
        };
        indices(transition.upstream, upstream);
        indices(transition.downstream, downstream);
        // A transition naming a step that does not exist is never enabled
        // (its upstream step is never active) and must not be indexed.
        const bool usable = transition.usable && known;
        if (usable) {
            for (std::size_t step : upstream)
                shape->following[step].push_back(t);
        }
        shape->upstream.push_back(std::move(upstream));
        shape->downstream.push_back(std::move(downstream));
        shape->usable.push_back(usable ? 1 : 0);
    }
    return shape;
}

void NestedEngine::reset()
{
    m_x.assign(m_shape->stepNumbers.size(), 0);
    m_timers.assign(m_grafcet->timers.size(), Timer{});
    m_outputs.assign(m_shape->outputNames.size(), 0);
    std::fill(m_emitting.begin(), m_emitting.end(), 0);
    m_complete = false;
    m_unstable = false;
    m_fired.clear();
    m_enabled.clear();
}

int NestedEngine::slot(std::string_view name) const
{
    return m_shape->slotOf(name);
}

int NestedEngine::ownOutput(std::string_view name) const
{
    for (std::size_t i = 0; i < m_shape->outputNames.size(); ++i) {
        if (equalsIgnoreCase(m_shape->outputNames[i], name))
            return static_cast<int>(i);
    }
    return -1;
}

int NestedEngine::stepIndex(int number) const
{
    return stepIndexIn(m_shape->stepNumbers, number);
}

bool NestedEngine::active(int stepNumber) const
{
    const int index = stepIndex(stepNumber);
    return index >= 0 && m_x[static_cast<std::size_t>(index)] != 0;
}

bool NestedEngine::emitting(int stepNumber, int actionIndex) const
{
    const int index = stepIndex(stepNumber);
    if (index < 0)
        return false;
    const std::vector<NestedAction>& continuous = m_grafcet->steps[static_cast<std::size_t>(index)].continuous;
    for (std::size_t i = 0; i < continuous.size(); ++i) {
        if (continuous[i].index == actionIndex)
            return m_emitting[m_shape->continuousStart[static_cast<std::size_t>(index)] + i] != 0;
    }
    return false;
}

std::vector<int> NestedEngine::activeSteps() const
{
    std::vector<int> numbers;
    for (std::size_t i = 0; i < m_x.size(); ++i) {
        if (m_x[i])
            numbers.push_back(m_shape->stepNumbers[i]);
    }
    return numbers;
}

std::vector<NestedTimerState> NestedEngine::timers() const
{
    std::vector<NestedTimerState> states;
    for (std::size_t i = 0; i < m_timers.size(); ++i) {
        const NestedTimer& timer = m_grafcet->timers[i];
        states.push_back({timer.name, timer.step, timer.durationMs, m_timers[i].elapsed, m_timers[i].q,
                          m_timers[i].running, m_timers[i].start});
    }
    return states;
}

// IEC 61131-3 TON: ET counts from the call in which IN became TRUE.
void NestedEngine::runTon(std::size_t index, bool in, std::int64_t nowMs)
{
    Timer& timer = m_timers[index];
    if (!in) {
        timer = Timer{};
        return;
    }
    if (!timer.running) {
        timer.running = true;
        timer.start = nowMs;
    }
    const bool wasDone = timer.q;
    timer.elapsed = std::min(nowMs - timer.start, m_grafcet->timers[index].durationMs);
    timer.q = nowMs - timer.start >= m_grafcet->timers[index].durationMs;
    // Under an oracle the time since the start means nothing (the verifier
    // merges runs that started at other times): from its second run on, a
    // TON not yet elapsed is decided when read, and once elapsed it stays so.
    if (m_timerOracle && nowMs != timer.start) {
        timer.q = wasDone;
        timer.undecided = !wasDone;
    }
}

bool NestedEngine::timerDone(std::size_t index) const
{
    Timer& timer = m_timers[index];
    if (timer.undecided && m_timerOracle) {
        timer.undecided = false;
        timer.q = m_timerOracle->elapsed(m_grafcet->timers[index], index);
        if (timer.q)
            timer.elapsed = m_grafcet->timers[index].durationMs;
    }
    return timer.q;
}

cond::Value NestedEngine::atom(const cond::Expression& expression, int node, const std::map<int, int>* timers,
                               const NestedGlobals& globals, bool firstEvolution) const
{
    const cond::Node& n = expression.at(node);
    switch (n.kind) {
    case cond::NodeKind::StepActivity: return active(n.number);
    case cond::NodeKind::StepDuration: {
        if (!timers || !timers->count(node))
            return false;
        return active(n.number) && timerDone(static_cast<std::size_t>(timers->at(node)));
    }
    case cond::NodeKind::Complete: return m_complete;
    case cond::NodeKind::Variable: {
        // The FB's own continuous outputs are its VAR_OUTPUTs: the previous call's values.
        if (const int own = ownOutput(n.text); own >= 0)
            return m_outputs[static_cast<std::size_t>(own)] != 0;
        const int s = slot(n.text);
        return s >= 0 ? globals.read(s) : cond::Value{false};
    }
    case cond::NodeKind::Unary: { // an edge, true in the first evolution of a call only
        if (!firstEvolution)
            return false;
        const std::string& name = expression.at(n.operand).text;
        const int s = slot(name);
        if (s < 0)
            return false;
        // Now: the variable as the receptivity reads it (an own continuous
        // output is the VAR_OUTPUT, spec §4.2 (4)); before: <V>_PREV, the
        // global at the end of the previous scan (§4.4).
        const int own = ownOutput(name);
        const bool now = own >= 0 ? m_outputs[static_cast<std::size_t>(own)] != 0 : cond::isTrue(globals.read(s));
        const bool before = globals.previous(s);
        return n.unaryOp == cond::UnaryOp::RisingEdge ? now && !before : !now && before;
    }
    default: return false;
    }
}

cond::Value NestedEngine::evaluate(const cond::Expression& expression, const std::map<int, int>* timers,
                                   const NestedGlobals& globals, bool firstEvolution) const
{
    int divisionByZero = -1;
    const cond::Value value = cond::evaluate(
        expression, [&](int node) { return atom(expression, node, timers, globals, firstEvolution); }, divisionByZero);
    if (divisionByZero >= 0 && !m_divisionFault)
        noteDivisionByZero(expression, divisionByZero);
    return value;
}

// Names the receptivity or action the expression belongs to.
void NestedEngine::noteDivisionByZero(const cond::Expression& expression, int node) const
{
    SimulationFault fault;
    const std::string& owner = m_grafcet->stepId;
    for (const NestedTransition& t : m_grafcet->transitions) {
        if (&t.receptivity.expression != &expression)
            continue;
        fault.nestedTransition = t.number;
        fault.place = "the receptivity of T" + std::to_string(t.number) + " of " + owner;
        fault.text = t.text;
    }
    for (const NestedStep& step : m_grafcet->steps) {
        for (const auto* list : {&step.onActivation, &step.onDeactivation, &step.continuous}) {
            for (const NestedAction& action : *list) {
                if (&action.parsed.action.condition != &expression && &action.parsed.action.value != &expression)
                    continue;
                fault.nestedStep = step.number;
                fault.actionIndex = action.index;
                fault.place = "action " + std::to_string(action.index + 1) + " of step " + std::to_string(step.number)
                    + " of " + owner;
                fault.text = action.text;
            }
        }
    }
    fault.division = excerpt(fault.text, expression.at(node).span);
    m_divisionFault = std::move(fault);
}

namespace {

// The value as the target's IEC type stores it: integers wrap around.
// A double as REAL holds it: out of float's range is INF, as IEEE 754 rounds
// (a plain cast would be undefined there).
float toFloat(double real)
{
    if (std::isfinite(real) && std::fabs(real) > static_cast<double>(std::numeric_limits<float>::max()))
        return real > 0 ? std::numeric_limits<float>::infinity() : -std::numeric_limits<float>::infinity();
    return static_cast<float>(real);
}

// A double truncated to 64 bits, NaN as 0 and saturated at the ends (a plain
// cast is undefined there); the type's own range wraps afterwards.
std::int64_t truncatedToInt64(double real)
{
    constexpr double kTwo63 = 9223372036854775808.0;
    if (std::isnan(real))
        return 0;
    if (real >= kTwo63)
        return std::numeric_limits<std::int64_t>::max();
    if (real < -kTwo63)
        return std::numeric_limits<std::int64_t>::min();
    return static_cast<std::int64_t>(real);
}

cond::Value storedValue(const cond::Value& value, IecType type)
{
    if (type == IecType::Bool)
        return cond::isTrue(value);
    if (isRealType(type)) {
        const double real = std::holds_alternative<double>(value) ? std::get<double>(value)
            : static_cast<double>(std::holds_alternative<std::int64_t>(value) ? std::get<std::int64_t>(value)
                                                                                : std::get<bool>(value));
        return type == IecType::Real ? static_cast<double>(toFloat(real)) : real;
    }
    std::int64_t integer = std::holds_alternative<std::int64_t>(value) ? std::get<std::int64_t>(value)
        : std::holds_alternative<bool>(value)                         ? std::int64_t{std::get<bool>(value)}
                                                                      : truncatedToInt64(std::get<double>(value));
    const cond::IntegerRange range = cond::integerRange(type);
    const auto width = static_cast<std::uint64_t>(range.high) - static_cast<std::uint64_t>(range.low) + 1;
    if (width != 0 && (integer < range.low || integer > range.high)) {
        const auto offset = (static_cast<std::uint64_t>(integer) - static_cast<std::uint64_t>(range.low)) % width;
        integer = static_cast<std::int64_t>(static_cast<std::uint64_t>(range.low) + offset);
    }
    return integer;
}

} // namespace

void NestedEngine::runStored(const std::vector<NestedAction>& actions, NestedGlobals& globals)
{
    for (const NestedAction& action : actions) {
        if (!action.usable)
            continue;
        const cond::ActionSyntax& syntax = action.parsed.action;
        cond::Value value = syntax.form == cond::ActionForm::Set ? cond::Value{true}
            : syntax.form == cond::ActionForm::Reset             ? cond::Value{false}
                                                                 : evaluate(syntax.value, nullptr, globals, false);
        if (action.targetIsComplete) {
            m_complete = cond::isTrue(value);
            continue;
        }
        const int s = slot(action.target);
        if (s >= 0)
            globals.write(s, storedValue(value, m_shape->targetTypes(s)));
    }
}

bool NestedEngine::enabled(std::size_t transition) const
{
    const std::vector<std::size_t>& upstream = m_shape->upstream[transition];
    return std::all_of(upstream.begin(), upstream.end(), [&](std::size_t step) { return m_x[step] != 0; });
}

// Once per evolving call: the transitions enabled in the situation it starts from.
void NestedEngine::findEnabled()
{
    m_enabled.clear();
    for (std::size_t t = 0; t < m_shape->usable.size(); ++t) {
        if (m_shape->usable[t] && enabled(t))
            m_enabled.push_back(t);
    }
}

// After an evolution only two kinds of transitions can have changed: those
// enabled before (one of their upstream steps may have left) and those
// following a step that entered.
void NestedEngine::updateEnabled(const std::vector<std::size_t>& entered)
{
    std::vector<std::size_t> candidates = std::move(m_enabled);
    for (std::size_t step : entered)
        candidates.insert(candidates.end(), m_shape->following[step].begin(), m_shape->following[step].end());
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    std::erase_if(candidates, [this](std::size_t t) { return !enabled(t); });
    m_enabled = std::move(candidates);
}

// IEC 60848 rules 2-5; true when a transition fired. Only the enabled
// transitions are evaluated: the others cannot fire, whatever their receptivity.
bool NestedEngine::evolve(bool firstEvolution, std::int64_t nowMs, NestedGlobals& globals)
{
    const auto& transitions = m_grafcet->transitions;
    std::vector<std::size_t> firing;
    m_receptivityEvaluations += m_enabled.size();
    for (std::size_t t : m_enabled) {
        const NestedTransition& transition = transitions[t];
        if (cond::isTrue(evaluate(transition.receptivity.expression, &transition.timerOfNode, globals, firstEvolution)))
            firing.push_back(t);
    }
    if (firing.empty())
        return false;
    constexpr char kDeactivated = 1, kActivated = 2;
    std::vector<std::pair<std::size_t, char>> touched; // step, what the firing does to it
    for (std::size_t t : firing) {
        m_fired.push_back(transitions[t].number);
        for (std::size_t step : m_shape->upstream[t])
            touched.emplace_back(step, kDeactivated);
        for (std::size_t step : m_shape->downstream[t])
            touched.emplace_back(step, kActivated);
    }
    // Steps in number order, as the actions run (steps are kept by number).
    std::sort(touched.begin(), touched.end());
    std::vector<std::size_t> left, entered;
    for (std::size_t i = 0; i < touched.size();) {
        const std::size_t step = touched[i].first;
        char what = 0;
        for (; i < touched.size() && touched[i].first == step; ++i)
            what |= touched[i].second;
        if (what == kDeactivated)
            left.push_back(step);
        else if ((what & kActivated) && !m_x[step])
            entered.push_back(step);
    }
    for (std::size_t step : left)
        m_x[step] = 0;
    for (std::size_t step : entered)
        m_x[step] = 1;
    for (std::size_t step : left)
        runStored(m_grafcet->steps[step].onDeactivation, globals);
    for (std::size_t step : entered) {
        runStored(m_grafcet->steps[step].onActivation, globals);
        for (int timer : m_grafcet->steps[step].timers)
            runTon(static_cast<std::size_t>(timer), false, nowMs);
    }
    updateEnabled(entered);
    return true;
}

void NestedEngine::computeOutputs(const NestedGlobals& globals)
{
    std::vector<char> values(m_outputs.size(), 0);
    bool complete = m_complete;
    for (std::size_t o = 0; o < m_grafcet->outputs.size(); ++o) {
        const ContinuousOutput& output = m_grafcet->outputs[o];
        bool value = false;
        for (const ContinuousOutput::Driver& driver : output.drivers) {
            // Every driver, not only up to the first that holds: each action's own state is shown.
            const auto index = static_cast<std::size_t>(stepIndex(driver.step));
            const auto action = static_cast<std::size_t>(driver.action);
            bool on = m_x[index] != 0;
            if (on) {
                const cond::Expression& condition = m_grafcet->steps[index].continuous[action].parsed.action.condition;
                on = condition.empty() || cond::isTrue(evaluate(condition, nullptr, globals, false));
            }
            m_emitting[m_shape->continuousStart[index] + action] = on;
            value = value || on;
        }
        if (m_shape->outputOf[o] < 0)
            complete = value;
        else
            values[static_cast<std::size_t>(m_shape->outputOf[o])] = value;
    }
    m_outputs = std::move(values);
    m_complete = complete;
}

void NestedEngine::call(bool initialization, std::int64_t nowMs, NestedGlobals& globals)
{
    m_fired.clear();
    if (initialization) {
        for (std::size_t i = 0; i < m_x.size(); ++i)
            m_x[i] = m_grafcet->steps[i].initial;
        m_complete = false;
        m_unstable = false;
        for (std::size_t t = 0; t < m_timers.size(); ++t)
            runTon(t, false, nowMs);
        for (const NestedStep& step : m_grafcet->steps) {
            if (step.initial)
                runStored(step.onActivation, globals);
        }
    } else {
        for (std::size_t t = 0; t < m_timers.size(); ++t)
            runTon(t, active(m_grafcet->timers[t].step), nowMs);
        findEnabled();
        int evolutions = 0;
        bool fired = false;
        do {
            fired = evolve(evolutions == 0, nowMs, globals);
            ++evolutions;
        } while (m_shape->untilStable && fired && evolutions < m_grafcet->maxEvolutions);
        if (m_shape->untilStable) {
            m_unstable = fired;
            // Each evolution added its own in number order; a transition may fire in several.
            std::sort(m_fired.begin(), m_fired.end());
            m_fired.erase(std::unique(m_fired.begin(), m_fired.end()), m_fired.end());
        }
    }
    computeOutputs(globals);
}

} // namespace core
