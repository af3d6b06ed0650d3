#pragma once

#include "core/model/iectypes.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace core {

struct Variable;

// Case-insensitive lookup of the declared variables, as IEC compares names.
class SymbolTable {
public:
    SymbolTable() = default;
    explicit SymbolTable(const std::vector<Variable>& variables);

    // nullptr when no variable has this name (any case).
    const Variable* find(std::string_view name) const;

private:
    // ASCII case folded in the hash and the comparison, so that a lookup
    // (done for every name a condition reads) builds no upper-case copy.
    struct FoldedHash {
        using is_transparent = void;
        std::size_t operator()(std::string_view name) const;
    };
    struct FoldedEqual {
        using is_transparent = void;
        bool operator()(std::string_view a, std::string_view b) const { return equalsIgnoreCase(a, b); }
    };

    std::unordered_map<std::string, const Variable*, FoldedHash, FoldedEqual> m_byName;
};

} // namespace core
