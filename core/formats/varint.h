#pragma once

// Integers as few bytes, for the byte strings that key a verifier's sets of
// states (core/machine/machinestatekey.cpp, core/verification/concretesearch.cpp):
// unsigned LEB128, seven bits a byte, the high bit set on all but the last,
// so that a small number costs one byte and a key stays prefix-free.

#include <cstdint>
#include <string>

namespace core {

inline void appendVarint(std::string& out, std::uint64_t value)
{
    while (value >= 0x80) {
        out.push_back(static_cast<char>((value & 0x7F) | 0x80));
        value >>= 7;
    }
    out.push_back(static_cast<char>(value));
}

// Zigzag: 0, -1, 1, -2... as 0, 1, 2, 3..., so that a small negative number
// is a small varint too.
inline std::uint64_t zigzag(std::int64_t value)
{
    return (static_cast<std::uint64_t>(value) << 1) ^ static_cast<std::uint64_t>(value >> 63);
}

} // namespace core
