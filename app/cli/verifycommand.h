#pragma once

#include "arguments.h"
#include "commands.h"

namespace cli {

// ggstudio-cli verify MODEL [--promela OUT.pml] [--counterexamples DIR]:
// proves the properties of core/verification.h; prints one line per finding,
// writes each counterexample as a scenario file into DIR, and the model as
// Promela for SPIN (core/promela.h) into OUT.pml. Exit 1 when a finding of
// severity error or warning exists, 2 when a file cannot be read or written.
int commandVerify(const Arguments& args, Streams streams);

} // namespace cli
