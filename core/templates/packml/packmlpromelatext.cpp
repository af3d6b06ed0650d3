#include "core/templates/packml/packmlpromelatext.h"

#include "core/condition/conditionevaluator.h"
#include "core/model/iectypes.h"
#include "core/verification/promela.h"
#include "core/verification/tonscans.h"

#include <algorithm>

namespace core::packml::promela {

namespace {

using cond::BinaryOp;
using cond::NodeKind;

// Promela's int is 32 bits: sums of 16-bit operands cannot overflow it as
// long as the generated code's 64-bit ones do not leave 16 bits either.
bool smallInteger(IecType type)
{
    return type == IecType::Sint || type == IecType::Int || type == IecType::Usint || type == IecType::Uint;
}

constexpr std::int64_t kLargestLiteral = 65535;

const char* binaryOperator(BinaryOp op)
{
    switch (op) {
    case BinaryOp::Or: return " || ";
    case BinaryOp::And: return " && ";
    case BinaryOp::Xor: return " != ";
    case BinaryOp::Equal: return " == ";
    case BinaryOp::NotEqual: return " != ";
    case BinaryOp::Less: return " < ";
    case BinaryOp::Greater: return " > ";
    case BinaryOp::LessEqual: return " <= ";
    case BinaryOp::GreaterEqual: return " >= ";
    case BinaryOp::Add: return " + ";
    case BinaryOp::Subtract: return " - ";
    default: return nullptr; // *, /, MOD (a division by zero stops the PLC), ->
    }
}

} // namespace

int Lines::line(const std::string& text)
{
    if (!text.empty())
        m_text.append(static_cast<std::size_t>(m_indent) * 4, ' ');
    m_text += text;
    m_text += '\n';
    return ++m_lines;
}

std::string comment(std::string_view text)
{
    return promelaComment(text);
}

std::string valueText(const cond::Value& value)
{
    if (const bool* b = std::get_if<bool>(&value))
        return *b ? "1" : "0";
    if (const std::int64_t* i = std::get_if<std::int64_t>(&value))
        return std::to_string(*i);
    throw Unsupported("a REAL value");
}

void addOnce(std::vector<int>& list, int value)
{
    if (std::find(list.begin(), list.end(), value) == list.end())
        list.push_back(value);
}

Names::Names(const PackmlProgram& program, int cycleTimeMs)
    : m_program(program)
    , m_cycleTimeMs(cycleTimeMs)
{
}

std::string Names::read(int slot) const
{
    return m_program.variables[static_cast<std::size_t>(slot)].kind == VariableKind::Input ? input(slot) : stored(slot);
}

std::string Names::step(int instance, int number)
{
    return "x" + std::to_string(instance) + "_" + std::to_string(number);
}

std::string Names::output(int instance, std::size_t index)
{
    return "o" + std::to_string(instance) + "_" + std::to_string(index);
}

std::string Names::timer(int instance, std::size_t index)
{
    return "t" + std::to_string(instance) + "_" + std::to_string(index);
}

std::int64_t Names::runsToElapse(const NestedGrafcet& grafcet, std::size_t index) const
{
    const std::int64_t runs = tonscans::runsToElapse(grafcet.timers[index].durationMs, m_cycleTimeMs);
    if (tonscans::countedPartly(runs, tonscans::kMaxCountedRuns))
        throw Unsupported("a TON of " + std::to_string(grafcet.timers[index].durationMs)
                          + " ms needs more scans than a Promela int counts");
    return runs;
}

int Names::ownOutput(const NestedGrafcet& grafcet, std::string_view variable)
{
    int index = 0;
    for (const ContinuousOutput& output : grafcet.outputs) {
        if (output.isComplete)
            continue;
        if (equalsIgnoreCase(output.variable, variable))
            return index;
        ++index;
    }
    return -1;
}

bool Names::holds(const Variable& variable) const
{
    return variable.type == IecType::Bool || smallInteger(variable.type) || variable.type == IecType::Dint;
}

std::string Names::type(const Variable& variable) const
{
    if (variable.type == IecType::Bool)
        return "bool";
    if (holds(variable))
        return "int";
    throw Unsupported(variable.name + " is " + std::string(iecTypeName(variable.type))
                      + ": the export holds BOOL, SINT, INT, DINT, USINT and UINT only");
}

std::string Names::expression(const cond::Expression& expression, const Place& place, const char* empty) const
{
    if (expression.empty())
        return empty;
    return node(expression, expression.root, place);
}

std::string Names::variableRead(const std::string& name, const Place& place) const
{
    if (place.grafcet) {
        // The FB's own continuous outputs are its VAR_OUTPUTs: the previous call's values.
        if (const int own = ownOutput(*place.grafcet, name); own >= 0)
            return Names::output(place.instance, static_cast<std::size_t>(own));
    }
    const int slot = m_program.slotOf(name);
    if (slot < 0)
        return "0";
    type(m_program.variables[static_cast<std::size_t>(slot)]);
    return read(slot);
}

// The operands of + and - are 16-bit variables and literals only.
void Names::requireArithmetic(const cond::Expression& expression, int index) const
{
    const cond::Node& n = expression.at(index);
    if (n.kind == NodeKind::Variable) {
        const int slot = m_program.slotOf(n.text);
        if (slot >= 0 && !smallInteger(m_program.variables[static_cast<std::size_t>(slot)].type))
            throw Unsupported("arithmetic on " + n.text + ", wider than 16 bits");
    }
}

std::string Names::node(const cond::Expression& expression, int index, const Place& place) const
{
    const cond::Node& n = expression.at(index);
    switch (n.kind) {
    case NodeKind::BoolLiteral: return cond::isTrue(*cond::parseValue(IecType::Bool, n.text)) ? "1" : "0";
    case NodeKind::IntegerLiteral: {
        const std::optional<cond::Value> value = cond::parseValue(IecType::Lint, n.text);
        if (!value || std::get<std::int64_t>(*value) > kLargestLiteral)
            throw Unsupported("the constant " + n.text + " is beyond what the export holds");
        return std::to_string(std::get<std::int64_t>(*value));
    }
    case NodeKind::RealLiteral: throw Unsupported("the REAL constant " + n.text);
    case NodeKind::Variable: return variableRead(n.text, place);
    case NodeKind::StepActivity:
        return place.grafcet && place.grafcet->step(n.number) ? step(place.instance, n.number) : "0";
    case NodeKind::StepDuration: {
        if (!place.grafcet || !place.timers || !place.timers->count(index) || !place.grafcet->step(n.number))
            return "0";
        const auto timerIndex = static_cast<std::size_t>(place.timers->at(index));
        return "(" + step(place.instance, n.number) + " && " + timer(place.instance, timerIndex)
               + " >= " + std::to_string(runsToElapse(*place.grafcet, timerIndex)) + ")";
    }
    case NodeKind::Complete: return place.grafcet ? complete(place.instance) : "0";
    case NodeKind::Unary: {
        const std::string operand = expression.at(n.operand).kind == NodeKind::Variable && place.grafcet
                                        ? variableRead(expression.at(n.operand).text, place)
                                        : std::string();
        switch (n.unaryOp) {
        case cond::UnaryOp::Not: return "!(" + node(expression, n.operand, place) + ")";
        case cond::UnaryOp::Negate:
            requireArithmetic(expression, n.operand);
            return "(-(" + node(expression, n.operand, place) + "))";
        case cond::UnaryOp::RisingEdge:
        case cond::UnaryOp::FallingEdge: {
            const int slot = m_program.slotOf(expression.at(n.operand).text);
            if (!place.firstEvolution || slot < 0 || operand.empty())
                return "0";
            const std::string before = previous(slot);
            return n.unaryOp == cond::UnaryOp::RisingEdge ? "(" + operand + " && !" + before + ")"
                                                          : "(!" + operand + " && " + before + ")";
        }
        }
        return "0";
    }
    case NodeKind::Binary: {
        const char* op = binaryOperator(n.binaryOp);
        if (!op)
            throw Unsupported(std::string("the operator ") + cond::operatorText(n.binaryOp));
        if (n.binaryOp == BinaryOp::Add || n.binaryOp == BinaryOp::Subtract) {
            requireArithmetic(expression, n.left);
            requireArithmetic(expression, n.right);
        }
        return "(" + node(expression, n.left, place) + op + node(expression, n.right, place) + ")";
    }
    default: throw Unsupported("a property-only operand in a condition");
    }
}

} // namespace core::packml::promela
