#include "core/simulation/scenarioerror.h"

#include "core/simulation/scenario.h"

namespace core {

namespace {

using Kind = ScenarioError::Kind;

std::string quote(const std::string& text)
{
    return "'" + text + "'";
}

// What a syntax error expected; empty for the other kinds.
std::string expectation(Kind kind)
{
    switch (kind) {
    case Kind::ExpectedAt: return "'at SCAN:' at the start of the line";
    case Kind::ExpectedScanNumber: return "a scan number after 'at'";
    case Kind::ExpectedColon: return "':' after the scan number";
    case Kind::ExpectedSetOrExpect: return "'set' or 'expect'";
    case Kind::ExpectedSetItem: return "a variable name or 'complete STEP'";
    case Kind::ExpectedStepAfterComplete: return "a step id after 'complete'";
    case Kind::ExpectedStepAfterStep: return "a step id after 'step'";
    case Kind::ExpectedTransition: return "a transition id or 'none' after 'fired'";
    case Kind::ExpectedToken: return "a token name after 'token'";
    case Kind::ExpectedVariable: return "a variable name after 'variable'";
    case Kind::ExpectedExpectItem: return "step, fired, token, variable, entry, complete or nested after 'expect'";
    case Kind::ExpectedStepAfterNested: return "a step id after 'nested'";
    case Kind::ExpectedNestedItem: return "'steps' or 'unstable' after the step id";
    case Kind::ExpectedStepNumber: return "a step number";
    case Kind::ExpectedEqualsAfterStep: return "'=' after the step id";
    case Kind::ExpectedEqualsAfterVariable: return "'=' after the variable name";
    case Kind::ExpectedEqualsAfterToken: return "'=' after the token name";
    case Kind::ExpectedEqualsAfterEntry: return "'=' after 'entry'";
    case Kind::ExpectedValue: return "a value after '='";
    case Kind::ExpectedBool: return "TRUE or FALSE";
    case Kind::ExpectedCompleteValue: return "TRUE, FALSE or auto";
    case Kind::ExpectedCommaOrEnd: return "',' or the end of the line";
    case Kind::ExpectedEnd: return "the end of the line";
    case Kind::ExpectedCommand: return "a command name after 'command'";
    case Kind::ExpectedMode: return "a mode name or number after 'mode'";
    case Kind::ExpectedState: return "a state name after 'state'";
    default: return {};
    }
}

std::string otherText(const ScenarioError& e)
{
    switch (e.kind) {
    case Kind::ScanBelowOne: return "scans are numbered from 1";
    case Kind::ScanTooLarge:
        return "scan number " + e.subject + " is too large: a scenario runs at most "
            + std::to_string(kMaxScenarioScan) + " scans";
    case Kind::UnknownVariable: return "unknown variable " + quote(e.subject);
    case Kind::InvalidValue: return e.subject + " is " + e.type + ": " + e.detail;
    case Kind::HiddenStep: return "step " + e.subject + " is hidden: it does not exist for the simulator";
    case Kind::UnknownStep: return "unknown step " + quote(e.subject);
    case Kind::SimpleStep: return "step " + e.subject + " is a simple step: it has no Complete";
    case Kind::IneffectiveTransition:
        return "transition " + e.subject + " is not effective (it or one of its steps is hidden)";
    case Kind::UnknownTransition: return "unknown transition " + quote(e.subject);
    case Kind::UnknownToken: return "unknown token " + quote(e.subject);
    case Kind::NotAnInput:
        return e.subject + " is an " + e.detail + " variable: the program writes it, a scenario sets only inputs";
    case Kind::NoGrafcet: return "step " + e.subject + " has no nested GRAFCET";
    case Kind::CompleteFromGrafcet:
        return "the Complete of " + e.subject + " comes from its nested GRAFCET: it cannot be set";
    case Kind::InvalidUtf8: return "invalid UTF-8: a scenario file must be UTF-8 text";
    case Kind::UnknownCommand: return "unknown command " + quote(e.subject);
    case Kind::UnknownMode: return "unknown unit mode " + quote(e.subject);
    case Kind::UnknownState: return "unknown state " + quote(e.subject);
    case Kind::UnknownInstance: return "unknown instance " + quote(e.subject);
    case Kind::PackMLOnly: return quote(e.subject) + " is for PackML models only";
    case Kind::NotForPackML: return quote(e.subject) + " is for GEMMA models only";
    case Kind::EdgeTooSoon:
        return "a " + e.subject + " in scan " + std::to_string(e.scan) + " right after the one of line "
            + std::to_string(e.otherLine) + " is not seen: the request must be FALSE for one scan in between";
    case Kind::ConflictingValue:
    case Kind::ConflictingComplete:
        return (e.kind == Kind::ConflictingValue ? e.subject : e.subject + "'s Complete") + " is set to two values in scan "
            + std::to_string(e.scan) + ": " + e.otherValue + " on line " + std::to_string(e.otherLine) + ", "
            + e.found + " on line " + std::to_string(e.line);
    default: return {};
    }
}

} // namespace

std::string toText(const ScenarioError& error)
{
    const std::string expected = expectation(error.kind);
    if (expected.empty())
        return otherText(error);
    return "expected " + expected + ", found " + (error.found.empty() ? "the end of the line" : quote(error.found));
}

std::string ScenarioError::toString() const
{
    std::string text = fileName.empty() ? std::string("scenario") : fileName;
    text += ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message;
    return text;
}

} // namespace core
