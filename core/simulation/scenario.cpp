#include "core/simulation/scenario.h"

#include "core/formats/fileio.h"
#include "core/machine/machineloop.h"
#include "core/templates/gemma/gemmatemplate.h"
#include "core/model/iectypes.h"

#include <algorithm>
#include <charconv>
#include <utility>

namespace core {

namespace {

// "6, 8, 10" (ascending), "none" for no step.
std::string nestedStepsText(std::vector<int> numbers)
{
    std::sort(numbers.begin(), numbers.end());
    numbers.erase(std::unique(numbers.begin(), numbers.end()), numbers.end());
    std::string text;
    for (int number : numbers)
        text += (text.empty() ? "" : ", ") + std::to_string(number);
    return text.empty() ? "none" : text;
}


// A word or one of the punctuation marks , = : of a scenario line.
struct Word {
    std::string_view text;
    int column = 0; // 1-based
};

bool isSeparator(char c)
{
    return c == ',' || c == '=' || c == ':';
}

bool isSpace(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

bool isContinuationByte(char c)
{
    return (static_cast<unsigned char>(c) & 0xC0u) == 0x80u;
}

// Columns count characters (UTF-8 code points), as core::textPosition and
// editors do, not bytes.
std::vector<Word> splitLine(std::string_view line)
{
    std::vector<Word> words;
    std::size_t i = 0;
    int column = 1; // of line[i]
    const auto advance = [&] {
        ++i;
        if (i >= line.size() || !isContinuationByte(line[i]))
            ++column;
    };
    while (i < line.size()) {
        const char c = line[i];
        if (c == '#')
            break;
        if (isSpace(c)) {
            advance();
            continue;
        }
        const std::size_t start = i;
        const int startColumn = column;
        if (isSeparator(c)) {
            advance();
        } else {
            while (i < line.size() && !isSpace(line[i]) && !isSeparator(line[i]) && line[i] != '#')
                advance();
        }
        words.push_back(Word{line.substr(start, i - start), startColumn});
    }
    return words;
}

// The column just past the last character before any comment, where an
// error about a missing word points.
int missingWordColumn(std::string_view line)
{
    const std::string_view code = line.substr(0, line.find('#'));
    const std::size_t last = code.find_last_not_of(" \t\r\f\v");
    if (last == std::string_view::npos)
        return 1;
    const std::string_view used = code.substr(0, last + 1);
    const auto characters = std::count_if(used.begin(), used.end(), [](char c) { return !isContinuationByte(c); });
    return static_cast<int>(characters) + 1;
}

bool isKeyword(const Word& word, std::string_view keyword)
{
    return equalsIgnoreCase(word.text, keyword);
}

bool isPunctuation(const Word& word)
{
    return word.text.size() == 1 && isSeparator(word.text.front());
}

std::string quote(std::string_view text)
{
    return "'" + std::string(text) + "'";
}

using ErrorKind = ScenarioError::Kind;

ScenarioError makeError(const std::string& fileName, int line, int column, ErrorKind kind, std::string_view found,
                        std::string subject)
{
    ScenarioError error;
    error.fileName = fileName;
    error.line = line;
    error.column = column;
    error.kind = kind;
    error.found = std::string(found);
    error.subject = std::move(subject);
    error.message = toText(error);
    return error;
}

// Reads one line's words left to right; the first problem stops it.
class LineParser {
public:
    LineParser(std::vector<Word> words, int line, int endColumn, const std::string& fileName)
        : m_words(std::move(words)), m_line(line), m_endColumn(endColumn), m_fileName(fileName)
    {
    }

    void parse(std::vector<ScenarioAction>& actions, std::vector<ScenarioError>& errors)
    {
        if (m_words.empty())
            return;
        std::vector<ScenarioAction> parsed;
        if (!parseLine(parsed)) {
            errors.push_back(m_error);
            return;
        }
        actions.insert(actions.end(), parsed.begin(), parsed.end());
    }

private:
    bool atEnd() const { return m_next >= m_words.size(); }
    int column() const { return atEnd() ? m_endColumn : m_words[m_next].column; }
    std::string_view found() const { return atEnd() ? std::string_view() : m_words[m_next].text; }

    bool fail(ErrorKind kind, std::string subject = {})
    {
        m_error = makeError(m_fileName, m_line, column(), kind, found(), std::move(subject));
        return false;
    }

    bool accept(std::string_view keyword)
    {
        if (atEnd() || !isKeyword(m_words[m_next], keyword))
            return false;
        ++m_next;
        return true;
    }

    bool name(ErrorKind missing, Word& word)
    {
        if (atEnd() || isPunctuation(m_words[m_next]))
            return fail(missing);
        word = m_words[m_next++];
        return true;
    }

    bool expect(char mark, ErrorKind missing)
    {
        if (atEnd() || m_words[m_next].text != std::string_view(&mark, 1))
            return fail(missing);
        ++m_next;
        return true;
    }

    // missingEquals: the error when the '=' before the value is missing.
    bool value(ErrorKind missingEquals, ScenarioAction& action)
    {
        if (!expect('=', missingEquals))
            return false;
        Word word;
        if (!name(ErrorKind::ExpectedValue, word))
            return false;
        action.value = std::string(word.text);
        action.valueColumn = word.column;
        return true;
    }

    bool boolValue(ErrorKind missingEquals, ScenarioAction& action)
    {
        if (!value(missingEquals, action))
            return false;
        if (!equalsIgnoreCase(action.value, "TRUE") && !equalsIgnoreCase(action.value, "FALSE")) {
            --m_next;
            return fail(ErrorKind::ExpectedBool);
        }
        action.value = toUpperAscii(action.value);
        return true;
    }

    bool endOfLine()
    {
        if (!atEnd())
            return fail(ErrorKind::ExpectedEnd);
        return true;
    }

    ScenarioAction makeAction(ScenarioAction::Kind kind, const Word& at) const
    {
        ScenarioAction action;
        action.kind = kind;
        action.scan = m_scan;
        action.line = m_line;
        action.column = at.column;
        return action;
    }

    bool parseLine(std::vector<ScenarioAction>& actions)
    {
        if (!accept("at"))
            return fail(ErrorKind::ExpectedAt);
        if (!scanNumber())
            return false;
        if (!expect(':', ErrorKind::ExpectedColon))
            return false;
        if (accept("set"))
            return parseSet(actions);
        if (accept("expect"))
            return parseExpect(actions);
        if (accept("command"))
            return parseNamed(ScenarioAction::Kind::Command, ErrorKind::ExpectedCommand, actions) && endOfLine();
        if (accept("mode"))
            return parseNamed(ScenarioAction::Kind::Mode, ErrorKind::ExpectedMode, actions) && endOfLine();
        if (accept("fault"))
            return parseFault(actions) && endOfLine();
        return fail(ErrorKind::ExpectedSetOrExpect);
    }

    // fault TARGET stuck TRUE|FALSE | flicker | jam | clear
    bool parseFault(std::vector<ScenarioAction>& actions)
    {
        Word target;
        if (!name(ErrorKind::ExpectedFaultTarget, target))
            return false;
        ScenarioAction action = makeAction(ScenarioAction::Kind::Fault, target);
        action.name = std::string(target.text);
        action.valueColumn = column();
        if (accept("stuck")) {
            if (atEnd() || !(isKeyword(m_words[m_next], "TRUE") || isKeyword(m_words[m_next], "FALSE")))
                return fail(ErrorKind::ExpectedBool);
            const bool stuckTrue = isKeyword(m_words[m_next++], "TRUE");
            action.value = machine::faultKindText(stuckTrue ? machine::FaultKind::StuckTrue : machine::FaultKind::StuckFalse);
        } else if (accept("flicker")) {
            action.value = machine::faultKindText(machine::FaultKind::Flicker);
        } else if (accept("jam")) {
            action.value = machine::faultKindText(machine::FaultKind::Jam);
        } else if (accept("clear")) {
            action.value = machine::faultKindText(machine::FaultKind::Clear);
        } else {
            return fail(ErrorKind::ExpectedFaultKind);
        }
        actions.push_back(std::move(action));
        return true;
    }

    bool scanNumber()
    {
        if (atEnd() || isPunctuation(m_words[m_next]))
            return fail(ErrorKind::ExpectedScanNumber);
        const std::string_view text = m_words[m_next].text;
        std::int64_t number = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
        const bool whole = end == text.data() + text.size() && text.front() != '-' && text.front() != '+';
        if (error == std::errc::result_out_of_range && whole)
            return fail(ErrorKind::ScanTooLarge, std::string(text));
        if (error != std::errc() || !whole)
            return fail(ErrorKind::ExpectedScanNumber);
        if (number < 1)
            return fail(ErrorKind::ScanBelowOne);
        if (number > kMaxScenarioScan)
            return fail(ErrorKind::ScanTooLarge, std::string(text));
        m_scan = number;
        ++m_next;
        return true;
    }

    // set NAME = VALUE, complete STEP = TRUE|FALSE|auto, ...
    bool parseSet(std::vector<ScenarioAction>& actions)
    {
        do {
            Word word;
            if (!name(ErrorKind::ExpectedSetItem, word))
                return false;
            if (isKeyword(word, "complete")) {
                Word step;
                if (!name(ErrorKind::ExpectedStepAfterComplete, step))
                    return false;
                ScenarioAction action = makeAction(ScenarioAction::Kind::SetComplete, step);
                action.name = std::string(step.text);
                if (!value(ErrorKind::ExpectedEqualsAfterStep, action))
                    return false;
                if (equalsIgnoreCase(action.value, "auto") || equalsIgnoreCase(action.value, "automatic")) {
                    action.kind = ScenarioAction::Kind::SetCompleteAuto;
                    action.value = "auto";
                } else if (equalsIgnoreCase(action.value, "TRUE") || equalsIgnoreCase(action.value, "FALSE")) {
                    action.value = toUpperAscii(action.value);
                } else {
                    --m_next;
                    return fail(ErrorKind::ExpectedCompleteValue);
                }
                actions.push_back(std::move(action));
            } else {
                ScenarioAction action = makeAction(ScenarioAction::Kind::SetVariable, word);
                action.name = std::string(word.text);
                if (!value(ErrorKind::ExpectedEqualsAfterVariable, action))
                    return false;
                actions.push_back(std::move(action));
            }
            if (atEnd())
                return true;
            if (m_words[m_next].text != ",")
                return fail(ErrorKind::ExpectedCommaOrEnd);
            ++m_next;
        } while (true);
    }

    bool parseExpect(std::vector<ScenarioAction>& actions)
    {
        using Kind = ScenarioAction::Kind;
        const Word keyword = atEnd() ? Word{{}, m_endColumn} : m_words[m_next];
        Word word;
        if (accept("step")) {
            if (!name(ErrorKind::ExpectedStepAfterStep, word))
                return false;
            ScenarioAction action = makeAction(Kind::ExpectStep, word);
            action.name = std::string(word.text);
            actions.push_back(std::move(action));
        } else if (accept("fired")) {
            if (!name(ErrorKind::ExpectedTransition, word))
                return false;
            const bool none = isKeyword(word, "none");
            ScenarioAction action = makeAction(none ? Kind::ExpectNoFiring : Kind::ExpectFired, word);
            if (!none)
                action.name = std::string(word.text);
            actions.push_back(std::move(action));
        } else if (accept("token")) {
            if (!name(ErrorKind::ExpectedToken, word))
                return false;
            ScenarioAction action = makeAction(Kind::ExpectToken, word);
            action.name = std::string(word.text);
            if (!boolValue(ErrorKind::ExpectedEqualsAfterToken, action))
                return false;
            actions.push_back(std::move(action));
        } else if (accept("variable")) {
            if (!name(ErrorKind::ExpectedVariable, word))
                return false;
            ScenarioAction action = makeAction(Kind::ExpectVariable, word);
            action.name = std::string(word.text);
            if (!value(ErrorKind::ExpectedEqualsAfterVariable, action))
                return false;
            actions.push_back(std::move(action));
        } else if (accept("entry")) {
            ScenarioAction action = makeAction(Kind::ExpectEntry, keyword);
            if (!boolValue(ErrorKind::ExpectedEqualsAfterEntry, action))
                return false;
            actions.push_back(std::move(action));
        } else if (accept("complete")) {
            if (!name(ErrorKind::ExpectedStepAfterComplete, word))
                return false;
            ScenarioAction action = makeAction(Kind::ExpectComplete, word);
            action.name = std::string(word.text);
            if (!boolValue(ErrorKind::ExpectedEqualsAfterStep, action))
                return false;
            actions.push_back(std::move(action));
        } else if (accept("nested")) {
            if (!parseNested(actions))
                return false;
        } else if (accept("state")) {
            if (!parseNamed(Kind::ExpectState, ErrorKind::ExpectedState, actions))
                return false;
        } else if (accept("mode")) {
            if (!parseNamed(Kind::ExpectMode, ErrorKind::ExpectedMode, actions))
                return false;
        } else {
            return fail(ErrorKind::ExpectedExpectItem);
        }
        return endOfLine();
    }

    // One name: command NAME, mode NAME, expect state NAME, expect mode NAME.
    bool parseNamed(ScenarioAction::Kind kind, ErrorKind missing, std::vector<ScenarioAction>& actions)
    {
        Word word;
        if (!name(missing, word))
            return false;
        ScenarioAction action = makeAction(kind, word);
        action.name = std::string(word.text);
        actions.push_back(std::move(action));
        return true;
    }

    // nested STEP steps 6, 8, 10 | nested STEP unstable = TRUE|FALSE
    bool parseNested(std::vector<ScenarioAction>& actions)
    {
        using Kind = ScenarioAction::Kind;
        Word step;
        if (!name(ErrorKind::ExpectedStepAfterNested, step))
            return false;
        if (accept("unstable")) {
            ScenarioAction action = makeAction(Kind::ExpectUnstable, step);
            action.name = std::string(step.text);
            if (!boolValue(ErrorKind::ExpectedEqualsAfterStep, action))
                return false;
            actions.push_back(std::move(action));
            return true;
        }
        if (!accept("steps"))
            return fail(ErrorKind::ExpectedNestedItem);
        ScenarioAction action = makeAction(Kind::ExpectNestedSteps, step);
        action.name = std::string(step.text);
        std::vector<int> numbers;
        do {
            Word number;
            if (!name(ErrorKind::ExpectedStepNumber, number))
                return false;
            const std::string text(number.text);
            if (text.empty() || text.size() > 6 || !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; })) {
                --m_next;
                return fail(ErrorKind::ExpectedStepNumber);
            }
            numbers.push_back(std::stoi(text));
        } while (accept(","));
        action.value = nestedStepsText(numbers);
        actions.push_back(std::move(action));
        return true;
    }

    std::vector<Word> m_words;
    std::size_t m_next = 0;
    int m_line;
    int m_endColumn;
    const std::string& m_fileName;
    std::int64_t m_scan = 0;
    ScenarioError m_error;
};

// --- Validation -----------------------------------------------------------------

const GemmaStep* findStep(const GemmaProgram& program, std::string_view id)
{
    for (const GemmaStep& step : program.steps) {
        if (equalsIgnoreCase(step.id, id))
            return &step;
    }
    return nullptr;
}

const GemmaTransition* findTransition(const GemmaProgram& program, std::string_view id)
{
    for (const GemmaStep& step : program.steps) {
        for (const GemmaTransition& transition : step.transitions) {
            if (equalsIgnoreCase(transition.id, id))
                return &transition;
        }
    }
    return nullptr;
}

bool isTemplateTransition(std::string_view id)
{
    for (const TemplateTransition& transition : templateTransitions()) {
        if (equalsIgnoreCase(makeTransitionId(transition.source, transition.target), id))
            return true;
    }
    return false;
}

// Why the simulator has no step `id`; nullopt when it has one.
std::optional<ErrorKind> stepProblem(const Simulator& simulator, std::string_view id)
{
    if (findStep(simulator.program(), id))
        return std::nullopt;
    return findTemplateState(toUpperAscii(id)) ? ErrorKind::HiddenStep : ErrorKind::UnknownStep;
}

// HiddenStep names the step in capitals, UnknownStep as written.
std::string stepSubject(ErrorKind kind, const std::string& id)
{
    return kind == ErrorKind::HiddenStep ? toUpperAscii(id) : id;
}

class Validator {
public:
    Validator(const Scenario& scenario, const Simulator& simulator, FaultLines faults)
        : m_scenario(scenario), m_simulator(simulator), m_faults(faults)
    {
    }

    std::vector<ScenarioError> run()
    {
        for (const ScenarioAction& action : m_scenario.actions)
            check(action);
        return std::move(m_errors);
    }

private:
    ScenarioError& error(const ScenarioAction& action, int column, ErrorKind kind, std::string subject)
    {
        return m_errors.emplace_back(
            makeError(m_scenario.fileName, action.line, column, kind, {}, std::move(subject)));
    }

    void stepError(const ScenarioAction& action, ErrorKind kind)
    {
        error(action, action.column, kind, stepSubject(kind, action.name));
    }

    void checkVariable(const ScenarioAction& action)
    {
        const int index = m_simulator.variableIndex(action.name);
        if (index < 0) {
            error(action, action.column, ErrorKind::UnknownVariable, action.name);
            return;
        }
        const std::string& declared = m_simulator.variableNames()[static_cast<std::size_t>(index)];
        const IecType type = iecTypeOf(index);
        const VariableKind kind = m_simulator.variableKind(static_cast<std::size_t>(index));
        if (action.kind == ScenarioAction::Kind::SetVariable && kind != VariableKind::Input) {
            ScenarioError& notInput = error(action, action.column, ErrorKind::NotAnInput, declared);
            notInput.detail = std::string(variableKindName(kind));
            notInput.message = toText(notInput);
            return;
        }
        std::optional<ValueProblem> problem = valueProblem(type, action.value);
        if (!problem) {
            if (action.kind == ScenarioAction::Kind::SetVariable)
                checkSameValue(action, index, declared, type);
            return;
        }
        ScenarioError& invalid = error(action, action.valueColumn, ErrorKind::InvalidValue, declared);
        invalid.type = std::string(iecTypeName(type));
        invalid.detail = toText(*problem);
        invalid.problem = std::move(problem);
        invalid.message = toText(invalid);
    }

    IecType iecTypeOf(int index) const
    {
        // The simulator knows the kinds; the program's types come from the model's declarations.
        return m_simulator.variableType(static_cast<std::size_t>(index));
    }

    void checkGrafcetStep(const ScenarioAction& action)
    {
        if (const std::optional<ErrorKind> problem = stepProblem(m_simulator, action.name)) {
            stepError(action, *problem);
            return;
        }
        if (!m_simulator.hasGrafcet(toUpperAscii(action.name)))
            error(action, action.column, ErrorKind::NoGrafcet, toUpperAscii(action.name));
    }

    void checkNestedStep(const ScenarioAction& action)
    {
        if (const std::optional<ErrorKind> problem = stepProblem(m_simulator, action.name)) {
            stepError(action, *problem);
            return;
        }
        const auto& nested = m_simulator.nestedSteps();
        const bool found = std::any_of(nested.begin(), nested.end(),
                                       [&](const std::string& id) { return equalsIgnoreCase(id, action.name); });
        if (!found)
            error(action, action.column, ErrorKind::SimpleStep, toUpperAscii(action.name));
        else if (action.kind != ScenarioAction::Kind::ExpectComplete && m_simulator.hasGrafcet(toUpperAscii(action.name)))
            error(action, action.column, ErrorKind::CompleteFromGrafcet, toUpperAscii(action.name));
        else if (action.kind != ScenarioAction::Kind::ExpectComplete)
            checkSameComplete(action);
    }

    // Line order within a scan does not matter, so one scan cannot set a
    // variable to two values: neither line could be said to win. The same
    // value twice is harmless and accepted. Values are compared in the
    // variable's type ("1" and "1.0" are the same REAL).
    void checkSameValue(const ScenarioAction& action, int index, const std::string& declared, IecType type)
    {
        const auto [slot, first] = m_firstSets.emplace(std::make_pair(action.scan, index), &action);
        if (first)
            return;
        const ScenarioAction& earlier = *slot->second;
        if (cond::parseValue(type, earlier.value) == cond::parseValue(type, action.value))
            return;
        conflict(action, earlier, ErrorKind::ConflictingValue, declared);
    }

    void checkSameComplete(const ScenarioAction& action)
    {
        const std::string step = toUpperAscii(action.name);
        const auto [slot, first] = m_firstCompletes.emplace(std::make_pair(action.scan, step), &action);
        if (!first && slot->second->value != action.value)
            conflict(action, *slot->second, ErrorKind::ConflictingComplete, step);
    }

    void conflict(const ScenarioAction& action, const ScenarioAction& earlier, ErrorKind kind, std::string subject)
    {
        ScenarioError& problem = error(action, action.valueColumn, kind, std::move(subject));
        problem.found = action.value;
        problem.scan = action.scan;
        problem.otherLine = earlier.line;
        problem.otherValue = earlier.value;
        problem.message = toText(problem);
    }

    void check(const ScenarioAction& action)
    {
        using Kind = ScenarioAction::Kind;
        switch (action.kind) {
        case Kind::SetVariable:
        case Kind::ExpectVariable: checkVariable(action); break;
        case Kind::SetComplete:
        case Kind::SetCompleteAuto:
        case Kind::ExpectComplete: checkNestedStep(action); break;
        case Kind::ExpectNestedSteps:
        case Kind::ExpectUnstable: checkGrafcetStep(action); break;
        case Kind::ExpectStep:
            if (const std::optional<ErrorKind> problem = stepProblem(m_simulator, action.name))
                stepError(action, *problem);
            break;
        case Kind::ExpectFired:
            if (!findTransition(m_simulator.program(), action.name)) {
                error(action, action.column,
                      isTemplateTransition(action.name) ? ErrorKind::IneffectiveTransition
                                                        : ErrorKind::UnknownTransition,
                      action.name);
            }
            break;
        case Kind::ExpectToken: {
            const auto& names = m_simulator.tokenNames();
            const bool found = std::any_of(names.begin(), names.end(),
                                           [&](const std::string& n) { return equalsIgnoreCase(n, action.name); });
            if (!found)
                error(action, action.column, ErrorKind::UnknownToken, action.name);
            break;
        }
        case Kind::ExpectNoFiring:
        case Kind::ExpectEntry: break;
        case Kind::Fault:
            if (m_faults == FaultLines::Refused)
                error(action, action.column, ErrorKind::FaultInOpenLoop, "fault");
            break;
        case Kind::Command:
        case Kind::Mode:
        case Kind::ExpectState:
        case Kind::ExpectMode: error(action, action.column, ErrorKind::PackMLOnly, std::string(scenarioKeyword(action.kind))); break;
        }
    }

    const Scenario& m_scenario;
    const Simulator& m_simulator;
    FaultLines m_faults;
    std::vector<ScenarioError> m_errors;
    // The first set of each (scan, variable index) and (scan, step id).
    std::map<std::pair<std::int64_t, int>, const ScenarioAction*> m_firstSets;
    std::map<std::pair<std::int64_t, std::string>, const ScenarioAction*> m_firstCompletes;
};

std::string boolText(bool value)
{
    return value ? "TRUE" : "FALSE";
}

} // namespace

std::int64_t Scenario::lastScan() const
{
    std::int64_t last = 0;
    for (const ScenarioAction& action : actions)
        last = std::max(last, action.scan);
    return last;
}

std::string toText(const ScenarioFailure& failure)
{
    using Kind = ScenarioFailure::Kind;
    const std::string& expected = failure.expected;
    const std::string& actual = failure.actual;
    std::string problem;
    switch (failure.kind) {
    case Kind::CannotApply: problem = "cannot apply: " + failure.detail; break;
    case Kind::WrongStep: problem = "expected step " + expected + ", active step is " + actual; break;
    case Kind::NoVisibleStep:
        problem = "expected step " + expected + ", active step is none (State = " + actual + " names no visible step)";
        break;
    case Kind::NothingFired: problem = "expected " + expected + " to fire, no transition fired"; break;
    case Kind::WrongFiring: problem = "expected " + expected + " to fire, " + actual + " fired"; break;
    case Kind::UnexpectedFiring: problem = "expected no transition to fire, " + actual + " fired"; break;
    case Kind::WrongToken:
        problem = "expected token " + failure.subject + " = " + expected + ", it is " + actual;
        break;
    case Kind::WrongVariable: problem = "expected " + failure.subject + " = " + expected + ", it is " + actual; break;
    case Kind::UnknownVariable: problem = "unknown variable " + quote(failure.subject); break;
    case Kind::WrongEntry: problem = "expected Entry = " + expected + ", it is " + actual; break;
    case Kind::WrongComplete:
        problem = "expected " + failure.subject + ".Complete = " + expected + ", it is " + actual;
        break;
    case Kind::WrongNestedSteps:
        problem = "expected the active steps of " + failure.subject + " to be " + expected + ", they are " + actual;
        break;
    case Kind::WrongUnstable:
        problem = "expected " + failure.subject + ".Unstable = " + expected + ", it is " + actual;
        break;
    }
    return "scan " + std::to_string(failure.scan) + ": " + problem;
}

ScenarioParseResult parseScenario(std::string_view text, std::string fileName)
{
    ScenarioParseResult result;
    result.scenario.fileName = fileName;
    // Not text in the one encoding scenarios use: one error at the first bad
    // byte, rather than a line-by-line cascade.
    if (const std::optional<Utf8Problem> problem = findInvalidUtf8(text)) {
        result.errors.push_back(makeError(result.scenario.fileName, static_cast<int>(problem->position.line),
                                          static_cast<int>(problem->position.column), ErrorKind::InvalidUtf8, {}, {}));
        return result;
    }
    // Editors on Windows write a byte order mark; it is no part of line 1.
    if (text.substr(0, 3) == "\xEF\xBB\xBF")
        text.remove_prefix(3);
    int lineNumber = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos)
            end = text.size();
        const std::string_view line = text.substr(start, end - start);
        ++lineNumber;
        LineParser(splitLine(line), lineNumber, missingWordColumn(line), result.scenario.fileName)
            .parse(result.scenario.actions, result.errors);
        if (end == text.size())
            break;
        start = end + 1;
    }
    return result;
}

std::vector<ScenarioError> validateScenario(const Scenario& scenario, const Simulator& simulator, FaultLines faults)
{
    return Validator(scenario, simulator, faults).run();
}

std::optional<machine::Fault> scenarioFault(const ScenarioAction& action)
{
    if (action.kind != ScenarioAction::Kind::Fault)
        return std::nullopt;
    const std::optional<machine::FaultKind> kind = machine::parseFaultKind(action.value);
    if (!kind)
        return std::nullopt;
    return machine::Fault{*kind, action.name};
}

// --- Running --------------------------------------------------------------------

ScenarioRunner::ScenarioRunner(const Scenario& scenario, Simulator& simulator)
    : m_scenario(scenario), m_simulator(simulator)
{
    for (const ScenarioAction& action : m_scenario.actions)
        m_byScan[action.scan].push_back(&action);
}

ScenarioRunner::ScenarioRunner(const Scenario& scenario, machine::MachineLoop& loop)
    : ScenarioRunner(scenario, loop.simulator())
{
    m_loop = &loop;
}

Status ScenarioRunner::applyFault(const ScenarioAction& action)
{
    const std::optional<machine::Fault> fault = scenarioFault(action);
    if (!m_loop || !fault)
        return Status::failure("fault", "a fault needs the virtual machine: run the scenario in closed loop");
    if (const std::optional<machine::FaultRefusal> refusal = m_loop->checkFault(*fault))
        return Status::failure("fault", machine::toText(*refusal));
    m_loop->applyFault(*fault);
    return Status::success();
}

void ScenarioRunner::apply(const ScenarioAction& action)
{
    using Kind = ScenarioAction::Kind;
    Status status;
    switch (action.kind) {
    case Kind::SetVariable: status = m_simulator.setVariableText(action.name, action.value); break;
    case Kind::SetComplete:
        status = m_simulator.setCompleteMode(action.name, CompleteMode::Manual);
        if (status)
            status = m_simulator.setComplete(action.name, action.value == "TRUE");
        break;
    case Kind::SetCompleteAuto: status = m_simulator.setCompleteMode(action.name, CompleteMode::Automatic); break;
    case Kind::Fault: status = applyFault(action); break;
    default: return;
    }
    if (!status) {
        ScenarioFailure failure;
        failure.scan = m_simulator.scanCount() + 1;
        failure.line = action.line;
        failure.kind = ScenarioFailure::Kind::CannotApply;
        failure.subject = action.name;
        failure.detail = status.message;
        m_lastFailures.push_back(std::move(failure));
    }
}

void ScenarioRunner::check(const ScenarioAction& action, const ScanRecord& record)
{
    using Kind = ScenarioAction::Kind;
    using Failure = ScenarioFailure::Kind;
    ScenarioFailure failure;
    failure.scan = record.scan;
    failure.line = action.line;
    switch (action.kind) {
    case Kind::ExpectStep:
        if (equalsIgnoreCase(record.stepAfter, action.name))
            return;
        failure.kind = record.stepAfter.empty() ? Failure::NoVisibleStep : Failure::WrongStep;
        failure.expected = toUpperAscii(action.name);
        failure.actual =
            record.stepAfter.empty() ? std::to_string(m_simulator.activeStepNumber()) : record.stepAfter;
        break;
    case Kind::ExpectFired:
        if (equalsIgnoreCase(record.fired, action.name))
            return;
        failure.kind = record.fired.empty() ? Failure::NothingFired : Failure::WrongFiring;
        failure.expected = action.name;
        failure.actual = record.fired;
        break;
    case Kind::ExpectNoFiring:
        if (record.fired.empty())
            return;
        failure.kind = Failure::UnexpectedFiring;
        failure.actual = record.fired;
        break;
    case Kind::ExpectToken: {
        const bool actual = m_simulator.token(action.name);
        if (boolText(actual) == action.value)
            return;
        failure.kind = Failure::WrongToken;
        failure.subject = action.name;
        failure.expected = action.value;
        failure.actual = boolText(actual);
        break;
    }
    case Kind::ExpectVariable: {
        const int index = m_simulator.variableIndex(action.name);
        if (index < 0) {
            failure.kind = Failure::UnknownVariable;
            failure.subject = action.name;
            break;
        }
        const std::optional<cond::Value> expected =
            cond::parseValue(m_simulator.variableType(static_cast<std::size_t>(index)), action.value);
        const cond::Value actual = m_simulator.variableValue(static_cast<std::size_t>(index));
        if (expected && *expected == actual)
            return;
        failure.kind = Failure::WrongVariable;
        failure.subject = m_simulator.variableNames()[static_cast<std::size_t>(index)];
        failure.expected = action.value;
        failure.actual = cond::formatValue(actual);
        break;
    }
    case Kind::ExpectEntry:
        if (boolText(record.entry) == action.value)
            return;
        failure.kind = Failure::WrongEntry;
        failure.expected = action.value;
        failure.actual = boolText(record.entry);
        break;
    case Kind::ExpectComplete: {
        const bool actual = m_simulator.complete(action.name);
        if (boolText(actual) == action.value)
            return;
        failure.kind = Failure::WrongComplete;
        failure.subject = toUpperAscii(action.name);
        failure.expected = action.value;
        failure.actual = boolText(actual);
        break;
    }
    case Kind::ExpectNestedSteps: {
        const std::string actual = nestedStepsText(m_simulator.activeNestedSteps(toUpperAscii(action.name)));
        if (actual == action.value)
            return;
        failure.kind = Failure::WrongNestedSteps;
        failure.subject = toUpperAscii(action.name);
        failure.expected = action.value;
        failure.actual = actual;
        break;
    }
    case Kind::ExpectUnstable: {
        const bool actual = m_simulator.unstable(toUpperAscii(action.name));
        if (boolText(actual) == action.value)
            return;
        failure.kind = Failure::WrongUnstable;
        failure.subject = toUpperAscii(action.name);
        failure.expected = action.value;
        failure.actual = boolText(actual);
        break;
    }
    default: return;
    }
    m_lastFailures.push_back(std::move(failure));
}

ScanRecord ScenarioRunner::step()
{
    m_lastFailures.clear();
    const std::int64_t scan = m_simulator.scanCount() + 1;
    auto found = m_byScan.find(scan);
    if (found != m_byScan.end()) {
        for (const ScenarioAction* action : found->second) {
            if (!action->isExpectation())
                apply(*action);
        }
    }
    ScanRecord record = m_simulator.step();
    if (found != m_byScan.end() && !m_simulator.fault()) { // a scan that faulted did not finish
        for (const ScenarioAction* action : found->second) {
            if (action->isExpectation())
                check(*action, record);
        }
    }
    if (m_loop && !m_skipCycle)
        m_loop->afterScan();
    m_skipCycle = false;
    m_failures.insert(m_failures.end(), m_lastFailures.begin(), m_lastFailures.end());
    return record;
}

namespace {

// A scenario starts from the program's start state with every Complete automatic.
void makeCompleteAutomatic(Simulator& simulator)
{
    for (const std::string& step : simulator.nestedSteps()) {
        simulator.setCompleteMode(step, CompleteMode::Automatic);
        simulator.setComplete(step, false);
    }
}

ScenarioRunResult runFromStart(const Scenario& scenario, ScenarioRunner& runner, Simulator& simulator,
                               std::int64_t scans)
{
    ScenarioRunResult result;
    const std::int64_t count = scans > 0 ? scans : scenario.lastScan();
    for (std::int64_t i = 0; i < count && !simulator.fault(); ++i)
        result.records.push_back(runner.step());
    result.failures = runner.failures();
    result.fault = simulator.fault();
    return result;
}

} // namespace

ScenarioRunResult runScenario(const Scenario& scenario, Simulator& simulator, std::int64_t scans)
{
    simulator.reset();
    makeCompleteAutomatic(simulator);
    ScenarioRunner runner(scenario, simulator);
    return runFromStart(scenario, runner, simulator, scans);
}

ScenarioRunResult runScenario(const Scenario& scenario, machine::MachineLoop& loop, std::int64_t scans)
{
    makeCompleteAutomatic(loop.simulator());
    loop.reset();
    ScenarioRunner runner(scenario, loop);
    return runFromStart(scenario, runner, loop.simulator(), scans);
}

std::string_view scenarioKeyword(ScenarioAction::Kind kind)
{
    using Kind = ScenarioAction::Kind;
    switch (kind) {
    case Kind::SetVariable: return "set";
    case Kind::SetComplete:
    case Kind::SetCompleteAuto: return "set complete";
    case Kind::Command: return "command";
    case Kind::Mode: return "mode";
    case Kind::Fault: return "fault";
    case Kind::ExpectStep: return "expect step";
    case Kind::ExpectFired:
    case Kind::ExpectNoFiring: return "expect fired";
    case Kind::ExpectToken: return "expect token";
    case Kind::ExpectVariable: return "expect variable";
    case Kind::ExpectEntry: return "expect entry";
    case Kind::ExpectComplete: return "expect complete";
    case Kind::ExpectNestedSteps:
    case Kind::ExpectUnstable: return "expect nested";
    case Kind::ExpectState: return "expect state";
    case Kind::ExpectMode: return "expect mode";
    }
    return {};
}

// --- Writing ----------------------------------------------------------------------

bool recordWorthKeeping(const ScanRecord& record, const ScanRecord* previous)
{
    if (!record.fired.empty() || !record.changedOutputs.empty())
        return true;
    if (!previous) {
        const auto any = [](const auto& list, const auto& test) { return std::any_of(list.begin(), list.end(), test); };
        return any(record.nestedActive, [](const std::vector<int>& steps) { return !steps.empty(); })
            || any(record.unstable, [](bool value) { return value; });
    }
    return record.nestedActive != previous->nestedActive || record.unstable != previous->unstable;
}

std::string writeScenario(const ScenarioRecording& recording)
{
    std::string out;
    if (!recording.title.empty()) {
        std::size_t start = 0;
        while (start <= recording.title.size()) {
            std::size_t end = recording.title.find('\n', start);
            if (end == std::string::npos)
                end = recording.title.size();
            std::string line = recording.title.substr(start, end - start);
            line.erase(std::remove(line.begin(), line.end(), '\r'), line.end());
            out += line.empty() ? "#\n" : "# " + line + "\n";
            start = end + 1;
        }
    }
    // Every line in scan order: sets of a scan, then what it did.
    std::map<std::int64_t, std::vector<std::string>> lines;
    for (const RecordedScan& scan : recording.changes) {
        const std::string at = "at " + std::to_string(scan.scan) + ": ";
        if (!scan.inputs.empty()) {
            std::string line = at + "set ";
            for (std::size_t i = 0; i < scan.inputs.size(); ++i)
                line += (i ? ", " : "") + scan.inputs[i].variable + " = " + cond::formatValue(scan.inputs[i].value);
            lines[scan.scan].push_back(std::move(line));
        }
        for (const RecordedScan::CompleteSetting& complete : scan.completes) {
            lines[scan.scan].push_back(at + "set complete " + complete.stepId + " = "
                                       + (complete.manualValue ? boolText(*complete.manualValue) : "auto"));
        }
        for (const machine::Fault& fault : scan.faults)
            lines[scan.scan].push_back(at + "fault " + machine::toText(fault));
    }
    const std::vector<std::string>& nested = recording.nestedSteps;
    std::vector<std::vector<int>> situations(nested.size());
    std::vector<bool> unstable(nested.size(), false);
    for (const ScanRecord& record : recording.records) {
        const std::string at = "at " + std::to_string(record.scan) + ": ";
        std::vector<std::string>& out = lines[record.scan];
        if (!record.fired.empty()) {
            out.push_back(at + "expect fired " + record.fired);
            if (!record.stepAfter.empty())
                out.push_back(at + "expect step " + record.stepAfter);
        }
        for (const InputChange& output : record.changedOutputs)
            out.push_back(at + "expect variable " + output.variable + " = " + cond::formatValue(output.value));
        for (std::size_t i = 0; i < nested.size(); ++i) {
            if (i < record.nestedActive.size() && record.nestedActive[i] != situations[i]) {
                situations[i] = record.nestedActive[i];
                if (!situations[i].empty()) // only power-on has no active step
                    out.push_back(at + "expect nested " + nested[i] + " steps " + nestedStepsText(situations[i]));
            }
            if (i < record.unstable.size() && record.unstable[i] != unstable[i]) {
                unstable[i] = record.unstable[i];
                out.push_back(at + "expect nested " + nested[i] + " unstable = " + boolText(unstable[i]));
            }
        }
    }
    for (const auto& [scan, texts] : lines) {
        for (const std::string& text : texts)
            out += text + "\n";
    }
    return out;
}

} // namespace core
