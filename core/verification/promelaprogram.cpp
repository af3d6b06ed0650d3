#include "core/verification/promelaprogram.h"

#include "core/verification/promelamachine.h"

#include "core/machine/fault.h"

#include "core/templates/gemma/gemmaprogram.h"
#include "core/condition/conditionanalysis.h"
#include "core/condition/conditionevaluator.h"
#include "core/condition/symboltable.h"
#include "core/model/model.h"
#include "core/verification/comparisonshape.h"
#include "core/verification/promelawriter.h"
#include "core/verification/property.h"
#include "core/verification/satisfiability.h"
#include "core/verification/tonscans.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <set>

namespace core {

namespace {

using cond::BinaryOp;
using cond::NodeKind;

std::string upperText(std::string_view text)
{
    std::string out(text);
    for (char& c : out)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

std::string commentSafe(std::string_view text)
{
    return promelaComment(text);
}

bool isComparisonOp(BinaryOp op)
{
    return op == BinaryOp::Less || op == BinaryOp::Greater || op == BinaryOp::LessEqual
        || op == BinaryOp::GreaterEqual || op == BinaryOp::Equal || op == BinaryOp::NotEqual;
}

// `A < B` and `A >= B` are one free BOOL and its negation: the comparison in
// a form its equivalents share (a < b, or a = b with the operands sorted).
std::string canonicalText(const cond::Expression& expression, int index, bool& negated)
{
    const cond::Node& node = expression.at(index);
    std::string left = cond::print(cond::Expression{expression.nodes, node.left});
    std::string right = cond::print(cond::Expression{expression.nodes, node.right});
    negated = node.binaryOp == BinaryOp::LessEqual || node.binaryOp == BinaryOp::GreaterEqual
        || node.binaryOp == BinaryOp::NotEqual;
    if (node.binaryOp == BinaryOp::Equal || node.binaryOp == BinaryOp::NotEqual) {
        if (right < left)
            std::swap(left, right);
        return "(" + left + ") = (" + right + ")";
    }
    if (node.binaryOp == BinaryOp::Greater || node.binaryOp == BinaryOp::LessEqual)
        std::swap(left, right);
    return "(" + left + ") < (" + right + ")";
}

sat::Relation relationOf(BinaryOp op)
{
    switch (op) {
    case BinaryOp::Less: return sat::Relation::Less;
    case BinaryOp::LessEqual: return sat::Relation::LessEqual;
    case BinaryOp::Greater: return sat::Relation::Greater;
    case BinaryOp::GreaterEqual: return sat::Relation::GreaterEqual;
    case BinaryOp::Equal: return sat::Relation::Equal;
    default: return sat::Relation::NotEqual;
    }
}

BinaryOp mirroredOp(BinaryOp op)
{
    switch (op) {
    case BinaryOp::Less: return BinaryOp::Greater;
    case BinaryOp::Greater: return BinaryOp::Less;
    case BinaryOp::LessEqual: return BinaryOp::GreaterEqual;
    case BinaryOp::GreaterEqual: return BinaryOp::LessEqual;
    default: return op;
    }
}

// What a declared variable is to the program.
enum class VariableRole {
    Input,    // BOOL input: chosen when read
    Sensor,   // closed loop: a BOOL input the machine drives, read from its state
    Stored,   // BOOL written by the program: part of the state
    Constant, // BOOL nothing writes: its default
    Number,   // numeric input or numeric variable an action writes: one representative when read
    Fixed,    // numeric variable nothing writes: its default
};

struct VariableInfo {
    const Variable* declared = nullptr;
    VariableRole role = VariableRole::Constant;
    cond::Value initial;
    std::vector<cond::Value> representatives;
    std::vector<sat::Atom> comparisons; // with constants, for the representatives
    bool edge = false;                  // read under an edge: p_<name>
    std::string sensor;                 // Sensor: the expression of the machine's state it reads
    bool readsAsBool() const
    {
        return role == VariableRole::Input || role == VariableRole::Sensor || role == VariableRole::Stored
            || role == VariableRole::Constant;
    }
};

// What an expression is evaluated in.
struct Context {
    const GemmaStep* step = nullptr;          // the GEMMA step whose GRAFCET runs (nullptr: GEMMA layer or property)
    const std::map<int, int>* timerOfNode = nullptr;
    const std::map<int, std::string>* tokens = nullptr; // GEMMA conditions: literal node -> token variable
    bool edges = false;                       // edges read `gFirst` (a receptivity); otherwise FALSE
    bool property = false;                    // `in S`, `S.Xn`
};

class ProgramPromela {
public:
    ProgramPromela(const Model& model, const ProgramPromelaOptions& options)
        : m_model(model), m_options(options), m_program(buildGemmaProgram(model)), m_symbols(model.variables())
    {
    }

    PromelaModel run();

private:
    // --- planning ---
    void classifyVariables();
    void wireMachine();
    void collectComparisons(const cond::Expression& expression);
    void collectAll();
    void computeRepresentatives();
    VariableInfo* variable(std::string_view name);
    const VariableInfo* variable(std::string_view name) const;
    int opaqueIndex(const std::string& text);
    bool usableAction(const NestedAction& action) const;

    // --- names ---
    static std::string xName(const GemmaStep& s, int number) { return s.id + "_X" + std::to_string(number); }
    static std::string outName(const GemmaStep& s, const std::string& v) { return s.id + "_o_" + v; }
    static std::string completeName(const GemmaStep& s) { return s.id + "_C"; }
    static std::string timerName(const GemmaStep& s, std::size_t k) { return s.id + "_T" + std::to_string(k); }
    static std::string timerChosenName(const GemmaStep& s, std::size_t k) { return s.id + "_D" + std::to_string(k); }
    std::string stateOf(const GemmaStep& s) const { return std::to_string(indexOf(s) + 1); }
    int indexOf(const GemmaStep& s) const { return static_cast<int>(&s - m_program.steps.data()); }
    static std::string ev(int depth) { return "ev[" + std::to_string(depth) + "]"; }

    // --- writing ---
    void writeHeader();
    void writeDeclarations();
    void writeReaders();
    void writeProcess();
    void writeStep(const GemmaStep& step);
    void writeGated(const GemmaTransition& t);
    void writeLaterConditions(const GemmaStep& step, std::size_t fired);
    void writeInitialization(const GemmaStep& step);
    void writeEvolvingCall(const GemmaStep& step);
    void writeCountedTimerRead(const GemmaStep& step, std::size_t k, const NestedTimer& ton, const std::string& result,
                               const std::string& text);
    void writeEvolution(const GemmaStep& step);
    void writeOutputs(const GemmaStep& step);
    void writeStored(const GemmaStep& step, int stepNumber, const std::vector<NestedAction>& actions, bool reportRaces);
    void writeNoteActive(const GemmaStep& step);
    void writeEndOfScan();
    void writeReset();
    void eval(const Context& context, const cond::Expression& expression, int node, int depth);
    void evalRoot(const Context& context, const cond::Expression& expression, int depth);
    void evalLeafComparison(const cond::Expression& expression, int node, int depth);
    std::string readBool(const VariableInfo& info);
    void marker(PromelaMarker marker, const std::string& comment);
    void markIf(const std::string& test, PromelaMarker marker, const std::string& comment);

    const Model& m_model;
    const ProgramPromelaOptions& m_options;
    GemmaProgram m_program;
    SymbolTable m_symbols;
    std::vector<VariableInfo> m_variables;  // declaration order
    std::map<std::string, std::size_t> m_variableIndex; // upper name
    std::vector<std::string> m_opaque;      // canonical texts
    std::vector<ParsedProperty> m_properties;
    std::vector<bool> m_propertyUsable;
    std::vector<std::string> m_d1Outputs;   // BOOL outputs the program writes, declared spelling
    int m_d1 = -1;
    int m_cycleMs = 20;
    PromelaMachine m_machine; // closed loop; empty otherwise
    // Single faults: flt 1..jams are the jams (component indices), then
    // three per sensor (stuck TRUE, stuck FALSE, flicker), its upper name
    // and the machine's expression of it.
    bool m_faults = false;
    std::vector<std::size_t> m_jams;
    std::vector<std::pair<std::string, std::string>> m_faultSensors;
    std::int64_t m_faultScanLimit = 0;
    int faultCode(std::size_t sensor, int kind) const { return static_cast<int>(m_jams.size() + 3 * sensor) + kind + 1; }
    void writeFaultChoice();
    int m_maxDepth = 1;
    std::size_t m_maxTransitions = 1, m_maxSteps = 1, m_maxOutputs = 1;
    int m_maxEvolutions = 1; // gEvolutions counts up to it: a byte holds only 255
    std::vector<std::string> m_storedWritten; // Stored variables some stored action writes
    PromelaWriter m_out;
    std::vector<PromelaMarker> m_markers;
};

// --- planning -------------------------------------------------------------------------

VariableInfo* ProgramPromela::variable(std::string_view name)
{
    auto it = m_variableIndex.find(upperText(name));
    return it == m_variableIndex.end() ? nullptr : &m_variables[it->second];
}

const VariableInfo* ProgramPromela::variable(std::string_view name) const
{
    auto it = m_variableIndex.find(upperText(name));
    return it == m_variableIndex.end() ? nullptr : &m_variables[it->second];
}

int ProgramPromela::opaqueIndex(const std::string& text)
{
    auto it = std::find(m_opaque.begin(), m_opaque.end(), text);
    if (it != m_opaque.end())
        return static_cast<int>(it - m_opaque.begin());
    m_opaque.push_back(text);
    return static_cast<int>(m_opaque.size()) - 1;
}

// An action the program runs on the state: usable, writing Complete or a
// stored BOOL (numeric targets are abstracted, inputs stay free).
bool ProgramPromela::usableAction(const NestedAction& action) const
{
    if (!action.usable)
        return false;
    if (action.targetIsComplete)
        return true;
    const VariableInfo* target = variable(action.target);
    return target && target->role == VariableRole::Stored;
}

void ProgramPromela::classifyVariables()
{
    std::set<std::string> written;
    for (const GemmaStep& step : m_program.steps) {
        if (!step.nested)
            continue;
        for (const std::string& target : step.nested->storedTargets)
            written.insert(upperText(target));
        for (const ContinuousOutput& output : step.nested->outputs) {
            if (!output.isComplete)
                written.insert(upperText(output.variable));
        }
    }
    for (const Variable& declared : m_model.variables()) {
        VariableInfo info;
        info.declared = &declared;
        std::optional<cond::Value> value = cond::parseValue(declared.type, declared.defaultValue);
        if (!value)
            value = cond::parseValue(declared.type, "");
        info.initial = value.value_or(cond::Value{false});
        const bool isWritten = written.count(upperText(declared.name)) > 0;
        const bool input = declared.kind == VariableKind::Input;
        if (declared.type == IecType::Bool)
            info.role = input ? VariableRole::Input : isWritten ? VariableRole::Stored : VariableRole::Constant;
        else
            info.role = input || isWritten ? VariableRole::Number : VariableRole::Fixed;
        if (declared.kind == VariableKind::Output && declared.type == IecType::Bool && isWritten)
            m_d1Outputs.push_back(declared.name);
        m_variableIndex.emplace(upperText(declared.name), m_variables.size());
        m_variables.push_back(std::move(info));
    }
    for (const std::string& name : m_program.edgeVariables) {
        if (VariableInfo* info = variable(name))
            info->edge = true;
    }
}

// Closed loop: the inputs the machine's sensors drive read its state, and
// the machine runs one cycle after each scan (core/verification/promelamachine.h).
void ProgramPromela::wireMachine()
{
    const auto wired = [&](std::string_view name, machine::SignalDirection direction) {
        const VariableInfo* info = variable(name);
        const VariableKind wanted
            = direction == machine::SignalDirection::Actuator ? VariableKind::Output : VariableKind::Input;
        return info && info->declared->type == IecType::Bool && info->declared->kind == wanted;
    };
    const auto outputValue = [&](std::string_view name) -> std::string {
        const VariableInfo* info = variable(name);
        if (info->role == VariableRole::Stored)
            return "v_" + info->declared->name;
        return cond::isTrue(info->initial) ? "1" : "0";
    };
    m_faults = m_options.singleFaults;
    if (m_faults) {
        for (std::size_t k = 0; k < m_options.machine->components.size(); ++k) {
            if (machine::canJam(m_options.machine->components[k].kind))
                m_jams.push_back(k);
        }
    }
    const auto jammed = [&](std::size_t k) -> std::string {
        const auto at = std::find(m_jams.begin(), m_jams.end(), k);
        return at == m_jams.end() ? std::string() : "flt == " + std::to_string(at - m_jams.begin() + 1);
    };
    m_machine = buildPromelaMachine(*m_options.machine, m_cycleMs, m_options.exactTime, wired, outputValue, jammed);
    for (const auto& [upper, expression] : m_machine.sensors) {
        if (VariableInfo* info = variable(upper)) {
            info->role = VariableRole::Sensor;
            info->sensor = expression;
            if (m_faults) {
                const std::size_t s = m_faultSensors.size();
                m_faultSensors.emplace_back(upper, expression);
                info->sensor = "(flt == " + std::to_string(faultCode(s, 0)) + " -> 1 : (flt == "
                    + std::to_string(faultCode(s, 1)) + " -> 0 : (flt == " + std::to_string(faultCode(s, 2))
                    + " -> flk : " + expression + ")))";
            }
        }
    }
    if (m_faults)
        m_machine.declarations.push_back("int flt = 0; bit flk = 0; int fc = 0; /* single faults: which (0 none), a "
                                         "flickering sensor's reading, scans since it began */");
}

void ProgramPromela::collectComparisons(const cond::Expression& expression)
{
    for (const cond::Node& node : expression.nodes) {
        if (node.kind != NodeKind::Binary || !isComparisonOp(node.binaryOp))
            continue;
        auto constant = [&](int n) -> std::optional<cond::Value> {
            bool reads = false;
            const cond::Value value = cond::evaluate(cond::Expression{expression.nodes, n}, [&](int) {
                reads = true;
                return cond::Value{false};
            });
            if (reads)
                return std::nullopt;
            return value;
        };
        auto record = [&](int variableNode, int otherNode, BinaryOp op) {
            const cond::Node& v = expression.at(variableNode);
            if (v.kind != NodeKind::Variable)
                return;
            VariableInfo* info = variable(v.text);
            if (!info || info->declared->type == IecType::Bool)
                return;
            if (std::optional<cond::Value> c = constant(otherNode)) {
                sat::Atom atom;
                atom.kind = sat::Atom::Kind::Comparison;
                atom.relation = relationOf(op);
                atom.constant = *c;
                info->comparisons.push_back(atom);
            }
        };
        record(node.left, node.right, node.binaryOp);
        record(node.right, node.left, mirroredOp(node.binaryOp));
    }
}

void ProgramPromela::collectAll()
{
    for (const GemmaStep& step : m_program.steps) {
        for (const GemmaTransition& t : step.transitions) {
            if (t.conditionUsable)
                collectComparisons(t.condition.expression);
        }
        if (!step.nested)
            continue;
        const NestedGrafcet& g = *step.nested;
        m_maxTransitions = std::max(m_maxTransitions, g.transitions.size());
        m_maxSteps = std::max(m_maxSteps, g.steps.size());
        m_maxOutputs = std::max(m_maxOutputs, g.outputs.size());
        m_maxEvolutions = std::max(m_maxEvolutions, g.maxEvolutions);
        for (const NestedTransition& t : g.transitions) {
            if (t.usable)
                collectComparisons(t.receptivity.expression);
        }
        for (const NestedStep& s : g.steps) {
            for (const auto* list : {&s.onActivation, &s.onDeactivation}) {
                for (const NestedAction& action : *list) {
                    if (usableAction(action) && action.parsed.action.form == cond::ActionForm::Assign)
                        collectComparisons(action.parsed.action.value);
                    if (usableAction(action) && !action.targetIsComplete
                        && std::find(m_storedWritten.begin(), m_storedWritten.end(), variable(action.target)->declared->name)
                               == m_storedWritten.end())
                        m_storedWritten.push_back(variable(action.target)->declared->name);
                }
            }
            for (const NestedAction& action : s.continuous) {
                if (action.usable && !action.parsed.action.condition.empty())
                    collectComparisons(action.parsed.action.condition);
            }
        }
    }
    for (const std::string& text : m_options.properties) {
        m_properties.push_back(parseProperty(text));
        const bool usable
            = m_properties.back().ok() && checkProperty(m_model, text, PropertyAtoms{m_faults}).empty();
        m_propertyUsable.push_back(usable);
        if (usable) {
            collectComparisons(m_properties.back().expression);
            for (const cond::Node& node : m_properties.back().expression.nodes) {
                if (node.kind == NodeKind::StepDuration && isFaultedAtom(m_model, node))
                    m_faultScanLimit = std::max(m_faultScanLimit, faultedScansFor(node.durationMs, m_cycleMs));
            }
        }
    }
}

void ProgramPromela::computeRepresentatives()
{
    for (VariableInfo& info : m_variables) {
        if (info.role != VariableRole::Number)
            continue;
        std::vector<const sat::Atom*> pointers;
        for (const sat::Atom& atom : info.comparisons)
            pointers.push_back(&atom);
        info.representatives = sat::representatives(info.declared->type, pointers);
        if (info.representatives.empty())
            info.representatives = {info.initial};
        if (info.declared->kind != VariableKind::Input && isRealType(info.declared->type)) {
            const std::vector<cond::Value> beyond = sat::nonFiniteReals();
            info.representatives.insert(info.representatives.end(), beyond.begin(), beyond.end());
        }
    }
}

// --- expressions ------------------------------------------------------------------------

std::string ProgramPromela::readBool(const VariableInfo& info)
{
    switch (info.role) {
    case VariableRole::Input:
        m_out.line("rd_" + info.declared->name + "();");
        return "i_" + info.declared->name;
    case VariableRole::Sensor: return info.sensor;
    case VariableRole::Stored: return "v_" + info.declared->name;
    case VariableRole::Constant: return cond::isTrue(info.initial) ? "1" : "0";
    default: return "0"; // a numeric variable in a BOOL context: not in a usable text
    }
}

void ProgramPromela::evalRoot(const Context& context, const cond::Expression& expression, int depth)
{
    if (expression.empty() || expression.root < 0) {
        m_out.line(ev(depth) + " = 0;");
        return;
    }
    eval(context, expression, expression.root, depth);
}

// A comparison: decided on the value of its one numeric variable, or a free BOOL.
void ProgramPromela::evalLeafComparison(const cond::Expression& expression, int index, int depth)
{
    std::set<const VariableInfo*> numeric;
    bool other = false;
    std::vector<int> stack{index};
    while (!stack.empty()) {
        const cond::Node& sub = expression.at(stack.back());
        stack.pop_back();
        if (sub.kind == NodeKind::Variable) {
            const VariableInfo* info = variable(sub.text);
            if (info && info->declared->type != IecType::Bool)
                numeric.insert(info);
            else
                other = true;
        } else if (sub.kind == NodeKind::Unary) {
            stack.push_back(sub.operand);
        } else if (sub.kind == NodeKind::Binary) {
            stack.push_back(sub.left);
            stack.push_back(sub.right);
        } else if (sub.kind != NodeKind::IntegerLiteral && sub.kind != NodeKind::RealLiteral) {
            other = true;
        }
    }
    const bool direct = verification::isVariableAgainstConstant(expression, index); // as the explorer reads it
    if (other || numeric.size() > 1 || (!numeric.empty() && !direct)) {
        bool negated = false;
        const int k = opaqueIndex(canonicalText(expression, index, negated));
        m_out.line("ro_" + std::to_string(k) + "();");
        m_out.line(ev(depth) + " = " + (negated ? "!" : "") + "o_" + std::to_string(k) + ";");
        return;
    }
    const cond::Expression sub{expression.nodes, index};
    const VariableInfo* read = numeric.empty() ? nullptr : *numeric.begin();
    auto truthAt = [&](const cond::Value& value) {
        return cond::isTrue(cond::evaluate(sub, [&](int) { return value; }));
    };
    if (!read || read->role == VariableRole::Fixed) {
        const bool value = truthAt(read ? read->initial : cond::Value{std::int64_t{0}});
        m_out.line(ev(depth) + " = " + (value ? "1" : "0") + ";");
        return;
    }
    std::vector<std::size_t> holding, failing;
    for (std::size_t i = 0; i < read->representatives.size(); ++i)
        (truthAt(read->representatives[i]) ? holding : failing).push_back(i);
    const std::string name = "n_" + read->declared->name;
    if (failing.empty() || holding.empty()) {
        m_out.line(ev(depth) + " = " + (failing.empty() ? "1" : "0") + ";");
        return;
    }
    m_out.line("rn_" + read->declared->name + "();");
    const bool fewerHold = holding.size() <= failing.size();
    std::string test;
    for (std::size_t i : fewerHold ? holding : failing)
        test += (test.empty() ? "" : " || ") + name + " == " + std::to_string(i);
    m_out.line(ev(depth) + " = " + (fewerHold ? "(" : "!(") + test + ");");
}

// The value of `node` into ev[depth], reading inputs as the scan reaches them
// (AND, OR and -> do not read their right operand when the left decides).
void ProgramPromela::eval(const Context& context, const cond::Expression& expression, int index, int depth)
{
    m_maxDepth = std::max(m_maxDepth, depth + 2);
    const std::string result = ev(depth);
    if (context.tokens) {
        if (auto token = context.tokens->find(index); token != context.tokens->end()) {
            m_out.line(result + " = tk_" + token->second + ";");
            return;
        }
    }
    const cond::Node& node = expression.at(index);
    const NestedGrafcet* grafcet = context.step && context.step->nested ? &*context.step->nested : nullptr;
    auto ownOutput = [&](const std::string& name) -> std::string {
        if (!grafcet)
            return {};
        for (const ContinuousOutput& output : grafcet->outputs) {
            if (!output.isComplete && equalsIgnoreCase(output.variable, name))
                return outName(*context.step, output.variable);
        }
        return {};
    };
    switch (node.kind) {
    case NodeKind::BoolLiteral: m_out.line(result + " = " + (equalsIgnoreCase(node.text, "TRUE") ? "1;" : "0;")); return;
    case NodeKind::Variable: {
        if (context.property && m_faults && isFaultedAtom(m_model, node)) {
            m_out.line(result + " = (flt != 0); /* faulted */");
            return;
        }
        if (std::string own = ownOutput(node.text); !own.empty()) {
            m_out.line(result + " = " + own + "; /* the FB's own output */");
            return;
        }
        const VariableInfo* info = variable(node.text);
        m_out.line(result + " = " + (info ? readBool(*info) : std::string("0")) + ";");
        return;
    }
    case NodeKind::StepActivity:
        m_out.line(result + " = " + (grafcet && grafcet->step(node.number) ? xName(*context.step, node.number) : "0") + ";");
        return;
    case NodeKind::StepDuration: {
        if (context.property && m_faults && isFaultedAtom(m_model, node)) {
            m_out.line(result + " = (flt != 0 && fc >= " + std::to_string(faultedScansFor(node.durationMs, m_cycleMs))
                       + "); /* " + commentSafe(node.text) + " */");
            return;
        }
        const auto timer = context.timerOfNode ? context.timerOfNode->find(index) : std::map<int, int>::const_iterator{};
        if (!grafcet || !context.timerOfNode || timer == context.timerOfNode->end() || !grafcet->step(node.number)) {
            m_out.line(result + " = 0;");
            return;
        }
        const auto k = static_cast<std::size_t>(timer->second);
        const NestedTimer& ton = grafcet->timers[k];
        const std::string t = timerName(*context.step, k);
        m_out.line("if");
        m_out.line(":: " + xName(*context.step, node.number) + " ->");
        m_out.in();
        if (m_options.exactTime) {
            writeCountedTimerRead(*context.step, k, ton, result, node.text);
        } else if (ton.durationMs > m_cycleMs) {
            const std::string chosen = timerChosenName(*context.step, k);
            m_out.line("if /* " + commentSafe(node.text) + ": running, it may or may not have elapsed */");
            m_out.line(":: " + t + " == 1 && !" + chosen + " -> " + chosen + " = 1; if :: " + t + " = 2 :: skip fi;");
            m_out.line(":: else -> skip;");
            m_out.line("fi;");
            m_out.line(result + " = (" + t + " == 2);");
        } else {
            m_out.line(result + " = (" + t + " == 2); /* " + commentSafe(node.text) + ": within one cycle */");
        }
        m_out.out();
        m_out.line(":: else -> " + result + " = 0;");
        m_out.line("fi;");
        return;
    }
    case NodeKind::Complete: m_out.line(result + " = " + (grafcet ? completeName(*context.step) : "0") + ";"); return;
    case NodeKind::InStep: {
        const GemmaStep* step = m_program.step(propertyStepId(m_model, node.text));
        m_out.line(result + " = " + (step ? "(gState == " + stateOf(*step) + ")" : std::string("0")) + ";");
        return;
    }
    case NodeKind::NestedStepActivity: {
        const GemmaStep* step = m_program.step(propertyStepId(m_model, node.text));
        if (!step || !step->nested || !step->nested->step(node.number)) {
            m_out.line(result + " = 0;");
            return;
        }
        m_out.line(result + " = (gState == " + stateOf(*step) + " && !gEntry && " + xName(*step, node.number) + ");");
        return;
    }
    case NodeKind::Unary: {
        if (node.unaryOp == cond::UnaryOp::Not) {
            eval(context, expression, node.operand, depth);
            m_out.line(result + " = !" + result + ";");
            return;
        }
        const std::string name = expression.at(node.operand).text;
        const VariableInfo* info = variable(name);
        if (!context.edges || !info || (node.unaryOp != cond::UnaryOp::RisingEdge && node.unaryOp != cond::UnaryOp::FallingEdge)) {
            m_out.line(result + " = 0;");
            return;
        }
        const std::string before = info->edge ? "p_" + info->declared->name : std::string("0");
        m_out.line("if");
        m_out.line(":: gFirst -> /* an edge: the first evolution of the call only */");
        m_out.in();
        std::string now = ownOutput(name);
        if (now.empty())
            now = readBool(*info);
        m_out.line(result + " = " + (node.unaryOp == cond::UnaryOp::RisingEdge ? "(" + now + " && !" + before + ")"
                                                                                 : "(!" + now + " && " + before + ")")
                   + ";");
        m_out.out();
        m_out.line(":: else -> " + result + " = 0;");
        m_out.line("fi;");
        return;
    }
    case NodeKind::Binary: break;
    default: m_out.line(result + " = 0;"); return;
    }
    const BinaryOp op = node.binaryOp;
    const bool boolOperands = cond::valueKind(expression, node.left, m_symbols) == cond::ValueKind::Bool;
    if (isComparisonOp(op) && !((op == BinaryOp::Equal || op == BinaryOp::NotEqual) && boolOperands)) {
        evalLeafComparison(expression, index, depth);
        return;
    }
    eval(context, expression, node.left, depth);
    switch (op) {
    case BinaryOp::And:
    case BinaryOp::Or:
    case BinaryOp::Implies: {
        const std::string go = op == BinaryOp::Or ? "!" + result : result; // the left operand does not decide
        m_out.line("if");
        m_out.line(":: " + go + " ->");
        m_out.in();
        eval(context, expression, node.right, depth);
        m_out.out();
        m_out.line(op == BinaryOp::Implies ? ":: else -> " + result + " = 1;" : ":: else -> skip;");
        m_out.line("fi;");
        return;
    }
    case BinaryOp::Xor:
    case BinaryOp::NotEqual:
    case BinaryOp::Equal:
        eval(context, expression, node.right, depth + 1);
        m_out.line(result + " = (" + result + (op == BinaryOp::Equal ? " == " : " != ") + ev(depth + 1) + ");");
        return;
    default: m_out.line(result + " = 0;"); return;
    }
}

// --- markers ------------------------------------------------------------------------------

void ProgramPromela::marker(PromelaMarker m, const std::string& comment)
{
    m.line = m_out.line("mark = 1; /* " + commentSafe(comment) + " */");
    m_markers.push_back(std::move(m));
}

void ProgramPromela::markIf(const std::string& test, PromelaMarker m, const std::string& comment)
{
    m_out.line("if");
    m_out.line(":: " + test + " ->");
    m_out.in();
    marker(std::move(m), comment);
    m_out.out();
    m_out.line(":: else -> skip;");
    m_out.line("fi;");
}

PromelaMarker transitionMarker(PromelaMarkerKind kind, const GemmaStep& step, const GemmaTransition& transition)
{
    PromelaMarker m;
    m.kind = kind;
    m.step = step.id;
    m.transition = transition.id;
    return m;
}

PromelaMarker nestedMarker(PromelaMarkerKind kind, const GemmaStep& step, std::vector<int> numbers)
{
    PromelaMarker m;
    m.kind = kind;
    m.step = step.id;
    m.numbers = std::move(numbers);
    return m;
}

// --- writing ------------------------------------------------------------------------------

PromelaModel ProgramPromela::run()
{
    m_cycleMs = m_model.settings().cycleTimeMs;
    classifyVariables();
    if (m_options.machine && !m_options.machine->empty())
        wireMachine();
    collectAll();
    computeRepresentatives();
    for (std::size_t i = 0; i < m_program.steps.size(); ++i) {
        if (m_program.steps[i].id == "D1")
            m_d1 = static_cast<int>(i);
    }
    // The scan process first (it fixes the opaque comparisons and the depth
    // of evaluation), then the declarations before it.
    writeProcess();
    const std::string process = m_out.take();
    const std::vector<PromelaMarker> markers = std::move(m_markers);
    m_markers.clear();
    m_out = PromelaWriter();
    writeHeader();
    writeDeclarations();
    writeReaders();
    std::string text = m_out.take();
    const int offset = static_cast<int>(std::count(text.begin(), text.end(), '\n'));
    PromelaModel result;
    result.text = text + process;
    result.markers = markers;
    for (PromelaMarker& m : result.markers)
        m.line += offset;
    return result;
}

void ProgramPromela::writeHeader()
{
    const std::string run = std::string(kSpinGenerate) + " FILE && " + kSpinCompile + " && " + kSpinRun;
    for (const std::string& text : std::vector<std::string>{
             "/*",
             " * Both layers of \"" + commentSafe(m_model.settings().name) + "\" as a Promela model for SPIN,",
             " * written by GG Studio (docs/verification.md, \"SPIN cross-check of both layers\").",
             " * One iteration of the do loop is one PLC scan of the generated program:",
             " * PROGRAM GEMMA and the function block of the active macro/enclosing step.",
             " * Inputs are chosen when first read in a scan (rd_*), numeric variables take",
             " * one value per combination of their comparisons with constants (rn_*),",
             std::string(" * other comparisons are free booleans (ro_*)")
                 + (m_options.exactTime ? "; time is counted in scans." : ";")
                 + (m_options.exactTime ? "" : " a TON longer than a cycle may or"),
             m_options.exactTime ? " *" : " * may not have elapsed from its second run on.",
             " *",
             " * Run:  " + run,
             " * Then read pan's list \"unreached in proctype scan\": a line that ends with",
             " * a marker comment is listed iff what the comment names never happens.",
             " */",
         })
        m_out.line(text);
    m_out.line("");
}

void ProgramPromela::writeDeclarations()
{
    m_out.line("/* The state between scans. gState: 0 no visible step active, else: */");
    for (const GemmaStep& step : m_program.steps)
        m_out.line("/*   " + stateOf(step) + " " + step.id + " " + commentSafe(step.name) + " */");
    const GemmaStep* initial = m_program.step(m_program.initialStepId);
    m_out.line("byte gState = " + (initial ? stateOf(*initial) : std::string("0")) + ";");
    m_out.line("bit gEntry = 1;");
    for (const GemmaStep& step : m_program.steps) {
        for (const GemmaToken& token : step.tokens)
            m_out.line("bit tk_" + token.name + "; /* token of " + commentSafe(token.transitionId) + " */");
    }
    for (const GemmaStep& step : m_program.steps) {
        if (!step.nested)
            continue;
        const NestedGrafcet& g = *step.nested;
        std::string line = "bit";
        for (const NestedStep& s : g.steps)
            line += std::string(line == "bit" ? " " : ", ") + xName(step, s.number);
        m_out.line(line + "; /* the situation of " + step.id + "'s GRAFCET */");
        for (const ContinuousOutput& output : g.outputs) {
            if (!output.isComplete)
                m_out.line("bit " + outName(step, output.variable) + "; /* its FB's output */");
        }
        m_out.line("bit " + completeName(step) + "; /* its Complete */");
        for (std::size_t k = 0; k < g.timers.size(); ++k) {
            m_out.line(std::string(m_options.exactTime ? "int " : "byte ") + timerName(step, k) + "; /* "
                       + g.timers[k].name + (m_options.exactTime ? ": runs with IN TRUE */" : ": 0 stopped, 1 running, 2 elapsed */"));
        }
    }
    for (const VariableInfo& info : m_variables) {
        if (info.role == VariableRole::Stored)
            m_out.line("bit v_" + info.declared->name + " = " + (cond::isTrue(info.initial) ? "1" : "0") + ";");
        if (info.edge)
            m_out.line("bit p_" + info.declared->name + " = "
                       + (info.declared->type == IecType::Bool && cond::isTrue(info.initial) ? "1" : "0")
                       + "; /* " + info.declared->name + "_PREV */");
    }
    m_out.line("");
    if (!m_machine.declarations.empty())
        m_out.line("/* The machine (closed loop). */");
    for (const std::string& declaration : m_machine.declarations)
        m_out.line(declaration);
    m_out.line("/* Within one scan, all 0 between scans. */");
    for (const VariableInfo& info : m_variables) {
        const std::string& name = info.declared->name;
        if (info.role == VariableRole::Input)
            m_out.line("bit i_" + name + ", d_" + name + "; /* the input and whether the scan read it */");
        if (info.role == VariableRole::Number) {
            std::string values;
            for (std::size_t i = 0; i < info.representatives.size(); ++i)
                values += (i ? ", " : "") + std::to_string(i) + " = " + cond::formatValue(info.representatives[i]);
            m_out.line(std::string(info.representatives.size() < 256 ? "byte" : "int") + " n_" + name + "; bit dn_" + name
                       + "; /* " + commentSafe(values) + " */");
        }
    }
    for (const std::string& name : m_storedWritten)
        m_out.line("byte w_" + name + "; bit wv_" + name + "; /* who wrote it in this scan (step index + 1), what */");
    for (std::size_t k = 0; k < m_opaque.size(); ++k)
        m_out.line("bit o_" + std::to_string(k) + ", do_" + std::to_string(k) + "; /* " + commentSafe(m_opaque[k]) + " */");
    for (const GemmaStep& step : m_program.steps) {
        if (!step.nested)
            continue;
        for (std::size_t k = 0; k < step.nested->timers.size(); ++k)
            m_out.line("bit " + timerChosenName(step, k) + "; /* the scan chose whether it elapsed */");
    }
    m_out.line("bit ev[" + std::to_string(m_maxDepth) + "]; /* evaluation */");
    m_out.line("bit gFi[" + std::to_string(m_maxTransitions) + "], gLeft[" + std::to_string(m_maxSteps) + "], gEnter["
               + std::to_string(m_maxSteps) + "], gOut[" + std::to_string(m_maxOutputs) + "];");
    if (m_maxEvolutions <= 255)
        m_out.line("byte gFrom, gEvolutions, mark;");
    else
        m_out.line("byte gFrom, mark; int gEvolutions;");
    m_out.line("bit gComplete, gFirst, gFired, gD1;");
    m_out.line("");
}

void ProgramPromela::writeReaders()
{
    for (const VariableInfo& info : m_variables) {
        const std::string& name = info.declared->name;
        if (info.role == VariableRole::Input)
            m_out.line("inline rd_" + name + "() { if :: !d_" + name + " -> d_" + name + " = 1; if :: i_" + name
                       + " = 1 :: i_" + name + " = 0 fi :: else -> skip fi }");
        if (info.role == VariableRole::Number)
            m_out.line("inline rn_" + name + "() { if :: !dn_" + name + " -> dn_" + name + " = 1; select (n_" + name
                       + " : 0 .. " + std::to_string(info.representatives.size() - 1) + ") :: else -> skip fi }");
    }
    for (std::size_t k = 0; k < m_opaque.size(); ++k) {
        const std::string n = std::to_string(k);
        m_out.line("inline ro_" + n + "() { if :: !do_" + n + " -> do_" + n + " = 1; if :: o_" + n + " = 1 :: o_" + n
                   + " = 0 fi :: else -> skip fi }");
    }
    m_out.line("");
}

void ProgramPromela::writeProcess()
{
    m_out.line("active proctype scan()");
    m_out.line("{");
    m_out.in();
    m_out.line("do");
    m_out.line(":: atomic {");
    m_out.in();
    m_out.line("gFrom = gState;");
    if (m_faults)
        writeFaultChoice();
    m_out.line("if");
    for (const GemmaStep& step : m_program.steps)
        writeStep(step);
    m_out.line(":: else -> skip; /* no visible step active: the PLC runs no step's code */");
    m_out.line("fi;");
    m_out.out();
    m_out.line("scanned:");
    m_out.in();
    writeEndOfScan();
    if (m_faults && !m_faultSensors.empty()) {
        std::string flickers;
        for (std::size_t s = 0; s < m_faultSensors.size(); ++s)
            flickers += (s ? " || flt == " : "flt == ") + std::to_string(faultCode(s, 2));
        m_out.line("if :: " + flickers + " -> flk = !flk :: else -> skip fi; /* a flicker toggles */");
    }
    if (!m_machine.cycle.empty())
        m_out.line("/* the machine's cycle, from the outputs the scan left */");
    for (const std::string& statement : m_machine.cycle)
        m_out.line(statement);
    writeReset();
    m_out.out();
    m_out.line("}");
    m_out.line("od");
    m_out.out();
    m_out.line("}");
}

// Single faults, before the scan: with none in effect, none or any one
// begins (a flicker reads the opposite of the machine's value first); then
// the scans since it began, as far as a property's `T/faulted` needs.
void ProgramPromela::writeFaultChoice()
{
    m_out.line("if");
    m_out.line(":: flt == 0 ->");
    m_out.in();
    m_out.line("if");
    m_out.line(":: skip");
    for (std::size_t j = 0; j < m_jams.size(); ++j)
        m_out.line(":: flt = " + std::to_string(j + 1) + " /* " + commentSafe(m_options.machine->components[m_jams[j]].name)
                   + " jam */");
    for (std::size_t s = 0; s < m_faultSensors.size(); ++s) {
        const std::string& upper = m_faultSensors[s].first;
        m_out.line(":: flt = " + std::to_string(faultCode(s, 0)) + " /* " + commentSafe(upper) + " stuck TRUE */");
        m_out.line(":: flt = " + std::to_string(faultCode(s, 1)) + " /* " + commentSafe(upper) + " stuck FALSE */");
        m_out.line(":: flt = " + std::to_string(faultCode(s, 2)) + "; flk = !" + m_faultSensors[s].second + " /* "
                   + commentSafe(upper) + " flicker */");
    }
    m_out.line("fi");
    m_out.out();
    m_out.line(":: else -> skip");
    m_out.line("fi;");
    if (m_faultScanLimit > 0)
        m_out.line("if :: flt != 0 && fc < " + std::to_string(m_faultScanLimit) + " -> fc++ :: else -> skip fi;");
}

void ProgramPromela::writeStep(const GemmaStep& step)
{
    m_out.line(":: gState == " + stateOf(step) + " -> /* " + step.id + " */");
    m_out.in();
    PromelaMarker reach;
    reach.kind = PromelaMarkerKind::Reach;
    reach.step = step.id;
    marker(reach, "reach " + step.id);
    if (step.hasNestedBehaviour()) {
        m_out.line("if");
        m_out.line(":: gEntry ->");
        m_out.in();
        if (step.nested)
            writeInitialization(step);
        m_out.line("gEntry = 0;");
        for (const GemmaToken& token : step.tokens)
            m_out.line("tk_" + token.name + " = 0;");
        m_out.out();
        m_out.line(":: else -> skip;");
        m_out.line("fi;");
        if (step.nested) {
            writeEvolvingCall(step);
            m_out.line("gComplete = " + completeName(step) + ";");
            markIf("gComplete", nestedMarker(PromelaMarkerKind::CompleteTrue, step, {}), step.id + " Complete TRUE");
        } else {
            auto assumption = m_options.complete.find(step.id);
            if (assumption == m_options.complete.end() || assumption->second == CompleteAssumption::Free)
                m_out.line("if :: gComplete = 1 :: gComplete = 0 fi; /* no GRAFCET: Complete free */");
            else
                m_out.line("gComplete = 1; /* no GRAFCET: Complete automatic */");
        }
    }
    for (std::size_t i = 0; i < step.transitions.size(); ++i) {
        const GemmaTransition& t = step.transitions[i];
        m_out.line("/* " + t.id + ": " + commentSafe(t.conditionText) + (t.waitsForComplete ? ", waits for Complete" : "")
                   + (t.conditionUsable ? "" : " (unusable: FALSE)") + " */");
        if (!t.conditionUsable)
            continue;
        writeGated(t);
        const GemmaStep* target = m_program.step(t.targetId);
        m_out.line("if");
        m_out.line(":: ev[0] ->");
        m_out.in();
        m_out.line("gState = " + (target ? stateOf(*target) : std::string("0")) + "; gEntry = 1;"
                   + (target && indexOf(*target) == m_d1 ? " gD1 = 1;" : ""));
        marker(transitionMarker(PromelaMarkerKind::Fire, step, t), "fire " + t.id + " in " + step.id);
        writeLaterConditions(step, i);
        m_out.line("goto scanned;");
        m_out.out();
        m_out.line(":: else ->");
        m_out.in();
        marker(transitionMarker(PromelaMarkerKind::Fails, step, t), t.id + " FALSE in " + step.id);
        m_out.out();
        m_out.line("fi;");
    }
    m_out.out();
}

// The condition as the CASE reads it (AND Complete where it waits) into ev[0].
void ProgramPromela::writeGated(const GemmaTransition& t)
{
    Context context;
    context.tokens = &t.substitutions;
    if (t.waitsForComplete) {
        m_out.line("if");
        m_out.line(":: gComplete ->");
        m_out.in();
        evalRoot(context, t.condition.expression, 0);
        m_out.out();
        m_out.line(":: else -> ev[0] = 0;");
        m_out.line("fi;");
    } else {
        evalRoot(context, t.condition.expression, 0);
    }
}

// GV103 and GV104: in the scan where transition `fired` fires, the conditions
// after it are read too (the generated code does not), so that SPIN sees each
// FALSE (Fails) and each that holds with it (Overlap; not after the family
// transition, whose priority is by design).
void ProgramPromela::writeLaterConditions(const GemmaStep& step, std::size_t fired)
{
    const GemmaTransition& higher = step.transitions[fired];
    for (std::size_t j = fired + 1; j < step.transitions.size(); ++j) {
        const GemmaTransition& lower = step.transitions[j];
        if (!lower.conditionUsable)
            continue;
        writeGated(lower);
        m_out.line("if");
        m_out.line(":: ev[0] ->");
        m_out.in();
        if (higher.family) {
            m_out.line("skip;");
        } else {
            PromelaMarker overlap = transitionMarker(PromelaMarkerKind::Overlap, step, higher);
            overlap.other = lower.id;
            marker(overlap, higher.id + " fires while " + lower.id + " holds in " + step.id);
        }
        m_out.out();
        m_out.line(":: else ->");
        m_out.in();
        marker(transitionMarker(PromelaMarkerKind::Fails, step, lower), lower.id + " FALSE in " + step.id);
        m_out.out();
        m_out.line("fi;");
    }
}

void ProgramPromela::writeNoteActive(const GemmaStep& step)
{
    for (const NestedStep& s : step.nested->steps)
        markIf(xName(step, s.number), nestedMarker(PromelaMarkerKind::NestedActive, step, {s.number}),
               step.id + ".X" + std::to_string(s.number) + " active");
}

void ProgramPromela::writeInitialization(const GemmaStep& step)
{
    const NestedGrafcet& g = *step.nested;
    m_out.line("/* the Initialization call */");
    for (const NestedStep& s : g.steps)
        m_out.line(xName(step, s.number) + " = " + (s.initial ? "1;" : "0;"));
    m_out.line(completeName(step) + " = 0;");
    for (std::size_t k = 0; k < g.timers.size(); ++k)
        m_out.line(timerName(step, k) + " = 0; " + timerChosenName(step, k) + " = 0;");
    for (const NestedStep& s : g.steps) {
        if (s.initial)
            writeStored(step, s.number, s.onActivation, false);
    }
    writeOutputs(step);
    writeNoteActive(step);
}

void ProgramPromela::writeStored(const GemmaStep& step, int stepNumber, const std::vector<NestedAction>& actions,
                                 bool reportRaces)
{
    const NestedGrafcet& g = *step.nested;
    int stepIndex = 0;
    for (std::size_t i = 0; i < g.steps.size(); ++i) {
        if (g.steps[i].number == stepNumber)
            stepIndex = static_cast<int>(i);
    }
    Context context;
    context.step = &step;
    for (const NestedAction& action : actions) {
        if (!usableAction(action))
            continue;
        m_out.line("/* X" + std::to_string(stepNumber) + ": " + commentSafe(action.text) + " */");
        std::string value;
        switch (action.parsed.action.form) {
        case cond::ActionForm::Set: value = "1"; break;
        case cond::ActionForm::Reset: value = "0"; break;
        default:
            evalRoot(context, action.parsed.action.value, 0);
            value = "ev[0]";
            break;
        }
        if (action.targetIsComplete) {
            m_out.line(completeName(step) + " = " + value + ";");
            continue;
        }
        const std::string name = variable(action.target)->declared->name;
        if (reportRaces) {
            // Another step of this GRAFCET wrote the opposite value in this scan.
            for (std::size_t other = 0; other < g.steps.size(); ++other) {
                if (static_cast<int>(other) == stepIndex)
                    continue;
                bool writes = false;
                for (const auto* list : {&g.steps[other].onActivation, &g.steps[other].onDeactivation}) {
                    for (const NestedAction& a : *list)
                        writes = writes || (usableAction(a) && !a.targetIsComplete && equalsIgnoreCase(a.target, name));
                }
                if (!writes)
                    continue;
                const int a = g.steps[other].number;
                PromelaMarker race = nestedMarker(PromelaMarkerKind::Race, step, {std::min(a, stepNumber), std::max(a, stepNumber)});
                race.variable = name;
                markIf("w_" + name + " == " + std::to_string(other + 1) + " && wv_" + name + " != " + value, race,
                       "race on " + name + " between " + step.id + ".X" + std::to_string(a) + " and " + step.id + ".X"
                           + std::to_string(stepNumber));
            }
        }
        m_out.line("w_" + name + " = " + std::to_string(stepIndex + 1) + "; wv_" + name + " = " + value + "; v_" + name
                   + " = " + value + ";");
    }
}

// The continuous outputs and Complete at the end of the call, from the
// situation it ends with; the FB's own outputs read as the previous call left them.
void ProgramPromela::writeOutputs(const GemmaStep& step)
{
    const NestedGrafcet& g = *step.nested;
    Context context;
    context.step = &step;
    for (std::size_t o = 0; o < g.outputs.size(); ++o) {
        const ContinuousOutput& output = g.outputs[o];
        const std::string slot = "gOut[" + std::to_string(o) + "]";
        m_out.line("/* " + (output.isComplete ? std::string("Complete") : output.variable) + " */");
        for (const ContinuousOutput::Driver& driver : output.drivers) {
            const NestedStep* s = g.step(driver.step);
            if (!s)
                continue;
            const NestedAction& action = s->continuous[static_cast<std::size_t>(driver.action)];
            if (!action.usable)
                continue;
            m_out.line("if");
            m_out.line(":: !" + slot + " && " + xName(step, driver.step) + " ->");
            m_out.in();
            if (action.parsed.action.condition.empty()) {
                m_out.line(slot + " = 1;");
            } else {
                evalRoot(context, action.parsed.action.condition, 0);
                m_out.line(slot + " = ev[0];");
            }
            m_out.out();
            m_out.line(":: else -> skip;");
            m_out.line("fi;");
        }
    }
    for (std::size_t o = 0; o < g.outputs.size(); ++o) {
        const ContinuousOutput& output = g.outputs[o];
        const std::string slot = "gOut[" + std::to_string(o) + "]";
        m_out.line((output.isComplete ? completeName(step) : outName(step, output.variable)) + " = " + slot + "; " + slot
                   + " = 0;");
    }
}

void ProgramPromela::writeEvolution(const GemmaStep& step)
{
    const NestedGrafcet& g = *step.nested;
    auto fire = [](std::size_t t) { return "gFi[" + std::to_string(t) + "]"; };
    for (std::size_t t = 0; t < g.transitions.size(); ++t) {
        const NestedTransition& transition = g.transitions[t];
        if (!transition.usable)
            continue;
        std::string enabled;
        for (int n : transition.upstream)
            enabled += (enabled.empty() ? "" : " && ") + (g.step(n) ? xName(step, n) : std::string("0"));
        m_out.line("/* (" + std::to_string(transition.number) + ") " + commentSafe(transition.text) + " */");
        m_out.line("if");
        m_out.line(":: " + (enabled.empty() ? std::string("0") : enabled) + " ->");
        m_out.in();
        Context context;
        context.step = &step;
        context.timerOfNode = &transition.timerOfNode;
        context.edges = true;
        evalRoot(context, transition.receptivity.expression, 0);
        m_out.line(fire(t) + " = ev[0];");
        m_out.out();
        m_out.line(":: else -> skip;");
        m_out.line("fi;");
    }
    std::string any;
    for (std::size_t t = 0; t < g.transitions.size(); ++t)
        any += (any.empty() ? "" : " || ") + fire(t);
    m_out.line("if");
    m_out.line(":: " + (any.empty() ? std::string("0") : any) + " ->");
    m_out.in();
    m_out.line("gFired = 1;");
    for (std::size_t t = 0; t < g.transitions.size(); ++t)
        markIf(fire(t), nestedMarker(PromelaMarkerKind::NestedFire, step, {g.transitions[t].number}),
               step.id + " (" + std::to_string(g.transitions[t].number) + ") fires");
    // Two transitions that fire from one upstream step: the first in number
    // order that fires from it, and a later one.
    for (const NestedStep& s : g.steps) {
        std::vector<std::size_t> from;
        for (std::size_t t = 0; t < g.transitions.size(); ++t) {
            const auto& up = g.transitions[t].upstream;
            if (std::find(up.begin(), up.end(), s.number) != up.end())
                from.push_back(t);
        }
        for (std::size_t a = 0; a < from.size(); ++a) {
            std::string firstOf = fire(from[a]);
            for (std::size_t earlier = 0; earlier < a; ++earlier)
                firstOf += " && !" + fire(from[earlier]);
            for (std::size_t b = a + 1; b < from.size(); ++b) {
                const int ta = g.transitions[from[a]].number, tb = g.transitions[from[b]].number;
                markIf(firstOf + " && " + fire(from[b]),
                       nestedMarker(PromelaMarkerKind::SimultaneousBranches, step, {s.number, ta, tb}),
                       step.id + ": (" + std::to_string(ta) + ") and (" + std::to_string(tb) + ") fire together from X"
                           + std::to_string(s.number));
            }
        }
    }
    for (std::size_t i = 0; i < g.steps.size(); ++i) {
        const int number = g.steps[i].number;
        std::string deactivated, activated;
        for (std::size_t t = 0; t < g.transitions.size(); ++t) {
            const auto& up = g.transitions[t].upstream;
            const auto& down = g.transitions[t].downstream;
            if (std::find(up.begin(), up.end(), number) != up.end())
                deactivated += (deactivated.empty() ? "" : " || ") + fire(t);
            if (std::find(down.begin(), down.end(), number) != down.end())
                activated += (activated.empty() ? "" : " || ") + fire(t);
        }
        if (deactivated.empty())
            deactivated = "0";
        if (activated.empty())
            activated = "0";
        const std::string x = xName(step, number), index = std::to_string(i);
        m_out.line("gLeft[" + index + "] = ((" + deactivated + ") && !(" + activated + "));");
        m_out.line("gEnter[" + index + "] = ((" + activated + ") && !" + x + ");");
        markIf("(" + activated + ") && " + x + " && !(" + deactivated + ")",
               nestedMarker(PromelaMarkerKind::UnsafeStep, step, {number}),
               step.id + ".X" + std::to_string(number) + " activated while active");
    }
    for (std::size_t i = 0; i < g.steps.size(); ++i) {
        const std::string x = xName(step, g.steps[i].number), index = std::to_string(i);
        m_out.line(x + " = ((" + x + " && !gLeft[" + index + "]) || gEnter[" + index + "]);");
    }
    writeNoteActive(step);
    m_out.line("gFirst = 0;");
    for (std::size_t i = 0; i < g.steps.size(); ++i) {
        if (g.steps[i].onDeactivation.empty())
            continue;
        m_out.line("if");
        m_out.line(":: gLeft[" + std::to_string(i) + "] ->");
        m_out.in();
        writeStored(step, g.steps[i].number, g.steps[i].onDeactivation, true);
        m_out.line("skip;");
        m_out.out();
        m_out.line(":: else -> skip;");
        m_out.line("fi;");
    }
    for (std::size_t i = 0; i < g.steps.size(); ++i) {
        if (g.steps[i].onActivation.empty() && g.steps[i].timers.empty())
            continue;
        m_out.line("if");
        m_out.line(":: gEnter[" + std::to_string(i) + "] ->");
        m_out.in();
        writeStored(step, g.steps[i].number, g.steps[i].onActivation, true);
        for (int k : g.steps[i].timers)
            m_out.line(timerName(step, static_cast<std::size_t>(k)) + " = 0; "
                       + timerChosenName(step, static_cast<std::size_t>(k)) + " = 0; /* entered: its TON restarts */");
        m_out.line("skip;");
        m_out.out();
        m_out.line(":: else -> skip;");
        m_out.line("fi;");
    }
    std::string clear;
    for (std::size_t t = 0; t < g.transitions.size(); ++t)
        clear += fire(t) + " = 0; ";
    for (std::size_t i = 0; i < g.steps.size(); ++i)
        clear += "gLeft[" + std::to_string(i) + "] = 0; gEnter[" + std::to_string(i) + "] = 0; ";
    m_out.line(clear);
    m_out.out();
    m_out.line(":: else -> gFired = 0;");
    m_out.line("fi;");
}

// t/Xn with time counted in scans: TRUE once the TON has run as often as its
// duration takes; one counted only up to maxCountedTimerRuns may or may not
// have elapsed from then on (the explorer's tonscans rule).
void ProgramPromela::writeCountedTimerRead(const GemmaStep& step, std::size_t k, const NestedTimer& ton,
                                           const std::string& result, const std::string& text)
{
    const std::string t = timerName(step, k);
    const std::int64_t runs = tonscans::runsToElapse(ton.durationMs, m_cycleMs);
    if (!tonscans::countedPartly(runs, m_options.maxCountedTimerRuns)) {
        m_out.line(result + " = (" + t + " >= " + std::to_string(runs) + "); /* " + commentSafe(text) + " */");
        return;
    }
    const std::string limit = std::to_string(m_options.maxCountedTimerRuns);
    const std::string chosen = timerChosenName(step, k);
    m_out.line("if /* " + commentSafe(text) + ": counted up to " + limit + " runs, it may or may not have elapsed */");
    m_out.line(":: " + t + " == " + limit + " && !" + chosen + " -> " + chosen + " = 1; if :: " + t + " = "
               + std::to_string(m_options.maxCountedTimerRuns + 1) + " :: skip fi;");
    m_out.line(":: else -> skip;");
    m_out.line("fi;");
    m_out.line(result + " = (" + t + " > " + limit + ");");
}

void ProgramPromela::writeEvolvingCall(const GemmaStep& step)
{
    const NestedGrafcet& g = *step.nested;
    m_out.line("/* the call of " + step.id + "'s FB: its TONs with X as the last call left it */");
    for (std::size_t k = 0; k < g.timers.size(); ++k) {
        const NestedTimer& ton = g.timers[k];
        const std::string t = timerName(step, k);
        const std::string in = g.step(ton.step) ? xName(step, ton.step) : std::string("0");
        m_out.line(timerChosenName(step, k) + " = 0;");
        if (m_options.exactTime) {
            const std::int64_t limit = tonscans::countLimit(tonscans::runsToElapse(ton.durationMs, m_cycleMs),
                                                            m_options.maxCountedTimerRuns);
            m_out.line("if :: " + in + " && " + t + " < " + std::to_string(limit) + " -> " + t + "++ :: " + in
                       + " -> skip :: else -> " + t + " = 0 fi;");
        } else if (ton.durationMs <= m_cycleMs) {
            m_out.line("if :: " + in + " && " + t + " < 2 -> " + t + "++ :: " + in + " -> skip :: else -> " + t + " = 0 fi;");
        } else {
            m_out.line("if :: " + in + " && " + t + " == 0 -> " + t + " = 1 :: " + in + " -> skip :: else -> " + t
                       + " = 0 fi;");
        }
    }
    m_out.line("gFirst = 1; gEvolutions = 0;");
    if (g.rule == EvolutionRule::UntilStable) {
        m_out.line("do");
        m_out.line(":: true ->");
        m_out.in();
        writeEvolution(step);
        m_out.line("gEvolutions++;");
        m_out.line("if :: gFired && gEvolutions < " + std::to_string(g.maxEvolutions) + " -> skip :: else -> break fi;");
        m_out.out();
        m_out.line("od;");
        markIf("gFired", nestedMarker(PromelaMarkerKind::Unstable, step, {}), step.id + " Unstable");
    } else {
        writeEvolution(step);
    }
    m_out.line("gFirst = 0;");
    writeOutputs(step);
}

void ProgramPromela::writeEndOfScan()
{
    m_out.line("/* after END_CASE: the continuous outputs of the step that stayed active */");
    std::map<std::string, std::vector<const GemmaStep*>> drivers; // declared name -> GRAFCET steps
    std::vector<std::string> order;
    for (const GemmaStep& step : m_program.steps) {
        if (!step.nested)
            continue;
        for (const ContinuousOutput& output : step.nested->outputs) {
            if (output.isComplete)
                continue;
            const VariableInfo* info = variable(output.variable);
            if (!info || info->role != VariableRole::Stored)
                continue;
            if (!drivers.count(info->declared->name))
                order.push_back(info->declared->name);
            drivers[info->declared->name].push_back(&step);
        }
    }
    for (const std::string& name : order) {
        std::string value;
        for (const GemmaStep* step : drivers[name])
            value += (value.empty() ? "" : " || ") + ("(gState == " + stateOf(*step) + " && " + outName(*step, name) + ")");
        m_out.line("v_" + name + " = (gState == gFrom && !gEntry && (" + value + "));");
    }
    m_out.line("/* the token updates, with the new State */");
    for (const GemmaStep& step : m_program.steps) {
        for (const GemmaToken& token : step.tokens) {
            const VariableInfo* info = variable(token.variable);
            if (!info)
                continue;
            m_out.line("if");
            m_out.line(":: gState == " + stateOf(step) + " && !tk_" + token.name + " ->");
            m_out.in();
            const std::string read = readBool(*info);
            m_out.line("tk_" + token.name + " = "
                       + (token.polarity == TokenPolarity::NormallyClosed ? "!" + read : read) + ";");
            m_out.out();
            m_out.line(":: else -> skip;");
            m_out.line("fi;");
        }
    }
    m_out.line("/* what the properties and the rule on D1 read: the end of the scan */");
    for (const std::string& name : m_d1Outputs) {
        PromelaMarker m;
        m.kind = PromelaMarkerKind::OutputOnD1;
        m.step = "D1";
        m.variable = name;
        markIf("gD1 && v_" + name, m, name + " TRUE as D1 is entered");
    }
    for (std::size_t p = 0; p < m_properties.size(); ++p) {
        if (!m_propertyUsable[p])
            continue;
        m_out.line("/* property " + std::to_string(p + 1) + ": " + commentSafe(m_options.properties[p]) + " */");
        evalRoot(Context{nullptr, nullptr, nullptr, false, true}, m_properties[p].expression, 0);
        PromelaMarker m;
        m.kind = PromelaMarkerKind::PropertyViolated;
        m.property = static_cast<int>(p);
        markIf(m_properties[p].kind == PropertyKind::Never ? "ev[0]" : "!ev[0]", m,
               "property " + std::to_string(p + 1) + " violated");
    }
    m_out.line("/* the edge memories */");
    for (const VariableInfo& info : m_variables) {
        if (info.edge)
            m_out.line("p_" + info.declared->name + " = " + readBool(info) + ";");
    }
    m_out.line("/* what a step that is not active keeps: nothing */");
    for (const GemmaStep& step : m_program.steps) {
        if (step.nested) {
            std::string clear;
            for (const NestedStep& s : step.nested->steps)
                clear += xName(step, s.number) + " = 0; ";
            for (const ContinuousOutput& output : step.nested->outputs) {
                if (!output.isComplete)
                    clear += outName(step, output.variable) + " = 0; ";
            }
            clear += completeName(step) + " = 0; ";
            for (std::size_t k = 0; k < step.nested->timers.size(); ++k)
                clear += timerName(step, k) + " = 0; ";
            m_out.line("if :: gFrom == " + stateOf(step) + " && gState != gFrom -> " + clear + ":: else -> skip fi;");
        }
        if (step.hasNestedBehaviour() && !step.tokens.empty()) {
            std::string clear;
            for (const GemmaToken& token : step.tokens)
                clear += "tk_" + token.name + " = 0; ";
            m_out.line("if :: gState != " + stateOf(step) + " || gEntry -> " + clear + ":: else -> skip fi;");
        }
    }
}

void ProgramPromela::writeReset()
{
    std::string reset = "d_step { gFrom = 0; gEvolutions = 0; mark = 0; gComplete = 0; gFirst = 0; gFired = 0; gD1 = 0; ";
    for (const VariableInfo& info : m_variables) {
        if (info.role == VariableRole::Input)
            reset += "i_" + info.declared->name + " = 0; d_" + info.declared->name + " = 0; ";
        if (info.role == VariableRole::Number)
            reset += "n_" + info.declared->name + " = 0; dn_" + info.declared->name + " = 0; ";
    }
    for (const std::string& name : m_storedWritten)
        reset += "w_" + name + " = 0; wv_" + name + " = 0; ";
    for (std::size_t k = 0; k < m_opaque.size(); ++k)
        reset += "o_" + std::to_string(k) + " = 0; do_" + std::to_string(k) + " = 0; ";
    for (const GemmaStep& step : m_program.steps) {
        if (!step.nested)
            continue;
        for (std::size_t k = 0; k < step.nested->timers.size(); ++k)
            reset += timerChosenName(step, k) + " = 0; ";
    }
    for (int d = 0; d < m_maxDepth; ++d)
        reset += ev(d) + " = 0; ";
    m_out.line(reset + "}");
}

} // namespace

PromelaModel buildProgramPromela(const Model& model, const ProgramPromelaOptions& options)
{
    return ProgramPromela(model, options).run();
}

} // namespace core
