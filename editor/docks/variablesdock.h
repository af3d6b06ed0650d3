#pragma once

#include "editor/elementref.h"

#include <QDockWidget>

class QAction;
class QLabel;
class QLineEdit;
class QModelIndex;
class QSortFilterProxyModel;
class QTableView;
class QTimer;

namespace editor {

class Document;
class Selection;
class VariablesTableModel;

// The variable table: add, remove, duplicate, reorder, sort, copy and paste
// rows (tab-separated, as spreadsheets copy them), edit cells in place. The
// table shows the model order, which is the order of the generated
// declarations; "Sort by name" changes that order as one undo step.
class VariablesDock : public QDockWidget {
    Q_OBJECT

public:
    // Also the title of the empty frame that stands for the dock at start-up.
    static QString title();
    VariablesDock(Document* document, Selection* selection, QWidget* parent = nullptr);

    VariablesTableModel* tableModel() const { return m_model; }
    QTableView* view() const { return m_view; }

    // Inserts rows of a spreadsheet (name[TAB]type[TAB]default[TAB]comment)
    // after the current row, as one undo step. False, with the reason shown
    // in the dock, when the text holds no valid rows.
    bool pasteVariables(const QString& text);
    // The selected variables in the clipboard format.
    QString copiedText() const;

    void addVariable();
    void removeSelected();
    void duplicateSelected();
    void moveCurrent(int delta);
    void sortByName();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    void createActions();
    void onSelectionChanged(const ElementRef& element);
    void onFocusFieldRequested(const ElementRef& element, const QString& field);
    void onCurrentRowChanged();
    void onVariableRenamed(const QString& oldName, const QString& newName);
    void onModelReset();
    void updateActions();
    void showMessage(const QString& message);
    void hideMessage();
    void selectVariable(const QString& name, int column = 0);
    QList<int> selectedRows() const; // model rows, ascending
    int currentRow() const; // model row; -1 for none
    QString freeVariableName() const;
    void copy();
    void paste();

    Document* m_document;
    Selection* m_selection;
    VariablesTableModel* m_model;
    QSortFilterProxyModel* m_proxy;
    QTableView* m_view;
    QLineEdit* m_filterEdit = nullptr;
    QLabel* m_messageLabel = nullptr;
    QTimer* m_messageTimer = nullptr;
    bool m_syncingSelection = false;

    QAction* m_addAction = nullptr;
    QAction* m_removeAction = nullptr;
    QAction* m_duplicateAction = nullptr;
    QAction* m_upAction = nullptr;
    QAction* m_downAction = nullptr;
    QAction* m_sortAction = nullptr;
    QAction* m_copyAction = nullptr;
    QAction* m_pasteAction = nullptr;
};

} // namespace editor
