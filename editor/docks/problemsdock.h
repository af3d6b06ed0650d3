#pragma once

#include "core/diagnostic.h"

#include <QDockWidget>

class QToolButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace editor {

class Document;
class Selection;

// Every diagnostic of the model (severity, code, element, message), with a
// filter button per severity that shows its count. Double-clicking (or
// Enter on) a problem selects its element and asks for the field at fault,
// which the Step, Transition and Variables docks focus.
class ProblemsDock : public QDockWidget {
    Q_OBJECT

public:
    enum Column { CodeColumn, ElementColumn, MessageColumn };

    ProblemsDock(Document* document, Selection* selection, QWidget* parent = nullptr);

    QTreeWidget* view() const { return m_view; }
    // Selects the element of a problem row and asks to focus its field.
    void activate(QTreeWidgetItem* item);

private:
    QToolButton* createFilterButton(core::Severity severity, const QString& objectName);
    void refresh();
    void updateFilterButtons();
    void applyFilter();
    void copySelected();
    bool isShown(core::Severity severity) const;

    Document* m_document;
    Selection* m_selection;
    QTreeWidget* m_view;
    QToolButton* m_errorsButton = nullptr;
    QToolButton* m_warningsButton = nullptr;
    QToolButton* m_infoButton = nullptr;
};

} // namespace editor
