#pragma once

// Why a value is not a literal of an IEC type (a variable's default value
// GG304, a value a scenario sets), as data: the editor words it in the UI
// language, toText() gives the English text the command line and tests use.
// The value, the type name and the bounds are code in every language.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace core {

struct ValueProblem {
    enum class Kind {
        Spaces,     // leading or trailing spaces or tabs
        NotBool,    // not TRUE, FALSE, 0 or 1
        NotInteger, // not a whole number
        NotReal,    // not a decimal number
        OutOfRange, // low, high: the type's bounds
    };

    Kind kind = Kind::Spaces;
    std::string value; // as written
    std::string type;  // "INT"
    std::string low;   // OutOfRange: "-32768", "-3.4E38"
    std::string high;  // OutOfRange: "32767", "3.4E38"

    friend bool operator==(const ValueProblem&, const ValueProblem&) = default;
};

// "'40000' is out of range for INT (-32768..32767)".
std::string toText(const ValueProblem& problem);

// A stable name per kind for Diagnostic::arguments ("out-of-range"), and back.
std::string_view kindName(ValueProblem::Kind kind);
std::optional<ValueProblem::Kind> valueProblemKind(std::string_view name);

// The problem as GG304 appends it to Diagnostic::arguments
// (docs/diagnostics.md): kind name, value, type, low, high.
// valueProblemFromArguments reads them back from position `first`; nullopt
// when they are missing or the kind is unknown.
void appendArguments(const ValueProblem& problem, std::vector<std::string>& arguments);
std::optional<ValueProblem> valueProblemFromArguments(const std::vector<std::string>& arguments, std::size_t first);

} // namespace core
