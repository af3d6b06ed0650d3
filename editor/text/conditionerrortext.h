#pragma once

#include "core/condition/conditionparseerror.h"

#include <QString>

namespace editor {

// Why a condition does not parse, in the UI language, without the final
// period: "expected an operand after 'AND', found ')'". The code it quotes
// (tokens, words, characters) stays as written.
QString conditionErrorText(const core::cond::ParseError& error);

} // namespace editor
