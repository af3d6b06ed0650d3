#pragma once

// The GEMMA layer as the Hierarchical Design Pattern sees it (spec §6): the
// visible steps in state order, each with the transitions it evaluates in the
// order it evaluates them, the parsed conditions and the tokens. Code
// generation, the simulator and the verifier all read this one structure, so
// they cannot disagree on what "effective", "waits for Complete" or "token"
// mean.

#include "core/codegen/nestedprogram.h"
#include "core/codegen/programproblem.h"
#include "core/condition/conditionparser.h"
#include "core/templates/gemma/gemmatemplate.h"
#include "core/model/model.h"

#include <optional>

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace core {

class Model;

enum class TokenPolarity {
    NormallyOpen,   // literal `X`: captures X = TRUE
    NormallyClosed, // literal `NOT X`: captures X = FALSE
};

// A token (spec §6.4) that takes effect: on a transition out of a
// macro/enclosing step, for a declared BOOL variable that occurs in the
// condition as a literal of one polarity only and is never an operand of
// = or <> (the same rules as the checks, GG207-GG212).
struct GemmaToken {
    std::string name;         // token variable: "Stop_F1_3_MEM"
    std::string variable;     // the BOOL variable, spelled as declared: "Stop"
    TokenPolarity polarity = TokenPolarity::NormallyOpen;
    std::string transitionId; // "F1->A2"
    // The literal nodes (`X` or the NOT of `NOT X`) in the transition's
    // parsed condition that read the token instead; in source order, never
    // empty. The first is "the" literal; a variable may occur several times.
    std::vector<int> literalNodes;
};

struct GemmaTransition {
    std::string id;           // "F1->A2", "F->D1"
    std::string targetId;
    int targetNumber = 0;
    int priority = 0;         // effective priority among the transitions of its source (1..n)
    bool family = false;      // a family transition evaluated by an F state
    bool negated = false;
    bool waitsForComplete = false;
    std::string conditionText;   // as the user wrote it
    cond::ParseResult condition; // the parse of conditionText
    // True when the condition parses and type-checks: only then is it used.
    // Otherwise the generated code and the simulator use FALSE.
    bool conditionUsable = false;
    std::map<int, std::string> substitutions; // literal node -> token variable
    std::vector<ProgramProblem> problems;       // of this transition, in the order found
};

struct GemmaStep {
    std::string id;   // "F1"
    int number = 0;   // State value
    std::string name; // official English name
    StepType type = StepType::Simple;
    bool initial = false;
    // The tokens of its own transitions, by transition priority, then by the
    // position of the literal in the condition.
    std::vector<GemmaToken> tokens;
    // What it evaluates, in order: family transitions first (F states only),
    // then its own effective transitions by priority.
    std::vector<GemmaTransition> transitions;

    // Its nested GRAFCET, when it has one (it then replaces the skeleton FB).
    std::optional<NestedGrafcet> nested;

    bool hasNestedBehaviour() const { return type != StepType::Simple; }
};

struct GemmaProgram {
    std::vector<GemmaStep> steps; // the visible steps, in state-number order
    std::string initialStepId;
    int initialNumber = 0;
    // Every problem of every step and transition, in program order (a family
    // transition's problems once, at its first use).
    std::vector<ProgramProblem> problems;
    EvolutionRule evolution = EvolutionRule::OneEvolutionPerScan;
    // BOOL variables read under an edge by a usable receptivity, spelled as
    // declared, in declaration order: each has a global <V>_PREV.
    std::vector<std::string> edgeVariables;

    bool hasNestedGrafcets() const;
    const GemmaStep* step(const std::string& id) const;
};

GemmaProgram buildGemmaProgram(const Model& model);

// What buildGemmaProgram builds for the nested GRAFCET of one GEMMA step,
// appending the same problems: nullopt (and nothing appended) when the step
// is hidden or its GRAFCET not effective. Without GG415 and the edge
// memories, which hold across GRAFCETs (core/codegen/nestedgrafcetset.h).
std::optional<NestedGrafcet> buildGemmaNestedGrafcet(const Model& model, const Step& step,
                                                     std::vector<ProgramProblem>& problems);

// The checks' code for a variable name the generated code cannot declare as
// it is: "GG301" (not an IEC identifier), "GG302" (a keyword), "GG303" (a
// fixed name the generator uses), "GG306" (the instance or function block of
// a visible macro/enclosing step of this model, core/model/stepnames.h);
// nullptr for a name it can. Such a variable is declared under another name
// (core/codegen/stgenerator.h), so no condition may read it: the condition is
// unusable.
const char* unusableNameCode(std::string_view name, const Model& model);

// Why, in English ("'State' is a name the generated code uses"); empty when
// unusableNameCode is nullptr.
std::string unusableNameDetail(std::string_view name, const Model& model);

// The arguments of the finding about a condition or action that reads such
// a variable: GG306's (core/model/stepnames.h), else the variable and the
// detail.
std::vector<std::string> unusableNameArguments(const Variable& variable, const Model& model);

// "Stop_F1_3_MEM".
std::string tokenVariableName(const std::string& variable, const std::string& sourceStepId, int priority);

} // namespace core
