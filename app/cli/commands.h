#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace cli {

// Exit codes, documented in docs/cli.md (verify's in docs/verification.md).
// 3 says the command could not conclude: `simulate` stopped on a run-time fault
// (an integer division by zero, as the PLC would), or `verify` decided neither way
// about something and found nothing violated.
enum ExitCode { Success = 0, ModelHasErrors = 1, UnreadableInput = 2, RunTimeFault = 3, Undecided = 3, UsageError = 64 };

struct Streams {
    std::ostream& out;
    std::ostream& err;
};

// Runs one ggstudio-cli invocation (words after the program name).
int run(const std::vector<std::string>& words, Streams streams);

} // namespace cli
