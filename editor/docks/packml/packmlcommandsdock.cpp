#include "editor/docks/packml/packmlcommandsdock.h"

#include "editor/commands/packml/packmlcommandtextcommands.h"
#include "editor/docks/conditionedit.h"
#include "editor/docks/diagnosticlist.h"
#include "editor/docks/dockreveal.h"
#include "editor/docks/packml/packmldockparts.h"
#include "editor/docks/undoshortcutfilter.h"
#include "editor/document.h"
#include "editor/selection.h"
#include "editor/stdstring.h"
#include "editor/text/packmltexts.h"

#include "core/model/model.h"

#include <QEvent>
#include <QFrame>
#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QStackedWidget>
#include <QVBoxLayout>

namespace editor {

namespace {

namespace packml = core::packml;

QString nameOf(packml::Command command)
{
    return packmltext::commandName(command);
}

// The command a selected element stands for: a command, or a transition of
// the chart that a command fires ("Execute->Holding": Hold); empty otherwise.
QString commandOf(const ElementRef& element, const core::Model& model)
{
    if (element.kind == ElementRef::Kind::PackmlCommand)
        return element.id;
    const packml::Configuration* configuration = model.packml();
    if (element.kind != ElementRef::Kind::PackmlTransition || !configuration)
        return {};
    const QStringList ends = element.id.split(QStringLiteral("->"));
    const auto source = ends.size() == 2 ? packml::findState(ends[0].toStdString()) : std::nullopt;
    const auto target = ends.size() == 2 ? packml::findState(ends[1].toStdString()) : std::nullopt;
    if (!source || !target)
        return {};
    for (const packml::TemplateTransition& transition : packml::transitionsFrom(*source, configuration->options))
        if (transition.target == *target && transition.trigger == packml::Trigger::Command)
            return nameOf(transition.command);
    return {};
}

} // namespace

QString PackmlCommandsDock::title()
{
    return tr("Commands");
}

PackmlCommandsDock::PackmlCommandsDock(Document* document, Selection* selection, QWidget* parent)
    : QDockWidget(title(), parent)
    , m_document(document)
    , m_selection(selection)
{
    setObjectName(QStringLiteral("packmlCommandsDock"));
    m_pages = new QStackedWidget(this);
    m_notPackml = packmlHintLabel(m_pages);
    m_notPackml->setObjectName(QStringLiteral("notPackml"));
    m_notPackml->setAlignment(Qt::AlignCenter);
    m_notPackml->setMargin(12);
    m_pages->addWidget(m_notPackml);
    m_scroll = new QScrollArea(m_pages);
    m_scroll->setWidgetResizable(true);
    m_scroll->setFrameShape(QFrame::NoFrame);
    m_pages->addWidget(m_scroll);
    setWidget(m_pages);

    connect(m_document, &Document::modelReset, this, &PackmlCommandsDock::rebuild);
    connect(m_document, &Document::packmlSettingsChanged, this, [this] {
        const packml::Configuration* configuration = m_document->model().packml();
        if (configuration && (configuration->options.edition == packml::Edition::Y2022) != m_shownEdition2022)
            rebuild(); // Complete comes or goes
    });
    connect(m_document, &Document::commandChanged, this, &PackmlCommandsDock::refreshCommand);
    connect(m_document, &Document::diagnosticsChanged, this, &PackmlCommandsDock::refreshAll);
    connect(m_document, &Document::variablesChanged, this, &PackmlCommandsDock::refreshVariableNames);
    connect(m_selection, &Selection::changed, this, &PackmlCommandsDock::onSelectionChanged);
    connect(m_selection, &Selection::focusFieldRequested, this, &PackmlCommandsDock::onFocusFieldRequested);
    retranslate();
    rebuild();
}

void PackmlCommandsDock::retranslate()
{
    setWindowTitle(title());
    m_notPackml->setText(tr("Commands belong to PackML models: this model follows GEMMA."));
    for (Row& row : m_rows)
        retranslateRow(row);
}

void PackmlCommandsDock::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDockWidget::changeEvent(event);
}

void PackmlCommandsDock::rebuild()
{
    const packml::Configuration* configuration = m_document->model().packml();
    m_pages->setCurrentIndex(configuration ? 1 : 0);
    m_rows.clear();
    delete m_scroll->takeWidget();
    m_rowsWidget = nullptr;
    if (!configuration)
        return;
    m_shownEdition2022 = configuration->options.edition == packml::Edition::Y2022;
    m_rowsWidget = new QWidget;
    m_rowsLayout = new QVBoxLayout(m_rowsWidget);
    m_rowsLayout->setContentsMargins(6, 6, 6, 6);
    m_rowsLayout->setSpacing(4);
    for (const packml::CommandInfo& info : packml::allCommands()) {
        if (!packml::commandInEdition(info.command, configuration->options.edition))
            continue;
        m_rows << createRow(info.command, m_rowsWidget);
        m_rowsLayout->addWidget(m_rows.back().frame);
    }
    m_rowsLayout->addStretch();
    m_scroll->setWidget(m_rowsWidget);
    for (Row& row : m_rows)
        retranslateRow(row);
    refreshAll();
    refreshVariableNames();
    if (!rowOf(m_current))
        m_current.clear();
    showCurrent();
}

PackmlCommandsDock::Row PackmlCommandsDock::createRow(packml::Command command, QWidget* parent)
{
    const QString name = nameOf(command);
    Row row;
    row.command = command;
    row.frame = new QFrame(parent);
    row.frame->setObjectName(QStringLiteral("row_") + name);
    row.frame->setFrameShape(QFrame::StyledPanel);
    row.frame->installEventFilter(this);
    auto* layout = new QVBoxLayout(row.frame);
    layout->setContentsMargins(6, 4, 6, 4);
    layout->setSpacing(3);

    row.title = new QLabel(row.frame);
    QFont titleFont = row.title->font();
    titleFont.setBold(true);
    row.title->setFont(titleFont);
    layout->addWidget(row.title);
    row.meaning = packmlHintLabel(row.frame);
    layout->addWidget(row.meaning);

    row.conditionLabel = new QLabel(row.frame);
    layout->addWidget(row.conditionLabel);
    row.condition = new ConditionEdit(row.frame);
    row.condition->setObjectName(QStringLiteral("condition_") + name);
    row.condition->installEventFilter(this);
    row.conditionLabel->setBuddy(row.condition);
    connect(row.condition, &ConditionEdit::textEdited, this, [this, name](const QString& text) {
        m_document->push(new SetCommandConditionCommand(*m_document, name, text));
    });
    layout->addWidget(row.condition);
    row.problems = new DiagnosticList(row.frame);
    row.problems->setObjectName(QStringLiteral("problems_") + name);
    row.problems->setDocument(m_document);
    layout->addWidget(row.problems);

    row.commentLabel = new QLabel(row.frame);
    layout->addWidget(row.commentLabel);
    row.comment = new QLineEdit(row.frame);
    row.comment->setObjectName(QStringLiteral("comment_") + name);
    row.comment->installEventFilter(this);
    row.commentLabel->setBuddy(row.comment);
    UndoShortcutFilter::install(row.comment);
    connect(row.comment, &QLineEdit::textEdited, this, [this, name](const QString& text) {
        m_document->push(new SetCommandCommentCommand(*m_document, name, text));
    });
    layout->addWidget(row.comment);
    return row;
}

void PackmlCommandsDock::retranslateRow(Row& row)
{
    //: a PackML command's row: its PackTags number and name, "4 Hold"
    row.title->setText(tr("%1 %2").arg(static_cast<int>(row.command)).arg(nameOf(row.command)));
    row.meaning->setText(packmltext::commandMeaning(row.command));
    row.conditionLabel->setText(tr("Condition:"));
    row.condition->setPlaceholderText(tr("e.g. %1, or FALSE for a command given only through CntrlCmd")
                                          .arg(toQString(packml::commandInfo(row.command).defaultInput)));
    row.condition->setToolTip(tr("Issues the command at its rising edge. Structured Text: declared variables, "
                                 "numbers, TRUE, FALSE, NOT, AND, XOR, OR, comparisons.\nCtrl+Space completes a "
                                 "variable name."));
    row.commentLabel->setText(tr("Comment:"));
    row.comment->setPlaceholderText(tr("Where the command comes from on this machine"));
}

void PackmlCommandsDock::refreshRow(Row& row)
{
    const packml::Configuration* configuration = m_document->model().packml();
    if (!configuration)
        return;
    const packml::CommandSetting& setting = configuration->command(row.command);
    const QString condition = fromStd(setting.condition);
    row.condition->setText(condition);
    const std::vector<core::Diagnostic> diagnostics
        = m_document->diagnosticsFor(ElementRef::packmlCommand(nameOf(row.command)));
    row.condition->setProblems(conditionProblems(condition, diagnostics));
    row.problems->setDiagnostics(diagnostics);
    const QString comment = fromStd(setting.comment);
    if (row.comment->text() != comment) {
        const QSignalBlocker blocker(row.comment);
        row.comment->setText(comment);
    }
}

void PackmlCommandsDock::refreshAll()
{
    for (Row& row : m_rows)
        refreshRow(row);
}

void PackmlCommandsDock::refreshCommand(const QString& name)
{
    if (Row* row = rowOf(name))
        refreshRow(*row);
}

void PackmlCommandsDock::refreshVariableNames()
{
    const QStringList names = declaredVariableNames(m_document->model());
    for (Row& row : m_rows)
        row.condition->setVariableNames(names);
}

PackmlCommandsDock::Row* PackmlCommandsDock::rowOf(const QString& name)
{
    for (Row& row : m_rows)
        if (nameOf(row.command) == name)
            return &row;
    return nullptr;
}

// The current row is drawn raised and scrolled into view.
void PackmlCommandsDock::showCurrent()
{
    for (Row& row : m_rows) {
        const bool current = nameOf(row.command) == m_current;
        row.frame->setFrameShadow(current ? QFrame::Raised : QFrame::Plain);
        row.frame->setLineWidth(current ? 2 : 1);
        row.frame->setBackgroundRole(current ? QPalette::AlternateBase : QPalette::Window);
        row.frame->setAutoFillBackground(current);
        if (current)
            m_scroll->ensureWidgetVisible(row.frame, 0, 0);
    }
}

bool PackmlCommandsDock::eventFilter(QObject* watched, QEvent* event)
{
    if (event->type() == QEvent::FocusIn || event->type() == QEvent::MouseButtonPress) {
        for (const Row& row : std::as_const(m_rows)) {
            if (watched == row.frame || watched == row.condition || watched == row.comment) {
                const ElementRef element = ElementRef::packmlCommand(nameOf(row.command));
                if (m_selection->current() != element)
                    m_selection->select(element);
                break;
            }
        }
    }
    return QDockWidget::eventFilter(watched, event);
}

void PackmlCommandsDock::onSelectionChanged(const ElementRef& element)
{
    const QString command = commandOf(element, m_document->model());
    if (command.isEmpty() || !rowOf(command))
        return; // the row stays current while something else is selected
    m_current = command;
    showCurrent();
    raiseOverPropertySibling(this);
}

void PackmlCommandsDock::onFocusFieldRequested(const ElementRef& element, const QString& field)
{
    Row* row = element.kind == ElementRef::Kind::PackmlCommand ? rowOf(element.id) : nullptr;
    if (!row)
        return;
    m_current = element.id;
    showCurrent();
    revealDock(this);
    if (field == QLatin1String("comment")) {
        row->comment->setFocus(Qt::OtherFocusReason);
        return;
    }
    const QList<ConditionEdit::Problem>& problems = row->condition->problems();
    const int end = static_cast<int>(row->condition->text().size());
    if (problems.isEmpty())
        row->condition->selectRange(end, end);
    else
        row->condition->selectRange(problems.front().begin, problems.front().end);
}

} // namespace editor
