#include "core/templates/packml/packmlprogramname.h"

#include "core/model/iectypes.h"
#include "core/templates/packml/packmlmodel.h"
#include "core/templates/packml/packmlrules.h"

#include <algorithm>

namespace core::packml {

namespace {

// GEMMA's generator names (GEMMA, its configuration...) are free in a PackML
// program; its own are isReservedName's.
bool isIdentifierOrGemmaName(std::string_view name)
{
    const IdentifierProblem problem = identifierProblem(name);
    return problem == IdentifierProblem::None || problem == IdentifierProblem::GeneratorName;
}

} // namespace

std::vector<std::string> modeNames(const Configuration& configuration)
{
    std::vector<std::string> names;
    for (const Mode& mode : configuration.modes)
        names.emplace_back(mode.displayName());
    return names;
}

std::string programName(const Model& model)
{
    const std::string& name = model.settings().name;
    const Configuration* configuration = model.packml();
    if (configuration == nullptr || !isIdentifierOrGemmaName(name))
        return std::string(kDefaultProgramName);
    const std::vector<std::string> modes = modeNames(*configuration);
    const bool variableTakesIt = std::any_of(model.variables().begin(), model.variables().end(),
                                             [&](const Variable& v) { return equalsIgnoreCase(v.name, name); });
    if (variableTakesIt || isReservedName(name, {}, modes))
        return std::string(kDefaultProgramName);
    return name;
}

} // namespace core::packml
