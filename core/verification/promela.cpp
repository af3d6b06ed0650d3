#include "core/verification/promela.h"

#include "core/condition/conditionanalysis.h"
#include "core/condition/conditionevaluator.h"
#include "core/templates/gemma/gemmaprogram.h"
#include "core/codegen/stgenerator.h"
#include "core/model/model.h"
#include "core/condition/symboltable.h"
#include "core/verification/promelawriter.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <limits>
#include <optional>
#include <set>
#include <sstream>

namespace core {

namespace {

using cond::BinaryOp;
using cond::NodeKind;

constexpr const char* kEmergencyStop = "D1";
// Promela names of the generated globals. `State` itself would clash with
// the C type of the same name in SPIN's pan.c.
constexpr const char* kState = "gState";
constexpr const char* kEntry = "gEntry";
constexpr const char* kMark = "mark";
constexpr const char* kProbeComplete = "pc";
constexpr const char* kFrom = "gFrom";
constexpr const char* kUntil = "gUntil";
constexpr int kNoUntil = 255;

// Text safe inside a Promela (C preprocessor) comment, on one line.
std::string commentText(std::string_view text)
{
    return promelaComment(text);
}

std::string stepKind(StepType type)
{
    switch (type) {
    case StepType::Simple: return "simple";
    case StepType::Macro: return "macro-step";
    case StepType::Enclosing: return "enclosing step";
    }
    return "simple";
}

bool isComparison(BinaryOp op)
{
    return op == BinaryOp::Equal || op == BinaryOp::NotEqual || op == BinaryOp::Less || op == BinaryOp::Greater
        || op == BinaryOp::LessEqual || op == BinaryOp::GreaterEqual;
}

bool hasVariable(const cond::Expression& expression, int index)
{
    const cond::Node& node = expression.at(index);
    switch (node.kind) {
    case NodeKind::Variable: return true;
    case NodeKind::Unary: return hasVariable(expression, node.operand);
    case NodeKind::Binary: return hasVariable(expression, node.left) || hasVariable(expression, node.right);
    default: return false;
    }
}

cond::Expression rootedAt(const cond::Expression& expression, int node)
{
    cond::Expression copy = expression;
    copy.root = node;
    return copy;
}

cond::Value constantValue(const cond::Expression& expression, int node)
{
    return cond::evaluate(rootedAt(expression, node), [](int) { return cond::Value{false}; });
}

bool isNumber(const cond::Value& value)
{
    return !std::holds_alternative<bool>(value);
}

long double toLong(const cond::Value& value)
{
    if (const auto* i = std::get_if<std::int64_t>(&value))
        return static_cast<long double>(*i);
    if (const auto* d = std::get_if<double>(&value))
        return *d;
    return std::get<bool>(value) ? 1 : 0;
}

double toDouble(const cond::Value& value)
{
    return static_cast<double>(toLong(value));
}

// As the PLC (and the simulator) compares: two integers as integers,
// otherwise as reals.
bool compareValues(BinaryOp op, const cond::Value& a, const cond::Value& b)
{
    const auto* ia = std::get_if<std::int64_t>(&a);
    const auto* ib = std::get_if<std::int64_t>(&b);
    auto apply = [op](auto x, auto y) {
        switch (op) {
        case BinaryOp::Equal: return x == y;
        case BinaryOp::NotEqual: return x != y;
        case BinaryOp::Less: return x < y;
        case BinaryOp::Greater: return x > y;
        case BinaryOp::LessEqual: return x <= y;
        case BinaryOp::GreaterEqual: return x >= y;
        default: return false;
        }
    };
    if (ia && ib)
        return apply(*ia, *ib);
    return apply(toDouble(a), toDouble(b));
}

BinaryOp mirrored(BinaryOp op)
{
    switch (op) {
    case BinaryOp::Less: return BinaryOp::Greater;
    case BinaryOp::Greater: return BinaryOp::Less;
    case BinaryOp::LessEqual: return BinaryOp::GreaterEqual;
    case BinaryOp::GreaterEqual: return BinaryOp::LessEqual;
    default: return op;
    }
}

// `Speed > 10`, `10 <= Speed`, `Level = 2 * 3`: one numeric variable against
// a constant subexpression.
struct VariableComparison {
    const Variable* variable = nullptr;
    BinaryOp op = BinaryOp::Equal;
    cond::Value constant;
};

std::optional<VariableComparison> variableComparison(const cond::Expression& expression, int index,
                                                     const SymbolTable& symbols)
{
    const cond::Node& node = expression.at(index);
    if (node.kind != NodeKind::Binary || !isComparison(node.binaryOp))
        return std::nullopt;
    auto numericVariable = [&](int side) -> const Variable* {
        const cond::Node& operand = expression.at(side);
        if (operand.kind != NodeKind::Variable)
            return nullptr;
        const Variable* variable = symbols.find(operand.text);
        return variable && isNumericType(variable->type) ? variable : nullptr;
    };
    auto constant = [&](int side) -> std::optional<cond::Value> {
        if (hasVariable(expression, side))
            return std::nullopt;
        cond::Value value = constantValue(expression, side);
        if (!isNumber(value) || std::isnan(toDouble(value)))
            return std::nullopt;
        return value;
    };
    if (const Variable* variable = numericVariable(node.left)) {
        if (auto value = constant(node.right))
            return VariableComparison{variable, node.binaryOp, *value};
    }
    if (const Variable* variable = numericVariable(node.right)) {
        if (auto value = constant(node.left))
            return VariableComparison{variable, mirrored(node.binaryOp), *value};
    }
    return std::nullopt;
}

// --- Numeric inputs: one value per interval of the constants ----------------

struct IntegerRange {
    long double low;
    long double high;
};

IntegerRange integerRange(IecType type)
{
    constexpr auto min64 = static_cast<long double>(std::numeric_limits<std::int64_t>::min());
    constexpr auto max64 = static_cast<long double>(std::numeric_limits<std::int64_t>::max());
    switch (type) {
    case IecType::Sint: return {-128, 127};
    case IecType::Int: return {-32768, 32767};
    case IecType::Dint: return {-2147483648.0L, 2147483647.0L};
    case IecType::Usint: return {0, 255};
    case IecType::Uint: return {0, 65535};
    case IecType::Udint: return {0, 4294967295.0L};
    case IecType::Ulint: return {0, max64}; // clamped to LINT, as the simulator stores it
    default: return {min64, max64};
    }
}

// A value of the type strictly between the bounds (an absent bound is the
// end of the type's range), or nothing.
std::optional<cond::Value> integerBetween(IecType type, std::optional<long double> low,
                                          std::optional<long double> high)
{
    const IntegerRange range = integerRange(type);
    long double candidate = 0;
    if (!low && high)
        candidate = std::min(std::ceil(*high) - 1, range.high); // nearest below: readable
    else if (low)
        candidate = std::max(std::floor(*low) + 1, range.low);
    else
        candidate = std::clamp(0.0L, range.low, range.high);
    if (candidate < range.low || candidate > range.high)
        return std::nullopt;
    if ((low && !(candidate > *low)) || (high && !(candidate < *high)))
        return std::nullopt;
    return cond::Value{static_cast<std::int64_t>(candidate)};
}

std::optional<cond::Value> realBetween(IecType type, std::optional<double> low, std::optional<double> high)
{
    const double limit = type == IecType::Real ? static_cast<double>(FLT_MAX) : DBL_MAX;
    const double inf = std::numeric_limits<double>::infinity();
    double candidate = 0;
    if (!low && !high) {
        candidate = 0;
    } else if (!low) {
        candidate = *high - 1;
        if (!(candidate < *high))
            candidate = std::nextafter(*high, -inf);
        candidate = std::min(candidate, limit);
    } else if (!high) {
        candidate = *low + 1;
        if (!(candidate > *low))
            candidate = std::nextafter(*low, inf);
        candidate = std::max(candidate, -limit);
    } else {
        candidate = std::clamp(*low / 2 + *high / 2, -limit, limit);
    }
    if (!(candidate >= -limit && candidate <= limit))
        return std::nullopt;
    if ((low && !(candidate > *low)) || (high && !(candidate < *high)))
        return std::nullopt;
    return cond::Value{candidate};
}

std::optional<cond::Value> pointOf(IecType type, const cond::Value& constant)
{
    if (isRealType(type)) {
        const double limit = type == IecType::Real ? static_cast<double>(FLT_MAX) : DBL_MAX;
        const double value = toDouble(constant);
        if (!(value >= -limit && value <= limit))
            return std::nullopt;
        return cond::Value{value};
    }
    const IntegerRange range = integerRange(type);
    const long double value = toLong(constant);
    if (std::floor(value) != value || value < range.low || value > range.high)
        return std::nullopt;
    return cond::Value{static_cast<std::int64_t>(value)};
}

struct NumericInput {
    const Variable* variable = nullptr;
    std::string name;                    // "in_Speed"
    std::vector<cond::Value> constants;  // compared with, ascending, distinct
    std::vector<cond::Value> values;     // one per non-empty region, ascending
    std::vector<std::string> regions;    // what each value stands for
};

void computeRegions(NumericInput& input)
{
    std::vector<cond::Value>& constants = input.constants;
    std::stable_sort(constants.begin(), constants.end(),
                     [](const cond::Value& a, const cond::Value& b) { return toLong(a) < toLong(b); });
    constants.erase(std::unique(constants.begin(), constants.end(),
                                [](const cond::Value& a, const cond::Value& b) { return toLong(a) == toLong(b); }),
                    constants.end());
    const IecType type = input.variable->type;
    const bool real = isRealType(type);
    auto between = [&](std::optional<std::size_t> low, std::optional<std::size_t> high) {
        if (real) {
            return realBetween(type, low ? std::optional<double>(toDouble(constants[*low])) : std::nullopt,
                               high ? std::optional<double>(toDouble(constants[*high])) : std::nullopt);
        }
        return integerBetween(type, low ? std::optional<long double>(toLong(constants[*low])) : std::nullopt,
                              high ? std::optional<long double>(toLong(constants[*high])) : std::nullopt);
    };
    auto add = [&](const std::optional<cond::Value>& value, std::string label) {
        if (!value)
            return;
        input.values.push_back(*value);
        input.regions.push_back(std::move(label) + " (" + cond::formatValue(*value) + ")");
    };
    if (constants.empty()) {
        add(between(std::nullopt, std::nullopt), "any value");
        return;
    }
    add(between(std::nullopt, std::size_t{0}), "below " + cond::formatValue(constants.front()));
    for (std::size_t i = 0; i < constants.size(); ++i) {
        add(pointOf(type, constants[i]), "equal to " + cond::formatValue(constants[i]));
        if (i + 1 < constants.size())
            add(between(i, i + 1), "between " + cond::formatValue(constants[i]) + " and "
                                       + cond::formatValue(constants[i + 1]));
    }
    add(between(constants.size() - 1, std::nullopt), "above " + cond::formatValue(constants.back()));
}

// --- Inputs and the translation of conditions -----------------------------------

class Inputs {
public:
    explicit Inputs(const Model& model) : m_model(model), m_symbols(model.variables()) {}

    const SymbolTable& symbols() const { return m_symbols; }

    // First pass: every variable, constant and opaque comparison the usable conditions use.
    void collect(const cond::Expression& expression, int index)
    {
        const cond::Node& node = expression.at(index);
        switch (node.kind) {
        case NodeKind::Variable:
            if (const Variable* variable = m_symbols.find(node.text); variable && variable->type == IecType::Bool)
                m_usedBools.insert(variable);
            return;
        case NodeKind::Unary: collect(expression, node.operand); return;
        case NodeKind::Binary: break;
        default: return;
        }
        if (!isComparison(node.binaryOp) || isBoolean(expression, node.left)) {
            collect(expression, node.left);
            collect(expression, node.right);
            return;
        }
        if (!hasVariable(expression, index))
            return; // folded
        if (auto comparison = variableComparison(expression, index, m_symbols)) {
            m_constants[comparison->variable].push_back(comparison->constant);
            return;
        }
        const std::string text = atomText(expression, index);
        if (!m_atomIndex.count(text)) {
            m_atomIndex[text] = m_atoms.size();
            m_atoms.push_back(text);
        }
    }

    // Fixes the names and the declaration order.
    void finish()
    {
        int rank = 0;
        for (const Variable& variable : m_model.variables()) {
            if (m_usedBools.count(&variable)) {
                m_bools.push_back(&variable);
                m_rank[boolName(variable)] = rank++;
            }
        }
        for (const Variable& variable : m_model.variables()) {
            auto found = m_constants.find(&variable);
            if (found == m_constants.end())
                continue;
            NumericInput input;
            input.variable = &variable;
            input.name = "in_" + variable.name;
            input.constants = found->second;
            computeRegions(input);
            m_numericIndex[&variable] = m_numerics.size();
            m_rank[input.name] = rank++;
            m_numerics.push_back(std::move(input));
        }
        for (std::size_t i = 0; i < m_atoms.size(); ++i)
            m_rank[atomName(i)] = rank++;
    }

    static std::string boolName(const Variable& variable) { return "in_" + variable.name; }
    static std::string atomName(std::size_t index) { return "atom_" + std::to_string(index + 1); }

    const std::vector<const Variable*>& bools() const { return m_bools; }
    const std::vector<NumericInput>& numerics() const { return m_numerics; }
    const std::vector<std::string>& atoms() const { return m_atoms; }

    bool isNumeric(const std::string& name) const
    {
        return std::any_of(m_numerics.begin(), m_numerics.end(),
                           [&](const NumericInput& input) { return input.name == name; });
    }

    // The number of values an input name ranges over (2 for booleans and atoms).
    std::size_t valueCount(const std::string& name) const
    {
        for (const NumericInput& input : m_numerics) {
            if (input.name == name)
                return input.values.size();
        }
        return 2;
    }

    // Input names in declaration order.
    std::vector<std::string> ordered(const std::set<std::string>& names) const
    {
        std::vector<std::string> out(names.begin(), names.end());
        std::sort(out.begin(), out.end(), [&](const std::string& a, const std::string& b) {
            return rankOf(a) < rankOf(b);
        });
        return out;
    }

    // Second pass: the Promela expression; `reads` gathers the inputs used.
    std::string translate(const cond::Expression& expression, int index, const std::map<int, std::string>& tokens,
                          std::set<std::string>& reads) const
    {
        if (auto token = tokens.find(index); token != tokens.end())
            return "tk_" + token->second;
        const cond::Node& node = expression.at(index);
        switch (node.kind) {
        case NodeKind::Variable: {
            const Variable* variable = m_symbols.find(node.text);
            if (!variable || variable->type != IecType::Bool)
                return "0"; // not reachable for a usable condition
            reads.insert(boolName(*variable));
            return boolName(*variable);
        }
        case NodeKind::BoolLiteral: return equalsIgnoreCase(node.text, "TRUE") ? "1" : "0";
        case NodeKind::Unary:
            if (node.unaryOp == cond::UnaryOp::Not)
                return "!" + translate(expression, node.operand, tokens, reads);
            return "0";
        case NodeKind::Binary: break;
        default: return "0";
        }
        auto both = [&](const char* op) {
            return "(" + translate(expression, node.left, tokens, reads) + " " + op + " "
                + translate(expression, node.right, tokens, reads) + ")";
        };
        switch (node.binaryOp) {
        case BinaryOp::And: return both("&&");
        case BinaryOp::Or: return both("||");
        case BinaryOp::Xor: return both("!=");
        default: break;
        }
        if (!isComparison(node.binaryOp))
            return "0";
        if (isBoolean(expression, node.left))
            return both(node.binaryOp == BinaryOp::Equal ? "==" : "!=");
        if (!hasVariable(expression, index))
            return cond::isTrue(constantValue(expression, index)) ? "1" : "0";
        if (auto comparison = variableComparison(expression, index, m_symbols)) {
            const NumericInput& input = m_numerics[m_numericIndex.at(comparison->variable)];
            reads.insert(input.name);
            return regionTest(input, *comparison);
        }
        const std::string name = atomName(m_atomIndex.at(atomText(expression, index)));
        reads.insert(name);
        return name;
    }

private:
    bool isBoolean(const cond::Expression& expression, int index) const
    {
        return cond::valueKind(expression, index, m_symbols) == cond::ValueKind::Bool;
    }

    std::string atomText(const cond::Expression& expression, int index) const
    {
        cond::PrintOptions options;
        options.variableName = [this](const cond::Node& variable) {
            const Variable* declared = m_symbols.find(variable.text);
            return declared ? declared->name : variable.text;
        };
        return cond::print(rootedAt(expression, index), options);
    }

    int rankOf(const std::string& name) const
    {
        auto found = m_rank.find(name);
        return found == m_rank.end() ? std::numeric_limits<int>::max() : found->second;
    }

    // The comparison as a test of the region index, from its truth at each
    // region's value.
    static std::string regionTest(const NumericInput& input, const VariableComparison& comparison)
    {
        std::vector<bool> truth;
        for (const cond::Value& value : input.values)
            truth.push_back(compareValues(comparison.op, value, comparison.constant));
        const auto count = static_cast<std::size_t>(std::count(truth.begin(), truth.end(), true));
        const std::string& v = input.name;
        if (count == truth.size())
            return "1";
        if (count == 0)
            return "0";
        auto firstIndex = [&](bool wanted) {
            return std::to_string(std::find(truth.begin(), truth.end(), wanted) - truth.begin());
        };
        const bool prefix = std::is_partitioned(truth.begin(), truth.end(), [](bool b) { return b; });
        const bool suffix = std::is_partitioned(truth.begin(), truth.end(), [](bool b) { return !b; });
        if (count == 1)
            return "(" + v + " == " + firstIndex(true) + ")";
        if (count + 1 == truth.size())
            return "(" + v + " != " + firstIndex(false) + ")";
        if (prefix)
            return "(" + v + " < " + firstIndex(false) + ")";
        if (suffix)
            return "(" + v + " >= " + firstIndex(true) + ")";
        std::string out;
        for (std::size_t i = 0; i < truth.size(); ++i) {
            if (truth[i])
                out += (out.empty() ? "(" : " || ") + v + " == " + std::to_string(i);
        }
        return out + ")";
    }

    const Model& m_model;
    SymbolTable m_symbols;
    std::set<const Variable*> m_usedBools;
    std::map<const Variable*, std::vector<cond::Value>> m_constants;
    std::vector<std::string> m_atoms;
    std::map<std::string, std::size_t> m_atomIndex;
    std::vector<const Variable*> m_bools;
    std::vector<NumericInput> m_numerics;
    std::map<const Variable*, std::size_t> m_numericIndex;
    std::map<std::string, int> m_rank;
};

// --- Writing ---------------------------------------------------------------------

std::string typeForCount(std::size_t values)
{
    return values <= 200 ? "byte" : values <= 30000 ? "short" : "int";
}

// One step's translated transitions.
struct StepPlan {
    const GemmaStep* step = nullptr;
    bool freeComplete = true;
    std::vector<std::string> conditions; // Promela, without the Complete gate
    std::set<std::string> conditionReads;
    std::set<std::string> scanReads;     // conditionReads and the token updates' variables
};

class Exporter {
public:
    Exporter(const Model& model, const PromelaOptions& options)
        : m_model(model), m_options(options), m_program(buildGemmaProgram(model)), m_inputs(model)
    {
    }

    PromelaModel run()
    {
        plan();
        writeHeader();
        writeDeclarations();
        writeProcess();
        PromelaModel result;
        result.text = m_out.take();
        result.markers = std::move(m_markers);
        return result;
    }

private:
    void plan();
    void writeHeader();
    void writeDeclarations();
    void writeProcess();
    void writeStep(const StepPlan& plan);
    void writeProbe(const StepPlan& plan);
    void writeTokenUpdates();
    void writeReset();
    void writeStart();
    void writeStartReading();
    void writeUntilReading();
    void writeListing();

    // The variables a configuration consists of, with the largest value each holds.
    struct StateVariable {
        std::string name;
        int max = 1;
    };
    std::vector<StateVariable> stateVariables() const;

    std::string gated(const StepPlan& plan, std::size_t t, const std::string& complete) const
    {
        const GemmaTransition& transition = plan.step->transitions[t];
        const std::string& condition = plan.conditions[t];
        return transition.waitsForComplete ? "(" + condition + " && " + complete + ")" : condition;
    }
    static std::string completeName(const GemmaStep& step) { return "cp_" + step.id; }
    void marker(PromelaMarkerKind kind, const std::string& step, const std::string& statement,
                const std::string& comment, std::string transition = {}, std::string other = {})
    {
        const int line = m_out.line(statement + " /* " + commentText(comment) + " */");
        PromelaMarker m;
        m.kind = kind;
        m.step = step;
        m.transition = std::move(transition);
        m.other = std::move(other);
        m.line = line;
        m_markers.push_back(std::move(m));
    }
    bool emergencyStopVisible() const { return m_program.step(kEmergencyStop) != nullptr; }

    const Model& m_model;
    const PromelaOptions& m_options;
    GemmaProgram m_program;
    Inputs m_inputs;
    std::vector<StepPlan> m_plans;
    std::size_t m_maxTransitions = 1;
    std::size_t m_maxFlags = 1;
    PromelaWriter m_out;
    std::vector<PromelaMarker> m_markers;
};

void Exporter::plan()
{
    for (const GemmaStep& step : m_program.steps) {
        for (const GemmaTransition& transition : step.transitions) {
            if (transition.conditionUsable)
                m_inputs.collect(transition.condition.expression, transition.condition.expression.root);
        }
    }
    m_inputs.finish();
    for (const GemmaStep& step : m_program.steps) {
        StepPlan plan;
        plan.step = &step;
        auto assumption = m_options.complete.find(step.id);
        plan.freeComplete = assumption == m_options.complete.end() || assumption->second == CompleteAssumption::Free;
        for (const GemmaTransition& transition : step.transitions) {
            if (!transition.conditionUsable) {
                plan.conditions.push_back("0");
                continue;
            }
            plan.conditions.push_back(m_inputs.translate(transition.condition.expression,
                                                         transition.condition.expression.root,
                                                         transition.substitutions, plan.conditionReads));
        }
        plan.scanReads = plan.conditionReads;
        // The token updates after the scan read the literals of the tokens of
        // the step that is active then: this one, or a target.
        auto addTokens = [&](const GemmaStep* owner) {
            if (!owner)
                return;
            for (const GemmaToken& token : owner->tokens) {
                if (const Variable* variable = m_inputs.symbols().find(token.variable))
                    plan.scanReads.insert(Inputs::boolName(*variable));
            }
        };
        addTokens(&step);
        for (const GemmaTransition& transition : step.transitions)
            addTokens(m_program.step(transition.targetId));
        const std::size_t n = step.transitions.size();
        m_maxTransitions = std::max(m_maxTransitions, n);
        m_maxFlags = std::max(m_maxFlags, 2 * n + 2 + n * n);
        m_plans.push_back(std::move(plan));
    }
}

void Exporter::writeHeader()
{
    const std::string run = std::string(kSpinGenerate) + " FILE && " + kSpinCompile + " && " + kSpinRun;
    for (const std::string& text : std::vector<std::string>{
             "/*",
             " * GEMMA layer of \"" + commentText(m_model.settings().name) + "\" as a Promela model for SPIN,",
             " * written by GG Studio (docs/verification.md, \"SPIN cross-check\").",
             " * One iteration of the do loop is one PLC scan of PROGRAM GEMMA (spec 6.6).",
             " * Inputs are chosen anew in every scan; a numeric variable compared with",
             " * constants takes one value per interval between them; other comparisons",
             " * are free booleans (atom_N).",
             " *",
             " * Run:  " + run,
             " * Then read pan's list \"unreached in proctype scan\". Every line that ends",
             " * with a marker comment holds one statement; the line is listed iff the",
             " * marker is never reached, i.e.:",
             " *   reach S        listed: step S is unreachable (GV101)",
             " *   fire T in S    listed: T never fires from S (GV102 when listed in every S)",
             " *   holds T in S   listed: the condition of T (AND Complete where it waits)",
             " *                  is never TRUE when S is active",
             " *   fails T in S   listed: ... never FALSE: always TRUE (GV103)",
             " *   overlap T U    listed: T never fires while U's condition holds (GV104)",
             " *   no fire in S   NOT listed: in some reachable situation of S no input",
             " *                  fires any transition in one scan (needed for GV106)",
             " *   no D1 from S   NOT listed: in some reachable situation of the F step S",
             " *                  no input leads to D1 in one scan (GV107)",
             " *",
             " * The search starts from reset. pan reads three environment variables:",
             " *   " + std::string(kSpinStartVariable) + "=\"gState=N gEntry=0|1 tk_...=0|1\"  starts from that",
             " *       configuration instead (variables not named keep their reset values);",
             " *   " + std::string(kSpinListVariable) + "=1  prints \"GG_CONFIG\" and the configuration, in that syntax,",
             " *       at the start of every scan explored: the reachable configurations;",
             " *   " + std::string(kSpinUntilVariable) + "=N  entering State N violates an assertion: the search stops.",
             " * From a reachable configuration C of step S, with GG_START=C and GG_UNTIL",
             " * set to the initial step's State: no assertion violated = the initial",
             " * step never comes back from C (GV105 for S); and then every \"fire T in S\"",
             " * listed = S is never left from C (GV106 for S).",
             " */",
         })
        m_out.line(text);
    m_out.line("");
}

void Exporter::writeDeclarations()
{
    m_out.line("/* The state of PROGRAM GEMMA between scans. State numbers: the spec's. */");
    m_out.line("byte " + std::string(kState) + " = " + std::to_string(m_program.initialNumber) + "; /* State, initial step "
               + m_program.initialStepId + " */");
    m_out.line("bool " + std::string(kEntry) + " = 1; /* Entry */");
    for (const GemmaStep& step : m_program.steps) {
        for (const GemmaToken& token : step.tokens)
            m_out.line("bool tk_" + token.name + " = 0; /* token of " + commentText(token.transitionId) + " */");
    }
    m_out.line("");
    m_out.line("/* Inputs and Complete: chosen at every scan, reset to 0 after it (not part of the state). */");
    for (const StepPlan& plan : m_plans) {
        if (!plan.step->hasNestedBehaviour())
            continue;
        m_out.line("bool " + completeName(*plan.step) + "; /* " + plan.step->id + ".Complete, "
                   + (plan.freeComplete ? "free" : "TRUE (automatic)") + " */");
    }
    for (const Variable* variable : m_inputs.bools())
        m_out.line("byte " + Inputs::boolName(*variable) + "; /* " + variable->name + " : BOOL */");
    for (const NumericInput& input : m_inputs.numerics()) {
        std::string regions;
        for (std::size_t i = 0; i < input.regions.size(); ++i)
            regions += (i ? ", " : "") + std::to_string(i) + " = " + input.regions[i];
        m_out.line(typeForCount(input.values.size()) + " " + input.name + "; /* " + input.variable->name + " : "
                   + std::string(iecTypeName(input.variable->type)) + ": " + commentText(regions) + " */");
    }
    for (std::size_t i = 0; i < m_inputs.atoms().size(); ++i)
        m_out.line("byte " + Inputs::atomName(i) + "; /* " + commentText(m_inputs.atoms()[i]) + " (free) */");
    m_out.line("");
    m_out.line("/* Bookkeeping of the markers and probes, reset after every scan. */");
    m_out.line("byte " + std::string(kMark) + ";");
    m_out.line("byte " + std::string(kFrom) + "; /* State at the start of the scan */");
    m_out.line("byte " + std::string(kUntil) + " = " + std::to_string(kNoUntil) + "; /* " + kSpinUntilVariable
               + ": entering this State ends the search (" + std::to_string(kNoUntil) + ": never) */");
    if (m_options.probes) {
        m_out.line("byte " + std::string(kProbeComplete) + "; /* Complete while probing */");
        m_out.line("byte pg[" + std::to_string(m_maxTransitions) + "]; /* each transition's gated condition */");
        m_out.line("byte pk; /* the transition that fires while probing */");
        m_out.line("bool pflag[" + std::to_string(m_maxFlags) + "]; /* what some input does */");
        m_out.line("short pi; /* a loop counter */");
    }
    m_out.line("");
}

std::vector<Exporter::StateVariable> Exporter::stateVariables() const
{
    // Complete is not among them: the FB rewrites it before the transitions read it.
    std::vector<StateVariable> out{{kState, 255}, {kEntry, 1}};
    for (const GemmaStep& step : m_program.steps) {
        for (const GemmaToken& token : step.tokens)
            out.push_back({"tk_" + token.name, 1});
    }
    return out;
}

// GG_START and GG_UNTIL, read once before the first scan: one compiled pan can then
// explore from any configuration (docs/verification.md).
void Exporter::writeStart()
{
    m_out.line("c_code {");
    m_out.in();
    writeStartReading();
    writeUntilReading();
    m_out.out();
    m_out.line("};");
}

void Exporter::writeStartReading()
{
    std::size_t longest = 63;
    for (const StateVariable& variable : stateVariables())
        longest = std::max(longest, variable.name.size());
    const std::string width = std::to_string(longest);
    m_out.line("/* GG_START=\"NAME=VALUE ...\": start from this configuration instead of the reset one */");
    m_out.line("const char *ggText = getenv(\"" + std::string(kSpinStartVariable) + "\");");
    m_out.line("char ggName[" + std::to_string(longest + 1) + "];");
    m_out.line("int ggValue = 0, ggUsed = 0;");
    m_out.line("while (ggText && sscanf(ggText, \" %" + width + "[A-Za-z0-9_] = %d%n\", ggName, &ggValue, &ggUsed) == 2) {");
    m_out.in();
    m_out.line("ggText += ggUsed;");
    std::string keyword = "if";
    for (const StateVariable& variable : stateVariables()) {
        m_out.line(keyword + " (strcmp(ggName, \"" + variable.name + "\") == 0 && ggValue >= 0 && ggValue <= "
                   + std::to_string(variable.max) + ") now." + variable.name + " = ggValue;");
        keyword = "else if";
    }
    m_out.line("else {");
    m_out.in();
    m_out.line("printf(\"GG_START: %s=%d: no such state variable, or a value it cannot hold\\n\", ggName, ggValue);");
    m_out.line("exit(2);");
    m_out.out();
    m_out.line("}");
    m_out.out();
    m_out.line("}");
    m_out.line("while (ggText && *ggText == ' ') ggText++;");
    m_out.line("if (ggText && *ggText) {");
    m_out.in();
    m_out.line("printf(\"GG_START: cannot read '%s': expected NAME=VALUE separated by spaces\\n\", ggText);");
    m_out.line("exit(2);");
    m_out.out();
    m_out.line("}");
}

// After writeStartReading, in the same block: its variables are reused.
void Exporter::writeUntilReading()
{
    m_out.line("/* " + std::string(kSpinUntilVariable) + "=N: entering State N is an error, which ends the search */");
    m_out.line("ggText = getenv(\"" + std::string(kSpinUntilVariable) + "\");");
    m_out.line("if (ggText) {");
    m_out.in();
    m_out.line("if (sscanf(ggText, \" %d %n\", &ggValue, &ggUsed) != 1 || ggText[ggUsed] || ggValue < 0 || ggValue >= "
               + std::to_string(kNoUntil) + ") {");
    m_out.in();
    m_out.line("printf(\"" + std::string(kSpinUntilVariable) + ": cannot read '%s': expected a State number\\n\", ggText);");
    m_out.line("exit(2);");
    m_out.out();
    m_out.line("}");
    m_out.line("now." + std::string(kUntil) + " = ggValue;");
    m_out.out();
    m_out.line("}");
}

// GG_LIST: the configuration every explored scan starts in, in GG_START's syntax.
void Exporter::writeListing()
{
    m_out.line("c_code {");
    m_out.in();
    m_out.line("static int ggList = -1; /* GG_LIST set: print the configuration of every scan explored */");
    m_out.line("if (ggList < 0) ggList = getenv(\"" + std::string(kSpinListVariable) + "\") != 0;");
    m_out.line("if (ggList) {");
    m_out.in();
    m_out.line("printf(\"GG_CONFIG\");");
    for (const StateVariable& variable : stateVariables())
        m_out.line("printf(\" " + variable.name + "=%d\", (int) now." + variable.name + ");");
    m_out.line("printf(\"\\n\");");
    m_out.out();
    m_out.line("}");
    m_out.out();
    m_out.line("};");
}

void Exporter::writeProcess()
{
    m_out.line("active proctype scan()");
    m_out.line("{");
    m_out.in();
    writeStart();
    m_out.line("do");
    m_out.line(":: atomic {");
    m_out.in();
    writeListing();
    m_out.line(std::string(kFrom) + " = " + kState + ";");
    m_out.line("if");
    for (const StepPlan& plan : m_plans)
        writeStep(plan);
    m_out.line(":: else ->");
    m_out.in();
    m_out.line("skip; /* State names no visible step (hidden initial step): the PLC does nothing */");
    m_out.out();
    m_out.line("fi;");
    m_out.out();
    m_out.line("scanned:");
    m_out.in();
    m_out.line(std::string(kMark) + " = 0;");
    m_out.line("assert(" + std::string(kUntil) + " == " + std::to_string(kNoUntil) + " || " + kState + " != " + kUntil
               + " || " + kFrom + " == " + kUntil + "); /* " + kSpinUntilVariable + " */");
    writeTokenUpdates();
    writeReset();
    m_out.out();
    m_out.line("}");
    m_out.line("od");
    m_out.out();
    m_out.line("}");
}

void Exporter::writeStep(const StepPlan& plan)
{
    const GemmaStep& step = *plan.step;
    m_out.line(":: " + std::string(kState) + " == " + std::to_string(step.number) + " -> /* " + step.id + " "
               + commentText(step.name) + ", " + stepKind(step.type) + " */");
    m_out.in();
    marker(PromelaMarkerKind::Reach, step.id, std::string(kMark) + " = 1;", "reach " + step.id);
    if (step.hasNestedBehaviour()) {
        m_out.line("if");
        m_out.line(":: " + std::string(kEntry) + " -> /* entry block: FB initialised, tokens cleared */");
        m_out.in();
        m_out.line(std::string(kEntry) + " = 0;");
        for (const GemmaToken& token : step.tokens)
            m_out.line("tk_" + token.name + " = 0;");
        m_out.out();
        m_out.line(":: else -> skip;");
        m_out.line("fi;");
    }
    if (m_options.probes)
        writeProbe(plan);
    if (step.hasNestedBehaviour()) {
        const std::string complete = completeName(step);
        if (plan.freeComplete)
            m_out.line("if :: " + complete + " = 1 :: " + complete + " = 0 fi; /* the FB runs: Complete, free */");
        else
            m_out.line(complete + " = 1; /* the FB runs: the skeleton completes at once */");
    }
    for (const std::string& input : m_inputs.ordered(plan.scanReads)) {
        if (m_inputs.isNumeric(input))
            m_out.line("select (" + input + " : 0 .. " + std::to_string(m_inputs.valueCount(input) - 1) + ");");
        else
            m_out.line("if :: " + input + " = 1 :: " + input + " = 0 fi;");
    }
    for (std::size_t t = 0; t < step.transitions.size(); ++t) {
        const GemmaTransition& transition = step.transitions[t];
        m_out.line("/* " + transition.id + (transition.family ? " (family)" : "") + ": "
                   + commentText(transition.conditionText) + (transition.conditionUsable ? "" : " (unusable: FALSE)")
                   + (transition.waitsForComplete ? ", waits for Complete" : "") + " */");
        m_out.line("if");
        m_out.line(":: " + gated(plan, t, completeName(step)) + " ->");
        m_out.in();
        marker(PromelaMarkerKind::Fire, step.id,
               std::string(kState) + " = " + std::to_string(transition.targetNumber) + "; " + kEntry
                   + " = 1; goto scanned;",
               "fire " + transition.id + " in " + step.id, transition.id);
        m_out.out();
        m_out.line(":: else -> skip;");
        m_out.line("fi;");
    }
    m_out.out();
}

// Every input (and Complete, when free) in the configuration the scan starts
// in, deterministically: what some input can do, as flags, then one marker
// line per flag.
void Exporter::writeProbe(const StepPlan& plan)
{
    const GemmaStep& step = *plan.step;
    const std::size_t n = step.transitions.size();
    const bool usesComplete = std::any_of(step.transitions.begin(), step.transitions.end(),
                                          [](const GemmaTransition& t) { return t.waitsForComplete; });
    const std::vector<std::string> loops = m_inputs.ordered(plan.conditionReads);
    const bool isF = !step.id.empty() && step.id[0] == 'F';
    auto holdsFlag = [](std::size_t t) { return t; };
    auto failsFlag = [n](std::size_t t) { return n + t; };
    const std::size_t anyFireFlag = 2 * n;
    const std::size_t toStopFlag = 2 * n + 1;
    auto overlapFlag = [n](std::size_t i, std::size_t j) { return 2 * n + 2 + i * n + j; };
    auto flag = [](std::size_t index) { return "pflag[" + std::to_string(index) + "]"; };
    auto setIf = [&](const std::string& test, std::size_t index) {
        m_out.line("if :: " + test + " -> " + flag(index) + " = 1 :: else -> skip fi;");
    };

    m_out.line("d_step { /* probe: every input of this scan */");
    m_out.in();
    int depth = 0;
    for (const std::string& input : loops) {
        m_out.line("for (" + input + " : 0 .. " + std::to_string(m_inputs.valueCount(input) - 1) + ") {");
        m_out.in();
        ++depth;
    }
    if (usesComplete && plan.freeComplete) {
        m_out.line("for (" + std::string(kProbeComplete) + " : 0 .. 1) {");
        m_out.in();
        ++depth;
    } else if (usesComplete) {
        m_out.line(std::string(kProbeComplete) + " = 1;");
    }
    for (std::size_t t = 0; t < n; ++t)
        m_out.line("pg[" + std::to_string(t) + "] = " + gated(plan, t, kProbeComplete) + ";");
    m_out.line("pk = " + std::to_string(n) + ";");
    for (std::size_t t = n; t-- > 0;)
        m_out.line("if :: pg[" + std::to_string(t) + "] -> pk = " + std::to_string(t) + " :: else -> skip fi;");
    for (std::size_t t = 0; t < n; ++t) {
        setIf("pg[" + std::to_string(t) + "]", holdsFlag(t));
        setIf("!pg[" + std::to_string(t) + "]", failsFlag(t));
    }
    setIf("pk < " + std::to_string(n), anyFireFlag);
    std::string toStop;
    for (std::size_t t = 0; t < n; ++t) {
        if (step.transitions[t].targetId == kEmergencyStop)
            toStop += (toStop.empty() ? "" : " || ") + std::string("pk == ") + std::to_string(t);
    }
    if (!toStop.empty())
        setIf(toStop, toStopFlag);
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j)
            setIf("pk == " + std::to_string(i) + " && pg[" + std::to_string(j) + "]", overlapFlag(i, j));
    }
    for (; depth > 0; --depth) {
        m_out.out();
        m_out.line("}");
    }
    std::string reset;
    for (const std::string& input : loops)
        reset += input + " = 0; ";
    m_out.line(reset + kProbeComplete + " = 0; pk = 0;");
    m_out.line("for (pi : 0 .. " + std::to_string(m_maxTransitions - 1) + ") { pg[pi] = 0 }; pi = 0;");
    m_out.out();
    m_out.line("};");

    auto markIf = [&](const std::string& test, PromelaMarkerKind kind, const std::string& comment,
                      const std::string& transition = {}, const std::string& other = {}) {
        m_out.line("if");
        m_out.line(":: " + test + " ->");
        m_out.in();
        marker(kind, step.id, std::string(kMark) + " = 1;", comment, transition, other);
        m_out.out();
        m_out.line(":: else -> skip;");
        m_out.line("fi;");
    };
    for (std::size_t t = 0; t < n; ++t) {
        const std::string& id = step.transitions[t].id;
        markIf(flag(holdsFlag(t)), PromelaMarkerKind::Holds, "holds " + id + " in " + step.id, id);
        markIf(flag(failsFlag(t)), PromelaMarkerKind::Fails, "fails " + id + " in " + step.id, id);
    }
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            const std::string& first = step.transitions[i].id;
            const std::string& second = step.transitions[j].id;
            markIf(flag(overlapFlag(i, j)), PromelaMarkerKind::Overlap, "overlap " + first + " " + second, first,
                   second);
        }
    }
    markIf("!" + flag(anyFireFlag), PromelaMarkerKind::NoFire, "no fire in " + step.id);
    if (isF && emergencyStopVisible())
        markIf("!" + flag(toStopFlag), PromelaMarkerKind::NoEmergencyStop, "no D1 from " + step.id);
}

void Exporter::writeTokenUpdates()
{
    bool any = false;
    for (const GemmaStep& step : m_program.steps) {
        for (const GemmaToken& token : step.tokens) {
            const Variable* variable = m_inputs.symbols().find(token.variable);
            if (!variable)
                continue;
            if (!any)
                m_out.line("/* token updates after END_CASE, with the new State */");
            any = true;
            const std::string literal = (token.polarity == TokenPolarity::NormallyClosed ? "!" : "")
                + Inputs::boolName(*variable);
            m_out.line("if :: " + std::string(kState) + " == " + std::to_string(step.number) + " && " + literal
                       + " -> tk_" + token.name + " = 1 :: else -> skip fi;");
        }
    }
}

void Exporter::writeReset()
{
    std::string reset = "d_step { " + std::string(kFrom) + " = 0; ";
    for (const Variable* variable : m_inputs.bools())
        reset += Inputs::boolName(*variable) + " = 0; ";
    for (const NumericInput& input : m_inputs.numerics())
        reset += input.name + " = 0; ";
    for (std::size_t i = 0; i < m_inputs.atoms().size(); ++i)
        reset += Inputs::atomName(i) + " = 0; ";
    for (const StepPlan& plan : m_plans) {
        if (plan.step->hasNestedBehaviour())
            reset += completeName(*plan.step) + " = 0; ";
    }
    if (m_options.probes)
        reset += "for (pi : 0 .. " + std::to_string(m_maxFlags - 1) + ") { pflag[pi] = 0 }; pi = 0; ";
    m_out.line("/* the inputs and Complete are forgotten: the next scan chooses them anew */");
    m_out.line(reset + "}");
}

long long numberAfter(std::string_view text, std::string_view label)
{
    const auto at = text.find(label);
    if (at == std::string_view::npos)
        return -1;
    std::size_t i = at + label.size();
    while (i < text.size() && text[i] == ' ')
        ++i;
    long long value = 0;
    bool digits = false;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') {
        value = value * 10 + (text[i] - '0');
        digits = true;
        ++i;
    }
    return digits ? value : -1;
}

// The number that starts the line `label` ends ("  128.730\ttotal actual
// memory usage"), -1 when there is none.
double numberBeforeOnLine(std::string_view text, std::string_view label)
{
    const auto at = text.find(label);
    if (at == std::string_view::npos)
        return -1;
    const auto newline = text.rfind('\n', at);
    const std::size_t begin = newline == std::string_view::npos ? 0 : newline + 1;
    const std::string line(text.substr(begin, at - begin));
    char* end = nullptr;
    const double value = std::strtod(line.c_str(), &end);
    return end != line.c_str() && value >= 0 ? value : -1;
}

// pan's "pan:1: assertion violated ..." line names GG_UNTIL's variable.
bool untilAssertion(std::string_view panOutput)
{
    const auto at = panOutput.find("pan:1: assertion violated");
    if (at == std::string_view::npos)
        return false;
    const auto end = panOutput.find('\n', at);
    return panOutput.substr(at, end == std::string_view::npos ? end : end - at).find(kUntil) != std::string_view::npos;
}

} // namespace

PromelaModel buildPromela(const Model& model, const PromelaOptions& options)
{
    return Exporter(model, options).run();
}

std::string exportPromela(const Model& model, const PromelaOptions& options)
{
    return buildPromela(model, options).text;
}

bool SpinReport::reached(const PromelaMarker& marker) const
{
    return complete && std::find(unreachedLines.begin(), unreachedLines.end(), marker.line) == unreachedLines.end();
}

std::vector<SpinConfiguration> readSpinConfigurations(std::string_view panOutput)
{
    constexpr std::string_view prefix = "GG_CONFIG ";
    std::vector<SpinConfiguration> out;
    std::set<std::string> seen;
    std::istringstream lines{std::string(panOutput)};
    std::string line;
    while (std::getline(lines, line)) {
        if (line.rfind(prefix, 0) != 0)
            continue;
        std::string text = line.substr(prefix.size());
        if (!seen.insert(text).second)
            continue;
        const long long state = numberAfter(text, std::string(kState) + "=");
        out.push_back(SpinConfiguration{std::move(text), static_cast<int>(state)});
    }
    return out;
}

SpinReport readSpinReport(std::string_view panOutput)
{
    SpinReport report;
    std::istringstream lines{std::string(panOutput)};
    std::string line;
    bool inScan = false;
    bool sawScanSection = false;
    while (std::getline(lines, line)) {
        if (line.rfind("unreached in ", 0) == 0) {
            inScan = line == "unreached in proctype scan";
            sawScanSection = sawScanSection || inScan;
            continue;
        }
        if (!inScan)
            continue;
        // "\tmodel.pml:42, state 17, \"mark = 1\"" or "\t(3 of 120 states)"
        const auto state = line.find(", state ");
        const auto colon = line.rfind(':', state);
        if (state == std::string::npos || colon == std::string::npos) {
            inScan = line.find(" states)") == std::string::npos && !line.empty() && line[0] == '\t';
            continue;
        }
        const long long number = numberAfter(std::string_view(line).substr(colon), ":");
        if (number > 0)
            report.unreachedLines.push_back(static_cast<int>(number));
    }
    const auto stored = panOutput.find(" states, stored");
    if (stored != std::string_view::npos) {
        std::size_t begin = panOutput.rfind('\n', stored);
        begin = begin == std::string_view::npos ? 0 : begin + 1;
        report.statesStored = numberAfter(panOutput.substr(begin, stored - begin + 1), "");
    }
    report.depthReached = numberAfter(panOutput, "depth reached");
    report.totalMemoryMb = numberBeforeOnLine(panOutput, "total actual memory usage");
    report.stateMemoryMb = numberBeforeOnLine(panOutput, "actual memory usage for states");
    const long long errors = numberAfter(panOutput, "errors:");
    if (panOutput.find("max search depth too small") != std::string_view::npos)
        report.problem = "pan's search depth limit (-m) cut the search short";
    else if (panOutput.find("out of memory") != std::string_view::npos
             || panOutput.find("reached -DMEMLIM bound") != std::string_view::npos)
        report.problem = "pan ran out of memory before the search was complete";
    else if (errors < 0)
        report.problem = "pan's output has no \"errors:\" line: the search did not run";
    else if (errors == 1 && untilAssertion(panOutput)) {
        report.untilReached = true;
        report.problem = std::string("pan stopped where ") + kSpinUntilVariable + " says: that State was entered";
    } else if (errors > 0)
        report.problem = "pan reported " + std::to_string(errors) + " error(s)";
    else if (!sawScanSection)
        report.problem = "pan's output has no \"unreached in proctype scan\" report";
    report.complete = report.problem.empty();
    return report;
}

std::string promelaComment(std::string_view text)
{
    std::string out;
    for (char c : escapeComment(std::string(text))) {
        out += c;
        const std::size_t n = out.size();
        if (n >= 2 && ((out[n - 2] == '*' && out[n - 1] == '/') || (out[n - 2] == '/' && out[n - 1] == '*')))
            out.insert(n - 1, " ");
    }
    return out;
}

} // namespace core
