#pragma once

// The chart's context menu: for a step (hide or show, its type, make it
// initial, edit its comment), for a transition (hide or show, edit the
// condition, negate, priority up or down) and for the empty sheet (show
// hidden elements, fit, export the chart). Every entry that changes the
// model pushes the same undoable command the docks push; entries that edit
// a text select the element and put the focus in its dock's field.

#include "editor/elementref.h"

#include <QList>
#include <QObject>

class QAction;
class QMenu;

namespace editor {

class Document;
class Selection;

class ChartContextMenu : public QObject {
    Q_OBJECT

public:
    // The window's own actions the sheet's menu offers.
    struct SheetActions {
        QAction* showHidden = nullptr;
        QAction* fit = nullptr;
        QAction* exportChart = nullptr;
    };

    ChartContextMenu(Document& document, Selection& selection, SheetActions sheet, QObject* parent = nullptr);

    // Fills `menu` for `element`; a null element is the empty sheet. The
    // entries are named (objectName) for tests and scripts.
    void populate(QMenu* menu, const ElementRef& element);

signals:
    // "Open Nested GRAFCET" on a step that has one.
    void openGrafcetRequested(const QString& stepId);

private:
    void addStepEntries(QMenu* menu, const QString& stepId);
    void addTransitionEntries(QMenu* menu, const QString& transitionId);
    void addSheetEntries(QMenu* menu);
    // Right-click on one of several selected elements: Hide or Show them all.
    void addSelectionEntries(QMenu* menu, const QList<ElementRef>& elements);

    Document& m_document;
    Selection& m_selection;
    SheetActions m_sheet;
};

} // namespace editor
