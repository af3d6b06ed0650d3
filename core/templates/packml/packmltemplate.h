#pragma once

// The PackML template (ISA-TR88.00.02, editions 2015 and 2022; spec
// packml.md §2) as data: its 17 states with their PackTags numbers, its
// commands, the transitions of each state in priority order, and where the
// chart draws each state. Fixed: a model never adds, hides or moves a state.
// What a unit mode makes of it (disabled states, skipping, mode changes) is
// in packmlrules.h; the names are PackTags', never translated.

#include <bitset>
#include <initializer_list>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace core::packml {

enum class Edition { Y2015, Y2022 };
std::string_view editionName(Edition edition); // "2015", "2022"
std::optional<Edition> parseEdition(std::string_view name);

// Wait states wait for a command; acting states do their work and end on
// their State Complete (SC); Execute acts and waits (spec §1).
enum class StateKind { Wait, Acting, Dual };

// PackTags StateCurrent numbers.
enum class State {
    Clearing = 1,
    Stopped = 2,
    Starting = 3,
    Idle = 4,
    Suspended = 5,
    Execute = 6,
    Stopping = 7,
    Aborting = 8,
    Aborted = 9,
    Holding = 10,
    Held = 11,
    Unholding = 12,
    Suspending = 13,
    Unsuspending = 14,
    Resetting = 15,
    Completing = 16,
    Complete = 17,
};
inline constexpr int kStateCount = 17;

// A set of states (a mode's disabled states, its mode-change states...).
class StateSet {
public:
    StateSet() = default;
    StateSet(std::initializer_list<State> states)
    {
        for (State state : states)
            insert(state);
    }
    bool contains(State state) const { return m_bits.test(static_cast<std::size_t>(state)); }
    void insert(State state) { m_bits.set(static_cast<std::size_t>(state)); }
    void erase(State state) { m_bits.reset(static_cast<std::size_t>(state)); }
    bool empty() const { return m_bits.none(); }
    int size() const { return static_cast<int>(m_bits.count()); }
    // In state-number order.
    std::vector<State> list() const
    {
        std::vector<State> result;
        for (int n = 1; n <= kStateCount; ++n)
            if (m_bits.test(static_cast<std::size_t>(n)))
                result.push_back(static_cast<State>(n));
        return result;
    }
    StateSet intersected(const StateSet& other) const
    {
        StateSet result;
        result.m_bits = m_bits & other.m_bits;
        return result;
    }
    friend bool operator==(const StateSet&, const StateSet&) = default;

private:
    std::bitset<kStateCount + 1> m_bits; // bit n: state number n
};

// PackTags CntrlCmd numbers; Complete exists in the 2022 edition only.
enum class Command {
    Reset = 1,
    Start = 2,
    Stop = 3,
    Hold = 4,
    Unhold = 5,
    Suspend = 6,
    Unsuspend = 7,
    Abort = 8,
    Clear = 9,
    Complete = 10,
};
inline constexpr int kCommandCount = 10;

// A cell of the chart's grid (spec §2.4): 5 columns × 6 rows.
struct ChartCell {
    int column = 0;
    int row = 0;
};
inline constexpr int kChartColumns = 5;
inline constexpr int kChartRows = 6;

struct StateInfo {
    State state;
    std::string_view name; // PackTags name: "Execute", "Complete" (2022 displays "Completed")
    StateKind kind;
    // May a mode disable it? Stopped, Idle, Execute and Aborted never;
    // Held, Suspended and Complete only while their loop's acting states are
    // disabled too (packmlrules.h).
    bool mayBeDisabled;
    std::optional<State> completeLeadsTo; // where its SC leads (acting states; Execute in 2015)
    ChartCell cell;
};

struct CommandInfo {
    Command command;
    std::string_view name;        // "Reset" ... "Complete"
    std::string_view defaultInput; // "Cmd_Reset": the BOOL input a new model declares for it
    bool only2022;
};

// Options of spec §2.3 that add optional transitions.
struct Options {
    Edition edition = Edition::Y2015;
    bool holdInSuspended = false;         // default TRUE in 2022, FALSE in 2015
    bool completeInSuspendedHeld = false; // 2022 only
    friend bool operator==(const Options&, const Options&) = default;
};
Options defaultOptions(Edition edition);

// How a transition of the template fires.
enum class Trigger { Command, StateComplete };

// One transition of the template, before a mode's skipping (spec §2.3):
// Abort and Stop are super-transitions (leaving every state of their frame),
// then the state's own commands in command-number order, then its SC.
struct TemplateTransition {
    State source;
    State target;
    Trigger trigger;
    Command command; // meaningful when trigger == Command
    bool optional;   // exists under an option only, drawn dashed
};

std::span<const StateInfo> states(); // in state-number order
const StateInfo& stateInfo(State state);
std::optional<State> findState(std::string_view name); // exact PackTags name
std::optional<State> stateFromNumber(int number);
std::string_view stateName(State state);

std::span<const CommandInfo> allCommands(); // in command-number order, 2022's Complete included
const CommandInfo& commandInfo(Command command);
std::optional<Command> findCommand(std::string_view name);
std::string_view commandName(Command command);
bool commandInEdition(Command command, Edition edition);

bool isActing(State state); // the ten acting states
// States that hold a nested GRAFCET per mode: the acting states and Execute.
bool holdsGrafcet(State state);
// The SC successor in this edition (Execute has none in 2022).
std::optional<State> completeTarget(State state, Edition edition);

// The states of the Abort frame (every state but Aborting and Aborted) and
// of the Stop frame (every state but Stopped, Stopping, Clearing, Aborting,
// Aborted): they accept Abort, resp. Stop, before their own transitions.
bool acceptsAbort(State state);
bool acceptsStop(State state);

// Every transition of `source` under these options, in priority order
// (the first whose event holds fires), targets before skipping.
std::vector<TemplateTransition> transitionsFrom(State source, const Options& options);

// The states where a mode change may be allowed (spec §3.4).
bool mayAllowModeChange(State state);

} // namespace core::packml
