#pragma once

#include "editor/commands/modelcommand.h"

namespace editor {

// Base of the edits of one text field of one element of a nested GRAFCET (a
// transition's receptivity, a step's comment), addressed by GEMMA step id and
// nested number: consecutive edits of the same field of the same element
// merge into one undo step, and typing back to where it started leaves none,
// as TextFieldCommand does for the GEMMA layer's fields.
class GrafcetTextCommand : public ModelCommand {
public:
    bool mergeWith(const QUndoCommand* other) override;

protected:
    GrafcetTextCommand(Document& document, Wording wording, const QString& stepId, int number, const QString& value);

    // The field's value before the first edit; empty when there is no such
    // element (writing then fails and says why).
    virtual std::string read(const std::string& stepId, int number) const = 0;
    virtual core::Status write(const std::string& stepId, int number, const std::string& value) = 0;

private:
    core::Status apply() final;
    core::Status revert() final;

    std::string m_stepId;
    int m_number;
    std::string m_value;
    std::string m_previous;
};

} // namespace editor
