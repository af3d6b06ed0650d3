#pragma once

#include "editor/elementref.h"

#include <QDockWidget>

class QScrollArea;
class QStackedWidget;

namespace editor {

class Document;
class Selection;
class WrappingLabel;

// A dock for the properties of the selected element of one kind (a step, a
// transition, a step or transition of a nested GRAFCET): a placeholder while the selection is something else, the
// dock's form otherwise. It follows the selection, refreshes as the document
// changes, reveals itself to focus a field on Selection::focusFieldRequested
// and follows a change of language; each dock supplies its form, how it
// fills it, its texts and which widget a field is.
class PropertyDock : public QDockWidget {
    Q_OBJECT

signals:
    // Esc in a field that takes the key for itself (a table cell's editor
    // cancels its edit): the user is done here too, as with Esc elsewhere
    // in the dock, which the window's shortcut takes back to the drawing.
    void leaveRequested();

protected:
    PropertyDock(ElementRef::Kind kind, const QString& title, Document* document, Selection* selection,
                 QWidget* parent);

    // At the end of the dock's constructor, once refreshForm() can run:
    // shows the placeholder or `form`, and starts following the selection.
    void setPages(QWidget* form);
    // What the dock says while no element of its kind is selected.
    void setPlaceholder(const QString& text);
    // Shown instead of the placeholder while nothing at all is selected
    // (after setPages()); none by default.
    void setIdlePage(QWidget* page);
    // `content` in a frameless scroll area: a dock shorter than its form
    // (docks share their column) scrolls instead of making the window taller.
    static QScrollArea* scrolling(QWidget* content);
    // Refreshes on every change of the declared variables too, for a dock
    // whose checks or completion depend on them.
    void refreshOnVariableChanges();

    void changeEvent(QEvent* event) override;

    Document* document() const { return m_document; }
    Selection* selection() const { return m_selection; }
    // Empty when the selection is not of the dock's kind.
    QString elementId() const { return m_elementId; }
    // The nested step or transition number (nested kinds; 0 otherwise).
    int elementNumber() const { return m_number; }
    ElementRef element() const { return {m_kind, m_elementId, m_number}; }
    // The element is about to take a new number: the dock shows it through
    // the change, not its placeholder between the old number's going and the
    // selection's following (that page switch back and forth left the form
    // painted over the dock tab bar under X11).
    void followNumber(int number) { m_number = number; }

    // The form while the element exists, filled again; else the placeholder.
    void refresh();

private:
    // The texts that do not depend on the element, in the UI language; the
    // constructor calls it too. refreshForm() follows on a change of language.
    virtual void retranslate() = 0;
    // Runs only while the element exists.
    virtual void refreshForm() = 0;
    // `field` as Selection::focusFieldRequested names it; the dock is revealed.
    virtual void focusField(const QString& field) = 0;

    bool exists(const ElementRef& element) const;
    void onSelectionChanged(const ElementRef& element);
    void onFocusFieldRequested(const ElementRef& element, const QString& field);

    const ElementRef::Kind m_kind;
    Document* m_document;
    Selection* m_selection;
    QString m_elementId;
    int m_number = 0;
    QStackedWidget* m_pages = nullptr;
    WrappingLabel* m_placeholder = nullptr;
    QWidget* m_idlePage = nullptr;
};

} // namespace editor
