#include "core/templates/packml/packmlconfiguration.h"

#include <algorithm>
#include <charconv>

namespace core::packml {

std::string_view baseModeName(int number)
{
    switch (number) {
    case 1: return "Production";
    case 2: return "Maintenance";
    case 3: return "Manual";
    default: return {};
    }
}

std::string_view Mode::displayName() const
{
    return number < kFirstUserMode ? baseModeName(number) : std::string_view(name);
}

const Mode* Configuration::mode(int number) const
{
    const auto found = std::find_if(modes.begin(), modes.end(), [&](const Mode& m) { return m.number == number; });
    return found == modes.end() ? nullptr : &*found;
}

Mode* Configuration::mode(int number)
{
    return const_cast<Mode*>(std::as_const(*this).mode(number));
}

Mode defaultMode(int number)
{
    Mode mode;
    mode.number = number;
    mode.modeChange = {State::Stopped, State::Idle, State::Aborted};
    return mode;
}

Configuration defaultConfiguration(Edition edition)
{
    Configuration configuration;
    configuration.options = defaultOptions(edition);
    for (const CommandInfo& info : allCommands()) {
        if (commandInEdition(info.command, edition))
            configuration.command(info.command).condition = std::string(info.defaultInput);
    }
    for (int number = 1; number < kFirstUserMode; ++number)
        configuration.modes.push_back(defaultMode(number));
    return configuration;
}

std::vector<std::string> structureProblems(const Configuration& configuration)
{
    std::vector<std::string> problems;
    int previous = 0;
    for (const Mode& mode : configuration.modes) {
        const std::string which = "mode " + std::to_string(mode.number);
        if (mode.number < kMinModeNumber || mode.number > kMaxModeNumber)
            problems.push_back(which + " is outside 1..31");
        if (mode.number <= previous)
            problems.push_back(which + " is repeated or out of number order");
        previous = mode.number;
        if (mode.number < kFirstUserMode && !mode.name.empty())
            problems.push_back(which + " has a name, but its name is fixed");
        for (const StateInfo& info : states()) {
            if (!holdsGrafcet(info.state) && mode.grafcetChoice(info.state).kind != GrafcetChoice::Kind::None)
                problems.push_back(which + " has a GRAFCET choice on " + std::string(info.name)
                                   + ", which holds no GRAFCET");
        }
        if (mode.grafcets[0].kind != GrafcetChoice::Kind::None)
            problems.push_back(which + " has a GRAFCET choice on no state");
    }
    return problems;
}

std::string grafcetKey(int mode, State state)
{
    return std::to_string(mode) + "/" + std::string(stateName(state));
}

std::optional<std::pair<int, State>> parseGrafcetKey(std::string_view key)
{
    const std::size_t slash = key.find('/');
    if (slash == std::string_view::npos || slash == 0)
        return std::nullopt;
    int mode = 0;
    const char* first = key.data();
    const char* last = key.data() + slash;
    const auto [end, error] = std::from_chars(first, last, mode);
    if (error != std::errc() || end != last || key.front() == '0' || key.front() == '+' || key.front() == '-')
        return std::nullopt;
    const std::optional<State> state = findState(key.substr(slash + 1));
    if (!state)
        return std::nullopt;
    return std::pair{mode, *state};
}

} // namespace core::packml
