#pragma once

// The findings of the PackML verifier (GV100, GV130-GV138, spec packml.md §8)
// in the UI language, from their code and arguments
// (core/templates/packml/packmlverifier.cpp says which).

#include "core/verification/verification.h"

#include <QString>

namespace editor {

// Empty for a finding that is not a PackML one, or whose arguments this
// wording does not know (the core's English message is shown then).
QString packmlVerificationText(const core::VerificationFinding& finding);

} // namespace editor
