#pragma once

// Verifies a PackML model (spec packml.md §8, docs/packml.md
// "Verification"): explores its program (packmlexplorer.h) and turns what
// the exploration saw into findings GV130-GV138, each one that claims a
// reachable violation with a scenario replayed in the PackmlSimulator to
// confirm it. A "never" claim (GV134, GV135, GV121 and the absence of an
// error) is made only when the exploration was exhaustive and left no run
// out (the timer abstraction only adds runs); GV130 and GV131 also need a
// sure way to Complete (packmlcompletion.h). A run that does not replay is
// searched again with time counted in scans. Otherwise GV100 says what is
// undecided and why.

#include "core/templates/packml/packmlprogram.h"
#include "core/verification/verification.h"

namespace core::packml {

VerificationResult verifyPackmlModel(const Model& model, const VerificationOptions& options = {});

// The same on `program` instead of the model's own: the tests show with
// programs built wrong on purpose that the checks see what they claim to.
VerificationResult verifyPackmlProgram(const Model& model, PackmlProgram program, const VerificationOptions& options = {});

namespace verification {
inline constexpr const char* kStuckGrafcet = "GV130";        // error: mode, acting state
inline constexpr const char* kAbortingStuck = "GV131";       // error: mode
inline constexpr const char* kDisabledStateActive = "GV132"; // error: mode, state
inline constexpr const char* kModeChangeOutside = "GV133";   // error: mode
inline constexpr const char* kNeverActive = "GV134";         // warning: mode, state; or mode
inline constexpr const char* kNeverAccepted = "GV135";       // warning: command
inline constexpr const char* kOutputOnAbort = "GV136";       // error: mode
inline constexpr const char* kStoredOutputOnAbort = "GV137"; // info: mode
inline constexpr const char* kExecuteEntry = "GV138";        // error: mode
} // namespace verification

} // namespace core::packml
