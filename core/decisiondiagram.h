#pragma once

// A small reduced ordered binary decision diagram (ROBDD) package for the
// verifier (core/verification.h).
//
// Why our own and not a library: the verifier needs a few thousand nodes per
// step, a dozen operations (and, or, not, exists, relational product,
// renaming, one satisfying assignment, model counting) and no garbage
// collection (a Manager lives for one step's analysis and is dropped whole).
// Debian's BuDDy or CUDD would add a C dependency with global state (BuDDy
// has one global manager, which would forbid verifying two models in two
// threads) for a few hundred lines of code; SAT solvers (minisat) cannot
// represent the sets of reachable token configurations the verifier
// computes.
//
// Variables are numbered 0..n-1; 0 is the top of the order. Node 0 is FALSE,
// node 1 is TRUE. A Manager refuses to grow beyond its node limit by
// throwing NodeLimitExceeded (the verifier reports "not exhaustive").

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace core::bdd {

using Ref = std::uint32_t;
inline constexpr Ref kFalse = 0;
inline constexpr Ref kTrue = 1;

struct NodeLimitExceeded : std::runtime_error {
    NodeLimitExceeded() : std::runtime_error("decision diagram node limit exceeded") {}
};

class Manager {
public:
    Manager(int variableCount, std::size_t nodeLimit);

    int variableCount() const { return m_variableCount; }
    std::size_t nodeCount() const { return m_nodes.size(); }

    Ref constant(bool value) const { return value ? kTrue : kFalse; }
    Ref variable(int index);          // the function "variable index is TRUE"
    Ref literal(int index, bool value); // variable(index), or its negation when !value

    Ref negate(Ref f);
    Ref conj(Ref f, Ref g);
    Ref disj(Ref f, Ref g);
    Ref exclusive(Ref f, Ref g);
    Ref equivalent(Ref f, Ref g);
    Ref ite(Ref f, Ref g, Ref h);

    // Quantifies away the variables whose mask entry is true. Masks are
    // remembered by content, so passing the same mask again reuses results.
    Ref exists(Ref f, const std::vector<bool>& mask);
    // exists(conj(f, g), mask) without building the conjunction.
    Ref andExists(Ref f, Ref g, const std::vector<bool>& mask);
    // f with the variable fixed to the value.
    Ref restrict(Ref f, int index, bool value);
    // f with every variable v replaced by mapping[v] (-1: unchanged).
    Ref rename(Ref f, const std::vector<int>& mapping);

    // One satisfying assignment of a satisfiable f: `assignment` (one entry
    // per variable) gets the value of every variable; where f leaves a
    // variable free, or on the way down where both branches satisfy, the
    // preferred value wins (preferred[v] < 0: FALSE). False when f is FALSE.
    bool pick(Ref f, const std::vector<int>& preferred, std::vector<bool>& assignment) const;
    // The value of f under a full assignment.
    bool evaluate(Ref f, const std::vector<bool>& assignment) const;
    // The number of assignments to the counted variables that satisfy f; f
    // must depend on counted variables only.
    long double count(Ref f, const std::vector<bool>& counted);

    int topVariable(Ref f) const { return static_cast<int>(m_nodes[f].variable); }

private:
    struct Node {
        std::uint32_t variable;
        Ref low;
        Ref high;
    };
    struct Key {
        std::uint32_t variable;
        Ref low;
        Ref high;
        bool operator==(const Key& other) const
        {
            return variable == other.variable && low == other.low && high == other.high;
        }
    };
    struct KeyHash {
        std::size_t operator()(const Key& key) const
        {
            std::uint64_t h = key.variable;
            h = h * 0x9E3779B97F4A7C15ull ^ key.low;
            h = h * 0x9E3779B97F4A7C15ull ^ key.high;
            return static_cast<std::size_t>(h ^ (h >> 29));
        }
    };
    struct CacheEntry {
        std::uint32_t op = 0; // 0: empty
        Ref a = 0, b = 0, c = 0;
        Ref result = 0;
    };

    Ref make(std::uint32_t variable, Ref low, Ref high);
    std::uint32_t maskId(const std::vector<bool>& mask);
    bool cached(std::uint32_t op, Ref a, Ref b, Ref c, Ref& result) const;
    void remember(std::uint32_t op, Ref a, Ref b, Ref c, Ref result);
    Ref cofactor(Ref f, std::uint32_t variable, bool high) const;
    Ref existsRec(Ref f, const std::vector<bool>& mask, std::uint32_t op);
    Ref andExistsRec(Ref f, Ref g, const std::vector<bool>& mask, std::uint32_t op, std::uint32_t existsOp);
    Ref renameRec(Ref f, const std::vector<int>& mapping, std::unordered_map<Ref, Ref>& memo);

    int m_variableCount;
    std::size_t m_nodeLimit;
    std::vector<Node> m_nodes;
    std::unordered_map<Key, Ref, KeyHash> m_unique;
    std::vector<CacheEntry> m_cache;
    std::vector<std::vector<bool>> m_masks;
};

} // namespace core::bdd
