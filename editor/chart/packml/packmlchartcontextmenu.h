#pragma once

// The PackML chart's context menu: for a state, open the GRAFCET it runs in
// the mode shown, or choose one, and show the chart in another mode; for a
// command's transition or a frame's arrow, edit the command's condition;
// for the empty sheet, fit and export the chart. Entries that edit a text
// select the element and put the focus in its dock's field, as on the
// GEMMA chart.

#include "editor/elementref.h"

#include <QObject>

class QAction;
class QMenu;

namespace editor {

class Document;
class PackmlChartScene;
class Selection;

class PackmlChartContextMenu : public QObject {
    Q_OBJECT

public:
    struct SheetActions {
        QAction* fit = nullptr;
        QAction* exportChart = nullptr;
    };

    PackmlChartContextMenu(Document& document, PackmlChartScene& scene, SheetActions sheet,
                           QObject* parent = nullptr);

    // Fills `menu` for `element`; a null element is the empty sheet. The
    // entries are named (objectName) for tests and scripts.
    void populate(QMenu* menu, const ElementRef& element);

signals:
    void openGrafcetRequested(const QString& key);

private:
    void addStateEntries(QMenu* menu, const ElementRef& element);
    void addCommandEntries(QMenu* menu, const QString& command);
    void addModeEntries(QMenu* menu);

    Document& m_document;
    PackmlChartScene& m_scene;
    SheetActions m_sheet;
};

} // namespace editor
