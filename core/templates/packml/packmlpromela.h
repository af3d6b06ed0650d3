#pragma once

// A PackML program as a Promela model, so that SPIN can check,
// independently of the explorer (packmlexplorer.h), what the PackML verifier
// claims (docs/packml.md, "SPIN cross-check").
//
// One iteration of the scan process's `do` loop is one scan of the
// generated PROGRAM, written from the PackmlProgram as spec packml.md §6.5
// words it: the commands through their R_TRIGs, the mode manager, the
// branch of (Mode, State) with its instance's entry block and call, the
// first transition that holds, the continuous outputs, StateCurrent,
// UnitModeCurrent and the <V>_PREV memories. Each instance that runs a
// GRAFCET keeps its own steps, outputs, Complete and TONs; a TON is counted
// in scans exactly as the explorer counts it with exactTime
// (core/verification/tonscans.h): time goes on for every instance, called
// or not, so a paused Execute resumes with the time it was away.
//
// The inputs are chosen as the explorer's InputChoices choose them
// (packmlinputchoices.h), so that both explore the same thing: a condition
// collapsed to its value gets a rising edge only where its event can act, at
// most one command event and one mode event a scan (CntrlCmd and UnitMode
// only with the request edges); every other input takes any of its values
// in every scan.
//
// Verdicts come from SPIN's report of unreached code, read by
// core::readSpinReport: each marker is a statement alone on its line,
// reached in the exhaustive search iff what it claims happens somewhere.

#include "core/templates/packml/packmlprogram.h"

#include <string>
#include <vector>

namespace core::packml {

enum class PackmlMarkerKind {
    Reach,         // (mode, state) at the start of some scan: GV134 when never
    CommandFires,  // command: a transition on it fires in some scan (GV135 when never)
    StepActive,    // instance, step: the nested step is active after some call of the instance
    DisabledState, // GV132: a scan ends in (mode, state), a state the rules disable in the mode
    ModeChange,    // GV133: mode changes from `mode` in `state`, outside the rules' S(c, r)
    ContinuousOnAbort, // GV136: a continuous output TRUE at the end of the scan that enters `state` (Aborting, Aborted)
    StoredOnAbort,     // GV137: a stored output still TRUE then
};

struct PackmlMarker {
    PackmlMarkerKind kind = PackmlMarkerKind::Reach;
    int mode = 0;
    State state = State::Stopped;
    Command command = Command::Reset;
    int instance = -1; // StepActive: index into PackmlProgram::instances
    int step = 0;      // StepActive: the nested step number
    int line = 0;      // 1-based line of the marker statement
};

struct PackmlPromela {
    std::string text;
    std::vector<PackmlMarker> markers; // in text order; several lines may mark one claim
    // Why the program cannot be exported (English); empty when it was.
    std::string unsupported;
};

// The model's own program, or `program` (built wrong for a test, as the
// explorer takes one); the checks' markers compare with the model's
// configuration, as the explorer's do.
PackmlPromela buildPackmlPromela(const Model& model);
PackmlPromela buildPackmlPromela(const Model& model, const PackmlProgram& program);

} // namespace core::packml
