#include "editor/commands/grafcettextcommand.h"

#include <utility>

namespace editor {

GrafcetTextCommand::GrafcetTextCommand(
    Document& document, Wording wording, const QString& stepId, int number, const QString& value)
    : ModelCommand(document, std::move(wording))
    , m_stepId(toStdString(stepId))
    , m_number(number)
    , m_value(toStdString(value))
{
}

bool GrafcetTextCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const GrafcetTextCommand*>(other); // same id(), so same field
    if (next->m_stepId != m_stepId || next->m_number != m_number)
        return false;
    m_value = next->m_value;
    setObsolete(m_value == m_previous); // typed back to where it started
    return true;
}

core::Status GrafcetTextCommand::apply()
{
    if (firstRun())
        m_previous = read(m_stepId, m_number);
    return write(m_stepId, m_number, m_value);
}

core::Status GrafcetTextCommand::revert()
{
    return write(m_stepId, m_number, m_previous);
}

} // namespace editor
