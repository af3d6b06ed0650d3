#pragma once

// A table of stable names for an enum's values (the names that data written
// to files or to Diagnostic::arguments carries), looked up both ways.

#include <cstddef>
#include <optional>
#include <string_view>

namespace core {

template <typename Enum>
struct EnumName {
    Enum value;
    std::string_view name;
};

// The name of `value`; empty when the table lacks it.
template <typename Enum, std::size_t N>
constexpr std::string_view nameIn(const EnumName<Enum> (&table)[N], Enum value)
{
    for (const EnumName<Enum>& entry : table) {
        if (entry.value == value)
            return entry.name;
    }
    return {};
}

// The value named `name`; nullopt when no entry has that name.
template <typename Enum, std::size_t N>
constexpr std::optional<Enum> valueIn(const EnumName<Enum> (&table)[N], std::string_view name)
{
    for (const EnumName<Enum>& entry : table) {
        if (entry.name == name)
            return entry.value;
    }
    return std::nullopt;
}

} // namespace core
