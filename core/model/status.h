#pragma once

#include <string>
#include <utility>

namespace core {

// Result of a model operation. Core has no translation system, so a failure
// carries a stable code (for the editor to translate) and an English message
// (for the command-line tool and logs).
struct Status {
    bool ok = true;
    std::string code;
    std::string message;

    explicit operator bool() const { return ok; }

    static Status success() { return {}; }
    static Status failure(std::string code, std::string message)
    {
        return {false, std::move(code), std::move(message)};
    }
};

} // namespace core
