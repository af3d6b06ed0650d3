#pragma once

// Deciding conditions (spec §4) for the verifier: a condition becomes a
// boolean formula over *atoms*, and a decision diagram over those atoms
// (core/verification/decisiondiagram.h) answers "can it be TRUE", "is it always TRUE".
//
// Atoms:
// - a BOOL variable;
// - a comparison of one numeric variable with a constant (`Speed > 10`,
//   `10 <= Speed`, `Level = 3`, `Temp < 2.5 * 4`: constant subexpressions are
//   folded). These are decided exactly: the truth values of all comparisons
//   on one variable are constrained to the combinations some value of the
//   variable's IEC type gives (integer or real domain, type range), so
//   `Speed > 10 AND Speed < 11` is unsatisfiable for INT and satisfiable for
//   REAL. Values compare as the simulator compares them (an integer with a
//   real constant as reals; REAL and LREAL as doubles).
// - anything else numeric (`A + B > C`, `X = Y` between numbers, `-S < 3`)
//   is opaque: a free boolean. Treating it as free only adds valuations, so
//   "unsatisfiable" is never claimed wrongly; "satisfiable" may be (check a
//   witness with findValuation).
// `=` and `<>` between BOOL operands are boolean equivalence and XOR, not
// atoms.

#include "core/condition/conditionevaluator.h"
#include "core/condition/conditionsyntax.h"
#include "core/verification/decisiondiagram.h"
#include "core/model/iectypes.h"
#include "core/condition/symboltable.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace core {
struct Variable;
}

namespace core::sat {

enum class Relation { Less, LessEqual, Greater, GreaterEqual, Equal, NotEqual };

struct Atom {
    enum class Kind { Boolean, Comparison, Opaque };
    Kind kind = Kind::Boolean;
    int variable = -1; // Boolean, Comparison: index in the declared variables
    Relation relation = Relation::Equal; // Comparison: variable <relation> constant
    cond::Value constant;                // Comparison
    cond::Expression expression;         // Opaque: a copy whose root is the atom
    std::vector<int> reads;              // Opaque: indices of the variables it reads
    std::string text;                    // ST text: "Speed > 10", "A + B > C"
};

// The declared variables and the atoms found in conditions, each once.
class AtomTable {
public:
    explicit AtomTable(const std::vector<Variable>& variables);
    AtomTable(const AtomTable&) = delete;
    AtomTable& operator=(const AtomTable&) = delete;

    const std::vector<Atom>& atoms() const { return m_atoms; }
    const Atom& atom(int index) const { return m_atoms[static_cast<std::size_t>(index)]; }
    std::size_t variableCount() const { return m_names.size(); }
    IecType variableType(int index) const { return m_types[static_cast<std::size_t>(index)]; }
    const std::string& variableName(int index) const { return m_names[static_cast<std::size_t>(index)]; }
    int variableIndex(std::string_view name) const; // case-insensitive; -1 when undeclared
    const SymbolTable& symbols() const { return *m_symbols; }
    // The values the PLC starts with (defaults), by variable index.
    const std::vector<cond::Value>& initialValues() const { return m_initial; }

    int booleanAtom(int variable);
    int comparisonAtom(int variable, Relation relation, const cond::Value& constant, std::string text);
    int opaqueAtom(const cond::Expression& expression, int node, std::string text);

private:
    std::unique_ptr<std::vector<Variable>> m_variables; // owned: the symbol table points into it
    std::unique_ptr<SymbolTable> m_symbols;
    std::vector<std::string> m_names;
    std::vector<IecType> m_types;
    std::vector<cond::Value> m_initial;
    std::vector<Atom> m_atoms;
};

// The boolean skeleton of a condition.
struct Formula {
    enum class Op { False, True, Atom, Leaf, Not, And, Or, Xor, Equal };
    struct Node {
        Op op = Op::False;
        int a = -1; // Atom: atom index; Leaf: the condition's node; Not/And/...: first operand
        int b = -1; // second operand
    };
    std::vector<Node> nodes; // operands before their users
    int root = -1;

    // The atoms and leaves it uses, ascending, each once.
    std::vector<int> atoms() const;
    std::vector<int> leaves() const;
};

// Translates a condition; the nodes listed in `leaves` (token literals: `X`
// or the NOT of `NOT X`) become Leaf nodes that the caller decides. An empty
// expression is FALSE.
Formula compileCondition(const cond::Expression& expression, const std::set<int>& leaves, AtomTable& atoms);

// The truth of a comparison atom for a value of its variable.
bool holds(const Atom& atom, const cond::Value& value);

// Values of the type: for every combination of truth values of the given
// comparisons (on one variable of that type) that some value of the type
// gives, one of these values gives it.
std::vector<cond::Value> representatives(IecType type, const std::vector<const Atom*>& comparisons);

// The values beyond every finite one that a REAL or LREAL holds once an action
// wrote it: -INF and +INF (an overflow, which storing into REAL's float also
// makes, or a division by 0.0) and NaN (0.0 / 0.0), where every comparison
// but <> is FALSE. The representatives above cover only the finite values,
// as an input takes; add these for a real variable the actions write.
std::vector<cond::Value> nonFiniteReals();

// The comparisons of one numeric variable with constants, as intervals: the
// values of the type fall into *regions*, each giving one combination of
// truth values of the comparisons (Speed > 10, Speed <= 200: the regions
// ..10, 11..200, 201..). A diagram does not give each comparison a variable
// of its own (k comparisons would allow 2^k combinations, of which k+1 or so
// exist, and the constraint excluding the others grows with the product of
// such counts over the variables); it encodes the index of the region in
// binary, so every combination of its bits is a real value (or excluded by
// one small constraint) and a comparison is a small function of the bits.
struct NumericDomain {
    int variable = -1;
    std::vector<int> atoms;                 // the comparison atoms on it, ascending
    std::vector<cond::Value> regionValues;  // one value per region, ascending
    std::vector<int> bits;                  // diagram variables, most significant first (set by the caller)

    std::size_t regionCount() const { return regionValues.size(); }
    int bitCount() const;
    // The region the value is in (the one with its truth values).
    std::size_t regionOf(const AtomTable& table, const cond::Value& value) const;
};

// The domains of the numeric variables that the listed comparison atoms
// compare (other atoms are ignored), in order of first appearance.
std::vector<NumericDomain> numericDomains(const AtomTable& table, const std::vector<int>& atoms);

// Builds diagrams over atoms: atomVariable[atom] is the diagram variable of a
// Boolean or opaque atom (-1: the atom is not used); the comparisons are
// encoded by their variable's domain.
class Encoder {
public:
    Encoder(bdd::Manager& manager, const AtomTable& atoms, std::vector<int> atomVariable,
            std::vector<NumericDomain> domains);

    bdd::Ref encode(const Formula& formula, const std::function<bdd::Ref(int leafNode)>& leaf);
    // Only region indices that exist; conjoin it before asking anything about
    // valuations. Linear in the bits, whatever the comparisons.
    bdd::Ref theory();
    // The atom as a function of the diagram variables; FALSE for an atom
    // without variables.
    bdd::Ref atomFunction(int atom);
    int variableOf(int atom) const; // Boolean and opaque atoms; -1 otherwise
    const std::vector<NumericDomain>& domains() const { return m_domains; }
    const NumericDomain* domainOf(int variable) const;

private:
    bdd::Ref regionFunction(const NumericDomain& domain, const std::function<bool(std::size_t region)>& inside);

    bdd::Manager& m_manager;
    const AtomTable& m_atoms;
    std::vector<int> m_atomVariable;
    std::vector<NumericDomain> m_domains;
    std::map<int, bdd::Ref> m_comparisons; // atom -> function, built once
};

// Values for every variable (by index) under which each listed atom has the
// listed truth value, keeping `current` values wherever they fit. nullopt
// when no values were found (possible only with opaque atoms).
std::optional<std::vector<cond::Value>> concretize(const AtomTable& atoms,
                                                   const std::vector<std::pair<int, bool>>& required,
                                                   std::vector<cond::Value> current);

// The value of an opaque atom under concrete values.
bool evaluateOpaque(const AtomTable& atoms, const Atom& atom, const std::vector<cond::Value>& values);

// One condition on its own, over the declared variables (tokens are not
// involved). Sound: false only when no valuation makes it TRUE.
bool isSatisfiable(const cond::Expression& expression, const std::vector<Variable>& variables);
// True only when every valuation makes it TRUE (opaque atoms are free).
bool isValid(const cond::Expression& expression, const std::vector<Variable>& variables);
// Values (by declaration index) that make it TRUE, checked with
// cond::evaluate; nullopt when unsatisfiable or no values were found.
std::optional<std::vector<cond::Value>> findValuation(const cond::Expression& expression,
                                                      const std::vector<Variable>& variables);

} // namespace core::sat
