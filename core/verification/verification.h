#pragma once

// Proves properties of the GEMMA layer (docs/verification.md) and gives, for
// each one that does not hold, a scenario that replays the violation in the
// simulator.
//
// What is verified is the finite system the generated PROGRAM GEMMA is
// (spec §6.6), read from the one intermediate form, core::GemmaProgram:
// - the state is a *configuration* (State, Entry, tokens);
// - at every scan the inputs (the model's variables) take any value of their
//   IEC type, independently of the previous scan;
// - the Complete output of a nested step's function block is, per step,
//   either free (any value at every scan, the entry scan included: the user's
//   nested behaviour may complete at any time, or never) or automatic (TRUE at
//   every scan, as the generated skeleton FB).
// The reachable configurations are explored exactly from the start (State =
// initial step, Entry = TRUE, tokens FALSE). The successors of a
// configuration come from partitioning the input valuations by which
// transition fires (evaluation order, family first, `AND Complete` where the
// transition waits for it, token literals read the tokens, the entry block
// clearing the tokens first), then, when none fires, by the token updates.
//
// Tokens of one step with the same literal (`Stop` on two transitions) always
// hold the same value and count once. Tokens of steps other than the active
// one are cleared before they are next read, so they do not make
// configurations differ. Within one step the reachable token sets can be
// exponential in the number of its tokens (a macro-step whose Complete is
// free lets every pulse through), so they are computed symbolically, as
// binary decision diagrams over the tokens and the condition atoms
// (core/verification/decisiondiagram.h); the steps themselves are explored one by one,
// shortest distances first, which gives shortest counterexamples.
//
// Conditions are decided exactly for boolean structure and for comparisons of
// a variable with constants (intervals per variable, integer or real domain,
// IEC type ranges). Any other comparison (`A + B > C`, `X = Y` between
// numbers) is a free boolean: that only adds behaviour, so a "never" claim
// (dead, unreachable, stuck) is never wrong. A claim that needs a path to a
// configuration is confirmed by replaying its counterexample in the
// simulator; one that cannot be confirmed is downgraded to info and says so.

#include "core/checks/diagnostic.h"
#include "core/simulation/scenario.h"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace core {

class Model;

// What the verifier assumes about the Complete output of one nested step.
enum class CompleteAssumption {
    Free,      // any value at every scan (default)
    Automatic, // TRUE at every scan, as the generated skeleton FB
};

struct VerificationOptions {
    // By nested step id ("F1"); a step not listed is Free.
    std::map<std::string, CompleteAssumption> complete;
    // The budget of one run, the same for the command line and the editor:
    // what is not decided within it is named by GV100 findings (the result is
    // then not exhaustive), and every property decided is still reported.
    // Decision-diagram nodes of all steps together (memory: about 70 bytes
    // each, so the default stays near 300 MB).
    std::size_t maxDiagramNodes = 4'000'000;
    // Distinct simulator states the search for a real violation of a
    // property may keep, when the exploration's violation does not replay
    // (core/verification/concretesearch.h); it also stops at timeLimit.
    std::size_t maxConcreteStates = 20'000;
    // Wall-clock time of the analysis; zero or less: no limit. With the
    // counterexamples written and replayed after it, a run ends within about
    // one more second.
    std::chrono::milliseconds timeLimit{4000};
    // Polled now and then; returning true abandons the run (result.cancelled).
    std::function<bool()> cancelled;

    // Both layers (docs/verification.md, "Both layers"): properties checked
    // in addition to the model's own (`never P` / `always P`), e.g. from
    // `ggstudio-cli verify --property`.
    std::vector<std::string> properties;
    // Time counted in scans: every TON elapses exactly when the PLC's would,
    // instead of "may or may not have elapsed" (more states).
    bool exactTime = false;
    // Program states (both layers) the exploration may visit (memory: about
    // 150 bytes each).
    std::size_t maxProgramStates = 2'000'000;
    // Under the timer abstraction, the runs that do not replay in the
    // simulator are searched again with time counted in scans; that search
    // stops once it has found them all. True: it explores everything anyway
    // (the same findings, more time; the tests compare the two).
    bool wholeExactTimeExploration = false;
    // Stored internal BOOLs nothing reads are not kept apart in the
    // exploration's states (explore::Options::hideWriteOnlyVariables, as
    // SPIN hides write-only variables). False: kept apart (more states, the
    // same findings; the tests compare the two).
    bool hideWriteOnlyVariables = true;
    // Closed loop (docs/verification.md, "Closed loop (--machine)"): the
    // program is explored with the model's machine, the inputs its sensors
    // drive computed from the machine's state, operator inputs free, time
    // counted in scans. Ignored for a model without machine (and for PackML).
    bool closedLoop = false;
    // Faults explored with the machine (docs/verification.md, "Single
    // faults (--faults single)"): Single branches, before any scan while no
    // fault has happened, into one sensor stuck TRUE, stuck FALSE or
    // flickering, or one cylinder or conveyor jammed, for the rest of the
    // run. Only in closed loop; ignored otherwise.
    enum class Faults { None, Single };
    Faults faults = Faults::None;
};

// A run of the simulator from reset that shows a finding: scenario text the
// editor can load and `ggstudio-cli simulate MODEL FILE` can replay. Its
// expectations (`expect step`, `expect fired`) state what the finding claims
// at the scan it happens.
struct Counterexample {
    std::string text;       // scenario text, starts with a `#` comment naming the finding
    Scenario scenario;      // the same, parsed
    std::int64_t scans = 0; // scans to replay (the scenario's last scan)
    // True when it was replayed in core::Simulator and every expectation held.
    bool confirmed = false;
};

// One finding (docs/verification.md lists the codes).
// Which analysis decided a finding; an unconfirmed one says why its run does
// not replay accordingly.
enum class FindingOrigin {
    GemmaLayer,     // the GEMMA layer alone, Complete free or automatic (verification.cpp)
    GemmaLayerKept, // the same, kept on a model whose both layers were explored: its run may not exist there
    BothLayers,     // the exploration of both layers (bothlayers.cpp), under its abstractions
    PackML,         // the exploration of a PackML program (core/templates/packml/packmlverifier.h)
};

struct VerificationFinding {
    std::string code; // "GV101"
    Severity severity = Severity::Warning;
    // What it concerns first (a step or transition id), then the elements the
    // message names (the covering transitions of a dead one, ...).
    std::vector<std::string> elements;
    std::string message; // English
    std::vector<std::string> arguments; // the values the message names, for translation; first = elements[0]
    std::optional<Counterexample> counterexample;
    // The GEMMA step whose nested GRAFCET the finding is about (elements
    // then name its steps "F1/5" and transitions "F1/T3"); empty otherwise.
    std::string gemmaStep;
    // GV120-GV122: the property's index (the model's properties, then
    // VerificationOptions::properties); -1 otherwise.
    int property = -1;
    FindingOrigin origin = FindingOrigin::GemmaLayer;
    // Its run does not replay, and the search for one with time counted in
    // scans stopped at the run's time or size limit: more time may find it.
    bool replaySearchCut = false;
    // PackML models: where the finding points, as the checks' diagnostics
    // do (Target Mode, ModeState or Command); unset for GEMMA models.
    std::optional<Diagnostic> location;
};

// What a run decided about one of the engineer's properties.
enum class PropertyOutcome {
    Holds,     // proved for every reachable scan (GV121)
    Violated,  // a counterexample that replays to the violation (GV120)
    Undecided, // neither: the reason says why (GV122, GV123)
};

struct PropertyVerdict {
    PropertyOutcome outcome = PropertyOutcome::Undecided;
    std::string reason; // Undecided: why (English), empty otherwise
};

struct VerificationResult {
    // By code, then by element in state order / program order.
    std::vector<VerificationFinding> findings;

    // Raw facts, for cross-checks (e.g. against SPIN) and the editor.
    std::vector<std::string> reachableSteps;       // visible steps some reachable configuration has, state order
    std::vector<std::string> fireableTransitions;  // transitions that fire in some reachable scan, program order, each once
    // Reachable configurations (State, Entry, tokens); saturates at SIZE_MAX.
    std::size_t configurations = 0;
    std::size_t maxDepth = 0;       // scans from the start to the farthest reachable configuration
    bool exhaustive = true;         // false when the budget left something undecided (GV100)
    bool cancelled = false;

    // Both layers (models with nested GRAFCETs or properties), by GEMMA step id:
    std::map<std::string, std::vector<int>> reachableNestedSteps;      // active after some evolution or Initialization call, ascending
    std::map<std::string, std::vector<int>> fireableNestedTransitions; // fire in some reachable call, ascending
    std::map<std::string, std::vector<int>> unsafeNestedSteps;         // activated while already active
    std::vector<std::string> unstableSteps;                            // until stable: Unstable reachable
    std::vector<std::string> properties;  // the texts checked: the model's, then the options'
    std::vector<bool> propertyHolds;      // per property: proved (FALSE when violated, undecided or not checkable)
    std::vector<PropertyVerdict> propertyVerdicts; // per property: holds, violated or undecided
    std::vector<std::string> abstractions; // what the exploration abstracted (English), empty when exact
    std::size_t programStates = 0;         // explored states of both layers (0: not explored)
    bool bothLayers = false;               // the exploration of both layers ran
    bool closedLoop = false;               // it ran with the model's machine (VerificationOptions::closedLoop)
    bool singleFaults = false;             // it ran with VerificationOptions::Faults::Single
    std::size_t faultChoices = 0;          // single faults: the faults a scan may begin (sensors x 3 kinds + jams)
    std::size_t faultedStates = 0;         // single faults: explored states in which a fault is in effect

    // A finding of severity error or warning other than GV100 and GV123: a
    // property does not hold.
    bool violated() const;
    // Something was left undecided: the budget ran out (GV100, not exhaustive),
    // a property is undecided (GV123), or a claim is reported only as "not
    // confirmed" because its run does not replay in the simulator.
    bool undecided() const;
};

// Verifies the model with the given assumptions, by its template's verifier.
// Never throws for any model the Model class accepts.
VerificationResult verifyModel(const Model& model, const VerificationOptions& options = {});

// verifyModel for a GEMMA model: a hidden initial step makes every visible
// step unreachable (GV101), as on the PLC. In closed loop the GEMMA layer's
// findings that claim a run (GV104-GV107) are dropped, being decided for
// arbitrary sensors: the exploration with the machine decides them.
VerificationResult verifyGemmaModel(const Model& model, const VerificationOptions& options = {});

// "F1", "F1->A2", or "F1->D3, F1->A2" for several: the elements joined by ", ".
std::string verificationElementLabel(const VerificationFinding& finding);

// Whether a run with these options is closed loop: asked, and the model has a machine.
bool runsClosedLoop(const Model& model, const VerificationOptions& options);

// Codes, for the editor and tests.
namespace verification {
inline constexpr const char* kIncomplete = "GV100";       // warning: the budget ran out before these were decided
inline constexpr const char* kUnreachableStep = "GV101";  // warning
inline constexpr const char* kDeadTransition = "GV102";   // warning
inline constexpr const char* kAlwaysTrue = "GV103";       // warning
inline constexpr const char* kOverlap = "GV104";          // info
inline constexpr const char* kNoReturn = "GV105";         // warning
inline constexpr const char* kStuck = "GV106";            // error
inline constexpr const char* kNoEmergencyStop = "GV107";  // error
// Both layers (docs/verification.md lists them).
inline constexpr const char* kNestedStepNeverActive = "GV110"; // warning
inline constexpr const char* kNestedTransitionDead = "GV111";  // warning
inline constexpr const char* kUnsafeNestedStep = "GV112";      // warning
inline constexpr const char* kUnstableReachable = "GV113";     // warning
inline constexpr const char* kBranchesTogether = "GV114";      // warning
inline constexpr const char* kNeverComplete = "GV115";         // error
inline constexpr const char* kWaitsForNoComplete = "GV116";    // warning
inline constexpr const char* kStoredRace = "GV117";            // warning
inline constexpr const char* kOutputOnEmergencyStop = "GV118"; // error: a continuous output
inline constexpr const char* kStoredOutputOnEmergencyStop = "GV119"; // info: a stored output (a memory)
inline constexpr const char* kPropertyViolated = "GV120";      // error
inline constexpr const char* kPropertyHolds = "GV121";         // info
inline constexpr const char* kPropertyUnusable = "GV122";      // warning
inline constexpr const char* kPropertyUndecided = "GV123";     // warning: neither proved nor shown violated
} // namespace verification

} // namespace core
