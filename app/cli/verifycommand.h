#pragma once

#include "arguments.h"
#include "commands.h"

namespace cli {

// ggstudio-cli verify MODEL [--promela OUT.pml] [--counterexamples DIR]
//                    [--complete-automatic STEP[,STEP...]|all]:
// proves the properties of core/verification/verification.h; prints one line per finding,
// writes each counterexample as a scenario file into DIR, and the model as
// Promela for SPIN (core/verification/promela.h) into OUT.pml. Complete is free for every
// nested step but the ones named automatic (both for the proof and OUT.pml).
// Exit 1 when a finding of severity error or warning exists, 2 when a file
// cannot be read or written, 64 for a step that is not a visible nested one.
int commandVerify(const Arguments& args, Streams streams);

} // namespace cli
