#pragma once

// How the program explorer (programexplorer.cpp) keeps what it has explored,
// in few bytes per state (issue 36: at most 200 bytes per explored program
// state, hash table and links included):
// - StateStore: each distinct state once, encoded compactly (encodeState)
//   in large blocks, found again through an open-addressing hash table of
//   32-bit indices; decoded on demand.
// - ChunkedArray: a per-state array in blocks, which grows without copying
//   (a std::vector's doubling holds the old and the new array at once).
// - EdgeStore: the explored edges of each state, contiguous, in blocks.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace core::explore {

// An array that grows by blocks of 4,096 elements: no element moves, no
// reallocation copies the whole.
template <typename T>
class ChunkedArray {
public:
    static constexpr std::size_t kShift = 12;
    static constexpr std::size_t kBlock = std::size_t{1} << kShift;

    std::size_t size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    void push_back(const T& value)
    {
        if ((m_size & (kBlock - 1)) == 0)
            m_blocks.push_back(std::make_unique<T[]>(kBlock));
        m_blocks.back()[m_size & (kBlock - 1)] = value;
        ++m_size;
    }
    T& operator[](std::size_t i) { return m_blocks[i >> kShift][i & (kBlock - 1)]; }
    const T& operator[](std::size_t i) const { return m_blocks[i >> kShift][i & (kBlock - 1)]; }
    T& back() { return (*this)[m_size - 1]; }
    const T& back() const { return (*this)[m_size - 1]; }
    std::size_t bytes() const { return m_blocks.size() * kBlock * sizeof(T) + m_blocks.capacity() * sizeof(void*); }

private:
    std::vector<std::unique_ptr<T[]>> m_blocks;
    std::size_t m_size = 0;
};

// A state's bytes, encoded so that equal states and only they have equal
// encodings (the shorter of two forms, the first on a tie):
// - form 0, for dense states of mostly 0 and 1 bytes: the length (LEB128),
//   a bitmap of the nonzero bytes, a bitmap of those above 1 among them,
//   then those bytes;
// - form 1, for long sparse states (a GRAFCET of thousands of steps, few
//   active): the length, then for each nonzero byte the zeros before it
//   (LEB128) and the byte.
// `out` is replaced.
void encodeState(std::string_view state, std::string& out);
// The state `encoded` (what encodeState wrote) stands for; `out` is replaced.
// Returns the encoded bytes read.
std::size_t decodeState(const unsigned char* encoded, std::string& out);

class StateStore {
public:
    StateStore();
    ~StateStore();
    StateStore(const StateStore&) = delete;
    StateStore& operator=(const StateStore&) = delete;

    // The index of `state` (its rank among the distinct states added) and
    // whether it was added now.
    std::pair<std::uint32_t, bool> insert(std::string_view state);
    // The index of `state`, or -1 when it was never added.
    std::int64_t find(std::string_view state) const;
    // State `index`, decoded.
    std::string at(std::size_t index) const;
    void decodeInto(std::size_t index, std::string& out) const;
    std::size_t size() const { return m_where.size(); }
    // Heap bytes held (blocks, table, indices).
    std::size_t bytes() const;

private:
    const unsigned char* encodedAt(std::uint32_t index) const;
    std::size_t encodedSizeAt(std::uint32_t index) const;
    std::uint64_t slotOf(std::string_view encoded, std::uint64_t hash) const; // the slot holding it, or the empty one
    void grow();

    std::vector<std::unique_ptr<unsigned char[]>> m_blocks;
    std::size_t m_used = 0;      // bytes used in the last block
    std::size_t m_blockSize = 0; // bytes of the last block
    // Where each state's encoding starts: block (high 32 bits) and offset.
    ChunkedArray<std::uint64_t> m_where;
    // Open addressing, linear probing: index + 1 (0: empty), and 8 bits of
    // the hash that tell most other states apart without reading them.
    std::vector<std::uint32_t> m_slots;
    std::vector<std::uint8_t> m_tags;
    std::string m_scratch; // the encoding of the state looked up
};

// One explored scan from a state: the state it leads to, the GEMMA
// transition it fires (global index, -1 none), whether the active step's
// nested GRAFCET yielded Complete TRUE, whether it enters D1. 8 bytes.
struct StateEdge {
    std::uint32_t to = 0;
    std::int32_t fired : 30 = -1;
    std::uint32_t completeTrue : 1 = 0;
    std::uint32_t entersD1 : 1 = 0;
};

// The edges of each state, added state by state in index order: a state's
// edges are added only while no later state has any (the explorer explores
// states in order), so each state's edges stay contiguous.
class EdgeStore {
public:
    // A new state, without edges yet.
    void addState();
    // Adds `edge` to `state`: the last state added to, or one after it.
    void add(std::size_t state, const StateEdge& edge);
    std::span<const StateEdge> of(std::size_t state) const;
    std::size_t states() const { return m_first.size(); }
    std::size_t edges() const { return m_edges; }
    std::size_t bytes() const;

private:
    struct Span {
        std::uint32_t block = 0;
        std::uint32_t offset = 0;
        std::uint32_t count = 0;
    };
    std::vector<std::unique_ptr<StateEdge[]>> m_blocks;
    std::vector<std::size_t> m_blockSizes;
    std::size_t m_used = 0; // edges used in the last block
    ChunkedArray<Span> m_first;
    std::size_t m_edges = 0;
};

} // namespace core::explore
