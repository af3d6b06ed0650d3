#pragma once

// Structured Text: the model's template builds a PlcProject (its POUs, the
// globals and a configuration; GEMMA: core/templates/gemma/gemmacodegen.h,
// PackML: core/templates/packml/packmlcodegen.h), and the printers below turn
// it into IEC 61131-3 or CODESYS text.

#include "core/model/model.h"
#include "core/codegen/plcproject.h"

#include <cstdint>
#include <map>
#include <string>
#include <string_view>

namespace core {

// The model's project, built by its template's generator
// (core/templates/templateengines.h).
PlcProject buildPlcProject(const Model& model, Dialect dialect);

// One POU with its declarations: "PROGRAM GEMMA ... END_PROGRAM" or
// "FUNCTION_BLOCK F1_FB ... END_FUNCTION_BLOCK", ending with a line feed.
std::string formatPou(const PlcPou& pou, Dialect dialect);

// Everything formatPou writes before the body: the comment, the POU keyword
// and name, the declaration blocks.
std::string formatPouHead(const PlcPou& pou, Dialect dialect);

// The number of line feeds in text.
int countLines(const std::string& text);

// "(* text *)", the text made safe by escapeComment.
std::string formatComment(std::string_view text);

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

// A POU as the editor previews it, with the lines each element produced
// (previewGemmaProgram, previewPackmlProgram, previewNestedFunctionBlock).
struct LineRange {
    int first = 0; // 1-based, inclusive
    int last = 0;  // inclusive

    friend bool operator==(const LineRange&, const LineRange&) = default;
};

struct StPreview {
    std::string text; // exactly formatPou of the POU
    // GEMMA's keys: a step id ("F1": its whole CASE branch); a transition id ("F1->A2":
    // its IF/ELSIF line through its assignments, with the problem comments
    // above it). A family transition is evaluated by every visible F state:
    // "F->D1" is its first occurrence, "F->D1@F2" the one in F2's branch.
    std::map<std::string, LineRange> ranges;
};

} // namespace core
