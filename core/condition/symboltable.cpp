#include "core/condition/symboltable.h"

#include "core/model/model.h"

namespace core {

std::size_t SymbolTable::FoldedHash::operator()(std::string_view name) const
{
    // FNV-1a over the upper-case letters.
    std::size_t hash = 14695981039346656037ULL;
    for (const char c : name) {
        const char folded = c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
        hash = (hash ^ static_cast<unsigned char>(folded)) * 1099511628211ULL;
    }
    return hash;
}

SymbolTable::SymbolTable(const std::vector<Variable>& variables)
{
    m_byName.reserve(variables.size());
    for (const Variable& variable : variables)
        m_byName.emplace(variable.name, &variable); // the first of a name wins
}

const Variable* SymbolTable::find(std::string_view name) const
{
    const auto found = m_byName.find(name);
    return found == m_byName.end() ? nullptr : found->second;
}

} // namespace core
