#include "core/verification/property.h"

#include "core/condition/conditionanalysis.h"
#include "core/condition/conditionparser.h"
#include "core/condition/symboltable.h"
#include "core/model/model.h"
#include "core/templates/templateengines.h"

#include <algorithm>
#include <cctype>

namespace core {

namespace {

const cond::ParseOptions kPropertyContext{cond::Context::Property};

std::optional<PropertyKind> quantifier(std::string_view word)
{
    auto equals = [word](std::string_view name) {
        if (word.size() != name.size())
            return false;
        for (std::size_t i = 0; i < word.size(); ++i) {
            if (std::tolower(static_cast<unsigned char>(word[i])) != name[i])
                return false;
        }
        return true;
    };
    if (equals("never"))
        return PropertyKind::Never;
    if (equals("always"))
        return PropertyKind::Always;
    return std::nullopt;
}

PropertyProblem problem(Span span, const char* code, std::string message, std::vector<std::string> arguments = {})
{
    return PropertyProblem{span, code, std::move(message), std::move(arguments), std::nullopt, std::nullopt};
}

void checkStatePredicate(const Model& model, const cond::Node& node, std::vector<PropertyProblem>& problems)
{
    const std::string stepId = propertyStepId(model, node.text);
    if (stepId.empty()) {
        problems.push_back(problem(node.span, property::kUnknownStep,
                                   "there is no visible GEMMA step '" + node.text + "'", {node.text}));
        return;
    }
    if (node.kind != cond::NodeKind::NestedStepActivity)
        return;
    const Grafcet* grafcet = model.effectiveGrafcet(stepId);
    if (!grafcet) {
        problems.push_back(problem(node.span, property::kNoGrafcet,
                                   "the step " + stepId + " has no nested GRAFCET", {stepId}));
        return;
    }
    for (const GrafcetStep& step : grafcet->steps()) {
        if (step.number == node.number)
            return;
    }
    const std::string number = std::to_string(node.number);
    problems.push_back(problem(node.span, property::kUnknownNestedStep,
                               "the GRAFCET of " + stepId + " has no step " + number, {stepId, number}));
}

} // namespace

ParsedProperty parseProperty(std::string_view text)
{
    ParsedProperty parsed;
    const std::vector<cond::Token> tokens = cond::tokenize(text, kPropertyContext);
    const cond::Token& first = tokens.front();
    const std::optional<PropertyKind> kind
        = first.kind == cond::TokenKind::Identifier ? quantifier(first.text) : std::nullopt;
    if (!kind) {
        const bool blank = first.kind == cond::TokenKind::End;
        parsed.error = cond::makeParseError(cond::ParseError::Kind::PropertyQuantifier,
                                            blank ? Span{0, text.size()} : first.span,
                                            blank ? std::string_view() : first.text);
        return parsed;
    }
    parsed.kind = *kind;
    cond::ParseResult body = cond::parseTokens(text, tokens, 1, tokens.size() - 1, kPropertyContext);
    if (!body.ok() && body.error->kind == cond::ParseError::Kind::Empty)
        body.error = cond::makeParseError(cond::ParseError::Kind::OperandAfter, Span{text.size(), text.size()}, {},
                                          first.text);
    parsed.expression = std::move(body.expression);
    parsed.error = std::move(body.error);
    return parsed;
}

std::string propertyStepId(const Model& model, std::string_view written)
{
    for (const Step& step : model.steps()) {
        if (step.hidden || step.id.size() != written.size())
            continue;
        bool same = true;
        for (std::size_t i = 0; i < written.size() && same; ++i)
            same = std::toupper(static_cast<unsigned char>(written[i])) == step.id[i];
        if (same)
            return step.id;
    }
    return {};
}

std::vector<PropertyProblem> checkProperty(const Model& model, std::string_view text)
{
    return enginesOf(model).checkProperty(model, text);
}

std::vector<PropertyProblem> checkProperty(const Model& model, std::string_view text, const PropertyAtoms& atoms)
{
    if (model.templateKind() == TemplateKind::Gemma)
        return checkGemmaProperty(model, text, atoms);
    return checkProperty(model, text);
}

bool isFaultedAtom(const Model& model, const cond::Node& node)
{
    if (node.kind == cond::NodeKind::StepDuration)
        return node.number == 0;
    if (node.kind != cond::NodeKind::Variable || node.text.size() != 7)
        return false;
    for (std::size_t i = 0; i < 7; ++i) {
        if (std::tolower(static_cast<unsigned char>(node.text[i])) != "faulted"[i])
            return false;
    }
    return !SymbolTable(model.variables()).find(node.text);
}

std::int64_t faultedScansFor(std::int64_t durationMs, int cycleTimeMs)
{
    const std::int64_t cycle = std::max(cycleTimeMs, 1);
    return std::max<std::int64_t>(1, durationMs / cycle + (durationMs % cycle != 0 ? 1 : 0));
}

std::vector<PropertyProblem> checkGemmaProperty(const Model& model, std::string_view text)
{
    return checkGemmaProperty(model, text, PropertyAtoms{});
}

std::vector<PropertyProblem> checkGemmaProperty(const Model& model, std::string_view text, const PropertyAtoms& atoms)
{
    const ParsedProperty parsed = parseProperty(text);
    if (!parsed.ok()) {
        PropertyProblem syntax = problem(parsed.error->span, property::kSyntax, parsed.error->message);
        syntax.syntax = parsed.error;
        return {syntax};
    }
    std::vector<PropertyProblem> problems;
    std::vector<Span> faultedAtoms; // where the property reads the atoms
    for (const cond::Node& node : parsed.expression.nodes) {
        if (node.kind == cond::NodeKind::InStep || node.kind == cond::NodeKind::NestedStepActivity)
            checkStatePredicate(model, node, problems);
        if (isFaultedAtom(model, node)) {
            faultedAtoms.push_back(node.span);
            if (!atoms.faulted)
                problems.push_back(problem(node.span, property::kFaultedWithoutFaults,
                                           "'" + node.text
                                               + "' is only defined when verifying with single faults "
                                                 "(--faults single, with the machine)",
                                           {node.text}));
        }
    }
    // `faulted` reads as a BOOL of the run, not a variable of the model.
    std::vector<Variable> variables = model.variables();
    if (!faultedAtoms.empty())
        variables.push_back(Variable{"faulted", IecType::Bool, {}, {}, VariableKind::Input});
    const SymbolTable symbols(variables);
    for (const cond::TypeIssue& issue : cond::typeCheck(parsed.expression, symbols)) {
        const bool unknown = issue.code == "GG203";
        PropertyProblem found = problem(issue.span, unknown ? property::kUnknownVariable : property::kType,
                                        issue.message);
        if (unknown) {
            for (const cond::Node& node : parsed.expression.nodes) {
                if (node.kind == cond::NodeKind::Variable && node.span == issue.span)
                    found.arguments = {node.text};
            }
        }
        found.type = issue.error;
        problems.push_back(std::move(found));
    }
    return problems;
}

} // namespace core
