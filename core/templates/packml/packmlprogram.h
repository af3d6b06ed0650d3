#pragma once

// A PackML model as its generated program runs it (spec packml.md §6): the
// commands and mode requests the code generates with their parsed
// conditions, per unit mode its enabled states with their transitions in
// priority order (skipping applied) and the mode changes it may grant, and
// one instance per (mode, enabled state holding a GRAFCET) with the nested
// GRAFCET it runs or the skeleton. The generator prints it, the simulator
// runs it and the verifier explores it: one reading of the semantics, as
// buildGemmaProgram is for GEMMA.

#include "core/codegen/programproblem.h"
#include "core/codegen/nestedprogram.h"
#include "core/condition/conditionparser.h"
#include "core/model/model.h"
#include "core/templates/packml/packmlrules.h"
#include "core/templates/packml/packmltemplate.h"

#include <string>
#include <vector>

namespace core::packml {

// A command or request condition as the program evaluates it. An unusable
// one (empty, or it does not parse or type-check as BOOL, or it reads a name
// the code cannot declare) is FALSE in the code, the simulator and the
// verifier; its problems say why.
struct ProgramCondition {
    std::string text; // as written
    cond::ParseResult parsed;
    bool usable = false;
};

struct ProgramCommand {
    Command command = Command::Reset;
    std::string name; // "Reset": Trig_Reset, Ev_Reset
    ProgramCondition condition;
};

struct ProgramState {
    State state = State::Stopped;
    // Spec §2.3 and §3.3: in priority order, skipping applied; the first
    // whose event (Ev_<C>) or SC (the instance's Complete) holds fires.
    std::vector<ModeTransition> transitions;
    int instance = -1; // index into PackmlProgram::instances; -1: no FB (wait states but Execute)
};

// A change the mode may grant to another (spec §3.4): in the states of
// S(c, r), in the scan its request rises.
struct ModeGrant {
    int targetMode = 0;
    StateSet states;
};

struct ProgramMode {
    int number = 0;
    std::string name; // "Production", a user mode's name: Trig_<name>, <name>_<State>
    StateSet enabled;
    std::vector<ProgramState> states; // the enabled ones, state-number order
    ProgramCondition request;         // text empty: the mode has no request condition
    // Some other mode may grant a change to this one and it has a request
    // condition: the code declares Trig_<name> (spec §6.2).
    bool requestGenerated = false;
    std::vector<ModeGrant> grants; // other modes, in mode order, with S(c, r) non-empty

    const ProgramState* state(State state) const;
};

// One function block instance <Mode>_<State> (spec §4, §6.1).
struct ProgramInstance {
    int mode = 0;
    State state = State::Stopped;
    std::string name;     // "Production_Execute"
    std::string typeName; // "Production_Execute_FB", the owner's, or the skeleton "Execute_FB"
    int ownerMode = 0;    // whose GRAFCET runs: this mode or the one it is the same as; 0: the skeleton
    int grafcet = -1;     // index into PackmlProgram::grafcets; -1: the skeleton

    bool isSkeleton() const { return grafcet < 0; }
};

// An own GRAFCET some instance runs, built once however many modes share it.
struct ProgramGrafcet {
    int ownerMode = 0;
    State state = State::Stopped;
    std::string key;      // grafcetKey(ownerMode, state): where its problems point
    std::string typeName; // "<Owner>_<State>_FB"
    NestedGrafcet grafcet;
};

struct PackmlProgram {
    std::string programName; // spec §6.1: packmlprogramname.h
    Options options;
    State initialState = State::Stopped;
    int initialMode = 1;
    EvolutionRule evolution = EvolutionRule::OneEvolutionPerScan;
    // The globals in slot order: the user variables, then the six PackTags
    // (packtags.h). Conditions and GRAFCETs name variables of this list.
    std::vector<Variable> variables;
    std::vector<ProgramCommand> commands;   // the generated ones (spec §6.2), command-number order
    std::vector<ProgramMode> modes;         // number order
    std::vector<ProgramInstance> instances; // mode, then state order
    std::vector<ProgramGrafcet> grafcets;   // owner mode, then state order
    std::vector<State> skeletons;           // skeleton FBs some instance uses, state-number order
    // BOOL variables read under an edge by a usable receptivity: each has a
    // global <V>_PREV (declared spelling, slot order).
    std::vector<std::string> edgeVariables;
    // What is wrong with the conditions, the names and the GRAFCETs: the
    // commands', each GRAFCET's (as the modes first use them), the requests',
    // then GG415 across GRAFCETs.
    std::vector<ProgramProblem> problems;

    const ProgramMode* mode(int number) const;
    const ProgramCommand* command(Command command) const;
    const ProgramInstance* instance(int mode, State state) const;
    // The slot of a variable in `variables` (ignoring case), -1 when none.
    int slotOf(std::string_view name) const;
};

PackmlProgram buildPackmlProgram(const Model& model);

// "Production_Execute", "Execute_FB", "Production_Execute_FB".
std::string instanceName(std::string_view modeName, State state);
std::string skeletonTypeName(State state);
std::string grafcetTypeName(std::string_view ownerModeName, State state);

} // namespace core::packml
