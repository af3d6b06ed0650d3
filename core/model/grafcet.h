#pragma once

// The nested GRAFCET of one macro-step or enclosing step (IEC 60848 subset,
// spec grafcet-layer.md §2): numbered steps with their actions, transitions
// between sets of steps, receptivities. The texts (receptivities, actions)
// are kept as the user wrote them, like GEMMA conditions, so that a text
// that does not parse yet is never lost; one parser reads them for the
// checks, the code generator and the simulator.
//
// Elements are addressed by step number and transition number, never by
// pointers handed out for writing. Every mutator keeps the invariants (step
// and transition numbers unique and positive, every transition with at
// least one upstream and one downstream step, all of them existing steps,
// no step twice in one set, action indices in range) or refuses with a
// failed Status, leaving the GRAFCET untouched. What a valid GRAFCET needs
// beyond that (an initial step, reachable steps...) is for the checks.

#include "core/model/status.h"

#include <string>
#include <string_view>
#include <vector>

namespace core {

// When an action of a step acts (spec §2).
enum class ActionTiming {
    Continuous,   // `N V`, `V`, `N V IF <condition>`: while the step is active
    OnActivation, // `S V`, `R V`, `V := <expr>`: when the step is activated
    OnDeactivation, // the same forms, when the step is deactivated
};

struct GrafcetAction {
    ActionTiming timing = ActionTiming::Continuous;
    std::string text; // "A_Plus", "N Valve IF Level < 10", "S Complete", "Count := Count + 1"

    bool operator==(const GrafcetAction&) const = default;
};

struct GrafcetStep {
    int number = 1; // unique within the GRAFCET; its activity is X<number>
    bool initial = false;
    std::string comment;
    std::vector<GrafcetAction> actions; // in the order they run and are drawn

    bool operator==(const GrafcetStep&) const = default;
};

struct GrafcetTransition {
    int number = 1;               // unique within the GRAFCET; shown as T<number>
    std::vector<int> upstream;    // step numbers, in branch order (left to right)
    std::vector<int> downstream;  // step numbers, in branch order
    std::string receptivity;

    bool operator==(const GrafcetTransition&) const = default;
};

// What a GRAFCET operation changed, for the model's observers.
struct GrafcetChange {
    enum class Kind { Step, StepList, Transition, TransitionList };
    Kind kind = Kind::Step;
    int number = 0; // the step or transition; 0 for the lists

    bool operator==(const GrafcetChange&) const = default;
};

class Grafcet {
public:
    // Steps in the order they were added (the layout orders them itself),
    // transitions likewise: the order of transitions leaving one step is the
    // left-to-right order of its selection branches.
    const std::vector<GrafcetStep>& steps() const { return m_steps; }
    const std::vector<GrafcetTransition>& transitions() const { return m_transitions; }

    const GrafcetStep* step(int number) const;
    const GrafcetTransition* transition(int number) const;
    std::vector<int> initialSteps() const;
    // The transitions whose upstream (downstream) set contains the step.
    std::vector<const GrafcetTransition*> transitionsFrom(int stepNumber) const;
    std::vector<const GrafcetTransition*> transitionsTo(int stepNumber) const;
    // One more than the largest number in use (1 for none).
    int nextStepNumber() const;
    int nextTransitionNumber() const;

    // Steps.
    Status addStep(GrafcetStep step);
    // Removes the step from every transition; a transition left without
    // upstream or downstream steps is removed with it (as SFC editors do).
    Status removeStep(int number);
    // Gives the step a new number: transitions follow, and the references
    // X<old> and t/X<old> in the receptivities and actions of this GRAFCET
    // are rewritten.
    Status renumberStep(int number, int newNumber);
    Status setStepInitial(int number, bool initial);
    // Exactly these steps become initial.
    Status setInitialSteps(const std::vector<int>& numbers);
    Status setStepComment(int number, std::string comment);

    // Actions of a step, by index in its list.
    Status addAction(int stepNumber, GrafcetAction action, int index = -1); // -1: append
    Status setAction(int stepNumber, int index, GrafcetAction action);
    Status removeAction(int stepNumber, int index);
    Status moveAction(int stepNumber, int from, int to);

    // Transitions.
    Status addTransition(GrafcetTransition transition);
    Status removeTransition(int number);
    Status setUpstream(int number, std::vector<int> steps);
    Status setDownstream(int number, std::vector<int> steps);
    Status setReceptivity(int number, std::string receptivity);

    // Rewrites every identifier equal to oldName (case-insensitively) in the
    // receptivities and actions; returns the numbers of what changed
    // (steps and transitions) through the lists given.
    void renameIdentifier(std::string_view oldName, std::string_view newName,
                          std::vector<int>& changedSteps, std::vector<int>& changedTransitions);

    // The changes of the last successful mutation, in the order they happened.
    const std::vector<GrafcetChange>& lastChanges() const { return m_lastChanges; }

    // Empty when every invariant holds; otherwise one line per violation
    // (a loader builds GRAFCETs element by element and checks with this).
    std::vector<std::string> invariantViolations() const;

    // True when both hold the same steps and transitions in the same order.
    bool sameContent(const Grafcet& other) const;

private:
    GrafcetStep* mutableStep(int number);
    GrafcetTransition* mutableTransition(int number);
    Status checkStepSet(const std::vector<int>& steps, std::string_view which) const;
    Status setStepSet(int number, std::vector<int> steps, std::vector<int> GrafcetTransition::*set,
                      std::string_view which);
    void beginChanges() { m_lastChanges.clear(); }
    void changed(GrafcetChange::Kind kind, int number = 0) { m_lastChanges.push_back({kind, number}); }

    std::vector<GrafcetStep> m_steps;
    std::vector<GrafcetTransition> m_transitions;
    std::vector<GrafcetChange> m_lastChanges;
};

} // namespace core
