#include "core/verification/statestore.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <stdexcept>

namespace core::explore {

namespace {

constexpr std::size_t kStoreBlockBytes = std::size_t{1} << 16;
constexpr std::size_t kEdgeBlock = std::size_t{1} << 13;

void putVarint(std::string& out, std::size_t value)
{
    while (value >= 0x80) {
        out.push_back(static_cast<char>((value & 0x7F) | 0x80));
        value >>= 7;
    }
    out.push_back(static_cast<char>(value));
}

std::size_t getVarint(const unsigned char*& at)
{
    std::size_t value = 0;
    for (int shift = 0;; shift += 7) {
        const unsigned char byte = *at++;
        value |= static_cast<std::size_t>(byte & 0x7F) << shift;
        if (!(byte & 0x80))
            return value;
    }
}

std::size_t varintSize(std::size_t value)
{
    std::size_t size = 1;
    while (value >= 0x80) {
        value >>= 7;
        ++size;
    }
    return size;
}

std::uint64_t hashBytes(std::string_view bytes)
{
    std::uint64_t h = 0x9E3779B97F4A7C15ULL ^ bytes.size();
    std::size_t i = 0;
    for (; i + 8 <= bytes.size(); i += 8) {
        std::uint64_t word;
        std::memcpy(&word, bytes.data() + i, 8);
        h = (h ^ word) * 0xFF51AFD7ED558CCDULL;
        h ^= h >> 29;
    }
    std::uint64_t tail = 0;
    std::memcpy(&tail, bytes.data() + i, bytes.size() - i);
    h = (h ^ tail) * 0xC4CEB9FE1A85EC53ULL;
    h ^= h >> 32;
    h *= 0xFF51AFD7ED558CCDULL;
    h ^= h >> 29;
    return h;
}

} // namespace

void encodeState(std::string_view state, std::string& out)
{
    const auto* bytes = reinterpret_cast<const unsigned char*>(state.data());
    const std::size_t n = state.size();
    std::size_t nonzero = 0, above = 0, sparseBytes = 0, zeros = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (bytes[i] == 0) {
            ++zeros;
            continue;
        }
        ++nonzero;
        above += bytes[i] > 1 ? 1 : 0;
        sparseBytes += varintSize(zeros) + 1;
        zeros = 0;
    }
    const std::size_t denseSize = (n + 7) / 8 + (nonzero + 7) / 8 + above;
    sparseBytes += varintSize(nonzero);
    out.clear();
    if (denseSize <= sparseBytes) {
        out.push_back(0);
        putVarint(out, n);
        const std::size_t nonzeroMap = out.size();
        const std::size_t aboveMap = nonzeroMap + (n + 7) / 8;
        out.resize(aboveMap + (nonzero + 7) / 8, '\0');
        std::size_t k = 0;
        for (std::size_t i = 0; i < n; ++i) {
            if (bytes[i] == 0)
                continue;
            out[nonzeroMap + i / 8] = static_cast<char>(out[nonzeroMap + i / 8] | (1 << (i % 8)));
            if (bytes[i] > 1) {
                out[aboveMap + k / 8] = static_cast<char>(out[aboveMap + k / 8] | (1 << (k % 8)));
                out.push_back(static_cast<char>(bytes[i]));
            }
            ++k;
        }
        return;
    }
    out.push_back(1);
    putVarint(out, n);
    putVarint(out, nonzero);
    zeros = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (bytes[i] == 0) {
            ++zeros;
            continue;
        }
        putVarint(out, zeros);
        out.push_back(static_cast<char>(bytes[i]));
        zeros = 0;
    }
}

std::size_t decodeState(const unsigned char* encoded, std::string& out)
{
    const unsigned char* at = encoded;
    const unsigned char form = *at++;
    const std::size_t n = getVarint(at);
    out.assign(n, '\0');
    if (form == 0) {
        const unsigned char* nonzeroMap = at;
        std::size_t nonzero = 0;
        for (std::size_t b = 0; b < (n + 7) / 8; ++b)
            nonzero += static_cast<std::size_t>(std::popcount(static_cast<unsigned>(nonzeroMap[b])));
        const unsigned char* aboveMap = nonzeroMap + (n + 7) / 8;
        const unsigned char* values = aboveMap + (nonzero + 7) / 8;
        std::size_t k = 0;
        for (std::size_t i = 0; i < n; ++i) {
            if (!(nonzeroMap[i / 8] & (1 << (i % 8))))
                continue;
            out[i] = (aboveMap[k / 8] & (1 << (k % 8))) ? static_cast<char>(*values++) : char{1};
            ++k;
        }
        return static_cast<std::size_t>(values - encoded);
    }
    const std::size_t nonzero = getVarint(at);
    std::size_t i = 0;
    for (std::size_t k = 0; k < nonzero; ++k) {
        i += getVarint(at);
        out[i++] = static_cast<char>(*at++);
    }
    return static_cast<std::size_t>(at - encoded);
}

StateStore::StateStore() = default;
StateStore::~StateStore() = default;

const unsigned char* StateStore::encodedAt(std::uint32_t index) const
{
    const std::uint64_t where = m_where[index];
    const unsigned char* at = m_blocks[static_cast<std::size_t>(where >> 32)].get() + (where & 0xFFFFFFFFULL);
    (void)getVarint(at); // its size
    return at;
}

std::size_t StateStore::encodedSizeAt(std::uint32_t index) const
{
    const std::uint64_t where = m_where[index];
    const unsigned char* at = m_blocks[static_cast<std::size_t>(where >> 32)].get() + (where & 0xFFFFFFFFULL);
    return getVarint(at);
}

std::uint64_t StateStore::slotOf(std::string_view encoded, std::uint64_t hash) const
{
    const std::uint64_t mask = m_slots.size() - 1;
    const auto tag = static_cast<std::uint8_t>(hash >> 56);
    for (std::uint64_t slot = hash & mask;; slot = (slot + 1) & mask) {
        const std::uint32_t held = m_slots[slot];
        if (held == 0)
            return slot;
        if (m_tags[slot] == tag && encodedSizeAt(held - 1) == encoded.size()
            && std::memcmp(encodedAt(held - 1), encoded.data(), encoded.size()) == 0)
            return slot;
    }
}

void StateStore::grow()
{
    const std::size_t capacity = m_slots.empty() ? 16 : 2 * m_slots.size();
    std::vector<std::uint32_t> slots(capacity, 0);
    std::vector<std::uint8_t> tags(capacity, 0);
    const std::uint64_t mask = capacity - 1;
    for (std::uint32_t held : m_slots) {
        if (held == 0)
            continue;
        const std::string_view encoded(reinterpret_cast<const char*>(encodedAt(held - 1)), encodedSizeAt(held - 1));
        const std::uint64_t hash = hashBytes(encoded);
        std::uint64_t slot = hash & mask;
        while (slots[slot] != 0)
            slot = (slot + 1) & mask;
        slots[slot] = held;
        tags[slot] = static_cast<std::uint8_t>(hash >> 56);
    }
    m_slots.swap(slots);
    m_tags.swap(tags);
}

std::pair<std::uint32_t, bool> StateStore::insert(std::string_view state)
{
    if (m_where.size() >= 0xFFFFFFFEULL)
        throw std::length_error("state store: more than 2^32 - 2 states");
    if (4 * (m_where.size() + 1) > 3 * m_slots.size())
        grow();
    encodeState(state, m_scratch);
    const std::uint64_t hash = hashBytes(m_scratch);
    const std::uint64_t slot = slotOf(m_scratch, hash);
    if (m_slots[slot] != 0)
        return {m_slots[slot] - 1, false};
    const std::size_t size = varintSize(m_scratch.size()) + m_scratch.size();
    if (m_blocks.empty() || m_used + size > m_blockSize) {
        m_blockSize = std::max(kStoreBlockBytes, size);
        m_blocks.push_back(std::make_unique<unsigned char[]>(m_blockSize));
        m_used = 0;
    }
    unsigned char* at = m_blocks.back().get() + m_used;
    std::string length;
    putVarint(length, m_scratch.size());
    std::memcpy(at, length.data(), length.size());
    std::memcpy(at + length.size(), m_scratch.data(), m_scratch.size());
    const auto index = static_cast<std::uint32_t>(m_where.size());
    m_where.push_back((static_cast<std::uint64_t>(m_blocks.size() - 1) << 32) | m_used);
    m_used += size;
    m_slots[slot] = index + 1;
    m_tags[slot] = static_cast<std::uint8_t>(hash >> 56);
    return {index, true};
}

std::int64_t StateStore::find(std::string_view state) const
{
    if (m_slots.empty())
        return -1;
    std::string encoded;
    encodeState(state, encoded);
    const std::uint32_t held = m_slots[slotOf(encoded, hashBytes(encoded))];
    return held == 0 ? -1 : static_cast<std::int64_t>(held) - 1;
}

void StateStore::decodeInto(std::size_t index, std::string& out) const
{
    (void)decodeState(encodedAt(static_cast<std::uint32_t>(index)), out);
}

std::string StateStore::at(std::size_t index) const
{
    std::string out;
    decodeInto(index, out);
    return out;
}

std::size_t StateStore::bytes() const
{
    std::size_t total = m_where.bytes() + m_slots.capacity() * sizeof(std::uint32_t) + m_tags.capacity()
        + m_blocks.capacity() * sizeof(void*);
    total += m_blocks.empty() ? 0 : (m_blocks.size() - 1) * kStoreBlockBytes + m_blockSize;
    return total;
}

void EdgeStore::addState()
{
    m_first.push_back(Span{});
}

void EdgeStore::add(std::size_t state, const StateEdge& edge)
{
    Span& span = m_first[state];
    if (span.count == 0) {
        span.block = m_blocks.empty() ? 0 : static_cast<std::uint32_t>(m_blocks.size() - 1);
        span.offset = static_cast<std::uint32_t>(m_used);
    }
    if (m_blocks.empty() || m_used == m_blockSizes.back()) {
        // A new block; the state's edges so far move with it, so that they stay contiguous.
        const std::size_t size = std::max(kEdgeBlock, 2 * static_cast<std::size_t>(span.count) + 1);
        auto block = std::make_unique<StateEdge[]>(size);
        if (span.count > 0)
            std::copy_n(m_blocks[span.block].get() + span.offset, span.count, block.get());
        m_blocks.push_back(std::move(block));
        m_blockSizes.push_back(size);
        span.block = static_cast<std::uint32_t>(m_blocks.size() - 1);
        span.offset = 0;
        m_used = span.count;
    }
    m_blocks[span.block][span.offset + span.count] = edge;
    ++span.count;
    ++m_used;
    ++m_edges;
}

std::span<const StateEdge> EdgeStore::of(std::size_t state) const
{
    const Span& span = m_first[state];
    if (span.count == 0)
        return {};
    return {m_blocks[span.block].get() + span.offset, span.count};
}

std::size_t EdgeStore::bytes() const
{
    std::size_t total = m_first.bytes() + m_blocks.capacity() * sizeof(void*) + m_blockSizes.capacity() * sizeof(std::size_t);
    for (std::size_t size : m_blockSizes)
        total += size * sizeof(StateEdge);
    return total;
}

} // namespace core::explore
