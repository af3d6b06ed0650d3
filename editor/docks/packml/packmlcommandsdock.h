#pragma once

#include "editor/elementref.h"

#include "core/templates/packml/packmltemplate.h"

#include <QDockWidget>
#include <QList>

class QFrame;
class QLabel;
class QLineEdit;
class QScrollArea;
class QStackedWidget;
class QVBoxLayout;

namespace editor {

class ConditionEdit;
class DiagnosticList;
class Document;
class Selection;

// The Commands panel of a PackML model (spec packml.md §2.2): one row per
// command of the edition (Reset ... Clear, and Complete in 2022) with its
// condition, checked as it is typed, its problems and its comment. Typing
// pushes commands that merge into one undo step per field. Working in a row
// selects the command (ElementRef::packmlCommand); a command selected
// elsewhere (the chart's frame arrows, Problems), or a transition of the
// chart that a command fires, brings its row forward. On
// a GEMMA model it says it is for PackML models.
class PackmlCommandsDock : public QDockWidget {
    Q_OBJECT

public:
    static QString title();
    PackmlCommandsDock(Document* document, Selection* selection, QWidget* parent = nullptr);

    // The command whose row is current ("Hold"); empty when none.
    QString currentCommand() const { return m_current; }

protected:
    void changeEvent(QEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    struct Row {
        core::packml::Command command;
        QFrame* frame = nullptr;
        QLabel* title = nullptr;
        QLabel* meaning = nullptr;
        QLabel* conditionLabel = nullptr;
        ConditionEdit* condition = nullptr;
        DiagnosticList* problems = nullptr;
        QLabel* commentLabel = nullptr;
        QLineEdit* comment = nullptr;
    };

    void retranslate();
    void rebuild();
    Row createRow(core::packml::Command command, QWidget* parent);
    void retranslateRow(Row& row);
    void refreshRow(Row& row);
    void refreshAll();
    void refreshCommand(const QString& name);
    void refreshVariableNames();
    Row* rowOf(const QString& name);
    void showCurrent();
    void onSelectionChanged(const ElementRef& element);
    void onFocusFieldRequested(const ElementRef& element, const QString& field);

    Document* m_document;
    Selection* m_selection;
    QStackedWidget* m_pages;
    QLabel* m_notPackml;
    QScrollArea* m_scroll;
    QWidget* m_rowsWidget = nullptr;
    QVBoxLayout* m_rowsLayout = nullptr;
    QList<Row> m_rows;
    QString m_current;
    bool m_shownEdition2022 = false;
};

} // namespace editor
