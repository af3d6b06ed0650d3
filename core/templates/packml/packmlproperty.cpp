#include "core/templates/packml/packmlproperty.h"

#include "core/condition/conditionanalysis.h"
#include "core/condition/conditionevaluator.h"
#include "core/condition/conditionparser.h"
#include "core/condition/symboltable.h"
#include "core/model/model.h"
#include "core/templates/packml/packmlprogram.h"
#include "core/templates/packml/packmlscenario.h"
#include "core/templates/packml/packmlsimulator.h"
#include "core/model/iectypes.h"

#include <algorithm>
#include <cctype>

namespace core::packml {

namespace {

PropertyProblem problem(Span span, const char* code, std::string message, std::vector<std::string> arguments)
{
    return PropertyProblem{span, code, std::move(message), std::move(arguments), std::nullopt, std::nullopt};
}

} // namespace

PackmlProperty parsePackmlProperty(std::string_view text, const PackmlProgram& program)
{
    // `mode M` becomes `in   M` (same length, so spans stay those of the
    // text as written); its node is then told from `in S` by where it starts.
    std::string rewritten(text);
    std::vector<std::size_t> modeStarts;
    const std::vector<cond::Token> tokens = cond::tokenize(text, cond::ParseOptions{cond::Context::Property});
    for (std::size_t i = 1; i + 1 < tokens.size(); ++i) {
        const cond::Token& word = tokens[i];
        if (word.kind == cond::TokenKind::Identifier && equalsIgnoreCase(word.text, "mode")
            && tokens[i + 1].kind == cond::TokenKind::Identifier) {
            rewritten.replace(word.span.begin, word.span.end - word.span.begin, "in  ");
            modeStarts.push_back(word.span.begin);
        }
    }
    PackmlProperty property;
    property.parsed = parseProperty(rewritten);
    const cond::Expression& body = property.parsed.expression;
    property.resolved.assign(body.nodes.size(), -1);
    property.isMode.assign(body.nodes.size(), false);
    if (!property.parsed.ok())
        return property;
    for (std::size_t n = 0; n < body.nodes.size(); ++n) {
        const cond::Node& node = body.nodes[n];
        if (node.kind == cond::NodeKind::InStep) {
            property.isMode[n] = std::find(modeStarts.begin(), modeStarts.end(), node.span.begin) != modeStarts.end();
            if (property.isMode[n]) {
                property.resolved[n] = findModeNamed(program, node.text).value_or(-1);
            } else if (const std::optional<State> state = findStateNamed(node.text)) {
                property.resolved[n] = static_cast<int>(*state);
            }
        } else if (node.kind == cond::NodeKind::NestedStepActivity) {
            property.resolved[n] = findInstanceNamed(program, node.text).value_or(-1);
        } else if (node.kind == cond::NodeKind::Variable) {
            property.reads.push_back(node.text);
        }
    }
    return property;
}

std::vector<PropertyProblem> checkPackmlProperty(const Model& model, std::string_view text)
{
    const PackmlProgram program = buildPackmlProgram(model);
    const PackmlProperty property = parsePackmlProperty(text, program);
    if (!property.parsed.ok()) {
        PropertyProblem syntax = problem(property.parsed.error->span, core::property::kSyntax,
                                         property.parsed.error->message, {});
        syntax.syntax = property.parsed.error;
        return {syntax};
    }
    std::vector<PropertyProblem> problems;
    const cond::Expression& body = property.parsed.expression;
    for (std::size_t n = 0; n < body.nodes.size(); ++n) {
        const cond::Node& node = body.nodes[n];
        if (node.kind == cond::NodeKind::InStep && property.resolved[n] < 0) {
            const std::string what = property.isMode[n] ? "unit mode" : "PackML state";
            problems.push_back(problem(node.span, core::property::kUnknownStep,
                                       "there is no " + what + " '" + node.text + "'", {node.text}));
        }
        if (node.kind != cond::NodeKind::NestedStepActivity)
            continue;
        if (property.resolved[n] < 0) {
            problems.push_back(problem(node.span, core::property::kUnknownStep,
                                       "there is no instance '" + node.text + "' (<Mode>_<State> of an enabled state)",
                                       {node.text}));
            continue;
        }
        const ProgramInstance& instance = program.instances[static_cast<std::size_t>(property.resolved[n])];
        if (instance.isSkeleton()) {
            problems.push_back(problem(node.span, core::property::kNoGrafcet,
                                       "the instance " + instance.name + " has no nested GRAFCET", {instance.name}));
            continue;
        }
        const NestedGrafcet& grafcet = program.grafcets[static_cast<std::size_t>(instance.grafcet)].grafcet;
        if (!grafcet.step(node.number)) {
            const std::string number = std::to_string(node.number);
            problems.push_back(problem(node.span, core::property::kUnknownNestedStep,
                                       "the GRAFCET of " + instance.name + " has no step " + number,
                                       {instance.name, number}));
        }
    }
    const SymbolTable symbols(program.variables);
    for (const cond::TypeIssue& issue : cond::typeCheck(body, symbols)) {
        const bool unknown = issue.code == "GG203";
        PropertyProblem found = problem(issue.span, unknown ? core::property::kUnknownVariable : core::property::kType,
                                        issue.message, {});
        if (unknown)
            for (const cond::Node& node : body.nodes)
                if (node.kind == cond::NodeKind::Variable && node.span == issue.span)
                    found.arguments = {node.text};
        found.type = issue.error;
        problems.push_back(std::move(found));
    }
    return problems;
}

bool packmlPropertyViolated(const PackmlProperty& property, const PackmlSimulator& simulator)
{
    const cond::Expression& body = property.parsed.expression;
    const cond::Value value = cond::evaluate(body, [&](int index) -> cond::Value {
        const cond::Node& node = body.at(index);
        const int resolved = property.resolved[static_cast<std::size_t>(index)];
        switch (node.kind) {
        case cond::NodeKind::InStep:
            return property.isMode[static_cast<std::size_t>(index)] ? simulator.mode() == resolved
                                                                    : static_cast<int>(simulator.state()) == resolved;
        case cond::NodeKind::NestedStepActivity: {
            if (resolved < 0)
                return false;
            const ProgramInstance& instance = simulator.program().instances[static_cast<std::size_t>(resolved)];
            const NestedEngine* engine = simulator.engine(resolved);
            if (!engine || simulator.mode() != instance.mode || simulator.state() != instance.state || simulator.entry())
                return false;
            const std::vector<int> active = engine->activeSteps();
            return std::find(active.begin(), active.end(), node.number) != active.end();
        }
        default:
            return simulator.value(node.text).value_or(cond::Value{false});
        }
    });
    const bool holds = cond::isTrue(value);
    return property.parsed.kind == PropertyKind::Never ? holds : !holds;
}

} // namespace core::packml
