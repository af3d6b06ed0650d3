#include "samplemodels.h"

#include "modelfactory.h"

#include "core/checks/checks.h"

#include <array>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace samples {

core::Variable variable(std::string name, core::IecType type, core::VariableKind kind)
{
    core::Variable v{std::move(name), type, "", ""};
    v.kind = kind;
    return v;
}

void requireBuilt(const core::Status& status)
{
    if (!status)
        throw std::logic_error("sample model: " + status.message);
}

namespace {

void addVariable(core::Model& model, const std::string& name, core::IecType type, std::string defaultValue = {},
                 std::string comment = {})
{
    requireBuilt(model.addVariable({name, type, std::move(defaultValue), std::move(comment)}));
}

// ---- random models -----------------------------------------------------------

class RandomModelBuilder {
public:
    explicit RandomModelBuilder(std::uint32_t seed) : m_rng(seed) {}

    core::Model build(bool allowHiding);

private:
    int uniform(int low, int high) { return std::uniform_int_distribution<int>(low, high)(m_rng); }
    bool chance(double p) { return std::bernoulli_distribution(p)(m_rng); }
    template <typename T> const T& pick(const std::vector<T>& values)
    {
        return values[static_cast<std::size_t>(uniform(0, static_cast<int>(values.size()) - 1))];
    }

    void addVariables(core::Model& model);
    void randomizeSteps(core::Model& model, bool allowHiding);
    void randomizeTransitions(core::Model& model, bool allowHiding);
    std::string condition(std::vector<std::pair<std::string, bool>>& boolLiterals);
    std::string comparison();
    void randomizePriorities(core::Model& model);

    std::mt19937 m_rng;
    std::vector<std::string> m_bools;
    std::vector<std::string> m_integers; // signed and unsigned: compared with small non-negative literals
    std::vector<std::string> m_reals;
};

const std::vector<std::string> kAwkwardTexts = {
    "",
    "plain comment",
    "ends a CDATA ]]> and opens (* an ST comment *)",
    "<tag attr=\"value\"> & 'quotes'",
    "multi\nline\ttext",
    "Caf\xC3\xA9 \xC3\x9Cnic\xC3\xB6" "de \xE2\x82\xAC \xF0\x9F\x98\x80",
};

void RandomModelBuilder::addVariables(core::Model& model)
{
    const std::vector<core::IecType> integerTypes = {core::IecType::Sint, core::IecType::Int, core::IecType::Dint,
                                                     core::IecType::Lint, core::IecType::Usint, core::IecType::Uint,
                                                     core::IecType::Udint, core::IecType::Ulint};
    const int boolCount = uniform(2, 8);
    for (int i = 1; i <= boolCount; ++i) {
        const std::string name = "Sig" + std::to_string(i);
        const std::string value = chance(0.3) ? (chance(0.5) ? "TRUE" : "FALSE") : "";
        addVariable(model, name, core::IecType::Bool, value, pick(kAwkwardTexts));
        m_bools.push_back(name);
    }
    const int integerCount = uniform(1, 4);
    for (int i = 1; i <= integerCount; ++i) {
        const std::string name = "Count" + std::to_string(i);
        const std::string value = chance(0.5) ? std::to_string(uniform(0, 100)) : "";
        addVariable(model, name, pick(integerTypes), value, pick(kAwkwardTexts));
        m_integers.push_back(name);
    }
    const int realCount = uniform(0, 2);
    for (int i = 1; i <= realCount; ++i) {
        const std::string name = "Level" + std::to_string(i);
        addVariable(model, name, chance(0.5) ? core::IecType::Real : core::IecType::Lreal,
                    chance(0.5) ? "2.5" : "", pick(kAwkwardTexts));
        m_reals.push_back(name);
    }
}

void RandomModelBuilder::randomizeSteps(core::Model& model, bool allowHiding)
{
    const std::vector<core::StepType> types = {core::StepType::Simple, core::StepType::Macro,
                                               core::StepType::Enclosing};
    for (const core::Step& step : std::vector<core::Step>(model.steps())) {
        requireBuilt(model.setStepType(step.id, pick(types)));
        requireBuilt(model.setStepComment(step.id, pick(kAwkwardTexts)));
    }
    const std::string initial = model.steps()[static_cast<std::size_t>(uniform(0, 15))].id;
    requireBuilt(model.setInitialStep(initial));
    if (!allowHiding)
        return;
    for (const core::Step& step : std::vector<core::Step>(model.steps())) {
        if (step.id != initial && chance(0.15))
            requireBuilt(model.setStepHidden(step.id, true));
    }
}

std::string RandomModelBuilder::comparison()
{
    static const std::vector<std::string> operators = {"=", "<>", "<", ">", "<=", ">="};
    if (!m_reals.empty() && chance(0.3))
        return pick(m_reals) + " " + pick(operators) + " 1.5";
    const std::string left = pick(m_integers);
    if (chance(0.3))
        return left + " + 1 " + pick(operators) + " " + std::to_string(uniform(0, 50));
    return left + " " + pick(operators) + " " + std::to_string(uniform(0, 100));
}

// Each BOOL variable occurs at most once, so any of them can take a token.
std::string RandomModelBuilder::condition(std::vector<std::pair<std::string, bool>>& boolLiterals)
{
    if (chance(0.05))
        return "TRUE";
    static const std::vector<std::string> joins = {" AND ", " OR ", " XOR ", " & "};
    std::vector<std::string> unused = m_bools;
    std::string text;
    const int operands = uniform(1, 3);
    for (int i = 0; i < operands; ++i) {
        std::string operand;
        if (!unused.empty() && chance(0.75)) {
            const std::size_t index = static_cast<std::size_t>(uniform(0, static_cast<int>(unused.size()) - 1));
            const bool negated = chance(0.35);
            boolLiterals.emplace_back(unused[index], negated);
            operand = (negated ? "NOT " : "") + unused[index];
            unused.erase(unused.begin() + static_cast<std::ptrdiff_t>(index));
        } else {
            operand = comparison();
            if (chance(0.5))
                operand = "(" + operand + ")";
        }
        text += i == 0 ? operand : pick(joins) + operand;
    }
    return text;
}

void RandomModelBuilder::randomizeTransitions(core::Model& model, bool allowHiding)
{
    for (const core::Transition& t : std::vector<core::Transition>(model.transitions())) {
        std::vector<std::pair<std::string, bool>> literals;
        requireBuilt(model.setCondition(t.id, condition(literals)));
        const core::Step* source = model.step(t.source);
        const bool nested = source && core::hasNestedBehaviour(source->type);
        requireBuilt(model.setNegated(t.id, nested && chance(0.3)));
        std::vector<std::string> tokens;
        for (const auto& literal : literals) {
            if (nested && chance(0.3))
                tokens.push_back(literal.first);
        }
        requireBuilt(model.setTokens(t.id, tokens));
        if (allowHiding && chance(0.08))
            requireBuilt(model.setTransitionHidden(t.id, true));
    }
}

void RandomModelBuilder::randomizePriorities(core::Model& model)
{
    for (const core::Transition& t : std::vector<core::Transition>(model.transitions())) {
        const auto effective = model.effectiveOutgoing(t.source);
        if (model.isEffective(t) && effective.size() > 1 && chance(0.3))
            requireBuilt(model.setPriority(t.id, uniform(1, static_cast<int>(effective.size()))));
    }
}

core::Model RandomModelBuilder::build(bool allowHiding)
{
    static const std::vector<std::string> names = {
        "Random machine", "Line 3 <pack & seal>", "Presse \"Nord\" ]]> test", "Caf\xC3\xA9 \xC3\xBCnicode"};
    m_bools.clear();
    m_integers.clear();
    m_reals.clear();
    core::Model model;
    requireBuilt(model.setName(pick(names) + " " + std::to_string(uniform(1, 999))));
    requireBuilt(model.setCycleTimeMs(pick(std::vector<int>{1, 5, 10, 20, 50, 100, 1500, 60000})));
    addVariables(model);
    randomizeSteps(model, allowHiding);
    randomizeTransitions(model, allowHiding);
    randomizePriorities(model);
    return model;
}

} // namespace

core::Model caseStudyModel()
{
    using core::IecType;
    core::Model model;
    requireBuilt(model.setName("Filling and capping machine"));
    for (const char* name : {"EmergencyInterrupter", "Alarm", "ManualCapping", "Stop", "Manual", "StationTest",
                             "Semiautomatic", "EmptyMachine", "Start", "Ready", "Automatic", "CycleEnd", "Reset"})
        addVariable(model, name, IecType::Bool);
    requireBuilt(model.setVariableDefault("EmergencyInterrupter", "TRUE"));
    requireBuilt(model.setVariableComment("EmergencyInterrupter", "NC contact: FALSE when the mushroom button is pressed"));
    addVariable(model, "PieceCount", IecType::Int, "0", "pieces since the start of the batch");
    addVariable(model, "Pressure", IecType::Real, "0.0", "bar");

    requireBuilt(model.setStepType("A7", core::StepType::Simple));
    requireBuilt(model.setStepType("D2", core::StepType::Simple));
    requireBuilt(model.setStepHidden("F6", true));
    requireBuilt(model.setStepComment("F1", "fill, cap, eject"));
    requireBuilt(model.setStepComment("D3", "capping by hand while the filler goes on"));
    for (const factory::CaseStudyCondition& row : factory::caseStudyConditions())
        requireBuilt(model.setCondition(row.transition, row.condition));
    requireBuilt(model.setTokens("F1->A2", {"Stop"}));
    requireBuilt(model.setTokens("F1->F3", {"EmptyMachine"}));
    return model;
}

core::Model randomModel(std::uint32_t seed)
{
    // Hiding can leave a step unreachable or without a way out; the checks
    // say so, and another draw from the same seed is taken.
    RandomModelBuilder builder(seed);
    for (int attempt = 0; attempt < 50; ++attempt) {
        core::Model model = builder.build(true);
        if (!core::hasErrors(core::checkModel(model)))
            return model;
    }
    return builder.build(false);
}

void addRandomNestedGrafcets(core::Model& model, std::uint32_t seed)
{
    std::mt19937 random(seed);
    const auto pick = [&](int count) { return static_cast<int>(random() % static_cast<unsigned>(count)); };
    std::vector<std::string> inputs;
    for (const core::Variable& variable : model.variables()) {
        if (variable.type == core::IecType::Bool && variable.kind == core::VariableKind::Input)
            inputs.push_back(variable.name);
    }
    if (inputs.empty()) {
        model.addVariable(core::Variable{"NestedIn", core::IecType::Bool, "", "input of the nested GRAFCETs"});
        inputs.push_back("NestedIn");
    }
    std::vector<std::string> outputs;
    for (int i = 0; i < 4; ++i) {
        core::Variable output{"NestedOut" + std::to_string(i), core::IecType::Bool, "", "driven by nested GRAFCETs"};
        output.kind = core::VariableKind::Output;
        model.addVariable(output);
        outputs.push_back(output.name);
    }
    core::Variable counter{"NestedCount", core::IecType::Int, "", "counted by nested GRAFCETs"};
    counter.kind = core::VariableKind::Internal;
    model.addVariable(counter);

    for (const core::Step& step : model.steps()) {
        if (step.hidden || step.type == core::StepType::Simple || pick(4) == 0)
            continue;
        const int steps = 3 + pick(7);
        const auto input = [&] { return inputs[static_cast<std::size_t>(pick(static_cast<int>(inputs.size())))]; };
        const auto receptivity = [&](int from) -> std::string {
            switch (pick(7)) {
            case 0: return input();
            case 1: return "NOT " + input();
            case 2: return "RE " + input();
            case 3: return "FE " + input() + " OR " + input();
            case 4: return std::to_string(20 * (1 + pick(10))) + "ms/X" + std::to_string(from);
            case 5: return input() + " AND X" + std::to_string(1 + pick(steps));
            default: return "TRUE";
            }
        };
        const auto action = [&]() -> core::GrafcetAction {
            const std::string out = outputs[static_cast<std::size_t>(pick(4))];
            switch (pick(6)) {
            case 0: return {core::ActionTiming::Continuous, "N " + out};
            case 1: return {core::ActionTiming::Continuous, out + " IF " + input()};
            case 2: return {core::ActionTiming::OnActivation, "NestedCount := NestedCount + 1"};
            case 3: return {core::ActionTiming::OnDeactivation, "S " + out};
            case 4: return {core::ActionTiming::OnActivation, "S Complete"};
            default: return {core::ActionTiming::Continuous, "Complete"};
            }
        };
        for (int n = 1; n <= steps; ++n) {
            core::GrafcetStep nested{n, n == 1, "", {}};
            for (int a = pick(3); a > 0; --a)
                nested.actions.push_back(action());
            model.addGrafcetStep(step.id, nested);
        }
        int number = 1;
        for (int n = 1; n < steps; ++n)
            model.addGrafcetTransition(step.id, {number++, {n}, {n + 1}, receptivity(n)});
        model.addGrafcetTransition(step.id, {number++, {steps}, {1}, receptivity(steps)});
        for (int extra = pick(4); extra > 0; --extra) {
            std::vector<int> upstream{1 + pick(steps)};
            std::vector<int> downstream{1 + pick(steps)};
            if (pick(2) == 0 && upstream[0] != steps)
                upstream.push_back(steps);
            if (pick(2) == 0 && downstream[0] != 1)
                downstream.push_back(1);
            model.addGrafcetTransition(step.id, {number++, upstream, downstream, receptivity(upstream[0])});
        }
    }
    if (pick(2) == 0)
        model.setEvolutionRule(core::EvolutionRule::UntilStable);
}

} // namespace samples

namespace samples {

namespace {

class ValidNestedBuilder {
public:
    ValidNestedBuilder(core::Model& model, std::mt19937& random) : m_model(model), m_random(random) {}

    // Random GRAFCETs at these keys (PackML: grafcetKey(mode, state), each
    // an Own choice with an empty GRAFCET).
    void buildAt(const std::vector<std::string>& keys)
    {
        declareVariables();
        for (const std::string& key : keys)
            buildGrafcet(key);
    }

    int build()
    {
        declareVariables();
        int added = 0;
        for (const core::Step& step : std::vector<core::Step>(m_model.steps())) {
            if (step.hidden || step.type == core::StepType::Simple || pick(4) == 0)
                continue;
            buildGrafcet(step.id);
            ++added;
        }
        return added;
    }

private:
    int pick(int count) { return static_cast<int>(m_random() % static_cast<unsigned>(count)); }
    bool chance(int in) { return pick(in) == 0; } // probability 1/in
    template <typename T> const T& any(const std::vector<T>& values)
    {
        return values[static_cast<std::size_t>(pick(static_cast<int>(values.size())))];
    }

    void declareVariables()
    {
        for (const char* name : {"NestedIn0", "NestedIn1", "NestedIn2"}) {
            requireBuilt(m_model.addVariable(core::Variable{name, core::IecType::Bool, "", "input of the nested GRAFCETs"}));
            m_inputs.push_back(name);
        }
        for (const core::Variable& variable : m_model.variables()) {
            if (variable.kind != core::VariableKind::Input || variable.name.rfind("NestedIn", 0) == 0)
                continue;
            if (variable.type == core::IecType::Bool)
                m_gemmaInputs.push_back(variable.name);
            else if (core::isIntegerType(variable.type))
                m_numbers.push_back(variable.name);
            else if (core::isRealType(variable.type))
                m_reals.push_back(variable.name);
        }
        for (int i = 0; i < 4; ++i) {
            core::Variable output{"NestedOut" + std::to_string(i), core::IecType::Bool, "", "continuous actions"};
            output.kind = core::VariableKind::Output;
            requireBuilt(m_model.addVariable(output));
            m_continuous.push_back(output.name);
        }
        for (int i = 0; i < 2; ++i) {
            core::Variable memory{"NestedMem" + std::to_string(i), core::IecType::Bool, i == 0 ? "" : "TRUE",
                                  "stored actions"};
            memory.kind = i == 0 ? core::VariableKind::Output : core::VariableKind::Internal;
            requireBuilt(m_model.addVariable(memory));
            m_stored.push_back(memory.name);
        }
        core::Variable counter{"NestedCount", core::IecType::Int, "", "counted by nested GRAFCETs"};
        counter.kind = core::VariableKind::Internal;
        requireBuilt(m_model.addVariable(counter));
    }

    // Mostly the nested GRAFCETs' own inputs, sometimes one the GEMMA layer reads.
    std::string input() { return m_gemmaInputs.empty() || !chance(4) ? any(m_inputs) : any(m_gemmaInputs); }
    std::string activity() { return "X" + std::to_string(any(m_numbersSoFar)); }

    std::string receptivity(int from)
    {
        switch (pick(14)) {
        case 0:
        case 12: return input();
        case 13:
            switch (pick(4)) {
            case 0: return "TRUE";
            case 1: return input() + " OR " + input();
            case 2: return (chance(2) ? "RE " : "FE ") + any(m_stored);     // written by stored actions in the call
            default: return (chance(2) ? "RE " : "FE ") + any(m_continuous); // maybe the FB's own VAR_OUTPUT
            }
        case 1: return "NOT " + input();
        case 2: return "RE " + input();
        case 3: return "FE " + input() + (chance(2) ? " OR " + input() : "");
        case 4: return std::to_string(any(std::vector<int>{1, 5, 10, 20, 40, 100, 250, 1500})) + "ms/X" + std::to_string(from);
        case 5: return input() + " AND " + activity();
        case 6:
            if (!m_reals.empty() && chance(4))
                return any(m_reals) + (chance(2) ? " > " : " <= ") + std::to_string(pick(5)) + ".5";
            if (!m_numbers.empty() && chance(2))
                return any(m_numbers) + (chance(2) ? " > " : " <= ") + std::to_string(pick(101));
            return input() + " OR " + input();
        case 7: return "TRUE";
        case 8: // the FB's VAR_OUTPUT, or a global
            return chance(2) ? any(m_continuous) + " OR " + input() : "NOT " + any(m_continuous);
        case 9: return chance(2) ? any(m_stored) : "NestedCount >= " + std::to_string(pick(4));
        case 10: return chance(2) ? "Complete" : "NOT Complete AND " + input();
        default: return "(" + input() + " OR RE " + input() + ") AND NOT " + activity();
        }
    }

    // No continuous output of the FB in an action's condition (GG421).
    std::string actionCondition()
    {
        switch (pick(4)) {
        case 0: return input();
        case 1: return "NOT " + input();
        case 2: return activity() + " AND " + any(m_stored);
        default: return "NestedCount > " + std::to_string(pick(3));
        }
    }

    core::GrafcetAction storedAction(core::ActionTiming timing)
    {
        switch (pick(5)) {
        case 0: return {timing, "S " + any(m_stored)};
        case 1: return {timing, "R " + any(m_stored)};
        case 2: return {timing, "NestedCount := NestedCount + " + std::to_string(1 + pick(2))};
        case 3: return {timing, any(m_stored) + " := " + input() + (chance(2) ? " AND " + activity() : "")};
        default: return {timing, "NestedCount := 0"};
        }
    }

    std::vector<core::GrafcetAction> actions(bool exit)
    {
        std::vector<core::GrafcetAction> list;
        for (int a = pick(4); a > 0; --a) {
            switch (pick(5)) {
            case 0: list.push_back({core::ActionTiming::Continuous, (chance(2) ? "N " : "") + any(m_continuous)}); break;
            case 1: list.push_back({core::ActionTiming::Continuous, any(m_continuous) + " IF " + actionCondition()}); break;
            case 2: list.push_back(storedAction(core::ActionTiming::OnActivation)); break;
            case 3: list.push_back(storedAction(core::ActionTiming::OnDeactivation)); break;
            default: list.push_back(completeAction(chance(3))); break;
            }
        }
        if (exit)
            list.push_back(completeAction(true));
        return list;
    }

    // Complete, in the GRAFCET's one style (GG415 refuses mixing them).
    core::GrafcetAction completeAction(bool set)
    {
        switch (m_completeStyle) {
        case 0: return {core::ActionTiming::Continuous, set ? "Complete" : "Complete IF " + actionCondition()};
        case 1: return {core::ActionTiming::OnActivation, set ? "S Complete" : "R Complete"};
        default: return {core::ActionTiming::OnActivation, set ? "Complete := TRUE" : "Complete := " + input()};
        }
    }

    int newStep()
    {
        m_next += chance(4) ? 1 + pick(3) : 1;
        m_numbersSoFar.push_back(m_next);
        m_steps.push_back({m_next, false, "", actions(false)});
        return m_next;
    }

    void transition(std::vector<int> upstream, std::vector<int> downstream, std::string text)
    {
        m_transitions.push_back({m_transitionNumber++, std::move(upstream), std::move(downstream), std::move(text)});
    }

    // A piece of sequence from step `from`; returns the step it ends on.
    int block(int from, int depth)
    {
        switch (depth > 1 ? 0 : pick(5)) {
        case 1: { // selection divergence and convergence
            const int a = newStep();
            const int b = newStep();
            const std::string r = receptivity(from);
            transition({from}, {a}, r);
            transition({from}, {b}, chance(4) ? receptivity(from) : "NOT (" + r + ")");
            const int aEnd = chance(2) ? block(a, depth + 1) : a;
            const int bEnd = chance(2) ? block(b, depth + 1) : b;
            const int join = newStep();
            transition({aEnd}, {join}, receptivity(aEnd));
            transition({bEnd}, {join}, receptivity(bEnd));
            return join;
        }
        case 2: { // simultaneous divergence and convergence
            const int a = newStep();
            const int b = newStep();
            std::vector<int> branches{a, b};
            if (chance(3))
                branches.push_back(newStep());
            transition({from}, branches, receptivity(from));
            std::vector<int> ends;
            for (int branch : branches)
                ends.push_back(chance(2) ? block(branch, depth + 1) : branch);
            const int join = newStep();
            transition(ends, {join}, chance(2) ? "TRUE" : receptivity(ends.front()));
            return join;
        }
        case 3: { // a loop back to `from`
            const int body = newStep();
            transition({from}, {body}, receptivity(from));
            const int after = newStep();
            const std::string r = receptivity(body);
            transition({body}, {from}, r);
            transition({body}, {after}, chance(4) ? receptivity(body) : "NOT (" + r + ")");
            return after;
        }
        default: { // sequence
            const int next = newStep();
            transition({from}, {next}, receptivity(from));
            return next;
        }
        }
    }

    void buildGrafcet(const std::string& stepId)
    {
        m_steps.clear();
        m_transitions.clear();
        m_numbersSoFar.clear();
        m_next = pick(3);
        m_transitionNumber = 1 + pick(2);
        m_completeStyle = pick(3);
        const int initial = newStep();
        m_steps.back().initial = true;
        if (m_completeStyle == 1 && chance(2))
            m_steps.back().actions.push_back(completeAction(false));
        int at = initial;
        for (int blocks = 1 + pick(3); blocks > 0; --blocks)
            at = block(at, 0);
        if (chance(4)) // an exit step with no way out: it sets Complete (no GG418)
            m_steps[m_steps.size() - 1].actions.push_back(completeAction(true));
        else {
            for (core::GrafcetStep& step : m_steps) {
                if (step.number == at)
                    step.actions.push_back(completeAction(true));
            }
            transition({at}, {initial}, receptivity(at));
        }
        if (chance(4)) { // a second initial step with its own loop
            const int other = newStep();
            m_steps.back().initial = true;
            const int second = newStep();
            transition({other}, {second}, receptivity(other));
            transition({second}, {other}, receptivity(second));
        }
        if (chance(4)) { // anything: a jump, a non-exclusive selection, a convergence never enabled
            std::vector<int> upstream{any(m_numbersSoFar)};
            std::vector<int> downstream{any(m_numbersSoFar)};
            if (chance(3) && upstream[0] != m_numbersSoFar.back())
                upstream.push_back(m_numbersSoFar.back());
            if (chance(3) && downstream[0] != initial)
                downstream.push_back(initial);
            transition(upstream, downstream, receptivity(upstream[0]));
        }
        for (const core::GrafcetStep& step : m_steps)
            requireBuilt(m_model.addGrafcetStep(stepId, step));
        for (const core::GrafcetTransition& t : m_transitions)
            requireBuilt(m_model.addGrafcetTransition(stepId, t));
    }

    core::Model& m_model;
    std::mt19937& m_random;
    std::vector<std::string> m_inputs;      // NestedIn0-2
    std::vector<std::string> m_gemmaInputs; // the model's other BOOL inputs
    std::vector<std::string> m_numbers; // integer inputs
    std::vector<std::string> m_reals;   // REAL and LREAL inputs
    std::vector<std::string> m_continuous;
    std::vector<std::string> m_stored;
    std::vector<core::GrafcetStep> m_steps;
    std::vector<core::GrafcetTransition> m_transitions;
    std::vector<int> m_numbersSoFar;
    int m_next = 0;
    int m_transitionNumber = 1;
    int m_completeStyle = 0;
};

} // namespace

void addRandomGrafcetsAt(core::Model& model, std::mt19937& random, const std::vector<std::string>& keys)
{
    ValidNestedBuilder(model, random).buildAt(keys);
}

int addValidRandomNestedGrafcets(core::Model& model, std::mt19937& random)
{
    for (int attempt = 0; attempt < 20; ++attempt) {
        core::Model candidate(model);
        const int added = ValidNestedBuilder(candidate, random).build();
        if (!core::hasErrors(core::checkModel(candidate))) {
            model.assign(candidate);
            return added;
        }
    }
    return 0;
}

core::Model lampGrafcetModel()
{
    using core::ActionTiming;
    core::Model model;
    for (const core::Variable& v : {variable("Start", core::IecType::Bool, core::VariableKind::Input),
                                    variable("Lamp", core::IecType::Bool, core::VariableKind::Output),
                                    variable("Count", core::IecType::Int, core::VariableKind::Internal)})
        requireBuilt(model.addVariable(v));
    requireBuilt(model.addGrafcetStep("F1", {1, true, "", {}}));
    requireBuilt(model.addGrafcetStep("F1", {2, false, "", {{ActionTiming::Continuous, "N Lamp"},
                                                       {ActionTiming::OnActivation, "Count := Count + 1"}}}));
    requireBuilt(model.addGrafcetStep("F1", {3, false, "", {{ActionTiming::OnActivation, "S Complete"}}}));
    requireBuilt(model.addGrafcetTransition("F1", {1, {1}, {2}, "RE Start"}));
    requireBuilt(model.addGrafcetTransition("F1", {2, {2}, {3}, "5s/X2"}));
    return model;
}

} // namespace samples
