#pragma once

#include "core/checks/diagnostic.h"

#include <QIcon>

namespace editor {

// The mark of a severity (a red disc with a cross, an amber triangle with an
// exclamation mark, a blue disc with an "i"), drawn rather than looked up in
// the icon theme: the problem counter shows one in the first frame, and a
// theme lookup costs milliseconds there (more without an installed theme),
// while a drawing looks the same on every system and at every scale.
QIcon severityIcon(core::Severity severity);

} // namespace editor
