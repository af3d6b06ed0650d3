#include "core/templates/packml/packmltemplate.h"

#include <algorithm>
#include <array>

namespace core::packml {

namespace {

using S = State;
using K = StateKind;

// Spec §2.1: number, name, kind, may be disabled, SC successor, chart cell.
constexpr std::array<StateInfo, kStateCount> kStates{{
    {S::Clearing, "Clearing", K::Acting, true, S::Stopped, {0, 4}},
    {S::Stopped, "Stopped", K::Wait, false, std::nullopt, {0, 3}},
    {S::Starting, "Starting", K::Acting, true, S::Execute, {1, 1}},
    {S::Idle, "Idle", K::Wait, false, std::nullopt, {0, 1}},
    {S::Suspended, "Suspended", K::Wait, true, std::nullopt, {2, 2}},
    {S::Execute, "Execute", K::Dual, false, S::Completing, {2, 1}},
    {S::Stopping, "Stopping", K::Acting, true, S::Stopped, {4, 3}},
    {S::Aborting, "Aborting", K::Acting, true, S::Aborted, {4, 5}},
    {S::Aborted, "Aborted", K::Wait, false, std::nullopt, {0, 5}},
    {S::Holding, "Holding", K::Acting, true, S::Held, {3, 0}},
    {S::Held, "Held", K::Wait, true, std::nullopt, {2, 0}},
    {S::Unholding, "Unholding", K::Acting, true, S::Execute, {1, 0}},
    {S::Suspending, "Suspending", K::Acting, true, S::Suspended, {3, 2}},
    {S::Unsuspending, "Unsuspending", K::Acting, true, S::Execute, {1, 2}},
    {S::Resetting, "Resetting", K::Acting, true, S::Idle, {0, 2}},
    {S::Completing, "Completing", K::Acting, true, S::Complete, {3, 1}},
    {S::Complete, "Complete", K::Wait, true, std::nullopt, {4, 1}},
}};

// Spec §2.2.
constexpr std::array<CommandInfo, kCommandCount> kCommands{{
    {Command::Reset, "Reset", "Cmd_Reset", false},
    {Command::Start, "Start", "Cmd_Start", false},
    {Command::Stop, "Stop", "Cmd_Stop", false},
    {Command::Hold, "Hold", "Cmd_Hold", false},
    {Command::Unhold, "Unhold", "Cmd_Unhold", false},
    {Command::Suspend, "Suspend", "Cmd_Suspend", false},
    {Command::Unsuspend, "Unsuspend", "Cmd_Unsuspend", false},
    {Command::Abort, "Abort", "Cmd_Abort", false},
    {Command::Clear, "Clear", "Cmd_Clear", false},
    {Command::Complete, "Complete", "Cmd_Complete", true},
}};

// The states' own commands (spec §2.3), each state's in command-number
// order; `needs`: the edition or option a transition exists under.
enum class Needs { Nothing, Edition2022, HoldInSuspended, CompleteInSuspendedHeld };

struct OwnCommand {
    State source;
    Command command;
    State target;
    Needs needs;
};

constexpr std::array<OwnCommand, 12> kOwnCommands{{
    {S::Stopped, Command::Reset, S::Resetting, Needs::Nothing},
    {S::Idle, Command::Start, S::Starting, Needs::Nothing},
    {S::Execute, Command::Hold, S::Holding, Needs::Nothing},
    {S::Execute, Command::Suspend, S::Suspending, Needs::Nothing},
    {S::Execute, Command::Complete, S::Completing, Needs::Edition2022},
    {S::Suspended, Command::Hold, S::Holding, Needs::HoldInSuspended},
    {S::Suspended, Command::Unsuspend, S::Unsuspending, Needs::Nothing},
    {S::Suspended, Command::Complete, S::Completing, Needs::CompleteInSuspendedHeld},
    {S::Held, Command::Unhold, S::Unholding, Needs::Nothing},
    {S::Held, Command::Complete, S::Completing, Needs::CompleteInSuspendedHeld},
    {S::Complete, Command::Reset, S::Resetting, Needs::Nothing},
    {S::Aborted, Command::Clear, S::Clearing, Needs::Nothing},
}};

bool satisfied(Needs needs, const Options& options)
{
    const bool edition2022 = options.edition == Edition::Y2022;
    switch (needs) {
    case Needs::Nothing: return true;
    case Needs::Edition2022: return edition2022;
    case Needs::HoldInSuspended: return options.holdInSuspended;
    case Needs::CompleteInSuspendedHeld: return edition2022 && options.completeInSuspendedHeld;
    }
    return false;
}

void addOwnCommands(State source, const Options& options, std::vector<TemplateTransition>& result)
{
    for (const OwnCommand& own : kOwnCommands)
        if (own.source == source && satisfied(own.needs, options))
            result.push_back({source, own.target, Trigger::Command, own.command, own.needs != Needs::Nothing
                              && own.needs != Needs::Edition2022});
}

} // namespace

std::string_view editionName(Edition edition)
{
    return edition == Edition::Y2022 ? "2022" : "2015";
}

std::optional<Edition> parseEdition(std::string_view name)
{
    if (name == "2015")
        return Edition::Y2015;
    if (name == "2022")
        return Edition::Y2022;
    return std::nullopt;
}

Options defaultOptions(Edition edition)
{
    Options options;
    options.edition = edition;
    options.holdInSuspended = edition == Edition::Y2022;
    return options;
}

std::span<const StateInfo> states()
{
    return kStates;
}

const StateInfo& stateInfo(State state)
{
    return kStates[static_cast<std::size_t>(state) - 1];
}

std::optional<State> findState(std::string_view name)
{
    for (const StateInfo& info : kStates)
        if (info.name == name)
            return info.state;
    return std::nullopt;
}

std::optional<State> stateFromNumber(int number)
{
    if (number < 1 || number > kStateCount)
        return std::nullopt;
    return static_cast<State>(number);
}

std::string_view stateName(State state)
{
    return stateInfo(state).name;
}

std::span<const CommandInfo> allCommands()
{
    return kCommands;
}

const CommandInfo& commandInfo(Command command)
{
    return kCommands[static_cast<std::size_t>(command) - 1];
}

std::optional<Command> findCommand(std::string_view name)
{
    for (const CommandInfo& info : kCommands)
        if (info.name == name)
            return info.command;
    return std::nullopt;
}

std::string_view commandName(Command command)
{
    return commandInfo(command).name;
}

bool commandInEdition(Command command, Edition edition)
{
    return !commandInfo(command).only2022 || edition == Edition::Y2022;
}

bool isActing(State state)
{
    return stateInfo(state).kind == StateKind::Acting;
}

bool holdsGrafcet(State state)
{
    return stateInfo(state).kind != StateKind::Wait;
}

std::optional<State> completeTarget(State state, Edition edition)
{
    if (state == State::Execute && edition == Edition::Y2022)
        return std::nullopt;
    return stateInfo(state).completeLeadsTo;
}

bool acceptsAbort(State state)
{
    return state != State::Aborting && state != State::Aborted;
}

bool acceptsStop(State state)
{
    return acceptsAbort(state) && state != State::Stopped && state != State::Stopping && state != State::Clearing;
}

std::vector<TemplateTransition> transitionsFrom(State source, const Options& options)
{
    std::vector<TemplateTransition> result;
    if (acceptsAbort(source))
        result.push_back({source, State::Aborting, Trigger::Command, Command::Abort, false});
    if (acceptsStop(source))
        result.push_back({source, State::Stopping, Trigger::Command, Command::Stop, false});
    addOwnCommands(source, options, result);
    if (const std::optional<State> target = completeTarget(source, options.edition))
        result.push_back({source, *target, Trigger::StateComplete, Command::Reset, false});
    return result;
}

bool mayAllowModeChange(State state)
{
    switch (state) {
    case State::Stopped:
    case State::Idle:
    case State::Suspended:
    case State::Execute:
    case State::Aborted:
    case State::Held:
    case State::Complete: return true;
    default: return false;
    }
}

} // namespace core::packml
