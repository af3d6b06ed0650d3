#pragma once

#include "core/model/iectypes.h"

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
    std::unordered_map<std::string, const Variable*> m_byUpperName;
};

} // namespace core
