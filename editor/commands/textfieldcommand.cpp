#include "editor/commands/textfieldcommand.h"

#include "core/model/iectypes.h"

#include <utility>

namespace editor {

TextFieldCommand::TextFieldCommand(
    Document& document, Wording wording, const QString& element, const QString& value, NameCase nameCase)
    : ModelCommand(document, std::move(wording))
    , m_nameCase(nameCase)
    , m_element(toStdString(element))
    , m_value(toStdString(value))
{
}

bool TextFieldCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const TextFieldCommand*>(other); // same id(), so same field
    const bool sameElement = m_nameCase == NameCase::Ignored ? core::equalsIgnoreCase(next->m_element, m_element)
                                                             : next->m_element == m_element;
    if (!sameElement)
        return false;
    m_value = next->m_value;
    setObsolete(m_value == m_previous); // typed back to where it started
    return true;
}

core::Status TextFieldCommand::validate(const std::string&, const std::string&) const
{
    return core::Status::success();
}

core::Status TextFieldCommand::apply()
{
    if (firstRun())
        m_previous = read(m_element);
    if (core::Status status = validate(m_element, m_value); !status)
        return status;
    return write(m_element, m_value);
}

core::Status TextFieldCommand::revert()
{
    return write(m_element, m_previous);
}

} // namespace editor
