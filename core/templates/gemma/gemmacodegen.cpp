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

#include "core/templates/gemma/gemmacodegen.h"

#include "core/codegen/linewriter.h"
#include "core/codegen/nestedcode.h"
#include "core/codegen/stgenerator.h"
#include "core/condition/conditionanalysis.h"
#include "core/condition/symboltable.h"
#include "core/templates/gemma/gemmaprogram.h"

#include <algorithm>
#include <functional>
#include <string_view>

namespace core {

namespace {

constexpr std::string_view kGemmaPouName = "GEMMA";

std::string comment(std::string_view text)
{
    return formatComment(text);
}

std::string problemComment(const ProgramProblem& problem)
{
    std::string text = problem.kind == ProgramProblem::Kind::Error ? "ERROR" : "WARNING";
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
            return std::string(kCodesysGlobalList) + "." + name;
        return name;
    }

    // An edge memory global: "Start_PREV" or "GVL.Start_PREV".
    std::string edgeMemory(std::string_view writtenName) const
    {
        const Variable* variable = m_symbols.find(writtenName);
        const std::string name = edgeMemoryName(variable ? variable->name : std::string(writtenName));
        return m_dialect == Dialect::Codesys ? std::string(kCodesysGlobalList) + "." + name : name;
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
        for (const ProgramProblem& problem : m_program.problems) {
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
    static bool isTransitionProblem(const ProgramProblem& problem)
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
            for (const ProgramProblem& problem : transition.problems)
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
        std::string value = plcInitialValue(variable, problem);
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
        globals.push_back(plcVariable(edgeMemoryName(name), "BOOL", variable ? plcInitialValue(*variable, unused) : "FALSE",
                                      "the value of " + name + " at the end of the previous scan, for its edges"));
    }
    return globals;
}

} // namespace

PlcProject buildGemmaPlcProject(const Model& model, Dialect dialect)
{
    const GemmaProgram program = buildGemmaProgram(model);
    PlcProject project = startPlcProject(model, dialect);
    project.globals = buildGlobals(model, program);
    project.pous.push_back(buildGemmaPou(model, program, dialect).pou);
    for (const GemmaStep& step : program.steps) {
        const Step* modelStep = model.step(step.id);
        if (step.hasNestedBehaviour() && modelStep)
            project.pous.push_back(buildFunctionBlock(model, program, step, *modelStep, dialect));
    }
    return project;
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
