#pragma once

// A problem met while turning a model into a program: shared by the nested
// layer and by every template's upper layer.

#include "core/model/span.h"

#include <optional>
#include <string>
#include <vector>

namespace core {

// Something wrong found while building: a condition that cannot be used, a
// token that cannot take effect. Code generation writes it as a comment at
// the place it concerns.
struct ProgramProblem {
    enum class Kind { Error, Warning };
    Kind kind = Kind::Error;
    std::string code;    // diagnostic code when one applies ("GG201"), else empty
    std::string element; // transition id or step id
    std::string message; // English, may quote user text
    // For the condition errors (GG201-GG204): Diagnostic::arguments as the
    // checks give them for the same code, so the UI can word them the same.
    std::vector<std::string> arguments;
    // In a nested GRAFCET (element: the GEMMA step or PackML key that holds
    // it): the nested step (with the action's index) or transition, and the
    // span in its text.
    int nestedStep = 0;
    int nestedTransition = 0;
    int actionIndex = -1;
    std::optional<Span> span;
};

} // namespace core
