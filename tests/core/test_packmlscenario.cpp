#include "packmlcapper.h"

#include "core/simulation/simulator.h"
#include "core/templates/packml/packmlmodel.h"
#include "core/templates/packml/packmlscenario.h"
#include "modelfactory.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace test_packmlscenario {

using namespace core;
using namespace core::packml;

namespace {

std::vector<std::string> errorTexts(const std::vector<ScenarioError>& errors)
{
    std::vector<std::string> texts;
    for (const ScenarioError& error : errors)
        texts.push_back(error.toString());
    return texts;
}

std::vector<std::string> failureTexts(const std::vector<PackmlScenarioFailure>& failures)
{
    std::vector<std::string> texts;
    for (const PackmlScenarioFailure& failure : failures)
        texts.push_back(toText(failure));
    return texts;
}

Scenario parsed(const char* text)
{
    ScenarioParseResult result = parseScenario(text, "s.txt");
    REQUIRE(result.ok());
    return result.scenario;
}

// The Capper of spec §6.6 driven by commands and modes instead of its inputs.
constexpr const char* kCapperScenario = "# the Capper, through the PackTags requests\n"
                                        "at 1: command Reset\n"
                                        "at 1: expect fired Stopped-Reset->Resetting\n"
                                        "at 2: expect variable HomeAxis = TRUE\n"
                                        "at 4: set Homed = TRUE\n"
                                        "at 4: expect state Idle\n"
                                        "at 6: command start\n"
                                        "at 6: expect state Execute\n"
                                        "at 7: expect variable Cap = TRUE\n"
                                        "at 8: mode Manual           # not in Execute: dropped\n"
                                        "at 8: expect mode Production\n"
                                        "at 10: command Stop\n"
                                        "at 10: expect state Stopped\n"
                                        "at 12: mode 3\n"
                                        "at 12: expect mode manual\n"
                                        "at 12: expect fired none\n"
                                        "at 14: command Reset\n"
                                        "at 14: expect fired Stopped-Reset->Idle\n"
                                        "at 14: expect state 4\n";

} // namespace

TEST_CASE("PackML scenarios: command and mode through the PackTags requests, expect state and mode", "[packml-sim]")
{
    const auto capper = packmltests::loadCapper();
    PackmlSimulator simulator(*capper);
    const Scenario scenario = parsed(kCapperScenario);
    CHECK(validatePackmlScenario(scenario, simulator).empty());
    const PackmlScenarioRunResult result = runPackmlScenario(scenario, simulator);
    CHECK(failureTexts(result.failures).empty());
    REQUIRE(result.records.size() == 14);
    // The mode request of scan 8 met Execute: dropped, with its reason.
    REQUIRE(result.records[7].dropped.size() == 1);
    CHECK(toText(result.records[7].dropped[0]) == "Manual is not granted in Execute: Production allows no mode change there");
    // Each request rose for one scan only.
    CHECK(simulator.value("CmdChangeRequest") == std::optional<cond::Value>(false));
    CHECK(simulator.value("UnitModeChangeRequest") == std::optional<cond::Value>(false));
}

TEST_CASE("PackML scenarios: expectations that do not hold are failures naming the scan", "[packml-sim]")
{
    const auto capper = packmltests::loadCapper();
    PackmlSimulator simulator(*capper);
    const Scenario scenario = parsed("at 1: command Reset\n"
                                     "at 1: expect fired none\n"
                                     "at 2: expect state Idle\n"
                                     "at 2: expect mode Manual\n"
                                     "at 2: expect variable HomeAxis = FALSE\n"
                                     "at 2: expect fired Resetting-SC->Idle\n"
                                     "at 3: command Start\n"
                                     "at 3: expect fired none\n"
                                     "at 3: expect fired Idle-Start->Execute\n");
    REQUIRE(validatePackmlScenario(scenario, simulator).empty());
    const PackmlScenarioRunResult result = runPackmlScenario(scenario, simulator);
    CHECK(failureTexts(result.failures)
          == std::vector<std::string>{
              "scan 1: expected no transition to fire, Stopped-Reset->Resetting fired",
              "scan 2: expected state Idle, the state is Resetting",
              "scan 2: expected mode Manual, the mode is Production",
              "scan 2: expected HomeAxis = FALSE, it is TRUE",
              "scan 2: expected Resetting-SC->Idle to fire, no transition fired",
              "scan 3: expected Idle-Start->Execute to fire, no transition fired",
          });
}

TEST_CASE("PackML scenarios: unknown names and impossible requests are errors with their line", "[packml-sim]")
{
    const auto capper = packmltests::loadCapper();
    PackmlSimulator simulator(*capper);
    const Scenario scenario = parsed("at 1: command Strat\n"
                                     "at 1: mode Cleaning\n"
                                     "at 2: expect state Running\n"
                                     "at 2: expect mode 9\n"
                                     "at 3: command Complete\n"
                                     "at 4: set Cap = TRUE\n"
                                     "at 4: expect step A1\n"
                                     "at 5: command Start\n"
                                     "at 5: command Stop\n"
                                     "at 6: command Stop\n"
                                     "at 8: mode Manual\n"
                                     "at 9: mode Production\n"
                                     "at 9: set Homed = 3\n");
    CHECK(errorTexts(validatePackmlScenario(scenario, simulator))
          == std::vector<std::string>{
              "s.txt:1:15: unknown command 'Strat'",
              "s.txt:2:12: unknown unit mode 'Cleaning'",
              "s.txt:3:20: unknown state 'Running'",
              "s.txt:4:19: unknown unit mode '9'",
              "s.txt:5:15: unknown command 'Complete'",
              "s.txt:6:11: Cap is an output variable: the program writes it, a scenario sets only inputs",
              "s.txt:7:19: 'expect step' is for GEMMA models only",
              "s.txt:9:15: CntrlCmd is set to two values in scan 5: Start on line 8, Stop on line 9",
              "s.txt:10:15: a command in scan 6 right after the one of line 8 is not seen: the request must be FALSE for one scan in between",
              "s.txt:12:12: a mode in scan 9 right after the one of line 11 is not seen: the request must be FALSE for one scan in between",
              "s.txt:13:19: Homed is BOOL: '3' is not a BOOL literal (TRUE or FALSE)",
          });
}

TEST_CASE("PackML scenario lines: syntax, and refused on a GEMMA model", "[packml-sim]")
{
    const ScenarioParseResult bad = parseScenario("at 1: command\nat 2: expect state\nat 3: mode Manual extra\n", "s.txt");
    CHECK(errorTexts(bad.errors)
          == std::vector<std::string>{
              "s.txt:1:14: expected a command name after 'command', found the end of the line",
              "s.txt:2:19: expected a state name after 'state', found the end of the line",
              "s.txt:3:19: expected the end of the line, found 'extra'",
          });
    const Scenario scenario = parsed("at 1: command Start\nat 2: expect mode Manual\n");
    Simulator gemma(factory::realisticModel());
    CHECK(errorTexts(validateScenario(scenario, gemma))
          == std::vector<std::string>{"s.txt:1:15: 'command' is for PackML models only",
                                      "s.txt:2:19: 'expect mode' is for PackML models only"});
}

TEST_CASE("PackML scenarios: set complete gives an instance without GRAFCET a manual SC", "[packml-sim]")
{
    const auto capper = packmltests::loadCapper();
    PackmlSimulator simulator(*capper);
    // Production's Resetting runs a GRAFCET; Manual disables Starting (no instance).
    const Scenario bad = parsed("at 1: set complete Production_Resetting = TRUE\n"
                                "at 1: set complete Manual_Starting = auto\n"
                                "at 2: expect complete Manual_Execute = TRUE\n");
    CHECK(errorTexts(validatePackmlScenario(bad, simulator))
          == std::vector<std::string>{
              "s.txt:1:20: the Complete of Production_Resetting comes from its nested GRAFCET: it cannot be set",
              "s.txt:2:20: unknown instance 'Manual_Starting'",
              "s.txt:3:23: 'expect complete' is for GEMMA models only",
          });

    Model model = newModel(Edition::Y2015);
    PackmlSimulator held(model);
    const Scenario scenario = parsed("at 1: set complete production_resetting = FALSE\n"
                                     "at 1: command Reset\n"
                                     "at 3: expect state Resetting\n"
                                     "at 4: set complete Production_Resetting = auto\n"
                                     "at 4: expect state Idle\n");
    REQUIRE(validatePackmlScenario(scenario, held).empty());
    const PackmlScenarioRunResult result = runPackmlScenario(scenario, held);
    CHECK(failureTexts(result.failures).empty());
    // A new run starts from the skeletons again.
    const PackmlScenarioRunResult again = runPackmlScenario(parsed("at 1: command Reset\nat 2: expect state Idle\n"), held);
    CHECK(failureTexts(again.failures).empty());
}

} // namespace test_packmlscenario
