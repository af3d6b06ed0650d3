#pragma once

#include "core/templates/packml/packmlscanrecord.h"
#include "core/templates/packml/packmlscenario.h"

#include <QString>

namespace core {
struct SimulationFault;
}

namespace editor {

// What the PackML simulator says, in the UI language. PackTags names
// (states, commands), mode names, transitions ("Idle-Start->Execute") and
// IEC values stay as they are; only the words around them are translated.
// The core's toText() gives the same in English for the command line.

// "Idle-Start->Execute", "Resetting-SC->Idle": the real target, after skipping.
QString packmlTransitionText(const core::packml::ModeTransition& transition);

// "Hold is not accepted in Idle", "Manual cannot be entered in Execute:
// Production allows mode changes in Stopped, Idle, Aborted".
QString packmlDroppedText(const core::packml::DroppedEvent& event, const core::packml::PackmlProgram& program);

// "scan 9: expected state Execute, the state is Held".
QString packmlScenarioFailureText(const core::packml::PackmlScenarioFailure& failure);

// "Stopped at scan 1: integer division by zero in the condition of the
// Reset command (Count / Batch in 'Count / Batch > 1'). ...".
QString packmlFaultText(const core::SimulationFault& fault);

// What became of a command pressed or a mode requested, from the scan that
// read it: "Start: fired Idle-Start->Execute", "Hold is not accepted in Idle",
// "Manual: granted". `number` is the command's CntrlCmd or the mode's number.
enum class PackmlRequestKind { Command, Mode };
QString packmlRequestOutcomeText(PackmlRequestKind kind, int number, const core::packml::PackmlScanRecord& record,
                                 const core::packml::PackmlProgram& program);

// The mode's name, or its number when the model has no such mode.
QString packmlModeName(const core::packml::PackmlProgram& program, int number);

} // namespace editor
