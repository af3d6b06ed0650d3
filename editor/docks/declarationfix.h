#pragma once

#include "core/checks/diagnostic.h"
#include "core/model/model.h"

#include <QString>

#include <optional>

namespace editor {

class Document;

// The quick fix of "'start' is not a declared variable" (GG203, GG403,
// GG405): declares the name, its kind and type guessed from where the model
// uses it (core/condition/declarationguess.h), as one undoable command.
class DeclarationFix {
public:
    // nullopt when the diagnostic is no undeclared name (any more).
    static std::optional<DeclarationFix> of(const core::Model& model, const core::Diagnostic& diagnostic);

    const core::Variable& variable() const { return m_variable; }
    // "Declare 'start' as INPUT BOOL", in the UI language.
    QString text() const;
    // Pushes the declaration; false when the document refused it.
    bool apply(Document& document) const;

private:
    explicit DeclarationFix(core::Variable variable);

    core::Variable m_variable;
};

} // namespace editor
