#include "editor/docks/stpreviewdock.h"

#include "editor/commands/setdialectcommand.h"
#include "editor/docks/sthighlighter.h"
#include "editor/document.h"
#include "editor/selection.h"
#include "editor/stdstring.h"
#include "editor/style/secondarytext.h"

#include "core/templates/gemma/gemmacodegen.h"
#include "core/codegen/nestedpreview.h"
#include "core/templates/packml/packmlpreview.h"
#include "core/model/model.h"

#include <QComboBox>
#include <QEvent>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QTextBlock>
#include <QTextCursor>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>

namespace editor {

namespace {

// Lines kept above the highlighted code when scrolling to it.
constexpr int kContextLines = 2;

// Replaces only what differs between the document's text and `text` (the
// span between their common beginning and common end), so that an edit of
// one condition re-lays out and re-highlights a line or two instead of the
// whole program, and the view keeps its place.
void replaceChangedSpan(QPlainTextEdit& editor, const QString& text)
{
    const QString old = editor.toPlainText();
    const qsizetype shorter = std::min(old.size(), text.size());
    qsizetype prefix = 0;
    while (prefix < shorter && old[prefix] == text[prefix])
        ++prefix;
    qsizetype suffix = 0;
    while (suffix < shorter - prefix && old[old.size() - 1 - suffix] == text[text.size() - 1 - suffix])
        ++suffix;
    QTextCursor cursor(editor.document());
    cursor.beginEditBlock();
    cursor.setPosition(static_cast<int>(prefix));
    cursor.setPosition(static_cast<int>(old.size() - suffix), QTextCursor::KeepAnchor);
    cursor.insertText(text.mid(prefix, text.size() - prefix - suffix));
    cursor.endEditBlock();
}

} // namespace

QString StPreviewDock::title()
{
    return tr("Structured Text");
}

StPreviewDock::StPreviewDock(Document* document, Selection* selection, QWidget* parent)
    : QDockWidget(title(), parent)
    , m_document(document)
    , m_selection(selection)
    , m_dialectLabel(new QLabel)
    , m_dialectCombo(new QComboBox)
    , m_noteLabel(new QLabel)
    , m_editor(new QPlainTextEdit)
    , m_highlighter(new StHighlighter(m_editor->document()))
    , m_updateTimer(new QTimer(this))
{
    setObjectName(QStringLiteral("stPreviewDock"));

    auto* content = new QWidget(this);
    auto* layout = new QVBoxLayout(content);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    auto* bar = new QHBoxLayout;
    bar->setContentsMargins(6, 3, 6, 3);
    m_dialectLabel->setParent(content);
    m_dialectLabel->setBuddy(m_dialectCombo);
    m_dialectCombo->setParent(content);
    m_dialectCombo->setObjectName(QStringLiteral("dialectCombo"));
    m_dialectCombo->addItem(QString(), static_cast<int>(core::Dialect::Iec));
    m_dialectCombo->addItem(QString(), static_cast<int>(core::Dialect::Codesys));
    connect(m_dialectCombo, &QComboBox::currentIndexChanged, this, &StPreviewDock::onDialectChosen);
    m_noteLabel->setParent(content);
    m_noteLabel->setObjectName(QStringLiteral("noteLabel"));
    useSecondaryText(m_noteLabel);
    bar->addWidget(m_dialectLabel);
    bar->addWidget(m_dialectCombo);
    bar->addSpacing(8);
    bar->addWidget(m_noteLabel, 1);
    layout->addLayout(bar);

    m_editor->setParent(content);
    m_editor->setObjectName(QStringLiteral("codeView"));
    m_editor->setReadOnly(true);
    // The preview is rewritten in place on every edit (replaceChangedSpan):
    // no history of those rewrites to keep.
    m_editor->setUndoRedoEnabled(false);
    m_editor->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_editor->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_editor->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
    m_editor->setFrameShape(QFrame::NoFrame);
    layout->addWidget(m_editor, 1);
    setWidget(content);

    // Coalesces the signals of one edit (a rename changes many transitions).
    m_updateTimer->setSingleShot(true);
    m_updateTimer->setInterval(0);
    connect(m_updateTimer, &QTimer::timeout, this, [this] {
        if (isOnScreen())
            updatePreview();
    });
    // A tab brought to the front (QDockWidget says so with this signal; its
    // isVisible() stays true behind another tab).
    connect(this, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible && m_stale)
            scheduleUpdate();
    });

    connect(m_document, &Document::stepChanged, this, &StPreviewDock::scheduleUpdate);
    connect(m_document, &Document::transitionChanged, this, &StPreviewDock::scheduleUpdate);
    connect(m_document, &Document::variableChanged, this, &StPreviewDock::scheduleUpdate);
    connect(m_document, &Document::variablesChanged, this, &StPreviewDock::scheduleUpdate);
    connect(m_document, &Document::settingsChanged, this, &StPreviewDock::scheduleUpdate);
    connect(m_document, &Document::modelReset, this, &StPreviewDock::scheduleUpdate);
    connect(m_document, &Document::grafcetChanged, this, &StPreviewDock::scheduleUpdate);
    connect(m_document, &Document::packmlSettingsChanged, this, &StPreviewDock::scheduleUpdate);
    connect(m_document, &Document::commandChanged, this, &StPreviewDock::scheduleUpdate);
    connect(m_document, &Document::modesChanged, this, &StPreviewDock::scheduleUpdate);
    connect(m_document, &Document::modeChanged, this, &StPreviewDock::scheduleUpdate);
    connect(m_document, &Document::settingsChanged, this, &StPreviewDock::refreshDialect);
    connect(m_document, &Document::modelReset, this, &StPreviewDock::refreshDialect);
    connect(m_selection, &Selection::changed, this, &StPreviewDock::onSelectionChanged);
    refreshDialect();
    retranslate();
}

void StPreviewDock::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDockWidget::changeEvent(event);
}

void StPreviewDock::retranslate()
{
    setWindowTitle(title());
    m_dialectLabel->setText(tr("&Dialect:"));
    m_dialectCombo->setItemText(0, tr("IEC 61131-3"));
    m_dialectCombo->setItemText(1, tr("CODESYS"));
    m_dialectCombo->setItemData(
        0, tr("Beremiz, OpenPLC, TwinCAT, matiec: globals in the configuration"), Qt::ToolTipRole);
    m_dialectCombo->setItemData(1, tr("CODESYS V3.5: globals in the list GVL, read as GVL.Name"), Qt::ToolTipRole);
    m_dialectCombo->setToolTip(tr("The flavour of the generated code; saved with the model"));
    m_noteLabel->setText(noCodeReason(m_selection->current()));
}

void StPreviewDock::showEvent(QShowEvent* event)
{
    QDockWidget::showEvent(event);
    if (m_stale)
        scheduleUpdate();
}

bool StPreviewDock::isOnScreen() const
{
    // A tab behind another is visible to Qt, but placed outside the window.
    return isVisible() && !visibleRegion().isEmpty();
}

void StPreviewDock::scheduleUpdate()
{
    m_stale = true;
    // A hidden preview (a closed dock, a tab behind another) waits until
    // shown: generating and laying out the program is the costliest work of
    // an edit, and of the startup when the window first opens.
    if (isVisible())
        m_updateTimer->start();
}

void StPreviewDock::updatePreview()
{
    m_updateTimer->stop();
    m_stale = false;
    const core::Model& model = m_document->model();
    const core::Dialect dialect = model.settings().dialect;
    const std::string grafcet = m_grafcetStepId.toStdString();
    if (model.templateKind() == core::TemplateKind::PackML)
        m_preview = grafcet.empty() ? core::packml::previewPackmlProgram(model, dialect)
                                    : core::packml::previewPackmlFunctionBlock(model, grafcet, dialect);
    else
        m_preview = grafcet.empty() ? core::previewGemmaProgram(model, dialect)
                                    : core::previewNestedFunctionBlock(model, grafcet, dialect);
    const QString text = fromStd(m_preview.text);
    if (text != m_editor->toPlainText()) {
        QScrollBar* vertical = m_editor->verticalScrollBar();
        QScrollBar* horizontal = m_editor->horizontalScrollBar();
        const int top = vertical->value();
        const int left = horizontal->value();
        replaceChangedSpan(*m_editor, text);
        vertical->setValue(top);
        horizontal->setValue(left);
    }
    highlightSelection(false);
}

void StPreviewDock::setGrafcetInFront(const QString& stepId)
{
    if (stepId == m_grafcetStepId)
        return;
    m_grafcetStepId = stepId;
    // Another text altogether: from its top, or at the selection's code.
    m_editor->clear();
    if (isOnScreen())
        updatePreview();
    else
        scheduleUpdate();
    highlightSelection(true);
}

void StPreviewDock::refreshDialect()
{
    const QSignalBlocker blocker(m_dialectCombo);
    const int dialect = static_cast<int>(m_document->model().settings().dialect);
    m_dialectCombo->setCurrentIndex(m_dialectCombo->findData(dialect));
}

void StPreviewDock::onDialectChosen(int index)
{
    if (index < 0)
        return;
    const auto dialect = static_cast<core::Dialect>(m_dialectCombo->itemData(index).toInt());
    m_document->push(new SetDialectCommand(*m_document, dialect));
    refreshDialect();
}

void StPreviewDock::onSelectionChanged()
{
    if (m_stale && isOnScreen())
        updatePreview();
    highlightSelection(true);
}

std::vector<core::LineRange> StPreviewDock::rangesFor(const ElementRef& element) const
{
    std::vector<core::LineRange> ranges;
    if (!m_grafcetStepId.isEmpty())
        return nestedRangesFor(element);
    if (element.kind == ElementRef::Kind::PackmlState || element.kind == ElementRef::Kind::PackmlMode)
        return packmlRangesFor(element);
    if (element.kind != ElementRef::Kind::Step && element.kind != ElementRef::Kind::Transition)
        return ranges;
    const std::string key = element.id.toStdString();
    // A family transition is evaluated in every F branch: "F->D1", then "F->D1@F2"...
    const std::string occurrence = key + "@";
    for (const auto& [name, range] : m_preview.ranges) {
        if (name == key || (element.kind == ElementRef::Kind::Transition && name.rfind(occurrence, 0) == 0))
            ranges.push_back(range);
    }
    std::sort(ranges.begin(), ranges.end(),
        [](const core::LineRange& a, const core::LineRange& b) { return a.first < b.first; });
    return ranges;
}

// A PackML state's branch in the mode the chart shows it in (or in every
// mode), a unit mode's whole branch (core::packml::previewPackmlProgram).
std::vector<core::LineRange> StPreviewDock::packmlRangesFor(const ElementRef& element) const
{
    std::vector<core::LineRange> ranges;
    const std::string mode = std::to_string(element.number);
    const std::string state = "/" + element.id.toStdString();
    for (const auto& [name, range] : m_preview.ranges) {
        const bool matches = element.kind == ElementRef::Kind::PackmlMode
            ? name == mode
            : name.size() > state.size() && name.compare(name.size() - state.size(), state.size(), state) == 0
                  && (element.number == 0 || name == mode + state);
        if (matches)
            ranges.push_back(range);
    }
    std::sort(ranges.begin(), ranges.end(),
        [](const core::LineRange& a, const core::LineRange& b) { return a.first < b.first; });
    return ranges;
}

// The code of a step or transition of the GRAFCET in front: "X3", "T2" and
// their further runs "X3@2"... (core::previewNestedFunctionBlock).
std::vector<core::LineRange> StPreviewDock::nestedRangesFor(const ElementRef& element) const
{
    std::vector<core::LineRange> ranges;
    if (!element.isNested() || element.id != m_grafcetStepId)
        return ranges;
    const char prefix = element.kind == ElementRef::Kind::GrafcetStep ? 'X' : 'T';
    const std::string key = prefix + std::to_string(element.number);
    for (const auto& [name, range] : m_preview.ranges) {
        if (name == key || name.rfind(key + "@", 0) == 0)
            ranges.push_back(range);
    }
    std::sort(ranges.begin(), ranges.end(),
        [](const core::LineRange& a, const core::LineRange& b) { return a.first < b.first; });
    // The first run is the declaration: the view scrolls to the code that
    // evolves or acts, the first one after it.
    if (ranges.size() > 1)
        std::rotate(ranges.begin(), ranges.begin() + 1, ranges.end());
    return ranges;
}

void StPreviewDock::highlightSelection(bool scrollToIt)
{
    const ElementRef& element = m_selection->current();
    m_highlighted = rangesFor(element);
    m_noteLabel->setText(noCodeReason(element));

    QColor background = palette().color(QPalette::Highlight);
    background.setAlpha(60);
    QList<QTextEdit::ExtraSelection> selections;
    QTextDocument* document = m_editor->document();
    for (const core::LineRange& range : m_highlighted) {
        for (int line = range.first; line <= range.last; ++line) {
            const QTextBlock block = document->findBlockByNumber(line - 1);
            if (!block.isValid())
                continue;
            QTextEdit::ExtraSelection selection;
            selection.cursor = QTextCursor(block);
            selection.format.setBackground(background);
            selection.format.setProperty(QTextFormat::FullWidthSelection, true);
            selections << selection;
        }
    }
    m_editor->setExtraSelections(selections);
    if (!m_highlighted.empty())
        scrollToLines(m_highlighted.front(), !scrollToIt);
}

void StPreviewDock::scrollToLines(const core::LineRange& range, bool onlyIfHidden)
{
    // Without line wrapping the vertical scroll value is the first visible line.
    QScrollBar* vertical = m_editor->verticalScrollBar();
    const int lineHeight = std::max(1, m_editor->fontMetrics().lineSpacing());
    const int visibleLines = std::max(1, m_editor->viewport()->height() / lineHeight);
    const int first = range.first - 1;
    const int last = range.last - 1;
    const int top = vertical->value();
    if (onlyIfHidden && first >= top && last < top + visibleLines)
        return;
    // The whole range when it fits, else its start, with a little context above.
    const int wanted = last - first + 1 + kContextLines <= visibleLines ? first - kContextLines : first;
    vertical->setValue(std::max(0, wanted));
    m_editor->horizontalScrollBar()->setValue(0);
}

QString StPreviewDock::noCodeReason(const ElementRef& element) const
{
    const core::Model& model = m_document->model();
    if (model.templateKind() == core::TemplateKind::PackML)
        return packmlNoCodeReason(element);
    if (!m_grafcetStepId.isEmpty()) {
        if (!model.effectiveGrafcet(m_grafcetStepId.toStdString()))
            return tr("%1 generates no function block: only a visible macro-step or enclosing step does.")
                .arg(m_grafcetStepId);
        //: the function block shown: "F1_FB (the nested GRAFCET of F1)"
        return tr("%1_FB (the nested GRAFCET of %1)").arg(m_grafcetStepId);
    }
    if (element.kind == ElementRef::Kind::Step) {
        const core::Step* step = model.step(element.id.toStdString());
        if (step && step->hidden)
            return tr("%1 is hidden: it generates no code.").arg(element.id);
    } else if (element.kind == ElementRef::Kind::Transition) {
        if (model.transition(element.id.toStdString()) && !model.isEffective(element.id.toStdString()))
            return tr("This transition is not effective: it generates no code.");
    }
    return {};
}

QString StPreviewDock::packmlNoCodeReason(const ElementRef& element) const
{
    if (!m_grafcetStepId.isEmpty()) {
        if (m_preview.text.empty())
            return tr("No enabled state runs this GRAFCET: it generates no function block.");
        return {};
    }
    if (element.kind == ElementRef::Kind::PackmlState && element.number != 0 && rangesFor(element).empty())
        return tr("%1 is disabled in this unit mode: the mode's state machine has no branch for it.")
            .arg(element.id);
    return {};
}

} // namespace editor
