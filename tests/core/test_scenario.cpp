#include <catch2/catch.hpp>

#include "core/model/model.h"
#include "core/simulation/scenario.h"
#include "core/simulation/simulator.h"
#include "modelfactory.h"

#include <string>
#include <vector>

namespace test_scenario {

using namespace core;

namespace {

std::vector<std::string> errorTexts(const std::vector<ScenarioError>& errors)
{
    std::vector<std::string> texts;
    for (const ScenarioError& error : errors)
        texts.push_back(error.toString());
    return texts;
}

std::vector<std::string> failureTexts(const std::vector<ScenarioFailure>& failures)
{
    std::vector<std::string> texts;
    for (const ScenarioFailure& failure : failures)
        texts.push_back(toText(failure));
    return texts;
}

// The realistic bottling model: A6 -> A1 on HomePosition AND AirPressureOk,
// A1 -> F1 on Start AND AutoMode AND PreparationDone AND DoorClosed, F1 a
// macro-step, F1 -> A2 on NOT Stop with a token (Stop_F1_2_MEM).
const char* const kBottling = R"(# Bottling line: home, start, stop
at 1: set HomePosition = TRUE, AirPressureOk = TRUE   # both needed
at 1: expect fired A6->A1
at 1: expect step A1
AT 2: SET Start = TRUE, PreparationDone = TRUE, DoorClosed = TRUE
at 2: expect step F1
at 2: expect entry = TRUE
at 3: set Start = FALSE, complete F1 = FALSE
at 3: expect fired none
at 3: expect entry = FALSE
at 4: set Stop = TRUE
at 4: expect token Stop_F1_2_MEM = TRUE
at 5: set Stop = FALSE
at 5: expect step F1
at 5: expect complete F1 = FALSE
at 6: set complete F1 = auto
at 6: expect fired F1->A2
at 6: expect variable BatchSize = 500
at 6: expect variable temperature = 20.0
)";

} // namespace

TEST_CASE("Scenario: parse the documented syntax", "[simulation]")
{
    const ScenarioParseResult parsed = parseScenario(kBottling, "bottling.txt");
    INFO(errorTexts(parsed.errors).size());
    REQUIRE(parsed.ok());
    const Scenario& scenario = parsed.scenario;
    CHECK(scenario.lastScan() == 6);
    REQUIRE(scenario.actions.size() == 22);
    const ScenarioAction& first = scenario.actions[0];
    CHECK(first.kind == ScenarioAction::Kind::SetVariable);
    CHECK(first.scan == 1);
    CHECK(first.name == "HomePosition");
    CHECK(first.value == "TRUE");
    CHECK(first.line == 2);
    CHECK(first.column == 11);
    CHECK(scenario.actions[2].kind == ScenarioAction::Kind::ExpectFired);
    CHECK(scenario.actions[2].name == "A6->A1");
    CHECK(scenario.actions[10].kind == ScenarioAction::Kind::SetComplete);
    CHECK(scenario.actions[10].name == "F1");
    CHECK(scenario.actions[10].value == "FALSE");
    CHECK(scenario.actions[11].kind == ScenarioAction::Kind::ExpectNoFiring);
    CHECK(scenario.actions[18].kind == ScenarioAction::Kind::SetCompleteAuto);

    Simulator sim(factory::realisticModel());
    CHECK(validateScenario(scenario, sim).empty());
}

TEST_CASE("Scenario: malformed lines give file:line:column errors", "[simulation]")
{
    struct Case {
        const char* line;
        const char* error;
    };
    const std::vector<Case> cases = {
        {"set Start = TRUE", "s.txt:1:1: expected 'at SCAN:' at the start of the line, found 'set'"},
        {"at x: set Start = TRUE", "s.txt:1:4: expected a scan number after 'at', found 'x'"},
        {"at 0: set Start = TRUE", "s.txt:1:4: scans are numbered from 1"},
        {"at -2: set Start = TRUE", "s.txt:1:4: expected a scan number after 'at', found '-2'"},
        {"at 3 set Start = TRUE", "s.txt:1:6: expected ':' after the scan number, found 'set'"},
        {"at 3: put Start = TRUE", "s.txt:1:7: expected 'set' or 'expect', found 'put'"},
        {"at 4: set Start TRUE", "s.txt:1:17: expected '=' after the variable name, found 'TRUE'"},
        {"at 4: set Start =", "s.txt:1:18: expected a value after '=', found the end of the line"},
        {"at 4: set Start = TRUE Stop = FALSE", "s.txt:1:24: expected ',' or the end of the line, found 'Stop'"},
        {"at 4: set Start = TRUE,", "s.txt:1:24: expected a variable name or 'complete STEP', found the end of the line"},
        {"at 4: set complete = TRUE", "s.txt:1:20: expected a step id after 'complete', found '='"},
        {"at 4: set complete F1 = maybe", "s.txt:1:25: expected TRUE, FALSE or auto, found 'maybe'"},
        {"at 4: expect stop F1", "s.txt:1:14: expected step, fired, token, variable, entry, complete or nested after 'expect', found 'stop'"},
        {"at 4: expect step", "s.txt:1:18: expected a step id after 'step', found the end of the line"},
        {"at 4: expect step F1 F2   # two steps", "s.txt:1:22: expected the end of the line, found 'F2'"},
        {"at 4: expect token T_F1_1_MEM = 1", "s.txt:1:33: expected TRUE or FALSE, found '1'"},
        {"at 4: expect entry TRUE", "s.txt:1:20: expected '=' after 'entry', found 'TRUE'"},
        {"at 99999999999999: expect entry = TRUE",
         "s.txt:1:4: scan number 99999999999999 is too large: a scenario runs at most 10000000 scans"},
        // Every run is bounded: four billion scans would print gigabytes.
        {"at 4000000000: expect entry = TRUE",
         "s.txt:1:4: scan number 4000000000 is too large: a scenario runs at most 10000000 scans"},
        {"at 10000001: expect entry = TRUE",
         "s.txt:1:4: scan number 10000001 is too large: a scenario runs at most 10000000 scans"},
        // Beyond 64 bits too, not 'expected a scan number'.
        {"at  99999999999999999999999: expect entry = TRUE",
         "s.txt:1:5: scan number 99999999999999999999999 is too large: a scenario runs at most 10000000 scans"},
    };
    for (const Case& c : cases) {
        const ScenarioParseResult parsed = parseScenario(c.line, "s.txt");
        INFO(c.line);
        REQUIRE(parsed.errors.size() == 1);
        CHECK(parsed.errors[0].toString() == c.error);
        CHECK(parsed.scenario.actions.empty());
    }

    // The bound itself is a scan like any other.
    CHECK(parseScenario("at 10000000: expect entry = TRUE", "s.txt").errors.empty());
    CHECK(parseScenario("at 10000000: expect entry = TRUE", "s.txt").scenario.lastScan() == kMaxScenarioScan);

    // Every bad line is reported, the good ones are kept; comments and blank lines are nothing.
    const ScenarioParseResult parsed = parseScenario("# title\n\nat 1: set A = TRUE\nat 2 set\n   \nat 3: expect\n"
                                                     "at 4: expect fired none # ok\n",
                                                     "x.txt");
    CHECK(errorTexts(parsed.errors)
          == std::vector<std::string>{"x.txt:4:6: expected ':' after the scan number, found 'set'",
                                      "x.txt:6:13: expected step, fired, token, variable, entry, complete or nested after "
                                      "'expect', found the end of the line"});
    CHECK(parsed.scenario.actions.size() == 2);
}

TEST_CASE("Scenario: syntax errors carry their kind and the word found", "[simulation]")
{
    using Kind = ScenarioError::Kind;
    struct Case {
        const char* line;
        Kind kind;
        std::string found; // empty: the end of the line
        std::string subject;
        std::string message; // exact
    };
    const std::vector<Case> cases = {
        {"set A = TRUE", Kind::ExpectedAt, "set", "", "expected 'at SCAN:' at the start of the line, found 'set'"},
        {"at", Kind::ExpectedScanNumber, "", "", "expected a scan number after 'at', found the end of the line"},
        {"at 0: set A = TRUE", Kind::ScanBelowOne, "0", "", "scans are numbered from 1"},
        {"at 99999999999999: set A = TRUE", Kind::ScanTooLarge, "99999999999999", "99999999999999",
         "scan number 99999999999999 is too large: a scenario runs at most 10000000 scans"},
        {"at 3 set", Kind::ExpectedColon, "set", "", "expected ':' after the scan number, found 'set'"},
        {"at 3: put", Kind::ExpectedSetOrExpect, "put", "", "expected 'set' or 'expect', found 'put'"},
        {"at 3: set = 1", Kind::ExpectedSetItem, "=", "", "expected a variable name or 'complete STEP', found '='"},
        {"at 3: set complete", Kind::ExpectedStepAfterComplete, "", "",
         "expected a step id after 'complete', found the end of the line"},
        {"at 3: set complete F1 TRUE", Kind::ExpectedEqualsAfterStep, "TRUE", "",
         "expected '=' after the step id, found 'TRUE'"},
        {"at 3: set A TRUE", Kind::ExpectedEqualsAfterVariable, "TRUE", "",
         "expected '=' after the variable name, found 'TRUE'"},
        {"at 3: set A = ,", Kind::ExpectedValue, ",", "", "expected a value after '=', found ','"},
        {"at 3: set complete F1 = soon", Kind::ExpectedCompleteValue, "soon", "",
         "expected TRUE, FALSE or auto, found 'soon'"},
        {"at 3: set A = 1 B = 2", Kind::ExpectedCommaOrEnd, "B", "", "expected ',' or the end of the line, found 'B'"},
        {"at 3: expect", Kind::ExpectedExpectItem, "", "",
         "expected step, fired, token, variable, entry, complete or nested after 'expect', found the end of the line"},
        {"at 3: expect step :", Kind::ExpectedStepAfterStep, ":", "", "expected a step id after 'step', found ':'"},
        {"at 3: expect fired", Kind::ExpectedTransition, "", "",
         "expected a transition id or 'none' after 'fired', found the end of the line"},
        {"at 3: expect token", Kind::ExpectedToken, "", "",
         "expected a token name after 'token', found the end of the line"},
        {"at 3: expect token T TRUE", Kind::ExpectedEqualsAfterToken, "TRUE", "",
         "expected '=' after the token name, found 'TRUE'"},
        {"at 3: expect token T = yes", Kind::ExpectedBool, "yes", "", "expected TRUE or FALSE, found 'yes'"},
        {"at 3: expect variable", Kind::ExpectedVariable, "", "",
         "expected a variable name after 'variable', found the end of the line"},
        {"at 3: expect entry", Kind::ExpectedEqualsAfterEntry, "", "",
         "expected '=' after 'entry', found the end of the line"},
        {"at 3: expect fired none now", Kind::ExpectedEnd, "now", "", "expected the end of the line, found 'now'"},
    };
    for (const Case& c : cases) {
        const ScenarioParseResult parsed = parseScenario(c.line, "s.txt");
        INFO(c.line);
        REQUIRE(parsed.errors.size() == 1);
        const ScenarioError& error = parsed.errors[0];
        CHECK(error.kind == c.kind);
        CHECK(error.found == c.found);
        CHECK(error.subject == c.subject);
        CHECK(error.message == c.message);
        CHECK(toText(error) == c.message);
        CHECK(error.line == 1);
    }
}

TEST_CASE("Scenario: unknown names are errors naming the line", "[simulation]")
{
    const char* text = "at 1: set Nope = TRUE\n"
                       "at 1: set BatchSize = TRUE\n"
                       "at 2: set BatchSize = 40000\n"
                       "at 2: expect step F3\n"
                       "at 2: expect step Q7\n"
                       "at 3: expect fired A1->F5\n"
                       "at 3: expect fired A1->Z1\n"
                       "at 4: set complete F2 = TRUE\n"
                       "at 4: expect token Start_F1_1_MEM = TRUE\n"
                       "at 5: expect variable Temperature = hot\n";
    const ScenarioParseResult parsed = parseScenario(text, "bad.txt");
    REQUIRE(parsed.ok());
    Simulator sim(factory::realisticModel());
    CHECK(errorTexts(validateScenario(parsed.scenario, sim))
          == std::vector<std::string>{
              "bad.txt:1:11: unknown variable 'Nope'",
              "bad.txt:2:23: BatchSize is INT: 'TRUE' is not an INT literal: write a whole number such as 42",
              "bad.txt:3:23: BatchSize is INT: '40000' is out of range for INT (-32768..32767)",
              "bad.txt:4:19: step F3 is hidden: it does not exist for the simulator",
              "bad.txt:5:19: unknown step 'Q7'",
              "bad.txt:6:20: transition A1->F5 is not effective (it or one of its steps is hidden)",
              "bad.txt:7:20: unknown transition 'A1->Z1'",
              "bad.txt:8:20: step F2 is a simple step: it has no Complete",
              "bad.txt:9:20: unknown token 'Start_F1_1_MEM'",
              "bad.txt:10:37: Temperature is REAL: 'hot' is not a REAL literal: write a decimal number such as 1.5 or 2.0E3",
          });

    // The same as data: the kind and the names, the value parser's English as the detail.
    using Kind = ScenarioError::Kind;
    const std::vector<ScenarioError> errors = validateScenario(parsed.scenario, sim);
    REQUIRE(errors.size() == 10);
    const std::vector<std::pair<Kind, std::string>> kinds = {
        {Kind::UnknownVariable, "Nope"},     {Kind::InvalidValue, "BatchSize"},
        {Kind::InvalidValue, "BatchSize"},   {Kind::HiddenStep, "F3"},
        {Kind::UnknownStep, "Q7"},           {Kind::IneffectiveTransition, "A1->F5"},
        {Kind::UnknownTransition, "A1->Z1"}, {Kind::SimpleStep, "F2"},
        {Kind::UnknownToken, "Start_F1_1_MEM"}, {Kind::InvalidValue, "Temperature"},
    };
    for (std::size_t i = 0; i < errors.size(); ++i) {
        INFO(i);
        CHECK(errors[i].kind == kinds[i].first);
        CHECK(errors[i].subject == kinds[i].second);
        CHECK(errors[i].message == toText(errors[i]));
    }
    CHECK(errors[2].type == "INT");
    CHECK(errors[2].detail == "'40000' is out of range for INT (-32768..32767)");
    REQUIRE(errors[2].problem.has_value());
    CHECK(*errors[2].problem == ValueProblem{ValueProblem::Kind::OutOfRange, "40000", "INT", "-32768", "32767"});
    REQUIRE(errors[1].problem.has_value());
    CHECK(errors[1].problem->kind == ValueProblem::Kind::NotInteger);
    CHECK_FALSE(errors[0].problem.has_value());
    CHECK(errors[9].type == "REAL");
}

TEST_CASE("Scenario: a UTF-8 byte order mark at the start is accepted", "[simulation]")
{
    const ScenarioParseResult parsed = parseScenario("\xEF\xBB\xBF" "at 1: set Start = TRUE\nat 2: expect step A1\n", "bom.txt");
    CHECK(errorTexts(parsed.errors).empty());
    REQUIRE(parsed.scenario.actions.size() == 2);
    CHECK(parsed.scenario.actions[0].column == 11); // the mark takes no column
    // An error on line 1 counts columns without it too.
    CHECK(errorTexts(parseScenario("\xEF\xBB\xBF" "at 1 set", "bom.txt").errors)
          == std::vector<std::string>{"bom.txt:1:6: expected ':' after the scan number, found 'set'"});
}

TEST_CASE("Scenario: invalid UTF-8 is refused at its line and column", "[simulation]")
{
    // "Température" in Latin-1: not UTF-8.
    const ScenarioParseResult parsed =
        parseScenario("at 1: set Start = TRUE\nat 2: set Temp\xE9rature = 1.5\nat 3 oops\n", "latin1.txt");
    CHECK(errorTexts(parsed.errors)
          == std::vector<std::string>{"latin1.txt:2:15: invalid UTF-8: a scenario file must be UTF-8 text"});
    CHECK(parsed.errors.front().kind == ScenarioError::Kind::InvalidUtf8);
    CHECK(parsed.scenario.actions.empty());
}

TEST_CASE("Scenario: columns count characters, not bytes", "[simulation]")
{
    CHECK(errorTexts(parseScenario("at 1: set \xC3\x84rger = TRUE Stop", "u.txt").errors)
          == std::vector<std::string>{"u.txt:1:24: expected ',' or the end of the line, found 'Stop'"});
    CHECK(errorTexts(parseScenario("at 1: set \xC3\x84rger =   # \xC3\xA9", "u.txt").errors)
          == std::vector<std::string>{"u.txt:1:18: expected a value after '=', found the end of the line"});
}

TEST_CASE("Scenario: one scan cannot set a variable or a Complete to two values", "[simulation]")
{
    Simulator sim(factory::realisticModel());
    const auto validate = [&](const char* text) {
        const ScenarioParseResult parsed = parseScenario(text, "c.txt");
        REQUIRE(parsed.ok());
        return validateScenario(parsed.scenario, sim);
    };
    // Line order within a scan does not matter, so no line may win.
    const std::vector<ScenarioError> errors = validate("at 2: set Start = TRUE\n"
                                                       "at 3: set Start = FALSE\n"
                                                       "at 2: set Stop = TRUE, start = FALSE\n"
                                                       "at 4: set complete F1 = FALSE\n"
                                                       "at 4: set Complete f1 = auto\n");
    CHECK(errorTexts(errors)
          == std::vector<std::string>{
              "c.txt:3:32: Start is set to two values in scan 2: TRUE on line 1, FALSE on line 3",
              "c.txt:5:25: F1's Complete is set to two values in scan 4: FALSE on line 4, auto on line 5",
          });
    REQUIRE(errors.size() == 2);
    CHECK(errors[0].kind == ScenarioError::Kind::ConflictingValue);
    CHECK(errors[0].subject == "Start");
    CHECK(errors[0].scan == 2);
    CHECK(errors[0].otherLine == 1);
    CHECK(errors[0].otherValue == "TRUE");
    CHECK(errors[0].found == "FALSE");
    CHECK(errors[1].kind == ScenarioError::Kind::ConflictingComplete);
    CHECK(errors[1].subject == "F1");
    CHECK(errors[1].otherValue == "FALSE");
    CHECK(errors[1].found == "auto");

    // The same value twice, spelt alike or not, is harmless.
    CHECK(validate("at 2: set Start = TRUE, START = true\n"
                   "at 2: set Temperature = 1, Temperature = 1.0\n"
                   "at 2: set complete F1 = TRUE\n"
                   "at 2: set complete F1 = TRUE\n")
              .empty());
    // Two values of one variable on one line are caught as well.
    CHECK(errorTexts(validate("at 7: set BatchSize = 5, BatchSize = 6"))
          == std::vector<std::string>{"c.txt:1:38: BatchSize is set to two values in scan 7: 5 on line 1, 6 on line 1"});
}

TEST_CASE("Scenario: running checks each expectation after its scan", "[simulation]")
{
    Simulator sim(factory::realisticModel());
    const ScenarioParseResult parsed = parseScenario(kBottling, "bottling.txt");
    REQUIRE(parsed.ok());
    ScenarioRunResult result = runScenario(parsed.scenario, sim);
    CHECK(failureTexts(result.failures).empty());
    REQUIRE(result.records.size() == 6);
    CHECK(result.records[1].fired == "A1->F1");
    CHECK(result.records[5].fired == "F1->A2");
    CHECK(sim.completeMode("F1") == CompleteMode::Automatic);

    // The same scenario with wrong expectations: each failure says the scan and what differed.
    const ScenarioParseResult wrong = parseScenario("at 1: expect step A1\n"
                                                    "at 2: expect fired A1->F1\n"
                                                    "at 2: expect fired none\n"
                                                    "at 2: expect token Stop_F1_2_MEM = TRUE\n"
                                                    "at 2: expect entry = FALSE\n"
                                                    "at 2: expect variable BatchSize = 12\n"
                                                    "at 2: expect complete F1 = TRUE\n"
                                                    "at 3: set HomePosition = TRUE, AirPressureOk = TRUE\n"
                                                    "at 3: expect fired none\n",
                                                    "wrong.txt");
    REQUIRE(wrong.ok());
    REQUIRE(validateScenario(wrong.scenario, sim).empty());
    result = runScenario(wrong.scenario, sim);
    CHECK(failureTexts(result.failures)
          == std::vector<std::string>{
              "scan 1: expected step A1, active step is A6",
              "scan 2: expected A1->F1 to fire, no transition fired",
              "scan 2: expected token Stop_F1_2_MEM = TRUE, it is FALSE",
              "scan 2: expected Entry = FALSE, it is TRUE",
              "scan 2: expected BatchSize = 12, it is 500",
              "scan 2: expected F1.Complete = TRUE, it is FALSE",
              "scan 3: expected no transition to fire, A6->A1 fired",
          });
    CHECK(result.failures[0].line == 1);
    CHECK(result.failures.back().line == 9);
    // The same as data, for the editor to word.
    REQUIRE(result.failures.size() == 7);
    using Kind = ScenarioFailure::Kind;
    CHECK(result.failures[0] == ScenarioFailure{1, 1, Kind::WrongStep, "", "A1", "A6", ""});
    CHECK(result.failures[1] == ScenarioFailure{2, 2, Kind::NothingFired, "", "A1->F1", "", ""});
    CHECK(result.failures[2] == ScenarioFailure{2, 4, Kind::WrongToken, "Stop_F1_2_MEM", "TRUE", "FALSE", ""});
    CHECK(result.failures[4] == ScenarioFailure{2, 6, Kind::WrongVariable, "BatchSize", "12", "500", ""});
    CHECK(result.failures[5] == ScenarioFailure{2, 7, Kind::WrongComplete, "F1", "TRUE", "FALSE", ""});
    CHECK(result.failures[6] == ScenarioFailure{3, 9, Kind::UnexpectedFiring, "", "", "A6->A1", ""});

    SECTION("--scans beyond the scenario runs idle scans")
    {
        result = runScenario(parsed.scenario, sim, 10);
        CHECK(result.records.size() == 10);
        CHECK(result.passed());
    }
}

TEST_CASE("Scenario: English text of the failures the runner rarely meets", "[simulation]")
{
    using Kind = ScenarioFailure::Kind;
    CHECK(toText(ScenarioFailure{4, 1, Kind::NoVisibleStep, "", "F1", "6", ""})
          == "scan 4: expected step F1, active step is none (State = 6 names no visible step)");
    CHECK(toText(ScenarioFailure{2, 1, Kind::WrongFiring, "", "A1->F1", "A1->F2", ""})
          == "scan 2: expected A1->F1 to fire, A1->F2 fired");
    CHECK(toText(ScenarioFailure{2, 1, Kind::UnknownVariable, "Speed", "", "", ""})
          == "scan 2: unknown variable 'Speed'");
    CHECK(toText(ScenarioFailure{3, 1, Kind::CannotApply, "Speed", "", "", "out of range"})
          == "scan 3: cannot apply: out of range");
}

TEST_CASE("Scenario: an expected step while State names no visible step", "[simulation]")
{
    Model model = factory::realisticModel();
    REQUIRE(model.setInitialStep("A3")); // hidden in the realistic model
    Simulator sim(model);
    const ScenarioParseResult parsed = parseScenario("at 1: expect step a1\n");
    REQUIRE(parsed.ok());
    const ScenarioRunResult result = runScenario(parsed.scenario, sim);
    REQUIRE(result.failures.size() == 1);
    CHECK(result.failures[0].kind == ScenarioFailure::Kind::NoVisibleStep);
    CHECK(result.failures[0].expected == "A1");
    CHECK(result.failures[0].actual == std::to_string(sim.activeStepNumber()));
    CHECK_THAT(toText(result.failures[0]), Catch::EndsWith(" names no visible step)"));
}

TEST_CASE("Scenario: a recorded session is written back as a scenario that replays it", "[simulation]")
{
    Simulator sim(factory::realisticModel());
    ScenarioRecording recording;
    recording.title = "Recorded session\nsecond line";
    auto before = [&](std::int64_t scan, std::vector<InputChange> inputs,
                      std::vector<RecordedScan::CompleteSetting> completes = {}) {
        for (const InputChange& change : inputs)
            REQUIRE(sim.setVariable(change.variable, change.value));
        for (const auto& complete : completes) {
            REQUIRE(sim.setCompleteMode(complete.stepId,
                                        complete.manualValue ? CompleteMode::Manual : CompleteMode::Automatic));
            if (complete.manualValue)
                REQUIRE(sim.setComplete(complete.stepId, *complete.manualValue));
        }
        recording.changes.push_back(RecordedScan{scan, std::move(inputs), std::move(completes), {}});
    };
    before(1, {{"HomePosition", true}, {"AirPressureOk", true}});
    recording.records.push_back(sim.step());
    before(2, {{"Start", true}, {"PreparationDone", true}, {"DoorClosed", true}, {"Temperature", 30.5}});
    recording.records.push_back(sim.step());
    before(3, {{"Stop", true}}, {{"F1", false}});
    recording.records.push_back(sim.step());
    before(4, {{"Stop", false}, {"BatchSize", std::int64_t{-3}}}, {{"F1", std::nullopt}});
    recording.records.push_back(sim.step());
    // Scan 3's entry block reset the token and Stop was TRUE then: the pulse
    // of scan 4 is captured at its end, and F1 -> A2 fires in scan 5.
    REQUIRE(recording.records.back().fired.empty());
    recording.records.push_back(sim.step());
    REQUIRE(recording.records.back().fired == "F1->A2");

    const std::string text = writeScenario(recording);
    CHECK(text == "# Recorded session\n"
                  "# second line\n"
                  "at 1: set HomePosition = TRUE, AirPressureOk = TRUE\n"
                  "at 1: expect fired A6->A1\n"
                  "at 1: expect step A1\n"
                  "at 2: set Start = TRUE, PreparationDone = TRUE, DoorClosed = TRUE, Temperature = 30.5\n"
                  "at 2: expect fired A1->F1\n"
                  "at 2: expect step F1\n"
                  "at 3: set Stop = TRUE\n"
                  "at 3: set complete F1 = FALSE\n"
                  "at 4: set Stop = FALSE, BatchSize = -3\n"
                  "at 4: set complete F1 = auto\n"
                  "at 5: expect fired F1->A2\n"
                  "at 5: expect step A2\n");
    const ScenarioParseResult parsed = parseScenario(text);
    REQUIRE(parsed.ok());
    REQUIRE(validateScenario(parsed.scenario, sim).empty());
    const ScenarioRunResult replay = runScenario(parsed.scenario, sim);
    CHECK(failureTexts(replay.failures).empty());
    REQUIRE(replay.records.size() == 5);
    for (std::size_t i = 0; i < 5; ++i) {
        CHECK(replay.records[i].fired == recording.records[i].fired);
        CHECK(replay.records[i].tokens == recording.records[i].tokens);
    }
}

} // namespace test_scenario
