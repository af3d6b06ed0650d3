// What a unit mode makes of the PackML template (spec packml.md §3, §5.3,
// §6.2): enabled states, the editor's consistent listing, skipping, the
// mode's transitions, generated commands, S(c,r) and reserved names.

#include "core/templates/packml/packmlrules.h"

#include <catch2/catch.hpp>

#include <map>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace test_packmlrules {

using namespace core::packml;

namespace {

StateSet enabledWith(const StateSet& disabledListing)
{
    return enabledStates(disabledListing).enabled;
}

// Every state that may be disabled but those given.
StateSet allDisabledBut(const StateSet& kept)
{
    StateSet listing;
    for (const StateInfo& info : states())
        if (info.mayBeDisabled && !kept.contains(info.state))
            listing.insert(info.state);
    return listing;
}

// The transition of `source` on `command` in the mode, if it exists there.
std::optional<ModeTransition> onCommand(State source, Command command, const StateSet& disabledListing,
                                        const Options& options = defaultOptions(Edition::Y2015))
{
    for (const ModeTransition& transition : modeTransitionsFrom(source, enabledWith(disabledListing), options))
        if (transition.transition.trigger == Trigger::Command && transition.transition.command == command)
            return transition;
    return std::nullopt;
}

std::optional<ModeTransition> onStateComplete(State source, const StateSet& disabledListing, const Options& options)
{
    for (const ModeTransition& transition : modeTransitionsFrom(source, enabledWith(disabledListing), options))
        if (transition.transition.trigger == Trigger::StateComplete)
            return transition;
    return std::nullopt;
}

StateSet randomListing(std::mt19937& random)
{
    StateSet listing;
    for (const StateInfo& info : states())
        if (std::bernoulli_distribution(0.4)(random))
            listing.insert(info.state);
    return listing;
}

State randomState(std::mt19937& random)
{
    return static_cast<State>(std::uniform_int_distribution<int>(1, kStateCount)(random));
}

Options randomOptions(std::mt19937& random)
{
    Options options;
    options.edition = std::bernoulli_distribution(0.5)(random) ? Edition::Y2022 : Edition::Y2015;
    options.holdInSuspended = std::bernoulli_distribution(0.5)(random);
    options.completeInSuspendedHeld = std::bernoulli_distribution(0.5)(random);
    return options;
}

// A branch of section 3 of the generated code, reduced to what the rules
// decide: "6 Execute: Ev_Abort>9 (Aborting skipped) | Ev_Stop>2 (...)".
using Branches = std::vector<std::string>;

// The branches of each mode in the spec's ST text.
std::map<std::string, Branches> branchesOfSpecText(const std::string& text)
{
    const std::regex modeLine(R"(^(\d+): \(\* (\w+) \*\)$)");
    const std::regex stateLine(R"(^    (\d+): \(\* (\w+) \*\)$)");
    const std::regex transitionLine(R"(^\s+(?:IF|ELSIF) (\S+) THEN State := (\d+);[^(]*(?:\(\* (.*) \*\))?$)");
    std::map<std::string, Branches> result;
    std::string mode;
    std::istringstream lines(text);
    std::string line;
    std::smatch match;
    while (std::getline(lines, line)) {
        if (std::regex_match(line, match, modeLine)) {
            mode = match[2];
        } else if (std::regex_match(line, match, stateLine)) {
            result[mode].push_back(match[1].str() + " " + match[2].str() + ":");
        } else if (std::regex_match(line, match, transitionLine)) {
            std::string& branch = result[mode].back();
            branch += " " + match[1].str() + ">" + match[2].str();
            if (match[3].matched)
                branch += " (" + match[3].str() + ")";
        }
    }
    return result;
}

std::string triggerText(const ModeTransition& transition, const std::string& modeName)
{
    const TemplateTransition& template_ = transition.transition;
    if (template_.trigger == Trigger::Command)
        return "Ev_" + std::string(commandName(template_.command));
    return modeName + "_" + std::string(stateName(template_.source)) + ".Complete";
}

std::string commentText(const ModeTransition& transition)
{
    const bool stateComplete = transition.transition.trigger == Trigger::StateComplete;
    if (!transition.destination.skipped)
        return stateComplete ? " (SC)" : "";
    return std::string(stateComplete ? " (SC: " : " (") + std::string(stateName(*transition.destination.skipped))
         + " skipped)";
}

// The same branches as the rules give them.
Branches branchesOfRules(const std::string& modeName, const StateSet& disabledListing, const Options& options)
{
    const StateSet enabled = enabledWith(disabledListing);
    Branches result;
    for (const State state : enabled.list()) {
        std::string branch = std::to_string(static_cast<int>(state)) + " " + std::string(stateName(state)) + ":";
        for (const ModeTransition& transition : modeTransitionsFrom(state, enabled, options))
            branch += " " + triggerText(transition, modeName) + ">"
                    + std::to_string(static_cast<int>(transition.destination.state)) + commentText(transition);
        result.push_back(branch);
    }
    return result;
}

// Section 3 of the Capper program of spec §6.6, verbatim.
const char* const kCapperStateMachine = R"((* 3. State machine of the current unit mode *)
CASE Mode OF
1: (* Production *)
    CASE State OF
    2: (* Stopped *)
        IF Ev_Abort THEN State := 9; Entry := TRUE; (* Aborting skipped *)
        ELSIF Ev_Reset THEN State := 15; Entry := TRUE;
        END_IF;
    4: (* Idle *)
        IF Ev_Abort THEN State := 9; Entry := TRUE; (* Aborting skipped *)
        ELSIF Ev_Stop THEN State := 2; Entry := TRUE; (* Stopping skipped *)
        ELSIF Ev_Start THEN State := 6; Entry := TRUE; Resume := FALSE; (* Starting skipped *)
        END_IF;
    6: (* Execute *)
        IF Entry THEN IF NOT Resume THEN Production_Execute(Initialization := Entry); END_IF; Entry := FALSE; Resume := FALSE; END_IF;
        Production_Execute(Initialization := Entry);
        IF Ev_Abort THEN State := 9; Entry := TRUE; (* Aborting skipped *)
        ELSIF Ev_Stop THEN State := 2; Entry := TRUE; (* Stopping skipped *)
        ELSIF Ev_Hold THEN State := 11; Entry := TRUE; Resume := TRUE; (* Holding skipped *)
        END_IF;
    9: (* Aborted *)
        IF Ev_Clear THEN State := 2; Entry := TRUE; (* Clearing skipped *)
        END_IF;
    11: (* Held *)
        IF Ev_Abort THEN State := 9; Entry := TRUE; (* Aborting skipped *)
        ELSIF Ev_Stop THEN State := 2; Entry := TRUE; (* Stopping skipped *)
        ELSIF Ev_Unhold THEN State := 6; Entry := TRUE; (* Unholding skipped *)
        END_IF;
    15: (* Resetting *)
        IF Entry THEN Production_Resetting(Initialization := Entry); Entry := FALSE; END_IF;
        Production_Resetting(Initialization := Entry);
        IF Ev_Abort THEN State := 9; Entry := TRUE; (* Aborting skipped *)
        ELSIF Ev_Stop THEN State := 2; Entry := TRUE; (* Stopping skipped *)
        ELSIF Production_Resetting.Complete THEN State := 4; Entry := TRUE; (* SC *)
        END_IF;
    END_CASE;
3: (* Manual *)
    CASE State OF
    2: (* Stopped *)
        IF Ev_Abort THEN State := 9; Entry := TRUE; (* Aborting skipped *)
        ELSIF Ev_Reset THEN State := 4; Entry := TRUE; (* Resetting skipped *)
        END_IF;
    4: (* Idle *)
        IF Ev_Abort THEN State := 9; Entry := TRUE; (* Aborting skipped *)
        ELSIF Ev_Stop THEN State := 2; Entry := TRUE; (* Stopping skipped *)
        ELSIF Ev_Start THEN State := 6; Entry := TRUE; Resume := FALSE; (* Starting skipped *)
        END_IF;
    6: (* Execute *)
        IF Entry THEN IF NOT Resume THEN Manual_Execute(Initialization := Entry); END_IF; Entry := FALSE; Resume := FALSE; END_IF;
        Manual_Execute(Initialization := Entry);
        IF Ev_Abort THEN State := 9; Entry := TRUE; (* Aborting skipped *)
        ELSIF Ev_Stop THEN State := 2; Entry := TRUE; (* Stopping skipped *)
        END_IF;
    9: (* Aborted *)
        IF Ev_Clear THEN State := 2; Entry := TRUE; (* Clearing skipped *)
        END_IF;
    END_CASE;
END_CASE;
)";

// Capper's modes (spec §6.6): Production enables Stopped, Resetting, Idle,
// Execute, Held, Aborted; Manual only the four that cannot be disabled.
const StateSet kCapperProduction = allDisabledBut({State::Resetting, State::Held});
const StateSet kCapperManual = allDisabledBut({});

} // namespace

TEST_CASE("PackML rules: a mode enables every state it does not list", "[packml-rules]")
{
    const EnabledStates none = enabledStates({});
    CHECK(none.enabled.size() == kStateCount);
    CHECK(none.ignoredListings.empty());
    CHECK(none.forced.empty());

    const EnabledStates some = enabledStates({State::Starting, State::Clearing});
    CHECK(some.enabled.size() == kStateCount - 2);
    CHECK_FALSE(some.enabled.contains(State::Starting));
    CHECK_FALSE(some.enabled.contains(State::Clearing));
}

TEST_CASE("PackML rules: Stopped, Idle, Execute, Aborted listed as disabled are ignored (PM004)", "[packml-rules]")
{
    const EnabledStates result = enabledStates({State::Stopped, State::Execute, State::Aborted, State::Idle,
                                                State::Starting});
    CHECK(result.ignoredListings == StateSet{State::Stopped, State::Idle, State::Execute, State::Aborted});
    CHECK(result.enabled.contains(State::Stopped));
    CHECK(result.enabled.contains(State::Idle));
    CHECK(result.enabled.contains(State::Execute));
    CHECK(result.enabled.contains(State::Aborted));
    CHECK_FALSE(result.enabled.contains(State::Starting));
}

TEST_CASE("PackML rules: a loop's wait state stays enabled while an acting state of the loop is (PM005)",
          "[packml-rules]")
{
    const EnabledStates result = enabledStates({State::Held, State::Holding, State::Suspended, State::Complete});
    REQUIRE(result.forced.size() == 3);
    CHECK(result.forced[0].state == State::Suspended);
    CHECK(result.forced[0].enabledActing == std::vector<State>{State::Suspending, State::Unsuspending});
    CHECK(result.forced[1].state == State::Held);
    CHECK(result.forced[1].enabledActing == std::vector<State>{State::Unholding});
    CHECK(result.forced[2].state == State::Complete);
    CHECK(result.forced[2].enabledActing == std::vector<State>{State::Completing});
    CHECK(result.enabled.contains(State::Held));
    CHECK(result.enabled.contains(State::Suspended));
    CHECK(result.enabled.contains(State::Complete));
    CHECK_FALSE(result.enabled.contains(State::Holding));
    CHECK(result.ignoredListings.empty());

    const EnabledStates wholeLoop = enabledStates({State::Held, State::Holding, State::Unholding});
    CHECK(wholeLoop.forced.empty());
    CHECK_FALSE(wholeLoop.enabled.contains(State::Held));
}

TEST_CASE("PackML rules: the acting states of each loop", "[packml-rules]")
{
    CHECK(loopActingStates(State::Held) == std::vector<State>{State::Holding, State::Unholding});
    CHECK(loopActingStates(State::Suspended) == std::vector<State>{State::Suspending, State::Unsuspending});
    CHECK(loopActingStates(State::Complete) == std::vector<State>{State::Completing});
    CHECK(loopActingStates(State::Idle).empty());
}

TEST_CASE("PackML rules: the editor's listing, one state toggled (spec 3.2)", "[packml-rules]")
{
    // Disabling Held disables Holding and Unholding; Complete, Completing.
    CHECK(consistentListing({}, State::Held) == StateSet{State::Held, State::Holding, State::Unholding});
    CHECK(consistentListing({}, State::Suspended)
          == StateSet{State::Suspended, State::Suspending, State::Unsuspending});
    CHECK(consistentListing({}, State::Complete) == StateSet{State::Complete, State::Completing});
    // Enabling Holding re-enables Held; Unholding stays disabled.
    CHECK(consistentListing({State::Held, State::Holding, State::Unholding}, State::Holding)
          == StateSet{State::Unholding});
    CHECK(consistentListing({State::Complete, State::Completing}, State::Completing) == StateSet{});
    // Enabling Held alone keeps its acting states disabled: Hold then skips Holding.
    CHECK(consistentListing({State::Held, State::Holding, State::Unholding}, State::Held)
          == StateSet{State::Holding, State::Unholding});
    // Disabling an acting state touches nothing else.
    CHECK(consistentListing({}, State::Holding) == StateSet{State::Holding});
    // A listed Held kept enabled by Holding counts as enabled: toggling disables the loop.
    CHECK(consistentListing({State::Held}, State::Held) == StateSet{State::Held, State::Holding, State::Unholding});
    // The never-disabled states do not toggle; their listings are dropped.
    CHECK(consistentListing({State::Starting}, State::Idle) == StateSet{State::Starting});
    CHECK(consistentListing({State::Idle, State::Starting}, State::Execute) == StateSet{State::Starting});
    CHECK(consistentListing({State::Idle, State::Held}) == StateSet{});
}

TEST_CASE("PackML rules: the one-step skips of spec 3.3", "[packml-rules]")
{
    const auto leadsTo = [](const std::optional<ModeTransition>& transition, State target, State skipped) {
        REQUIRE(transition);
        CHECK(transition->destination.state == target);
        CHECK(transition->destination.skipped == skipped);
    };
    leadsTo(onCommand(State::Stopped, Command::Reset, {State::Resetting}), State::Idle, State::Resetting);
    leadsTo(onCommand(State::Idle, Command::Start, {State::Starting}), State::Execute, State::Starting);
    leadsTo(onCommand(State::Execute, Command::Stop, {State::Stopping}), State::Stopped, State::Stopping);
    leadsTo(onCommand(State::Execute, Command::Abort, {State::Aborting}), State::Aborted, State::Aborting);
    leadsTo(onCommand(State::Aborted, Command::Clear, {State::Clearing}), State::Stopped, State::Clearing);
    leadsTo(onCommand(State::Execute, Command::Hold, {State::Holding}), State::Held, State::Holding);
    leadsTo(onCommand(State::Held, Command::Unhold, {State::Unholding}), State::Execute, State::Unholding);
    leadsTo(onCommand(State::Execute, Command::Complete, {State::Completing}, defaultOptions(Edition::Y2022)),
            State::Complete, State::Completing);
    leadsTo(onStateComplete(State::Execute, {State::Completing}, defaultOptions(Edition::Y2015)), State::Complete,
            State::Completing);
}

TEST_CASE("PackML rules: a transition to an enabled state is not skipped", "[packml-rules]")
{
    const std::optional<ModeTransition> reset = onCommand(State::Stopped, Command::Reset, {});
    REQUIRE(reset);
    CHECK(reset->destination.state == State::Resetting);
    CHECK_FALSE(reset->destination.skipped);
    CHECK(reset->transition.target == State::Resetting);
}

TEST_CASE("PackML rules: Hold is not accepted when Holding and Held are disabled", "[packml-rules]")
{
    const StateSet listing{State::Holding, State::Held, State::Unholding};
    CHECK_FALSE(onCommand(State::Execute, Command::Hold, listing));
    CHECK_FALSE(onCommand(State::Suspended, Command::Hold, listing, defaultOptions(Edition::Y2022)));
    CHECK(onCommand(State::Execute, Command::Suspend, listing));
}

TEST_CASE("PackML rules: Execute's SC (2015) does not exist when Completing and Complete are disabled",
          "[packml-rules]")
{
    const Options options = defaultOptions(Edition::Y2015);
    CHECK_FALSE(onStateComplete(State::Execute, {State::Completing, State::Complete}, options));
    CHECK(onStateComplete(State::Execute, {}, options));
}

TEST_CASE("PackML rules: where a transition to a state leads", "[packml-rules]")
{
    const StateSet enabled = enabledWith({State::Holding, State::Held, State::Unholding, State::Resetting});
    CHECK_FALSE(destination(State::Held, enabled));    // a disabled wait state: no transition
    CHECK_FALSE(destination(State::Holding, enabled)); // its SC successor is disabled too
    const std::optional<Destination> unholding = destination(State::Unholding, enabled);
    REQUIRE(unholding);
    CHECK(unholding->state == State::Execute);
    CHECK(unholding->skipped == State::Unholding);
}

TEST_CASE("PackML rules: a disabled state has no transitions in its mode", "[packml-rules]")
{
    const StateSet enabled = enabledWith({State::Starting});
    CHECK(modeTransitionsFrom(State::Starting, enabled, defaultOptions(Edition::Y2015)).empty());
    CHECK(modeTransitionsFrom(State::Resetting, enabled, defaultOptions(Edition::Y2015)).size() == 3);
}

TEST_CASE("PackML rules: the Capper example's state machines are the spec's (6.6)", "[packml-rules]")
{
    const std::map<std::string, Branches> spec = branchesOfSpecText(kCapperStateMachine);
    REQUIRE(spec.size() == 2);
    REQUIRE(spec.at("Production").size() == 6);
    REQUIRE(spec.at("Manual").size() == 4);
    CHECK(spec.at("Manual")[0] == "2 Stopped: Ev_Abort>9 (Aborting skipped) Ev_Reset>4 (Resetting skipped)");
    const Options options = defaultOptions(Edition::Y2015);
    CHECK(branchesOfRules("Production", kCapperProduction, options) == spec.at("Production"));
    CHECK(branchesOfRules("Manual", kCapperManual, options) == spec.at("Manual"));
}

TEST_CASE("PackML rules: Capper generates every command but Suspend and Unsuspend (PM013)", "[packml-rules]")
{
    const std::vector<StateSet> enabledPerMode{enabledWith(kCapperProduction), enabledWith(kCapperManual)};
    const Options options = defaultOptions(Edition::Y2015);
    CHECK(generatedCommands(enabledPerMode, options)
          == std::vector<Command>{Command::Reset, Command::Start, Command::Stop, Command::Hold, Command::Unhold,
                                  Command::Abort, Command::Clear});
    CHECK(unacceptedCommands(enabledPerMode, options) == std::vector<Command>{Command::Suspend, Command::Unsuspend});
}

TEST_CASE("PackML rules: the Complete command is generated in 2022 only", "[packml-rules]")
{
    const std::vector<StateSet> enabledPerMode{enabledWith({})};
    CHECK(generatedCommands(enabledPerMode, defaultOptions(Edition::Y2022)).size() == 10);
    CHECK(generatedCommands(enabledPerMode, defaultOptions(Edition::Y2015)).size() == 9);
    CHECK(unacceptedCommands(enabledPerMode, defaultOptions(Edition::Y2015)).empty());
    // A command another mode accepts is generated.
    const std::vector<StateSet> twoModes{enabledWith(allDisabledBut({})), enabledWith({})};
    CHECK(unacceptedCommands(twoModes, defaultOptions(Edition::Y2015)).empty());
}

TEST_CASE("PackML rules: S(c,r) of spec 3.4", "[packml-rules]")
{
    const StateSet defaults{State::Stopped, State::Idle, State::Aborted};
    CHECK(modeChangeStates(defaults, defaults, enabledWith({})) == defaults);
    CHECK(modeChangeStates(defaults, {State::Stopped, State::Execute}, enabledWith({})) == StateSet{State::Stopped});
    // A state the requested mode disables is no place to change into it.
    CHECK(modeChangeStates({State::Held, State::Idle}, {State::Held, State::Idle},
                           enabledWith({State::Held, State::Holding, State::Unholding}))
          == StateSet{State::Idle});
    // Acting states never allow a change, whatever the lists say.
    CHECK(modeChangeStates({State::Starting, State::Idle}, {State::Starting, State::Idle}, enabledWith({}))
          == StateSet{State::Idle});
}

TEST_CASE("PackML rules: the names spec 5.3 reserves, ignoring case", "[packml-rules]")
{
    const std::vector<std::string> modes{"Production", "Manual", "Cleaning"};
    for (const char* name : {"State", "mode", "ENTRY", "Resume", "Initialization", "Complete", "r_trig", "CntrlCmd",
                             "CmdChangeRequest", "UnitMode", "UnitModeChangeRequest", "StateCurrent",
                             "UnitModeCurrent", "PackMLConfiguration", "PackMLResource", "MainTask",
                             "PackMLInstance", "Capper", "CAPPER", "Trig_Anything", "trig_x", "Ev_Start", "EV_",
                             "Production_Execute", "manual_resetting", "Cleaning_Execute_FB", "Execute_FB",
                             "complete_fb", "Cleaning_Aborted", "GVL", "gvl"}) {
        INFO(name);
        CHECK(isReservedName(name, "Capper", modes));
    }
    for (const char* name : {"Cmd_Start", "Trigger", "Event", "Production", "Manual", "PackML", "Maintenance_Execute",
                             "Production_Foo", "Execute_FBX", "Cap", "Capper_"}) {
        INFO(name);
        CHECK_FALSE(isReservedName(name, "Capper", modes));
    }
    CHECK(isReservedName("PackML", "PackML", modes));
}

TEST_CASE("PackML rules: on random listings, every target exists and is enabled", "[packml-rules]")
{
    std::mt19937 random(3401);
    for (int trial = 0; trial < 500; ++trial) {
        const StateSet listing = randomListing(random);
        const Options options = randomOptions(random);
        const EnabledStates result = enabledStates(listing);
        for (const StateInfo& info : states()) {
            INFO("trial " << trial << " state " << info.name);
            if (!info.mayBeDisabled || !listing.contains(info.state))
                CHECK(result.enabled.contains(info.state));
            for (const ModeTransition& transition : modeTransitionsFrom(info.state, result.enabled, options)) {
                CHECK(result.enabled.contains(transition.destination.state));
                if (transition.destination.skipped) {
                    const State skipped = *transition.destination.skipped;
                    CHECK_FALSE(result.enabled.contains(skipped));
                    CHECK(isActing(skipped));
                    CHECK(skipped == transition.transition.target);
                    CHECK(stateInfo(skipped).completeLeadsTo == transition.destination.state);
                } else {
                    CHECK(transition.destination.state == transition.transition.target);
                }
            }
        }
        // Aborted and Stopped are never disabled: every state of a frame keeps its Abort, resp. Stop.
        for (const State source : result.enabled.list()) {
            bool abort = false;
            bool stop = false;
            for (const ModeTransition& transition : modeTransitionsFrom(source, result.enabled, options)) {
                abort = abort || (transition.transition.trigger == Trigger::Command
                                  && transition.transition.command == Command::Abort);
                stop = stop || (transition.transition.trigger == Trigger::Command
                                && transition.transition.command == Command::Stop);
            }
            CHECK(abort == acceptsAbort(source));
            CHECK(stop == acceptsStop(source));
        }
    }
}

TEST_CASE("PackML rules: on random listings, the consistent listing is a fixed point", "[packml-rules]")
{
    std::mt19937 random(3402);
    for (int trial = 0; trial < 500; ++trial) {
        const StateSet listing = randomListing(random);
        const State toggled = randomState(random);
        INFO("trial " << trial << " toggled " << stateName(toggled));
        const StateSet consistent = consistentListing(listing, toggled);
        const EnabledStates result = enabledStates(consistent);
        CHECK(result.ignoredListings.empty());
        CHECK(result.forced.empty());
        CHECK(consistentListing(consistent) == consistent);
        for (const StateInfo& info : states())
            CHECK(result.enabled.contains(info.state) != consistent.contains(info.state));
        // The toggled state changed, unless it can never be disabled.
        const bool wasEnabled = enabledWith(listing).contains(toggled);
        if (stateInfo(toggled).mayBeDisabled)
            CHECK(result.enabled.contains(toggled) != wasEnabled);
        else
            CHECK(enabledWith(consistent) == enabledWith(listing));
    }
}

TEST_CASE("PackML rules: on random listings, S(c,r) holds no acting or disabled state", "[packml-rules]")
{
    std::mt19937 random(3403);
    for (int trial = 0; trial < 500; ++trial) {
        const StateSet current = randomListing(random);
        const StateSet requested = randomListing(random);
        const StateSet enabled = enabledWith(randomListing(random));
        const StateSet granted = modeChangeStates(current, requested, enabled);
        INFO("trial " << trial);
        for (const State state : granted.list()) {
            CHECK_FALSE(isActing(state));
            CHECK(enabled.contains(state));
            CHECK(current.contains(state));
            CHECK(requested.contains(state));
            CHECK(mayAllowModeChange(state));
        }
        for (const State state : current.list())
            if (requested.contains(state) && enabled.contains(state) && mayAllowModeChange(state))
                CHECK(granted.contains(state));
    }
}

TEST_CASE("Execute's Resume flag: set by Hold and Suspend out of Execute, cleared by a start", "[packml-rules]")
{
    const Options options = defaultOptions(Edition::Y2015);
    StateSet all;
    for (const StateInfo& info : states())
        all.insert(info.state);
    const auto effectOf = [&](State source, Command command, const StateSet& enabled) {
        for (const ModeTransition& t : modeTransitionsFrom(source, enabled, options))
            if (t.transition.trigger == Trigger::Command && t.transition.command == command)
                return resumeEffect(t);
        FAIL("no such transition");
        return ResumeEffect::None;
    };
    CHECK(effectOf(State::Execute, Command::Hold, all) == ResumeEffect::Set);
    CHECK(effectOf(State::Execute, Command::Suspend, all) == ResumeEffect::Set);
    CHECK(effectOf(State::Execute, Command::Stop, all) == ResumeEffect::None);
    CHECK(effectOf(State::Held, Command::Unhold, all) == ResumeEffect::None);
    CHECK(effectOf(State::Idle, Command::Start, all) == ResumeEffect::None); // into Starting
    StateSet noStarting = all;
    noStarting.erase(State::Starting);
    CHECK(effectOf(State::Idle, Command::Start, noStarting) == ResumeEffect::Clear); // Starting skipped
    for (const ModeTransition& t : modeTransitionsFrom(State::Starting, all, options))
        if (t.transition.trigger == Trigger::StateComplete)
            CHECK(resumeEffect(t) == ResumeEffect::Clear);
}

} // namespace test_packmlrules
