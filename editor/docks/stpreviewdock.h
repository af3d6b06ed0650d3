#pragma once

#include "editor/elementref.h"

#include "core/codegen/stgenerator.h"

#include <QDockWidget>

#include <vector>

class QComboBox;
class QLabel;
class QPlainTextEdit;
class QTimer;

namespace editor {

class Document;
class Selection;
class StHighlighter;

// The PROGRAM GEMMA the model generates, live and read-only, in the chosen
// dialect (a model setting, so choosing it is an undoable edit); while a
// nested GRAFCET's tab is in front, the function block that GRAFCET
// generates instead. The code of the selected step or transition (of the
// chart, or of that GRAFCET) is highlighted and scrolled to; with nothing
// selected, updates keep the scroll position.
class StPreviewDock : public QDockWidget {
    Q_OBJECT

public:
    // Also the title of the empty frame that stands for the dock at start-up.
    static QString title();
    StPreviewDock(Document* document, Selection* selection, QWidget* parent = nullptr);

    QPlainTextEdit* editor() const { return m_editor; }
    // Regenerates now instead of after the current edit completes.
    void updatePreview();
    // The 1-based line ranges highlighted for the selection.
    const std::vector<core::LineRange>& highlightedRanges() const { return m_highlighted; }
    // The GEMMA step whose nested GRAFCET's function block is shown; empty
    // for the GEMMA program.
    void setGrafcetInFront(const QString& stepId);
    const QString& grafcetInFront() const { return m_grafcetStepId; }

protected:
    void showEvent(QShowEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    bool isOnScreen() const;
    void retranslate();
    void scheduleUpdate();
    void refreshDialect();
    void onDialectChosen(int index);
    void onSelectionChanged();
    void highlightSelection(bool scrollToIt);
    std::vector<core::LineRange> rangesFor(const ElementRef& element) const;
    std::vector<core::LineRange> nestedRangesFor(const ElementRef& element) const;
    std::vector<core::LineRange> packmlRangesFor(const ElementRef& element) const;
    QString packmlNoCodeReason(const ElementRef& element) const;
    void scrollToLines(const core::LineRange& range, bool onlyIfHidden);
    QString noCodeReason(const ElementRef& element) const;

    Document* m_document;
    Selection* m_selection;
    QLabel* m_dialectLabel;
    QComboBox* m_dialectCombo;
    QLabel* m_noteLabel;
    QPlainTextEdit* m_editor;
    StHighlighter* m_highlighter;
    QTimer* m_updateTimer;
    core::StPreview m_preview;
    QString m_grafcetStepId;
    std::vector<core::LineRange> m_highlighted;
    bool m_stale = true;
};

} // namespace editor
