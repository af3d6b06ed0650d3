#pragma once

// The names the generated code declares for GEMMA steps (spec gemma-grafcet.md
// §6.1, §6.5): for each VISIBLE macro-step or enclosing step S, the instance
// `S : S_FB` in PROGRAM GEMMA and the FUNCTION_BLOCK S_FB. Simple and hidden
// steps declare nothing, so their ids are free for variables: a1, b0, d1 are
// the usual names of limit switches. Which names are taken therefore depends
// on the model; identifierProblem() (core/model/iectypes.h) checks the rest.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace core {

class Model;
struct Step;
struct Variable;

struct StepNameClash {
    const Step* step = nullptr;
    bool functionBlock = false; // the name is S_FB, not the instance S
};

// The visible macro/enclosing step whose instance or function block is
// named `name` (case-insensitively, as IEC compares), if any.
std::optional<StepNameClash> stepNameClash(const Model& model, std::string_view name);

// "instance" or "function block"; "macro-step" or "enclosing step".
std::string_view clashedDeclaration(const StepNameClash& clash);
std::string_view clashedStepKind(const StepNameClash& clash);

// "'A1' is the instance of macro-step A1 in the generated code".
std::string stepNameClashDetail(const StepNameClash& clash, std::string_view name);

// A name the variable could take instead: its name with a suffix for its
// kind (A1_Sensor for an input, A1_Out for an output, A1_Mem for an
// internal variable), numbered when taken, free of every rule.
std::string suggestedVariableName(const Model& model, const Variable& variable);

// The values GG306's message names (docs/diagnostics.md): the variable, the
// step, "instance" or "function-block", "macro" or "enclosing", the
// suggested name.
std::vector<std::string> stepNameClashArguments(const Model& model, const Variable& variable,
                                                const StepNameClash& clash);

// "rename the variable (for example to 'A1_Sensor')".
std::string stepNameClashFix(const Model& model, const Variable& variable);

} // namespace core
