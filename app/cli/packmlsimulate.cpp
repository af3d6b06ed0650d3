#include "packmlsimulate.h"

#include "core/formats/fileio.h"
#include "core/templates/packml/packmlscenario.h"
#include "core/templates/packml/packmlsimulator.h"
#include "terminal.h"

#include <ostream>

namespace cli {

namespace {

constexpr std::int64_t kDefaultScans = 10;

std::string modeName(const core::packml::PackmlProgram& program, int number)
{
    const core::packml::ProgramMode* mode = program.mode(number);
    return mode ? mode->name : std::to_string(number);
}

std::string joined(const std::vector<int>& numbers)
{
    std::string text;
    for (int number : numbers)
        text += (text.empty() ? "" : ", ") + std::to_string(number);
    return text.empty() ? "none" : text;
}

// The instance the scan called, then every continuous output.
void printTrace(const core::packml::PackmlScanRecord& record, const core::packml::PackmlSimulator& simulator,
                std::ostream& out)
{
    const core::packml::PackmlProgram& program = simulator.program();
    if (record.calledInstance >= 0) {
        const auto& instance = program.instances[static_cast<std::size_t>(record.calledInstance)];
        const core::NestedEngine* engine = simulator.engine(record.calledInstance);
        out << "    " << instance.name << (engine ? " steps: " + joined(engine->activeSteps()) : std::string(" (skeleton)"))
            << ", Complete = " << (simulator.complete(record.calledInstance) ? "TRUE" : "FALSE") << lineEnd;
    }
    std::string outputs;
    for (const core::Variable& variable : program.variables) {
        if (variable.kind != core::VariableKind::Output || variable.type != core::IecType::Bool)
            continue;
        outputs += (outputs.empty() ? "" : ", ") + variable.name + " = "
                 + core::cond::formatValue(*simulator.value(variable.name));
    }
    out << "    Entry = " << (simulator.entry() ? "TRUE" : "FALSE") << ", Resume = "
        << (simulator.resume() ? "TRUE" : "FALSE") << lineEnd;
    if (!outputs.empty())
        out << "    outputs: " << outputs << lineEnd;
}

// "scan 14: Idle in Manual, mode Production->Manual, fired Stopped-Reset->Idle",
// then a line per dropped event.
void printScan(const core::packml::PackmlScanRecord& record, const core::packml::PackmlSimulator& simulator,
               bool trace, std::ostream& out)
{
    const core::packml::PackmlProgram& program = simulator.program();
    out << "scan " << record.scan << ": " << core::packml::stateName(record.state) << " in "
        << modeName(program, record.mode);
    if (record.modeChanged())
        out << ", mode " << modeName(program, record.modeBefore) << "->" << modeName(program, record.mode);
    if (record.fired)
        out << ", fired " << core::packml::transitionText(*record.fired);
    if (record.resumed)
        out << ", Execute resumed";
    out << lineEnd;
    for (const core::packml::DroppedEvent& event : record.dropped)
        out << "    dropped: " << core::packml::toText(event) << lineEnd;
    if (trace)
        printTrace(record, simulator, out);
}

bool loadScenario(const std::string& path, const core::packml::PackmlSimulator& simulator, core::Scenario& scenario,
                  std::ostream& err)
{
    std::string text;
    if (core::Status status = core::readFileLimited(path, 16u * 1024u * 1024u, text); !status) {
        err << path << ": " << status.message << lineEnd;
        return false;
    }
    core::ScenarioParseResult parsed = core::parseScenario(text, path);
    std::vector<core::ScenarioError> errors = parsed.errors;
    if (parsed.ok())
        errors = core::packml::validatePackmlScenario(parsed.scenario, simulator);
    for (const core::ScenarioError& error : errors)
        err << error.toString() << lineEnd;
    scenario = std::move(parsed.scenario);
    return errors.empty();
}

} // namespace

int simulatePackml(const core::Model& model, const std::vector<std::string>& files, std::int64_t scans, bool trace,
                   Streams streams)
{
    core::packml::PackmlSimulator simulator(model);
    int errors = 0;
    for (const core::ProgramProblem& problem : simulator.program().problems)
        errors += problem.kind == core::ProgramProblem::Kind::Error ? 1 : 0;
    if (errors > 0)
        streams.err << files[0] << ": " << errors << " error(s) in the model: "
                    << "a condition that cannot be used is FALSE, as in the generated code" << lineEnd;

    core::Scenario scenario;
    if (files.size() == 2 && !loadScenario(files[1], simulator, scenario, streams.err))
        return UnreadableInput;
    if (scans == 0)
        scans = scenario.lastScan() > 0 ? scenario.lastScan() : kDefaultScans;

    core::packml::PackmlScenarioRunner runner(scenario, simulator);
    std::size_t failures = 0;
    for (std::int64_t i = 0; i < scans; ++i) {
        const core::packml::PackmlScanRecord record = runner.step();
        if (const auto& fault = simulator.fault()) {
            streams.err << files[0] << ": " << core::toText(*fault) << lineEnd;
            return RunTimeFault;
        }
        printScan(record, simulator, trace, streams.out);
        for (const core::packml::PackmlScenarioFailure& failure : runner.lastFailures())
            streams.err << files[1] << ":" << failure.line << ": " << core::packml::toText(failure) << lineEnd;
        failures += runner.lastFailures().size();
    }
    if (files.size() < 2)
        return Success;
    std::size_t expectations = 0;
    for (const core::ScenarioAction& action : scenario.actions)
        expectations += action.isExpectation() && action.scan <= scans ? 1 : 0;
    if (failures > 0) {
        streams.err << files[1] << ": " << failures << " of " << expectations << " expectation(s) failed" << lineEnd;
        return ModelHasErrors;
    }
    streams.out << files[1] << ": all " << expectations << " expectation(s) met" << lineEnd;
    return Success;
}

} // namespace cli
