#include "editor/commands/packml/modenamerule.h"

#include "core/model/iectypes.h"
#include "core/templates/packml/packmlprogramname.h"
#include "core/templates/packml/packmlrules.h"

#include <string>
#include <vector>

namespace editor {

namespace {

// GEMMA's generator names are free in a PackML model (as PM002 has it).
bool isModeIdentifier(std::string_view name)
{
    const core::IdentifierProblem problem = core::identifierProblem(name);
    return problem == core::IdentifierProblem::None || problem == core::IdentifierProblem::GeneratorName;
}

} // namespace

core::Status modeNameProblem(const core::Model& model, int number, std::string_view name)
{
    const std::string quoted = "'" + std::string(name) + "'";
    if (!isModeIdentifier(name))
        return core::Status::failure("not-identifier", quoted + " is not an IEC identifier (letters, digits and "
                                                                "single underscores, not a keyword)");
    const core::packml::Configuration* configuration = model.packml();
    if (!configuration)
        return core::Status::success();
    std::vector<std::string> otherNames;
    for (const core::packml::Mode& mode : configuration->modes) {
        if (mode.number == number)
            continue;
        if (core::equalsIgnoreCase(mode.displayName(), name))
            return core::Status::failure("duplicate-name", "unit mode " + std::to_string(mode.number)
                                                               + " is already named " + std::string(mode.displayName()));
        otherNames.emplace_back(mode.displayName());
    }
    otherNames.emplace_back(name);
    if (core::packml::isReservedName(name, core::packml::programName(model), otherNames))
        return core::Status::failure("reserved", quoted + " is a name the generated code uses");
    return core::Status::success();
}

} // namespace editor
