#pragma once

// A malformed or invalid line of a scenario file (core/simulation/scenario.h), as data:
// the editor words it in the UI language, toText() gives the English text
// the command line and tests use. Words of the file, names and values are
// kept as written: they are code in every language.

#include "core/condition/valueproblem.h"

#include <cstdint>
#include <optional>
#include <string>

namespace core {

struct ScenarioError {
    enum class Kind {
        // Syntax (parseScenario). found: the word there instead, as written;
        // empty at the end of the line.
        ExpectedAt,               // 'at SCAN:' at the start of the line
        ExpectedScanNumber,       // a scan number after 'at'
        ScanBelowOne,             // scans are numbered from 1
        ScanTooLarge,             // subject: the scan number as written
        ExpectedColon,            // ':' after the scan number
        ExpectedSetOrExpect,      // 'set' or 'expect' after the ':'
        ExpectedSetItem,          // a variable name or 'complete STEP' after 'set' or ','
        ExpectedStepAfterComplete, // a step id after 'complete'
        ExpectedStepAfterStep,    // a step id after 'step'
        ExpectedTransition,       // a transition id or 'none' after 'fired'
        ExpectedToken,            // a token name after 'token'
        ExpectedVariable,         // a variable name after 'variable'
        ExpectedExpectItem,       // step, fired, token, variable, entry or complete after 'expect'
        ExpectedEqualsAfterStep,  // '=' after the step id
        ExpectedEqualsAfterVariable, // '=' after the variable name
        ExpectedEqualsAfterToken, // '=' after the token name
        ExpectedEqualsAfterEntry, // '=' after 'entry'
        ExpectedValue,            // a value after '='
        ExpectedBool,             // TRUE or FALSE
        ExpectedCompleteValue,    // TRUE, FALSE or auto
        ExpectedCommaOrEnd,       // ',' or the end of the line
        ExpectedStepAfterNested,  // a step id after 'nested'
        ExpectedNestedItem,       // 'steps' or 'unstable' after 'nested STEP'
        ExpectedStepNumber,       // a nested step number after 'steps' or ','
        ExpectedEnd,              // the end of the line
        InvalidUtf8,              // at the first byte that is not UTF-8; the file is not read further
        ExpectedCommand,          // a command name after 'command'
        ExpectedMode,             // a mode name or number after 'mode'
        ExpectedState,            // a state name after 'state'
        ExpectedFaultTarget,      // a sensor or component name after 'fault'
        ExpectedFaultKind,        // stuck, flicker, jam or clear after the fault's target
        // Names and values (validateScenario). subject: the name, as the kind says.
        UnknownVariable,          // as written
        InvalidValue,             // the variable as declared; type: its IEC type; detail: why (English)
        HiddenStep,               // the step id in capitals
        UnknownStep,              // as written
        SimpleStep,               // the step id in capitals: it has no Complete
        IneffectiveTransition,    // as written: it or one of its steps is hidden
        UnknownTransition,        // as written
        UnknownToken,             // as written
        NotAnInput,               // the variable as declared; detail: its kind ("output", "internal")
        NoGrafcet,                // the step id in capitals: it has no nested GRAFCET
        CompleteFromGrafcet,      // the step id in capitals: its Complete comes from its GRAFCET
        UnknownCommand,           // as written: no command of the model's edition (PackML)
        UnknownMode,              // as written: no mode of the model (PackML)
        UnknownState,             // as written: no PackML state
        UnknownInstance,          // as written: no instance <Mode>_<State> (PackML `set complete`)
        PackMLOnly,               // subject: the keyword ("command", "state"); a GEMMA scenario
        NotForPackML,             // subject: the keyword ("step", "token"); a PackML scenario
        // A command (mode) in the scan right after another: the request
        // tag must be FALSE for one scan for its R_TRIG to see the next edge.
        // subject: "command" or "mode"; otherLine: the earlier one's line.
        EdgeTooSoon,
        // A second set of one thing in one scan, to another value; at the
        // value of the later line. found: its value; otherLine, otherValue:
        // the earlier set's; scan: the scan both name.
        ConflictingValue,         // subject: the variable as declared; values as written
        ConflictingComplete,      // subject: the step id in capitals; values TRUE, FALSE or auto
        // In closed loop: a set of a sensor the virtual machine writes.
        // subject: the variable as declared; detail: the component's name.
        MachineSensor,
        // Fault lines (docs/simulation.md, "Faults"). In open loop: subject "fault".
        FaultInOpenLoop,
        // In closed loop (machine::FaultRefusal): subject and detail as there.
        FaultOnOperatorInput,     // subject: the variable as declared; detail: its component
        FaultNotMachineSensor,    // subject: the variable as declared
        FaultUnknownComponent,    // subject: as written
        FaultCannotJam,           // subject: the component; detail: its kind ("lamp")
        FaultUnknownTarget,       // subject: as written (clear)
    };

    std::string fileName;
    int line = 0;
    int column = 0;
    Kind kind = Kind::ExpectedAt;
    std::string found;
    std::string subject;
    std::string type;    // InvalidValue: "INT"
    std::string detail;  // InvalidValue: the value parser's English ("'x' is not an integer")
    std::optional<ValueProblem> problem; // InvalidValue: detail as data
    std::int64_t scan = 0;  // Conflicting*
    int otherLine = 0;      // Conflicting*
    std::string otherValue; // Conflicting*
    std::string message; // English: toText() of the above

    // "scenario.txt:4:12: expected '=' after the variable name, found 'TRUE'".
    std::string toString() const;

    friend bool operator==(const ScenarioError&, const ScenarioError&) = default;
};

// "expected '=' after the variable name, found 'TRUE'", "unknown step 'X9'".
std::string toText(const ScenarioError& error);

} // namespace core
