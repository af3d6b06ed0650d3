#pragma once

#include <cstddef>

namespace core {

// Byte range [begin, end) in a piece of user text (a condition).
struct Span {
    std::size_t begin = 0;
    std::size_t end = 0;

    std::size_t length() const { return end - begin; }
    friend bool operator==(const Span&, const Span&) = default;
};

} // namespace core
