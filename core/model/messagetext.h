#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace core {

// How the diagnostics and messages write names.

// A name or text quoted: 'Start'.
inline std::string quoted(std::string_view text)
{
    std::string result;
    result.reserve(text.size() + 2);
    result.append("'").append(text).append("'");
    return result;
}

// Names as the messages list them: "a, b, c".
inline std::string joined(const std::vector<std::string>& items)
{
    std::string result;
    for (const std::string& item : items) {
        if (!result.empty())
            result += ", ";
        result += item;
    }
    return result;
}

} // namespace core
