#include "editor/selection.h"

namespace editor {

Selection::Selection(QObject* parent)
    : QObject(parent)
{
}

void Selection::select(const ElementRef& element, const QString& field)
{
    const QList<ElementRef> alone = element.isNull() ? QList<ElementRef>() : QList<ElementRef>{element};
    const bool setChanged = alone != m_elements;
    m_elements = alone;
    // Selecting the current element again only asks for the field: the
    // views need not rebuild themselves.
    if (element != m_current) {
        m_current = element;
        emit changed(m_current);
    }
    if (setChanged)
        emit elementsChanged();
    if (!field.isEmpty())
        emit focusFieldRequested(m_current, field);
}

void Selection::selectMany(const QList<ElementRef>& elements, const ElementRef& current)
{
    if (elements.size() <= 1 || !elements.contains(current)) {
        select(elements.isEmpty() ? ElementRef() : (elements.contains(current) ? current : elements.first()));
        return;
    }
    const bool setChanged = elements != m_elements;
    m_elements = elements;
    if (current != m_current) {
        m_current = current;
        emit changed(m_current);
    }
    if (setChanged)
        emit elementsChanged();
}

void Selection::clear()
{
    select(ElementRef());
}

} // namespace editor
