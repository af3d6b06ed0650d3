#pragma once

#include <string_view>

namespace core {

// Whether a condition, action or name holds nothing but white space: what
// every engine (checks, code, simulation) treats as left empty, so they all
// read the same characters as white space.
inline bool isBlank(std::string_view text)
{
    return text.find_first_not_of(" \t\r\n\f\v") == std::string_view::npos;
}

} // namespace core
