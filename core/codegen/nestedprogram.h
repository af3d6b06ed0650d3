#pragma once

// A nested GRAFCET as the function block S_FB executes it (spec
// grafcet-layer.md §4): the steps in number order with their parsed actions,
// the transitions in number order with their parsed receptivities, the TONs
// of the time-dependent receptivities and the continuous outputs with their
// drivers. The code generator prints it, the simulator runs it and the
// verifier explores it: one structure, one reading of the semantics.
//
// Built by buildGemmaProgram (gemmaprogram.h) for every visible macro-step
// and enclosing step that has a nested GRAFCET; GemmaStep::nested holds it.

#include "core/condition/actionparser.h"
#include "core/condition/conditionparser.h"
#include "core/model/grafcet.h"
#include "core/model/span.h"

#include <optional>
#include <span>

#include <cstdint>
#include <map>
#include <string_view>
#include <string>
#include <vector>

namespace core {

enum class EvolutionRule;
class Model;
class SymbolTable;
struct ProgramProblem;
struct Step;
struct Variable;

// One action of a step. Unusable actions (they do not parse or type-check,
// or write what they may not) are kept for the comments of the generated
// code and do nothing.
struct NestedAction {
    ActionTiming timing = ActionTiming::Continuous;
    int index = 0;                 // in the step's list of actions (GrafcetStep::actions)
    std::string text;              // as the user wrote it
    cond::ActionParseResult parsed;
    bool usable = false;
    // The variable written, spelled as declared, or "Complete".
    std::string target;
    bool targetIsComplete = false;
};

struct NestedStep {
    int number = 0;
    bool initial = false;
    std::string comment;
    // In list order, each group apart (spec §4.2: on-deactivation actions of
    // the steps that left run before the on-activation actions of those that
    // entered).
    std::vector<NestedAction> onActivation;
    std::vector<NestedAction> onDeactivation;
    std::vector<NestedAction> continuous;
    // Indices into NestedGrafcet::timers of the TONs with IN := X<number>.
    std::vector<int> timers;
};

// The TON of one time-dependent receptivity `t/Xn` (one per step and
// duration, shared by every receptivity that reads it).
struct NestedTimer {
    int step = 0;
    std::int64_t durationMs = 0;
    std::string name; // the FB's TON instance, a reserved name (spec §4.5)
};

struct NestedTransition {
    int number = 0;
    std::vector<int> upstream;   // as in the model, branch order
    std::vector<int> downstream;
    std::string text;            // the receptivity as written
    cond::ParseResult receptivity; // parsed in the Nested context
    // True when it parses and type-checks: only then is it used. Otherwise
    // the generated code and the simulator use FALSE (the transition never fires).
    bool usable = false;
    // StepDuration node -> index into NestedGrafcet::timers.
    std::map<int, int> timerOfNode;
};

// An output the FB computes from its continuous actions (spec §4.2 (3),
// §4.3): the OR of X<step> AND condition over its drivers.
struct ContinuousOutput {
    std::string variable;     // spelled as declared, or "Complete"
    bool isComplete = false;
    struct Driver {
        int step = 0;
        int action = 0;       // index into that NestedStep::continuous
    };
    std::vector<Driver> drivers; // in step-number order, then action order
};

struct NestedGrafcet {
    std::string stepId;       // the GEMMA step: "F1"
    EvolutionRule rule{};     // the model's setting
    std::vector<NestedStep> steps;             // by number
    std::vector<NestedTransition> transitions; // by number
    std::vector<NestedTimer> timers;           // by step number, then duration
    std::vector<ContinuousOutput> outputs;     // by variable declaration order; Complete last
    // Variables written by usable stored actions, declared spelling, in
    // declaration order (Complete excluded).
    std::vector<std::string> storedTargets;
    // Variables read by usable receptivities, conditions and assigned values,
    // declared spelling, in declaration order.
    std::vector<std::string> readVariables;
    // Complete is written by a usable action (stored or continuous).
    bool writesComplete = false;
    // Until stable: evolutions allowed in one call before Unstable (the
    // number of transitions plus one).
    int maxEvolutions = 1;

    const NestedStep* step(int number) const;
    const NestedTransition* transition(int number) const;
    const ContinuousOutput* output(std::string_view variable) const; // case-insensitive
};

// Which variable names the generated code cannot declare as they are (each
// template reserves its own); a text reading such a variable is unusable.
class UnusableNames {
public:
    virtual ~UnusableNames() = default;
    // The checks' code ("GG301", "PM018"...), nullptr for a usable name.
    virtual const char* code(std::string_view name) const = 0;
    // Why, in English; empty for a usable name.
    virtual std::string detail(std::string_view name) const = 0;
    // The arguments of a finding about a text that reads `variable`.
    virtual std::vector<std::string> arguments(const Variable& variable) const = 0;
};

// Where a nested GRAFCET runs, as its builder needs it.
struct NestedScope {
    std::string element; // what its problems locate: the GEMMA step ("F1"), the PackML key ("3/Execute")
    std::string label;   // how its messages name it: "F1", "Manual Execute"
    // Every variable its texts may name, in declaration order (the slots of
    // the simulator's globals), and the lookup over exactly these.
    std::span<const Variable> variables;
    const SymbolTable& symbols;
    const UnusableNames& unusableNames;
};

// Builds the GRAFCET of a visible macro/enclosing step or of a PackML
// (mode, state), appending what is wrong with its receptivities and actions
// to `problems` (codes GG401-GG406, GG410, GG411, GG413, GG414, GG421; GG415
// across GRAFCETs is added by nestedgrafcetset.h).
NestedGrafcet buildNestedGrafcet(const Model& model, const NestedScope& scope, const Grafcet& grafcet,
                                 std::vector<ProgramProblem>& problems);

// The names the code of a nested GRAFCET declares inside S_FB, reserved for
// user variables of a model with nested GRAFCETs (spec grafcet-layer.md §4.5).
std::string stepActivityName(int step);                     // "X3"
std::string timerName(int step, std::int64_t durationMs);   // "GG_T3_5000ms"
std::string fireFlagName(int transition);                   // "GG_Fire1"
std::string edgeMemoryName(const std::string& variable);    // "Start_PREV"
inline constexpr std::string_view kUnstableName = "Unstable";

} // namespace core
