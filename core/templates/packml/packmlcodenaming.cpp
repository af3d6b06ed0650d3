#include "core/templates/packml/packmlcodenaming.h"

#include "core/codegen/nestedprogram.h"
#include "core/model/iectypes.h"
#include "core/templates/packml/packtags.h"

#include <algorithm>

namespace core::packml {

namespace {

std::vector<std::string> modeNamesOf(const PackmlProgram& program)
{
    std::vector<std::string> names;
    for (const ProgramMode& mode : program.modes)
        names.push_back(mode.name);
    return names;
}

} // namespace

std::vector<std::string> declaredGlobalNames(const PackmlProgram& program)
{
    const std::vector<std::string> modeNames = modeNamesOf(program);
    const std::size_t userCount = program.variables.size() - packTags().size();
    std::vector<std::string> names;
    std::vector<std::string> taken; // upper case, every name declared so far
    for (const Variable& variable : program.variables)
        taken.push_back(toUpperAscii(variable.name));
    for (std::size_t i = 0; i < program.variables.size(); ++i) {
        const std::string& name = program.variables[i].name;
        const bool usable = i >= userCount
                            || (identifierProblem(name) == IdentifierProblem::None
                                && !isReservedName(name, program.programName, modeNames));
        if (usable) {
            names.push_back(name);
            continue;
        }
        const std::string base = "Invalid_Name_" + std::to_string(i + 1);
        std::string candidate = base;
        for (int suffix = 2; std::find(taken.begin(), taken.end(), toUpperAscii(candidate)) != taken.end(); ++suffix)
            candidate = base + "_" + std::to_string(suffix);
        taken.push_back(toUpperAscii(candidate));
        names.push_back(std::move(candidate));
    }
    return names;
}

PackmlNaming::PackmlNaming(const PackmlProgram& program, const std::vector<std::string>& declared, Dialect dialect)
    : m_program(program)
    , m_declared(declared)
    , m_symbols(program.variables)
    , m_dialect(dialect)
    , m_read(program.variables.size(), false)
{
}

std::string PackmlNaming::qualified(std::string name) const
{
    return m_dialect == Dialect::Codesys ? std::string(kCodesysGlobalList) + "." + name : name;
}

std::string PackmlNaming::global(std::string_view name)
{
    const Variable* variable = m_symbols.find(name);
    if (!variable)
        return qualified(std::string(name)); // not reached: usable texts name declared variables
    const auto slot = static_cast<std::size_t>(variable - m_program.variables.data());
    m_read[slot] = true;
    return qualified(m_declared[slot]);
}

std::string PackmlNaming::edgeMemory(std::string_view name) const
{
    const Variable* variable = m_symbols.find(name);
    return qualified(edgeMemoryName(variable ? variable->name : std::string(name)));
}

std::vector<PlcVariable> PackmlNaming::readVariables() const
{
    return readUserVariables(m_program.variables.size());
}

std::vector<PlcVariable> PackmlNaming::readUserVariables(std::size_t userCount) const
{
    std::vector<PlcVariable> result;
    for (std::size_t i = 0; i < std::min(userCount, m_read.size()); ++i) {
        if (m_read[i])
            result.push_back(PlcVariable{m_declared[i], std::string(iecTypeName(m_program.variables[i].type)), {}, {}});
    }
    return result;
}

} // namespace core::packml
