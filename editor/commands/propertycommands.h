#pragma once

// The edits of the engineer's verification properties (core::Model::properties),
// by position in the list: add, remove, move, and the text and comment of one
// (typing in the same field of the same property merges into one step).

#include "editor/commands/modelcommand.h"
#include "editor/commands/textfieldcommand.h"

#include "core/model/userproperty.h"

#include <QCoreApplication>

namespace editor {

// "Add property": at `index` (0-based; -1 appends).
class AddPropertyCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(AddPropertyCommand)

public:
    AddPropertyCommand(Document& document, core::UserProperty property, int index = -1);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    core::UserProperty m_property;
    int m_index;
    int m_added = -1;
};

// "Remove property 2".
class RemovePropertyCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(RemovePropertyCommand)

public:
    RemovePropertyCommand(Document& document, int index);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    int m_index;
    core::UserProperty m_removed;
};

// "Move property 2": to another position.
class MovePropertyCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(MovePropertyCommand)

public:
    MovePropertyCommand(Document& document, int from, int to);
    int id() const override;

private:
    core::Status apply() override;
    core::Status revert() override;

    int m_from;
    int m_to;
};

// "Edit property 2".
class SetPropertyTextCommand : public TextFieldCommand {
    Q_DECLARE_TR_FUNCTIONS(SetPropertyTextCommand)

public:
    SetPropertyTextCommand(Document& document, int index, const QString& text);
    int id() const override;

private:
    std::string read(const std::string& element) const override;
    core::Status write(const std::string& element, const std::string& value) override;
};

// "Edit comment of property 2".
class SetPropertyCommentCommand : public TextFieldCommand {
    Q_DECLARE_TR_FUNCTIONS(SetPropertyCommentCommand)

public:
    SetPropertyCommentCommand(Document& document, int index, const QString& comment);
    int id() const override;

private:
    std::string read(const std::string& element) const override;
    core::Status write(const std::string& element, const std::string& value) override;
};

} // namespace editor
