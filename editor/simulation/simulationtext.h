#pragma once

#include "core/simulation/explanationreason.h"
#include "core/simulation/scenario.h"

#include <QString>

#include <vector>

namespace editor {

// What the core says about a simulation, in the UI language. IEC code
// (expressions, names, TRUE/FALSE, values) stays as it is; only the words
// around it are translated.

// "Speed > 10 is FALSE (Speed = 3)", "F1.Complete = FALSE",
// "A1 → F1 fires first"; an unusable condition as the Problems dock words
// the diagnostic of the same code.
QString explanationReasonText(const core::ExplanationReason& reason);

// Step numbers of a nested GRAFCET: "3, 5".
QString stepNumbersText(const std::vector<int>& numbers);

// "scan 3: expected step F1, active step is A1".
QString scenarioFailureText(const core::ScenarioFailure& failure);

// "s.txt:4:12: expected '=' after the variable name, found 'TRUE'": the
// location as ScenarioError::toString() writes it, then the message.
QString scenarioErrorText(const core::ScenarioError& error);

// Why a fault does not apply to the machine, as a scenario's `fault` line would be told.
QString faultRefusalText(const core::machine::FaultRefusal& refusal);

// The first ten of a scenario file's problems, one a line, then "(3 more)".
QString scenarioErrorListText(const std::vector<core::ScenarioError>& errors);

} // namespace editor
