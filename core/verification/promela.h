#pragma once

// The GEMMA layer as a Promela model, so that SPIN can check, independently
// of core/verification/verification.cpp, what the built-in verifier claims
// (docs/verification.md, "SPIN cross-check").
//
// The model is the scan loop of the generated PROGRAM GEMMA (spec §6.6),
// read from core::GemmaProgram: one iteration of a `do` loop is one scan.
// Global state: State, Entry and the token bits. Inputs (and Complete) are
// chosen anew in every scan and forgotten after it (they are not part of the
// state between scans):
// - a BOOL variable: TRUE or FALSE;
// - a numeric variable compared with constants: one value per interval
//   between the constants it is compared with (and per constant), over the
//   values its IEC type allows, so comparisons of a variable with constants
//   are decided exactly;
// - any other comparison (`A > B`, `A + 1 > 3`): a free boolean per distinct
//   text;
// - Complete of the active nested step: free (any value) or TRUE, per step,
//   as core::VerificationOptions says.
// A scan: the entry block (Entry := FALSE, the step's tokens := FALSE), the
// FB (Complete), the transitions in evaluation order with `&& Complete` where
// they wait, the first that holds fires (State := target, Entry := TRUE),
// then the token updates with the new State.
//
// Verdicts come from SPIN's report of unreached code (`spin -o3` keeps every
// statement apart): each property has a *marker*, a statement alone on its
// line, and the line is reached in the exhaustive search iff the marker's
// claim holds somewhere in the reachable state space. Properties that need an
// "exists an input" for every reachable configuration (GV107, ...) are
// decided by a *probe* inside the scan: a deterministic enumeration of every
// input (d_step) in the configuration the scan starts in, whose flags drive
// marker lines.

#include "core/verification/verification.h"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace core {

class Model;

struct PromelaOptions {
    // By nested step id; a step not listed is Free (as VerificationOptions).
    std::map<std::string, CompleteAssumption> complete;
    // The one-scan probes (Holds, Fails, Overlap, NoFire, NoEmergencyStop
    // markers). Without them only Reach and Fire markers are written.
    bool probes = true;
};

// What a marker line claims when SPIN reaches it.
enum class PromelaMarkerKind {
    Reach,           // State = step at the start of some reachable scan (GV101 when never)
    Fire,            // transition fires from step in some reachable scan (GV102 when never, everywhere)
    Holds,           // its condition (AND Complete where it waits) is TRUE for some input, in some reachable configuration of step
    Fails,           // its condition is FALSE for some input there (GEMMA layer) / read FALSE in some reachable scan (both layers); GV103 when never
    Overlap,         // transition fires while `other`'s condition also holds (GV104)
    NoFire,          // a reachable configuration of step where no input fires any transition (necessary for GV106)
    NoEmergencyStop, // an F step's reachable configuration where no input leads to D1 in one scan (GV107)
    // Both layers (core/verification/promelaprogram.h); `step` is the GEMMA step.
    NestedActive,         // numbers {n}: nested step n is active after some call
    NestedFire,           // numbers {t}: nested transition t fires in some call
    UnsafeStep,           // numbers {n}: n is activated while already active
    SimultaneousBranches, // numbers {upstream step, transition, transition}: both fire from it together
    Race,                 // numbers {step, step}, variable: stored actions of both write it, opposite values, one scan
    Unstable,             // until stable: the call ends with a transition still firing
    OutputOnD1,           // variable: a continuous output TRUE in the scan that enters D1
    PropertyViolated,     // property: its index in the options' list
    CompleteTrue,         // the GRAFCET's Complete is TRUE after some call (GV116 when never)
};

struct PromelaMarker {
    PromelaMarkerKind kind = PromelaMarkerKind::Reach;
    std::string step;       // the step whose branch holds the marker
    std::string transition; // Fire, Holds, Fails, Overlap: the transition
    std::string other;      // Overlap: the later transition
    int line = 0;           // 1-based line of the marker statement in the text
    std::vector<int> numbers; // both layers: nested steps and transitions, as the kind says
    std::string variable;     // Race, OutputOnD1
    int property = -1;        // PropertyViolated
};

struct PromelaModel {
    std::string text;
    std::vector<PromelaMarker> markers; // in text order
};

PromelaModel buildPromela(const Model& model, const PromelaOptions& options = {});
std::string exportPromela(const Model& model, const PromelaOptions& options = {});

// How to run SPIN on the text so that the report is what readSpinReport
// expects: -o3 keeps every statement apart (no merging), so each marker line
// is reported on its own; -DSAFETY: a plain reachability search. Each scan
// explores every input a step reads, so the cost grows as 2^(inputs read by
// one step).
inline constexpr const char* kSpinGenerate = "spin -o3 -a";               // + FILE
inline constexpr const char* kSpinCompile = "gcc -O2 -DSAFETY -DMEMLIM=1024 -o pan pan.c";
inline constexpr const char* kSpinRun = "./pan -m200000 -w20";

// Where pan starts, and what it lists, are read from the environment when pan
// runs, so that one compiled pan serves many starts (docs/verification.md):
// - GG_START="gState=8 gEntry=0 tk_Stop_F1_2_MEM=1": the scan loop starts in
//   this configuration instead of the reset one (a variable not named keeps
//   its reset value; a name that is not a state variable of the model, or a
//   value it cannot hold, stops pan with exit code 2 before the search);
// - GG_LIST (any value): at the start of every scan the search explores, pan
//   prints `GG_CONFIG ` and the configuration in the syntax GG_START reads.
// - GG_UNTIL=N: a scan that enters State N (a transition from another step
//   into it fires) violates an assertion, which ends the search: with
//   GG_START in another step, "State N can become active" is then
//   SpinReport::untilReached.
// Without them the model is the plain scan loop from reset.
inline constexpr const char* kSpinStartVariable = "GG_START";
inline constexpr const char* kSpinListVariable = "GG_LIST";
inline constexpr const char* kSpinUntilVariable = "GG_UNTIL";

// A configuration a GG_LIST run printed: every state variable (State, Entry,
// every step's tokens) with its value.
struct SpinConfiguration {
    std::string text; // "gState=8 gEntry=0 tk_Stop_F1_2_MEM=1 ...": what GG_START reads
    int state = -1;   // gState's value
};

// The configurations a GG_LIST run printed, each once, in the order printed.
std::vector<SpinConfiguration> readSpinConfigurations(std::string_view panOutput);

// What SPIN's verifier (pan) printed, read.
struct SpinReport {
    // The search covered the whole state space without errors and printed
    // the unreached-code report of the scan process.
    bool complete = false;
    std::string problem;            // why not, in English; empty when complete
    std::vector<int> unreachedLines; // lines of statements of the scan process never executed
    long long statesStored = -1;
    long long depthReached = -1; // pan's deepest search stack (statements, not scans)
    // pan's "Stats on memory usage (in Megabytes)": "total actual memory
    // usage" (its hash table and search stack included) and "actual memory
    // usage for states"; -1 when not printed.
    double totalMemoryMb = -1;
    double stateMemoryMb = -1;
    // pan stopped at GG_UNTIL's assertion: the State it names was entered
    // (then not complete: the search was cut short on purpose).
    bool untilReached = false;

    // Reached: the marker's claim holds somewhere. False when not complete.
    bool reached(const PromelaMarker& marker) const;
};

SpinReport readSpinReport(std::string_view panOutput);

// Text safe inside a Promela comment, on one line: escaped as the ST writer
// escapes its comments (core::escapeComment: no control character, bidi
// override or invalid UTF-8 byte survives), then no `/*` or `*/` either.
std::string promelaComment(std::string_view text);

} // namespace core
