#pragma once

// What a PackML model adds to the template (spec packml.md §2.2, §3, §4,
// §5.1): its settings, the condition of each command and its unit modes.
// Texts and values are kept as the user wrote them, even wrong, as GEMMA
// conditions are: the checks (PM001–PM019) report them. Only the structure
// the rest of the model relies on is enforced (structureProblems): mode
// numbers 1..31, each once, in number order, and GRAFCET choices only on the
// states that hold a GRAFCET. The GRAFCETs themselves live in the Model's
// GRAFCET storage under grafcetKey(mode, state).

#include "core/templates/packml/packmltemplate.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace core::packml {

inline constexpr int kMinModeNumber = 1;
inline constexpr int kMaxModeNumber = 31;
inline constexpr int kFirstUserMode = 4; // 1..3 are Production, Maintenance, Manual

// Production, Maintenance, Manual for 1..3; empty for user modes.
std::string_view baseModeName(int number);

// What runs in a state that holds a GRAFCET (spec §4), in one mode.
struct GrafcetChoice {
    enum class Kind { None, Own, SameAs };
    Kind kind = Kind::None;
    int sameAsMode = 0; // Kind::SameAs: the mode whose own GRAFCET runs (kept as written)

    static GrafcetChoice none() { return {}; }
    static GrafcetChoice own() { return {Kind::Own, 0}; }
    static GrafcetChoice sameAs(int mode) { return {Kind::SameAs, mode}; }
    friend bool operator==(const GrafcetChoice&, const GrafcetChoice&) = default;
};

struct Mode {
    int number = 1;
    std::string name; // user modes only; 1..3 use baseModeName
    std::string comment;
    std::string request; // the request condition (spec §3.4); empty: none
    StateSet disabled;
    StateSet modeChange;
    // Indexed by state number; only states that holdsGrafcet() may be other than None.
    std::array<GrafcetChoice, kStateCount + 1> grafcets{};

    // The name the mode goes by: the base name for 1..3, else `name`.
    std::string_view displayName() const;
    const GrafcetChoice& grafcetChoice(State state) const { return grafcets[static_cast<std::size_t>(state)]; }
    friend bool operator==(const Mode&, const Mode&) = default;
};

struct CommandSetting {
    std::string condition;
    std::string comment;
    friend bool operator==(const CommandSetting&, const CommandSetting&) = default;
};

struct Configuration {
    Options options;
    State initialState = State::Stopped;
    int initialMode = 1;
    // Indexed by command number - 1, Complete included: in 2015 it is "set"
    // only when its condition or comment is not empty (spec §9, PM017).
    std::array<CommandSetting, kCommandCount> commands{};
    std::vector<Mode> modes; // in number order

    const CommandSetting& command(Command command) const { return commands[commandIndex(command)]; }
    CommandSetting& command(Command command) { return commands[commandIndex(command)]; }
    const Mode* mode(int number) const;
    Mode* mode(int number);
    friend bool operator==(const Configuration&, const Configuration&) = default;

    static std::size_t commandIndex(Command command) { return static_cast<std::size_t>(command) - 1; }
};

// The default configuration of a new model (spec §3.1, §5.1): Production,
// Maintenance and Manual with every state enabled and mode changes in
// Stopped, Idle and Aborted, initial state Stopped, initial mode 1, each
// command of the edition conditioned on its Cmd_ input (which the caller
// declares).
Configuration defaultConfiguration(Edition edition);
Mode defaultMode(int number);

// Why the configuration could not be held by a model; empty when it can.
std::vector<std::string> structureProblems(const Configuration& configuration);

// The key of a mode's own GRAFCET for a state in the Model's GRAFCET
// storage: "3/Execute". The only place that spells it.
std::string grafcetKey(int mode, State state);
// The (mode, state) of a key grafcetKey made; nullopt for any other text.
std::optional<std::pair<int, State>> parseGrafcetKey(std::string_view key);

} // namespace core::packml
