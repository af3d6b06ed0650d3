#include "core/templates/packml/packmlconditionchecks.h"

#include "core/condition/blanktext.h"
#include "core/condition/conditionanalysis.h"
#include "core/condition/conditionparser.h"
#include "core/condition/symboltable.h"
#include "core/model/iectypes.h"
#include "core/model/model.h"
#include "core/templates/packml/packmldiagnostics.h"
#include "core/templates/packml/packtags.h"

#include <functional>
#include <optional>
#include <set>
#include <string>

namespace core::packml {

namespace {

// The user's variables and the PackTags globals a condition may read; a
// user variable of the same name hides the global (PM018 reports it).
std::vector<Variable> readableVariables(const Model& model)
{
    std::vector<Variable> variables = model.variables();
    for (Variable& tag : packTagVariables(*model.packml()))
        if (model.variable(tag.name) == nullptr)
            variables.push_back(std::move(tag));
    return variables;
}

// The construct of a nested GRAFCET's text a node is, or nullptr.
const char* nestedOnlyKind(const cond::Node& node)
{
    switch (node.kind) {
    case cond::NodeKind::StepActivity: return "step-activity";
    case cond::NodeKind::StepDuration: return "step-duration";
    case cond::NodeKind::Complete: return "complete";
    case cond::NodeKind::Unary:
        return node.unaryOp == cond::UnaryOp::RisingEdge || node.unaryOp == cond::UnaryOp::FallingEdge ? "edge"
                                                                                                       : nullptr;
    default: return nullptr;
    }
}

std::string nestedOnlyWords(std::string_view kind)
{
    if (kind == "step-activity")
        return "a step activity";
    if (kind == "step-duration")
        return "a step duration";
    if (kind == "complete")
        return "Complete";
    return "an edge";
}

// One command or request condition, as checked.
struct CheckedCondition {
    std::vector<Finding> findings;
    std::optional<cond::Expression> expression; // when it parses without error
};

class ConditionChecker {
public:
    explicit ConditionChecker(const Model& model)
        : m_variables(readableVariables(model))
        , m_symbols(m_variables)
    {
    }

    // `label` names the element in messages: "command Hold".
    CheckedCondition check(const std::string& label, const std::string& text) const
    {
        CheckedCondition checked;
        if (isBlank(text)) {
            checked.findings.push_back({"GG202", Severity::Error, "condition",
                                        "the condition of " + label
                                            + " is empty: write FALSE for a command that comes only through CntrlCmd",
                                        {label}});
            return checked;
        }
        if (findNestedOnly(label, text, checked.findings))
            return checked;
        const cond::ParseResult parsed = cond::parse(text);
        if (!parsed.ok()) {
            const cond::ParseError& error = *parsed.error;
            std::vector<std::string> arguments{label, excerpt(text, error.span), error.message};
            cond::appendArguments(error, arguments);
            checked.findings.push_back({"GG201", Severity::Error, "condition",
                                        "syntax error in the condition of " + label + ": " + error.message,
                                        std::move(arguments), error.span});
            return checked;
        }
        const std::vector<cond::TypeIssue> issues = cond::typeCheck(parsed.expression, m_symbols);
        for (const cond::TypeIssue& issue : issues) {
            std::vector<std::string> arguments{label, excerpt(text, issue.span), issue.message};
            if (issue.error)
                cond::appendArguments(*issue.error, arguments);
            checked.findings.push_back({issue.code, Severity::Error, "condition",
                                        "in the condition of " + label + ": " + issue.message, std::move(arguments),
                                        issue.span});
        }
        if (!issues.empty())
            return checked;
        findOutputsRead(label, parsed.expression, checked.findings);
        checked.expression = parsed.expression;
        return checked;
    }

    // Identical conditions compare by their parse, names in any case.
    std::string canonical(const cond::Expression& expression) const
    {
        cond::PrintOptions options;
        options.variableName = [](const cond::Node& node) { return toUpperAscii(node.text); };
        return cond::print(expression, options);
    }

private:
    // PM019: read in the texts of nested GRAFCETs, the condition uses what
    // only they have. Reported instead of the syntax or undeclared-variable
    // error the GEMMA language would give.
    bool findNestedOnly(const std::string& label, const std::string& text, std::vector<Finding>& findings) const
    {
        const cond::ParseResult nested = cond::parse(text, cond::ParseOptions{cond::Context::Nested});
        if (!nested.ok())
            return false;
        bool found = false;
        for (const cond::Node& node : nested.expression.nodes) {
            const char* kind = nestedOnlyKind(node);
            if (kind == nullptr)
                continue;
            found = true;
            const std::string written = excerpt(text, node.span);
            findings.push_back({"PM019", Severity::Error, "condition",
                                "the condition of " + label + " uses " + nestedOnlyWords(kind) + " ('" + written
                                    + "'), which only the texts of nested GRAFCETs have; a command or request is "
                                      "already the rising edge of its condition",
                                {label, written, kind}, node.span});
        }
        return found;
    }

    // PM012, once per variable, where it is first read.
    void findOutputsRead(const std::string& label, const cond::Expression& expression,
                         std::vector<Finding>& findings) const
    {
        std::set<const Variable*> reported;
        for (int index : cond::variableNodes(expression)) {
            const Variable* variable = m_symbols.find(expression.at(index).text);
            if (variable == nullptr || variable->kind != VariableKind::Output || !reported.insert(variable).second)
                continue;
            findings.push_back({"PM012", Severity::Warning, "condition",
                                "the condition of " + label + " reads the output '" + variable->name
                                    + "': commands and mode requests come from an operator, a line controller or an "
                                      "alarm, so read an input or an internal variable",
                                {label, variable->name}, expression.at(index).span});
        }
    }

    std::vector<Variable> m_variables;
    SymbolTable m_symbols;
};

bool isConstantFalse(const cond::Expression& expression)
{
    const cond::Node& root = expression.rootNode();
    return root.kind == cond::NodeKind::BoolLiteral && equalsIgnoreCase(root.text, "FALSE");
}

// One checked condition of a list (the commands, or the requests) with its
// name for PM011 and how to address its diagnostics.
struct ListedCondition {
    std::string name; // "Start", or the mode's label
    CheckedCondition checked;
    std::function<Diagnostic(Finding)> address;
};

// PM011 on the later of two conditions of one list that parse alike; FALSE
// is how a command says it comes only through CntrlCmd, so it repeats freely.
void findIdenticalConditions(const ConditionChecker& checker, std::vector<ListedCondition>& list,
                             std::string_view what)
{
    std::vector<std::string> canonical;
    for (const ListedCondition& item : list)
        canonical.push_back(item.checked.expression && !isConstantFalse(*item.checked.expression)
                                ? checker.canonical(*item.checked.expression)
                                : std::string());
    for (std::size_t later = 0; later < list.size(); ++later) {
        for (std::size_t first = 0; first < later; ++first) {
            if (canonical[later].empty() || canonical[first] != canonical[later])
                continue;
            list[later].checked.findings.push_back(
                {"PM011", Severity::Warning, "condition",
                 std::string(what) + " " + list[later].name + " has the same condition as " + std::string(what) + " "
                     + list[first].name + ": one rising edge issues both, and only the first in priority acts",
                 {list[first].name, list[later].name}});
            break;
        }
    }
}

void flushList(std::vector<ListedCondition>& list, std::vector<Diagnostic>& result)
{
    for (ListedCondition& item : list)
        for (Finding& finding : item.checked.findings)
            result.push_back(item.address(std::move(finding)));
}

} // namespace

std::vector<Diagnostic> checkConditions(const Model& model)
{
    const Configuration& configuration = *model.packml();
    const ConditionChecker checker(model);
    std::vector<Diagnostic> result;

    std::vector<ListedCondition> commands;
    for (const CommandInfo& info : allCommands()) {
        if (!commandInEdition(info.command, configuration.options.edition))
            continue;
        const std::string label = "command " + std::string(info.name);
        const Command command = info.command;
        commands.push_back({std::string(info.name), checker.check(label, configuration.command(command).condition),
                            [command](Finding f) { return commandDiagnostic(command, std::move(f)); }});
    }
    findIdenticalConditions(checker, commands, "command");
    flushList(commands, result);

    std::vector<ListedCondition> requests;
    for (const Mode& mode : configuration.modes) {
        if (isBlank(mode.request))
            continue;
        const std::string label = "request of mode " + modeLabel(mode);
        requests.push_back({modeLabel(mode), checker.check(label, mode.request),
                            [&mode](Finding f) { return requestDiagnostic(mode, std::move(f)); }});
    }
    findIdenticalConditions(checker, requests, "the request of mode");
    flushList(requests, result);
    return result;
}

} // namespace core::packml
