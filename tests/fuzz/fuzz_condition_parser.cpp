// libFuzzer target: the condition parser (all three contexts), verification properties, the action parser,
// the type checker and the printer on arbitrary text. Spans must stay inside the text, and printing must be a
// fixed point: the printed condition parses and prints to itself.

#include "core/condition/actionparser.h"
#include "core/condition/conditionanalysis.h"
#include "core/condition/conditionparser.h"
#include "core/model/model.h"
#include "core/condition/symboltable.h"
#include "core/verification/property.h"

#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace {

void expect(bool condition)
{
    if (!condition)
        std::abort();
}

const std::vector<core::Variable>& variables()
{
    static const std::vector<core::Variable> list = {
        {"Start", core::IecType::Bool, "", ""},
        {"Stop", core::IecType::Bool, "TRUE", ""},
        {"Count", core::IecType::Int, "", ""},
        {"Level", core::IecType::Usint, "", ""},
        {"Speed", core::IecType::Real, "", ""},
        {"Total", core::IecType::Lreal, "", ""},
    };
    return list;
}

bool spanInside(const core::Span& span, std::size_t size)
{
    return span.begin <= span.end && span.end <= size;
}

// One context: tokens and spans inside the text, printing a fixed point.
void checkCondition(std::string_view text, const core::cond::ParseOptions& options)
{
    static const core::SymbolTable symbols(variables());
    const std::size_t size = text.size();
    for (const core::cond::Token& token : core::cond::tokenize(text, options))
        expect(spanInside(token.span, size));
    core::cond::renameIdentifier(text, "Start", "Go", options);

    const core::cond::ParseResult parsed = core::cond::parse(text, options);
    if (!parsed.ok()) {
        expect(spanInside(parsed.error->span, size));
        expect(!parsed.error->message.empty());
        return;
    }
    const core::cond::Expression& expression = parsed.expression;
    for (const core::cond::Node& node : expression.nodes)
        expect(spanInside(node.span, size));
    for (const core::cond::TypeIssue& issue : core::cond::typeCheck(expression, symbols))
        expect(spanInside(issue.span, size));
    core::cond::booleanLiterals(expression);
    core::cond::needsParenthesesBeforeAnd(expression);

    const std::string printed = core::cond::print(expression);
    const core::cond::ParseResult reparsed = core::cond::parse(printed, options);
    expect(reparsed.ok());
    expect(core::cond::print(reparsed.expression) == printed);
}

// An action: spans inside the whole text, the expressions print and re-parse.
void checkAction(std::string_view text)
{
    const core::cond::ActionParseResult parsed = core::cond::parseAction(text);
    if (!parsed.ok()) {
        expect(spanInside(parsed.error->span, text.size()));
        expect(!parsed.error->message.empty());
        return;
    }
    expect(spanInside(parsed.action.targetSpan, text.size()));
    for (const core::cond::Expression* expression : {&parsed.action.condition, &parsed.action.value}) {
        for (const core::cond::Node& node : expression->nodes)
            expect(spanInside(node.span, text.size()));
        if (!expression->empty())
            expect(core::cond::parse(core::cond::print(*expression), {core::cond::Context::Nested}).ok());
    }
}

// A verification property: every problem's span inside the text.
void checkProperty(std::string_view text)
{
    static const core::Model model;
    for (const core::PropertyProblem& problem : core::checkProperty(model, text)) {
        expect(spanInside(problem.span, text.size()));
        expect(!problem.message.empty());
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    checkCondition(text, {});
    checkCondition(text, {core::cond::Context::Nested});
    checkCondition(text, {core::cond::Context::Property});
    checkAction(text);
    checkProperty(text);
    return 0;
}
