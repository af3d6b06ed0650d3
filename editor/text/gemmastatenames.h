#pragma once

#include "core/templates/gemma/gemmatemplate.h"

#include <QString>

namespace editor {

// Official GEMMA names in the UI language. The English source texts are the
// spec's (the same as core::TemplateState::englishName, which the generated
// code uses); the translators provide the others under the "StateNames"
// context.

// "A1" -> "Stop in initial state"; empty for an unknown id.
QString officialStateName(const QString& id);

// Family::A -> "Stop procedures".
QString officialFamilyName(core::Family family);

} // namespace editor
