#include "core/condition/declarationguess.h"

#include "core/condition/actionparser.h"
#include "core/condition/conditionanalysis.h"
#include "core/condition/conditionparser.h"
#include "core/condition/symboltable.h"
#include "core/templates/packml/packmlconfiguration.h"

#include <optional>
#include <vector>

namespace core {

namespace {

using cond::BinaryOp;
using cond::Expression;
using cond::Node;
using cond::NodeKind;
using cond::UnaryOp;

// How much a use says about the type: where a BOOL is expected says
// little, a literal more, a declared variable's own type most.
enum class Evidence { None, Boolean, Literal, Declared };

struct TypeClue {
    IecType type = IecType::Bool;
    Evidence evidence = Evidence::None;
};

bool isComparison(BinaryOp op)
{
    return op == BinaryOp::Less || op == BinaryOp::Greater || op == BinaryOp::LessEqual
        || op == BinaryOp::GreaterEqual;
}

bool isArithmetic(BinaryOp op)
{
    return op == BinaryOp::Add || op == BinaryOp::Subtract || op == BinaryOp::Multiply || op == BinaryOp::Divide
        || op == BinaryOp::Modulo;
}

// Each node's parent in the arena; -1 for the root.
std::vector<int> parentsOf(const Expression& expression)
{
    std::vector<int> parents(expression.nodes.size(), -1);
    for (std::size_t i = 0; i < expression.nodes.size(); ++i) {
        const Node& node = expression.nodes[i];
        for (int child : {node.operand, node.left, node.right}) {
            if (child >= 0)
                parents[static_cast<std::size_t>(child)] = static_cast<int>(i);
        }
    }
    return parents;
}

class UseCollector {
public:
    UseCollector(const Model& model, std::string_view name)
        : m_name(name)
        , m_symbols(model.variables())
    {
    }

    // `expected`: what the whole expression must be (a BOOL condition, the
    // type of an assignment's target).
    void read(const Expression& expression, TypeClue expected)
    {
        if (expression.empty())
            return;
        const std::vector<int> parents = parentsOf(expression);
        for (int node : cond::variableNodes(expression)) {
            if (!isName(expression.at(node).text))
                continue;
            m_read = true;
            const int parent = parents[static_cast<std::size_t>(node)];
            consider(parent < 0 ? expected : clueFromParent(expression, node, parent));
        }
    }

    void readUnparsed(std::string_view text, cond::Context context)
    {
        for (const cond::Token& token : cond::tokenize(text, {context})) {
            if (token.kind == cond::TokenKind::Identifier && isName(token.text))
                m_read = true;
        }
    }

    void readAction(const std::string& text)
    {
        const cond::ActionParseResult parsed = cond::parseAction(text);
        if (!parsed.ok()) {
            readUnparsed(text, cond::Context::Nested);
            return;
        }
        const cond::ActionSyntax& action = parsed.action;
        const TypeClue targetType = targetClue(action);
        if (!action.targetIsComplete && isName(action.target)) {
            m_written = true;
            consider(action.form == cond::ActionForm::Assign ? valueClue(action.value, action.value.root)
                                                              : TypeClue{IecType::Bool, Evidence::Boolean});
        }
        read(action.condition, {IecType::Bool, Evidence::Boolean});
        read(action.value, targetType);
    }

    DeclarationGuess result() const
    {
        DeclarationGuess guess;
        guess.kind = m_written ? (m_read ? VariableKind::Internal : VariableKind::Output) : VariableKind::Input;
        guess.type = m_clue.evidence == Evidence::None ? IecType::Bool : m_clue.type;
        return guess;
    }

private:
    bool isName(std::string_view text) const { return equalsIgnoreCase(text, m_name); }

    // The first of the strongest clues wins.
    void consider(const TypeClue& clue)
    {
        if (clue.evidence > m_clue.evidence)
            m_clue = clue;
    }

    TypeClue targetClue(const cond::ActionSyntax& action) const
    {
        if (action.targetIsComplete)
            return {IecType::Bool, Evidence::Boolean};
        if (const Variable* target = m_symbols.find(action.target))
            return {target->type, Evidence::Declared};
        return {};
    }

    // What a value says about a name it is compared with or assigned to.
    TypeClue valueClue(const Expression& expression, int node) const
    {
        if (node < 0)
            return {};
        const Node& n = expression.at(node);
        if (n.kind == NodeKind::Variable) {
            const Variable* variable = m_symbols.find(n.text);
            return variable ? TypeClue{variable->type, Evidence::Declared} : TypeClue{};
        }
        switch (cond::valueKind(expression, node, m_symbols)) {
        case cond::ValueKind::Bool: return {IecType::Bool, Evidence::Literal};
        case cond::ValueKind::Integer: return {IecType::Int, Evidence::Literal};
        case cond::ValueKind::Real: return {IecType::Real, Evidence::Literal};
        case cond::ValueKind::Unknown: break;
        }
        return {};
    }

    TypeClue clueFromParent(const Expression& expression, int node, int parentIndex) const
    {
        const Node& parent = expression.at(parentIndex);
        if (parent.kind == NodeKind::Unary)
            return parent.unaryOp == UnaryOp::Negate ? TypeClue{IecType::Int, Evidence::Literal}
                                                     : TypeClue{IecType::Bool, Evidence::Boolean};
        if (parent.kind != NodeKind::Binary)
            return {};
        const BinaryOp op = parent.binaryOp;
        if (!isComparison(op) && !isArithmetic(op) && op != BinaryOp::Equal && op != BinaryOp::NotEqual)
            return {IecType::Bool, Evidence::Boolean}; // AND, OR, XOR
        const int other = parent.left == node ? parent.right : parent.left;
        const TypeClue clue = valueClue(expression, other);
        if (clue.evidence != Evidence::None || op == BinaryOp::Equal || op == BinaryOp::NotEqual)
            return clue;
        return {IecType::Int, Evidence::Literal}; // a number of no known type
    }

    std::string_view m_name;
    SymbolTable m_symbols;
    bool m_read = false;
    bool m_written = false;
    TypeClue m_clue;
};

} // namespace

DeclarationGuess guessDeclaration(const Model& model, std::string_view name)
{
    UseCollector uses(model, name);
    const TypeClue condition{IecType::Bool, Evidence::Boolean};
    const auto readText = [&](const std::string& text, cond::Context context) {
        const cond::ParseResult parsed = cond::parse(text, {context});
        if (parsed.ok())
            uses.read(parsed.expression, condition);
        else
            uses.readUnparsed(text, context);
    };
    for (const Transition& transition : model.transitions())
        readText(transition.condition, cond::Context::Gemma);
    if (const packml::Configuration* packml = model.packml()) {
        for (const packml::CommandSetting& command : packml->commands)
            readText(command.condition, cond::Context::Gemma);
        for (const packml::Mode& mode : packml->modes)
            readText(mode.request, cond::Context::Gemma);
    }
    for (const auto& [stepId, grafcet] : model.grafcets()) {
        for (const GrafcetTransition& transition : grafcet.transitions())
            readText(transition.receptivity, cond::Context::Nested);
        for (const GrafcetStep& step : grafcet.steps()) {
            for (const GrafcetAction& action : step.actions)
                uses.readAction(action.text);
        }
    }
    return uses.result();
}

} // namespace core
