#pragma once

// How an action's text is drawn (docs/grafcet-layout.md, Actions): its
// qualifier cell, its text cell and the condition under it. Split by words,
// not parsed: a text that does not parse yet is drawn as written.

#include "core/model/grafcet.h"

#include <string>

namespace core {

struct ActionParts {
    // "S", "R", an event mark for stored actions ("↑", "↓S"); empty for a
    // continuous action (N is not drawn).
    std::string qualifier;
    std::string text;      // without qualifier and condition
    std::string condition; // after IF, for a continuous action; empty otherwise
};

ActionParts splitAction(const GrafcetAction& action);

} // namespace core
