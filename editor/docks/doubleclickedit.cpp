#include "editor/docks/doubleclickedit.h"

#include <QAbstractItemView>
#include <QMouseEvent>

namespace editor {

void DoubleClickEdit::install(QAbstractItemView* view)
{
    view->viewport()->installEventFilter(new DoubleClickEdit(view));
}

DoubleClickEdit::DoubleClickEdit(QAbstractItemView* view)
    : QObject(view)
    , m_view(view)
{
}

bool DoubleClickEdit::eventFilter(QObject* watched, QEvent* event)
{

    if (event->type() != QEvent::MouseButtonDblClick || watched != m_view->viewport()
        || !(m_view->editTriggers() & QAbstractItemView::DoubleClicked))
        return QObject::eventFilter(watched, event);
    auto* mouse = static_cast<QMouseEvent*>(event);
    const QModelIndex index = m_view->indexAt(mouse->position().toPoint());
    if (mouse->button() != Qt::LeftButton || !index.isValid() || !(index.flags() & Qt::ItemIsEditable))
        return QObject::eventFilter(watched, event);
    m_view->setCurrentIndex(index);
    m_view->edit(index);
    return true;
}

} // namespace editor
