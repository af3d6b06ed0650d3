// libFuzzer target: the scenario parser on arbitrary bytes, then validation
// and a short run on a small bottling-like program. Besides crashes and
// sanitizer reports, it checks that every position points inside its line,
// that a leading byte order mark changes nothing, and that a valid scenario
// runs exactly its last scan's number of scans.

#include "core/model/model.h"
#include "core/simulation/scenario.h"
#include "core/simulation/simulator.h"

#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace {

void expect(bool condition)
{
    if (!condition)
        std::abort();
}

void require(const core::Status& status)
{
    expect(static_cast<bool>(status));
}

// The names the seed scenarios use (tests/cli/data/bottling.json, trimmed).
core::Model bottlingModel()
{
    core::Model model;
    for (const char* name : {"Start", "Stop", "HomePosition", "AirPressureOk", "PreparationDone", "DoorClosed",
                             "CycleEnd"})
        require(model.addVariable({name, core::IecType::Bool, "", ""}));
    require(model.addVariable({"BatchSize", core::IecType::Int, "500", ""}));
    require(model.addVariable({"Temperature", core::IecType::Real, "20.0", ""}));
    require(model.setStepType("F1", core::StepType::Macro));
    require(model.setCondition("A6->A1", "HomePosition AND AirPressureOk"));
    require(model.setCondition("A1->F1", "Start AND PreparationDone AND DoorClosed"));
    require(model.setCondition("F1->A2", "NOT Stop"));
    require(model.setTokens("F1->A2", {"Stop"}));
    require(model.setCondition("A2->A1", "CycleEnd"));
    return model;
}

core::Simulator& simulator()
{
    static core::Simulator instance(bottlingModel());
    return instance;
}

// The lines as the parser numbers them, without a leading byte order mark.
std::vector<std::string_view> linesOf(std::string_view text)
{
    if (text.substr(0, 3) == "\xEF\xBB\xBF")
        text.remove_prefix(3);
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = text.find('\n', start);
        lines.push_back(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
        if (end == std::string_view::npos)
            return lines;
        start = end + 1;
    }
}

std::size_t characterCount(std::string_view line)
{
    std::size_t count = 0;
    for (char c : line)
        count += (static_cast<unsigned char>(c) & 0xC0u) != 0x80u;
    return count;
}

// Line and column name a place on a line of the text, or just past its end.
void expectInside(const std::vector<std::string_view>& lines, int line, int column)
{
    expect(line >= 1 && static_cast<std::size_t>(line) <= lines.size());
    expect(column >= 1 && static_cast<std::size_t>(column) <= characterCount(lines[static_cast<std::size_t>(line) - 1]) + 1);
}

void checkErrors(const std::vector<core::ScenarioError>& errors, const std::vector<std::string_view>& lines)
{
    int previousLine = 0;
    for (const core::ScenarioError& error : errors) {
        expectInside(lines, error.line, error.column);
        expect(error.line >= previousLine);
        previousLine = error.line;
        expect(!error.message.empty());
        expect(error.message == core::toText(error));
    }
}

bool sameActions(const std::vector<core::ScenarioAction>& a, const std::vector<core::ScenarioAction>& b)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].kind != b[i].kind || a[i].scan != b[i].scan || a[i].name != b[i].name || a[i].value != b[i].value
            || a[i].line != b[i].line || a[i].column != b[i].column || a[i].valueColumn != b[i].valueColumn)
            return false;
    }
    return true;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const core::ScenarioParseResult parsed = core::parseScenario(text, "fuzz.scenario");
    const std::vector<std::string_view> lines = linesOf(text);
    checkErrors(parsed.errors, lines);
    for (const core::ScenarioAction& action : parsed.scenario.actions) {
        expectInside(lines, action.line, action.column);
        expect(action.scan >= 1);
    }

    // A byte order mark is invisible: same actions, same errors.
    if (text.substr(0, 3) != "\xEF\xBB\xBF") {
        const core::ScenarioParseResult marked = core::parseScenario("\xEF\xBB\xBF" + std::string(text), "fuzz.scenario");
        expect(marked.errors == parsed.errors);
        expect(sameActions(marked.scenario.actions, parsed.scenario.actions));
    }

    if (!parsed.ok())
        return 0;
    const std::vector<core::ScenarioError> invalid = core::validateScenario(parsed.scenario, simulator());
    checkErrors(invalid, lines);
    // Runs stay short: a scan number may be as large as 10^12.
    if (!invalid.empty() || parsed.scenario.lastScan() > 64)
        return 0;
    const core::ScenarioRunResult run = core::runScenario(parsed.scenario, simulator());
    expect(static_cast<std::int64_t>(run.records.size()) == parsed.scenario.lastScan());
    for (const core::ScenarioFailure& failure : run.failures) {
        expect(failure.scan >= 1 && failure.scan <= parsed.scenario.lastScan());
        expect(!core::toText(failure).empty());
    }
    return 0;
}
