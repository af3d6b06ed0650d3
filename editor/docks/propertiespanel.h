#pragma once

#include <QWidget>

class QAction;
class QLabel;
class QTableView;

namespace editor {

class ConditionEdit;
class Document;
class PropertiesTableModel;
class WrappingLabel;

// The Properties tab of the Problems dock, beside Verification: the
// engineer's verification properties (docs/verification.md,
// "Properties"): a table of `never P` / `always P` with their comments, and
// under it the current property in a condition editor that underlines what
// the verifier cannot check as it is typed. Every change is an undo step.
class PropertiesPanel : public QWidget {
    Q_OBJECT

public:
    static QString title(); // of its tab
    explicit PropertiesPanel(Document* document, QWidget* parent = nullptr);

    PropertiesTableModel* tableModel() const { return m_model; }
    QTableView* view() const { return m_view; }
    ConditionEdit* propertyEdit() const { return m_edit; }

    void addProperty();
    void removeCurrent();
    void moveCurrent(int delta);
    int currentRow() const; // -1 for none
    void setCurrentRow(int row);

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    void createActions();
    void onPropertiesChanged();
    void onOtherChange();
    void refreshEditor();
    void updateActions();

    Document* m_document;
    PropertiesTableModel* m_model;
    QTableView* m_view;
    QLabel* m_editLabel;
    ConditionEdit* m_edit;
    WrappingLabel* m_problemLabel;
    QAction* m_addAction = nullptr;
    QAction* m_removeAction = nullptr;
    QAction* m_upAction = nullptr;
    QAction* m_downAction = nullptr;
};

} // namespace editor
