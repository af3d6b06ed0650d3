#include "faultoption.h"

namespace cli {

bool parseFaultOption(const std::string& option, core::ScenarioAction& action, std::string& error)
{
    const std::size_t colon = option.find(':');
    // Anything else on the "line" (a second fault, a comment) would be read as scenario text.
    if (colon == std::string::npos || option.find_first_of("#\n\r") != std::string::npos) {
        error = "give SCAN:TARGET stuck TRUE|FALSE, flicker, jam or clear";
        return false;
    }
    const std::string line = "at " + option.substr(0, colon) + ": fault " + option.substr(colon + 1);
    const core::ScenarioParseResult parsed = core::parseScenario(line);
    if (!parsed.ok()) {
        error = core::toText(parsed.errors.front());
        return false;
    }
    if (parsed.scenario.actions.size() != 1) {
        error = "give SCAN:TARGET stuck TRUE|FALSE, flicker, jam or clear";
        return false;
    }
    action = parsed.scenario.actions.front();
    action.line = 0; // no line of a file
    return true;
}

} // namespace cli
