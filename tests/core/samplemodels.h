#pragma once

// Models for the PLCopen tests and the schema-validation samples, beside
// those of tests/support/modelfactory.h: the GG-Generator paper case study
// (tokens, all three step types, six function blocks) and seeded random ones.

#include "core/model/model.h"

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace samples {

// Throws std::logic_error with the refusal when a mutator refuses what a
// sample builder asks: a sample that cannot be built is a bug in the test.
void requireBuilt(const core::Status& status);

// A variable with no default value and no comment, of the given kind.
core::Variable variable(std::string name, core::IecType type, core::VariableKind kind);

// The template whose F1 has a small nested GRAFCET:
// 1 --RE Start--> 2 (N Lamp, Count := Count + 1) --5s/X2--> 3 (S Complete),
// over Start (input), Lamp (output) and Count (internal INT).
core::Model lampGrafcetModel();

// The filling-and-capping machine of the GG-Generator paper: F1-F5 and D3
// with nested behaviour, F6 hidden, tokens on F1 -> A2 (NOT Stop) and F1 -> F3.
core::Model caseStudyModel();

// A random model the checks accept without error: random step types, hidden
// steps and transitions, conditions over declared BOOL and numeric variables,
// negations, tokens, priorities, comments full of XML and ST delimiters.
// The same seed gives the same model.
core::Model randomModel(std::uint32_t seed);

// Gives every visible macro-step and enclosing step of the model, with
// probability 3/4, a random nested GRAFCET of 3 to 9 steps: a sequence with a
// loop back, extra transitions between random sets of steps (selections,
// simultaneous divergences and convergences, jumps), receptivities with edges,
// step activities and durations, continuous (some conditional) and stored
// actions on declared outputs, and Complete. Declares the outputs it writes.
// Not every such model is free of errors: the code generated from it must
// still be valid.
void addRandomNestedGrafcets(core::Model& model, std::uint32_t seed);

// Gives every visible macro-step and enclosing step of the model, with
// probability 3/4, a random nested GRAFCET the checks accept without error:
// sequences, selections (mostly exclusive, sometimes not), simultaneous
// divergences and convergences, loops, sometimes a second initial step and a
// random extra transition; receptivities with edges, durations, step
// activities, numeric comparisons, Complete and the FB's own continuous
// outputs; continuous (some conditional) actions on NestedOut0-3, stored
// actions (S, R, assignments) on NestedMem0-1, NestedCount and Complete.
// Declares the variables it uses (NestedIn0-2 inputs, outputs, NestedCount
// internal). Draws again while the checks find an error; leaves the model
// without nested GRAFCETs when 20 draws all have one. Returns the number of
// GRAFCETs added. The model's evolution rule is left as it is.
int addValidRandomNestedGrafcets(core::Model& model, std::mt19937& random);

// The GRAFCETs of addValidRandomNestedGrafcets, one at each key whatever
// the checks say (the caller decides), with the variables they use; for a
// PackML model each key's choice must already be Own.
void addRandomGrafcetsAt(core::Model& model, std::mt19937& random, const std::vector<std::string>& keys);

} // namespace samples

namespace samples {

// For the verification of both layers: A1 --Start--> F1 (a macro-step)
// --Done AND Complete--> A2 --TRUE--> A1, F -> D1 on EStop; inputs Start,
// Done, EStop, A, B, C; output Lamp; internal Flag; F1 has no GRAFCET yet.
core::Model nestedMachine();
// Adds a step, a transition to F1's GRAFCET (the model must accept them).
void addMachineStep(core::Model& model, int number, bool initial, std::vector<core::GrafcetAction> actions = {});
void addMachineTransition(core::Model& model, int number, std::vector<int> up, std::vector<int> down,
                          std::string receptivity);
// nestedMachine with 1 --A--> 2 (N Lamp, S Complete) --NOT A--> 1: a sound GRAFCET that completes.
core::Model soundMachine();
// nestedMachine with 1 --25m/X1 AND NOT 30m/X1--> 2 (N Out1, S Complete) --A--> 1
// and the output Out1, at the 20 ms cycle: step 2 becomes active in scan
// 75,002 (the 25 minutes are 75,000 cycles, far more than 16 bits count).
core::Model longTimerMachine();
// soundMachine whose step 1 sets Flag on activation, with F1 -> A2 negated
// (not waiting for Complete) on Flag, and F1 -> A3 on B: F1 -> A2 is always
// TRUE on both layers, though Flag is free on the GEMMA layer (GV103).
core::Model alwaysTrueMachine();
// soundMachine with F1 -> A3 on B: with Done, B and Complete TRUE both hold
// in the same scan (GV104).
core::Model overlapMachine();
// F1's steps 1 and 2 set one of Flag and Flag2 and reset the other, and the
// negated F1 -> A2 (Flag AND B) and F1 -> A3 (Flag2 AND B) can never hold
// together, though they can on the GEMMA layer (no GV104 on both layers).
core::Model exclusiveByMemoryMachine();
// Closed loop (docs/verification.md, "Closed loop (--machine)"): F1's
// GRAFCET 1 --A--> 2 (N Lamp) --B--> 1, and a machine whose single-acting
// cylinder Pusher is extended by Lamp, A its retracted switch and B its
// extended one, 3 cycles out (60 ms at 20 ms) and 2 back.
core::Model cylinderCell();

// Models seeded with each defect the verification of both layers finds
// (a nested step never active, an unsafe step, Unstable, branches that start
// together, a macro-step stuck without Complete, a race, a stored output on
// D1, a violated property, a timer, a GEMMA transition always TRUE, two that
// hold together or never do), with the properties to check on each.
struct SeededModel {
    std::string name;
    core::Model model;
    std::vector<std::string> properties;
};
std::vector<SeededModel> seededDefectModels();

} // namespace samples
