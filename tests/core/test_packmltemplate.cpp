// The PackML template's data against the tables of spec packml.md §2.1-§2.3,
// transcribed here row by row.

#include "core/templates/packml/packmltemplate.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace test_packmltemplate {

using namespace core::packml;

namespace {

struct StateRow {
    int number;
    const char* name;
    StateKind kind;
    bool mayBeDisabled;
    const char* completeLeadsTo; // "" when none
    int column;
    int row;
};

// Spec §2.1, in table order.
const StateRow kSpecStates[] = {
    {1, "Clearing", StateKind::Acting, true, "Stopped", 0, 4},
    {2, "Stopped", StateKind::Wait, false, "", 0, 3},
    {3, "Starting", StateKind::Acting, true, "Execute", 1, 1},
    {4, "Idle", StateKind::Wait, false, "", 0, 1},
    {5, "Suspended", StateKind::Wait, true, "", 2, 2},
    {6, "Execute", StateKind::Dual, false, "Completing", 2, 1},
    {7, "Stopping", StateKind::Acting, true, "Stopped", 4, 3},
    {8, "Aborting", StateKind::Acting, true, "Aborted", 4, 5},
    {9, "Aborted", StateKind::Wait, false, "", 0, 5},
    {10, "Holding", StateKind::Acting, true, "Held", 3, 0},
    {11, "Held", StateKind::Wait, true, "", 2, 0},
    {12, "Unholding", StateKind::Acting, true, "Execute", 1, 0},
    {13, "Suspending", StateKind::Acting, true, "Suspended", 3, 2},
    {14, "Unsuspending", StateKind::Acting, true, "Execute", 1, 2},
    {15, "Resetting", StateKind::Acting, true, "Idle", 0, 2},
    {16, "Completing", StateKind::Acting, true, "Complete", 3, 1},
    {17, "Complete", StateKind::Wait, true, "", 4, 1},
};

// "Abort>Aborting Stop>Stopping SC>Idle", with "?" after an optional one.
std::string describe(const std::vector<TemplateTransition>& transitions)
{
    std::string text;
    for (const TemplateTransition& transition : transitions) {
        if (!text.empty())
            text += ' ';
        text += transition.trigger == Trigger::StateComplete ? std::string("SC")
                                                             : std::string(commandName(transition.command));
        text += '>';
        text += stateName(transition.target);
        if (transition.optional)
            text += '?';
    }
    return text;
}

std::string transitionsOf(const char* state, Edition edition, bool holdInSuspended, bool completeInSuspendedHeld)
{
    const Options options{edition, holdInSuspended, completeInSuspendedHeld};
    return describe(transitionsFrom(*findState(state), options));
}

} // namespace

TEST_CASE("PackML template: every state of spec 2.1 with its number, kind, SC successor and cell",
          "[packml-template]")
{
    REQUIRE(states().size() == std::size(kSpecStates));
    for (const StateRow& row : kSpecStates) {
        INFO(row.name);
        const std::optional<State> state = findState(row.name);
        REQUIRE(state);
        CHECK(static_cast<int>(*state) == row.number);
        CHECK(stateFromNumber(row.number) == state);
        const StateInfo& info = stateInfo(*state);
        CHECK(info.name == row.name);
        CHECK(info.kind == row.kind);
        CHECK(info.mayBeDisabled == row.mayBeDisabled);
        const std::string successor = info.completeLeadsTo ? std::string(stateName(*info.completeLeadsTo)) : "";
        CHECK(successor == row.completeLeadsTo);
        CHECK(info.cell.column == row.column);
        CHECK(info.cell.row == row.row);
        CHECK(isActing(*state) == (row.kind == StateKind::Acting));
        CHECK(holdsGrafcet(*state) == (row.kind != StateKind::Wait));
    }
    CHECK_FALSE(findState("Completed")); // the 2022 display name is not the key
    CHECK_FALSE(stateFromNumber(0));
    CHECK_FALSE(stateFromNumber(18));
}

TEST_CASE("PackML template: Execute's SC leads to Completing in 2015 only", "[packml-template]")
{
    CHECK(completeTarget(State::Execute, Edition::Y2015) == State::Completing);
    CHECK_FALSE(completeTarget(State::Execute, Edition::Y2022));
    CHECK(completeTarget(State::Resetting, Edition::Y2022) == State::Idle);
    CHECK_FALSE(completeTarget(State::Idle, Edition::Y2015));
}

TEST_CASE("PackML template: the chart cells are distinct and inside the 5 x 6 grid", "[packml-template]")
{
    for (const StateInfo& a : states()) {
        CHECK(a.cell.column >= 0);
        CHECK(a.cell.column < kChartColumns);
        CHECK(a.cell.row >= 0);
        CHECK(a.cell.row < kChartRows);
        for (const StateInfo& b : states())
            if (a.state != b.state)
                CHECK_FALSE((a.cell.column == b.cell.column && a.cell.row == b.cell.row));
    }
}

TEST_CASE("PackML template: the commands of spec 2.2, Complete in 2022 only", "[packml-template]")
{
    const char* const names[] = {"Reset", "Start", "Stop", "Hold", "Unhold",
                                 "Suspend", "Unsuspend", "Abort", "Clear", "Complete"};
    REQUIRE(allCommands().size() == std::size(names));
    for (int number = 1; number <= kCommandCount; ++number) {
        const char* name = names[number - 1];
        INFO(name);
        const std::optional<Command> command = findCommand(name);
        REQUIRE(command);
        CHECK(static_cast<int>(*command) == number);
        CHECK(commandName(*command) == name);
        CHECK(commandInfo(*command).defaultInput == "Cmd_" + std::string(name));
        CHECK(commandInEdition(*command, Edition::Y2022));
        CHECK(commandInEdition(*command, Edition::Y2015) == (number != 10));
    }
    CHECK_FALSE(findCommand("reset")); // PackTags names, exactly
}

TEST_CASE("PackML template: the Abort frame holds 15 states (rows 0-4), the Stop frame 12 (rows 0-2)",
          "[packml-template]")
{
    int abortCount = 0;
    int stopCount = 0;
    for (const StateInfo& info : states()) {
        INFO(info.name);
        CHECK(acceptsAbort(info.state) == (info.cell.row <= 4));
        CHECK(acceptsStop(info.state) == (info.cell.row <= 2));
        abortCount += acceptsAbort(info.state) ? 1 : 0;
        stopCount += acceptsStop(info.state) ? 1 : 0;
    }
    CHECK(abortCount == 15);
    CHECK(stopCount == 12);
    CHECK_FALSE(acceptsStop(State::Clearing));
    CHECK(acceptsAbort(State::Clearing));
    CHECK_FALSE(acceptsAbort(State::Aborting));
}

TEST_CASE("PackML template: each state's transitions in the priority order of spec 2.3", "[packml-template]")
{
    for (const Edition edition : {Edition::Y2015, Edition::Y2022}) {
        for (const bool holdInSuspended : {false, true}) {
            for (const bool completeInSuspendedHeld : {false, true}) {
                const bool y2022 = edition == Edition::Y2022;
                const bool completeInWait = y2022 && completeInSuspendedHeld;
                INFO("edition " << editionName(edition) << " holdInSuspended " << holdInSuspended
                                << " completeInSuspendedHeld " << completeInSuspendedHeld);
                auto of = [&](const char* state) {
                    return transitionsOf(state, edition, holdInSuspended, completeInSuspendedHeld);
                };
                const std::string frames = "Abort>Aborting Stop>Stopping";
                CHECK(of("Stopped") == "Abort>Aborting Reset>Resetting");
                CHECK(of("Idle") == frames + " Start>Starting");
                CHECK(of("Execute")
                      == frames + " Hold>Holding Suspend>Suspending"
                             + (y2022 ? " Complete>Completing" : " SC>Completing"));
                CHECK(of("Suspended")
                      == frames + (holdInSuspended ? " Hold>Holding?" : "") + " Unsuspend>Unsuspending"
                             + (completeInWait ? " Complete>Completing?" : ""));
                CHECK(of("Held") == frames + " Unhold>Unholding" + (completeInWait ? " Complete>Completing?" : ""));
                CHECK(of("Complete") == frames + " Reset>Resetting");
                CHECK(of("Aborted") == "Clear>Clearing");
                // Acting states: only the frames they lie in compete with their SC.
                CHECK(of("Clearing") == "Abort>Aborting SC>Stopped");
                CHECK(of("Starting") == frames + " SC>Execute");
                CHECK(of("Stopping") == "Abort>Aborting SC>Stopped");
                CHECK(of("Aborting") == "SC>Aborted");
                CHECK(of("Holding") == frames + " SC>Held");
                CHECK(of("Unholding") == frames + " SC>Execute");
                CHECK(of("Suspending") == frames + " SC>Suspended");
                CHECK(of("Unsuspending") == frames + " SC>Execute");
                CHECK(of("Resetting") == frames + " SC>Idle");
                CHECK(of("Completing") == frames + " SC>Complete");
            }
        }
    }
}

TEST_CASE("PackML template: every transition starts at its source", "[packml-template]")
{
    for (const StateInfo& info : states())
        for (const TemplateTransition& transition : transitionsFrom(info.state, defaultOptions(Edition::Y2022)))
            CHECK(transition.source == info.state);
}

TEST_CASE("PackML template: holdInSuspended defaults to TRUE in 2022, FALSE in 2015", "[packml-template]")
{
    CHECK_FALSE(defaultOptions(Edition::Y2015).holdInSuspended);
    CHECK(defaultOptions(Edition::Y2022).holdInSuspended);
    CHECK_FALSE(defaultOptions(Edition::Y2015).completeInSuspendedHeld);
    CHECK_FALSE(defaultOptions(Edition::Y2022).completeInSuspendedHeld);
    CHECK(defaultOptions(Edition::Y2022).edition == Edition::Y2022);
    CHECK(parseEdition("2022") == Edition::Y2022);
    CHECK(parseEdition(editionName(Edition::Y2015)) == Edition::Y2015);
    CHECK_FALSE(parseEdition("2019"));
}

TEST_CASE("PackML template: a mode change may be allowed in the seven states of spec 3.4", "[packml-template]")
{
    const StateSet allowed{State::Stopped, State::Idle,    State::Suspended, State::Execute,
                           State::Aborted, State::Held,    State::Complete};
    for (const StateInfo& info : states()) {
        INFO(info.name);
        CHECK(mayAllowModeChange(info.state) == allowed.contains(info.state));
    }
}

} // namespace test_packmltemplate
