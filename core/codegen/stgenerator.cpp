// The printers of Structured Text (spec §6, §7) that every template's
// generator shares: declarations, POUs, the global list, the configuration.
// What a template's code says comes from its own generator
// (core/templates/gemma/gemmacodegen.cpp, core/templates/packml/packmlcodegen.cpp).
//
//
// IEC rules the printers keep: (* *) comments only, user text escaped inside
// them; `;` after every END_IF and END_CASE; no empty statement, CASE branch,
// declaration block or POU body; a simple step with no outgoing transition
// gets a comment and `State := <its number>;` (a real, idempotent statement).
//
// All text is built by appending to one string per POU, so the cost is

#include "core/codegen/stgenerator.h"

#include "core/templates/templateengines.h"

#include <algorithm>
#include <string_view>

namespace core {

namespace {


// A REAL literal IEC accepts: digits on both sides of a decimal point ("5" -> "5.0", "1e3" -> "1.0e3").
std::string normalizeRealLiteral(const std::string& text)
{
    std::size_t exponent = text.find_first_of("eE");
    std::string mantissa = text.substr(0, exponent);
    std::string rest = exponent == std::string::npos ? std::string() : text.substr(exponent);
    std::size_t point = mantissa.find('.');
    if (point == std::string::npos) {
        mantissa += ".0";
    } else {
        if (point == mantissa.size() - 1)
            mantissa += "0";
        if (point == 0 || mantissa[point - 1] == '-' || mantissa[point - 1] == '+')
            mantissa.insert(point, "0");
    }
    return mantissa + rest;
}

} // namespace

std::string formatComment(std::string_view text)
{
    return "(* " + escapeComment(std::string(text)) + " *)";
}

std::string plcInitialValue(const Variable& variable, std::string& problem)
{
    if (variable.defaultValue.empty())
        return std::string(implicitDefault(variable.type));
    problem = defaultValueProblem(variable.type, variable.defaultValue);
    if (!problem.empty())
        return std::string(implicitDefault(variable.type));
    if (variable.type == IecType::Bool) {
        const bool isTrue = equalsIgnoreCase(variable.defaultValue, "TRUE") || variable.defaultValue == "1";
        return isTrue ? "TRUE" : "FALSE";
    }
    if (isRealType(variable.type))
        return normalizeRealLiteral(variable.defaultValue);
    return variable.defaultValue;
}

namespace {

std::string comment(std::string_view text)
{
    return formatComment(text);
}

void appendDeclaration(std::string& out, int indent, const PlcVariable& variable)
{
    out.append(static_cast<std::size_t>(indent), ' ');
    out += variable.name;
    out += " : ";
    out += variable.typeName;
    if (!variable.initialValue.empty()) {
        out += " := ";
        out += variable.initialValue;
    }
    out += ';';
    if (!variable.comment.empty()) {
        out += ' ';
        out += comment(variable.comment);
    }
    out += '\n';
}

// IEC forbids an empty declaration block, so an empty list prints nothing.
void appendBlock(std::string& out, int indent, std::string_view keyword, const std::vector<PlcVariable>& variables)
{
    if (variables.empty())
        return;
    out.append(static_cast<std::size_t>(indent), ' ');
    out += keyword;
    out += '\n';
    for (const PlcVariable& variable : variables)
        appendDeclaration(out, indent + 4, variable);
    out.append(static_cast<std::size_t>(indent), ' ');
    out += "END_VAR\n";
}

std::string_view pouKeyword(PouKind kind)
{
    return kind == PouKind::Program ? "PROGRAM" : "FUNCTION_BLOCK";
}

} // namespace

// Everything of formatPou before the body.
std::string formatPouHead(const PlcPou& pou, Dialect dialect)
{
    std::string out;
    if (!pou.comment.empty())
        out += comment(pou.comment) + "\n";
    out += pouKeyword(pou.kind);
    out += ' ';
    out += pou.name;
    out += '\n';
    appendBlock(out, 0, "VAR_INPUT", pou.inputs);
    appendBlock(out, 0, "VAR_OUTPUT", pou.outputs);
    if (dialect == Dialect::Iec)
        appendBlock(out, 0, "VAR_EXTERNAL", pou.externals);
    appendBlock(out, 0, "VAR", pou.locals);
    return out;
}

int countLines(const std::string& text)
{
    int lines = 0;
    for (char c : text) {
        if (c == '\n')
            ++lines;
    }
    return lines;
}

namespace {

// Printable ASCII without a comment delimiter: what nearly every comment the
// generators write is, and what escapeComment leaves as it is.
bool isPlainCommentText(std::string_view text)
{
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c < 0x20 || c > 0x7E)
            return false;
        const char next = i + 1 < text.size() ? text[i + 1] : '\0';
        if ((c == '(' && next == '*') || (c == '*' && next == ')'))
            return false;
    }
    return true;
}

} // namespace

std::string escapeComment(const std::string& text)
{
    if (isPlainCommentText(text))
        return text;
    std::string out;
    out.reserve(text.size());
    std::string_view rest = text;
    while (!rest.empty()) {
        const Utf8Character character = decodeUtf8(rest);
        const char32_t c = character.codePoint;
        const char next = rest.size() > 1 ? rest[1] : '\0';
        if ((c == '(' && next == '*') || (c == '*' && next == ')')) {
            out += static_cast<char>(c);
            out += ' ';
        } else if (c == '\n' || c == '\r' || c == '\t' || c == 0x2028 || c == 0x2029) {
            out += ' ';
        } else if (!character.valid || isControlCharacter(c)) {
            // Neither the compiler nor an editor showing the file should
            // meet a terminal control, a bidi override or invalid UTF-8.
            out += '?';
        } else {
            out.append(rest.substr(0, character.length));
        }
        rest.remove_prefix(character.length);
    }
    return out;
}

std::string formatDuration(std::int64_t milliseconds)
{
    if (milliseconds <= 0)
        return "T#0ms";
    struct Unit {
        std::int64_t ms;
        const char* suffix;
    };
    static constexpr Unit kUnits[] = {{86'400'000, "d"}, {3'600'000, "h"}, {60'000, "m"}, {1'000, "s"}, {1, "ms"}};
    int firstUnit = -1;
    int lastUnit = -1;
    std::int64_t rest = milliseconds;
    for (int i = 0; i < 5; ++i) {
        if (rest / kUnits[i].ms > 0) {
            if (firstUnit < 0)
                firstUnit = i;
            lastUnit = i;
        }
        rest %= kUnits[i].ms;
    }
    std::string out = "T#";
    rest = milliseconds;
    for (int i = 0; i < 5; ++i) {
        const std::int64_t count = rest / kUnits[i].ms;
        rest %= kUnits[i].ms;
        if (i >= firstUnit && i <= lastUnit)
            out += std::to_string(count) + kUnits[i].suffix;
    }
    return out;
}

PlcProject buildPlcProject(const Model& model, Dialect dialect)
{
    return enginesOf(model).buildPlcProject(model, dialect);
}

namespace {

void appendPou(std::string& out, const PlcPou& pou, Dialect dialect)
{
    out += formatPouHead(pou, dialect);
    out.reserve(out.size() + pou.body.size() + 32);
    out += pou.body;
    if (!pou.body.empty() && pou.body.back() != '\n')
        out += '\n';
    out += pou.kind == PouKind::Program ? "END_PROGRAM\n" : "END_FUNCTION_BLOCK\n";
}

} // namespace

std::string formatPou(const PlcPou& pou, Dialect dialect)
{
    std::string out;
    appendPou(out, pou, dialect);
    return out;
}

std::string formatGlobals(const PlcProject& project)
{
    std::string out;
    if (project.dialect == Dialect::Codesys) {
        out += "{attribute 'qualified_only'}\nVAR_GLOBAL\n";
        for (const PlcVariable& variable : project.globals)
            appendDeclaration(out, 4, variable);
        out += "END_VAR\n";
        return out;
    }
    appendBlock(out, 0, "VAR_GLOBAL", project.globals);
    return out;
}

namespace {

// The type of the configuration's program instance: the project's PROGRAM
// (every generator writes one; "GEMMA", the first template's, otherwise).
std::string programTypeName(const PlcProject& project)
{
    for (const PlcPou& pou : project.pous)
        if (pou.kind == PouKind::Program)
            return pou.name;
    return "GEMMA";
}

std::string configurationText(const PlcProject& project, bool withGlobals)
{
    std::string out = "CONFIGURATION " + project.configurationName + "\n";
    if (withGlobals)
        appendBlock(out, 4, "VAR_GLOBAL", project.globals);
    out += "    RESOURCE " + project.resourceName + " ON PLC\n";
    out += "        TASK " + project.taskName + "(INTERVAL := " + formatDuration(project.cycleTimeMs)
           + ", PRIORITY := " + std::to_string(project.taskPriority) + ");\n";
    out += "        PROGRAM " + project.programInstanceName + " WITH " + project.taskName + " : "
           + programTypeName(project) + ";\n";
    out += "    END_RESOURCE\n";
    out += "END_CONFIGURATION\n";
    return out;
}

} // namespace

// CODESYS keeps its globals in the GVL, not in the configuration.
std::string formatConfiguration(const PlcProject& project)
{
    return configurationText(project, project.dialect == Dialect::Iec);
}

std::string formatSingleFileIec(const PlcProject& project)
{
    // Written in place: the text of a large PackML program is about a
    // megabyte, and a copy per POU doubled the time to write it.
    std::size_t bodies = 0;
    for (const PlcPou& pou : project.pous)
        bodies += pou.body.size();
    std::string out;
    out.reserve(bodies + bodies / 4);
    for (const PlcPou& pou : project.pous) {
        if (pou.kind == PouKind::FunctionBlock) {
            appendPou(out, pou, Dialect::Iec);
            out += '\n';
        }
    }
    for (const PlcPou& pou : project.pous) {
        if (pou.kind == PouKind::Program) {
            appendPou(out, pou, Dialect::Iec);
            out += '\n';
        }
    }
    out += configurationText(project, true);
    return out;
}

} // namespace core
