#include "editor/docks/wrappinglabel.h"

#include <QEvent>

namespace editor {

WrappingLabel::WrappingLabel(QWidget* parent)
    : WrappingLabel(QString(), parent)
{
}

WrappingLabel::WrappingLabel(const QString& text, QWidget* parent)
    : QLabel(text, parent)
{
    setWordWrap(true);
}

int WrappingLabel::heightForWidth(int width) const
{
    // QLabel::setText is not virtual: a changed text is noticed here.
    if (text() != m_measuredText) {
        forget();
        m_measuredText = text();
    }
    for (const Entry& entry : m_entries) {
        if (entry.width == width)
            return entry.height;
    }
    const int height = QLabel::heightForWidth(width);
    m_entries[m_next] = Entry{width, height};
    m_next = (m_next + 1) % m_entries.size();
    return height;
}

void WrappingLabel::changeEvent(QEvent* event)
{
    switch (event->type()) {
    case QEvent::FontChange:
    case QEvent::StyleChange:
    case QEvent::ContentsRectChange:
        forget();
        break;
    default:
        break;
    }
    QLabel::changeEvent(event);
}

void WrappingLabel::forget() const
{
    m_entries.fill(Entry{});
    m_next = 0;
}

} // namespace editor
