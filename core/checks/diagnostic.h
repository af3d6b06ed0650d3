#pragma once

#include "core/model/span.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace core {

enum class Severity { Error, Warning, Info };
std::string_view severityName(Severity severity); // "error", "warning", "info"

// One finding of the checks (spec §5). The code is stable: the editor
// translates by code, tests and scripts match on it; the README lists them.
struct Diagnostic {
    // GrafcetStep and GrafcetTransition: a step or transition of the nested
    // GRAFCET of the GEMMA step named by `element`, numbered by nestedNumber.
    // PackML models (core/templates/packml/packmlchecks.h): Mode, a unit
    // mode (element: its name, `mode` its number); Command (element: the
    // command's PackTags name); ModeState, a state in a mode (element: the
    // mode's name, `state` the state's); Request, a mode's request condition
    // (element: the mode's name). MachineComponent: a component of the
    // virtual machine (core/machine/machinechecks.h; element: its name,
    // field: the role or parameter at fault).
    enum class Target {
        Model, Step, Transition, Variable, GrafcetStep, GrafcetTransition,
        Mode, Command, ModeState, Request, MachineComponent,
    };

    std::string code;         // "GG201"
    Severity severity = Severity::Error;
    Target target = Target::Model;
    std::string element;      // step id, transition id, variable name; empty for the model
    std::string field;        // the field at fault: "condition", "tokens", "name", "default", ...
    std::string message;      // English
    std::optional<Span> span; // for conditions: where in the text
    std::vector<std::string> arguments; // the values the message names, for translation
    int nestedNumber = 0;     // GrafcetStep, GrafcetTransition: the nested step or transition number
    int actionIndex = -1;     // GrafcetStep, field "action": the action's index in the step's list
    int mode = 0;             // Mode, ModeState, Request: the unit mode's number
    std::string state{};      // ModeState: the state's PackTags name ("Execute")

    friend bool operator==(const Diagnostic&, const Diagnostic&) = default;
};

// "A1", "F1->A2", the variable name, "F1 step 3", "F1 T2", "mode Manual",
// "command Hold", "Manual: Execute", "request of mode Manual", "machine
// component Clamp", or "model".
std::string diagnosticElementLabel(const Diagnostic& diagnostic);

bool hasErrors(const std::vector<Diagnostic>& diagnostics);

// One step of reading UTF-8: the code point at the start of `text` and how
// many bytes it takes. An invalid, overlong or truncated sequence is one
// byte long and not valid.
struct Utf8Character {
    char32_t codePoint = 0;
    std::size_t length = 1;
    bool valid = false;
};
Utf8Character decodeUtf8(std::string_view text);

// Characters that break a line, drive a terminal or reorder the text around
// them: the C0 controls, DEL, the C1 controls U+0080-U+009F, the bidi
// embeddings, overrides and isolates (U+202A-U+202E, U+2066-U+2069) and the
// line and paragraph separators U+2028, U+2029.
bool isControlCharacter(char32_t codePoint);

// User text fit for one line of a terminal, reversibly: \n, \r, \t and \\ for
// themselves, \xNN for the other C0 controls, DEL and each byte of invalid
// UTF-8, \uNNNN for the other control characters (lower-case hex). Every
// other character, non-ASCII ones included, is kept.
std::string escapeControlCharacters(std::string_view text);

} // namespace core
