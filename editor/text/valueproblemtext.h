#pragma once

#include "core/condition/valueproblem.h"

#include <QString>

namespace editor {

// Why a value is not a literal of its IEC type, in the UI language, without
// the final period: "'40000' is out of range for INT (-32768..32767)". The
// value, the type and the bounds stay as written.
QString valueProblemText(const core::ValueProblem& problem);

} // namespace editor
