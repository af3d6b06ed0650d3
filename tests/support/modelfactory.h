#pragma once

// Models the tests and benchmarks share: the realistic model and the stress
// model the issues' performance figures refer to, and random edit sequences
// for the property tests.

#include "core/model/model.h"

#include <cstdint>
#include <random>
#include <span>
#include <string>

namespace factory {

// A bottle-filling machine on the template: 11 visible states (A1 A2 A4 A5
// A6 A7 F1 F2 F4 D1 D2), 20 variables of BOOL, INT and REAL, a condition on
// every effective transition, tokens on three transitions out of F1, and all
// three step types (F1 macro, F4 enclosing, the rest simple).
core::Model realisticModel();

// 500 variables (400 BOOL, 100 INT), every step and transition visible,
// every condition 30 operands long.
core::Model stressModel();

// Six nested GRAFCETs (F1, F2, F3, F5, A7, F4) of 40 steps: a sequence of
// blocks, each a three-way parallel section of three steps per branch, with
// a timer on every branch, and a loop back to the initial step; 20 BOOL
// inputs In<n>, 20 outputs Out<n>, an internal INT Count.
core::Model nestedStressModel();

// For the verifier: every step and transition of the template visible, 40
// BOOL variables spread over the conditions (each condition reads three of
// them, `(A AND NOT B) OR C`), and a token on every variable of every
// transition out of a macro or enclosing step.
core::Model verificationStressModel();

// For the verifier's budget (issue 15): every step and transition of the
// template visible, 8 INT, 8 BOOL and 2 REAL variables, and on every
// transition a condition of `operands` operands joined by AND and OR.
// Comparisons only (`Speed3 > 10 AND Level5 <= 200 ...`) when `mixed` is
// false; otherwise comparisons of INT and REAL variables with constants,
// BOOL variables (some negated) and opaque comparisons (`Speed1 + Speed2 >
// 40`) in turn. The same arguments give the same model.
core::Model comparisonVerificationModel(int operands, bool mixed);

// The comparison model with 12 operands, except that the conditions of
// A1->F1 and F1->A2 are about 5,000 characters long (`(In0 AND Speed3 > 17)
// OR ...` over 16 variables), and D2->A5 can never fire (`Speed0 > 10 AND
// Speed0 < 5`): that GV102 must be found whatever happens to the huge ones.
core::Model hugeConditionVerificationModel();

// A nested GRAFCET of `steps` steps in one sequence that loops back to step
// 1 (the initial one): step n with the continuous action "Out<n>", after it
// transition n with the receptivity "Go<n>". A tall drawing for the page
// breaking of the exports.
core::Grafcet loopedSequence(int steps);

// The realistic model whose F1 (a macro-step) has loopedSequence(steps)
// (its Out<n> and Go<n> undeclared: drawing and opening do not need them).
core::Model longGrafcetModel(int steps);

// Issue 32's unstable GRAFCET: a model whose initial step F1 (a macro-step)
// holds a cycle of `steps` steps (step 1 initial, transition n from step n
// to step n + 1, the last back to step 1), every receptivity TRUE, under the
// evolution rule *until stable*: every scan makes the most evolutions the
// search for stability allows (steps + 1) and ends Unstable.
core::Model unstableGrafcetModel(int steps = 10000);

// For the verification of both layers (issue 19): six nested GRAFCETs (F1,
// F2, F3, F5 macro-steps, F4 and D3 enclosing steps), each a three-way
// parallel section of `branchLength` steps per branch between a fork and a
// join, with a step that sets Complete and one that waits for an
// acknowledgement; 20 stored BOOL variables (each branch's first step sets
// one, the join resets them; two more mark the batch), continuous outputs,
// tokens on F1 -> A2 (NOT Stop) and F1 -> F3, and a reachable path A1 -> F2
// -> F1 -> F5 -> F4 -> A6 -> A1 with F1 -> D3 and the emergency stop.
core::Model bothLayersStressModel(int branchLength = 3);

// Issue 36's case-study-sized model, in the spirit of the GG-Generator
// paper's filling and capping machine: the paper's GEMMA conditions and
// tokens (F1 -> A2 on NOT Stop, F1 -> F3 on EmptyMachine), 22 BOOL inputs
// and the paper's two numeric ones (PieceCount, Pressure), 14 BOOL outputs,
// a stored Alarm (Alarm := NOT (CP1 AND CP2 AND CP3) when a bottle leaves
// F1's join, reset by F2), and six nested GRAFCETs: F1 (fill, cap, eject),
// F3 (emptying), F5 (one semi-automatic cycle) and D3 (capping by hand
// while the filler goes on) each a three-station parallel section; F2 (the
// preparation run) a sequence; F4 (manual and station test) a selection that
// is not exclusive (Manual and StationTest may hold together), so that its
// step 4 can be activated while active (unsafe).
core::Model caseStudyModel();

// Issue 36's growing series for the verifier against SPIN: one GEMMA layer
// whatever the size (A1 -> F2 -> F1 and from F1 to F5 -> F4 -> A6, F3, F6,
// D3 -> A2, A3 -> A4, the emergency stop F -> D1 -> A5 -> A7 -> A4 and D1
// -> D2 -> A5; six BOOL inputs), and `nestedGrafcets` (1 to 16) nested
// GRAFCETs, one per step: first the template's eight steps that are not
// simple (F1, F2, F5, F4, F3, F6, D3, A7: F4, F6 and D3 are enclosing steps,
// which the GEMMA layer may leave in mid-cycle), then A2, A6, A5, A4, A3,
// D2, D1, A1 made macro-steps. Each is a three-way parallel section between
// a fork and a join (as bothLayersStressModel's) with its own inputs and
// output; the `storedBools` stored BOOLs Mem<j> go to GRAFCET j mod
// nestedGrafcets, each set on activation of one branch step and reset by
// the join, so they are part of the explored state (and those an enclosing
// step leaves set multiply the states). Branches are max(2, ceil(per
// GRAFCET / 3)) steps long.
core::Model verificationSeriesModel(int nestedGrafcets, int storedBools);

// The GEMMA conditions of the GG-Generator paper's filling and capping
// machine, one per transition it uses: caseStudyModel and the core tests'
// samples::caseStudyModel write the same 34.
struct CaseStudyCondition {
    const char* transition;
    const char* condition;
};
std::span<const CaseStudyCondition> caseStudyConditions();

// For the verifier's budget inside one scan (issue 32): the template with
// A1 --Start--> F1, F1 a macro-step whose GRAFCET is a cycle of `steps`
// steps (1 initial) evolving until stable, transition n from step n to n + 1
// (the last back to 1) with the receptivity TRUE when `inputs` is 0, else
// the BOOL input In<n mod inputs>. With TRUE everywhere no scan of F1 ever
// settles: each runs `steps` + 1 evolutions and ends Unstable.
core::Model unstableCycleModel(int steps, int inputs);

// Applies `count` random operations (valid and invalid ones: the model must
// refuse the latter) and returns how many the model accepted.
int applyRandomEdits(core::Model& model, std::mt19937& random, int count);

} // namespace factory
