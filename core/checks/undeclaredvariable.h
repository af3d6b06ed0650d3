#pragma once

// Which name a diagnostic reports as not declared, for the quick fix that
// declares it (core/condition/declarationguess.h guesses how).

#include "core/checks/diagnostic.h"

#include <optional>
#include <string>

namespace core {

class Model;

// The undeclared name a diagnostic is about: GG203 (a GEMMA condition, a
// PackML command or mode request condition),
// GG403 (a nested receptivity), GG405 (a nested action), read from the text
// at the diagnostic's span. nullopt for any other diagnostic, or when that
// text is no longer an undeclared name that could be declared (the model
// changed, the name is a keyword).
std::optional<std::string> undeclaredVariable(const Model& model, const Diagnostic& diagnostic);

} // namespace core
