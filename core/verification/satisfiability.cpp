#include "core/verification/satisfiability.h"

#include "core/condition/conditionanalysis.h"
#include "core/model/model.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <map>

namespace core::sat {

namespace {

// Beyond this magnitude a double no longer holds every integer: comparisons
// of 64-bit integers with such real constants are left opaque.
constexpr double kExactIntegerLimit = 9007199254740992.0; // 2^53

using cond::IntegerRange;
using cond::integerRange;

double realLimit(IecType type)
{
    return type == IecType::Real ? static_cast<double>(FLT_MAX) : DBL_MAX;
}

double toDouble(const cond::Value& value)
{
    if (const auto* i = std::get_if<std::int64_t>(&value))
        return static_cast<double>(*i);
    if (const auto* d = std::get_if<double>(&value))
        return *d;
    return std::get<bool>(value) ? 1.0 : 0.0;
}

template<typename T>
bool compare(Relation relation, T a, T b)
{
    switch (relation) {
    case Relation::Less: return a < b;
    case Relation::LessEqual: return a <= b;
    case Relation::Greater: return a > b;
    case Relation::GreaterEqual: return a >= b;
    case Relation::Equal: return a == b;
    case Relation::NotEqual: return a != b;
    }
    return false;
}

Relation relationOf(cond::BinaryOp op)
{
    switch (op) {
    case cond::BinaryOp::Less: return Relation::Less;
    case cond::BinaryOp::LessEqual: return Relation::LessEqual;
    case cond::BinaryOp::Greater: return Relation::Greater;
    case cond::BinaryOp::GreaterEqual: return Relation::GreaterEqual;
    case cond::BinaryOp::NotEqual: return Relation::NotEqual;
    default: return Relation::Equal;
    }
}

// `c < x` is `x > c`.
Relation mirrored(Relation relation)
{
    switch (relation) {
    case Relation::Less: return Relation::Greater;
    case Relation::LessEqual: return Relation::GreaterEqual;
    case Relation::Greater: return Relation::Less;
    case Relation::GreaterEqual: return Relation::LessEqual;
    default: return relation;
    }
}

bool isComparison(cond::BinaryOp op)
{
    switch (op) {
    case cond::BinaryOp::Equal:
    case cond::BinaryOp::NotEqual:
    case cond::BinaryOp::Less:
    case cond::BinaryOp::Greater:
    case cond::BinaryOp::LessEqual:
    case cond::BinaryOp::GreaterEqual: return true;
    default: return false;
    }
}

cond::Expression rootedAt(const cond::Expression& expression, int node)
{
    cond::Expression copy = expression;
    copy.root = node;
    return copy;
}

bool containsVariable(const cond::Expression& expression, int node)
{
    const cond::Node& n = expression.at(node);
    switch (n.kind) {
    case cond::NodeKind::Variable: return true;
    case cond::NodeKind::Unary: return containsVariable(expression, n.operand);
    case cond::NodeKind::Binary: return containsVariable(expression, n.left) || containsVariable(expression, n.right);
    default: return false;
    }
}

// Translates the tree node by node.
class Compiler {
public:
    Compiler(const cond::Expression& expression, const std::set<int>& leaves, AtomTable& atoms)
        : m_expression(expression), m_leaves(leaves), m_atoms(atoms)
    {
    }

    Formula run()
    {
        m_formula.root = m_expression.empty() ? add(Formula::Op::False) : node(m_expression.root);
        return std::move(m_formula);
    }

private:
    int add(Formula::Op op, int a = -1, int b = -1)
    {
        m_formula.nodes.push_back(Formula::Node{op, a, b});
        return static_cast<int>(m_formula.nodes.size()) - 1;
    }

    cond::ValueKind kind(int index) const { return cond::valueKind(m_expression, index, m_atoms.symbols()); }

    std::string text(int index) const
    {
        return cond::print(rootedAt(m_expression, index));
    }

    int opaque(int index) { return add(Formula::Op::Atom, m_atoms.opaqueAtom(m_expression, index, text(index))); }

    int node(int index)
    {
        if (m_leaves.count(index))
            return add(Formula::Op::Leaf, index);
        const cond::Node& n = m_expression.at(index);
        switch (n.kind) {
        case cond::NodeKind::BoolLiteral:
            return add(equalsIgnoreCase(n.text, "TRUE") ? Formula::Op::True : Formula::Op::False);
        case cond::NodeKind::Variable: {
            const int variable = m_atoms.variableIndex(n.text);
            if (variable >= 0 && m_atoms.variableType(variable) == IecType::Bool)
                return add(Formula::Op::Atom, m_atoms.booleanAtom(variable));
            return opaque(index);
        }
        case cond::NodeKind::Unary:
            if (n.unaryOp == cond::UnaryOp::Not)
                return add(Formula::Op::Not, node(n.operand));
            return opaque(index);
        case cond::NodeKind::Binary: return binary(index, n);
        default: return opaque(index);
        }
    }

    int binary(int index, const cond::Node& n)
    {
        switch (n.binaryOp) {
        case cond::BinaryOp::And: return add(Formula::Op::And, node(n.left), node(n.right));
        case cond::BinaryOp::Or: return add(Formula::Op::Or, node(n.left), node(n.right));
        case cond::BinaryOp::Xor: return add(Formula::Op::Xor, node(n.left), node(n.right));
        default: break;
        }
        if (!isComparison(n.binaryOp))
            return opaque(index);
        const bool booleans = kind(n.left) == cond::ValueKind::Bool && kind(n.right) == cond::ValueKind::Bool;
        if (booleans && n.binaryOp == cond::BinaryOp::Equal)
            return add(Formula::Op::Equal, node(n.left), node(n.right));
        if (booleans && n.binaryOp == cond::BinaryOp::NotEqual)
            return add(Formula::Op::Xor, node(n.left), node(n.right));
        if (booleans)
            return opaque(index);
        return comparison(index, n);
    }

    // variable <op> constant, constant <op> variable, constant <op> constant.
    int comparison(int index, const cond::Node& n)
    {
        const bool leftConstant = !containsVariable(m_expression, n.left);
        const bool rightConstant = !containsVariable(m_expression, n.right);
        if (leftConstant && rightConstant) {
            const bool value = cond::isTrue(cond::evaluate(rootedAt(m_expression, index), {}));
            return add(value ? Formula::Op::True : Formula::Op::False);
        }
        const bool leftVariable = m_expression.at(n.left).kind == cond::NodeKind::Variable;
        const bool rightVariable = m_expression.at(n.right).kind == cond::NodeKind::Variable;
        Relation relation = relationOf(n.binaryOp);
        int variableNode = -1;
        int constantNode = -1;
        if (leftVariable && rightConstant) {
            variableNode = n.left;
            constantNode = n.right;
        } else if (rightVariable && leftConstant) {
            variableNode = n.right;
            constantNode = n.left;
            relation = mirrored(relation);
        } else {
            return opaque(index);
        }
        const int variable = m_atoms.variableIndex(m_expression.at(variableNode).text);
        if (variable < 0 || !isNumericType(m_atoms.variableType(variable)))
            return opaque(index);
        const cond::Value constant = cond::evaluate(rootedAt(m_expression, constantNode), {});
        if (std::holds_alternative<bool>(constant))
            return opaque(index);
        const IecType type = m_atoms.variableType(variable);
        const bool wideInteger = type == IecType::Lint || type == IecType::Ulint;
        if (wideInteger && std::holds_alternative<double>(constant)
            && !(std::fabs(std::get<double>(constant)) < kExactIntegerLimit))
            return opaque(index);
        if (std::holds_alternative<double>(constant) && std::isnan(std::get<double>(constant)))
            return opaque(index);
        return add(Formula::Op::Atom, m_atoms.comparisonAtom(variable, relation, constant, text(index)));
    }

    const cond::Expression& m_expression;
    const std::set<int>& m_leaves;
    AtomTable& m_atoms;
    Formula m_formula;
};

void addIntegerCandidates(std::vector<cond::Value>& out, IntegerRange range, const cond::Value& constant)
{
    auto push = [&](long double value) {
        if (value < static_cast<long double>(range.low) || value > static_cast<long double>(range.high))
            return;
        out.push_back(static_cast<std::int64_t>(value));
    };
    long double base = 0;
    if (const auto* i = std::get_if<std::int64_t>(&constant))
        base = static_cast<long double>(*i);
    else
        base = std::floor(static_cast<long double>(std::get<double>(constant)));
    for (int delta = -1; delta <= 2; ++delta)
        push(base + delta);
}

std::vector<cond::Value> integerRepresentatives(IecType type, const std::vector<const Atom*>& comparisons)
{
    const IntegerRange range = integerRange(type);
    std::vector<cond::Value> out{cond::Value{range.low}, cond::Value{range.high}};
    for (const Atom* atom : comparisons)
        addIntegerCandidates(out, range, atom->constant);
    return out;
}

std::vector<cond::Value> realRepresentatives(IecType type, const std::vector<const Atom*>& comparisons)
{
    const double limit = realLimit(type);
    std::vector<double> points;
    for (const Atom* atom : comparisons) {
        const double c = toDouble(atom->constant);
        if (c >= -limit && c <= limit)
            points.push_back(c);
    }
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    std::vector<cond::Value> out{cond::Value{-limit}, cond::Value{limit}};
    for (std::size_t i = 0; i < points.size(); ++i) {
        out.push_back(points[i]);
        if (i + 1 < points.size()) {
            const double middle = points[i] / 2 + points[i + 1] / 2;
            if (middle > points[i] && middle < points[i + 1])
                out.push_back(middle);
        }
    }
    if (!points.empty()) {
        // Just outside the extremes: a round value when there is one.
        const double below = points.front() - 1 < points.front() ? points.front() - 1
                                                                 : std::nextafter(points.front(), -limit);
        const double above = points.back() + 1 > points.back() ? points.back() + 1
                                                               : std::nextafter(points.back(), limit);
        if (below >= -limit && below < points.front())
            out.push_back(below);
        if (above <= limit && above > points.back())
            out.push_back(above);
    }
    return out;
}

cond::Value valueOfType(IecType type, const cond::Value& value)
{
    if (type == IecType::Bool)
        return cond::isTrue(value);
    if (isRealType(type))
        return toDouble(value);
    if (const auto* i = std::get_if<std::int64_t>(&value))
        return *i;
    return static_cast<std::int64_t>(toDouble(value));
}

// Rounder values first: they make readable scenarios.
double niceness(const cond::Value& value)
{
    const double d = std::fabs(toDouble(value));
    const double fraction = std::fabs(toDouble(value) - std::round(toDouble(value)));
    return d + (fraction > 0 ? 0.5 : 0.0);
}

std::vector<cond::Value> candidatesFor(const AtomTable& atoms, int variable, const cond::Value& current,
                                       const std::vector<cond::Value>& extra)
{
    std::vector<const Atom*> comparisons;
    for (const Atom& atom : atoms.atoms()) {
        if (atom.kind == Atom::Kind::Comparison && atom.variable == variable)
            comparisons.push_back(&atom);
    }
    const IecType type = atoms.variableType(variable);
    std::vector<cond::Value> pool = representatives(type, comparisons);
    pool.push_back(valueOfType(type, cond::Value{std::int64_t{0}}));
    pool.push_back(valueOfType(type, cond::Value{std::int64_t{1}}));
    for (const cond::Value& value : extra)
        pool.push_back(valueOfType(type, value));
    std::stable_sort(pool.begin(), pool.end(),
                     [](const cond::Value& a, const cond::Value& b) { return niceness(a) < niceness(b); });
    std::vector<cond::Value> out{current};
    for (const cond::Value& value : pool) {
        if (std::find(out.begin(), out.end(), value) == out.end())
            out.push_back(value);
    }
    // Keep only values of the type's range.
    out.erase(std::remove_if(out.begin(), out.end(),
                             [&](const cond::Value& value) {
                                 if (isRealType(type))
                                     return !(std::fabs(toDouble(value)) <= realLimit(type));
                                 const IntegerRange range = integerRange(type);
                                 const auto* i = std::get_if<std::int64_t>(&value);
                                 return !i || *i < range.low || *i > range.high;
                             }),
              out.end());
    return out;
}

bool fits(const AtomTable& atoms, int variable, const cond::Value& value,
          const std::vector<std::pair<int, bool>>& required)
{
    for (const auto& [index, truth] : required) {
        const Atom& atom = atoms.atom(index);
        if (atom.kind == Atom::Kind::Comparison && atom.variable == variable && holds(atom, value) != truth)
            return false;
    }
    return true;
}

// Tries combinations of candidate values of the variables the unmet opaque
// atoms read.
bool searchOpaque(const AtomTable& atoms, const std::vector<std::pair<int, bool>>& required,
                  std::vector<cond::Value>& values)
{
    auto opaqueHold = [&] {
        for (const auto& [index, truth] : required) {
            const Atom& atom = atoms.atom(index);
            if (atom.kind == Atom::Kind::Opaque && evaluateOpaque(atoms, atom, values) != truth)
                return false;
        }
        return true;
    };
    if (opaqueHold())
        return true;
    std::vector<int> involved;
    std::vector<cond::Value> constants;
    for (const auto& [index, truth] : required) {
        const Atom& atom = atoms.atom(index);
        if (atom.kind != Atom::Kind::Opaque)
            continue;
        for (int variable : atom.reads) {
            if (std::find(involved.begin(), involved.end(), variable) == involved.end()
                && atoms.variableType(variable) != IecType::Bool)
                involved.push_back(variable);
        }
        for (const cond::Node& node : atom.expression.nodes) {
            if (node.kind == cond::NodeKind::IntegerLiteral || node.kind == cond::NodeKind::RealLiteral) {
                const cond::Value c = cond::evaluate(
                    rootedAt(atom.expression, static_cast<int>(&node - atom.expression.nodes.data())), {});
                constants.push_back(c);
                constants.push_back(cond::Value{toDouble(c) + 1});
                constants.push_back(cond::Value{toDouble(c) - 1});
            }
        }
    }
    std::vector<std::vector<cond::Value>> choices;
    for (int variable : involved) {
        std::vector<cond::Value> options;
        for (const cond::Value& value :
             candidatesFor(atoms, variable, values[static_cast<std::size_t>(variable)], constants)) {
            if (fits(atoms, variable, value, required))
                options.push_back(value);
        }
        if (options.empty())
            return false;
        if (options.size() > 12)
            options.resize(12);
        choices.push_back(std::move(options));
    }
    // Odometer over the choices, at most a bounded number of tries.
    std::vector<std::size_t> digit(choices.size(), 0);
    for (int tries = 0; tries < 50'000; ++tries) {
        for (std::size_t i = 0; i < choices.size(); ++i)
            values[static_cast<std::size_t>(involved[i])] = choices[i][digit[i]];
        if (opaqueHold())
            return true;
        std::size_t i = 0;
        while (i < digit.size() && ++digit[i] == choices[i].size())
            digit[i++] = 0;
        if (i == digit.size())
            return false;
    }
    return false;
}

} // namespace

// --- AtomTable ---------------------------------------------------------------

AtomTable::AtomTable(const std::vector<Variable>& variables)
    : m_variables(std::make_unique<std::vector<Variable>>(variables)),
      m_symbols(std::make_unique<SymbolTable>(*m_variables))
{
    for (const Variable& variable : *m_variables) {
        m_names.push_back(variable.name);
        m_types.push_back(variable.type);
        std::optional<cond::Value> initial = cond::parseValue(variable.type, variable.defaultValue);
        if (!initial)
            initial = cond::parseValue(variable.type, "");
        m_initial.push_back(initial ? *initial : valueOfType(variable.type, cond::Value{std::int64_t{0}}));
    }
}

int AtomTable::variableIndex(std::string_view name) const
{
    const Variable* variable = m_symbols->find(name);
    return variable ? static_cast<int>(variable - m_variables->data()) : -1;
}

int AtomTable::booleanAtom(int variable)
{
    for (std::size_t i = 0; i < m_atoms.size(); ++i) {
        if (m_atoms[i].kind == Atom::Kind::Boolean && m_atoms[i].variable == variable)
            return static_cast<int>(i);
    }
    Atom atom;
    atom.kind = Atom::Kind::Boolean;
    atom.variable = variable;
    atom.text = variableName(variable);
    m_atoms.push_back(std::move(atom));
    return static_cast<int>(m_atoms.size()) - 1;
}

int AtomTable::comparisonAtom(int variable, Relation relation, const cond::Value& constant, std::string text)
{
    for (std::size_t i = 0; i < m_atoms.size(); ++i) {
        const Atom& atom = m_atoms[i];
        if (atom.kind == Atom::Kind::Comparison && atom.variable == variable && atom.relation == relation
            && atom.constant == constant)
            return static_cast<int>(i);
    }
    Atom atom;
    atom.kind = Atom::Kind::Comparison;
    atom.variable = variable;
    atom.relation = relation;
    atom.constant = constant;
    atom.text = std::move(text);
    m_atoms.push_back(std::move(atom));
    return static_cast<int>(m_atoms.size()) - 1;
}

int AtomTable::opaqueAtom(const cond::Expression& expression, int node, std::string text)
{
    // The same text reads the same variables the same way: one atom.
    const std::string key = toUpperAscii(text);
    for (std::size_t i = 0; i < m_atoms.size(); ++i) {
        if (m_atoms[i].kind == Atom::Kind::Opaque && toUpperAscii(m_atoms[i].text) == key)
            return static_cast<int>(i);
    }
    Atom atom;
    atom.kind = Atom::Kind::Opaque;
    atom.expression = rootedAt(expression, node);
    atom.text = std::move(text);
    std::vector<int> pending{node};
    while (!pending.empty()) {
        const cond::Node& n = expression.at(pending.back());
        pending.pop_back();
        if (n.kind == cond::NodeKind::Variable) {
            const int variable = variableIndex(n.text);
            if (variable >= 0 && std::find(atom.reads.begin(), atom.reads.end(), variable) == atom.reads.end())
                atom.reads.push_back(variable);
        } else if (n.kind == cond::NodeKind::Unary) {
            pending.push_back(n.operand);
        } else if (n.kind == cond::NodeKind::Binary) {
            pending.push_back(n.left);
            pending.push_back(n.right);
        }
    }
    m_atoms.push_back(std::move(atom));
    return static_cast<int>(m_atoms.size()) - 1;
}

// --- Formula -------------------------------------------------------------------

std::vector<int> Formula::atoms() const
{
    std::vector<int> out;
    for (const Node& node : nodes) {
        if (node.op == Op::Atom)
            out.push_back(node.a);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

std::vector<int> Formula::leaves() const
{
    std::vector<int> out;
    for (const Node& node : nodes) {
        if (node.op == Op::Leaf)
            out.push_back(node.a);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

Formula compileCondition(const cond::Expression& expression, const std::set<int>& leaves, AtomTable& atoms)
{
    return Compiler(expression, leaves, atoms).run();
}

bool holds(const Atom& atom, const cond::Value& value)
{
    if (std::holds_alternative<double>(value) || std::holds_alternative<double>(atom.constant))
        return compare(atom.relation, toDouble(value), toDouble(atom.constant));
    const auto* left = std::get_if<std::int64_t>(&value);
    const auto* right = std::get_if<std::int64_t>(&atom.constant);
    if (!left || !right)
        return compare(atom.relation, toDouble(value), toDouble(atom.constant));
    return compare(atom.relation, *left, *right);
}

std::vector<cond::Value> representatives(IecType type, const std::vector<const Atom*>& comparisons)
{
    if (isRealType(type))
        return realRepresentatives(type, comparisons);
    if (isIntegerType(type))
        return integerRepresentatives(type, comparisons);
    return {cond::Value{false}, cond::Value{true}};
}

std::vector<cond::Value> nonFiniteReals()
{
    constexpr double infinity = std::numeric_limits<double>::infinity();
    return {cond::Value{-infinity}, cond::Value{infinity}, cond::Value{std::numeric_limits<double>::quiet_NaN()}};
}

// --- Numeric domains -------------------------------------------------------------

namespace {

std::vector<bool> truthsOf(const AtomTable& table, const std::vector<int>& atoms, const cond::Value& value)
{
    std::vector<bool> truths;
    truths.reserve(atoms.size());
    for (int atom : atoms)
        truths.push_back(holds(table.atom(atom), value));
    return truths;
}

bool valueLess(const cond::Value& a, const cond::Value& b)
{
    const auto* x = std::get_if<std::int64_t>(&a);
    const auto* y = std::get_if<std::int64_t>(&b);
    return x && y ? *x < *y : toDouble(a) < toDouble(b);
}

NumericDomain domainOf(const AtomTable& table, int variable, std::vector<int> atoms)
{
    NumericDomain domain;
    domain.variable = variable;
    std::sort(atoms.begin(), atoms.end());
    domain.atoms = std::move(atoms);
    std::vector<const Atom*> comparisons;
    for (int atom : domain.atoms)
        comparisons.push_back(&table.atom(atom));
    std::vector<cond::Value> values = representatives(table.variableType(variable), comparisons);
    std::sort(values.begin(), values.end(), valueLess);
    // Values with the same truth values are one region (`<> 5` has two
    // intervals and one region).
    std::set<std::vector<bool>> seen;
    for (const cond::Value& value : values) {
        if (seen.insert(truthsOf(table, domain.atoms, value)).second)
            domain.regionValues.push_back(value);
    }
    return domain;
}

} // namespace

int NumericDomain::bitCount() const
{
    int bits = 0;
    while ((std::size_t{1} << bits) < regionCount())
        ++bits;
    return bits;
}

std::size_t NumericDomain::regionOf(const AtomTable& table, const cond::Value& value) const
{
    const std::vector<bool> truths = truthsOf(table, atoms, value);
    for (std::size_t region = 0; region < regionValues.size(); ++region) {
        if (truthsOf(table, atoms, regionValues[region]) == truths)
            return region;
    }
    return 0; // cannot happen: the regions cover every value of the type
}

std::vector<NumericDomain> numericDomains(const AtomTable& table, const std::vector<int>& atoms)
{
    std::vector<int> order;
    std::map<int, std::vector<int>> byVariable;
    for (int atom : atoms) {
        const Atom& a = table.atom(atom);
        if (a.kind != Atom::Kind::Comparison)
            continue;
        std::vector<int>& list = byVariable[a.variable];
        if (list.empty())
            order.push_back(a.variable);
        if (std::find(list.begin(), list.end(), atom) == list.end())
            list.push_back(atom);
    }
    std::vector<NumericDomain> domains;
    for (int variable : order)
        domains.push_back(domainOf(table, variable, byVariable[variable]));
    return domains;
}

// --- Encoder -------------------------------------------------------------------

Encoder::Encoder(bdd::Manager& manager, const AtomTable& atoms, std::vector<int> atomVariable,
                 std::vector<NumericDomain> domains)
    : m_manager(manager), m_atoms(atoms), m_atomVariable(std::move(atomVariable)), m_domains(std::move(domains))
{
}

int Encoder::variableOf(int atom) const
{
    return atom >= 0 && static_cast<std::size_t>(atom) < m_atomVariable.size()
        ? m_atomVariable[static_cast<std::size_t>(atom)]
        : -1;
}

const NumericDomain* Encoder::domainOf(int variable) const
{
    for (const NumericDomain& domain : m_domains) {
        if (domain.variable == variable)
            return &domain;
    }
    return nullptr;
}

// The regions where `inside` holds, over the domain's bits; region indices
// beyond the last region are FALSE. Linear in the regions.
bdd::Ref Encoder::regionFunction(const NumericDomain& domain, const std::function<bool(std::size_t region)>& inside)
{
    const int bits = domain.bitCount();
    const std::size_t regions = domain.regionCount();
    auto build = [&](auto&& self, int depth, std::size_t prefix) -> bdd::Ref {
        if ((prefix << (bits - depth)) >= regions)
            return bdd::kFalse;
        if (depth == bits)
            return inside(prefix) ? bdd::kTrue : bdd::kFalse;
        const bdd::Ref low = self(self, depth + 1, prefix << 1);
        const bdd::Ref high = self(self, depth + 1, (prefix << 1) | 1);
        return m_manager.ite(m_manager.variable(domain.bits[static_cast<std::size_t>(depth)]), high, low);
    };
    return build(build, 0, 0);
}

bdd::Ref Encoder::atomFunction(int atom)
{
    const Atom& a = m_atoms.atom(atom);
    if (a.kind != Atom::Kind::Comparison) {
        const int variable = variableOf(atom);
        return variable >= 0 ? m_manager.variable(variable) : bdd::kFalse;
    }
    if (auto found = m_comparisons.find(atom); found != m_comparisons.end())
        return found->second;
    const NumericDomain* domain = domainOf(a.variable);
    // Every atom of an encoded formula has variables (the caller lays out
    // formula.atoms()); FALSE keeps a mistake from crashing.
    if (!domain || std::find(domain->atoms.begin(), domain->atoms.end(), atom) == domain->atoms.end())
        return bdd::kFalse;
    const bdd::Ref function = regionFunction(
        *domain, [&](std::size_t region) { return holds(a, domain->regionValues[region]); });
    m_comparisons.emplace(atom, function);
    return function;
}

bdd::Ref Encoder::encode(const Formula& formula, const std::function<bdd::Ref(int leafNode)>& leaf)
{
    std::vector<bdd::Ref> value(formula.nodes.size(), bdd::kFalse);
    for (std::size_t i = 0; i < formula.nodes.size(); ++i) {
        const Formula::Node& node = formula.nodes[i];
        auto operand = [&](int index) { return value[static_cast<std::size_t>(index)]; };
        switch (node.op) {
        case Formula::Op::False: value[i] = bdd::kFalse; break;
        case Formula::Op::True: value[i] = bdd::kTrue; break;
        case Formula::Op::Atom: value[i] = atomFunction(node.a); break;
        case Formula::Op::Leaf: value[i] = leaf ? leaf(node.a) : bdd::kFalse; break;
        case Formula::Op::Not: value[i] = m_manager.negate(operand(node.a)); break;
        case Formula::Op::And: value[i] = m_manager.conj(operand(node.a), operand(node.b)); break;
        case Formula::Op::Or: value[i] = m_manager.disj(operand(node.a), operand(node.b)); break;
        case Formula::Op::Xor: value[i] = m_manager.exclusive(operand(node.a), operand(node.b)); break;
        case Formula::Op::Equal: value[i] = m_manager.equivalent(operand(node.a), operand(node.b)); break;
        }
    }
    return formula.root >= 0 ? value[static_cast<std::size_t>(formula.root)] : bdd::kFalse;
}

bdd::Ref Encoder::theory()
{
    bdd::Ref result = bdd::kTrue;
    for (const NumericDomain& domain : m_domains)
        result = m_manager.conj(result, regionFunction(domain, [](std::size_t) { return true; }));
    return result;
}

// --- Concrete values -------------------------------------------------------------

bool evaluateOpaque(const AtomTable& atoms, const Atom& atom, const std::vector<cond::Value>& values)
{
    const cond::Value result = cond::evaluate(atom.expression, [&](int node) -> cond::Value {
        const int variable = atoms.variableIndex(atom.expression.at(node).text);
        return variable >= 0 ? values[static_cast<std::size_t>(variable)] : cond::Value{false};
    });
    return cond::isTrue(result);
}

std::optional<std::vector<cond::Value>> concretize(const AtomTable& atoms,
                                                   const std::vector<std::pair<int, bool>>& required,
                                                   std::vector<cond::Value> current)
{
    current.resize(atoms.variableCount(), cond::Value{false});
    std::vector<bool> constrained(atoms.variableCount(), false);
    for (const auto& [index, truth] : required) {
        const Atom& atom = atoms.atom(index);
        if (atom.kind == Atom::Kind::Boolean)
            current[static_cast<std::size_t>(atom.variable)] = truth;
        else if (atom.kind == Atom::Kind::Comparison)
            constrained[static_cast<std::size_t>(atom.variable)] = true;
    }
    for (std::size_t variable = 0; variable < atoms.variableCount(); ++variable) {
        if (!constrained[variable])
            continue;
        const int v = static_cast<int>(variable);
        bool found = false;
        for (const cond::Value& value : candidatesFor(atoms, v, current[variable], {})) {
            if (fits(atoms, v, value, required)) {
                current[variable] = value;
                found = true;
                break;
            }
        }
        if (!found)
            return std::nullopt;
    }
    if (!searchOpaque(atoms, required, current))
        return std::nullopt;
    return current;
}

// --- One condition -----------------------------------------------------------------

namespace {

struct SingleCondition {
    AtomTable atoms;
    Formula formula;
    std::unique_ptr<bdd::Manager> manager;
    std::unique_ptr<Encoder> encoder;
    bdd::Ref theory = bdd::kTrue;
    bdd::Ref condition = bdd::kFalse;

    SingleCondition(const cond::Expression& expression, const std::vector<Variable>& variables) : atoms(variables)
    {
        formula = compileCondition(expression, {}, atoms);
        const std::vector<int> used = formula.atoms();
        std::vector<NumericDomain> domains = numericDomains(atoms, used);
        int next = 0;
        std::vector<int> mapping(atoms.atoms().size(), -1);
        for (int atom : used) {
            if (atoms.atom(atom).kind != Atom::Kind::Comparison)
                mapping[static_cast<std::size_t>(atom)] = next++;
        }
        for (NumericDomain& domain : domains) {
            for (int bit = 0; bit < domain.bitCount(); ++bit)
                domain.bits.push_back(next++);
        }
        manager = std::make_unique<bdd::Manager>(next, std::size_t{1} << 22);
        encoder = std::make_unique<Encoder>(*manager, atoms, mapping, std::move(domains));
        theory = encoder->theory();
        condition = encoder->encode(formula, {});
    }

    // The truth of every atom of the formula under a diagram assignment.
    std::vector<std::pair<int, bool>> truths(const std::vector<bool>& assignment)
    {
        std::vector<std::pair<int, bool>> out;
        for (int atom : formula.atoms())
            out.emplace_back(atom, manager->evaluate(encoder->atomFunction(atom), assignment));
        return out;
    }
};

} // namespace

bool isSatisfiable(const cond::Expression& expression, const std::vector<Variable>& variables)
{
    try {
        SingleCondition single(expression, variables);
        return single.manager->conj(single.theory, single.condition) != bdd::kFalse;
    } catch (const bdd::NodeLimitExceeded&) {
        return true; // not decided: never claim unsatisfiable
    }
}

bool isValid(const cond::Expression& expression, const std::vector<Variable>& variables)
{
    try {
        SingleCondition single(expression, variables);
        return single.manager->conj(single.theory, single.manager->negate(single.condition)) == bdd::kFalse;
    } catch (const bdd::NodeLimitExceeded&) {
        return false;
    }
}

std::optional<std::vector<cond::Value>> findValuation(const cond::Expression& expression,
                                                      const std::vector<Variable>& variables)
{
    try {
        SingleCondition single(expression, variables);
        const bdd::Ref both = single.manager->conj(single.theory, single.condition);
        std::vector<bool> assignment;
        if (!single.manager->pick(both, {}, assignment))
            return std::nullopt;
        auto values = concretize(single.atoms, single.truths(assignment), single.atoms.initialValues());
        if (!values)
            return std::nullopt;
        const cond::Value result = cond::evaluate(expression, [&](int node) -> cond::Value {
            const int variable = single.atoms.variableIndex(expression.at(node).text);
            return variable >= 0 ? (*values)[static_cast<std::size_t>(variable)] : cond::Value{false};
        });
        if (!cond::isTrue(result))
            return std::nullopt;
        return values;
    } catch (const bdd::NodeLimitExceeded&) {
        return std::nullopt;
    }
}

} // namespace core::sat
