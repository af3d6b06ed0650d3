#include "editor/selection.h"

namespace editor {

Selection::Selection(QObject* parent)
    : QObject(parent)
{
}

void Selection::select(const ElementRef& element, const QString& field)
{
    // Selecting the current element again only asks for the field: the
    // views need not rebuild themselves.
    if (element != m_current) {
        m_current = element;
        emit changed(m_current);
    }
    if (!field.isEmpty())
        emit focusFieldRequested(m_current, field);
}

void Selection::clear()
{
    select(ElementRef());
}

} // namespace editor
