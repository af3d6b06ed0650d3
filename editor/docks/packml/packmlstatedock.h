#pragma once

#include "editor/elementref.h"

#include "core/templates/packml/packmltemplate.h"

#include <QDockWidget>
#include <QList>

class QComboBox;
class QGridLayout;
class QGroupBox;
class QLabel;
class QPushButton;
class QStackedWidget;

namespace editor {

class DiagnosticList;
class Document;
class Selection;

// The panel of the PackML state selected on the chart
// (ElementRef::packmlState): its name, PackTags number, kind and meaning,
// its problems, and for the acting states and Execute what runs there in
// each mode (spec packml.md §4): its own nested GRAFCET, the same as mode
// k's, or none (the skeleton). Each choice is one undoable command; Own
// creates an empty GRAFCET. "Open GRAFCET" asks for the GRAFCET that runs
// in that mode to be shown (its own, or mode k's). The mode the state was
// selected in comes first and in bold.
class PackmlStateDock : public QDockWidget {
    Q_OBJECT

public:
    static QString title();
    PackmlStateDock(Document* document, Selection* selection, QWidget* parent = nullptr);

    // The state shown; empty when none.
    QString stateName() const { return m_state; }

signals:
    // packml::grafcetKey(mode, state) of the GRAFCET to open: "3/Execute".
    void openGrafcetRequested(const QString& grafcetKey);

protected:
    void changeEvent(QEvent* event) override;

private:
    struct ModeRow {
        int mode = 0;
        QLabel* label = nullptr;
        QComboBox* choice = nullptr;
        QPushButton* open = nullptr;
    };

    QWidget* createForm();
    void retranslate();
    void refresh();
    void onFocusFieldRequested(const ElementRef& element, const QString& field);
    void refreshHeader(core::packml::State state);
    void refreshGrafcets(core::packml::State state);
    void fillChoice(ModeRow& row, core::packml::State state);
    void clearModeRows();
    void onChoiceActivated(int mode, int index);
    void onOpen(int mode);
    void onSelectionChanged(const ElementRef& element);

    Document* m_document;
    Selection* m_selection;
    QString m_state;
    int m_selectedMode = 0;
    QStackedWidget* m_pages;
    QLabel* m_placeholder;
    QLabel* m_titleLabel = nullptr;
    QLabel* m_kindLabel = nullptr;
    QLabel* m_meaningLabel = nullptr;
    DiagnosticList* m_problems = nullptr;
    QGroupBox* m_grafcetGroup = nullptr;
    QLabel* m_grafcetHint = nullptr;
    QGridLayout* m_grafcetGrid = nullptr;
    QList<ModeRow> m_modeRows;
};

} // namespace editor
