#include "core/model/iectypes.h"

#include "core/model/messagetext.h"
#include "core/templates/gemma/gemmatemplate.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>

namespace core {

namespace {

constexpr char upperAscii(char c)
{
    return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
}

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

// Case-insensitive three-way comparison, for the sorted keyword table.
constexpr int compareIgnoreCase(std::string_view a, std::string_view b)
{
    const std::size_t common = std::min(a.size(), b.size());
    for (std::size_t i = 0; i < common; ++i) {
        const char x = upperAscii(a[i]);
        const char y = upperAscii(b[i]);
        if (x != y)
            return x < y ? -1 : 1;
    }
    if (a.size() == b.size())
        return 0;
    return a.size() < b.size() ? -1 : 1;
}

// Reserved words of IEC 61131-3 (2nd and 3rd edition), its elementary and
// generic type names and the standard function block types, plus the few
// words common compilers (CODESYS, TwinCAT) also reserve. Sorted, upper case:
// looked up by binary search.
constexpr std::array kKeywords = std::to_array<std::string_view>({
    "ABSTRACT", "ACTION", "AND", "ANY", "ANY_BIT", "ANY_CHAR", "ANY_CHARS", "ANY_DATE",
    "ANY_DERIVED", "ANY_DURATION", "ANY_ELEMENTARY", "ANY_INT", "ANY_MAGNITUDE", "ANY_NUM",
    "ANY_REAL", "ANY_SIGNED", "ANY_STRING", "ANY_UNSIGNED", "ARRAY", "AT",
    "BOOL", "BY", "BYTE",
    "CASE", "CHAR", "CLASS", "CONFIGURATION", "CONSTANT", "CONTINUE", "CTD", "CTU", "CTUD",
    "DATE", "DATE_AND_TIME", "DINT", "DO", "DT", "DWORD",
    "ELSE", "ELSIF", "EN", "END_ACTION", "END_CASE", "END_CLASS", "END_CONFIGURATION",
    "END_FOR", "END_FUNCTION", "END_FUNCTION_BLOCK", "END_IF", "END_INTERFACE",
    "END_METHOD", "END_NAMESPACE", "END_PROGRAM", "END_PROPERTY", "END_REPEAT",
    "END_RESOURCE", "END_STEP", "END_STRUCT", "END_TRANSITION", "END_TYPE", "END_VAR",
    "END_WHILE", "ENO", "EXIT", "EXTENDS",
    "FALSE", "FINAL", "FOR", "FROM", "FUNCTION", "FUNCTION_BLOCK", "F_EDGE", "F_TRIG",
    "IF", "IMPLEMENTS", "INITIAL_STEP", "INT", "INTERFACE", "INTERNAL", "INTERVAL",
    "LDATE", "LDATE_AND_TIME", "LDT", "LINT", "LREAL", "LTIME", "LTIME_OF_DAY", "LTOD", "LWORD",
    "METHOD", "MOD",
    "NAMESPACE", "NIL", "NON_RETAIN", "NOT", "NULL",
    "OF", "ON", "OR", "OVERRIDE",
    "POINTER", "PRIORITY", "PRIVATE", "PROGRAM", "PROPERTY", "PROTECTED", "PUBLIC",
    "READ_ONLY", "READ_WRITE", "REAL", "REF", "REF_TO", "REPEAT", "RESOURCE", "RETAIN",
    "RETURN", "RS", "R_EDGE", "R_TRIG",
    "SINGLE", "SINT", "SR", "STEP", "STRING", "STRUCT", "SUPER",
    "TASK", "THEN", "THIS", "TIME", "TIME_OF_DAY", "TO", "TOD", "TOF", "TON", "TP",
    "TRANSITION", "TRUE", "TYPE",
    "UDINT", "UINT", "ULINT", "UNTIL", "USING", "USINT",
    "VAR", "VAR_ACCESS", "VAR_CONFIG", "VAR_EXTERNAL", "VAR_GLOBAL", "VAR_INPUT",
    "VAR_INST", "VAR_IN_OUT", "VAR_OUTPUT", "VAR_STAT", "VAR_TEMP",
    "WCHAR", "WHILE", "WITH", "WORD", "WSTRING",
    "XOR",
});
static_assert(std::is_sorted(kKeywords.begin(), kKeywords.end(),
                             [](std::string_view a, std::string_view b) { return compareIgnoreCase(a, b) < 0; }),
              "isIecKeyword searches kKeywords by bisection");

// kKeywordStart[i]: the first keyword whose initial is 'A' + i or later. The
// condition tokenizer asks about every identifier: a bucket per initial keeps
// the search to a handful of comparisons.
constexpr auto kKeywordStart = [] {
    std::array<std::size_t, 27> start{};
    std::size_t k = 0;
    for (std::size_t letter = 0; letter < 26; ++letter) {
        while (k < kKeywords.size() && kKeywords[k][0] < static_cast<char>('A' + letter))
            ++k;
        start[letter] = k;
    }
    start[26] = kKeywords.size();
    return start;
}();

constexpr std::size_t kLongestKeyword = [] {
    std::size_t longest = 0;
    for (std::string_view keyword : kKeywords)
        longest = std::max(longest, keyword.size());
    return longest;
}();

// Fixed names of the generated project (spec §6, §7). The instances and
// function blocks of the steps depend on the model: core/model/stepnames.h.
constexpr std::array kGeneratorNames = std::to_array<std::string_view>({
    "GEMMA", "State", "Entry", "Initialization", "Complete", "GVL",
    "GemmaConfiguration", "GemmaResource", "MainTask", "GemmaInstance",
});

bool isStepId(std::string_view word)
{
    for (const TemplateState& state : templateStates()) {
        if (equalsIgnoreCase(state.id, word))
            return true;
    }
    return false;
}

bool endsWithIgnoreCase(std::string_view text, std::string_view suffix)
{
    return text.size() >= suffix.size()
        && equalsIgnoreCase(text.substr(text.size() - suffix.size()), suffix);
}

// Token memories are named <variable>_<step>_<priority>_MEM (spec §6.4).
bool isTokenName(std::string_view word)
{
    if (!endsWithIgnoreCase(word, "_MEM"))
        return false;
    std::string_view rest = word.substr(0, word.size() - 4);
    std::size_t digits = 0;
    while (digits < rest.size() && isDigit(rest[rest.size() - 1 - digits]))
        ++digits;
    if (digits == 0 || digits == rest.size() || rest[rest.size() - 1 - digits] != '_')
        return false;
    rest = rest.substr(0, rest.size() - digits - 1);
    const std::size_t underscore = rest.rfind('_');
    return underscore != std::string_view::npos && underscore > 0
        && isStepId(rest.substr(underscore + 1));
}

// --- literal scanning -------------------------------------------------------

struct IntegerText {
    bool negative = false;
    bool overflow = false; // magnitude beyond 2^64 - 1
    std::uint64_t magnitude = 0;
};

// [+|-] integer, the whole text; nullopt when it is not one.
std::optional<IntegerText> parseSignedInteger(std::string_view text)
{
    IntegerText result;
    std::size_t pos = 0;
    if (!text.empty() && (text[0] == '+' || text[0] == '-')) {
        result.negative = text[0] == '-';
        pos = 1;
    }
    const std::size_t end = scanIecDigits(text, pos);
    if (end == pos || end != text.size())
        return std::nullopt;
    constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
    for (std::size_t i = pos; i < end; ++i) {
        if (text[i] == '_')
            continue;
        const auto digit = static_cast<std::uint64_t>(text[i] - '0');
        if (result.magnitude > (kMax - digit) / 10)
            result.overflow = true;
        else
            result.magnitude = result.magnitude * 10 + digit;
    }
    return result;
}

// [+|-] integer ['.' integer] [('E'|'e') [+|-] integer], the whole text.
bool isRealLiteral(std::string_view text)
{
    std::size_t pos = (!text.empty() && (text[0] == '+' || text[0] == '-')) ? 1 : 0;
    std::size_t end = scanIecDigits(text, pos);
    if (end == pos)
        return false;
    pos = end;
    if (pos < text.size() && text[pos] == '.') {
        end = scanIecDigits(text, pos + 1);
        if (end == pos + 1)
            return false;
        pos = end;
    }
    if (pos < text.size() && (text[pos] == 'e' || text[pos] == 'E')) {
        ++pos;
        if (pos < text.size() && (text[pos] == '+' || text[pos] == '-'))
            ++pos;
        end = scanIecDigits(text, pos);
        if (end == pos)
            return false;
        pos = end;
    }
    return pos == text.size();
}

// The power of ten of the first significant digit of a valid real literal
// (without separators): tells overflow from underflow when a double cannot hold it.
long decimalExponent(std::string_view compact)
{
    std::size_t pos = (!compact.empty() && compact[0] == '-') ? 1 : 0;
    long exponent = 0;
    const std::size_t exponentAt = compact.find_first_of("eE");
    if (exponentAt != std::string_view::npos) {
        long parsed = 0;
        std::string_view digits = compact.substr(exponentAt + 1);
        const bool negative = !digits.empty() && digits[0] == '-';
        if (!digits.empty() && (digits[0] == '-' || digits[0] == '+'))
            digits.remove_prefix(1);
        for (char c : digits)
            parsed = std::min(parsed * 10 + (c - '0'), 100000L); // saturate: only the sign matters
        exponent = negative ? -parsed : parsed;
    }
    const std::string_view mantissa = compact.substr(pos, exponentAt == std::string_view::npos ? std::string_view::npos : exponentAt - pos);
    const std::size_t point = std::min(mantissa.find('.'), mantissa.size());
    const std::size_t firstNonZero = mantissa.find_first_of("123456789");
    if (firstNonZero == std::string_view::npos)
        return 0;
    if (firstNonZero < point)
        return exponent + static_cast<long>(point - firstNonZero - 1);
    return exponent - static_cast<long>(firstNonZero - point);
}

struct IntegerRange {
    std::int64_t min;
    std::uint64_t max;
};

IntegerRange integerRange(IecType type)
{
    switch (type) {
    case IecType::Sint: return {-128, 127};
    case IecType::Int: return {-32768, 32767};
    case IecType::Dint: return {std::numeric_limits<std::int32_t>::min(), 2147483647u};
    case IecType::Lint:
        return {std::numeric_limits<std::int64_t>::min(),
                static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())};
    case IecType::Usint: return {0, 255};
    case IecType::Uint: return {0, 65535};
    case IecType::Udint: return {0, 4294967295u};
    default: return {0, std::numeric_limits<std::uint64_t>::max()};
    }
}

bool fitsRange(const IntegerText& value, IntegerRange range)
{
    if (value.overflow)
        return false;
    if (!value.negative)
        return value.magnitude <= range.max;
    // -min computed without overflowing for INT64_MIN.
    const std::uint64_t minMagnitude =
        range.min < 0 ? static_cast<std::uint64_t>(-(range.min + 1)) + 1 : 0;
    return value.magnitude <= minMagnitude;
}

ValueProblem makeProblem(ValueProblem::Kind kind, IecType type, std::string_view value, std::string low = {},
                         std::string high = {})
{
    return ValueProblem{kind, std::string(value), std::string(iecTypeName(type)), std::move(low), std::move(high)};
}

std::optional<ValueProblem> integerProblem(IecType type, std::string_view value)
{
    const auto parsed = parseSignedInteger(value);
    if (!parsed)
        return makeProblem(ValueProblem::Kind::NotInteger, type, value);
    const IntegerRange range = integerRange(type);
    if (fitsRange(*parsed, range))
        return std::nullopt;
    return makeProblem(ValueProblem::Kind::OutOfRange, type, value, std::to_string(range.min),
                       std::to_string(range.max));
}

std::optional<ValueProblem> realProblem(IecType type, std::string_view value)
{
    if (!isRealLiteral(value))
        return makeProblem(ValueProblem::Kind::NotReal, type, value);
    const auto number = parseRealLiteral(value);
    const bool real = type == IecType::Real;
    const double limit = real ? static_cast<double>(FLT_MAX) : DBL_MAX;
    if (!number || std::fabs(*number) > limit)
        return makeProblem(ValueProblem::Kind::OutOfRange, type, value, real ? "-3.4E38" : "-1.8E308",
                           real ? "3.4E38" : "1.8E308");
    return std::nullopt;
}

} // namespace

const std::vector<IecType>& allIecTypes()
{
    static const std::vector<IecType> types = {
        IecType::Bool, IecType::Sint, IecType::Int, IecType::Dint, IecType::Lint, IecType::Usint,
        IecType::Uint, IecType::Udint, IecType::Ulint, IecType::Real, IecType::Lreal,
    };
    return types;
}

std::string_view iecTypeName(IecType type)
{
    switch (type) {
    case IecType::Bool: return "BOOL";
    case IecType::Sint: return "SINT";
    case IecType::Int: return "INT";
    case IecType::Dint: return "DINT";
    case IecType::Lint: return "LINT";
    case IecType::Usint: return "USINT";
    case IecType::Uint: return "UINT";
    case IecType::Udint: return "UDINT";
    case IecType::Ulint: return "ULINT";
    case IecType::Real: return "REAL";
    case IecType::Lreal: return "LREAL";
    }
    return "BOOL";
}

std::optional<IecType> parseIecType(std::string_view name)
{
    for (IecType type : allIecTypes()) {
        if (equalsIgnoreCase(iecTypeName(type), name))
            return type;
    }
    return std::nullopt;
}

bool isIntegerType(IecType type)
{
    return type != IecType::Bool && !isRealType(type);
}

bool isRealType(IecType type)
{
    return type == IecType::Real || type == IecType::Lreal;
}

bool isNumericType(IecType type)
{
    return type != IecType::Bool;
}

std::optional<double> parseRealLiteral(std::string_view text)
{
    if (!isRealLiteral(text))
        return std::nullopt;
    // from_chars takes neither a leading '+' nor the IEC digit separators.
    std::string compact;
    compact.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '_' && !(i == 0 && text[i] == '+'))
            compact.push_back(text[i]);
    }
    double value = 0.0;
    const char* first = compact.data();
    const char* last = first + compact.size();
    const auto [end, error] = std::from_chars(first, last, value);
    if (end != last)
        return std::nullopt;
    if (error == std::errc::result_out_of_range)
        return decimalExponent(compact) < 0 ? std::optional<double>(0.0) : std::nullopt;
    if (error != std::errc())
        return std::nullopt;
    return value;
}

std::optional<ValueProblem> valueProblem(IecType type, std::string_view value)
{
    if (value.empty())
        return std::nullopt;
    if (value.front() == ' ' || value.back() == ' ' || value.front() == '\t' || value.back() == '\t')
        return makeProblem(ValueProblem::Kind::Spaces, type, value);
    if (type == IecType::Bool) {
        // IEC 61131-3 also writes BOOL literals as 0 and 1; both are accepted.
        if (equalsIgnoreCase(value, "TRUE") || equalsIgnoreCase(value, "FALSE") || value == "0"
            || value == "1")
            return std::nullopt;
        return makeProblem(ValueProblem::Kind::NotBool, type, value);
    }
    if (isRealType(type))
        return realProblem(type, value);
    return integerProblem(type, value);
}

std::string defaultValueProblem(IecType type, std::string_view value)
{
    const std::optional<ValueProblem> problem = valueProblem(type, value);
    return problem ? toText(*problem) : std::string();
}

std::string_view implicitDefault(IecType type)
{
    if (type == IecType::Bool)
        return "FALSE";
    return isRealType(type) ? "0.0" : "0";
}

IdentifierProblem identifierProblem(std::string_view name)
{
    if (name.empty())
        return IdentifierProblem::Empty;
    if (!(isLetter(name[0]) || name[0] == '_'))
        return IdentifierProblem::InvalidCharacter;
    for (char c : name) {
        if (!(isLetter(c) || isDigit(c) || c == '_'))
            return IdentifierProblem::InvalidCharacter;
    }
    if (name.find("__") != std::string_view::npos)
        return IdentifierProblem::DoubleUnderscore;
    if (name.back() == '_')
        return IdentifierProblem::TrailingUnderscore;
    if (isIecKeyword(name))
        return IdentifierProblem::Keyword;
    if (isGeneratorName(name))
        return IdentifierProblem::GeneratorName;
    return IdentifierProblem::None;
}

std::string identifierProblemMessage(IdentifierProblem problem, std::string_view name)
{
    const std::string q = quoted(name);
    switch (problem) {
    case IdentifierProblem::None: return {};
    case IdentifierProblem::Empty: return "the name is empty";
    case IdentifierProblem::InvalidCharacter:
        return q + " is not a valid IEC 61131-3 identifier: use ASCII letters, digits and '_',"
                   " not starting with a digit";
    case IdentifierProblem::DoubleUnderscore:
        return q + " contains '__', which IEC 61131-3 identifiers may not";
    case IdentifierProblem::TrailingUnderscore:
        return q + " ends with '_', which IEC 61131-3 identifiers may not";
    case IdentifierProblem::Keyword:
        return q + " is an IEC 61131-3 keyword or type name";
    case IdentifierProblem::GeneratorName:
        return q + " is a name the generated code uses";
    }
    return {};
}

bool isIecKeyword(std::string_view word)
{
    if (word.empty() || word.size() > kLongestKeyword)
        return false;
    const char initial = upperAscii(word[0]);
    if (initial < 'A' || initial > 'Z')
        return false;
    const auto letter = static_cast<std::size_t>(initial - 'A');
    return std::binary_search(kKeywords.begin() + static_cast<std::ptrdiff_t>(kKeywordStart[letter]),
                              kKeywords.begin() + static_cast<std::ptrdiff_t>(kKeywordStart[letter + 1]), word,
                              [](std::string_view a, std::string_view b) {
                                  return compareIgnoreCase(a, b) < 0;
                              });
}

bool isGeneratorName(std::string_view word)
{
    for (std::string_view name : kGeneratorNames) {
        if (equalsIgnoreCase(name, word))
            return true;
    }
    return isTokenName(word);
}

bool equalsIgnoreCase(std::string_view a, std::string_view b)
{
    return a.size() == b.size() && compareIgnoreCase(a, b) == 0;
}

std::string toUpperAscii(std::string_view text)
{
    std::string result(text);
    for (char& c : result)
        c = upperAscii(c);
    return result;
}

std::size_t scanIecDigits(std::string_view text, std::size_t from)
{
    const auto isDigit = [](char c) { return c >= '0' && c <= '9'; };
    std::size_t pos = from;
    if (pos >= text.size() || !isDigit(text[pos]))
        return from;
    ++pos;
    while (pos < text.size()) {
        if (isDigit(text[pos]))
            ++pos;
        else if (text[pos] == '_' && pos + 1 < text.size() && isDigit(text[pos + 1]))
            pos += 2;
        else
            break;
    }
    return pos;
}

} // namespace core
