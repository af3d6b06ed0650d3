#pragma once

// Structured editing of a nested GRAFCET, as CODESYS and other SFC editors
// offer it: the user names a step or a transition and an operation, and the
// operation adds, removes or reconnects whole pieces so that the GRAFCET
// keeps its shape (a sequence stays connected, a branch rejoins its
// convergence). Plain functions on a core::Grafcet built on its mutators.
//
// Every operation either succeeds or returns a failed Status and leaves the
// GRAFCET exactly as it was (each works on a copy and assigns it at the
// end). New steps and transitions take the next free numbers
// (Grafcet::nextStepNumber, nextTransitionNumber); new transitions get the
// receptivity TRUE, as CODESYS gives them, for the user to replace. The
// operations that create elements report their numbers through `created`
// (may be null), so that the editor can select them.

#include "core/model/grafcet.h"
#include "core/model/status.h"

#include <string_view>
#include <vector>

namespace core {

inline constexpr std::string_view kNewTransitionReceptivity = "TRUE";

// The numbers of what an operation created, in creation order.
struct GrafcetCreated {
    std::vector<int> steps;
    std::vector<int> transitions;
};

// Copied steps with the transitions among them, for pasting elsewhere.
struct GrafcetFragment {
    std::vector<GrafcetStep> steps;             // in the source GRAFCET's order
    std::vector<GrafcetTransition> transitions; // their upstream and downstream steps all in `steps`

    bool empty() const { return steps.empty(); }
};

// step → T → N, the transitions that left `step` now leave N (a new step
// after a step, the CODESYS way: the step keeps its place and its
// incoming links, what followed it follows N).
Status insertStepAfterStep(Grafcet& grafcet, int step, GrafcetCreated* created = nullptr);
// N → T → step, the transitions that reached `step` now reach N. An
// initial step passes its initial flag to N, the new top of its sequence.
Status insertStepBeforeStep(Grafcet& grafcet, int step, GrafcetCreated* created = nullptr);
// transition → N → T → the transition's former downstream steps.
Status insertStepAfterTransition(Grafcet& grafcet, int transition, GrafcetCreated* created = nullptr);
// The transition's former upstream steps → T → N → transition.
Status insertStepBeforeTransition(Grafcet& grafcet, int transition, GrafcetCreated* created = nullptr);

// A new alternative branch leaving `step`, to the right of its branches:
// step → Ta → N → Tb → the join, the step where the step's branches
// converge (selectionJoin). Refused for a step without outgoing transition.
Status addSelectionBranchAtStep(Grafcet& grafcet, int step, GrafcetCreated* created = nullptr);
// The same, beside `transition` (right after it in branch order); the
// transition must leave exactly one step.
Status addSelectionBranchAtTransition(Grafcet& grafcet, int transition, GrafcetCreated* created = nullptr);
// A new branch leaving `step`, to the right of its branches, that ends on
// a new step with no transition after it (an exit step, IEC 60848 allows
// it): step → T → N. On a step without outgoing transition, the sequence
// goes on with N.
Status addBranchEndingOnStep(Grafcet& grafcet, int step, GrafcetCreated* created = nullptr);
// Where the selection leaving `step` converges: the step the most of its
// branches reach going down (not through `step`), the nearest of those;
// with one branch, the step it leads to. 0 when the step has no outgoing
// transition; `step` itself when its branches only come back to it.
int selectionJoin(const Grafcet& grafcet, int step);

// A new step N at the right of the simultaneous divergence of `transition`
// and, when the section is closed, of its convergence (the nearest
// transition below whose upstream steps are all reached from the
// divergence's branches; for a transition with one downstream step D, D's
// only outgoing transition when D is its only upstream step). Without a
// convergence the new branch ends on N.
Status addParallelBranch(Grafcet& grafcet, int transition, GrafcetCreated* created = nullptr);
// That convergence of the transition's simultaneous divergence; 0 for none
// or an unknown transition.
int simultaneousConvergence(const Grafcet& grafcet, int transition);

// A new transition fromStep → toStep, at the right of fromStep's branches.
// The layout draws it as a loop line or a jump arrow (grafcetlayout.h).
// Refused when such a transition exists already.
Status addJump(Grafcet& grafcet, int fromStep, int toStep, GrafcetCreated* created = nullptr);

// Removes the step and repairs what it connected:
//  - when it has one outgoing transition O, leaving only it (a sequence),
//    O goes too and the transitions that reached the step reach O's
//    downstream steps (an initial step passes its flag to them);
//  - else, when it has one incoming transition I, reaching only it, I goes
//    too and the transitions that left the step leave I's upstream steps;
//  - else it goes as Grafcet::removeStep removes it (transitions lose it,
//    those left without upstream or downstream steps go).
Status removeStepWithRepair(Grafcet& grafcet, int step);
// Removes a selection branch: its first transition (it must leave one step
// that has other branches) and the steps reached only through it, with
// their transitions.
Status removeSelectionBranch(Grafcet& grafcet, int firstTransition);
// Removes the parallel branch that starts with `firstStep` (a downstream
// step of a simultaneous divergence with other branches): the steps reached
// only through it, with their transitions; the convergence loses them.
Status removeParallelBranch(Grafcet& grafcet, int firstStep);

// Numbers the steps 1..n and the transitions 1..m in drawing order (the
// independent parts of the drawing left to right, each top to bottom, each
// row left to right). References X<n> and t/X<n> follow (renumberStep).
// The order of the lists, hence the drawing, stays.
Status renumberAll(Grafcet& grafcet);

// Sets a transition's upstream and downstream steps at once, for the shapes
// the structured operations do not reach.
Status connectDirectly(Grafcet& grafcet, int transition, std::vector<int> upstream, std::vector<int> downstream);

// The steps named (unknown numbers are skipped) and the transitions among
// them: every transition whose upstream and downstream steps were all named.
GrafcetFragment copyFragment(const Grafcet& grafcet, const std::vector<int>& steps);
// Adds the fragment with fresh numbers; references X<n> and t/X<n> to its
// own steps in its texts follow, references to other steps stay. Pasted
// steps are never initial. With afterStep (not 0) the fragment must be one
// piece with one entry step (no transition of the fragment reaches it) and
// one exit step (none leaves it): afterStep → T → entry ... exit → what
// followed afterStep, as insertStepAfterStep does. With 0 it stands apart.
Status pasteFragment(Grafcet& grafcet, const GrafcetFragment& fragment, int afterStep,
                     GrafcetCreated* created = nullptr);

// What a new macro-step or enclosing step usually needs: initial step 1 →
// T1 → step 2 → T2 → step 3, the exit step, which sets Complete (`S
// Complete` on activation) for the GEMMA layer to leave the state.
Grafcet usualGrafcet();

} // namespace core
