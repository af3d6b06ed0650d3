#pragma once

// A run-time fault: what stops the PLC's task, and with it the simulation.
// The only one the language allows is an integer division or MOD by zero
// (`Count / Batch` while Batch is 0): CODESYS raises an exception and the
// task stops. A REAL division by zero is no fault (IEEE 754: INF or NaN).

#include <cstdint>
#include <string>

namespace core {

struct SimulationFault {
    std::int64_t scan = 0;   // the scan in which it happened
    std::string stepId;      // the GEMMA step whose branch or function block ran it
    // The GEMMA transition ("F1->A2"), or empty for a nested GRAFCET's text:
    // then nestedTransition (its receptivity) or nestedStep and actionIndex
    // (an action, its index in the step's list).
    std::string transitionId;
    int nestedTransition = 0;
    int nestedStep = 0;
    int actionIndex = -1;
    std::string place;    // English: "the condition of F1->A2", "the receptivity of T3 of F1", "action 1 of step 2 of F1"
    std::string text;     // the condition, receptivity or action as written
    std::string division; // the division as written: "Count / Batch"
};

// "scan 12: integer division by zero in the condition of F1->A2
// (Count / Batch in 'Count / Batch > 1'): the PLC stops with a fault, and so
// does the simulation".
std::string toText(const SimulationFault& fault);

} // namespace core
