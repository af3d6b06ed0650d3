#include "editor/docks/undoshortcutfilter.h"

#include <QKeyEvent>
#include <QLocale>
#include <QSpinBox>
#include <QWidget>

#include <utility>

namespace editor {

namespace {

// The text a spin box shows for its value, as QSpinBox writes it.
QString committedText(const QSpinBox* spin)
{
    QString text = spin->locale().toString(spin->value());
    if (!spin->isGroupSeparatorShown())
        text.remove(spin->locale().groupSeparator());
    return text;
}

} // namespace

UndoShortcutFilter::UndoShortcutFilter(QObject* parent, std::function<bool()> typingPending)
    : QObject(parent)
    , m_typingPending(std::move(typingPending))
{
}

void UndoShortcutFilter::install(QWidget* widget)
{
    widget->installEventFilter(new UndoShortcutFilter(widget, {}));
}

void UndoShortcutFilter::installAfterCommit(QSpinBox* spin)
{
    spin->installEventFilter(
        new UndoShortcutFilter(spin, [spin] { return spin->cleanText() != committedText(spin); }));
}

bool UndoShortcutFilter::eventFilter(QObject* watched, QEvent* event)
{
    const bool key = event->type() == QEvent::ShortcutOverride || event->type() == QEvent::KeyPress;
    if (key && !(m_typingPending && m_typingPending())) {
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
