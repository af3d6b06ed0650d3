#include "core/simulation/simulator.h"

#include "core/simulation/decidingoperands.h"
#include "core/simulation/nestedengine.h"

#include "core/condition/conditionanalysis.h"
#include "core/model/model.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <unordered_map>

namespace core {

namespace {

enum class Kind : std::uint8_t { Bool, Integer, Real };

// A value whose kind the compiler knows statically: BOOL and integers in i
// (BOOL as 0/1), reals in r.
union Cell {
    std::int64_t i;
    double r;
};

Kind kindOf(IecType type)
{
    if (type == IecType::Bool)
        return Kind::Bool;
    return isRealType(type) ? Kind::Real : Kind::Integer;
}

Kind kindOf(const cond::Value& value)
{
    if (std::holds_alternative<bool>(value))
        return Kind::Bool;
    return std::holds_alternative<double>(value) ? Kind::Real : Kind::Integer;
}

Cell toCell(const cond::Value& value)
{
    Cell cell;
    if (const bool* b = std::get_if<bool>(&value))
        cell.i = *b ? 1 : 0;
    else if (const std::int64_t* i = std::get_if<std::int64_t>(&value))
        cell.i = *i;
    else
        cell.r = std::get<double>(value);
    return cell;
}

cond::Value toValue(Cell cell, Kind kind)
{
    switch (kind) {
    case Kind::Bool: return cell.i != 0;
    case Kind::Integer: return cell.i;
    case Kind::Real: return cell.r;
    }
    return false;
}

bool sameCell(Cell a, Cell b, Kind kind)
{
    return kind == Kind::Real ? a.r == b.r : a.i == b.i;
}

// The postfix instruction set. Kinds are resolved at compile time, so every
// instruction works on one representation; mixed integer/real operands get
// an explicit conversion, as cond::evaluate converts them.
enum class Op : std::uint8_t {
    PushVariable, PushToken, PushConstant, IntToReal,
    Not, And, Or, Xor,
    NegateInt, NegateReal,
    AddInt, SubInt, MulInt, DivInt, ModInt,
    AddReal, SubReal, MulReal, DivReal, ModReal,
    EqInt, NeInt, LtInt, GtInt, LeInt, GeInt,
    EqReal, NeReal, LtReal, GtReal, LeReal, GeReal,
};

struct Instruction {
    Op op = Op::PushConstant;
    int slot = 0; // variable slot or token index; DivInt, ModInt: the node, to name a division by zero
    Cell constant{};
};

// A condition compiled once. `fallback`: the expression did not have the
// shape the compiler expects (it passed typeCheck, so this should not
// happen); it is then evaluated by cond::evaluate, slower but the same.
struct CompiledCondition {
    std::vector<Instruction> code;
    int depth = 0;
    bool fallback = false;
    bool alwaysFalse = false; // unusable condition
};

struct CompiledTransition {
    const GemmaTransition* source = nullptr;
    int targetNumber = 0;
    bool waitsForComplete = false;
    CompiledCondition condition;
    // For explain() and the fallback: each Variable-like node's reading
    // (variable slot, or token index when a literal is substituted).
    cond::Expression readable;          // condition with token literals turned into Variable nodes
    std::vector<int> nodeVariable;      // node -> variable slot, -1
    std::vector<int> nodeToken;         // node -> token index, -1
};

struct CompiledToken {
    int variableSlot = -1;
    bool normallyClosed = false;
};

struct CompiledStep {
    const GemmaStep* source = nullptr;
    int nestedIndex = -1; // index into the Complete arrays; -1 for a simple step
    int firstToken = 0;
    int tokenCount = 0;
    std::vector<CompiledTransition> transitions;
};

} // namespace

std::string_view transitionStatusName(TransitionStatus status)
{
    switch (status) {
    case TransitionStatus::Fires: return "fires";
    case TransitionStatus::ConditionFalse: return "condition false";
    case TransitionStatus::WaitingForComplete: return "waiting for Complete";
    case TransitionStatus::PreemptedByHigherPriority: return "preempted by higher priority";
    case TransitionStatus::Unusable: return "unusable condition";
    }
    return "";
}

namespace {

// The program compiled from a model: built once, never changed, so copies
// of a simulator share it (a copy costs only the run-time state).
struct CompiledProgram {
    explicit CompiledProgram(const Model& model);

    GemmaProgram program;
    int initialNumber = 0;
    int cycleTimeMs = 0;

    // Variables.
    std::vector<std::string> variableNames;
    std::vector<IecType> variableTypes;
    std::vector<VariableKind> variableRoles; // input, output, internal
    std::vector<Kind> variableKinds;
    std::vector<Cell> defaults;
    std::unordered_map<std::string, int> variableByUpperName;

    // Steps and transitions; `source` pointers point into `program`.
    std::vector<CompiledStep> steps;
    std::vector<int> stepByNumber; // State value -> index in steps, -1
    std::vector<std::string> tokenNames;
    std::vector<CompiledToken> tokens;
    std::vector<std::string> nestedSteps;
    std::vector<int> nestedStepIndex; // nested index -> index in steps
    int stackDepth = 1;               // the deepest condition's evaluation stack
    // Spec §4.3: each continuous output of the nested GRAFCETs, written after
    // END_CASE from the FBs that drive it.
    struct OutputDriver {
        int stateNumber = 0;
        int nestedIndex = 0;
        std::size_t output = 0; // in that engine's outputNames()
    };
    struct OutputWrite {
        int slot = -1;
        std::vector<OutputDriver> drivers;
    };
    std::vector<OutputWrite> outputWrites;
    std::vector<int> edgeSlots; // variables with a <V>_PREV memory
    std::vector<int> outputSlots; // VariableKind::Output variables, declaration order

    int slotOf(std::string_view name) const
    {
        const auto found = variableByUpperName.find(toUpperAscii(name));
        return found == variableByUpperName.end() ? -1 : found->second;
    }

private:
    void compileVariables(const Model& model);
    void compileProgram();
    void compileNestedOutputs();
    void compileTransition(const GemmaTransition& transition, CompiledTransition& out);
    bool compileNode(const CompiledTransition& transition, const cond::Expression& expression,
                     const std::vector<char>& constant, int node, CompiledCondition& out, Kind& kind, int& depth);
};

} // namespace

struct Simulator::Impl {
    explicit Impl(const Model& model);

    std::shared_ptr<const CompiledProgram> compiled;
    // Shorthands into *compiled; a copied Impl's refer to the same program.
    const GemmaProgram& program = compiled->program;
    const int& initialNumber = compiled->initialNumber;
    const int& cycleTimeMs = compiled->cycleTimeMs;
    const std::vector<std::string>& variableNames = compiled->variableNames;
    const std::vector<IecType>& variableTypes = compiled->variableTypes;
    const std::vector<Kind>& variableKinds = compiled->variableKinds;
    const std::vector<Cell>& defaults = compiled->defaults;
    const std::unordered_map<std::string, int>& variableByUpperName = compiled->variableByUpperName;
    const std::vector<CompiledStep>& steps = compiled->steps;
    const std::vector<int>& stepByNumber = compiled->stepByNumber;
    const std::vector<std::string>& tokenNames = compiled->tokenNames;
    const std::vector<CompiledToken>& tokens = compiled->tokens;
    const std::vector<std::string>& nestedSteps = compiled->nestedSteps;
    const std::vector<int>& nestedStepIndex = compiled->nestedStepIndex;

    // Variables.
    std::vector<Cell> values;
    std::vector<Cell> valuesAtLastScan;
    std::vector<int> dirty;          // slots set since the last scan
    std::vector<char> isDirty;

    // State.
    int state = 0;
    int active = -1;
    bool entry = true;
    std::vector<char> tokenValues;
    std::vector<CompleteMode> completeModes;
    std::vector<char> manualComplete;
    std::vector<char> completeOutput;
    std::int64_t scanCount = 0;
    const GemmaTransition* lastFired = nullptr;
    int calledNested = -1; // the nested index whose FB the last scan called, -1 for none

    // Nested GRAFCETs, by nested index (empty for a skeleton FB), and the
    // edge memories by slot.
    std::vector<std::optional<NestedEngine>> engines;
    std::vector<char> previous;

    // Evaluation scratch.
    mutable std::vector<Cell> stack;
    // The node of the first integer division or MOD by zero of the last
    // evaluate(), -1 for none.
    mutable int divisionByZero = -1;
    // Set by the scan that divided integers by zero: no scan runs after it.
    std::optional<SimulationFault> fault;

    bool traceEnabled = false;
    std::vector<ScanRecord> trace;
    std::function<void(const ScanRecord&)> callback;

    void reset();
    void callFunctionBlock(const CompiledStep& step, bool initialization);
    void writeContinuousOutputs();
    void updateEdgeMemories();
    // What a condition reads: the tokens and the variables. A scan reads its
    // own; explain() those it predicts for the next scan (the entry block's
    // reset tokens, what a nested GRAFCET's stored actions write first).
    struct ConditionInputs {
        const std::vector<char>& tokens;
        const std::vector<Cell>& values;
    };
    bool evaluate(const CompiledTransition& transition, const ConditionInputs& inputs) const;
    cond::Value nodeReading(const CompiledTransition& transition, int node, const ConditionInputs& inputs) const;
    bool fbComplete(int nestedIndex) const;
    bool predictNestedCall(const CompiledStep& step, std::vector<Cell>& scratch) const;
    int activeIndexFor(int number) const;
    void scan(ScanRecord* record);
    bool nestedFaulted(const CompiledStep& step);
    void transitionFaulted(const CompiledStep& step, const CompiledTransition& transition);
    void fillRecordAfter(ScanRecord& record, const std::vector<Cell>& outputsBefore) const;
    void collectChanges(ScanRecord* record);
    int stepIndexOfNested(std::string_view stepId) const;
    std::vector<ExplanationReason> explainFalse(const CompiledTransition& transition,
                                                const ConditionInputs& inputs) const;
    void explainNode(const CompiledTransition& transition, const ConditionInputs& inputs, int node,
                     std::vector<ExplanationReason>& reasons) const;
    // A node that is no NOT, AND, OR or XOR.
    void explainLeaf(const CompiledTransition& transition, const ConditionInputs& inputs, int node,
                     std::vector<ExplanationReason>& reasons) const;
    ConditionReading reading(const CompiledTransition& transition, int node, const ConditionInputs& inputs) const;
};

CompiledProgram::CompiledProgram(const Model& model)
    : program(buildGemmaProgram(model))
    , initialNumber(program.initialNumber)
    , cycleTimeMs(model.settings().cycleTimeMs)
{
    compileVariables(model);
    compileProgram();
}

Simulator::Impl::Impl(const Model& model)
    : compiled(std::make_shared<const CompiledProgram>(model))
    , isDirty(variableNames.size(), 0)
    , completeModes(nestedSteps.size(), CompleteMode::Automatic)
    , manualComplete(nestedSteps.size(), 0)
    , stack(static_cast<std::size_t>(compiled->stackDepth) + 1)
{
    // The engines refer to the shared, immutable program: copies of this Impl share it too.
    const CompiledProgram* shared = compiled.get();
    const std::function<int(std::string_view)> slotOf = [shared](std::string_view name) { return shared->slotOf(name); };
    const std::function<IecType(int)> typeOf = [shared](int slot) {
        return shared->variableTypes[static_cast<std::size_t>(slot)];
    };
    for (int stepIndex : nestedStepIndex) {
        const GemmaStep& step = *steps[static_cast<std::size_t>(stepIndex)].source;
        engines.emplace_back();
        if (step.nested)
            engines.back().emplace(*step.nested, slotOf, typeOf);
    }
    reset();
}

// The globals as a nested GRAFCET's FB reads and writes them.
class SimulatorGlobals final : public NestedGlobals {
public:
    SimulatorGlobals(std::vector<Cell>& values, const std::vector<Kind>& kinds, const std::vector<char>& previous)
        : m_values(values)
        , m_kinds(kinds)
        , m_previous(previous)
    {
    }
    cond::Value read(int slot) const override
    {
        return toValue(m_values[static_cast<std::size_t>(slot)], m_kinds[static_cast<std::size_t>(slot)]);
    }
    void write(int slot, const cond::Value& value) override
    {
        Cell cell = toCell(value);
        if (m_kinds[static_cast<std::size_t>(slot)] == Kind::Real && !std::holds_alternative<double>(value))
            cell.r = static_cast<double>(cell.i);
        m_values[static_cast<std::size_t>(slot)] = cell;
    }
    bool previous(int slot) const override { return m_previous[static_cast<std::size_t>(slot)] != 0; }

private:
    std::vector<Cell>& m_values;
    const std::vector<Kind>& m_kinds;
    const std::vector<char>& m_previous;
};

// S(Initialization := ...): the nested GRAFCET, or the skeleton's Complete.
void Simulator::Impl::callFunctionBlock(const CompiledStep& step, bool initialization)
{
    const auto nested = static_cast<std::size_t>(step.nestedIndex);
    if (std::optional<NestedEngine>& engine = engines[nested]) {
        SimulatorGlobals globals(values, variableKinds, previous);
        engine->call(initialization, scanCount * cycleTimeMs, globals);
        completeOutput[nested] = engine->complete();
        return;
    }
    completeOutput[nested] = fbComplete(step.nestedIndex);
}

void Simulator::Impl::writeContinuousOutputs()
{
    for (const CompiledProgram::OutputWrite& write : compiled->outputWrites) {
        bool value = false;
        for (const CompiledProgram::OutputDriver& driver : write.drivers)
            value = value || (state == driver.stateNumber && !entry
                              && engines[static_cast<std::size_t>(driver.nestedIndex)]->output(driver.output));
        values[static_cast<std::size_t>(write.slot)].i = value ? 1 : 0;
    }
}

void Simulator::Impl::updateEdgeMemories()
{
    for (int slot : compiled->edgeSlots)
        previous[static_cast<std::size_t>(slot)] = values[static_cast<std::size_t>(slot)].i != 0;
}

void CompiledProgram::compileVariables(const Model& model)
{
    for (const Variable& variable : model.variables()) {
        const int slot = static_cast<int>(variableNames.size());
        variableNames.push_back(variable.name);
        variableTypes.push_back(variable.type);
        variableRoles.push_back(variable.kind);
        variableKinds.push_back(kindOf(variable.type));
        // A default that does not fit: the implicit default, as the generated code declares it.
        std::optional<cond::Value> value = cond::parseValue(variable.type, variable.defaultValue);
        if (!value)
            value = cond::parseValue(variable.type, "");
        defaults.push_back(value ? toCell(*value) : Cell{});
        variableByUpperName.emplace(toUpperAscii(variable.name), slot);
        if (variable.kind == VariableKind::Output)
            outputSlots.push_back(slot);
    }
}

void CompiledProgram::compileNestedOutputs()
{
    for (std::size_t n = 0; n < nestedSteps.size(); ++n) {
        const GemmaStep& step = program.steps[static_cast<std::size_t>(nestedStepIndex[n])];
        if (!step.nested)
            continue;
        std::size_t outputIndex = 0;
        for (const ContinuousOutput& output : step.nested->outputs) {
            if (output.isComplete)
                continue;
            const int slot = slotOf(output.variable);
            auto found = std::find_if(outputWrites.begin(), outputWrites.end(),
                                      [slot](const OutputWrite& w) { return w.slot == slot; });
            if (found == outputWrites.end()) {
                outputWrites.push_back({slot, {}});
                found = outputWrites.end() - 1;
            }
            found->drivers.push_back({step.number, static_cast<int>(n), outputIndex++});
        }
    }
    for (const std::string& name : program.edgeVariables)
        edgeSlots.push_back(slotOf(name));
}

void CompiledProgram::compileProgram()
{
    int maxNumber = program.initialNumber;
    for (const GemmaStep& step : program.steps)
        maxNumber = std::max(maxNumber, step.number);
    stepByNumber.assign(static_cast<std::size_t>(std::max(maxNumber, 0)) + 1, -1);

    // Token indices first: a transition's condition reads them.
    steps.resize(program.steps.size());
    for (std::size_t i = 0; i < program.steps.size(); ++i) {
        const GemmaStep& step = program.steps[i];
        CompiledStep& compiled = steps[i];
        compiled.source = &step;
        if (step.number >= 0)
            stepByNumber[static_cast<std::size_t>(step.number)] = static_cast<int>(i);
        if (step.hasNestedBehaviour()) {
            compiled.nestedIndex = static_cast<int>(nestedSteps.size());
            nestedSteps.push_back(step.id);
            nestedStepIndex.push_back(static_cast<int>(i));
        }
        compiled.firstToken = static_cast<int>(tokens.size());
        compiled.tokenCount = static_cast<int>(step.tokens.size());
        for (const GemmaToken& token : step.tokens) {
            tokenNames.push_back(token.name);
            auto found = variableByUpperName.find(toUpperAscii(token.variable));
            tokens.push_back(CompiledToken{found == variableByUpperName.end() ? -1 : found->second,
                                           token.polarity == TokenPolarity::NormallyClosed});
        }
    }
    compileNestedOutputs();
    for (std::size_t i = 0; i < program.steps.size(); ++i) {
        for (const GemmaTransition& transition : program.steps[i].transitions) {
            steps[i].transitions.emplace_back();
            compileTransition(transition, steps[i].transitions.back());
        }
    }
    for (const CompiledStep& step : steps) {
        for (const CompiledTransition& transition : step.transitions)
            stackDepth = std::max(stackDepth, transition.condition.depth);
    }
}

void CompiledProgram::compileTransition(const GemmaTransition& transition, CompiledTransition& out)
{
    out.source = &transition;
    out.targetNumber = transition.targetNumber;
    out.waitsForComplete = transition.waitsForComplete;
    if (!transition.conditionUsable) {
        out.condition.alwaysFalse = true;
        return;
    }
    // The readable form: every token literal becomes a Variable node named
    // after the token, so evaluating any subtree reads the token there.
    out.readable = transition.condition.expression;
    const std::size_t size = out.readable.nodes.size();
    out.nodeVariable.assign(size, -1);
    out.nodeToken.assign(size, -1);
    for (const auto& [node, tokenName] : transition.substitutions) {
        if (node < 0 || static_cast<std::size_t>(node) >= size)
            continue;
        auto it = std::find(tokenNames.begin(), tokenNames.end(), tokenName);
        if (it == tokenNames.end())
            continue;
        cond::Node& replaced = out.readable.nodes[static_cast<std::size_t>(node)];
        replaced.kind = cond::NodeKind::Variable;
        replaced.text = tokenName;
        out.nodeToken[static_cast<std::size_t>(node)] = static_cast<int>(it - tokenNames.begin());
    }
    // Which nodes are constant (no variable or token below them).
    std::vector<char> constant(size, 1);
    for (std::size_t n = 0; n < size; ++n) {
        cond::Node& node = out.readable.nodes[n];
        if (node.kind == cond::NodeKind::Variable) {
            constant[n] = 0;
            if (out.nodeToken[n] < 0) {
                auto found = variableByUpperName.find(toUpperAscii(node.text));
                out.nodeVariable[n] = found == variableByUpperName.end() ? -1 : found->second;
            }
        } else if (node.kind == cond::NodeKind::Unary) {
            constant[n] = node.operand >= 0 && node.operand < static_cast<int>(n) ? constant[static_cast<std::size_t>(node.operand)] : 0;
        } else if (node.kind == cond::NodeKind::Binary) {
            const bool ok = node.left >= 0 && node.right >= 0 && node.left < static_cast<int>(n) && node.right < static_cast<int>(n);
            constant[n] = ok && constant[static_cast<std::size_t>(node.left)] && constant[static_cast<std::size_t>(node.right)];
        }
    }
    Kind kind = Kind::Bool;
    int depth = 0;
    const bool compiled = !out.readable.empty()
        && compileNode(out, out.readable, constant, out.readable.root, out.condition, kind, depth);
    out.condition.depth = depth;
    if (!compiled || kind != Kind::Bool) {
        out.condition.code.clear();
        out.condition.fallback = true;
        out.condition.depth = 0;
    }
}

// Emits postfix code for the subtree at `node`; false when its shape is not
// one the instruction set covers. `depth` receives the stack depth it needs.
bool CompiledProgram::compileNode(const CompiledTransition& transition, const cond::Expression& expression,
                                  const std::vector<char>& constant, int node, CompiledCondition& out, Kind& kind,
                                  int& depth)
{
    const cond::Node& n = expression.at(node);
    const auto index = static_cast<std::size_t>(node);
    if (constant[index]) {
        cond::Expression sub = expression;
        sub.root = node;
        const cond::Value value = cond::evaluate(sub, {});
        kind = kindOf(value);
        out.code.push_back(Instruction{Op::PushConstant, 0, toCell(value)});
        depth = 1;
        return true;
    }
    if (n.kind == cond::NodeKind::Variable) {
        if (transition.nodeToken[index] >= 0) {
            out.code.push_back(Instruction{Op::PushToken, transition.nodeToken[index], {}});
            kind = Kind::Bool;
        } else {
            const int slot = transition.nodeVariable[index];
            if (slot < 0)
                return false;
            out.code.push_back(Instruction{Op::PushVariable, slot, {}});
            kind = variableKinds[static_cast<std::size_t>(slot)];
        }
        depth = 1;
        return true;
    }
    if (n.kind == cond::NodeKind::Unary) {
        Kind operandKind;
        if (!compileNode(transition, expression, constant, n.operand, out, operandKind, depth))
            return false;
        if (n.unaryOp == cond::UnaryOp::Not) {
            if (operandKind != Kind::Bool)
                return false;
            out.code.push_back(Instruction{Op::Not, 0, {}});
            kind = Kind::Bool;
            return true;
        }
        if (operandKind == Kind::Bool)
            return false;
        out.code.push_back(Instruction{operandKind == Kind::Real ? Op::NegateReal : Op::NegateInt, 0, {}});
        kind = operandKind;
        return true;
    }
    if (n.kind != cond::NodeKind::Binary)
        return false;

    // Both operands first, converting an integer beside a real right after it is pushed.
    CompiledCondition left;
    CompiledCondition right;
    Kind leftKind;
    Kind rightKind;
    int leftDepth = 0;
    int rightDepth = 0;
    if (!compileNode(transition, expression, constant, n.left, left, leftKind, leftDepth)
        || !compileNode(transition, expression, constant, n.right, right, rightKind, rightDepth))
        return false;
    const cond::BinaryOp op = n.binaryOp;
    const bool logical = op == cond::BinaryOp::And || op == cond::BinaryOp::Or || op == cond::BinaryOp::Xor;
    const bool comparison = op == cond::BinaryOp::Equal || op == cond::BinaryOp::NotEqual || op == cond::BinaryOp::Less
        || op == cond::BinaryOp::Greater || op == cond::BinaryOp::LessEqual || op == cond::BinaryOp::GreaterEqual;
    const bool bothBool = leftKind == Kind::Bool && rightKind == Kind::Bool;
    const bool bothNumbers = leftKind != Kind::Bool && rightKind != Kind::Bool;
    if (logical && !bothBool)
        return false;
    if (!logical && !bothNumbers && !(comparison && bothBool))
        return false;
    const bool real = bothNumbers && (leftKind == Kind::Real || rightKind == Kind::Real);
    out.code.insert(out.code.end(), left.code.begin(), left.code.end());
    if (real && leftKind == Kind::Integer)
        out.code.push_back(Instruction{Op::IntToReal, 0, {}});
    out.code.insert(out.code.end(), right.code.begin(), right.code.end());
    if (real && rightKind == Kind::Integer)
        out.code.push_back(Instruction{Op::IntToReal, 0, {}});
    depth = std::max(leftDepth, rightDepth + 1);

    Op code = Op::And;
    switch (op) {
    case cond::BinaryOp::And: code = Op::And; break;
    case cond::BinaryOp::Or: code = Op::Or; break;
    case cond::BinaryOp::Xor: code = Op::Xor; break;
    case cond::BinaryOp::Add: code = real ? Op::AddReal : Op::AddInt; break;
    case cond::BinaryOp::Subtract: code = real ? Op::SubReal : Op::SubInt; break;
    case cond::BinaryOp::Multiply: code = real ? Op::MulReal : Op::MulInt; break;
    case cond::BinaryOp::Divide: code = real ? Op::DivReal : Op::DivInt; break;
    case cond::BinaryOp::Modulo: code = real ? Op::ModReal : Op::ModInt; break;
    // BOOL operands compare as 0/1 integers: the same order as bool.
    case cond::BinaryOp::Equal: code = real ? Op::EqReal : Op::EqInt; break;
    case cond::BinaryOp::NotEqual: code = real ? Op::NeReal : Op::NeInt; break;
    case cond::BinaryOp::Less: code = real ? Op::LtReal : Op::LtInt; break;
    case cond::BinaryOp::Greater: code = real ? Op::GtReal : Op::GtInt; break;
    case cond::BinaryOp::LessEqual: code = real ? Op::LeReal : Op::LeInt; break;
    case cond::BinaryOp::GreaterEqual: code = real ? Op::GeReal : Op::GeInt; break;
    case cond::BinaryOp::Implies: return false; // properties only: never in a program's condition
    }
    out.code.push_back(Instruction{code, (code == Op::DivInt || code == Op::ModInt) ? node : 0, {}});
    kind = (logical || comparison) ? Kind::Bool : (real ? Kind::Real : Kind::Integer);
    return true;
}

namespace {

constexpr std::int64_t kInt64Min = std::numeric_limits<std::int64_t>::min();

// Integer semantics of cond::evaluate: wrap-around; a division or MOD by
// zero gives 0 and is reported (the scan then stops the run).
std::int64_t wrapAdd(std::int64_t a, std::int64_t b)
{
    return static_cast<std::int64_t>(static_cast<std::uint64_t>(a) + static_cast<std::uint64_t>(b));
}
std::int64_t wrapSub(std::int64_t a, std::int64_t b)
{
    return static_cast<std::int64_t>(static_cast<std::uint64_t>(a) - static_cast<std::uint64_t>(b));
}
std::int64_t wrapMul(std::int64_t a, std::int64_t b)
{
    return static_cast<std::int64_t>(static_cast<std::uint64_t>(a) * static_cast<std::uint64_t>(b));
}
std::int64_t safeDiv(std::int64_t a, std::int64_t b)
{
    if (b == 0)
        return 0;
    return (a == kInt64Min && b == -1) ? kInt64Min : a / b;
}
std::int64_t safeMod(std::int64_t a, std::int64_t b)
{
    return (b == 0 || b == -1) ? 0 : a % b;
}

} // namespace

bool Simulator::Impl::evaluate(const CompiledTransition& transition, const ConditionInputs& inputs) const
{
    const CompiledCondition& condition = transition.condition;
    if (condition.alwaysFalse)
        return false;
    if (condition.fallback) {
        return cond::isTrue(cond::evaluate(
            transition.readable, [&](int node) { return nodeReading(transition, node, inputs); }, divisionByZero));
    }
    // `next` is the first free cell; the top of the stack is next[-1].
    Cell* next = stack.data();
    const Cell* vars = inputs.values.data();
    for (const Instruction& in : condition.code) {
        switch (in.op) {
        case Op::PushVariable: *next++ = vars[in.slot]; break;
        case Op::PushToken: (next++)->i = inputs.tokens[static_cast<std::size_t>(in.slot)]; break;
        case Op::PushConstant: *next++ = in.constant; break;
        case Op::IntToReal: next[-1].r = static_cast<double>(next[-1].i); break;
        case Op::Not: next[-1].i = !next[-1].i; break;
        case Op::NegateInt: next[-1].i = wrapSub(0, next[-1].i); break;
        case Op::NegateReal: next[-1].r = -next[-1].r; break;
        default: {
            const Cell b = *--next;
            Cell& a = next[-1];
            switch (in.op) {
            case Op::And: a.i = (a.i != 0) && (b.i != 0); break;
            case Op::Or: a.i = (a.i != 0) || (b.i != 0); break;
            case Op::Xor: a.i = (a.i != 0) != (b.i != 0); break;
            case Op::AddInt: a.i = wrapAdd(a.i, b.i); break;
            case Op::SubInt: a.i = wrapSub(a.i, b.i); break;
            case Op::MulInt: a.i = wrapMul(a.i, b.i); break;
            case Op::DivInt:
            case Op::ModInt:
                if (b.i == 0 && divisionByZero < 0)
                    divisionByZero = in.slot;
                a.i = in.op == Op::DivInt ? safeDiv(a.i, b.i) : safeMod(a.i, b.i);
                break;
            case Op::AddReal: a.r = a.r + b.r; break;
            case Op::SubReal: a.r = a.r - b.r; break;
            case Op::MulReal: a.r = a.r * b.r; break;
            case Op::DivReal: a.r = cond::realDivision(a.r, b.r); break;
            case Op::ModReal: a.r = std::fmod(a.r, b.r); break;
            case Op::EqInt: a.i = a.i == b.i; break;
            case Op::NeInt: a.i = a.i != b.i; break;
            case Op::LtInt: a.i = a.i < b.i; break;
            case Op::GtInt: a.i = a.i > b.i; break;
            case Op::LeInt: a.i = a.i <= b.i; break;
            case Op::GeInt: a.i = a.i >= b.i; break;
            case Op::EqReal: a.i = a.r == b.r; break;
            case Op::NeReal: a.i = a.r != b.r; break;
            case Op::LtReal: a.i = a.r < b.r; break;
            case Op::GtReal: a.i = a.r > b.r; break;
            case Op::LeReal: a.i = a.r <= b.r; break;
            case Op::GeReal: a.i = a.r >= b.r; break;
            default: break;
            }
        }
        }
    }
    return next[-1].i != 0;
}

cond::Value Simulator::Impl::nodeReading(const CompiledTransition& transition, int node,
                                         const ConditionInputs& inputs) const
{
    const auto index = static_cast<std::size_t>(node);
    if (index < transition.nodeToken.size() && transition.nodeToken[index] >= 0)
        return inputs.tokens[static_cast<std::size_t>(transition.nodeToken[index])] != 0;
    if (index < transition.nodeVariable.size() && transition.nodeVariable[index] >= 0) {
        const auto slot = static_cast<std::size_t>(transition.nodeVariable[index]);
        return toValue(inputs.values[slot], variableKinds[slot]);
    }
    return false;
}

void Simulator::Impl::reset()
{
    values = defaults;
    valuesAtLastScan = defaults;
    dirty.clear();
    std::fill(isDirty.begin(), isDirty.end(), 0);
    state = initialNumber;
    active = activeIndexFor(state);
    entry = true;
    tokenValues.assign(tokens.size(), 0);
    completeOutput.assign(nestedSteps.size(), 0);
    for (std::optional<NestedEngine>& engine : engines) {
        if (engine)
            engine->reset();
    }
    previous.assign(values.size(), 0);
    for (std::size_t slot = 0; slot < values.size(); ++slot)
        previous[slot] = variableKinds[slot] != Kind::Real && values[slot].i != 0;
    scanCount = 0;
    lastFired = nullptr;
    calledNested = -1;
    fault.reset();
    trace.clear();
}

int Simulator::Impl::activeIndexFor(int number) const
{
    if (number < 0 || static_cast<std::size_t>(number) >= stepByNumber.size())
        return -1;
    return stepByNumber[static_cast<std::size_t>(number)];
}

// What the FB writes into Complete in a call (see CompleteMode): the
// Initialization block's FALSE is overwritten by the body in the same call.
bool Simulator::Impl::fbComplete(int nestedIndex) const
{
    const auto index = static_cast<std::size_t>(nestedIndex);
    return completeModes[index] == CompleteMode::Automatic || manualComplete[index] != 0;
}

// The next scan's call(s) of a step's nested GRAFCET, run on a copy of the
// engine over `scratch` (a copy of the values, left as the calls leave them:
// what the GEMMA conditions read after the FB). Returns the Complete the FB
// yields. For a step without GRAFCET: fbComplete(), scratch untouched.
bool Simulator::Impl::predictNestedCall(const CompiledStep& step, std::vector<Cell>& scratch) const
{
    const std::optional<NestedEngine>& engine = engines[static_cast<std::size_t>(step.nestedIndex)];
    if (!engine)
        return fbComplete(step.nestedIndex);
    NestedEngine next(*engine);
    SimulatorGlobals globals(scratch, variableKinds, previous);
    const std::int64_t nowMs = (scanCount + 1) * cycleTimeMs;
    if (entry)
        next.call(true, nowMs, globals);
    next.call(false, nowMs, globals);
    return next.complete();
}

void Simulator::Impl::collectChanges(ScanRecord* record)
{
    if (record) // declaration order, whatever order the inputs were set in
        std::sort(dirty.begin(), dirty.end());
    for (int slot : dirty) {
        const auto s = static_cast<std::size_t>(slot);
        isDirty[s] = 0;
        if (sameCell(values[s], valuesAtLastScan[s], variableKinds[s]))
            continue;
        valuesAtLastScan[s] = values[s];
        if (record)
            record->changedInputs.push_back(InputChange{variableNames[s], toValue(values[s], variableKinds[s])});
    }
    dirty.clear();
}

// One scan, mirroring the generated GEMMA body (see simulator.h).
void Simulator::Impl::scan(ScanRecord* record)
{
    if (!dirty.empty())
        collectChanges(record);
    ++scanCount;
    lastFired = nullptr;
    calledNested = -1;
    std::vector<Cell> outputsBefore;
    if (record) {
        for (int slot : compiled->outputSlots)
            outputsBefore.push_back(values[static_cast<std::size_t>(slot)]);
        record->scan = scanCount;
        if (active >= 0)
            record->stepBefore = steps[static_cast<std::size_t>(active)].source->id;
    }
    if (active >= 0) {
        const CompiledStep& step = steps[static_cast<std::size_t>(active)];
        bool complete = false;
        if (step.nestedIndex >= 0) {
            const auto nested = static_cast<std::size_t>(step.nestedIndex);
            calledNested = step.nestedIndex;
            if (std::optional<NestedEngine>& engine = engines[nested])
                engine->clearDivisionFault(); // explain() may have evaluated on it
            if (entry) {
                // IF Entry THEN S(Initialization := Entry); Entry := FALSE; tokens := FALSE; END_IF;
                callFunctionBlock(step, true);
                entry = false;
                std::fill_n(tokenValues.begin() + step.firstToken, step.tokenCount, 0);
            }
            callFunctionBlock(step, false); // S(Initialization := Entry);
            complete = completeOutput[nested] != 0;
            if (nestedFaulted(step)) {
                if (record)
                    fillRecordAfter(*record, outputsBefore);
                return;
            }
        }
        for (const CompiledTransition& transition : step.transitions) {
            divisionByZero = -1;
            const bool holds = evaluate(transition, {tokenValues, values});
            if (divisionByZero >= 0) { // the PLC stops in the middle of the CASE
                transitionFaulted(step, transition);
                if (record)
                    fillRecordAfter(*record, outputsBefore);
                return;
            }
            if (holds && (!transition.waitsForComplete || complete)) {
                state = transition.targetNumber;
                active = activeIndexFor(state);
                entry = true;
                lastFired = transition.source;
                break;
            }
        }
    }
    writeContinuousOutputs();
    // After END_CASE: IF State = <source no.> AND <literal> THEN token := TRUE; END_IF;
    // Only the active step's tokens can match State.
    if (active >= 0) {
        const CompiledStep& step = steps[static_cast<std::size_t>(active)];
        for (int t = step.firstToken; t < step.firstToken + step.tokenCount; ++t) {
            const CompiledToken& token = tokens[static_cast<std::size_t>(t)];
            if (token.variableSlot < 0)
                continue;
            const bool value = values[static_cast<std::size_t>(token.variableSlot)].i != 0;
            if (value != token.normallyClosed)
                tokenValues[static_cast<std::size_t>(t)] = 1;
        }
    }
    updateEdgeMemories();
    if (record)
        fillRecordAfter(*record, outputsBefore);
}

// The engine went on with 0 for the quotient to the end of its call; the
// scan stops after it, before the GEMMA transitions.
bool Simulator::Impl::nestedFaulted(const CompiledStep& step)
{
    const std::optional<NestedEngine>& engine = engines[static_cast<std::size_t>(step.nestedIndex)];
    if (!engine || !engine->divisionFault())
        return false;
    fault = *engine->divisionFault();
    fault->scan = scanCount;
    fault->stepId = step.source->id;
    return true;
}

void Simulator::Impl::transitionFaulted(const CompiledStep& step, const CompiledTransition& transition)
{
    SimulationFault found;
    found.scan = scanCount;
    found.stepId = step.source->id;
    found.transitionId = transition.source->id;
    found.place = "the condition of " + transition.source->id;
    found.text = transition.source->conditionText;
    found.division = excerpt(found.text, transition.readable.at(divisionByZero).span);
    fault = std::move(found);
}

void Simulator::Impl::fillRecordAfter(ScanRecord& record, const std::vector<Cell>& outputsBefore) const
{
    if (lastFired)
        record.fired = lastFired->id;
    if (active >= 0)
        record.stepAfter = steps[static_cast<std::size_t>(active)].source->id;
    record.entry = entry;
    record.tokens.assign(tokenValues.begin(), tokenValues.end());
    record.complete.assign(completeOutput.begin(), completeOutput.end());
    record.nestedActive.clear();
    record.unstable.clear();
    for (const std::optional<NestedEngine>& engine : engines) {
        record.nestedActive.push_back(engine ? engine->activeSteps() : std::vector<int>{});
        record.unstable.push_back(engine && engine->unstable());
    }
    record.changedOutputs.clear();
    for (std::size_t i = 0; i < compiled->outputSlots.size() && i < outputsBefore.size(); ++i) {
        const auto slot = static_cast<std::size_t>(compiled->outputSlots[i]);
        if (!sameCell(values[slot], outputsBefore[i], variableKinds[slot]))
            record.changedOutputs.push_back(InputChange{variableNames[slot], toValue(values[slot], variableKinds[slot])});
    }
}

int Simulator::Impl::stepIndexOfNested(std::string_view stepId) const
{
    for (std::size_t i = 0; i < nestedSteps.size(); ++i) {
        if (equalsIgnoreCase(nestedSteps[i], stepId))
            return static_cast<int>(i);
    }
    return -1;
}

// Speed reads 3; Stop_F1_3_MEM reads FALSE and stores NOT Stop.
ConditionReading Simulator::Impl::reading(const CompiledTransition& transition, int node,
                                          const ConditionInputs& inputs) const
{
    const auto index = static_cast<std::size_t>(node);
    ConditionReading result;
    result.value = cond::formatValue(nodeReading(transition, node, inputs));
    const int token = transition.nodeToken[index];
    if (token >= 0) {
        const CompiledToken& t = tokens[static_cast<std::size_t>(token)];
        result.name = tokenNames[static_cast<std::size_t>(token)];
        result.tokenLiteral = t.variableSlot >= 0 ? variableNames[static_cast<std::size_t>(t.variableSlot)] : "?";
        if (t.normallyClosed)
            result.tokenLiteral = "NOT " + result.tokenLiteral;
        return result;
    }
    const int slot = transition.nodeVariable[index];
    result.name = slot >= 0 ? variableNames[static_cast<std::size_t>(slot)] : transition.readable.at(node).text;
    return result;
}

// Why the subtree at `node` has the value it has: logical operators descend
// to the operands that decide the result (visitDecidingOperands), everything
// else is explained by its text, its value and the values it reads.
void Simulator::Impl::explainNode(const CompiledTransition& transition, const ConditionInputs& inputs, int node,
                                  std::vector<ExplanationReason>& reasons) const
{
    const cond::Expression& expression = transition.readable;
    const auto isTrueAt = [&](int at) {
        cond::Expression sub = expression;
        sub.root = at;
        return cond::isTrue(cond::evaluate(sub, [&](int v) { return nodeReading(transition, v, inputs); }));
    };
    visitDecidingOperands(expression, node, isTrueAt,
                          [&](int leaf) { explainLeaf(transition, inputs, leaf, reasons); });
}

void Simulator::Impl::explainLeaf(const CompiledTransition& transition, const ConditionInputs& inputs, int node,
                                  std::vector<ExplanationReason>& reasons) const
{
    const cond::Expression& expression = transition.readable;
    const cond::Node& n = expression.at(node);
    ExplanationReason reason;
    if (n.kind == cond::NodeKind::Variable) {
        reason.kind = ExplanationReason::Kind::Reading;
        reason.readings.push_back(reading(transition, node, inputs));
        reasons.push_back(std::move(reason));
        return;
    }
    if (n.kind == cond::NodeKind::BoolLiteral) {
        reason.kind = ExplanationReason::Kind::Literal;
        reason.value = toUpperAscii(n.text);
        reasons.push_back(std::move(reason));
        return;
    }
    // A comparison (or anything else): "Speed > 10 is FALSE (Speed = 3)".
    cond::Expression sub = expression;
    sub.root = node;
    cond::PrintOptions options;
    options.variableName = [this, &transition, &sub](const cond::Node& variable) {
        const auto at = static_cast<std::size_t>(&variable - sub.nodes.data());
        if (at < transition.nodeVariable.size() && transition.nodeVariable[at] >= 0)
            return variableNames[static_cast<std::size_t>(transition.nodeVariable[at])];
        return variable.text;
    };
    reason.kind = ExplanationReason::Kind::Expression;
    reason.subject = cond::print(sub, options);
    reason.value = cond::formatValue(cond::evaluate(sub, [&](int v) { return nodeReading(transition, v, inputs); }));
    for (int v : cond::variableNodes(sub)) { // walks the subtree only
        ConditionReading operand = reading(transition, v, inputs);
        if (std::find(reason.readings.begin(), reason.readings.end(), operand) == reason.readings.end())
            reason.readings.push_back(std::move(operand));
    }
    reasons.push_back(std::move(reason));
}

std::vector<ExplanationReason> Simulator::Impl::explainFalse(const CompiledTransition& transition,
                                                             const ConditionInputs& inputs) const
{
    std::vector<ExplanationReason> reasons;
    if (!transition.readable.empty())
        explainNode(transition, inputs, transition.readable.root, reasons);
    return reasons;
}

// --- Simulator ---------------------------------------------------------------

Simulator::Simulator(const Model& model)
    : m_impl(std::make_unique<Impl>(model))
{
}

Simulator::~Simulator() = default;
Simulator::Simulator(Simulator&&) noexcept = default;
Simulator& Simulator::operator=(Simulator&&) noexcept = default;

// The copy shares the compiled program; `lastFired` points into it, so it stays valid.
Simulator::Simulator(const Simulator& other)
    : m_impl(std::make_unique<Impl>(*other.m_impl))
{
}

Simulator& Simulator::operator=(const Simulator& other)
{
    if (this != &other) {
        Simulator copy(other);
        *this = std::move(copy);
    }
    return *this;
}

void Simulator::reset()
{
    m_impl->reset();
}

ScanRecord Simulator::step()
{
    ScanRecord record;
    if (m_impl->fault) { // the task has stopped
        record.scan = m_impl->scanCount;
        return record;
    }
    m_impl->scan(&record);
    if (m_impl->traceEnabled)
        m_impl->trace.push_back(record);
    if (m_impl->callback)
        m_impl->callback(record);
    return record;
}

void Simulator::run(std::int64_t scans)
{
    const bool records = m_impl->traceEnabled || m_impl->callback;
    for (std::int64_t i = 0; i < scans && !m_impl->fault; ++i) {
        if (records) {
            step();
        } else {
            m_impl->scan(nullptr);
        }
    }
}

Status Simulator::setVariable(std::string_view name, const cond::Value& value)
{
    const int index = variableIndex(name);
    if (index < 0)
        return Status::failure("simulation.unknown-variable", "no variable is named '" + std::string(name) + "'");
    return setVariableAt(static_cast<std::size_t>(index), value);
}

Status Simulator::setVariableAt(std::size_t index, const cond::Value& value)
{
    Impl& impl = *m_impl;
    if (index >= impl.variableNames.size())
        return Status::failure("simulation.unknown-variable", "no variable has index " + std::to_string(index));
    const IecType type = impl.variableTypes[index];
    const Kind kind = impl.variableKinds[index];
    const Kind given = kindOf(value);
    const std::string& name = impl.variableNames[index];
    Cell cell = toCell(value);
    if (kind == Kind::Real && given == Kind::Integer) {
        cell.r = static_cast<double>(cell.i);
    } else if (kind != given) {
        return Status::failure("simulation.wrong-kind", name + " is " + std::string(iecTypeName(type)) + ": "
                                                            + cond::formatValue(value) + " is not a value of it");
    }
    bool inRange = true;
    if (kind == Kind::Integer) {
        const cond::IntegerRange range = cond::integerRange(type);
        inRange = cell.i >= range.low && cell.i <= range.high;
    } else if (kind == Kind::Real) {
        const double limit = type == IecType::Real ? static_cast<double>(FLT_MAX) : DBL_MAX;
        inRange = cell.r >= -limit && cell.r <= limit; // NaN fails both
    }
    if (!inRange) {
        std::string problem = defaultValueProblem(type, cond::formatValue(value));
        if (problem.empty())
            problem = cond::formatValue(value) + " is out of range for " + std::string(iecTypeName(type));
        return Status::failure("simulation.out-of-range", name + ": " + problem);
    }
    impl.values[index] = cell;
    if (!impl.isDirty[index]) {
        impl.isDirty[index] = 1;
        impl.dirty.push_back(static_cast<int>(index));
    }
    return Status::success();
}

VariableKind Simulator::variableKind(std::size_t index) const
{
    const auto& roles = m_impl->compiled->variableRoles;
    return index < roles.size() ? roles[index] : VariableKind::Input;
}

Status Simulator::setVariableText(std::string_view name, std::string_view text)
{
    const int index = variableIndex(name);
    if (index < 0)
        return Status::failure("simulation.unknown-variable", "no variable is named '" + std::string(name) + "'");
    const IecType type = m_impl->variableTypes[static_cast<std::size_t>(index)];
    const std::string& declared = m_impl->variableNames[static_cast<std::size_t>(index)];
    if (text.empty())
        return Status::failure("simulation.bad-value", declared + ": a value is missing");
    std::optional<cond::Value> value = cond::parseValue(type, text);
    if (!value) {
        return Status::failure("simulation.bad-value", declared + " is " + std::string(iecTypeName(type)) + ": "
                                                           + defaultValueProblem(type, text));
    }
    return setVariableAt(static_cast<std::size_t>(index), *value);
}

int Simulator::variableIndex(std::string_view name) const
{
    auto found = m_impl->variableByUpperName.find(toUpperAscii(name));
    return found == m_impl->variableByUpperName.end() ? -1 : found->second;
}

cond::Value Simulator::variable(std::string_view name) const
{
    const int index = variableIndex(name);
    return index < 0 ? cond::Value{false} : variableValue(static_cast<std::size_t>(index));
}

const std::vector<std::string>& Simulator::variableNames() const
{
    return m_impl->variableNames;
}

cond::Value Simulator::variableValue(std::size_t index) const
{
    if (index >= m_impl->values.size())
        return false;
    return toValue(m_impl->values[index], m_impl->variableKinds[index]);
}

IecType Simulator::variableType(std::size_t index) const
{
    return index < m_impl->variableTypes.size() ? m_impl->variableTypes[index] : IecType::Bool;
}

namespace {

Status noNestedStep(std::string_view stepId)
{
    return Status::failure("simulation.not-nested", "'" + std::string(stepId)
                                                        + "' is not a visible macro-step or enclosing step");
}

} // namespace

Status completeFromGrafcet(std::string_view stepId)
{
    return Status::failure("simulation.complete-from-grafcet",
                           "the Complete of " + std::string(stepId) + " comes from its nested GRAFCET");
}

Status Simulator::setCompleteMode(std::string_view stepId, CompleteMode mode)
{
    const int index = m_impl->stepIndexOfNested(stepId);
    if (index < 0)
        return noNestedStep(stepId);
    if (m_impl->engines[static_cast<std::size_t>(index)])
        return completeFromGrafcet(stepId);
    m_impl->completeModes[static_cast<std::size_t>(index)] = mode;
    return Status::success();
}

Status Simulator::setComplete(std::string_view stepId, bool complete)
{
    const int index = m_impl->stepIndexOfNested(stepId);
    if (index < 0)
        return noNestedStep(stepId);
    if (m_impl->engines[static_cast<std::size_t>(index)])
        return completeFromGrafcet(stepId);
    m_impl->manualComplete[static_cast<std::size_t>(index)] = complete;
    return Status::success();
}

CompleteMode Simulator::completeMode(std::string_view stepId) const
{
    const int index = m_impl->stepIndexOfNested(stepId);
    return index < 0 ? CompleteMode::Automatic : m_impl->completeModes[static_cast<std::size_t>(index)];
}

bool Simulator::manualComplete(std::string_view stepId) const
{
    const int index = m_impl->stepIndexOfNested(stepId);
    return index >= 0 && m_impl->manualComplete[static_cast<std::size_t>(index)];
}

bool Simulator::complete(std::string_view stepId) const
{
    const int index = m_impl->stepIndexOfNested(stepId);
    return index >= 0 && m_impl->completeOutput[static_cast<std::size_t>(index)];
}

const std::vector<std::string>& Simulator::nestedSteps() const
{
    return m_impl->nestedSteps;
}

const NestedEngine* Simulator::grafcetEngine(std::string_view stepId) const
{
    const int index = m_impl->stepIndexOfNested(stepId);
    if (index < 0)
        return nullptr;
    const std::optional<NestedEngine>& engine = m_impl->engines[static_cast<std::size_t>(index)];
    return engine ? &*engine : nullptr;
}

bool Simulator::hasGrafcet(std::string_view stepId) const
{
    return grafcetEngine(stepId) != nullptr;
}

std::vector<int> Simulator::activeNestedSteps(std::string_view stepId) const
{
    const NestedEngine* engine = grafcetEngine(stepId);
    return engine ? engine->activeSteps() : std::vector<int>{};
}

bool Simulator::unstable(std::string_view stepId) const
{
    const NestedEngine* engine = grafcetEngine(stepId);
    return engine && engine->unstable();
}

bool Simulator::nestedCalled(std::string_view stepId) const
{
    const int index = m_impl->stepIndexOfNested(stepId);
    return index >= 0 && index == m_impl->calledNested;
}

std::vector<int> Simulator::firedNestedTransitions(std::string_view stepId) const
{
    const int index = m_impl->stepIndexOfNested(stepId);
    if (index < 0 || index != m_impl->calledNested)
        return {};
    const std::optional<NestedEngine>& engine = m_impl->engines[static_cast<std::size_t>(index)];
    return engine ? engine->firedTransitions() : std::vector<int>{};
}

std::vector<NestedTimerState> Simulator::nestedTimers(std::string_view stepId) const
{
    const NestedEngine* engine = grafcetEngine(stepId);
    return engine ? engine->timers() : std::vector<NestedTimerState>{};
}

std::vector<std::string> Simulator::nestedOutputs(std::string_view stepId) const
{
    const NestedEngine* engine = grafcetEngine(stepId);
    return engine ? engine->outputNames() : std::vector<std::string>{};
}

std::string Simulator::activeStepId() const
{
    return m_impl->active < 0 ? std::string() : m_impl->steps[static_cast<std::size_t>(m_impl->active)].source->id;
}

int Simulator::activeStepNumber() const
{
    return m_impl->state;
}

bool Simulator::entry() const
{
    return m_impl->entry;
}

const std::vector<std::string>& Simulator::tokenNames() const
{
    return m_impl->tokenNames;
}

std::vector<bool> Simulator::tokenValues() const
{
    return std::vector<bool>(m_impl->tokenValues.begin(), m_impl->tokenValues.end());
}

bool Simulator::token(std::string_view tokenName) const
{
    for (std::size_t i = 0; i < m_impl->tokenNames.size(); ++i) {
        if (equalsIgnoreCase(m_impl->tokenNames[i], tokenName))
            return m_impl->tokenValues[i] != 0;
    }
    return false;
}

const std::optional<SimulationFault>& Simulator::fault() const
{
    return m_impl->fault;
}

std::int64_t Simulator::scanCount() const
{
    return m_impl->scanCount;
}

std::int64_t Simulator::simulatedTimeMs() const
{
    return m_impl->scanCount * m_impl->cycleTimeMs;
}

int Simulator::cycleTimeMs() const
{
    return m_impl->cycleTimeMs;
}

std::string Simulator::lastFired() const
{
    return m_impl->lastFired ? m_impl->lastFired->id : std::string();
}

namespace {

// The errors among `problems` that `concerns` picks, which make a condition
// or receptivity unusable, with what the editor needs to word them as the
// checks' diagnostics of the same code.
template <typename Concerns>
std::vector<ExplanationReason> unusableReasons(const std::vector<ProgramProblem>& problems, Concerns concerns)
{
    std::vector<ExplanationReason> reasons;
    for (const ProgramProblem& problem : problems) {
        if (problem.kind != ProgramProblem::Kind::Error || !concerns(problem))
            continue;
        ExplanationReason reason;
        reason.kind = ExplanationReason::Kind::Unusable;
        reason.code = problem.code;
        reason.arguments = problem.arguments;
        reason.message = problem.message;
        reasons.push_back(std::move(reason));
    }
    if (reasons.empty()) { // not expected: an unusable text has an error
        ExplanationReason unknown;
        unknown.kind = ExplanationReason::Kind::Unusable;
        reasons.push_back(std::move(unknown));
    }
    return reasons;
}

} // namespace

std::vector<TransitionExplanation> Simulator::explain() const
{
    const Impl& impl = *m_impl;
    std::vector<TransitionExplanation> result;
    if (impl.active < 0)
        return result;
    const CompiledStep& step = impl.steps[static_cast<std::size_t>(impl.active)];
    // The next scan as it will start: the entry block resets the tokens, the FB yields Complete.
    std::vector<char> tokenState = impl.tokenValues;
    std::vector<Cell> nextValues = impl.values;
    bool complete = false;
    if (step.nestedIndex >= 0) {
        if (impl.entry)
            std::fill_n(tokenState.begin() + step.firstToken, step.tokenCount, 0);
        // A nested GRAFCET runs first: Complete is what it yields, the
        // conditions read what its stored actions wrote.
        complete = impl.predictNestedCall(step, nextValues);
    }
    const Impl::ConditionInputs inputs{tokenState, nextValues};
    ExplanationReason completeFalse;
    completeFalse.kind = ExplanationReason::Kind::CompleteFalse;
    completeFalse.subject = step.source->id;
    std::string firing;
    for (const CompiledTransition& transition : step.transitions) {
        const GemmaTransition& source = *transition.source;
        TransitionExplanation explanation;
        explanation.transitionId = source.id;
        explanation.targetId = source.targetId;
        explanation.priority = source.priority;
        explanation.family = source.family;
        explanation.waitsForComplete = source.waitsForComplete;
        if (!source.conditionUsable) {
            explanation.status = TransitionStatus::Unusable;
            explanation.reasons = unusableReasons(source.problems, [](const ProgramProblem&) { return true; });
        } else if (!impl.evaluate(transition, inputs)) {
            explanation.status = TransitionStatus::ConditionFalse;
            explanation.reasons = impl.explainFalse(transition, inputs);
            if (transition.waitsForComplete && !complete)
                explanation.reasons.push_back(completeFalse);
        } else if (transition.waitsForComplete && !complete) {
            explanation.status = TransitionStatus::WaitingForComplete;
            explanation.reasons.push_back(completeFalse);
        } else if (!firing.empty()) {
            explanation.status = TransitionStatus::PreemptedByHigherPriority;
            explanation.preemptedBy = firing;
            ExplanationReason first;
            first.kind = ExplanationReason::Kind::FiresFirst;
            first.subject = firing;
            explanation.reasons.push_back(std::move(first));
        } else {
            explanation.status = TransitionStatus::Fires;
            firing = source.id;
        }
        result.push_back(std::move(explanation));
    }
    return result;
}

NestedExplanation Simulator::explainNested(std::string_view stepId) const
{
    const Impl& impl = *m_impl;
    NestedExplanation result;
    const int index = impl.stepIndexOfNested(stepId);
    if (index < 0 || !impl.engines[static_cast<std::size_t>(index)])
        return result;
    const NestedEngine& engine = *impl.engines[static_cast<std::size_t>(index)];
    result.stepId = impl.nestedSteps[static_cast<std::size_t>(index)];
    result.untilStable = engine.grafcet().rule == EvolutionRule::UntilStable;
    result.called = impl.active >= 0 && impl.steps[static_cast<std::size_t>(impl.active)].nestedIndex == index;
    if (!result.called) {
        result.situation = engine.activeSteps();
        result.transitions = engine.explainNotCalled(result.stepId);
        return result;
    }
    result.initialization = impl.entry;
    // The Initialization call's actions write the globals: predict on a copy.
    std::vector<Cell> scratch = impl.values;
    SimulatorGlobals globals(scratch, impl.variableKinds, impl.previous);
    result.transitions = engine.explainNextCall(result.initialization, (impl.scanCount + 1) * impl.cycleTimeMs,
                                                globals, &result.situation);
    for (NestedTransitionExplanation& explanation : result.transitions) {
        if (explanation.status != NestedTransitionStatus::Unusable)
            continue;
        explanation.reasons = unusableReasons(impl.program.problems, [&](const ProgramProblem& problem) {
            return problem.nestedTransition == explanation.number && equalsIgnoreCase(problem.element, result.stepId);
        });
    }
    return result;
}

void Simulator::setTraceEnabled(bool enabled)
{
    m_impl->traceEnabled = enabled;
}

bool Simulator::traceEnabled() const
{
    return m_impl->traceEnabled;
}

const std::vector<ScanRecord>& Simulator::trace() const
{
    return m_impl->trace;
}

void Simulator::clearTrace()
{
    m_impl->trace.clear();
}

void Simulator::setScanCallback(std::function<void(const ScanRecord&)> callback)
{
    m_impl->callback = std::move(callback);
}

const GemmaProgram& Simulator::program() const
{
    return m_impl->program;
}

int Simulator::stepIndexForNumber(int number) const
{
    return m_impl->activeIndexFor(number);
}

} // namespace core
