#include "core/templates/packml/packmlmodel.h"

#include "core/templates/packml/packmlconfiguration.h"

namespace core::packml {

Model newModel(Edition edition)
{
    Model model(defaultConfiguration(edition));
    for (const CommandInfo& info : allCommands()) {
        if (!commandInEdition(info.command, edition))
            continue;
        Variable input;
        input.name = std::string(info.defaultInput);
        input.comment = "The " + std::string(info.name) + " command (PackTags CntrlCmd "
                        + std::to_string(static_cast<int>(info.command)) + ")";
        model.addVariable(std::move(input));
    }
    return model;
}

} // namespace core::packml
