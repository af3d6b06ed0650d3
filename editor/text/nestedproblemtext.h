#pragma once

#include "core/checks/diagnostic.h"

#include <QString>

namespace editor {

// The message of a problem of one nested receptivity or action (GG401-GG411,
// GG413-GG415, GG421, and GG301-GG303 on a name they read; found by
// core/codegen/nestedprogram.cpp) in the UI language, filled with
// Diagnostic::arguments; the place ("the receptivity of T2 of F1") is worded
// again from the diagnostic's target, its English form in the arguments
// left aside. Empty when the code is none of them or the
// arguments are not those it promises (docs/diagnostics.md).
QString nestedProblemText(const core::Diagnostic& diagnostic);

} // namespace editor
