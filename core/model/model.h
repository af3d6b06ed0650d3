#pragma once

#include "core/templates/gemma/gemmatemplate.h"
#include "core/model/grafcet.h"
#include "core/model/iectypes.h"
#include "core/model/status.h"
#include "core/model/userproperty.h"

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace core {

enum class Dialect { Iec, Codesys };
std::string_view dialectName(Dialect dialect); // "iec", "codesys"
bool parseDialect(std::string_view name, Dialect& dialect);

struct Step {
    std::string id;  // template id, "A1" ... "D3"
    int number = 0;  // State value in generated code
    Family family = Family::A;
    StepType type = StepType::Simple;
    bool initial = false;
    bool hidden = false;
    std::string comment;
};

struct Transition {
    std::string id;     // "A1->F4"; the family transition is "F->D1"
    std::string source; // a step id, or kFamilySource for the family transition
    std::string target;
    std::string condition;
    // Position among all outgoing transitions of the source, hidden ones
    // included (1..m). The effective priority (Model::priority) is the rank
    // among the effective ones, so hidden transitions keep their place.
    int order = 1;
    bool negated = false;
    bool hidden = false;
    std::vector<std::string> tokens; // BOOL variable names, spelled as declared

    bool isFamilyTransition() const { return source == kFamilySource; }
};

// What a variable is to the machine (spec grafcet-layer.md §2). Existing
// files, written before kinds existed, declare inputs.
enum class VariableKind {
    Input,    // read from the machine; set in simulation and scenarios, never written by actions
    Output,   // written by the actions of nested GRAFCETs; shown in simulation
    Internal, // a memory the program writes and reads
};
std::string_view variableKindName(VariableKind kind); // "input", "output", "internal"
bool parseVariableKind(std::string_view name, VariableKind& kind);

struct Variable {
    std::string name;
    IecType type = IecType::Bool;
    std::string defaultValue; // empty: the type's implicit default
    std::string comment;
    VariableKind kind = VariableKind::Input; // last, so that {name, type, default, comment} still reads
};

// How a nested GRAFCET evolves in one call of its function block (spec
// grafcet-layer.md §4.1).
enum class EvolutionRule {
    OneEvolutionPerScan, // the default: one evolution per PLC cycle, as SFC runtimes do
    UntilStable,         // IEC 60848's search for stability, bounded, reporting Unstable
};
std::string_view evolutionRuleName(EvolutionRule rule); // "one-per-scan", "until-stable"
bool parseEvolutionRule(std::string_view name, EvolutionRule& rule);

struct ModelSettings {
    std::string name = "GEMMA";
    int cycleTimeMs = 20;
    Dialect dialect = Dialect::Iec;
    EvolutionRule evolution = EvolutionRule::OneEvolutionPerScan;
};

inline constexpr int kMinCycleTimeMs = 1;
inline constexpr int kMaxCycleTimeMs = 3'600'000;

// What an operation changed, for observers (the editor's Document, caches).
struct ModelChange {
    enum class Kind { Step, Transition, Variable, VariableList, Settings, Grafcet, Properties, Reset };
    Kind kind;
    std::string id; // step id, transition id or variable name; empty for lists, settings, reset
    // Kind::Grafcet (id: the GEMMA step): what changed inside its GRAFCET;
    // empty when the whole GRAFCET was created, replaced or removed.
    std::vector<GrafcetChange> grafcetChanges = {};
};

// The GEMMA-GRAFCET model: the fixed template plus what the user changed.
// Every mutator keeps the invariants (exactly one initial step, unique
// non-empty variable names, per-source orders forming 1..m) and refuses what
// would break them with a failed Status, leaving the model untouched.
class Model {
public:
    Model(); // the template with its defaults
    Model(const Model& other);
    Model& operator=(const Model& other) = delete; // use assign(): observers must hear of it

    // Queries. Steps are in state-number order, transitions in template order.
    const std::vector<Step>& steps() const { return m_steps; }
    const std::vector<Transition>& transitions() const { return m_transitions; }
    const std::vector<Variable>& variables() const { return m_variables; }
    const ModelSettings& settings() const { return m_settings; }

    const Step* step(std::string_view id) const;
    const Transition* transition(std::string_view id) const;
    const Variable* variable(std::string_view name) const; // case-insensitive
    const Step& initialStep() const;

    // Nested GRAFCETs, by GEMMA step id, including those of steps that are
    // hidden or simple now: they are kept for when the step comes back.
    const std::map<std::string, Grafcet, std::less<>>& grafcets() const { return m_grafcets; }
    const Grafcet* grafcet(std::string_view stepId) const;
    // The GRAFCET that is the body of S_FB: the step is visible, a macro-step
    // or an enclosing step, and has one; nullptr otherwise.
    const Grafcet* effectiveGrafcet(std::string_view stepId) const;

    // A transition is effective when it and both its ends are visible.
    bool isEffective(const Transition& transition) const;
    bool isEffective(std::string_view transitionId) const;
    // 1..n among the effective outgoing transitions of its source; 0 when not effective.
    int priority(std::string_view transitionId) const;
    // All outgoing transitions of a source, in order (hidden ones included).
    std::vector<const Transition*> outgoing(std::string_view source) const;
    // The effective outgoing transitions of a source, by priority.
    std::vector<const Transition*> effectiveOutgoing(std::string_view source) const;
    std::vector<const Transition*> incoming(std::string_view target) const;

    // Steps.
    Status setStepType(std::string_view stepId, StepType type);
    Status setInitialStep(std::string_view stepId);
    Status setStepHidden(std::string_view stepId, bool hidden);
    Status setStepComment(std::string_view stepId, std::string comment);

    // Transitions.
    Status setTransitionHidden(std::string_view transitionId, bool hidden);
    // Moves an effective transition to the given priority (1..n), shifting the
    // others like a list reorder.
    Status setPriority(std::string_view transitionId, int priority);
    // Sets the position among all outgoing transitions (1..m), hidden included.
    Status setOrder(std::string_view transitionId, int order);
    Status setCondition(std::string_view transitionId, std::string condition);
    Status setNegated(std::string_view transitionId, bool negated);
    Status setTokens(std::string_view transitionId, std::vector<std::string> tokens);

    // Nested GRAFCETs, addressed by GEMMA step id and nested step or
    // transition number. A step that is simple has no GRAFCET created for it
    // (make it a macro-step or an enclosing step first); one it kept from
    // before can still be edited. See grafcet.h for each operation.
    Status setGrafcet(std::string_view stepId, Grafcet grafcet); // creates or replaces (loaders, undo)
    Status removeGrafcet(std::string_view stepId);
    // Creates the step's GRAFCET when it has none.
    Status addGrafcetStep(std::string_view stepId, GrafcetStep step);
    Status removeGrafcetStep(std::string_view stepId, int number);
    Status renumberGrafcetStep(std::string_view stepId, int number, int newNumber);
    Status setGrafcetStepInitial(std::string_view stepId, int number, bool initial);
    Status setGrafcetInitialSteps(std::string_view stepId, const std::vector<int>& numbers);
    Status setGrafcetStepComment(std::string_view stepId, int number, std::string comment);
    Status addGrafcetAction(std::string_view stepId, int stepNumber, GrafcetAction action, int index = -1);
    Status setGrafcetAction(std::string_view stepId, int stepNumber, int index, GrafcetAction action);
    Status removeGrafcetAction(std::string_view stepId, int stepNumber, int index);
    Status moveGrafcetAction(std::string_view stepId, int stepNumber, int from, int to);
    Status addGrafcetTransition(std::string_view stepId, GrafcetTransition transition);
    Status removeGrafcetTransition(std::string_view stepId, int number);
    Status setGrafcetUpstream(std::string_view stepId, int number, std::vector<int> steps);
    Status setGrafcetDownstream(std::string_view stepId, int number, std::vector<int> steps);
    Status setReceptivity(std::string_view stepId, int number, std::string receptivity);

    // Variables. Names are unique case-insensitively and never empty.
    Status addVariable(Variable variable, int index = -1); // -1: append
    Status removeVariable(std::string_view name);
    // A refactoring: every condition, token, receptivity and action that
    // uses the variable follows.
    // The new name must be a valid identifier (identifierProblem() of
    // iectypes.h finds none), so that the rewritten conditions still parse.
    Status renameVariable(std::string_view oldName, std::string newName);
    Status setVariableType(std::string_view name, IecType type);
    Status setVariableDefault(std::string_view name, std::string defaultValue);
    Status setVariableComment(std::string_view name, std::string comment);
    Status setVariableKind(std::string_view name, VariableKind kind);
    Status moveVariable(std::string_view name, int index);
    int variableIndex(std::string_view name) const; // -1 when absent

    // The engineer's verification properties, in list order. An index out of
    // range fails; text is kept as written (checked by the verifier).
    const std::vector<UserProperty>& properties() const { return m_properties; }
    Status addProperty(UserProperty property, int index = -1); // -1: append
    Status setPropertyText(int index, std::string text);
    Status setPropertyComment(int index, std::string comment);
    Status removeProperty(int index);
    Status moveProperty(int from, int to);

    // Settings.
    Status setName(std::string name);
    Status setCycleTimeMs(int cycleTimeMs);
    void setDialect(Dialect dialect);
    void setEvolutionRule(EvolutionRule rule);

    void resetToTemplate();
    void assign(const Model& other); // replaces everything; observers get Reset

    // Change notification: every successful mutation bumps the revision and
    // calls each observer with what changed.
    using Observer = std::function<void(const ModelChange&)>;
    int addObserver(Observer observer);
    void removeObserver(int handle);
    std::uint64_t revision() const { return m_revision; }

    // Empty when every invariant holds; otherwise one line per violation.
    std::vector<std::string> invariantViolations() const;

    // True when both models hold the same user data (observers and revision aside).
    bool sameContent(const Model& other) const;

private:
    Step* mutableStep(std::string_view id);
    Transition* mutableTransition(std::string_view id);
    Variable* mutableVariable(std::string_view name);
    void notify(ModelChange::Kind kind, std::string id = {});
    void notifyGrafcet(std::string_view stepId, std::vector<GrafcetChange> changes);
    template <typename Edit>
    Status editGrafcet(std::string_view stepId, Edit edit);
    void renumberOrders(const std::vector<Transition*>& ordered);
    std::vector<Transition*> mutableOutgoing(std::string_view source);

    std::vector<Step> m_steps;
    std::vector<Transition> m_transitions;
    std::vector<Variable> m_variables;
    std::map<std::string, Grafcet, std::less<>> m_grafcets;
    ModelSettings m_settings;
    std::vector<UserProperty> m_properties;
    std::uint64_t m_revision = 0;
    std::map<int, Observer> m_observers;
    int m_nextObserver = 1;
};

bool operator==(const Step& a, const Step& b);
bool operator==(const Transition& a, const Transition& b);
bool operator==(const Variable& a, const Variable& b);
bool operator==(const ModelSettings& a, const ModelSettings& b);

} // namespace core
