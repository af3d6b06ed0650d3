#pragma once

// One reason why a transition does or does not fire in the next scan
// (Simulator::explain()), as data: the editor words it in the UI language,
// toText() gives the English text the command line and tests use. IEC code
// (expressions, names, TRUE/FALSE, values) is kept as text: it is code in
// every language, only the words around it are translated.

#include <cstdint>
#include <string>
#include <vector>

namespace core {

// What an operand of a condition reads in the predicted scan.
struct ConditionReading {
    std::string name;  // the variable as declared ("Speed"), or the token ("Stop_F1_1_MEM")
    std::string value; // IEC text: "FALSE", "3", "2.5"
    // For a token: the literal it stores ("Stop", "NOT Stop"); empty for a variable.
    std::string tokenLiteral;

    bool isToken() const { return !tokenLiteral.empty(); }
    friend bool operator==(const ConditionReading&, const ConditionReading&) = default;
};

struct ExplanationReason {
    enum class Kind {
        Reading,       // a variable or token operand: readings holds the one reading
        Literal,       // a TRUE/FALSE constant: value
        Expression,    // any other operand (a comparison...): subject is value, readings it depends on
        CompleteFalse, // subject (a step id).Complete = FALSE: the transition waits for it
        FiresFirst,    // subject (a transition id) fires first
        Unusable,      // the condition cannot be used (code, arguments, message); no code: no detail known
        // Nested GRAFCETs (Simulator::explainNested()):
        StepsInactive,   // steps: the upstream steps of the nested transition that are not active
        NoRisingEdge,    // subject: the variable; value: now; previous: at the end of the previous scan
        NoFallingEdge,   // the same for a falling edge
        TimerNotElapsed, // subject: "5s/X2"; steps: {2}; elapsedMs of durationMs
        NotCalled,       // subject (a GEMMA step) is not active: its function block is not called
    };

    Kind kind = Kind::Reading;
    std::string subject;                   // Expression: its IEC text; CompleteFalse: step; FiresFirst: transition
    std::string value;                     // Literal, Expression: "TRUE" or "FALSE"
    std::vector<ConditionReading> readings; // Reading: one; Expression: each distinct one, in order
    // Unusable: the problem as core::Diagnostic gives it, so the UI can use
    // its translated diagnostic texts.
    std::string code;                   // "GG201"; empty when the problem has no code
    std::vector<std::string> arguments; // as Diagnostic::arguments for that code
    std::string message;                // English
    // Nested GRAFCETs.
    std::vector<int> steps;      // StepsInactive: step numbers; TimerNotElapsed: the step timed
    std::string previous;        // NoRisingEdge, NoFallingEdge: "TRUE" or "FALSE"
    std::int64_t elapsedMs = 0;  // TimerNotElapsed: the TON's ET as the evolution reads it
    std::int64_t durationMs = 0; // TimerNotElapsed: its PT

    friend bool operator==(const ExplanationReason&, const ExplanationReason&) = default;
};

// "Start = FALSE", "Stop_F1_1_MEM = FALSE (token of NOT Stop)".
std::string toText(const ConditionReading& reading);
// "Speed > 10 is FALSE (Speed = 3)", "F1.Complete = FALSE", "F->D1 fires first",
// the problem's message for an unusable condition; for nested GRAFCETs
// "step 3 is not active", "no rising edge of Start (Start = TRUE, FALSE ...)",
// "5s/X2 is FALSE: step 2 active for 1200 ms of 5000 ms", "F1 is not active".
std::string toText(const ExplanationReason& reason);

} // namespace core
