#include "faultoption.h"

#include "terminal.h"

#include <ostream>

namespace cli {

namespace {

const char* const kFaultSyntax = "give SCAN:TARGET stuck TRUE|FALSE, flicker, jam or clear";

} // namespace

bool parseFaultOption(const std::string& option, core::ScenarioAction& action, std::string& error)
{
    const std::size_t colon = option.find(':');
    // Anything else on the "line" (a second fault, a comment) would be read as scenario text.
    if (colon == std::string::npos || option.find_first_of("#\n\r") != std::string::npos) {
        error = kFaultSyntax;
        return false;
    }
    const std::string line = "at " + option.substr(0, colon) + ": fault " + option.substr(colon + 1);
    const core::ScenarioParseResult parsed = core::parseScenario(line);
    if (!parsed.ok()) {
        error = core::toText(parsed.errors.front());
        return false;
    }
    if (parsed.scenario.actions.size() != 1) {
        error = kFaultSyntax;
        return false;
    }
    action = parsed.scenario.actions.front();
    action.line = 0; // no line of a file
    return true;
}

bool parseFaultOptions(const std::vector<std::string>& options, std::vector<core::ScenarioAction>& faults,
                       std::string& error)
{
    for (const std::string& option : options) {
        core::ScenarioAction action;
        if (!parseFaultOption(option, action, error)) {
            error = "--fault '" + option + "': " + error;
            return false;
        }
        faults.push_back(std::move(action));
    }
    return true;
}

bool checkFaultOptions(const std::vector<std::string>& options, const std::vector<core::ScenarioAction>& faults,
                       const core::machine::MachineLoop* loop, bool openLoop, std::string& error)
{
    if (faults.empty())
        return true;
    if (!loop) {
        error = openLoop ? "--fault needs the virtual machine: leave out --open-loop"
                         : "--fault needs the virtual machine: the model has none";
        return false;
    }
    for (std::size_t i = 0; i < faults.size() && i < options.size(); ++i) {
        const std::optional<core::machine::Fault> fault = core::scenarioFault(faults[i]);
        if (!fault)
            continue;
        if (const std::optional<core::machine::FaultRefusal> refusal = loop->checkFault(*fault)) {
            error = "--fault '" + options[i] + "': " + core::machine::toText(*refusal);
            return false;
        }
    }
    return true;
}

FaultAnnouncements::FaultAnnouncements(const core::Scenario& scenario)
{
    for (const core::ScenarioAction& action : scenario.actions) {
        if (const std::optional<core::machine::Fault> fault = core::scenarioFault(action))
            m_faults.emplace(action.scan, core::machine::toText(*fault));
    }
}

void FaultAnnouncements::print(std::int64_t scan, std::ostream& out) const
{
    const auto [first, last] = m_faults.equal_range(scan);
    for (auto fault = first; fault != last; ++fault)
        out << "fault at scan " << scan << ": " << fault->second << lineEnd;
}

} // namespace cli
