#pragma once

// One of the engineer's verification properties (docs/verification.md,
// "Properties"): `never P` or `always P`, kept as written. Its syntax is
// checked live (core/verification/property.h), not by the model: a row may
// hold a property being written.

#include <string>

namespace core {

struct UserProperty {
    std::string text;    // "never A_Plus AND A_Minus"
    std::string comment; // why it must hold

    bool operator==(const UserProperty&) const = default;
};

} // namespace core
