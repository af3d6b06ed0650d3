#include <catch2/catch.hpp>

#include "core/model/model.h"
#include "core/verification/promela.h"
#include "core/verification/verification.h"
#include "modelfactory.h"
#include "spinrunner.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <stdlib.h> // mkdtemp

namespace test_spin {

using namespace core;

// SPIN as an independent check of core::verifyModel: the model is exported as
// Promela (core/verification/promela.h), SPIN explores it exhaustively, and the verdicts it
// gives through its unreached-code report must be the built-in verifier's.
// docs/verification.md ("SPIN cross-check") says which property maps how.

namespace {

namespace fs = std::filesystem;
namespace code = verification;

using Set = std::set<std::string>;
using Pair = std::pair<std::string, std::string>;

// spin and the C compiler once per model (tests/support/spinrunner.h).
struct CompiledPan : spin::CompiledPan {
    CompiledPan(const PromelaModel& promela, const std::string& name) : spin::CompiledPan(promela.text, name) {}
};

// What SPIN says about the model, by marker kind.
struct SpinFacts {
    Set reachable;
    Set firing;              // transitions that fire from some step
    std::set<Pair> fires;    // (step, transition)
    std::set<Pair> holds;    // (step, transition)
    std::set<Pair> fails;    // (step, transition)
    std::set<Pair> overlaps; // (first, second)
    Set noFire;
    Set noEmergencyStop;
    // From one run per reachable configuration (GG_START):
    std::size_t configurations = 0;
    Set listed;   // the steps of the configurations GG_LIST printed
    Set stuck;    // a configuration from which no transition out of the step ever fires
    Set noReturn; // a configuration from which the initial step is never entered (GV106 steps included)
};

// One run from each reachable configuration SPIN lists, each stopped as soon
// as the initial step is entered (GG_UNTIL): when it is not, the search was
// exhaustive, and the step can be left iff one of its `fire` markers was reached.
void addConfigurationFacts(const CompiledPan& pan, const PromelaModel& promela, const GemmaProgram& program,
                           const std::string& panOutput, const SpinReport& fromReset, SpinFacts& facts)
{
    std::map<int, std::string> stepOfState;
    for (const GemmaStep& step : program.steps)
        stepOfState[step.number] = step.id;
    std::vector<std::string> starts;
    std::vector<std::string> stepOfStart;
    for (const SpinConfiguration& configuration : readSpinConfigurations(panOutput)) {
        auto step = stepOfState.find(configuration.state);
        if (step == stepOfState.end())
            continue; // a hidden initial step: the PLC runs no code
        starts.push_back(configuration.text);
        stepOfStart.push_back(step->second);
        facts.listed.insert(step->second);
    }
    facts.configurations = starts.size();
    const PromelaMarker* reachInitial = nullptr;
    for (const PromelaMarker& marker : promela.markers) {
        if (marker.kind == PromelaMarkerKind::Reach && marker.step == program.initialStepId)
            reachInitial = &marker;
    }
    // Generous: the search from a configuration covers part of the search from reset.
    const long long depth = std::max(10000LL, 4 * fromReset.depthReached);
    const std::vector<std::string> outputs = pan.runFrom(starts, program.initialNumber, depth);
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const SpinReport report = readSpinReport(outputs[i]);
        if (report.untilReached)
            continue; // left the step, and the initial step came back
        INFO("from " << starts[i] << ": " << report.problem << "\n" << outputs[i]);
        REQUIRE(report.complete);
        const std::string& step = stepOfStart[i];
        bool leaves = false;
        for (const PromelaMarker& marker : promela.markers)
            leaves = leaves || (marker.kind == PromelaMarkerKind::Fire && marker.step == step && report.reached(marker));
        if (!leaves)
            facts.stuck.insert(step);
        if (step != program.initialStepId) {
            REQUIRE(reachInitial);
            CHECK(!report.reached(*reachInitial)); // GG_UNTIL would have stopped the search
            facts.noReturn.insert(step);
        }
    }
}

SpinFacts spinFacts(const Model& model, const PromelaOptions& options, const std::string& name)
{
    const PromelaModel promela = buildPromela(model, options);
    const CompiledPan pan(promela, name);
    const std::string output = pan.run(std::string(kSpinListVariable) + "=1");
    const SpinReport report = readSpinReport(output);
    INFO(report.problem);
    REQUIRE(report.complete);
    REQUIRE(report.statesStored > 0);
    SpinFacts facts;
    addConfigurationFacts(pan, promela, buildGemmaProgram(model), output, report, facts);
    for (const PromelaMarker& marker : promela.markers) {
        if (!report.reached(marker))
            continue;
        const Pair at{marker.step, marker.transition};
        switch (marker.kind) {
        case PromelaMarkerKind::Reach: facts.reachable.insert(marker.step); break;
        case PromelaMarkerKind::Fire:
            facts.fires.insert(at);
            facts.firing.insert(marker.transition);
            break;
        case PromelaMarkerKind::Holds: facts.holds.insert(at); break;
        case PromelaMarkerKind::Fails: facts.fails.insert(at); break;
        case PromelaMarkerKind::Overlap: facts.overlaps.insert({marker.transition, marker.other}); break;
        case PromelaMarkerKind::NoFire: facts.noFire.insert(marker.step); break;
        case PromelaMarkerKind::NoEmergencyStop: facts.noEmergencyStop.insert(marker.step); break;
        default: break; // both layers' markers: buildPromela writes none
        }
    }
    return facts;
}

Set findings(const VerificationResult& result, const std::string& findingCode)
{
    Set out;
    for (const VerificationFinding& finding : result.findings) {
        if (finding.code == findingCode && !finding.elements.empty())
            out.insert(finding.elements.front());
    }
    return out;
}

const VerificationFinding* finding(const VerificationResult& result, const std::string& findingCode,
                                   const std::string& element)
{
    for (const VerificationFinding& f : result.findings) {
        if (f.code == findingCode && !f.elements.empty() && f.elements.front() == element)
            return &f;
    }
    return nullptr;
}

struct Comparison {
    SpinFacts spin;
    VerificationResult builtIn;
};

// Runs both and checks that they agree on every property SPIN cross-checks.
Comparison compare(const Model& model, const std::string& name,
                   const std::map<std::string, CompleteAssumption>& complete = {})
{
    PromelaOptions promelaOptions;
    promelaOptions.complete = complete;
    VerificationOptions verificationOptions;
    verificationOptions.complete = complete;
    Comparison c{spinFacts(model, promelaOptions, name), verifyModel(model, verificationOptions)};
    const SpinFacts& spin = c.spin;
    const VerificationResult& result = c.builtIn;
    REQUIRE(result.exhaustive);
    const GemmaProgram program = buildGemmaProgram(model);

    // GV101: reachable steps.
    CHECK(spin.reachable == Set(result.reachableSteps.begin(), result.reachableSteps.end()));
    Set unreachable;
    for (const GemmaStep& step : program.steps) {
        if (!spin.reachable.count(step.id))
            unreachable.insert(step.id);
    }
    CHECK(findings(result, code::kUnreachableStep) == unreachable);

    // GV102: transitions that fire; dead ones among those a reachable step evaluates.
    CHECK(spin.firing == Set(result.fireableTransitions.begin(), result.fireableTransitions.end()));
    Set dead;
    Set alwaysTrue;
    for (const GemmaStep& step : program.steps) {
        if (!spin.reachable.count(step.id))
            continue;
        for (const GemmaTransition& transition : step.transitions) {
            if (!spin.firing.count(transition.id))
                dead.insert(transition.id);
        }
    }
    CHECK(findings(result, code::kDeadTransition) == dead);
    // Dead by priority (the built-in names the covering transitions) exactly
    // when SPIN saw its condition hold somewhere.
    for (const std::string& id : dead) {
        bool holdsSomewhere = false;
        for (const Pair& at : spin.holds)
            holdsSomewhere = holdsSomewhere || at.second == id;
        const VerificationFinding* f = finding(result, code::kDeadTransition, id);
        REQUIRE(f);
        INFO(id << ": " << f->message);
        CHECK((f->elements.size() > 1) == holdsSomewhere);
    }

    // GV103: fires, never FALSE where evaluated, with transitions after it.
    for (const std::string& id : spin.firing) {
        bool neverFalse = true;
        bool hasLater = false;
        for (const GemmaStep& step : program.steps) {
            if (!spin.reachable.count(step.id))
                continue;
            for (std::size_t t = 0; t < step.transitions.size(); ++t) {
                if (step.transitions[t].id != id)
                    continue;
                neverFalse = neverFalse && !spin.fails.count({step.id, id});
                hasLater = hasLater || t + 1 < step.transitions.size();
            }
        }
        if (neverFalse && hasLater)
            alwaysTrue.insert(id);
    }
    CHECK(findings(result, code::kAlwaysTrue) == alwaysTrue);

    // GV104: an own transition that fires while a later one that can fire also holds.
    std::set<Pair> overlaps;
    for (const GemmaStep& step : program.steps) {
        for (const GemmaTransition& first : step.transitions) {
            for (const GemmaTransition& second : step.transitions) {
                if (!first.family && spin.overlaps.count({first.id, second.id})
                    && spin.fires.count({step.id, first.id}) && spin.fires.count({step.id, second.id}))
                    overlaps.insert({first.id, second.id});
            }
        }
    }
    std::set<Pair> builtInOverlaps;
    for (const VerificationFinding& f : result.findings) {
        if (f.code == code::kOverlap && f.elements.size() >= 2)
            builtInOverlaps.insert({f.elements[0], f.elements[1]});
    }
    CHECK(builtInOverlaps == overlaps);

    // GG_LIST printed a configuration of every reachable step, and only those.
    CHECK(spin.listed == spin.reachable);

    // GV106: a reachable configuration from which the step is never left; it
    // has no input that fires anything in one scan.
    CHECK(findings(result, code::kStuck) == spin.stuck);
    for (const std::string& id : spin.stuck)
        CHECK(spin.noFire.count(id));

    // GV105: a reachable configuration from which the initial step is never
    // entered again; not reported for a step that is stuck (GV106 says more).
    Set noReturn;
    for (const std::string& id : spin.noReturn) {
        if (!spin.stuck.count(id))
            noReturn.insert(id);
    }
    CHECK(findings(result, code::kNoReturn) == noReturn);

    // GV107: the F steps with a reachable situation that cannot enter D1 in one scan.
    CHECK(findings(result, code::kNoEmergencyStop) == spin.noEmergencyStop);
    return c;
}

// A random variant of the template: visibility, types, initial step,
// priorities, negation, tokens and conditions over BOOL, INT and REAL
// variables, with exact and opaque comparisons.
Model randomModel(std::mt19937& random, std::map<std::string, CompleteAssumption>& complete)
{
    static const std::vector<std::string> conditions{
        "A", "NOT B", "A AND NOT C", "A OR B", "A XOR C", "A = B", "N > 2", "N <= 1 AND A", "TRUE", "FALSE",
        "N = 3 OR NOT A", "(A OR N < 2) AND NOT B", "C AND N <> 2", "R > 1.5 AND R < 1.75", "N > 2 AND N < 3",
        "N > M", "NOT (N > M) AND A", "B AND C", "NOT A AND NOT C", "TRUE", "A OR NOT A", "B", "C"};
    auto chance = [&](int percent) { return std::uniform_int_distribution<int>(0, 99)(random) < percent; };
    auto index = [&](std::size_t size) { return std::uniform_int_distribution<std::size_t>(0, size - 1)(random); };
    Model model;
    for (const char* name : {"A", "B", "C"})
        REQUIRE(model.addVariable(Variable{name, IecType::Bool, "", ""}));
    REQUIRE(model.addVariable(Variable{"N", IecType::Int, "", ""}));
    REQUIRE(model.addVariable(Variable{"M", IecType::Usint, "", ""}));
    REQUIRE(model.addVariable(Variable{"R", IecType::Real, "", ""}));
    std::vector<std::string> stepIds;
    for (const Step& step : model.steps())
        stepIds.push_back(step.id);
    REQUIRE(model.setInitialStep(stepIds[index(stepIds.size())]));
    for (const std::string& id : stepIds) {
        if (id != model.initialStep().id && chance(15))
            REQUIRE(model.setStepHidden(id, true));
        const auto type = static_cast<StepType>(index(3));
        REQUIRE(model.setStepType(id, type));
        if (type != StepType::Simple)
            complete[id] = chance(50) ? CompleteAssumption::Free : CompleteAssumption::Automatic;
    }
    std::vector<std::string> transitionIds;
    for (const Transition& t : model.transitions())
        transitionIds.push_back(t.id);
    for (const std::string& id : transitionIds) {
        const std::string& condition = conditions[index(conditions.size())];
        REQUIRE(model.setCondition(id, condition));
        if (chance(10))
            REQUIRE(model.setTransitionHidden(id, true));
        if (chance(25))
            REQUIRE(model.setNegated(id, true));
        std::vector<std::string> tokens;
        for (const char* name : {"A", "B", "C"}) {
            if (condition.find(name) != std::string::npos && chance(50))
                tokens.push_back(name);
        }
        REQUIRE(model.setTokens(id, tokens));
        if (chance(30) && model.priority(id) > 0)
            REQUIRE(model.setPriority(id, 1));
    }
    return model;
}

Model realisticWith(const std::vector<std::pair<const char*, const char*>>& conditions)
{
    Model model = factory::realisticModel();
    for (const auto& [id, condition] : conditions)
        REQUIRE(model.setCondition(id, condition));
    return model;
}

// A1 (initial) -> F1 -> A2 -> A1, the other steps hidden. F1 is enclosing
// (its transitions do not wait for Complete) and leaves by F1->A2 with the
// given condition and tokens; with `trap`, also by F1->D2 when Trap is TRUE,
// to D2, which has no way out.
Model tokenLoop(const std::string& condition, const std::vector<std::string>& tokens, bool trap = false)
{
    Model model;
    for (const char* name : {"Go", "Ready", "Trap"})
        REQUIRE(model.addVariable(Variable{name, IecType::Bool, "", ""}));
    REQUIRE(model.setInitialStep("A1"));
    std::vector<std::string> stepIds;
    for (const Step& step : model.steps())
        stepIds.push_back(step.id);
    for (const std::string& id : stepIds) {
        if (id != "A1" && id != "F1" && id != "A2" && !(trap && id == "D2"))
            REQUIRE(model.setStepHidden(id, true));
    }
    REQUIRE(model.setStepType("F1", StepType::Enclosing));
    REQUIRE(model.setCondition("A1->F1", "TRUE"));
    REQUIRE(model.setCondition("A2->A1", "TRUE"));
    REQUIRE(model.setCondition("F1->A2", condition));
    REQUIRE(model.setTokens("F1->A2", tokens));
    if (trap)
        REQUIRE(model.setCondition("F1->D2", "Trap"));
    return model;
}

} // namespace

TEST_CASE("SPIN agrees with the verifier on the template", "[spin]")
{
    // Every condition empty: the generated code reads them as FALSE, so the
    // initial step A6 is stuck and nothing else is reachable.
    const Comparison c = compare(Model(), "template");
    CHECK(c.spin.reachable == Set{"A6"});
    CHECK(c.spin.firing.empty());
    CHECK(findings(c.builtIn, code::kStuck) == Set{"A6"});
}

TEST_CASE("SPIN agrees with the verifier on the realistic model", "[spin]")
{
    SECTION("Complete free")
    {
        const Comparison c = compare(factory::realisticModel(), "realistic");
        CHECK(c.spin.reachable.size() == 11);
        CHECK(c.spin.firing.count("F1->A2"));
        CHECK(c.spin.noEmergencyStop.empty());
        CHECK(!c.spin.overlaps.empty());
        // Every configuration leaves its step and leads back to A6, stale
        // tokens of the steps left included.
        CHECK(c.spin.configurations > 21);
        CHECK(c.spin.stuck.empty());
        CHECK(c.spin.noReturn.empty());
    }
    SECTION("Complete automatic")
    {
        std::map<std::string, CompleteAssumption> automatic;
        for (const char* id : {"A7", "F1", "F4"})
            automatic[id] = CompleteAssumption::Automatic;
        const Comparison c = compare(factory::realisticModel(), "realistic-auto", automatic);
        CHECK(c.spin.reachable.size() == 11);
    }
}

TEST_CASE("SPIN agrees with the verifier on seeded defects", "[spin]")
{
    SECTION("unreachable step: its only way in is covered by a higher priority")
    {
        const Comparison c = compare(realisticWith({{"A5->A7", "Reset AND Acknowledge AND NOT HomePosition"}}),
                                     "unreachable");
        CHECK(!c.spin.reachable.count("A7"));
        CHECK(findings(c.builtIn, code::kUnreachableStep) == Set{"A4", "A7"}); // A4 is entered from A7 only
        CHECK(findings(c.builtIn, code::kDeadTransition).count("A5->A7"));
    }
    SECTION("dead transition by priority")
    {
        const Comparison c = compare(realisticWith({{"A1->F2", "Start"}}), "priority");
        CHECK(!c.spin.firing.count("A1->F1"));
        CHECK(c.spin.holds.count({"A1", "A1->F1"}));
        CHECK(c.spin.reachable.count("F1")); // still entered from F2 and A4
        const VerificationFinding* f = finding(c.builtIn, code::kDeadTransition, "A1->F1");
        REQUIRE(f);
        CHECK(f->elements.size() > 1);
    }
    SECTION("dead transition by an unsatisfiable condition, numeric intervals decided exactly")
    {
        // No DINT lies strictly between 2 and 3; a REAL does between 45 and 45.5.
        const Comparison c = compare(realisticWith({{"F1->D2", "Fault AND FaultCount > 2 AND FaultCount < 3"},
                                                    {"D2->A5", "Acknowledge AND Temperature > 45 AND Temperature < 45.5"}}),
                                     "unsatisfiable");
        CHECK(!c.spin.firing.count("F1->D2"));
        CHECK(c.spin.firing.count("D2->A5"));
        CHECK(!c.spin.holds.count({"F1", "F1->D2"}));
        CHECK(findings(c.builtIn, code::kDeadTransition) == Set{"F1->D2"});
    }
    SECTION("always TRUE condition")
    {
        const Comparison c = compare(realisticWith({{"A1->F4", "Start OR NOT Start"}}), "always-true");
        CHECK(!c.spin.fails.count({"A1", "A1->F4"}));
        CHECK(findings(c.builtIn, code::kAlwaysTrue) == Set{"A1->F4"});
    }
    SECTION("hidden initial step: the PLC starts in a state without code")
    {
        Model model = factory::realisticModel();
        REQUIRE(model.setStepHidden("A6", true));
        const Comparison c = compare(model, "hidden-initial");
        CHECK(c.spin.reachable.empty());
        CHECK(findings(c.builtIn, code::kUnreachableStep).size() == 10);
    }
    SECTION("no way back to the initial step")
    {
        Model model = factory::realisticModel();
        REQUIRE(model.setTransitionHidden("A5->A6", true));
        REQUIRE(model.setTransitionHidden("F4->A6", true));
        const Comparison c = compare(model, "no-return");
        CHECK(c.spin.noReturn.count("A1"));
        CHECK(!c.spin.noReturn.count("A6"));
        CHECK(c.spin.stuck.empty());
        CHECK(findings(c.builtIn, code::kNoReturn).count("F1"));
    }
    SECTION("a step no transition can leave")
    {
        const Comparison c = compare(realisticWith({{"D2->A5", "Acknowledge AND NOT Acknowledge"}}), "stuck");
        CHECK(c.spin.stuck == Set{"D2"});
        CHECK(findings(c.builtIn, code::kStuck) == Set{"D2"});
        CHECK(!findings(c.builtIn, code::kNoReturn).count("D2"));
    }
    SECTION("F states that cannot enter D1 in one scan")
    {
        // F1 keeps its own F1->D1; F2 and F4 only had the family transition.
        const Comparison c = compare(realisticWith({{"F->D1", "EmergencyStop AND NOT EmergencyStop"}}), "no-d1");
        CHECK(c.spin.noEmergencyStop == Set{"F2", "F4"});
    }
}

TEST_CASE("SPIN agrees with the verifier where tokens decide GV105 and GV106", "[spin]")
{
    // In each, F1's entry configuration (tokens cleared) can leave F1 and
    // come back to A1, or can do neither in one scan: what matters is the
    // configurations F1 reaches after tokens were set.
    SECTION("stuck once both tokens are set: Go XOR Ready reads two tokens")
    {
        const Comparison c = compare(tokenLoop("Go XOR Ready", {"Go", "Ready"}), "tokens-stuck");
        CHECK(c.spin.stuck == Set{"F1"});
        const VerificationFinding* f = finding(c.builtIn, code::kStuck, "F1");
        REQUIRE(f);
        CHECK(f->message.find("tokens") != std::string::npos);
    }
    SECTION("never stuck although no input fires on entry: Go AND Ready reads two tokens")
    {
        const Comparison c = compare(tokenLoop("Go AND Ready", {"Go", "Ready"}), "tokens-not-stuck");
        CHECK(c.spin.noFire.count("F1"));
        CHECK(c.spin.stuck.empty());
        CHECK(findings(c.builtIn, code::kStuck).empty());
    }
    SECTION("no way back once the token on Go is set: only the trap is left")
    {
        const Comparison c = compare(tokenLoop("(Go XOR TRUE) AND Ready", {"Go"}, true), "tokens-no-return");
        CHECK(c.spin.stuck == Set{"D2"});
        CHECK(c.spin.noReturn == Set{"F1", "D2"});
        const VerificationFinding* f = finding(c.builtIn, code::kNoReturn, "F1");
        REQUIRE(f);
        CHECK(f->message.find("tokens") != std::string::npos);
    }
    SECTION("the same without the token: F1 can always come back")
    {
        const Comparison c = compare(tokenLoop("(Go XOR TRUE) AND Ready", {}, true), "tokens-return");
        CHECK(c.spin.stuck == Set{"D2"});
        CHECK(c.spin.noReturn == Set{"D2"});
        CHECK(findings(c.builtIn, code::kNoReturn).empty());
    }
}

TEST_CASE("SPIN agrees with the verifier on random models", "[spin]")
{
    std::mt19937 random(20261122);
    std::map<std::string, int> seen; // finding code -> models that have it
    for (int i = 0; i < 8; ++i) {
        std::map<std::string, CompleteAssumption> complete;
        const Model model = randomModel(random, complete);
        INFO("random model " << i);
        const Comparison c = compare(model, "random" + std::to_string(i), complete);
        Set codes;
        for (const VerificationFinding& f : c.builtIn.findings)
            codes.insert(f.code);
        for (const std::string& findingCode : codes)
            ++seen[findingCode];
    }
    // The sample exercises every property SPIN cross-checks, held and violated.
    for (const char* findingCode : {code::kUnreachableStep, code::kDeadTransition, code::kAlwaysTrue, code::kOverlap,
                                    code::kNoReturn, code::kStuck, code::kNoEmergencyStop}) {
        INFO(findingCode);
        CHECK(seen[findingCode] > 0);
    }
}

TEST_CASE("readSpinReport reads pan's verdicts and refuses incomplete searches", "[spin]")
{
    const std::string complete = "State-vector 20 byte, depth reached 8, errors: 0\n"
                                 "        2 states, stored\n"
                                 "unreached in proctype scan\n"
                                 "\tmodel.pml:20, state 22, \"mark = 1\"\n"
                                 "\tmodel.pml:33, state 42, \"-end-\"\n"
                                 "\t(2 of 42 states)\n"
                                 "Stats on memory usage (in Megabytes):\n"
                                 "    0.000\tequivalent memory usage for states (stored*(State-vector + overhead))\n"
                                 "    0.287\tactual memory usage for states\n"
                                 "  128.000\tmemory used for hash table (-w24)\n"
                                 "  128.730\ttotal actual memory usage\n"
                                 "\npan: elapsed time 0 seconds\n";
    const SpinReport report = readSpinReport(complete);
    CHECK(report.complete);
    CHECK(report.statesStored == 2);
    CHECK(report.totalMemoryMb == 128.73);
    CHECK(report.stateMemoryMb == 0.287);
    CHECK(readSpinReport("errors: 0\n").totalMemoryMb == -1);
    CHECK(report.unreachedLines == std::vector<int>{20, 33});
    CHECK(!report.reached(PromelaMarker{PromelaMarkerKind::Reach, "A1", "", "", 20, {}, "", -1}));
    CHECK(report.reached(PromelaMarker{PromelaMarkerKind::Reach, "A1", "", "", 21, {}, "", -1}));

    CHECK(!readSpinReport("pan:1: assertion violated (0) (at depth 3)\nState-vector 20 byte, depth reached 3, "
                          "errors: 1\nunreached in proctype scan\n")
               .complete);
    const SpinReport until = readSpinReport(
        "pan:1: assertion violated (((gUntil==255)||(gState!=gUntil))||(gFrom==gUntil)) (at depth 160)\n"
        "State-vector 84 byte, depth reached 160, errors: 1\n");
    CHECK(until.untilReached);
    CHECK(!until.complete);
    CHECK(until.depthReached == 160);
    CHECK(report.depthReached == 8);
    CHECK(!report.untilReached);
    const SpinReport cut = readSpinReport("error: max search depth too small\nerrors: 0\nunreached in proctype scan\n");
    CHECK(!cut.complete);
    CHECK(cut.problem.find("depth") != std::string::npos);
    CHECK(!readSpinReport("").complete);
}

TEST_CASE("pan starts where GG_START says, lists with GG_LIST and stops where GG_UNTIL says", "[spin]")
{
    const Model model = factory::realisticModel();
    const PromelaModel promela = buildPromela(model);
    const GemmaProgram program = buildGemmaProgram(model);
    auto reach = [](const PromelaModel& in, const std::string& step) {
        for (const PromelaMarker& m : in.markers) {
            if (m.kind == PromelaMarkerKind::Reach && m.step == step)
                return m;
        }
        FAIL("no reach marker for " << step);
        return PromelaMarker{};
    };
    auto number = [&](const std::string& id) { return std::to_string(program.step(id)->number); };
    const CompiledPan pan(promela, "start");

    // Default: reset. The configurations listed start with the reset one.
    const std::string fromReset = pan.run(std::string(kSpinListVariable) + "=1");
    const std::vector<SpinConfiguration> listed = readSpinConfigurations(fromReset);
    REQUIRE(!listed.empty());
    CHECK(listed.front().text == "gState=6 gEntry=1 tk_Stop_F1_2_MEM=0 tk_VerifyMode_F1_3_MEM=0 tk_Fault_F1_4_MEM=0");
    CHECK(listed.front().state == 6);
    const SpinReport plain = readSpinReport(pan.run());
    REQUIRE(plain.complete);
    CHECK(plain.reached(reach(promela, "A6")));
    CHECK(readSpinConfigurations(pan.run()).empty());

    // From D1: A6 comes back through A5, and GG_UNTIL stops the search there.
    const std::string d1 = std::string(kSpinStartVariable) + "='gState=" + number("D1") + "'";
    const SpinReport fromD1 = readSpinReport(pan.run(d1));
    REQUIRE(fromD1.complete);
    CHECK(fromD1.reached(reach(promela, "D1")));
    CHECK(fromD1.reached(reach(promela, "A6")));
    const SpinReport untilA6 = readSpinReport(pan.run(d1 + " " + kSpinUntilVariable + "=" + number("A6")));
    CHECK(untilA6.untilReached);
    CHECK(untilA6.statesStored < fromD1.statesStored);

    // The template (every condition FALSE): nothing ever fires. A6 staying
    // active is not entering it; from A1, A1 is reached and A6 is not.
    const PromelaModel templatePromela = buildPromela(Model());
    const CompiledPan templatePan(templatePromela, "start-template");
    const SpinReport stays = readSpinReport(templatePan.run(std::string(kSpinUntilVariable) + "=6"));
    CHECK(stays.complete);
    CHECK(!stays.untilReached);
    const SpinReport fromA1 = readSpinReport(templatePan.run(std::string(kSpinStartVariable) + "='gState=1'"));
    REQUIRE(fromA1.complete);
    CHECK(fromA1.reached(reach(templatePromela, "A1")));
    CHECK(!fromA1.reached(reach(templatePromela, "A6")));

    // A name that is not a state variable, or a value out of range: pan stops before searching.
    for (const char* wrong : {"'gState=8 Stop=1'", "'gEntry=2'", "'gState=8,gEntry=0'"}) {
        INFO(wrong);
        const std::string output = pan.run(std::string(kSpinStartVariable) + "=" + wrong);
        CHECK(output.find("GG_START: ") != std::string::npos);
        CHECK(!readSpinReport(output).complete);
    }
}

TEST_CASE("exportPromela writes the scan loop of the generated code", "[spin]")
{
    const PromelaModel promela = buildPromela(factory::realisticModel());
    const std::string& text = promela.text;
    // Tokens read in the condition, Complete gating, token update with the new State.
    CHECK(text.find("pg[2] = (tk_Stop_F1_2_MEM && pc);") != std::string::npos);
    CHECK(text.find(":: (tk_Stop_F1_2_MEM && cp_F1) ->") != std::string::npos);
    CHECK(text.find("if :: gState == 8 && !in_Stop -> tk_Stop_F1_2_MEM = 1 :: else -> skip fi;")
          != std::string::npos);
    // FaultCount < 3 on a DINT: three regions, the test is the lowest one.
    CHECK(text.find("(in_FaultCount == 0)") != std::string::npos);
    // Every marker is alone on its line.
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    for (const PromelaMarker& marker : promela.markers) {
        REQUIRE(marker.line >= 1);
        REQUIRE(static_cast<std::size_t>(marker.line) <= lines.size());
        const std::string& line = lines[static_cast<std::size_t>(marker.line) - 1];
        INFO(line);
        CHECK(line.find("::") == std::string::npos);
        CHECK(line.find("/* ") != std::string::npos);
    }
    // A hostile model name cannot end the header comment.
    Model model;
    REQUIRE(model.setName("x */ byte evil; /*"));
    CHECK(exportPromela(model).find("x * / byte evil; / *") != std::string::npos);
}

} // namespace test_spin
