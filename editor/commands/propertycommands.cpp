#include "editor/commands/propertycommands.h"

#include "editor/commands/commandids.h"

#include "core/model/model.h"

namespace editor {

namespace {

// The element key of the text-field commands: the position, as text.
int positionOf(const std::string& element)
{
    try {
        return std::stoi(element);
    } catch (const std::exception&) {
        return -1;
    }
}

const core::UserProperty* propertyAt(const core::Model& model, const std::string& element)
{
    const int index = positionOf(element);
    const auto& properties = model.properties();
    return index >= 0 && index < static_cast<int>(properties.size()) ? &properties[static_cast<std::size_t>(index)]
                                                                      : nullptr;
}

} // namespace

AddPropertyCommand::AddPropertyCommand(Document& document, core::UserProperty property, int index)
    : ModelCommand(document, [=] { return tr("Add property"); })
    , m_property(std::move(property))
    , m_index(index)
{
}

int AddPropertyCommand::id() const
{
    return AddPropertyId;
}

core::Status AddPropertyCommand::apply()
{
    m_added = m_index < 0 ? static_cast<int>(model().properties().size()) : m_index;
    return model().addProperty(m_property, m_index);
}

core::Status AddPropertyCommand::revert()
{
    return model().removeProperty(m_added);
}

RemovePropertyCommand::RemovePropertyCommand(Document& document, int index)
    : ModelCommand(document, [=] { return tr("Remove property %1").arg(index + 1); })
    , m_index(index)
{
}

int RemovePropertyCommand::id() const
{
    return RemovePropertyId;
}

core::Status RemovePropertyCommand::apply()
{
    if (firstRun() && m_index >= 0 && m_index < static_cast<int>(model().properties().size()))
        m_removed = model().properties()[static_cast<std::size_t>(m_index)];
    return model().removeProperty(m_index);
}

core::Status RemovePropertyCommand::revert()
{
    return model().addProperty(m_removed, m_index);
}

MovePropertyCommand::MovePropertyCommand(Document& document, int from, int to)
    : ModelCommand(document, [=] { return tr("Move property %1").arg(from + 1); })
    , m_from(from)
    , m_to(to)
{
}

int MovePropertyCommand::id() const
{
    return MovePropertyId;
}

core::Status MovePropertyCommand::apply()
{
    return model().moveProperty(m_from, m_to);
}

core::Status MovePropertyCommand::revert()
{
    return model().moveProperty(m_to, m_from);
}

SetPropertyTextCommand::SetPropertyTextCommand(Document& document, int index, const QString& text)
    : TextFieldCommand(
        document, [=] { return tr("Edit property %1").arg(index + 1); }, QString::number(index), text)
{
}

int SetPropertyTextCommand::id() const
{
    return SetPropertyTextId;
}

std::string SetPropertyTextCommand::read(const std::string& element) const
{
    const core::UserProperty* property = propertyAt(model(), element);
    return property ? property->text : std::string();
}

core::Status SetPropertyTextCommand::write(const std::string& element, const std::string& value)
{
    return model().setPropertyText(positionOf(element), value);
}

SetPropertyCommentCommand::SetPropertyCommentCommand(Document& document, int index, const QString& comment)
    : TextFieldCommand(
        document, [=] { return tr("Edit comment of property %1").arg(index + 1); }, QString::number(index), comment)
{
}

int SetPropertyCommentCommand::id() const
{
    return SetPropertyCommentId;
}

std::string SetPropertyCommentCommand::read(const std::string& element) const
{
    const core::UserProperty* property = propertyAt(model(), element);
    return property ? property->comment : std::string();
}

core::Status SetPropertyCommentCommand::write(const std::string& element, const std::string& value)
{
    return model().setPropertyComment(positionOf(element), value);
}

} // namespace editor
