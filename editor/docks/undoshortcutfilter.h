#pragma once

#include <QObject>

#include <functional>

class QSpinBox;
class QWidget;

namespace editor {

// Text fields in the docks edit the model by pushing commands, so the
// document's undo stack is their history: this filter keeps a text widget
// from taking Ctrl+Z / Ctrl+Shift+Z for its own undo, and the window's
// Undo and Redo actions get them.
class UndoShortcutFilter : public QObject {
    Q_OBJECT

public:
    // Installs a filter owned by the widget.
    static void install(QWidget* widget);
    // For a field that edits the model when its text is committed (a spin
    // box's Enter or focus loss): while typed text is pending, Ctrl+Z undoes
    // the typing in the field; once committed, the document's last edit.
    static void installAfterCommit(QSpinBox* spin);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    UndoShortcutFilter(QObject* parent, std::function<bool()> typingPending);

    std::function<bool()> m_typingPending;
};

} // namespace editor
