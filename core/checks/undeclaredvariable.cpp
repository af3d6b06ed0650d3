#include "core/checks/undeclaredvariable.h"

#include "core/condition/conditionparser.h"
#include "core/condition/symboltable.h"
#include "core/model/iectypes.h"
#include "core/model/model.h"
#include "core/templates/packml/packmlconfiguration.h"

namespace core {

namespace {

// The text the diagnostic's span points into, with the context it is read in.
const std::string* fieldText(const Model& model, const Diagnostic& diagnostic, cond::Context& context)
{
    context = cond::Context::Nested;
    switch (diagnostic.target) {
    case Diagnostic::Target::Transition: {
        context = cond::Context::Gemma;
        const Transition* transition = model.transition(diagnostic.element);
        return transition ? &transition->condition : nullptr;
    }
    case Diagnostic::Target::GrafcetTransition: {
        const Grafcet* grafcet = model.grafcet(diagnostic.element);
        const GrafcetTransition* transition = grafcet ? grafcet->transition(diagnostic.nestedNumber) : nullptr;
        return transition ? &transition->receptivity : nullptr;
    }
    case Diagnostic::Target::GrafcetStep: {
        const Grafcet* grafcet = model.grafcet(diagnostic.element);
        const GrafcetStep* step = grafcet ? grafcet->step(diagnostic.nestedNumber) : nullptr;
        if (!step || diagnostic.actionIndex < 0 || static_cast<std::size_t>(diagnostic.actionIndex) >= step->actions.size())
            return nullptr;
        return &step->actions[static_cast<std::size_t>(diagnostic.actionIndex)].text;
    }
    case Diagnostic::Target::Command: {
        context = cond::Context::Gemma;
        const std::optional<packml::Command> command = packml::findCommand(diagnostic.element);
        return model.packml() && command ? &model.packml()->command(*command).condition : nullptr;
    }
    case Diagnostic::Target::Request: {
        context = cond::Context::Gemma;
        const packml::Mode* mode = model.packml() ? model.packml()->mode(diagnostic.mode) : nullptr;
        return mode ? &mode->request : nullptr;
    }
    default:
        return nullptr;
    }
}

bool isOneIdentifier(std::string_view text, cond::Context context)
{
    const std::vector<cond::Token> tokens = cond::tokenize(text, {context});
    return tokens.size() == 2 && tokens[0].kind == cond::TokenKind::Identifier && tokens[0].text == text;
}

} // namespace

std::optional<std::string> undeclaredVariable(const Model& model, const Diagnostic& diagnostic)
{
    if (diagnostic.code != "GG203" && diagnostic.code != "GG403" && diagnostic.code != "GG405")
        return std::nullopt;
    if (!diagnostic.span)
        return std::nullopt;
    cond::Context context = cond::Context::Gemma;
    const std::string* text = fieldText(model, diagnostic, context);
    if (!text)
        return std::nullopt;
    std::string name = excerpt(*text, *diagnostic.span);
    if (!isOneIdentifier(name, context) || identifierProblem(name) != IdentifierProblem::None)
        return std::nullopt;
    if (SymbolTable(model.variables()).find(name))
        return std::nullopt;
    return name;
}

} // namespace core
