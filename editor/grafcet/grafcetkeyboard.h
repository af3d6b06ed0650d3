#pragma once

#include "editor/elementref.h"

#include <QList>
#include <QObject>
#include <QPointer>

class QKeyEvent;
class QMouseEvent;

namespace editor {

class GrafcetScene;
class GrafcetView;
class Selection;

// The keyboard of a GRAFCET tab, as on the GEMMA chart: Tab and Shift+Tab
// walk the steps and transitions in drawing order, round and round while
// there are any (a nested GRAFCET is drawn without any other widget in the
// way); Enter, F2 or a double-click on an element puts the focus in its main
// field in its dock (the receptivity, the actions); Esc clears the
// selection. It filters the view's events, so that the view's own mouse
// handling (panning, dragging) stays as it is.
class GrafcetKeyboard : public QObject {
    Q_OBJECT

public:
    // Lives as long as `view` (its parent).
    GrafcetKeyboard(GrafcetView* view, Selection* selection);

    // This GRAFCET's steps and transitions as drawn: top to bottom, and left
    // to right on one height.
    QList<ElementRef> drawingOrder() const;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    bool onKeyPress(QKeyEvent* event);
    bool onDoubleClick(QMouseEvent* event);
    // Selects the next (previous) element after the current one; false when there is none.
    bool walk(bool next);
    // The selected element when it is this GRAFCET's; else a null one.
    ElementRef current() const;
    ElementRef elementAt(const QPoint& viewportPosition) const;

    GrafcetView* m_view;
    QWidget* m_viewport; // compared with, never called: events may come while the view goes
    GrafcetScene* m_scene;
    QPointer<Selection> m_selection; // the window's, which may go before the tab
};

} // namespace editor
