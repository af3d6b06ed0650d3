#pragma once

#include <QObject>

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

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    using QObject::QObject;
};

} // namespace editor
