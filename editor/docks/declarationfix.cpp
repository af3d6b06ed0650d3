#include "editor/docks/declarationfix.h"

#include "editor/commands/addvariablecommand.h"
#include "editor/document.h"
#include "editor/stdstring.h"

#include "core/checks/undeclaredvariable.h"
#include "core/condition/declarationguess.h"
#include "core/model/iectypes.h"

#include <QCoreApplication>

namespace editor {

namespace {

class DeclarationFixText {
    Q_DECLARE_TR_FUNCTIONS(DeclarationFixText)
};

} // namespace

DeclarationFix::DeclarationFix(core::Variable variable)
    : m_variable(std::move(variable))
{
}

std::optional<DeclarationFix> DeclarationFix::of(const core::Model& model, const core::Diagnostic& diagnostic)
{
    const std::optional<std::string> name = core::undeclaredVariable(model, diagnostic);
    if (!name)
        return std::nullopt;
    const core::DeclarationGuess guess = core::guessDeclaration(model, *name);
    core::Variable variable;
    variable.name = *name;
    variable.type = guess.type;
    variable.kind = guess.kind;
    return DeclarationFix(std::move(variable));
}

QString DeclarationFix::text() const
{
    const QString name = fromStd(m_variable.name);
    const QString type = fromStd(std::string(core::iecTypeName(m_variable.type)));
    switch (m_variable.kind) {
    case core::VariableKind::Output:
        //: A quick fix; %2: an IEC type name (BOOL, INT)
        return DeclarationFixText::tr("Declare '%1' as OUTPUT %2").arg(name, type);
    case core::VariableKind::Internal:
        //: A quick fix; %2: an IEC type name (BOOL, INT)
        return DeclarationFixText::tr("Declare '%1' as INTERNAL %2").arg(name, type);
    case core::VariableKind::Input:
        break;
    }
    //: A quick fix; %2: an IEC type name (BOOL, INT)
    return DeclarationFixText::tr("Declare '%1' as INPUT %2").arg(name, type);
}

bool DeclarationFix::apply(Document& document) const
{
    return document.push(new AddVariableCommand(document, m_variable));
}

} // namespace editor
