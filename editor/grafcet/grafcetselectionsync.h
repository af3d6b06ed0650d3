#pragma once

#include "editor/elementref.h"

#include <QObject>
#include <QPointer>

class QGraphicsItem;

namespace editor {

class GrafcetScene;
class GrafcetView;
class Selection;

// Keeps the selection of one GRAFCET tab and the app-wide Selection in step,
// as ChartScene does for the GEMMA chart: clicking a step or transition of
// the drawing selects it for the docks, and selecting a nested element of
// this GRAFCET elsewhere (the Problems dock, a dock's link) selects its item
// and scrolls the view to it. The items are made again on every change of
// the GRAFCET; the selection is carried over to the new ones.
class GrafcetSelectionSync : public QObject {
    Q_OBJECT

public:
    // Lives as long as `view` (its parent).
    GrafcetSelectionSync(GrafcetView* view, Selection* selection);

    QGraphicsItem* itemFor(const ElementRef& element) const;
    ElementRef elementOf(const QGraphicsItem* item) const;

private:
    void onSceneSelectionChanged();
    // `scroll`: bring the current element's item into view.
    void selectFromSelection(bool scroll);

    GrafcetView* m_view;
    GrafcetScene* m_scene;
    QPointer<Selection> m_selection; // the window's, which may go before the tab
    bool m_syncing = false;
};

} // namespace editor
