#include "core/verification/stepspace.h"

#include <algorithm>

namespace core::verify {

namespace {

bool anyWaits(const CompiledStep& step)
{
    return std::any_of(step.transitions.begin(), step.transitions.end(),
                       [](const CompiledTransition& t) { return t.transition->waitsForComplete; });
}

int booleanAtomOf(const sat::AtomTable& atoms, int variable)
{
    for (std::size_t i = 0; i < atoms.atoms().size(); ++i) {
        const sat::Atom& atom = atoms.atoms()[i];
        if (atom.kind == sat::Atom::Kind::Boolean && atom.variable == variable)
            return static_cast<int>(i);
    }
    return -1;
}

} // namespace

StepSpace::StepSpace(const CompiledStep& step, const sat::AtomTable& atoms, bdd::Budget& budget,
                     const std::function<bool()>& cancelled)
    : m_step(step), m_atoms(atoms), m_cancelled(cancelled), m_budget(budget)
{
    assignVariables(atoms);
    buildFormulas(atoms);
    explore();
}

void StepSpace::checkCancelled() const
{
    if (m_cancelled && m_cancelled())
        throw Cancelled{};
}

int StepSpace::atomVariable(int atom) const
{
    return atom >= 0 && static_cast<std::size_t>(atom) < m_atomVar.size() ? m_atomVar[static_cast<std::size_t>(atom)]
                                                                          : -1;
}

// The order puts each token's now and after variables next to the input it
// captures, so the update relation stays linear in the number of tokens, and
// the bits of one numeric variable's region together, at its first
// comparison, so the constraint on them stays linear too.
void StepSpace::assignVariables(const sat::AtomTable& atoms)
{
    int next = 0;
    m_atomVar.assign(atoms.atoms().size(), -1);
    m_tokenVar.assign(m_step.groups.size(), -1);
    m_primedVar.assign(m_step.groups.size(), -1);
    if (nested() && m_step.freeComplete && anyWaits(m_step))
        m_completeVar = next++;

    std::vector<int> comparisons;
    for (const CompiledTransition& transition : m_step.transitions) {
        for (const sat::Formula::Node& node : transition.formula.nodes) {
            if (node.op == sat::Formula::Op::Atom)
                comparisons.push_back(node.a);
        }
    }
    std::vector<sat::NumericDomain> domains = sat::numericDomains(atoms, comparisons);
    std::vector<bool> domainPlaced(domains.size(), false);

    std::function<void(int)> placeAtom;
    auto placeGroup = [&](int group) {
        const auto g = static_cast<std::size_t>(group);
        if (m_tokenVar[g] >= 0)
            return;
        m_tokenVar[g] = next++;
        m_primedVar[g] = next++;
        placeAtom(booleanAtomOf(atoms, m_step.groups[g].variable));
    };
    auto placeDomain = [&](int variable) {
        for (std::size_t d = 0; d < domains.size(); ++d) {
            if (domains[d].variable != variable || domainPlaced[d])
                continue;
            domainPlaced[d] = true;
            for (int bit = 0; bit < domains[d].bitCount(); ++bit)
                domains[d].bits.push_back(next++);
        }
    };
    placeAtom = [&](int atom) {
        if (atom < 0 || std::find(m_usedAtoms.begin(), m_usedAtoms.end(), atom) != m_usedAtoms.end())
            return;
        m_usedAtoms.push_back(atom);
        const sat::Atom& a = atoms.atom(atom);
        if (a.kind == sat::Atom::Kind::Comparison) {
            placeDomain(a.variable);
            return;
        }
        if (a.kind == sat::Atom::Kind::Boolean) {
            for (std::size_t g = 0; g < m_step.groups.size(); ++g) {
                if (m_step.groups[g].variable == a.variable && m_tokenVar[g] < 0) {
                    m_tokenVar[g] = next++;
                    m_primedVar[g] = next++;
                }
            }
        }
        m_atomVar[static_cast<std::size_t>(atom)] = next++;
    };
    for (std::size_t t = 0; t < m_step.transitions.size(); ++t) {
        for (const sat::Formula::Node& node : m_step.transitions[t].formula.nodes) {
            if (node.op == sat::Formula::Op::Atom) {
                placeAtom(node.a);
            } else if (node.op == sat::Formula::Op::Leaf) {
                auto found = m_step.leafGroup.find({static_cast<int>(t), node.a});
                if (found != m_step.leafGroup.end())
                    placeGroup(found->second);
            }
        }
    }
    for (std::size_t g = 0; g < m_step.groups.size(); ++g)
        placeGroup(static_cast<int>(g));

    m_manager = std::make_unique<bdd::Manager>(next, m_budget);
    const auto count = static_cast<std::size_t>(next);
    m_inputMask.assign(count, false);
    m_tokenMask.assign(count, false);
    m_toPrimed.assign(count, -1);
    m_fromPrimed.assign(count, -1);
    for (int atom : m_usedAtoms) {
        if (m_atomVar[static_cast<std::size_t>(atom)] >= 0)
            m_inputMask[static_cast<std::size_t>(m_atomVar[static_cast<std::size_t>(atom)])] = true;
    }
    for (const sat::NumericDomain& domain : domains) {
        for (int bit : domain.bits)
            m_inputMask[static_cast<std::size_t>(bit)] = true;
    }
    if (m_completeVar >= 0)
        m_inputMask[static_cast<std::size_t>(m_completeVar)] = true;
    m_imageMask = m_inputMask;
    m_preimageMask = m_inputMask;
    for (std::size_t g = 0; g < m_step.groups.size(); ++g) {
        const auto now = static_cast<std::size_t>(m_tokenVar[g]);
        const auto after = static_cast<std::size_t>(m_primedVar[g]);
        m_tokenMask[now] = true;
        m_imageMask[now] = true;
        m_preimageMask[after] = true;
        m_toPrimed[now] = m_primedVar[g];
        m_fromPrimed[after] = m_tokenVar[g];
    }
    m_encoder = std::make_unique<sat::Encoder>(*m_manager, atoms, m_atomVar, std::move(domains));
}

bool StepSpace::atomHolds(int atom, const std::vector<bool>& assignment)
{
    return m_manager->evaluate(m_encoder->atomFunction(atom), assignment);
}

std::vector<int> StepSpace::preferredAssignment(const std::vector<cond::Value>& values)
{
    std::vector<int> preferred(static_cast<std::size_t>(m_manager->variableCount()), 0);
    for (int atom : m_usedAtoms) {
        const sat::Atom& a = m_atoms.atom(atom);
        const int variable = m_atomVar[static_cast<std::size_t>(atom)];
        if (a.kind == sat::Atom::Kind::Boolean)
            preferred[static_cast<std::size_t>(variable)] = cond::isTrue(values[static_cast<std::size_t>(a.variable)]);
        else if (a.kind == sat::Atom::Kind::Opaque)
            preferred[static_cast<std::size_t>(variable)] = sat::evaluateOpaque(m_atoms, a, values);
    }
    for (const sat::NumericDomain& domain : m_encoder->domains()) {
        const std::size_t region = domain.regionOf(m_atoms, values[static_cast<std::size_t>(domain.variable)]);
        const int bits = domain.bitCount();
        for (int bit = 0; bit < bits; ++bit)
            preferred[static_cast<std::size_t>(domain.bits[static_cast<std::size_t>(bit)])] =
                (region >> (bits - 1 - bit)) & 1 ? 1 : 0;
    }
    return preferred;
}

void StepSpace::buildFormulas(const sat::AtomTable& atoms)
{
    bdd::Manager& m = *m_manager;
    sat::Encoder& encoder = *m_encoder;
    m_theory = encoder.theory();
    const bdd::Ref complete = m_completeVar >= 0 ? m.variable(m_completeVar) : bdd::kTrue;
    bdd::Ref earlier = bdd::kFalse;
    for (std::size_t t = 0; t < m_step.transitions.size(); ++t) {
        const CompiledTransition& transition = m_step.transitions[t];
        auto leaf = [&](int node) {
            auto found = m_step.leafGroup.find({static_cast<int>(t), node});
            return found == m_step.leafGroup.end()
                ? bdd::kFalse
                : m.variable(m_tokenVar[static_cast<std::size_t>(found->second)]);
        };
        bdd::Ref condition = encoder.encode(transition.formula, leaf);
        if (transition.transition->waitsForComplete)
            condition = m.conj(condition, complete);
        m_gated.push_back(condition);
        m_fires.push_back(m.conj(m_theory, m.conj(condition, m.negate(earlier))));
        earlier = m.disj(earlier, condition);
        checkCancelled();
    }
    m_noFire = m.conj(m_theory, m.negate(earlier));
    for (std::size_t g = 0; g < m_step.groups.size(); ++g) {
        const TokenGroup& group = m_step.groups[g];
        const int atom = booleanAtomOf(atoms, group.variable);
        const bdd::Ref literal = m.literal(m_atomVar[static_cast<std::size_t>(atom)], !group.negated);
        const bdd::Ref captured = m.disj(m.variable(m_tokenVar[g]), literal);
        m_update = m.conj(m_update, m.equivalent(m.variable(m_primedVar[g]), captured));
        m_zero = m.conj(m_zero, m.literal(m_tokenVar[g], false));
    }
}

bdd::Ref StepSpace::image(bdd::Ref set)
{
    bdd::Manager& m = *m_manager;
    const bdd::Ref next = m.andExists(m.conj(set, m_noFire), m_update, m_imageMask);
    return m.rename(next, m_fromPrimed);
}

bdd::Ref StepSpace::preimage(bdd::Ref set)
{
    bdd::Manager& m = *m_manager;
    return m.andExists(m.conj(m_update, m.rename(set, m_toPrimed)), m_noFire, m_preimageMask);
}

bdd::Ref StepSpace::possible(bdd::Ref f)
{
    return m_manager->exists(f, m_inputMask);
}

bdd::Ref StepSpace::canReach(bdd::Ref target)
{
    bdd::Manager& m = *m_manager;
    bdd::Ref result = target;
    for (;;) {
        checkCancelled();
        const bdd::Ref grown = m.disj(result, preimage(result));
        if (grown == result)
            return result;
        result = grown;
    }
}

void StepSpace::explore()
{
    bdd::Manager& m = *m_manager;
    if (!nested()) {
        m_any = m_zero;
        return;
    }
    // Tokens only grow while the step stays active, so this ends after at
    // most one layer per token group (plus one).
    bdd::Ref frontier = image(m_zero);
    while (frontier != bdd::kFalse) {
        checkCancelled();
        m_layers.push_back(frontier);
        m_reached = m.disj(m_reached, frontier);
        frontier = m.conj(image(frontier), m.negate(m_reached));
    }
    m_any = m.disj(m_zero, m_reached);
}

bdd::Ref StepSpace::tokenCube(const std::vector<bool>& values, bool primed)
{
    bdd::Ref cube = bdd::kTrue;
    for (std::size_t g = 0; g < m_step.groups.size() && g < values.size(); ++g)
        cube = m_manager->conj(cube, m_manager->literal(primed ? m_primedVar[g] : m_tokenVar[g], values[g]));
    return cube;
}

std::vector<bool> StepSpace::tokensOf(const std::vector<bool>& assignment) const
{
    std::vector<bool> values;
    for (int variable : m_tokenVar)
        values.push_back(assignment[static_cast<std::size_t>(variable)]);
    return values;
}

long double StepSpace::configurationCount()
{
    if (!nested())
        return 1.0L;
    return 1.0L + m_manager->count(m_reached, m_tokenMask);
}

} // namespace core::verify
