#pragma once

// What one scan of the PackML simulator did (spec packml.md §6.5): the
// transition that fired, the mode change, whether Execute resumed, which
// instance was called, and every event it dropped with the reason, as data
// (the editor words it in the UI language; toText() in English).

#include "core/templates/packml/packmlrules.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace core::packml {

enum class DropReason {
    NotAcceptedInState,  // the template has no transition for the command in this state
    NotAcceptedInMode,   // the template has one, but the mode disables where it leads (§3.3)
    Preempted,           // a higher-priority transition fired (preemptedBy)
    NoSuchCommand,       // CntrlCmd names no command of the edition
    NotAllowedByCurrentMode,   // the current mode allows no mode change in this state
    NotAllowedByRequestedMode, // the requested mode allows no mode change in this state
    DisabledInRequestedMode,   // the requested mode disables this state
    ModePreempted,       // a lower-numbered mode was granted in the same scan (preemptedBy)
    AlreadyCurrent,      // the requested mode is the current one: nothing to do
    NoSuchMode,          // UnitMode names no mode of the model
};

struct DroppedEvent {
    enum class Kind { Command, StateComplete, ModeRequest };
    Kind kind = Kind::Command;
    DropReason reason = DropReason::NotAcceptedInState;
    // Command: the command (CntrlCmd) number; ModeRequest: the requested
    // mode's number; StateComplete: 0.
    int number = 0;
    std::string name;      // "Hold", "Manual"; empty when number names nothing
    State state = State::Stopped; // the state the event met
    std::string modeName;  // the mode it met (for a request: the current one)
    std::string preemptedBy; // Preempted: the transition that fired; ModePreempted: the granted mode

    friend bool operator==(const DroppedEvent&, const DroppedEvent&) = default;
};

// "Hold is not accepted in Idle", "Manual is not granted in Execute:
// Production allows no mode change there".
std::string toText(const DroppedEvent& event);

// "Stopped-Reset->Resetting", "Resetting-SC->Idle": the real target, after skipping.
std::string transitionText(const ModeTransition& transition);

struct PackmlScanRecord {
    std::int64_t scan = 0; // 1 for the first scan
    State stateBefore = State::Stopped;
    int modeBefore = 0;
    State state = State::Stopped; // after the scan
    int mode = 0;                 // after the scan
    std::optional<ModeTransition> fired;
    bool resumed = false;   // Execute resumed: Entry with Resume, no Initialization call
    int calledInstance = -1; // index into PackmlProgram::instances; -1: no FB was called
    std::vector<DroppedEvent> dropped; // mode requests, then commands in number order, then SC

    bool modeChanged() const { return mode != modeBefore; }
};

// "fired Stopped-Reset->Resetting", "mode 1->3 fired Stopped-Reset->Idle",
// "resumed"; empty when the scan did none of these.
std::string summaryText(const PackmlScanRecord& record);

} // namespace core::packml
