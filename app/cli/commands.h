#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace cli {

// Exit codes, documented in the README.
enum ExitCode { Success = 0, ModelHasErrors = 1, UnreadableInput = 2, UsageError = 64 };

struct Streams {
    std::ostream& out;
    std::ostream& err;
};

// Runs one ggstudio-cli invocation (words after the program name).
int run(const std::vector<std::string>& words, Streams streams);

} // namespace cli
