#pragma once

#include "editor/commands/modelcommand.h"

namespace core {
struct Variable;
}

namespace editor {

// Base of the edits of a variable's text fields (default, comment):
// consecutive edits of the same field of the same variable merge into one
// undo step, so typing undoes as a whole. Subclasses say which field, and
// give each field its own id() so that typing in another field starts a new step.
class VariableTextCommand : public ModelCommand {
public:
    bool mergeWith(const QUndoCommand* other) override;

protected:
    VariableTextCommand(Document& document, const QString& text, const QString& name, const QString& value);

    virtual std::string field(const core::Variable& variable) const = 0;
    virtual core::Status setField(const std::string& name, const std::string& value) = 0;

private:
    core::Status apply() final;
    core::Status revert() final;

    std::string m_name;
    std::string m_value;
    std::string m_previous;
};

} // namespace editor
