#pragma once

#include "editor/elementref.h"

#include <QDockWidget>

class QComboBox;
class QLabel;
class QListWidget;
class QPushButton;
class QSpinBox;
class QStackedWidget;

namespace editor {

class Document;
class PackmlModeForm;
class Selection;

// The Modes panel of a PackML model (spec packml.md §3): the list of unit
// modes (number, name, comment as tooltip), adding a user mode (the first
// free number of 4..31, or the one chosen), removing one (never Production),
// the initial mode, and the selected mode's fields (PackmlModeForm). Picking
// a mode selects it (ElementRef::packmlMode); a mode selected elsewhere
// (Problems), or a state or transition picked on the chart in a mode, shows
// that mode. On a GEMMA model it says it is for
// PackML models.
class PackmlModesDock : public QDockWidget {
    Q_OBJECT

public:
    static QString title();
    PackmlModesDock(Document* document, Selection* selection, QWidget* parent = nullptr);

    // The mode whose fields are shown; 0 on a GEMMA model.
    int currentMode() const;

protected:
    void changeEvent(QEvent* event) override;

private:
    QWidget* createPage();
    void retranslate();
    void refresh();
    void refreshList();
    void refreshInitialMode();
    void refreshButtons();
    void showMode(int number);
    void onRowChanged(int row);
    void onAdd();
    void onRemove();
    void onInitialModeChosen(int index);
    void onSelectionChanged(const ElementRef& element);
    void onFocusFieldRequested(const ElementRef& element, const QString& field);

    Document* m_document;
    Selection* m_selection;
    QStackedWidget* m_pages;
    QLabel* m_notPackml;
    QListWidget* m_list = nullptr;
    QSpinBox* m_numberSpin = nullptr;
    QPushButton* m_addButton = nullptr;
    QPushButton* m_removeButton = nullptr;
    QLabel* m_initialLabel = nullptr;
    QComboBox* m_initialCombo = nullptr;
    QLabel* m_formTitle = nullptr;
    PackmlModeForm* m_form = nullptr;
};

} // namespace editor
