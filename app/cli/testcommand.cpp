#include "testcommand.h"

#include "junitreport.h"
#include "loadreport.h"
#include "terminal.h"

#include "core/formats/fileio.h"
#include "core/machine/closedloopscenario.h"
#include "core/machine/machineloop.h"
#include "core/simulation/scenario.h"
#include "core/simulation/simulator.h"
#include "core/templates/packml/packmlscenario.h"
#include "core/templates/packml/packmlsimulator.h"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <ostream>
#include <system_error>

namespace cli {

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kMaxScenarioBytes = 16u * 1024u * 1024u;

// What one scenario did against one model.
struct ScenarioOutcome {
    JUnitCase::Outcome outcome = JUnitCase::Outcome::Passed;
    std::int64_t scans = 0;
    std::size_t expectations = 0;
    std::vector<std::string> problems; // failed: "line 9: scan 154: ..."; error: the messages
};

// The files of a folder whose names end with one of `suffixes`, by name; a
// path that is no folder stands for itself (a missing file is reported when read).
std::vector<std::string> expand(const std::string& path, const std::vector<std::string>& suffixes)
{
    std::error_code error;
    if (!fs::is_directory(path, error))
        return {path};
    std::vector<std::string> files;
    for (const fs::directory_entry& entry : fs::directory_iterator(path, error)) {
        const std::string name = entry.path().filename().string();
        const bool wanted = std::any_of(suffixes.begin(), suffixes.end(), [&](const std::string& suffix) {
            return name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
        });
        if (wanted && entry.is_regular_file(error))
            files.push_back((fs::path(path) / name).string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

ScenarioOutcome errorOutcome(std::vector<std::string> messages)
{
    ScenarioOutcome outcome;
    outcome.outcome = JUnitCase::Outcome::Error;
    outcome.problems = std::move(messages);
    return outcome;
}

std::size_t countExpectations(const core::Scenario& scenario)
{
    return static_cast<std::size_t>(std::count_if(scenario.actions.begin(), scenario.actions.end(),
                                                  [](const core::ScenarioAction& a) { return a.isExpectation(); }));
}

std::vector<std::string> errorTexts(const std::vector<core::ScenarioError>& errors)
{
    std::vector<std::string> texts;
    for (const core::ScenarioError& error : errors)
        texts.push_back(error.toString());
    return texts;
}

// Runs the scenario's scans on a runner (GEMMA or PackML): every failure
// as "line N: scan S: ...", and a run-time fault as the last problem.
template <typename Runner, typename Simulator>
ScenarioOutcome play(const core::Scenario& scenario, Runner& runner, const Simulator& simulator)
{
    ScenarioOutcome outcome;
    outcome.expectations = countExpectations(scenario);
    const std::int64_t scans = scenario.lastScan();
    for (std::int64_t i = 0; i < scans; ++i) {
        runner.step();
        outcome.scans = simulator.scanCount();
        if (simulator.fault()) {
            outcome.problems.push_back(core::toText(*simulator.fault())); // "scan 3: integer division by zero ..."
            break;
        }
    }
    std::vector<std::string> failures;
    for (const auto& failure : runner.failures())
        failures.push_back("line " + std::to_string(failure.line) + ": " + toText(failure));
    outcome.problems.insert(outcome.problems.begin(), failures.begin(), failures.end());
    if (!outcome.problems.empty())
        outcome.outcome = JUnitCase::Outcome::Failed;
    return outcome;
}

ScenarioOutcome runGemma(const core::Model& model, const core::Scenario& scenario)
{
    core::Simulator simulator(model);
    std::optional<core::machine::MachineLoop> loop;
    if (!model.machine().empty())
        loop.emplace(simulator, model.machine());
    std::vector<core::ScenarioError> errors = core::validateScenario(
        scenario, simulator, loop ? core::FaultLines::CheckedByMachine : core::FaultLines::Refused);
    if (errors.empty() && loop)
        errors = core::machine::validateClosedLoopScenario(scenario, *loop);
    if (!errors.empty())
        return errorOutcome(errorTexts(errors));
    core::ScenarioRunner runner = loop ? core::ScenarioRunner(scenario, *loop) : core::ScenarioRunner(scenario, simulator);
    return play(scenario, runner, simulator);
}

ScenarioOutcome runPackml(const core::Model& model, const core::Scenario& scenario)
{
    core::packml::PackmlSimulator simulator(model);
    const std::vector<core::ScenarioError> errors = core::packml::validatePackmlScenario(scenario, simulator);
    if (!errors.empty())
        return errorOutcome(errorTexts(errors));
    core::packml::PackmlScenarioRunner runner(scenario, simulator);
    return play(scenario, runner, simulator);
}

ScenarioOutcome runScenarioFile(const core::Model& model, const std::string& path)
{
    std::string text;
    if (const core::Status status = core::readFileLimited(path, kMaxScenarioBytes, text); !status)
        return errorOutcome({path + ": " + status.message});
    const core::ScenarioParseResult parsed = core::parseScenario(text, path);
    if (!parsed.ok())
        return errorOutcome(errorTexts(parsed.errors));
    return model.packml() ? runPackml(model, parsed.scenario) : runGemma(model, parsed.scenario);
}

// "PASS (1415 scans, 17 expectation(s) met)", "FAIL (...): line 9: scan 154: ...".
std::string summary(const ScenarioOutcome& outcome)
{
    const std::string scans = std::to_string(outcome.scans) + " scans, ";
    switch (outcome.outcome) {
    case JUnitCase::Outcome::Passed:
        return "PASS (" + scans + std::to_string(outcome.expectations) + " expectation(s) met)";
    case JUnitCase::Outcome::Failed:
        return "FAIL (" + scans + std::to_string(outcome.problems.size()) + " problem(s)): "
            + outcome.problems.front();
    case JUnitCase::Outcome::Error: return "ERROR: " + outcome.problems.front();
    }
    return {};
}

JUnitCase junitCase(const std::string& scenario, const ScenarioOutcome& outcome)
{
    JUnitCase test;
    test.name = scenario;
    test.outcome = outcome.outcome;
    if (!outcome.problems.empty())
        test.message = outcome.problems.front();
    for (const std::string& problem : outcome.problems)
        test.details += problem + "\n";
    return test;
}

int exitCode(JUnitCase::Outcome outcome)
{
    switch (outcome) {
    case JUnitCase::Outcome::Passed: return Success;
    case JUnitCase::Outcome::Failed: return ModelHasErrors;
    case JUnitCase::Outcome::Error: return UnreadableInput;
    }
    return UnreadableInput;
}

// Every scenario against one model: a line each, then the model's total.
JUnitSuite testModel(const std::string& modelPath, const std::vector<std::string>& scenarios, int& worst,
                     Streams streams)
{
    JUnitSuite suite{modelPath, {}};
    const core::LoadedModel loaded = loadAndReport(modelPath, streams.err, core::TemplateSupport::GemmaAndPackML);
    std::size_t passed = 0;
    for (const std::string& scenario : scenarios) {
        const ScenarioOutcome outcome = loaded.ok() ? runScenarioFile(*loaded.model, scenario)
                                                    : errorOutcome({modelPath + ": the model cannot be read"});
        streams.out << modelPath << ": " << scenario << ": " << summary(outcome) << lineEnd;
        passed += outcome.outcome == JUnitCase::Outcome::Passed ? 1 : 0;
        worst = std::max(worst, exitCode(outcome.outcome));
        suite.cases.push_back(junitCase(scenario, outcome));
    }
    streams.out << modelPath << ": " << passed << " of " << scenarios.size() << " scenario(s) passed" << lineEnd;
    return suite;
}

int usage(std::ostream& err, const std::string& message)
{
    err << "ggstudio-cli: " << message << lineEnd << "Try 'ggstudio-cli --help'." << lineEnd;
    return UsageError;
}

} // namespace

int commandTest(const Arguments& args, Streams streams)
{
    const std::vector<std::string>& words = args.positional();
    const std::vector<std::string> modelOptions = args.values("--models");
    std::vector<std::string> models;
    std::vector<std::string>::const_iterator firstScenario = words.begin();
    if (modelOptions.empty()) {
        if (words.size() < 2)
            return usage(streams.err, "test takes a model file, then scenario files or folders");
        models.push_back(words.front());
        ++firstScenario;
    } else {
        if (words.empty())
            return usage(streams.err, "test --models takes scenario files or folders");
        for (const std::string& option : modelOptions) {
            const std::vector<std::string> found = expand(option, {".json", ".xml"});
            if (found.empty()) {
                streams.err << option << ": no model file (*.json, *.xml) in this folder" << lineEnd;
                return UnreadableInput;
            }
            models.insert(models.end(), found.begin(), found.end());
        }
    }
    const std::optional<std::string> junit = args.value("--junit");
    if (junit && junit->empty())
        return usage(streams.err, "--junit takes a file name");
    std::vector<std::string> scenarios;
    for (auto word = firstScenario; word != words.end(); ++word) {
        const std::vector<std::string> found = expand(*word, {".scenario"});
        if (found.empty()) {
            streams.err << *word << ": no scenario file (*.scenario) in this folder" << lineEnd;
            return UnreadableInput;
        }
        scenarios.insert(scenarios.end(), found.begin(), found.end());
    }

    int worst = Success;
    std::vector<JUnitSuite> suites;
    for (const std::string& model : models)
        suites.push_back(testModel(model, scenarios, worst, streams));
    if (junit) {
        if (const core::Status status = core::writeFileAtomically(*junit, writeJUnit(suites)); !status) {
            streams.err << *junit << ": " << status.message << lineEnd;
            return UnreadableInput;
        }
    }
    return worst;
}

} // namespace cli
