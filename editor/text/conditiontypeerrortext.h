#pragma once

#include "core/condition/conditiontypeerror.h"

#include <QString>

namespace editor {

// Why a condition does not type-check, in the UI language, without the
// final period: "AND needs BOOL operands, but 'Speed' is INT". The code it
// quotes (operators, subexpressions, literals, type names) stays as written.
QString conditionTypeErrorText(const core::cond::TypeError& error);

} // namespace editor
