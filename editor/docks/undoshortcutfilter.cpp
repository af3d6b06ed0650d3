#include "editor/docks/undoshortcutfilter.h"

#include <QKeyEvent>
#include <QWidget>

namespace editor {

void UndoShortcutFilter::install(QWidget* widget)
{
    widget->installEventFilter(new UndoShortcutFilter(widget));
}

bool UndoShortcutFilter::eventFilter(QObject* watched, QEvent* event)
{
    const bool key = event->type() == QEvent::ShortcutOverride || event->type() == QEvent::KeyPress;
    if (key) {
        auto* keyEvent = static_cast<QKeyEvent*>(event);
        // An unaccepted override lets the shortcut reach the window's
        // actions; a key press that no action took must not become a
        // second, local history either.
        if (keyEvent->matches(QKeySequence::Undo) || keyEvent->matches(QKeySequence::Redo))
            return true;
    }
    return QObject::eventFilter(watched, event);
}

} // namespace editor
