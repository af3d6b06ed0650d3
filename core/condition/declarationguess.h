#pragma once

// The declaration the quick fix of an undeclared name proposes ("Declare
// 'start' as INPUT BOOL"), guessed from every text of the model that uses
// the name: the GEMMA conditions, the PackML command and request conditions,
// the nested receptivities and the nested actions.

#include "core/model/iectypes.h"
#include "core/model/model.h"

#include <string_view>

namespace core {

// Kind: written by an action (S, R, :=, a continuous action) and read
// somewhere -> Internal; written only -> Output; read only -> Input.
// Type: the type of what the name is compared with, computed with or
// assigned (a declared variable's type, INT for an integer, REAL for a real
// number); BOOL where it is read as a condition, under an edge, or set and
// reset, and when nothing says otherwise.
struct DeclarationGuess {
    VariableKind kind = VariableKind::Input;
    IecType type = IecType::Bool;

    friend bool operator==(const DeclarationGuess&, const DeclarationGuess&) = default;
};

DeclarationGuess guessDeclaration(const Model& model, std::string_view name);

} // namespace core
