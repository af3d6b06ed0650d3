#pragma once

// Structured Text generation by the Hierarchical Design Pattern (spec §6, §7):
// the model becomes a PlcProject (one PROGRAM GEMMA, one FUNCTION_BLOCK per
// visible macro/enclosing step, the globals and a configuration), and the
// printers below turn that into IEC 61131-3 or CODESYS text.

#include "core/model/model.h"
#include "core/codegen/plcproject.h"

#include <cstdint>
#include <map>
#include <string>

namespace core {

// A PackML model's project comes from core/templates/packml/packmlcodegen.h.
PlcProject buildPlcProject(const Model& model, Dialect dialect);

// One POU with its declarations: "PROGRAM GEMMA ... END_PROGRAM" or
// "FUNCTION_BLOCK F1_FB ... END_FUNCTION_BLOCK", ending with a line feed.
std::string formatPou(const PlcPou& pou, Dialect dialect);

// IEC: the VAR_GLOBAL block as it appears in the configuration (empty text
// when there are no globals: IEC does not allow an empty VAR_GLOBAL).
// CODESYS: the text of the global variable list, {attribute 'qualified_only'}
// then VAR_GLOBAL ... END_VAR.
std::string formatGlobals(const PlcProject& project);

// CONFIGURATION ... END_CONFIGURATION with the globals, one resource, the
// cyclic task and the instance of the project's PROGRAM.
std::string formatConfiguration(const PlcProject& project);

// Every POU (function blocks first, so each type is declared before use) and
// the configuration: one file an IEC compiler (matiec, ...) builds directly.
// Meant for the IEC dialect: CODESYS conditions name GVL, which has no
// IEC counterpart.
std::string formatSingleFileIec(const PlcProject& project);

// The ST literal a global is initialised with: its default as a literal of
// its type, or the type's implicit default when it has none or it does not
// fit (then `problem` says why).
std::string plcInitialValue(const Variable& variable, std::string& problem);

// T#20ms, T#1s500ms, T#1m0s500ms: the units from the largest to the smallest
// non-zero one, none skipped in between (IEC 61131-3 duration grammar).
// Written as given, never clamped: the checks refuse a duration above
// cond::kMaxTimeMs (GG407), so none reaches the code.
std::string formatDuration(std::int64_t milliseconds);

// Text made safe inside (* *): no comment delimiter survives, line breaks
// become spaces, and control characters (core::isControlCharacter: terminal
// controls, bidi overrides) and invalid UTF-8 bytes become '?'.
std::string escapeComment(const std::string& text);

// The GEMMA POU as the editor previews it, with the lines each element
// produced.
struct LineRange {
    int first = 0; // 1-based, inclusive
    int last = 0;  // inclusive

    friend bool operator==(const LineRange&, const LineRange&) = default;
};

struct StPreview {
    std::string text; // exactly formatPou of the GEMMA POU
    // Keys: a step id ("F1": its whole CASE branch); a transition id ("F1->A2":
    // its IF/ELSIF line through its assignments, with the problem comments
    // above it). A family transition is evaluated by every visible F state:
    // "F->D1" is its first occurrence, "F->D1@F2" the one in F2's branch.
    std::map<std::string, LineRange> ranges;
};

StPreview previewGemmaProgram(const Model& model, Dialect dialect);

} // namespace core
