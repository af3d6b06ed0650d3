#pragma once

#include <string>

namespace core {

// Why a file could not be read into a model. Nothing is partly loaded: a
// loader either returns a whole model or one of these.
struct LoadError {
    std::string file;     // the path as given, or "<input>"
    std::string location; // JSON path ("/transitions/F1->A2/order") or "line 3, column 14"; may be empty
    std::string message;  // English, says what is wrong and what was expected
    // Fixed English advice holding no user text, so that a terminal may print
    // it as it is: it can hold a backslash ("write it as \u0000") that the
    // escaping of user text would double. Empty when there is none.
    std::string advice = {};

    // "FILE: LOCATION: MESSAGE; ADVICE" (LOCATION and ADVICE omitted when empty).
    std::string toString() const;
    // The same without "; ADVICE".
    std::string toStringWithoutAdvice() const;
};

// Something a loader did not take over exactly as the file has it, though the
// model did load: what and where, so that nothing is lost silently.
struct LoadWarning {
    std::string file;
    std::string location; // as in LoadError; may be empty
    std::string message;  // English

    // "FILE: LOCATION: warning: MESSAGE" (LOCATION omitted when empty).
    std::string toString() const;

    friend bool operator==(const LoadWarning&, const LoadWarning&) = default;
};

} // namespace core
