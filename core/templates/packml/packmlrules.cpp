#include "core/templates/packml/packmlrules.h"

#include "core/model/iectypes.h"
#include "core/templates/packml/packtags.h"

#include <algorithm>
#include <array>

namespace core::packml {

namespace {

// The minimum set of every unit (spec §3.2).
bool neverDisabled(State state)
{
    return !stateInfo(state).mayBeDisabled;
}

// A wait state with the acting states of its loop: the loop never ends in a
// disabled wait state (spec §3.2).
struct Loop {
    State waitState;
    std::array<State, 2> acting;
    int actingCount;
};

constexpr std::array<Loop, 3> kLoops{{
    {State::Suspended, {State::Suspending, State::Unsuspending}, 2},
    {State::Held, {State::Holding, State::Unholding}, 2},
    {State::Complete, {State::Completing, State::Completing}, 1},
}};

const Loop* loopOfWaitState(State state)
{
    for (const Loop& loop : kLoops)
        if (loop.waitState == state)
            return &loop;
    return nullptr;
}

std::optional<State> waitStateOfLoop(State actingState)
{
    for (const Loop& loop : kLoops)
        for (int i = 0; i < loop.actingCount; ++i)
            if (loop.acting[static_cast<std::size_t>(i)] == actingState)
                return loop.waitState;
    return std::nullopt;
}

bool acceptedSomewhere(Command command, std::span<const StateSet> enabledPerMode, const Options& options)
{
    for (const StateSet& enabled : enabledPerMode)
        for (const State source : enabled.list())
            for (const ModeTransition& transition : modeTransitionsFrom(source, enabled, options))
                if (transition.transition.trigger == Trigger::Command && transition.transition.command == command)
                    return true;
    return false;
}

// Spec §5.3's names that do not depend on the model, besides the six
// PackTags (packtags.h); and GVL, the CODESYS dialect's global list (spec
// §6.7), reserved in both dialects as GEMMA does, so that a model stays
// valid whichever dialect it is exported in.
constexpr std::array<std::string_view, 12> kFixedNames{
    "State",  "Mode",           "Entry",          "Resume",   "Initialization", "Complete",
    "R_TRIG", "PackMLConfiguration", "PackMLResource", "MainTask", "PackMLInstance", "GVL",
};

constexpr std::array<std::string_view, 2> kReservedPrefixes{"Trig_", "Ev_"};

bool startsWithIgnoringCase(std::string_view name, std::string_view prefix)
{
    return name.size() >= prefix.size() && equalsIgnoreCase(name.substr(0, prefix.size()), prefix);
}

bool isStateName(std::string_view text)
{
    const auto all = states();
    return std::any_of(all.begin(), all.end(), [&](const StateInfo& info) { return equalsIgnoreCase(text, info.name); });
}

// "<State>" or "<State>_FB".
bool namesStateOrItsBlock(std::string_view text)
{
    constexpr std::string_view suffix = "_FB";
    if (isStateName(text))
        return true;
    return text.size() > suffix.size() && equalsIgnoreCase(text.substr(text.size() - suffix.size()), suffix)
        && isStateName(text.substr(0, text.size() - suffix.size()));
}

// "<State>_FB", "<Mode>_<State>" or "<Mode>_<State>_FB", read from the name
// rather than spelled for every mode and state: the checks ask for every
// name a model's texts read.
bool namesInstanceOrBlock(std::string_view name, std::span<const std::string> modeNames)
{
    if (namesStateOrItsBlock(name) && !isStateName(name))
        return true;
    for (const std::string& mode : modeNames) {
        if (name.size() > mode.size() + 1 && name[mode.size()] == '_' && startsWithIgnoringCase(name, mode)
            && namesStateOrItsBlock(name.substr(mode.size() + 1)))
            return true;
    }
    return false;
}

} // namespace

std::vector<State> loopActingStates(State waitState)
{
    const Loop* loop = loopOfWaitState(waitState);
    if (!loop)
        return {};
    return {loop->acting.begin(), loop->acting.begin() + loop->actingCount};
}

EnabledStates enabledStates(const StateSet& disabledListing)
{
    EnabledStates result;
    for (const StateInfo& info : states()) {
        const bool listed = disabledListing.contains(info.state);
        if (!listed)
            result.enabled.insert(info.state);
        else if (neverDisabled(info.state)) {
            result.enabled.insert(info.state);
            result.ignoredListings.insert(info.state);
        }
    }
    // Acting states are never forced, so the loops can be settled after them.
    for (const Loop& loop : kLoops) {
        if (!disabledListing.contains(loop.waitState))
            continue;
        ForcedWaitState forced{loop.waitState, {}};
        for (const State acting : loopActingStates(loop.waitState))
            if (result.enabled.contains(acting))
                forced.enabledActing.push_back(acting);
        if (forced.enabledActing.empty())
            continue;
        result.enabled.insert(loop.waitState);
        result.forced.push_back(std::move(forced));
    }
    return result;
}

StateSet consistentListing(const StateSet& disabledListing)
{
    const StateSet enabled = enabledStates(disabledListing).enabled;
    StateSet listing;
    for (const StateInfo& info : states())
        if (!enabled.contains(info.state))
            listing.insert(info.state);
    return listing;
}

StateSet consistentListing(const StateSet& disabledListing, State toggled)
{
    StateSet listing = consistentListing(disabledListing);
    if (neverDisabled(toggled))
        return listing;
    if (listing.contains(toggled)) {
        listing.erase(toggled);
        if (const std::optional<State> waitState = waitStateOfLoop(toggled))
            listing.erase(*waitState);
    } else {
        listing.insert(toggled);
        for (const State acting : loopActingStates(toggled))
            listing.insert(acting);
    }
    return listing;
}

ResumeEffect resumeEffect(const ModeTransition& transition)
{
    const TemplateTransition& t = transition.transition;
    const bool pausesExecute = t.source == State::Execute && t.trigger == Trigger::Command
                               && (t.command == Command::Hold || t.command == Command::Suspend);
    if (pausesExecute)
        return ResumeEffect::Set;
    const bool startsExecute = transition.destination.state == State::Execute
                               && (t.source == State::Starting || t.target == State::Starting);
    return startsExecute ? ResumeEffect::Clear : ResumeEffect::None;
}

std::optional<Destination> destination(State target, const StateSet& enabled)
{
    if (enabled.contains(target))
        return Destination{target, std::nullopt};
    // An acting state's SC successor does not depend on the edition: only
    // Execute's does, and Execute is never disabled.
    const std::optional<State> successor = stateInfo(target).completeLeadsTo;
    if (isActing(target) && successor && enabled.contains(*successor))
        return Destination{*successor, target};
    return std::nullopt;
}

std::vector<ModeTransition> modeTransitionsFrom(State source, const StateSet& enabled, const Options& options)
{
    std::vector<ModeTransition> result;
    if (!enabled.contains(source))
        return result;
    for (const TemplateTransition& transition : transitionsFrom(source, options))
        if (const std::optional<Destination> leadsTo = destination(transition.target, enabled))
            result.push_back({transition, *leadsTo});
    return result;
}

std::vector<Command> generatedCommands(std::span<const StateSet> enabledPerMode, const Options& options)
{
    std::vector<Command> result;
    for (const CommandInfo& info : allCommands())
        if (commandInEdition(info.command, options.edition)
            && acceptedSomewhere(info.command, enabledPerMode, options))
            result.push_back(info.command);
    return result;
}

std::vector<Command> unacceptedCommands(std::span<const StateSet> enabledPerMode, const Options& options)
{
    std::vector<Command> result;
    for (const CommandInfo& info : allCommands())
        if (commandInEdition(info.command, options.edition)
            && !acceptedSomewhere(info.command, enabledPerMode, options))
            result.push_back(info.command);
    return result;
}

StateSet modeChangeStates(const StateSet& modeChangeOfCurrent, const StateSet& modeChangeOfRequested,
                          const StateSet& enabledOfRequested)
{
    StateSet result = modeChangeOfCurrent.intersected(modeChangeOfRequested).intersected(enabledOfRequested);
    for (const State state : result.list())
        if (!mayAllowModeChange(state))
            result.erase(state);
    return result;
}

bool isReservedName(std::string_view name, std::string_view programName, std::span<const std::string> modeNames)
{
    if (equalsIgnoreCase(name, programName))
        return true;
    for (const std::string_view fixed : kFixedNames)
        if (equalsIgnoreCase(name, fixed))
            return true;
    if (isPackTagName(name))
        return true;
    for (const std::string_view prefix : kReservedPrefixes)
        if (startsWithIgnoringCase(name, prefix))
            return true;
    return namesInstanceOrBlock(name, modeNames);
}

} // namespace core::packml
