#pragma once

#include "editor/commands/modelcommand.h"

namespace editor {

// Base of the edits of one text field of one element (a transition's
// condition, a step's comment, a variable's default or comment): consecutive
// edits of the same field of the same element merge into one undo step, so
// typing undoes as a whole, and typing back to where it started leaves no
// step. Subclasses give each field its own id() and say how to read and
// write it.
class TextFieldCommand : public ModelCommand {
public:
    bool mergeWith(const QUndoCommand* other) override;

protected:
    // How element names compare: variable names ignore case (IEC 61131-3).
    enum class NameCase { Exact, Ignored };

    TextFieldCommand(Document& document, Wording wording, const QString& element, const QString& value,
        NameCase nameCase = NameCase::Exact);

    // The field's value before the first edit; empty when there is no such
    // element (writing then fails and says why).
    virtual std::string read(const std::string& element) const = 0;
    virtual core::Status write(const std::string& element, const std::string& value) = 0;
    // Whether the model accepts `value` at all (an edit it refuses never
    // enters the stack); undo restores the previous value without asking.
    virtual core::Status validate(const std::string& element, const std::string& value) const;

private:
    core::Status apply() final;
    core::Status revert() final;

    NameCase m_nameCase;
    std::string m_element;
    std::string m_value;
    std::string m_previous;
};

} // namespace editor
