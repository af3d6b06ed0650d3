#pragma once

// A small reduced ordered binary decision diagram (ROBDD) package for the
// verifier (core/verification/verification.h).
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
// node 1 is TRUE. A Manager refuses to grow beyond its Budget: it throws
// NodeLimitExceeded when the budget's nodes (shared by every manager of one
// verification, so that the memory of the whole run is bounded) are used
// up, and TimeLimitExceeded once the budget's deadline has passed (checked
// every few thousand recursive steps, so even an operation that creates no
// node stops in time). The verifier reports what it could not decide.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace core::bdd {

using Ref = std::uint32_t;
inline constexpr Ref kFalse = 0;
inline constexpr Ref kTrue = 1;

struct BudgetExceeded : std::runtime_error {
    using std::runtime_error::runtime_error;
};
struct NodeLimitExceeded : BudgetExceeded {
    NodeLimitExceeded() : BudgetExceeded("decision diagram node limit exceeded") {}
};
struct TimeLimitExceeded : BudgetExceeded {
    TimeLimitExceeded() : BudgetExceeded("decision diagram time limit exceeded") {}
};

// What the managers sharing it may spend. Not thread-safe: one budget per
// verification, which runs in one thread.
struct Budget {
    std::size_t nodeLimit = 0; // nodes of all managers together
    std::size_t nodesUsed = 0;
    std::optional<std::chrono::steady_clock::time_point> deadline;

    bool expired() const { return deadline && std::chrono::steady_clock::now() >= *deadline; }
};

class Manager {
public:
    // A manager with a budget of its own.
    Manager(int variableCount, std::size_t nodeLimit);
    // A manager spending a shared budget, which must outlive it.
    Manager(int variableCount, Budget& budget);
    ~Manager(); // gives its nodes back to the budget
    Manager(const Manager&) = delete;
    Manager& operator=(const Manager&) = delete;

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
    void step(); // one recursive step: polls the deadline now and then
    void growCache();
    std::uint32_t maskId(const std::vector<bool>& mask);
    bool cached(std::uint32_t op, Ref a, Ref b, Ref c, Ref& result) const;
    void remember(std::uint32_t op, Ref a, Ref b, Ref c, Ref result);
    Ref cofactor(Ref f, std::uint32_t variable, bool high) const;
    Ref existsRec(Ref f, const std::vector<bool>& mask, std::uint32_t op);
    Ref andExistsRec(Ref f, Ref g, const std::vector<bool>& mask, std::uint32_t op, std::uint32_t existsOp);
    Ref renameRec(Ref f, const std::vector<int>& mapping, std::unordered_map<Ref, Ref>& memo);

    int m_variableCount;
    Budget m_ownBudget;
    Budget& m_budget;
    std::uint32_t m_steps = 0;
    std::vector<Node> m_nodes;
    std::unordered_map<Key, Ref, KeyHash> m_unique;
    std::vector<CacheEntry> m_cache;
    std::vector<std::vector<bool>> m_masks;
};

} // namespace core::bdd
