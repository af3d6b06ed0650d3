#include "core/templates/packml/packmlscenario.h"

#include "core/model/iectypes.h"

#include <algorithm>
#include <charconv>

namespace core::packml {

namespace {

using ErrorKind = ScenarioError::Kind;
using ActionKind = ScenarioAction::Kind;

std::optional<int> smallNumber(std::string_view text)
{
    int number = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
    if (error != std::errc() || end != text.data() + text.size() || text.empty())
        return std::nullopt;
    return number;
}

// A command or mode request as the runner issues it: which tag carries the
// number, which one rises.
struct Request {
    std::string_view numberTag;
    std::string_view edgeTag;
    std::string_view word; // "command", "mode"
};
constexpr Request kCommandRequest{"CntrlCmd", "CmdChangeRequest", "command"};
constexpr Request kModeRequest{"UnitMode", "UnitModeChangeRequest", "mode"};

class Validator {
public:
    Validator(const Scenario& scenario, const PackmlSimulator& simulator)
        : m_scenario(scenario), m_simulator(simulator)
    {
    }

    std::vector<ScenarioError> run()
    {
        for (const ScenarioAction& action : m_scenario.actions)
            check(action);
        checkSpacing(m_commands, kCommandRequest);
        checkSpacing(m_modes, kModeRequest);
        std::stable_sort(m_errors.begin(), m_errors.end(), [](const ScenarioError& a, const ScenarioError& b) {
            return a.line != b.line ? a.line < b.line : a.column < b.column;
        });
        return std::move(m_errors);
    }

private:
    struct Issued {
        const ScenarioAction* action;
        int number;
    };

    ScenarioError& error(const ScenarioAction& action, int column, ErrorKind kind, std::string subject)
    {
        ScenarioError error;
        error.fileName = m_scenario.fileName;
        error.line = action.line;
        error.column = column;
        error.kind = kind;
        error.subject = std::move(subject);
        error.message = toText(error);
        m_errors.push_back(std::move(error));
        return m_errors.back();
    }

    void check(const ScenarioAction& action)
    {
        const PackmlProgram& program = m_simulator.program();
        switch (action.kind) {
        case ActionKind::SetVariable:
        case ActionKind::ExpectVariable: checkVariable(action); break;
        case ActionKind::Command: {
            const std::optional<Command> command = findCommandNamed(action.name, program.options.edition);
            if (!command)
                error(action, action.column, ErrorKind::UnknownCommand, action.name);
            else
                issue(m_commands, action, static_cast<int>(*command), kCommandRequest);
            break;
        }
        case ActionKind::Mode:
        case ActionKind::ExpectMode: {
            const std::optional<int> mode = findModeNamed(program, action.name);
            if (!mode)
                error(action, action.column, ErrorKind::UnknownMode, action.name);
            else if (action.kind == ActionKind::Mode)
                issue(m_modes, action, *mode, kModeRequest);
            break;
        }
        case ActionKind::ExpectState:
            if (!findStateNamed(action.name))
                error(action, action.column, ErrorKind::UnknownState, action.name);
            break;
        case ActionKind::SetComplete:
        case ActionKind::SetCompleteAuto: checkManualComplete(action); break;
        case ActionKind::ExpectFired:
        case ActionKind::ExpectNoFiring: break;
        default:
            error(action, action.column, ErrorKind::NotForPackML, std::string(scenarioKeyword(action.kind)));
            break;
        }
    }

    void checkVariable(const ScenarioAction& action)
    {
        const int slot = m_simulator.slotOf(action.name);
        if (slot < 0) {
            error(action, action.column, ErrorKind::UnknownVariable, action.name);
            return;
        }
        const Variable& variable = m_simulator.program().variables[static_cast<std::size_t>(slot)];
        if (action.kind == ActionKind::SetVariable && variable.kind != VariableKind::Input) {
            ScenarioError& problem = error(action, action.column, ErrorKind::NotAnInput, variable.name);
            problem.detail = variable.kind == VariableKind::Output ? "output" : "internal";
            problem.message = toText(problem);
            return;
        }
        if (action.value.empty() || !cond::parseValue(variable.type, action.value)) {
            ScenarioError& problem = error(action, action.valueColumn, ErrorKind::InvalidValue, variable.name);
            problem.type = std::string(iecTypeName(variable.type));
            problem.detail = defaultValueProblem(variable.type, action.value);
            problem.message = toText(problem);
        }
    }

    // set complete <Mode>_<State>: an instance without GRAFCET.
    void checkManualComplete(const ScenarioAction& action)
    {
        const std::optional<int> instance = findInstanceNamed(m_simulator.program(), action.name);
        if (!instance) {
            error(action, action.column, ErrorKind::UnknownInstance, action.name);
            return;
        }
        const ProgramInstance& found = m_simulator.program().instances[static_cast<std::size_t>(*instance)];
        if (!found.isSkeleton())
            error(action, action.column, ErrorKind::CompleteFromGrafcet, found.name);
    }

    // One command (mode) per scan: CntrlCmd (UnitMode) holds one number.
    void issue(std::map<std::int64_t, Issued>& issued, const ScenarioAction& action, int number, const Request& request)
    {
        const auto [slot, first] = issued.emplace(action.scan, Issued{&action, number});
        if (first || slot->second.number == number)
            return;
        ScenarioError& problem = error(action, action.column, ErrorKind::ConflictingValue, std::string(request.numberTag));
        problem.found = action.name;
        problem.scan = action.scan;
        problem.otherLine = slot->second.action->line;
        problem.otherValue = slot->second.action->name;
        problem.message = toText(problem);
    }

    void checkSpacing(const std::map<std::int64_t, Issued>& issued, const Request& request)
    {
        const Issued* previous = nullptr;
        for (const auto& [scan, current] : issued) {
            if (previous && previous->action->scan == scan - 1) {
                ScenarioError& problem = error(*current.action, current.action->column, ErrorKind::EdgeTooSoon,
                                               std::string(request.word));
                problem.scan = scan;
                problem.otherLine = previous->action->line;
                problem.message = toText(problem);
            }
            previous = &current;
        }
    }

    const Scenario& m_scenario;
    const PackmlSimulator& m_simulator;
    std::vector<ScenarioError> m_errors;
    std::map<std::int64_t, Issued> m_commands; // the first of each scan
    std::map<std::int64_t, Issued> m_modes;
};

std::string modeNameOf(const PackmlProgram& program, int number)
{
    const ProgramMode* mode = program.mode(number);
    return mode ? mode->name : std::to_string(number);
}

} // namespace

std::optional<int> findInstanceNamed(const PackmlProgram& program, std::string_view name)
{
    for (std::size_t i = 0; i < program.instances.size(); ++i)
        if (equalsIgnoreCase(program.instances[i].name, name))
            return static_cast<int>(i);
    return std::nullopt;
}

std::optional<Command> findCommandNamed(std::string_view name, Edition edition)
{
    for (const CommandInfo& info : allCommands())
        if (equalsIgnoreCase(info.name, name) && commandInEdition(info.command, edition))
            return info.command;
    return std::nullopt;
}

std::optional<int> findModeNamed(const PackmlProgram& program, std::string_view name)
{
    for (const ProgramMode& mode : program.modes)
        if (equalsIgnoreCase(mode.name, name))
            return mode.number;
    const std::optional<int> number = smallNumber(name);
    return number && program.mode(*number) ? number : std::nullopt;
}

std::optional<State> findStateNamed(std::string_view name)
{
    for (const StateInfo& info : states())
        if (equalsIgnoreCase(info.name, name))
            return info.state;
    const std::optional<int> number = smallNumber(name);
    return number ? stateFromNumber(*number) : std::nullopt;
}

std::vector<ScenarioError> validatePackmlScenario(const Scenario& scenario, const PackmlSimulator& simulator)
{
    return Validator(scenario, simulator).run();
}

std::string toText(const PackmlScenarioFailure& failure)
{
    using Kind = PackmlScenarioFailure::Kind;
    const std::string& expected = failure.expected;
    const std::string& actual = failure.actual;
    std::string problem;
    switch (failure.kind) {
    case Kind::CannotApply: problem = "cannot apply: " + failure.detail; break;
    case Kind::WrongState: problem = "expected state " + expected + ", the state is " + actual; break;
    case Kind::WrongMode: problem = "expected mode " + expected + ", the mode is " + actual; break;
    case Kind::WrongVariable: problem = "expected " + failure.subject + " = " + expected + ", it is " + actual; break;
    case Kind::NothingFired: problem = "expected " + expected + " to fire, no transition fired"; break;
    case Kind::WrongFiring: problem = "expected " + expected + " to fire, " + actual + " fired"; break;
    case Kind::UnexpectedFiring: problem = "expected no transition to fire, " + actual + " fired"; break;
    }
    return "scan " + std::to_string(failure.scan) + ": " + problem;
}

PackmlScenarioRunner::PackmlScenarioRunner(const Scenario& scenario, PackmlSimulator& simulator)
    : m_scenario(scenario), m_simulator(simulator)
{
    for (const ScenarioAction& action : m_scenario.actions)
        m_byScan[action.scan].push_back(&action);
}

void PackmlScenarioRunner::setInput(const ScenarioAction& action, std::string_view name, const std::string& value)
{
    const Status status = m_simulator.setInputText(name, value);
    if (status)
        return;
    PackmlScenarioFailure failure;
    failure.scan = m_simulator.scanCount() + 1;
    failure.line = action.line;
    failure.kind = PackmlScenarioFailure::Kind::CannotApply;
    failure.subject = std::string(name);
    failure.detail = status.message;
    m_lastFailures.push_back(std::move(failure));
}

void PackmlScenarioRunner::setManualComplete(const ScenarioAction& action)
{
    const std::optional<int> instance = findInstanceNamed(m_simulator.program(), action.name);
    const std::optional<bool> value =
        action.kind == ActionKind::SetCompleteAuto ? std::nullopt : std::optional(action.value == "TRUE");
    const Status status = instance ? m_simulator.setManualComplete(*instance, value)
                                   : Status::failure("simulation.unknown-instance", "no instance is named " + action.name);
    if (status)
        return;
    PackmlScenarioFailure failure;
    failure.scan = m_simulator.scanCount() + 1;
    failure.line = action.line;
    failure.kind = PackmlScenarioFailure::Kind::CannotApply;
    failure.subject = action.name;
    failure.detail = status.message;
    m_lastFailures.push_back(std::move(failure));
}

void PackmlScenarioRunner::apply(const ScenarioAction& action)
{
    const PackmlProgram& program = m_simulator.program();
    std::optional<int> number;
    const Request* request = nullptr;
    if (action.kind == ActionKind::SetVariable) {
        setInput(action, action.name, action.value);
        return;
    }
    if (action.kind == ActionKind::SetComplete || action.kind == ActionKind::SetCompleteAuto) {
        setManualComplete(action);
        return;
    }
    if (action.kind == ActionKind::Command) {
        const std::optional<Command> command = findCommandNamed(action.name, program.options.edition);
        number = command ? std::optional(static_cast<int>(*command)) : std::nullopt;
        request = &kCommandRequest;
    } else if (action.kind == ActionKind::Mode) {
        number = findModeNamed(program, action.name);
        request = &kModeRequest;
    }
    if (!request || !number)
        return; // an expectation, or a name validatePackmlScenario reports
    setInput(action, request->numberTag, std::to_string(*number));
    setInput(action, request->edgeTag, "TRUE");
}

void PackmlScenarioRunner::check(const ScenarioAction& action, const PackmlScanRecord& record)
{
    using Failure = PackmlScenarioFailure::Kind;
    const PackmlProgram& program = m_simulator.program();
    PackmlScenarioFailure failure;
    failure.scan = record.scan;
    failure.line = action.line;
    const std::string fired = record.fired ? transitionText(*record.fired) : std::string();
    switch (action.kind) {
    case ActionKind::ExpectState: {
        const std::optional<State> expected = findStateNamed(action.name);
        if (!expected || *expected == record.state)
            return;
        failure.kind = Failure::WrongState;
        failure.expected = std::string(stateName(*expected));
        failure.actual = std::string(stateName(record.state));
        break;
    }
    case ActionKind::ExpectMode: {
        const std::optional<int> expected = findModeNamed(program, action.name);
        if (!expected || *expected == record.mode)
            return;
        failure.kind = Failure::WrongMode;
        failure.expected = modeNameOf(program, *expected);
        failure.actual = modeNameOf(program, record.mode);
        break;
    }
    case ActionKind::ExpectVariable: {
        const int slot = m_simulator.slotOf(action.name);
        if (slot < 0)
            return;
        const Variable& variable = program.variables[static_cast<std::size_t>(slot)];
        const cond::Value actual = m_simulator.value(slot);
        if (cond::parseValue(variable.type, action.value) == std::optional(actual))
            return;
        failure.kind = Failure::WrongVariable;
        failure.subject = variable.name;
        failure.expected = action.value;
        failure.actual = cond::formatValue(actual);
        break;
    }
    case ActionKind::ExpectFired:
        if (equalsIgnoreCase(fired, action.name))
            return;
        failure.kind = fired.empty() ? Failure::NothingFired : Failure::WrongFiring;
        failure.expected = action.name;
        failure.actual = fired;
        break;
    case ActionKind::ExpectNoFiring:
        if (fired.empty())
            return;
        failure.kind = Failure::UnexpectedFiring;
        failure.actual = fired;
        break;
    default: return;
    }
    m_lastFailures.push_back(std::move(failure));
}

PackmlScanRecord PackmlScenarioRunner::step()
{
    m_lastFailures.clear();
    const auto found = m_byScan.find(m_simulator.scanCount() + 1);
    const std::vector<const ScenarioAction*> none;
    const std::vector<const ScenarioAction*>& actions = found != m_byScan.end() ? found->second : none;
    bool command = false, mode = false;
    for (const ScenarioAction* action : actions) {
        if (action->isExpectation())
            continue;
        apply(*action);
        command = command || action->kind == ActionKind::Command;
        mode = mode || action->kind == ActionKind::Mode;
    }
    const PackmlScanRecord record = m_simulator.scan();
    // The request rose for this scan only: FALSE again for the next one.
    if (command)
        m_simulator.setInput(kCommandRequest.edgeTag, false);
    if (mode)
        m_simulator.setInput(kModeRequest.edgeTag, false);
    for (const ScenarioAction* action : actions)
        if (action->isExpectation() && !m_simulator.fault()) // a scan that faulted did not finish
            check(*action, record);
    m_failures.insert(m_failures.end(), m_lastFailures.begin(), m_lastFailures.end());
    return record;
}

PackmlScenarioRunResult runPackmlScenario(const Scenario& scenario, PackmlSimulator& simulator, std::int64_t scans)
{
    // A scenario starts from the program's start state with every Complete from its skeleton.
    simulator.reset();
    for (std::size_t i = 0; i < simulator.program().instances.size(); ++i)
        if (simulator.program().instances[i].isSkeleton())
            simulator.setManualComplete(static_cast<int>(i), std::nullopt);
    PackmlScenarioRunResult result;
    PackmlScenarioRunner runner(scenario, simulator);
    const std::int64_t count = scans > 0 ? scans : scenario.lastScan();
    for (std::int64_t i = 0; i < count && !simulator.fault(); ++i)
        result.records.push_back(runner.step());
    result.failures = runner.failures();
    result.fault = simulator.fault();
    return result;
}

} // namespace core::packml
