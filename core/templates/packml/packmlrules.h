#pragma once

// What a unit mode makes of the PackML template (spec packml.md §3, §5.3,
// §6.2): the states it enables from the ones it lists as disabled, where a
// transition to a disabled state leads (skipping), the transitions that
// exist in the mode, the commands some mode accepts, the states where a
// mode change may be granted, and the names the generated code reserves.
// Pure functions of the template and a mode's lists: the checks, the
// generator, the simulator, the verifier and the chart read them alike.

#include "core/templates/packml/packmltemplate.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace core::packml {

// A wait state a mode listed as disabled but that stays enabled because
// acting states of its loop are (spec §3.2, PM005).
struct ForcedWaitState {
    State state;                       // Held, Suspended or Complete
    std::vector<State> enabledActing; // the enabled acting states of its loop, state-number order
};

struct EnabledStates {
    StateSet enabled;
    StateSet ignoredListings;           // listed but never disabled: Stopped, Idle, Execute, Aborted (PM004)
    std::vector<ForcedWaitState> forced; // state-number order (PM005)
};

// Spec §3.2: the enabled set of a mode from the states it lists as disabled.
EnabledStates enabledStates(const StateSet& disabledListing);

// The acting states whose being enabled keeps `waitState` enabled (Holding
// and Unholding for Held, ...); empty for a state that closes no loop.
std::vector<State> loopActingStates(State waitState);

// The listing the editor keeps (spec §3.2): the listing with `toggled`
// switched between enabled and disabled, as the mode has it now (a listed
// Held that an enabled Holding keeps enabled counts as enabled). Disabling a
// loop's wait state disables its acting states; enabling an acting state
// enables its loop's wait state; a state that is never disabled does not
// toggle. The result lists exactly the states the mode disables: no listing
// is ignored or overridden.
StateSet consistentListing(const StateSet& disabledListing, State toggled);

// The listing that disables exactly what `disabledListing` disables.
StateSet consistentListing(const StateSet& disabledListing);

// Where a transition to `target` leads in a mode (spec §3.3).
struct Destination {
    State state;                  // target, or its SC successor when target is skipped
    std::optional<State> skipped; // the disabled acting state passed over
};

// nullopt: the transition does not exist in the mode (its target is
// disabled and is a wait state, or its SC successor is disabled too).
std::optional<Destination> destination(State target, const StateSet& enabled);

// A transition of the template as it exists in a mode.
struct ModeTransition {
    TemplateTransition transition; // the template's, target before skipping
    Destination destination;
};

// What a transition does to Execute's Resume flag (spec §4, §6.4): Hold and
// Suspend out of Execute set it (the return from their loop resumes);
// entering Execute from Starting, or from Idle with Starting skipped, clears
// it (a fresh start). The generator and the simulator both apply this rule.
enum class ResumeEffect { None, Set, Clear };
ResumeEffect resumeEffect(const ModeTransition& transition);

// The transitions of `source` in a mode with these enabled states, in
// priority order, skipping applied, the ones that do not exist left out.
// None for a disabled source: it is never active in the mode.
std::vector<ModeTransition> modeTransitionsFrom(State source, const StateSet& enabled, const Options& options);

// Commands of the edition accepted by some enabled state of some mode,
// given each mode's enabled set (spec §6.2: the generated ones), in
// command-number order.
std::vector<Command> generatedCommands(std::span<const StateSet> enabledPerMode, const Options& options);

// Commands of the edition that no enabled state of any mode accepts (PM013).
std::vector<Command> unacceptedCommands(std::span<const StateSet> enabledPerMode, const Options& options);

// S(c,r) of spec §3.4: the states where a change from mode c to mode r is
// granted: modeChange(c) ∩ modeChange(r) ∩ enabled(r), restricted to the
// states that may allow a mode change (never an acting state).
StateSet modeChangeStates(const StateSet& modeChangeOfCurrent, const StateSet& modeChangeOfRequested,
                          const StateSet& enabledOfRequested);

// Spec §5.3: is `name` one the generated code of a PackML model uses
// (ignoring case, as IEC identifiers compare)? `programName` is the
// PROGRAM's name as §6.1 chooses it; `modeNames` the names of the model's
// modes ("Production", "Manual", a user mode's). The IEC keywords and the
// nested GRAFCETs' names are checked elsewhere (core/model/iectypes.h,
// core/codegen/nestedprogram.h).
bool isReservedName(std::string_view name, std::string_view programName, std::span<const std::string> modeNames);

} // namespace core::packml
