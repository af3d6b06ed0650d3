#pragma once

#include <string>

namespace core {

// Why a file could not be read into a model. Nothing is partly loaded: a
// loader either returns a whole model or one of these.
struct LoadError {
    std::string file;     // the path as given, or "<input>"
    std::string location; // JSON path ("/transitions/F1->A2/order") or "line 3, column 14"; may be empty
    std::string message;  // English, says what is wrong and what was expected

    // "FILE: LOCATION: MESSAGE" (LOCATION omitted when empty).
    std::string toString() const;
};

} // namespace core
