#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>

namespace core {

// Byte range [begin, end) in a piece of user text (a condition).
struct Span {
    std::size_t begin = 0;
    std::size_t end = 0;

    std::size_t length() const { return end - begin; }
    friend bool operator==(const Span&, const Span&) = default;
};

// The part of the text a span designates, clamped so a bad span never reads
// outside the text.
inline std::string excerpt(std::string_view text, const Span& span)
{
    const std::size_t begin = std::min(span.begin, text.size());
    const std::size_t end = std::clamp(span.end, begin, text.size());
    return std::string(text.substr(begin, end - begin));
}

} // namespace core
