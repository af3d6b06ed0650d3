#pragma once

#include "core/templates/gemma/gemmatemplate.h"
#include "core/machine/machine.h"
#include "core/model/grafcet.h"
#include "core/model/iectypes.h"
#include "core/model/status.h"
#include "core/model/userproperty.h"
#include "core/templates/packml/packmlconfiguration.h"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
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
    enum class Kind {
        Step,
        Transition,
        Variable,
        VariableList,
        Settings,
        Grafcet,
        Properties,
        Reset,
        PackMLSettings, // edition, options, initial state or initial mode
        PackMLCommand,  // id: the command's name ("Reset")
        PackMLModes,    // a mode added or removed
        PackMLMode,     // id: the mode's number ("4"): its name, comment, request, listings or GRAFCET choices
        Machine,        // the virtual machine's description
    };
    Kind kind;
    // Step id, transition id, variable name, command name or mode number;
    // empty for lists, settings, reset.
    std::string id;
    // Kind::Grafcet (id: the GEMMA step, or packml::grafcetKey): what changed inside its GRAFCET;
    // empty when the whole GRAFCET was created, replaced or removed.
    std::vector<GrafcetChange> grafcetChanges = {};
};

// Which fixed chart a model fills in.
enum class TemplateKind { Gemma, PackML };

// The model: a fixed template plus what the user changed. A GEMMA model has
// the GEMMA steps and transitions; a PackML model has none of them but a
// packml::Configuration (its commands and modes), its GRAFCETs stored under
// packml::grafcetKey(mode, state) and addressed by that key wherever a GEMMA
// step id addresses a GRAFCET. Name, settings, variables and properties are
// common. Every mutator keeps the invariants (exactly one initial step, unique
// non-empty variable names, per-source orders forming 1..m) and refuses what
// would break them with a failed Status, leaving the model untouched.
class Model {
public:
    Model(); // the GEMMA template with its defaults
    // A PackML model with this configuration, no variables and no GRAFCET
    // (so no choice may be Own yet); packml::newModel makes a new one.
    explicit Model(packml::Configuration configuration);
    Model(const Model& other);
    Model& operator=(const Model& other) = delete; // use assign(): observers must hear of it

    // Queries. Steps are in state-number order, transitions in template order.
    const std::vector<Step>& steps() const { return m_steps; }
    const std::vector<Transition>& transitions() const { return m_transitions; }
    const std::vector<Variable>& variables() const { return m_variables; }
    const ModelSettings& settings() const { return m_settings; }
    TemplateKind templateKind() const { return m_packml ? TemplateKind::PackML : TemplateKind::Gemma; }
    // The PackML part; nullptr for a GEMMA model.
    const packml::Configuration* packml() const { return m_packml ? &*m_packml : nullptr; }

    const Step* step(std::string_view id) const;
    const Transition* transition(std::string_view id) const;
    const Variable* variable(std::string_view name) const; // case-insensitive
    const Step& initialStep() const; // GEMMA models only: a PackML model has no steps

    // Nested GRAFCETs, by GEMMA step id, including those of steps that are
    // hidden or simple now: they are kept for when the step comes back. In a
    // PackML model, by packml::grafcetKey: exactly the Own choices.
    const std::map<std::string, Grafcet, std::less<>>& grafcets() const { return m_grafcets; }
    const Grafcet* grafcet(std::string_view stepId) const;
    // The GRAFCET that is the body of S_FB: the step is visible, a macro-step
    // or an enclosing step, and has one; nullptr otherwise. PackML: the
    // GRAFCET that runs in (mode, state) of the key: its own, or mode k's
    // own for "same as k"; nullptr when the mode disables the state.
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
    // PackML: a key of an existing mode and a state that holds a GRAFCET;
    // setGrafcet makes the choice Own, removeGrafcet None, and
    // addGrafcetStep creates no GRAFCET (choose Own first).
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
    // A refactoring: every condition (PackML commands and mode requests
    // included), token, receptivity and action that uses the variable follows.
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

    // The virtual machine (core/machine/machine.h): components wired to the
    // variables by name. GEMMA models only for now (a PackML model's is
    // always empty). setMachine replaces the whole description; it refuses
    // one with structural problems (Machine::structuralProblems). Wiring to
    // unknown variables or variables of the wrong kind is allowed: the checks
    // report it. renameVariable rewires the machine too.
    const machine::Machine& machine() const { return m_machine; }
    Status setMachine(machine::Machine machine);

    // Settings.
    Status setName(std::string name);
    Status setCycleTimeMs(int cycleTimeMs);
    void setDialect(Dialect dialect);
    void setEvolutionRule(EvolutionRule rule);

    // PackML (spec packml.md §3, §5.1). Each fails with "not-packml" on a
    // GEMMA model. Texts and numbers are kept as written (the checks report
    // them); mode numbers are 1..31, each once.
    Status setPackMLOptions(packml::Options options); // edition and options
    Status setPackMLInitialState(packml::State state);
    Status setPackMLInitialMode(int mode);
    Status setCommandCondition(packml::Command command, std::string condition);
    Status setCommandComment(packml::Command command, std::string comment);
    // A mode with the defaults of a new one (every state enabled, mode
    // changes in Stopped, Idle, Aborted); `name` only for user modes (4..31).
    Status addMode(int number, std::string name = {});
    // Its GRAFCETs go with it; "same as" it becomes none.
    Status removeMode(int number);
    Status renameMode(int number, std::string name); // user modes only
    Status setModeComment(int number, std::string comment);
    Status setModeRequest(int number, std::string condition); // empty: none
    Status setModeDisabled(int number, packml::StateSet disabled);
    Status setModeChangeStates(int number, packml::StateSet states);
    // Own creates an empty GRAFCET; leaving Own removes it.
    Status setGrafcetChoice(int mode, packml::State state, packml::GrafcetChoice choice);

    void resetToTemplate(); // PackML: a new model of the same edition
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
    bool ownsGrafcetKey(std::string_view key) const;
    Status unknownGrafcetOwner(std::string_view key) const;
    Status notPackML() const;
    packml::Mode* mutableMode(int number);
    Status findMutableMode(int number, packml::Mode*& mode);
    void renameInPackMLConditions(const std::string& previous, const std::string& newName);
    void gemmaInvariantViolations(std::vector<std::string>& problems) const;
    void packMLInvariantViolations(std::vector<std::string>& problems) const;
    const Grafcet* effectivePackMLGrafcet(std::string_view key) const;
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
    std::optional<packml::Configuration> m_packml;
    machine::Machine m_machine;
    std::uint64_t m_revision = 0;
    std::map<int, Observer> m_observers;
    int m_nextObserver = 1;
};

bool operator==(const Step& a, const Step& b);
bool operator==(const Transition& a, const Transition& b);
bool operator==(const Variable& a, const Variable& b);
bool operator==(const ModelSettings& a, const ModelSettings& b);

} // namespace core
