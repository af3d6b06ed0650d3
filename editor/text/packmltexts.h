#pragma once

// The wording of the PackML template in the UI language: what each state
// means, what kind it is, what each command does. The names themselves are
// PackTags', never translated (spec packml.md §2.1).

#include "core/templates/packml/packmltemplate.h"

#include <QString>

namespace editor::packmltext {

// "Execute" (the PackTags name, as a QString).
QString stateName(core::packml::State state);
QString commandName(core::packml::Command command);

// "Wait state", "Acting state", "Dual state (acts and waits)".
QString stateKindName(core::packml::StateKind kind);

// One sentence: what the unit does in the state.
QString stateMeaning(core::packml::State state);

// One sentence: what the command asks of the unit.
QString commandMeaning(core::packml::Command command);

} // namespace editor::packmltext
