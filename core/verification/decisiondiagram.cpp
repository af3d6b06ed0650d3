#include "core/verification/decisiondiagram.h"

#include <algorithm>
#include <cmath>

namespace core::bdd {

namespace {

// Operation codes in the computed table; quantifications add 8 x mask id.
enum : std::uint32_t { OpIte = 1, OpExists = 2, OpAndExists = 3 };
// The computed table starts small (a manager per step, most steps need a few
// hundred nodes) and grows with the diagram up to a bound: a table much
// smaller than the diagram makes the operations recompute shared
// subresults again and again, which costs exponential time.
constexpr std::size_t kInitialCacheSize = std::size_t{1} << 12;
constexpr std::size_t kMaxCacheSize = std::size_t{1} << 21;
// Recursive steps between two looks at the clock.
constexpr std::uint32_t kStepsPerClockCheck = 1u << 13;

} // namespace

Manager::Manager(int variableCount, std::size_t nodeLimit)
    : m_variableCount(std::max(variableCount, 0)), m_ownBudget{std::max<std::size_t>(nodeLimit, 16), 0, {}},
      m_budget(m_ownBudget), m_cache(kInitialCacheSize)
{
    const auto terminal = static_cast<std::uint32_t>(m_variableCount);
    m_nodes.push_back(Node{terminal, kFalse, kFalse});
    m_nodes.push_back(Node{terminal, kTrue, kTrue});
}

Manager::Manager(int variableCount, Budget& budget)
    : m_variableCount(std::max(variableCount, 0)), m_budget(budget), m_cache(kInitialCacheSize)
{
    const auto terminal = static_cast<std::uint32_t>(m_variableCount);
    m_nodes.push_back(Node{terminal, kFalse, kFalse});
    m_nodes.push_back(Node{terminal, kTrue, kTrue});
}

Manager::~Manager()
{
    m_budget.nodesUsed -= std::min(m_budget.nodesUsed, m_nodes.size() - 2);
}

Ref Manager::make(std::uint32_t variable, Ref low, Ref high)
{
    if (low == high)
        return low;
    const Key key{variable, low, high};
    auto found = m_unique.find(key);
    if (found != m_unique.end())
        return found->second;
    if (m_budget.nodesUsed >= m_budget.nodeLimit)
        throw NodeLimitExceeded();
    ++m_budget.nodesUsed;
    const auto ref = static_cast<Ref>(m_nodes.size());
    m_nodes.push_back(Node{variable, low, high});
    m_unique.emplace(key, ref);
    if (m_nodes.size() > 2 * m_cache.size() && m_cache.size() < kMaxCacheSize)
        growCache();
    return ref;
}

void Manager::growCache()
{
    // Entries are placed by hash of the table size: start afresh.
    m_cache.assign(m_cache.size() * 4, CacheEntry{});
}

void Manager::step()
{
    if (++m_steps % kStepsPerClockCheck == 0 && m_budget.expired())
        throw TimeLimitExceeded();
}

Ref Manager::variable(int index)
{
    return make(static_cast<std::uint32_t>(index), kFalse, kTrue);
}

Ref Manager::literal(int index, bool value)
{
    return value ? make(static_cast<std::uint32_t>(index), kFalse, kTrue)
                 : make(static_cast<std::uint32_t>(index), kTrue, kFalse);
}

bool Manager::cached(std::uint32_t op, Ref a, Ref b, Ref c, Ref& result) const
{
    std::uint64_t h = op;
    h = h * 0x9E3779B97F4A7C15ull ^ a;
    h = h * 0x9E3779B97F4A7C15ull ^ b;
    h = h * 0x9E3779B97F4A7C15ull ^ c;
    const CacheEntry& entry = m_cache[(h ^ (h >> 31)) & (m_cache.size() - 1)];
    if (entry.op == op && entry.a == a && entry.b == b && entry.c == c) {
        result = entry.result;
        return true;
    }
    return false;
}

void Manager::remember(std::uint32_t op, Ref a, Ref b, Ref c, Ref result)
{
    std::uint64_t h = op;
    h = h * 0x9E3779B97F4A7C15ull ^ a;
    h = h * 0x9E3779B97F4A7C15ull ^ b;
    h = h * 0x9E3779B97F4A7C15ull ^ c;
    m_cache[(h ^ (h >> 31)) & (m_cache.size() - 1)] = CacheEntry{op, a, b, c, result};
}

Ref Manager::cofactor(Ref f, std::uint32_t variable, bool high) const
{
    const Node& node = m_nodes[f];
    if (node.variable != variable)
        return f;
    return high ? node.high : node.low;
}

Ref Manager::ite(Ref f, Ref g, Ref h)
{
    if (f == kTrue)
        return g;
    if (f == kFalse)
        return h;
    if (g == h)
        return g;
    if (g == kTrue && h == kFalse)
        return f;
    Ref result;
    if (cached(OpIte, f, g, h, result))
        return result;
    step();
    const std::uint32_t top = std::min({m_nodes[f].variable, m_nodes[g].variable, m_nodes[h].variable});
    const Ref low = ite(cofactor(f, top, false), cofactor(g, top, false), cofactor(h, top, false));
    const Ref high = ite(cofactor(f, top, true), cofactor(g, top, true), cofactor(h, top, true));
    result = make(top, low, high);
    remember(OpIte, f, g, h, result);
    return result;
}

Ref Manager::negate(Ref f)
{
    return ite(f, kFalse, kTrue);
}

Ref Manager::conj(Ref f, Ref g)
{
    return ite(f, g, kFalse);
}

Ref Manager::disj(Ref f, Ref g)
{
    return ite(f, kTrue, g);
}

Ref Manager::exclusive(Ref f, Ref g)
{
    return ite(f, negate(g), g);
}

Ref Manager::equivalent(Ref f, Ref g)
{
    return ite(f, g, negate(g));
}

std::uint32_t Manager::maskId(const std::vector<bool>& mask)
{
    for (std::size_t i = 0; i < m_masks.size(); ++i) {
        if (m_masks[i] == mask)
            return static_cast<std::uint32_t>(i);
    }
    m_masks.push_back(mask);
    return static_cast<std::uint32_t>(m_masks.size() - 1);
}

Ref Manager::existsRec(Ref f, const std::vector<bool>& mask, std::uint32_t op)
{
    if (f <= kTrue)
        return f;
    Ref result;
    if (cached(op, f, 0, 0, result))
        return result;
    step();
    const Node node = m_nodes[f];
    const Ref low = existsRec(node.low, mask, op);
    const bool quantified = node.variable < mask.size() && mask[node.variable];
    if (quantified && low == kTrue) {
        result = kTrue;
    } else {
        const Ref high = existsRec(node.high, mask, op);
        result = quantified ? disj(low, high) : make(node.variable, low, high);
    }
    remember(op, f, 0, 0, result);
    return result;
}

Ref Manager::exists(Ref f, const std::vector<bool>& mask)
{
    return existsRec(f, mask, OpExists + 8 * maskId(mask));
}

Ref Manager::andExistsRec(Ref f, Ref g, const std::vector<bool>& mask, std::uint32_t op, std::uint32_t existsOp)
{
    if (f == kFalse || g == kFalse)
        return kFalse;
    if (f == kTrue && g == kTrue)
        return kTrue;
    if (f == kTrue || f == g)
        return existsRec(g, mask, existsOp);
    if (g == kTrue)
        return existsRec(f, mask, existsOp);
    if (f > g)
        std::swap(f, g);
    Ref result;
    if (cached(op, f, g, 0, result))
        return result;
    step();
    const std::uint32_t top = std::min(m_nodes[f].variable, m_nodes[g].variable);
    const bool quantified = top < mask.size() && mask[top];
    const Ref low = andExistsRec(cofactor(f, top, false), cofactor(g, top, false), mask, op, existsOp);
    if (quantified && low == kTrue) {
        result = kTrue;
    } else {
        const Ref high = andExistsRec(cofactor(f, top, true), cofactor(g, top, true), mask, op, existsOp);
        result = quantified ? disj(low, high) : make(top, low, high);
    }
    remember(op, f, g, 0, result);
    return result;
}

Ref Manager::andExists(Ref f, Ref g, const std::vector<bool>& mask)
{
    const std::uint32_t id = maskId(mask);
    return andExistsRec(f, g, mask, OpAndExists + 8 * id, OpExists + 8 * id);
}

Ref Manager::restrict(Ref f, int index, bool value)
{
    std::vector<bool> mask(static_cast<std::size_t>(m_variableCount), false);
    mask[static_cast<std::size_t>(index)] = true;
    return andExists(f, literal(index, value), mask);
}

Ref Manager::renameRec(Ref f, const std::vector<int>& mapping, std::unordered_map<Ref, Ref>& memo)
{
    if (f <= kTrue)
        return f;
    auto found = memo.find(f);
    if (found != memo.end())
        return found->second;
    const Node node = m_nodes[f];
    const Ref low = renameRec(node.low, mapping, memo);
    const Ref high = renameRec(node.high, mapping, memo);
    const int target = node.variable < mapping.size() && mapping[node.variable] >= 0
        ? mapping[node.variable]
        : static_cast<int>(node.variable);
    // ite is correct whatever the order of the new variable relative to the
    // renamed children.
    const Ref result = ite(variable(target), high, low);
    memo.emplace(f, result);
    return result;
}

Ref Manager::rename(Ref f, const std::vector<int>& mapping)
{
    std::unordered_map<Ref, Ref> memo;
    return renameRec(f, mapping, memo);
}

bool Manager::pick(Ref f, const std::vector<int>& preferred, std::vector<bool>& assignment) const
{
    assignment.assign(static_cast<std::size_t>(m_variableCount), false);
    for (std::size_t v = 0; v < assignment.size() && v < preferred.size(); ++v)
        assignment[v] = preferred[v] > 0;
    if (f == kFalse)
        return false;
    while (f > kTrue) {
        const Node& node = m_nodes[f];
        const bool want = assignment[node.variable];
        const Ref wanted = want ? node.high : node.low;
        if (wanted != kFalse) {
            f = wanted;
        } else {
            assignment[node.variable] = !want;
            f = want ? node.low : node.high;
        }
    }
    return true;
}

bool Manager::evaluate(Ref f, const std::vector<bool>& assignment) const
{
    while (f > kTrue) {
        const Node& node = m_nodes[f];
        f = node.variable < assignment.size() && assignment[node.variable] ? node.high : node.low;
    }
    return f == kTrue;
}

long double Manager::count(Ref f, const std::vector<bool>& counted)
{
    // countedBelow[v]: counted variables with index >= v.
    std::vector<int> countedFrom(static_cast<std::size_t>(m_variableCount) + 1, 0);
    for (int v = m_variableCount - 1; v >= 0; --v)
        countedFrom[static_cast<std::size_t>(v)] = countedFrom[static_cast<std::size_t>(v) + 1]
            + (static_cast<std::size_t>(v) < counted.size() && counted[static_cast<std::size_t>(v)] ? 1 : 0);
    std::unordered_map<Ref, long double> memo;
    // Assignments of the counted variables at or below the node's variable.
    auto rec = [&](auto&& self, Ref node) -> long double {
        if (node == kFalse)
            return 0.0L;
        if (node == kTrue)
            return 1.0L;
        auto found = memo.find(node);
        if (found != memo.end())
            return found->second;
        const Node& n = m_nodes[node];
        auto child = [&](Ref c) {
            const int gap = countedFrom[n.variable + 1] - countedFrom[m_nodes[c].variable];
            return self(self, c) * std::pow(2.0L, gap);
        };
        const long double result = child(n.low) + child(n.high);
        memo.emplace(node, result);
        return result;
    };
    const int above = countedFrom[0] - countedFrom[m_nodes[f].variable];
    return rec(rec, f) * std::pow(2.0L, above);
}

} // namespace core::bdd
