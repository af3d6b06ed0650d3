#pragma once

// What the rest of GG Studio asks of a parsed condition: its type errors,
// its variables and boolean literals (for tokens), and its ST text.

#include "core/condition/conditionsyntax.h"
#include "core/condition/conditiontypeerror.h"
#include "core/condition/symboltable.h"

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace core::cond {

enum class ValueKind { Bool, Integer, Real, Unknown };

struct TypeIssue {
    std::string code;    // diagnostic code, see core/checks/diagnostic.h
    std::string message; // English
    Span span;
    std::optional<TypeError> error; // GG204: the message as data
};

// Checks that the expression is BOOL and every operator gets operands of the
// right kind (spec §4), and that every variable is declared.
std::vector<TypeIssue> typeCheck(const Expression& expression, const SymbolTable& symbols);
// The same for a value of any kind (the right-hand side of an assignment):
// the operators and variables are checked, not that the whole is BOOL.
std::vector<TypeIssue> typeCheckValue(const Expression& expression, const SymbolTable& symbols);
std::vector<TypeIssue> typeCheck(const Expression& expression, const SymbolTable& symbols, bool mustBeBool);

// The kind of value a node yields (Unknown for undeclared variables or errors).
ValueKind valueKind(const Expression& expression, int node, const SymbolTable& symbols);

// Indices of the Variable nodes, in source order (edge operands included).
std::vector<int> variableNodes(const Expression& expression);

// Indices of the nodes of one kind, in source order.
std::vector<int> nodesOfKind(const Expression& expression, NodeKind kind);

// Indices of the edges (RE, FE unary nodes), in source order.
std::vector<int> edgeNodes(const Expression& expression);

// A boolean literal: an occurrence of a variable, either bare (`X`,
// normally open) or directly under NOT (`NOT X`, normally closed). `node` is
// the node the literal occupies: the variable itself or the NOT above it.
struct Literal {
    int node = -1;
    int variableNode = -1;
    bool negated = false;
};
std::vector<Literal> booleanLiterals(const Expression& expression);

// True when the variable (matched case-insensitively) is an operand of = or
// <>, bare or directly under NOT. There it has no polarity: `X = FALSE` means
// NOT X, so a token standing for X would capture the opposite of what the
// condition waits for. The checks (GG212) and the generator refuse such a token.
bool isComparedWithEquality(const Expression& expression, std::string_view variableName);

struct PrintOptions {
    // The spelling of a variable in the output; default: as written.
    std::function<std::string(const Node& variable)> variableName;
    // Nodes to print as the given text instead (token variables).
    std::map<int, std::string> substitutions;
};

// ST text with upper-case keywords, single spaces around binary operators and
// the fewest parentheses ST precedence needs, except that a unary operator
// applied to another unary expression is always parenthesised: NOT (NOT x).
std::string print(const Expression& expression, const PrintOptions& options = {});

// True when the top-level operator is OR or XOR (the spec parenthesises such
// conditions before `AND S.Complete`). Substituted nodes count as atoms.
bool needsParenthesesBeforeAnd(const Expression& expression);
// The same, for the text print(expression, options) gives: a substituted root
// is an atom.
bool needsParenthesesBeforeAnd(const Expression& expression, const PrintOptions& options);

} // namespace core::cond
