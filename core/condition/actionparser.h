#pragma once

// The actions of the steps of nested GRAFCETs (spec grafcet-layer.md §2):
//   continuous   `N V`, `V`, `N V IF <condition>`, `V IF <condition>`
//   stored       `S V`, `R V`, `V := <expression>`
// (stored on activation or on deactivation: the step's action list says
// which). One parser for the checks, the code generator, renaming and the
// simulator; its expressions are read in the Nested context, and every span
// is an offset into the whole action text.

#include "core/condition/conditionparseerror.h"
#include "core/condition/conditionsyntax.h"

#include <optional>
#include <string>
#include <string_view>

namespace core::cond {

enum class ActionForm { Continuous, Set, Reset, Assign };

struct ActionSyntax {
    ActionForm form = ActionForm::Continuous;
    bool qualifierWritten = false; // `N V`, `S V`, `R V` (false for a bare `V` and for assignments)
    std::string target;            // the variable as written ("A_Plus", "Complete")
    Span targetSpan;
    bool targetIsComplete = false; // the target is Complete (any case)
    Expression condition;          // Continuous with `IF <condition>`; empty otherwise
    Expression value;              // Assign: the right-hand side; empty otherwise
};

struct ActionParseResult {
    ActionSyntax action;
    std::optional<ParseError> error;

    bool ok() const { return !error.has_value(); }
};

ActionParseResult parseAction(std::string_view text);

} // namespace core::cond
