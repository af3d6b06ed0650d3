#include "core/condition/symboltable.h"

#include "core/model/model.h"

namespace core {

SymbolTable::SymbolTable(const std::vector<Variable>& variables)
{
    m_byUpperName.reserve(variables.size());
    for (const Variable& variable : variables)
        m_byUpperName.emplace(toUpperAscii(variable.name), &variable);
}

const Variable* SymbolTable::find(std::string_view name) const
{
    auto found = m_byUpperName.find(toUpperAscii(name));
    return found == m_byUpperName.end() ? nullptr : found->second;
}

} // namespace core
