// Structured Text by the Hierarchical Design Pattern (spec §6, §7).
//
// Layout of the generated code: POU bodies start at column 0; inside
// `CASE State OF` a branch label stands at the column of CASE and its
// statements are indented 4 spaces, each further block 4 more, exactly as the
// spec's examples (so the spec's `    ELSIF Stop_F1_3_MEM AND F1.Complete THEN`
// comes out character for character).
//
// Models with errors still generate code that compiles; each problem becomes
// a comment at the place it concerns:
// - a condition that does not parse, is empty, is not BOOL, or names an
//   undeclared variable: `(* ERROR <code>: condition of <id>: <message> *)`
//   above its IF/ELSIF line, and FALSE as the condition (the transition
//   never fires, which is also what the simulator does);
// - a token that cannot take effect (simple source, not BOOL, not in the
//   condition, compared with = or <>, both polarities, unusable condition):
//   `(* WARNING: token on 'X' of <id> ignored: <why> *)`, no token variable;
// - a default value that does not fit its type: the type's implicit default,
//   with the reason in the declaration's comment;
// - a hidden initial step: a comment at the top of the GEMMA body.
// - a variable whose name the code cannot declare (not an IEC identifier, a
//   keyword, a name the generator uses, the instance or function block of a
//   visible macro/enclosing step: the checks' GG301-GG303, GG306) is
//   declared as Invalid_Name_<its position>, with the reason in its comment,
//   and every condition that reads it is FALSE with its ERROR comment
//   (gemmaprogram.h, unusableNameCode). Other names are written as declared.
// No user text is written outside a comment but names that are identifiers
// and defaults that are literals of their type (docs/generated-code.md).
//
// IEC rules the printers keep: (* *) comments only, user text escaped inside
// them; `;` after every END_IF and END_CASE; no empty statement, CASE branch,
// declaration block or POU body; a simple step with no outgoing transition
// gets a comment and `State := <its number>;` (a real, idempotent statement).
//
// All text is built by appending to one string per POU, so the cost is
// linear in the size of the output.

#include "core/codegen/stgenerator.h"

#include "core/condition/conditionanalysis.h"
#include "core/checks/diagnostic.h"
#include "core/codegen/gemmaprogram.h"
#include "core/codegen/nestedcode.h"
#include "core/condition/symboltable.h"
#include "core/templates/packml/packmlcodegen.h"

#include <algorithm>
#include <functional>
#include <string_view>

namespace core {

namespace {

constexpr std::string_view kGemmaPouName = "GEMMA";
constexpr std::string_view kGlobalListName = "GVL";

// Appends lines and counts them, so the preview knows where each element went.
class LineWriter {
public:
    void line(int indent, std::string_view text)
    {
        m_text.append(static_cast<std::size_t>(indent), ' ');
        m_text.append(text);
        m_text.push_back('\n');
        ++m_lines;
    }
    int lines() const { return m_lines; }
    std::string& text() { return m_text; }

private:
    std::string m_text;
    int m_lines = 0;
};

std::string comment(std::string_view text)
{
    return "(* " + escapeComment(std::string(text)) + " *)";
}

std::string problemComment(const GemmaProblem& problem)
{
    std::string text = problem.kind == GemmaProblem::Kind::Error ? "ERROR" : "WARNING";
    if (!problem.code.empty())
        text += " " + problem.code;
    text += ": " + problem.message;
    return comment(text);
}

// The name each global is declared under, by position: its own, or
// Invalid_Name_<position> when the code cannot declare it as it is
// (unusableNameCode), with _2, _3, ... should a user variable already have
// that name. No condition reads a renamed variable, so the name only has to
// be a fresh identifier.
std::vector<std::string> declaredNames(const Model& model)
{
    const std::vector<Variable>& variables = model.variables();
    std::vector<std::string> names;
    names.reserve(variables.size());
    SymbolTable taken(variables);
    std::vector<std::string> generated; // upper case
    auto isFree = [&](const std::string& candidate) {
        const std::string key = toUpperAscii(candidate);
        return !taken.find(candidate) && std::find(generated.begin(), generated.end(), key) == generated.end();
    };
    for (std::size_t i = 0; i < variables.size(); ++i) {
        if (!unusableNameCode(variables[i].name, model)) {
            names.push_back(variables[i].name);
            continue;
        }
        const std::string base = "Invalid_Name_" + std::to_string(i + 1);
        std::string candidate = base;
        for (int suffix = 2; !isFree(candidate); ++suffix)
            candidate = base + "_" + std::to_string(suffix);
        generated.push_back(toUpperAscii(candidate));
        names.push_back(std::move(candidate));
    }
    return names;
}

// Spellings of the names the code reads, per dialect.
class Naming {
public:
    Naming(const Model& model, Dialect dialect)
        : m_variables(model.variables())
        , m_symbols(model.variables())
        , m_declared(declaredNames(model))
        , m_dialect(dialect)
        , m_read(model.variables().size(), false)
    {
    }

    // A global as code reads it: "Stop" or "GVL.Stop".
    std::string global(std::string_view writtenName)
    {
        const Variable* variable = m_symbols.find(writtenName);
        std::string name = std::string(writtenName); // not reached: usable conditions name declared variables
        if (variable) {
            const auto index = static_cast<std::size_t>(variable - m_variables.data());
            m_read[index] = true;
            name = m_declared[index];
        }
        if (m_dialect == Dialect::Codesys)
            return std::string(kGlobalListName) + "." + name;
        return name;
    }

    // An edge memory global: "Start_PREV" or "GVL.Start_PREV".
    std::string edgeMemory(std::string_view writtenName) const
    {
        const Variable* variable = m_symbols.find(writtenName);
        const std::string name = edgeMemoryName(variable ? variable->name : std::string(writtenName));
        return m_dialect == Dialect::Codesys ? std::string(kGlobalListName) + "." + name : name;
    }

    // The globals read so far, in declaration order, as declared.
    std::vector<PlcVariable> readVariables() const
    {
        std::vector<PlcVariable> result;
        for (std::size_t i = 0; i < m_variables.size(); ++i) {
            if (m_read[i])
                result.push_back(PlcVariable{m_declared[i], std::string(iecTypeName(m_variables[i].type)), {}, {}});
        }
        return result;
    }

private:
    const std::vector<Variable>& m_variables;
    SymbolTable m_symbols;
    std::vector<std::string> m_declared;
    Dialect m_dialect;
    std::vector<bool> m_read;
};

std::string printCondition(const GemmaTransition& transition, const GemmaStep& step, Naming& naming)
{
    if (!transition.conditionUsable)
        return "FALSE";
    cond::PrintOptions options;
    options.variableName = [&naming](const cond::Node& node) { return naming.global(node.text); };
    options.substitutions = transition.substitutions;
    const cond::Expression& expression = transition.condition.expression;
    std::string text = cond::print(expression, options);
    if (!transition.waitsForComplete)
        return text;
    if (cond::needsParenthesesBeforeAnd(expression, options))
        text = "(" + text + ")";
    return text + " AND " + step.id + ".Complete";
}

class GemmaBodyWriter {
public:
    GemmaBodyWriter(const GemmaProgram& program, Naming& naming)
        : m_program(program)
        , m_naming(naming)
    {
    }

    void write()
    {
        for (const GemmaProblem& problem : m_program.problems) {
            if (!isTransitionProblem(problem)) // the program's own, e.g. a hidden initial step
                m_out.line(0, problemComment(problem));
        }
        if (m_program.steps.empty()) {
            m_out.line(0, comment("Every step is hidden: the GEMMA has no state to run."));
            m_out.line(0, "State := " + std::to_string(m_program.initialNumber) + ";");
            return;
        }
        m_out.line(0, "CASE State OF");
        for (const GemmaStep& step : m_program.steps)
            writeStep(step);
        m_out.line(0, "END_CASE;");
        writeContinuousOutputs();
        writeTokenUpdates();
        writeEdgeMemories();
    }

    std::string& text() { return m_out.text(); }
    std::map<std::string, LineRange>& ranges() { return m_ranges; }

private:
    static bool isTransitionProblem(const GemmaProblem& problem)
    {
        return problem.element.find("->") != std::string::npos;
    }

    void writeStep(const GemmaStep& step)
    {
        const int first = m_out.lines() + 1;
        m_out.line(0, std::to_string(step.number) + ": " + comment(step.id + " " + step.name));
        if (step.hasNestedBehaviour())
            writeEntryBlock(step);
        if (step.transitions.empty()) {
            m_out.line(4, comment(step.id + " has no outgoing transition"));
            if (!step.hasNestedBehaviour())
                m_out.line(4, "State := " + std::to_string(step.number) + ";");
        } else {
            writeTransitions(step);
        }
        m_ranges[step.id] = LineRange{first, m_out.lines()};
    }

    void writeEntryBlock(const GemmaStep& step)
    {
        const std::string call = step.id + "(Initialization := Entry);";
        m_out.line(4, "IF Entry THEN");
        m_out.line(8, call);
        m_out.line(8, "Entry := FALSE;");
        for (const GemmaToken& token : step.tokens)
            m_out.line(8, token.name + " := FALSE;");
        m_out.line(4, "END_IF;");
        m_out.line(4, call);
    }

    void writeTransitions(const GemmaStep& step)
    {
        bool firstBranch = true;
        for (const GemmaTransition& transition : step.transitions) {
            const int first = m_out.lines() + 1;
            for (const GemmaProblem& problem : transition.problems)
                m_out.line(4, problemComment(problem));
            const std::string keyword = firstBranch ? "IF " : "ELSIF ";
            m_out.line(4, keyword + printCondition(transition, step, m_naming) + " THEN");
            m_out.line(8, "State := " + std::to_string(transition.targetNumber) + ";");
            m_out.line(8, "Entry := TRUE;");
            recordTransition(step, transition, LineRange{first, m_out.lines()});
            firstBranch = false;
        }
        m_out.line(4, "END_IF;");
    }

    void recordTransition(const GemmaStep& step, const GemmaTransition& transition, LineRange range)
    {
        if (transition.family) {
            m_ranges.emplace(transition.id, range); // the first occurrence only
            m_ranges[transition.id + "@" + step.id] = range;
        } else {
            m_ranges[transition.id] = range;
        }
    }

    // Spec §4.3: each continuous output of the nested GRAFCETs has one
    // writer, gated by the state and by Entry, so leaving a state drops it.
    void writeContinuousOutputs()
    {
        std::vector<std::string> written; // upper case
        for (const GemmaStep& step : m_program.steps) {
            if (!step.nested)
                continue;
            for (const ContinuousOutput& output : step.nested->outputs) {
                const std::string key = toUpperAscii(output.variable);
                if (output.isComplete || std::find(written.begin(), written.end(), key) != written.end())
                    continue;
                written.push_back(key);
                if (written.size() == 1)
                    m_out.line(0, comment("Continuous outputs of the nested GRAFCETs: one writer each"));
                m_out.line(0, m_naming.global(output.variable) + " := " + continuousValue(output.variable) + ";");
            }
        }
    }

    std::string continuousValue(const std::string& variable) const
    {
        std::string value;
        for (const GemmaStep& step : m_program.steps) {
            if (!step.nested || !step.nested->output(variable))
                continue;
            const std::string own = step.nested->output(variable)->variable;
            value += (value.empty() ? "" : " OR ") + std::string("(State = ") + std::to_string(step.number)
                + " AND NOT Entry AND " + step.id + "." + own + ")";
        }
        return value;
    }

    // Spec §4.4: an edge compares with the value at the end of the previous scan.
    void writeEdgeMemories()
    {
        if (m_program.edgeVariables.empty())
            return;
        m_out.line(0, comment("Edge memories: the values at the end of this scan"));
        for (const std::string& name : m_program.edgeVariables)
            m_out.line(0, m_naming.edgeMemory(name) + " := " + m_naming.global(name) + ";");
    }

    void writeTokenUpdates()
    {
        bool any = false;
        for (const GemmaStep& step : m_program.steps) {
            for (const GemmaToken& token : step.tokens) {
                if (!any)
                    m_out.line(0, comment("Tokens: remember a pulse until the nested behaviour is complete"));
                any = true;
                std::string literal = m_naming.global(token.variable);
                if (token.polarity == TokenPolarity::NormallyClosed)
                    literal = "NOT " + literal;
                m_out.line(0, "IF State = " + std::to_string(step.number) + " AND " + literal + " THEN " + token.name
                                  + " := TRUE; END_IF;");
            }
        }
    }

    const GemmaProgram& m_program;
    Naming& m_naming;
    LineWriter m_out;
    std::map<std::string, LineRange> m_ranges;
};

PlcVariable plcVariable(std::string name, std::string typeName, std::string initialValue, std::string comment)
{
    return PlcVariable{std::move(name), std::move(typeName), std::move(initialValue), std::move(comment)};
}

struct GemmaPou {
    PlcPou pou;
    std::map<std::string, LineRange> bodyRanges; // lines counted from the first body line
};

GemmaPou buildGemmaPou(const Model& model, const GemmaProgram& program, Dialect dialect)
{
    GemmaPou result;
    PlcPou& pou = result.pou;
    pou.name = std::string(kGemmaPouName);
    pou.kind = PouKind::Program;
    pou.comment = model.settings().name + ": operating modes by the GEMMA-GRAFCET method "
                  "(Hierarchical Design Pattern), generated by GG Studio";

    pou.locals.push_back(plcVariable("State", "UINT", std::to_string(program.initialNumber),
                                     "code number of the active GEMMA state"));
    pou.locals.push_back(plcVariable("Entry", "BOOL", "TRUE", "TRUE in the first scan of a state"));
    for (const GemmaStep& step : program.steps) {
        if (step.hasNestedBehaviour())
            pou.locals.push_back(plcVariable(step.id, step.id + "_FB", {}, "nested behaviour of " + step.id + " " + step.name));
    }
    for (const GemmaStep& step : program.steps) {
        for (const GemmaToken& token : step.tokens) {
            const std::string literal = (token.polarity == TokenPolarity::NormallyClosed ? "NOT " : "") + token.variable;
            pou.locals.push_back(plcVariable(token.name, "BOOL", "FALSE", "token of " + token.transitionId + ": " + literal));
        }
    }

    Naming naming(model, dialect);
    GemmaBodyWriter writer(program, naming);
    writer.write();
    pou.body = std::move(writer.text());
    result.bodyRanges = std::move(writer.ranges());

    if (dialect == Dialect::Iec) {
        pou.externals = naming.readVariables();
        for (const std::string& name : program.edgeVariables)
            pou.externals.push_back(plcVariable(edgeMemoryName(name), "BOOL", {}, {}));
    }
    return result;
}

PlcPou buildNestedFunctionBlock(const Model& model, const GemmaProgram& program, const GemmaStep& step,
                                PlcPou pou, Dialect dialect)
{
    Naming naming(model, dialect);
    const std::function<std::string(std::string_view)> global = [&naming](std::string_view name) {
        return naming.global(name);
    };
    const std::function<std::string(std::string_view)> edgeMemory = [&naming](std::string_view name) {
        return naming.edgeMemory(name);
    };
    NestedCode code = generateNestedCode(step, program, global, edgeMemory);
    pou.outputs.insert(pou.outputs.end(), code.outputs.begin(), code.outputs.end());
    pou.locals = std::move(code.locals);
    pou.body = std::move(code.body);
    if (dialect == Dialect::Iec) {
        pou.externals = naming.readVariables();
        pou.externals.insert(pou.externals.end(), code.edgeMemories.begin(), code.edgeMemories.end());
    }
    return pou;
}

PlcPou buildNestedFunctionBlock(const Model& model, const GemmaProgram& program, const GemmaStep& step,
                                PlcPou pou, Dialect dialect);

PlcPou buildFunctionBlock(const Model& model, const GemmaProgram& program, const GemmaStep& step,
                          const Step& modelStep, Dialect dialect)
{
    PlcPou pou;
    pou.name = step.id + "_FB";
    pou.kind = PouKind::FunctionBlock;
    pou.comment = "Nested behaviour of " + step.id + " " + step.name + " (" + std::string(stepTypeName(step.type))
                  + (step.type == StepType::Macro ? "-step)" : " step)");
    if (!modelStep.comment.empty())
        pou.comment += ": " + modelStep.comment;
    pou.inputs.push_back(plcVariable("Initialization", "BOOL", {}, "TRUE in the first scan of " + step.id));
    pou.outputs.push_back(plcVariable("Complete", "BOOL", {}, "the nested behaviour has reached its exit step"));
    if (step.nested)
        return buildNestedFunctionBlock(model, program, step, std::move(pou), dialect);

    LineWriter body;
    body.line(0, "IF Initialization THEN");
    body.line(4, "Complete := FALSE;");
    body.line(4, comment("initialization actions"));
    body.line(0, "END_IF;");
    body.line(0, comment("The nested behaviour of " + step.id + " goes here; it sets Complete := TRUE at its exit step."));
    body.line(0, comment("Until it is written, the empty nested behaviour completes at once:"));
    body.line(0, "Complete := TRUE;");
    pou.body = std::move(body.text());
    return pou;
}

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

std::string initialValue(const Variable& variable, std::string& problem)
{
    return plcInitialValue(variable, problem);
}

// "ERROR GG303: invalid variable name: 'State' is a name the generated code
// uses; declared as Invalid_Name_1, and every condition that reads it is FALSE".
std::string renamedNote(const Model& model, const Variable& variable, const std::string& declaredName)
{
    const char* code = unusableNameCode(variable.name, model);
    return std::string("ERROR ") + code + ": invalid variable name: " + unusableNameDetail(variable.name, model)
           + "; declared as " + declaredName + ", and every condition that reads it is FALSE";
}

std::vector<PlcVariable> buildGlobals(const Model& model, const GemmaProgram& program)
{
    const std::vector<Variable>& variables = model.variables();
    const std::vector<std::string> names = declaredNames(model);
    std::vector<PlcVariable> globals;
    globals.reserve(variables.size());
    for (std::size_t i = 0; i < variables.size(); ++i) {
        const Variable& variable = variables[i];
        std::string problem;
        std::string value = initialValue(variable, problem);
        std::vector<std::string> notes;
        if (names[i] != variable.name)
            notes.push_back(renamedNote(model, variable, names[i]));
        if (!problem.empty())
            notes.push_back("ERROR: default " + problem + "; " + value + " is used instead");
        if (!variable.comment.empty())
            notes.push_back(variable.comment);
        std::string note;
        for (const std::string& part : notes)
            note += (note.empty() ? "" : ". ") + part;
        globals.push_back(plcVariable(names[i], std::string(iecTypeName(variable.type)), value, note));
    }
    for (const std::string& name : program.edgeVariables) {
        const Variable* variable = model.variable(name);
        std::string unused;
        globals.push_back(plcVariable(edgeMemoryName(name), "BOOL", variable ? initialValue(*variable, unused) : "FALSE",
                                      "the value of " + name + " at the end of the previous scan, for its edges"));
    }
    return globals;
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

} // namespace

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
    if (model.packml())
        return packml::buildPackmlPlcProject(model, dialect);
    const GemmaProgram program = buildGemmaProgram(model);
    PlcProject project;
    project.projectName = model.settings().name;
    project.dialect = dialect;
    project.cycleTimeMs = model.settings().cycleTimeMs;
    project.globals = buildGlobals(model, program);
    if (dialect == Dialect::Codesys)
        project.globalListName = std::string(kGlobalListName);
    project.pous.push_back(buildGemmaPou(model, program, dialect).pou);
    for (const GemmaStep& step : program.steps) {
        const Step* modelStep = model.step(step.id);
        if (step.hasNestedBehaviour() && modelStep)
            project.pous.push_back(buildFunctionBlock(model, program, step, *modelStep, dialect));
    }
    return project;
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

// The type of the configuration's program instance: the project's PROGRAM.
std::string programTypeName(const PlcProject& project)
{
    for (const PlcPou& pou : project.pous)
        if (pou.kind == PouKind::Program)
            return pou.name;
    return std::string(kGemmaPouName);
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

StPreview previewGemmaProgram(const Model& model, Dialect dialect)
{
    const GemmaProgram program = buildGemmaProgram(model);
    GemmaPou gemma = buildGemmaPou(model, program, dialect);
    StPreview preview;
    preview.text = formatPou(gemma.pou, dialect);
    const int offset = countLines(formatPouHead(gemma.pou, dialect));
    for (auto& [key, range] : gemma.bodyRanges)
        preview.ranges.emplace(key, LineRange{range.first + offset, range.last + offset});
    return preview;
}

} // namespace core
