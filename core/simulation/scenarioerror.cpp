#include "core/simulation/scenarioerror.h"

#include "core/simulation/scenario.h"

namespace core {

namespace {

using ErrorKind = ScenarioError::Kind;

std::string quote(const std::string& text)
{
    return "'" + text + "'";
}

// What a syntax error expected; empty for the other kinds.
std::string expectation(ErrorKind kind)
{
    switch (kind) {
    case ErrorKind::ExpectedAt: return "'at SCAN:' at the start of the line";
    case ErrorKind::ExpectedScanNumber: return "a scan number after 'at'";
    case ErrorKind::ExpectedColon: return "':' after the scan number";
    case ErrorKind::ExpectedSetOrExpect: return "'set' or 'expect'";
    case ErrorKind::ExpectedSetItem: return "a variable name or 'complete STEP'";
    case ErrorKind::ExpectedStepAfterComplete: return "a step id after 'complete'";
    case ErrorKind::ExpectedStepAfterStep: return "a step id after 'step'";
    case ErrorKind::ExpectedTransition: return "a transition id or 'none' after 'fired'";
    case ErrorKind::ExpectedToken: return "a token name after 'token'";
    case ErrorKind::ExpectedVariable: return "a variable name after 'variable'";
    case ErrorKind::ExpectedExpectItem: return "step, fired, token, variable, entry, complete or nested after 'expect'";
    case ErrorKind::ExpectedStepAfterNested: return "a step id after 'nested'";
    case ErrorKind::ExpectedNestedItem: return "'steps' or 'unstable' after the step id";
    case ErrorKind::ExpectedStepNumber: return "a step number";
    case ErrorKind::ExpectedEqualsAfterStep: return "'=' after the step id";
    case ErrorKind::ExpectedEqualsAfterVariable: return "'=' after the variable name";
    case ErrorKind::ExpectedEqualsAfterToken: return "'=' after the token name";
    case ErrorKind::ExpectedEqualsAfterEntry: return "'=' after 'entry'";
    case ErrorKind::ExpectedValue: return "a value after '='";
    case ErrorKind::ExpectedBool: return "TRUE or FALSE";
    case ErrorKind::ExpectedCompleteValue: return "TRUE, FALSE or auto";
    case ErrorKind::ExpectedCommaOrEnd: return "',' or the end of the line";
    case ErrorKind::ExpectedEnd: return "the end of the line";
    case ErrorKind::ExpectedCommand: return "a command name after 'command'";
    case ErrorKind::ExpectedMode: return "a mode name or number after 'mode'";
    case ErrorKind::ExpectedState: return "a state name after 'state'";
    case ErrorKind::ExpectedFaultTarget: return "a sensor or component name after 'fault'";
    case ErrorKind::ExpectedFaultKind: return "stuck, flicker, jam or clear after the name";
    default: return {};
    }
}

machine::FaultRefusal faultRefusal(const ScenarioError& e)
{
    using Refusal = machine::FaultRefusal::Kind;
    machine::FaultRefusal refusal{Refusal::UnknownTarget, e.subject, e.detail};
    switch (e.kind) {
    case ErrorKind::FaultOnOperatorInput: refusal.kind = Refusal::OperatorInput; break;
    case ErrorKind::FaultNotMachineSensor: refusal.kind = Refusal::NotMachineSensor; break;
    case ErrorKind::FaultUnknownComponent: refusal.kind = Refusal::UnknownComponent; break;
    case ErrorKind::FaultCannotJam: refusal.kind = Refusal::CannotJam; break;
    default: break;
    }
    return refusal;
}

std::string otherText(const ScenarioError& e)
{
    switch (e.kind) {
    case ErrorKind::ScanBelowOne: return "scans are numbered from 1";
    case ErrorKind::ScanTooLarge:
        return "scan number " + e.subject + " is too large: a scenario runs at most "
            + std::to_string(kMaxScenarioScan) + " scans";
    case ErrorKind::UnknownVariable: return "unknown variable " + quote(e.subject);
    case ErrorKind::InvalidValue: return e.subject + " is " + e.type + ": " + e.detail;
    case ErrorKind::HiddenStep: return "step " + e.subject + " is hidden: it does not exist for the simulator";
    case ErrorKind::UnknownStep: return "unknown step " + quote(e.subject);
    case ErrorKind::SimpleStep: return "step " + e.subject + " is a simple step: it has no Complete";
    case ErrorKind::IneffectiveTransition:
        return "transition " + e.subject + " is not effective (it or one of its steps is hidden)";
    case ErrorKind::UnknownTransition: return "unknown transition " + quote(e.subject);
    case ErrorKind::UnknownToken: return "unknown token " + quote(e.subject);
    case ErrorKind::NotAnInput:
        return e.subject + " is an " + e.detail + " variable: the program writes it, a scenario sets only inputs";
    case ErrorKind::MachineSensor:
        return e.subject + " is a sensor of the machine's " + e.detail
            + ": the machine sets it; set it by hand in open loop only";
    case ErrorKind::FaultInOpenLoop:
        return "a fault needs the virtual machine: run the scenario in closed loop, on a model with a machine";
    case ErrorKind::FaultOnOperatorInput:
    case ErrorKind::FaultNotMachineSensor:
    case ErrorKind::FaultUnknownComponent:
    case ErrorKind::FaultCannotJam:
    case ErrorKind::FaultUnknownTarget: return machine::toText(faultRefusal(e));
    case ErrorKind::NoGrafcet: return "step " + e.subject + " has no nested GRAFCET";
    case ErrorKind::CompleteFromGrafcet:
        return "the Complete of " + e.subject + " comes from its nested GRAFCET: it cannot be set";
    case ErrorKind::InvalidUtf8: return "invalid UTF-8: a scenario file must be UTF-8 text";
    case ErrorKind::UnknownCommand: return "unknown command " + quote(e.subject);
    case ErrorKind::UnknownMode: return "unknown unit mode " + quote(e.subject);
    case ErrorKind::UnknownState: return "unknown state " + quote(e.subject);
    case ErrorKind::UnknownInstance: return "unknown instance " + quote(e.subject);
    case ErrorKind::PackMLOnly: return quote(e.subject) + " is for PackML models only";
    case ErrorKind::NotForPackML: return quote(e.subject) + " is for GEMMA models only";
    case ErrorKind::EdgeTooSoon:
        return "a " + e.subject + " in scan " + std::to_string(e.scan) + " right after the one of line "
            + std::to_string(e.otherLine) + " is not seen: the request must be FALSE for one scan in between";
    case ErrorKind::ConflictingValue:
    case ErrorKind::ConflictingComplete:
        return (e.kind == ErrorKind::ConflictingValue ? e.subject : e.subject + "'s Complete") + " is set to two values in scan "
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
