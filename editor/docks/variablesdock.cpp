#include "editor/docks/variablesdock.h"

#include "editor/commands/addvariablecommand.h"
#include "editor/commands/movevariablecommand.h"
#include "editor/commands/pastevariablescommand.h"
#include "editor/commands/removevariablecommand.h"
#include "editor/commands/undohistorywording.h"
#include "editor/docks/choicedelegate.h"
#include "editor/docks/dockreveal.h"
#include "editor/docks/toolicons.h"
#include "editor/docks/variablestablemodel.h"
#include "editor/document.h"
#include "editor/selection.h"
#include "editor/stdstring.h"
#include "editor/style/severityicon.h"

#include "core/model/iectypes.h"
#include "core/model/model.h"

#include <QAction>
#include <QClipboard>
#include <QEvent>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QSortFilterProxyModel>
#include <QStyle>
#include <QTableView>
#include <QTimer>
#include <QToolBar>
#include <QToolTip>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>

namespace editor {

namespace {

QString fromView(std::string_view text)
{
    return QString::fromLatin1(text.data(), static_cast<qsizetype>(text.size()));
}

// The IEC types, as written in the code.
QList<ChoiceDelegate::Choice> typeChoices()
{
    QList<ChoiceDelegate::Choice> choices;
    for (core::IecType type : core::allIecTypes())
        choices.push_back({fromView(core::iecTypeName(type)), fromView(core::iecTypeName(type))});
    return choices;
}

// The kinds in the UI language, with their file names as values.
QList<ChoiceDelegate::Choice> kindChoices()
{
    QList<ChoiceDelegate::Choice> choices;
    for (core::VariableKind kind : {core::VariableKind::Input, core::VariableKind::Output, core::VariableKind::Internal})
        choices.push_back({VariablesTableModel::kindText(kind), fromView(core::variableKindName(kind))});
    return choices;
}

bool lessByName(const std::string& a, const std::string& b)
{
    return core::toUpperAscii(a) < core::toUpperAscii(b);
}

// Insert adds a row, as in spreadsheets and the IEC editors' declaration tables.
bool isInsertKey(QKeyEvent* event)
{
    return event->key() == Qt::Key_Insert && event->modifiers() == Qt::NoModifier;
}

bool isTableKey(QKeyEvent* event)
{
    return event->matches(QKeySequence::Copy) || event->matches(QKeySequence::Paste)
        || event->matches(QKeySequence::Delete) || isInsertKey(event);
}

} // namespace

QString VariablesDock::title()
{
    return tr("Variables");
}

VariablesDock::VariablesDock(Document* document, Selection* selection, QWidget* parent)
    : QDockWidget(title(), parent)
    , m_document(document)
    , m_selection(selection)
    , m_model(new VariablesTableModel(document, this))
    , m_proxy(new QSortFilterProxyModel(this))
    , m_view(new QTableView)
{
    setObjectName(QStringLiteral("variablesDock"));

    m_proxy->setSourceModel(m_model);
    m_proxy->setFilterCaseSensitivity(Qt::CaseInsensitive);
    m_proxy->setFilterKeyColumn(-1);

    auto* content = new QWidget(this);
    auto* layout = new QVBoxLayout(content);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    createActions();
    auto* toolbar = new QToolBar(content);
    toolbar->setIconSize(QSize(16, 16));
    toolbar->addActions({ m_addAction, m_removeAction, m_duplicateAction });
    toolbar->addSeparator();
    toolbar->addActions({ m_upAction, m_downAction, m_sortAction });
    m_filterEdit = new QLineEdit(toolbar);
    m_filterEdit->setObjectName(QStringLiteral("filterEdit"));
    m_filterEdit->setClearButtonEnabled(true);
    m_filterEdit->setMaximumWidth(160);
    connect(m_filterEdit, &QLineEdit::textChanged, m_proxy, &QSortFilterProxyModel::setFilterFixedString);
    auto* spacer = new QWidget(toolbar);
    spacer->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    toolbar->addWidget(spacer);
    toolbar->addWidget(m_filterEdit);
    layout->addWidget(toolbar);

    m_view->setParent(content);
    m_view->setObjectName(QStringLiteral("variablesView"));
    m_view->setModel(m_proxy);
    m_view->setItemDelegateForColumn(VariablesTableModel::TypeColumn,
                                     new ChoiceDelegate(&typeChoices, QStringLiteral("typeCombo"), m_view));
    m_view->setItemDelegateForColumn(VariablesTableModel::KindColumn,
                                     new ChoiceDelegate(&kindChoices, QStringLiteral("kindCombo"), m_view));
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
        | QAbstractItemView::AnyKeyPressed | QAbstractItemView::SelectedClicked);
    m_view->setAlternatingRowColors(true);
    m_view->setWordWrap(false);
    m_view->setCornerButtonEnabled(false);
    m_view->verticalHeader()->setDefaultSectionSize(m_view->fontMetrics().height() + 8);
    m_view->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    QHeaderView* header = m_view->horizontalHeader();
    header->setHighlightSections(false);
    header->setStretchLastSection(true);
    // Narrow enough that the comment shows in the dock column beside the chart.
    // Names such as EmergencyOk, types such as LREAL and kinds such as
    // Internal still show whole.
    header->resizeSection(VariablesTableModel::NameColumn, 96);
    header->resizeSection(VariablesTableModel::TypeColumn, 46);
    header->resizeSection(VariablesTableModel::KindColumn, 58);
    header->resizeSection(VariablesTableModel::DefaultColumn, 52);
    m_view->installEventFilter(this);
    m_view->setContextMenuPolicy(Qt::ActionsContextMenu);
    const auto separator = [this]() {
        auto* a = new QAction(m_view);
        a->setSeparator(true);
        return a;
    };
    m_view->addActions({ m_addAction, m_removeAction, m_duplicateAction, separator(), m_copyAction, m_pasteAction,
        separator(), m_upAction, m_downAction, m_sortAction });
    layout->addWidget(m_view, 1);

    auto* messageRow = new QWidget(content);
    messageRow->setObjectName(QStringLiteral("messageRow"));
    auto* messageLayout = new QHBoxLayout(messageRow);
    messageLayout->setContentsMargins(6, 4, 6, 4);
    auto* messageIcon = new QLabel(messageRow);
    const int iconSize = style()->pixelMetric(QStyle::PM_SmallIconSize);
    // Drawn, as the Problems dock's marks: the style's message-box icon goes
    // through the icon theme (a third of the docks' build, with no theme).
    messageIcon->setPixmap(severityIcon(core::Severity::Warning).pixmap(iconSize, iconSize));
    m_messageLabel = new QLabel(messageRow);
    m_messageLabel->setObjectName(QStringLiteral("messageLabel"));
    m_messageLabel->setWordWrap(true);
    m_messageLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    messageLayout->addWidget(messageIcon, 0, Qt::AlignTop);
    messageLayout->addWidget(m_messageLabel, 1);
    messageRow->hide();
    layout->addWidget(messageRow);
    m_messageTimer = new QTimer(this);
    m_messageTimer->setSingleShot(true);
    m_messageTimer->setInterval(10000);
    connect(m_messageTimer, &QTimer::timeout, messageRow, &QWidget::hide);
    setWidget(content);

    connect(m_model, &VariablesTableModel::editRefused, this, [this](const QModelIndex& index, const QString& message) {
        showMessage(message);
        const QRect cell = m_view->visualRect(m_proxy->mapFromSource(index));
        QToolTip::showText(m_view->viewport()->mapToGlobal(cell.bottomLeft()), message, m_view);
    });
    // A refusal is about the edit just tried: the next edit that goes
    // through (or an undo, a redo) makes it old news.
    connect(m_document->undoStack(), &QUndoStack::indexChanged, this, &VariablesDock::hideMessage);
    connect(m_model, &VariablesTableModel::variableRenamed, this, &VariablesDock::onVariableRenamed);
    connect(m_model, &QAbstractItemModel::modelReset, this, &VariablesDock::onModelReset);
    connect(m_model, &QAbstractItemModel::dataChanged, this, &VariablesDock::updateActions);
    connect(
        m_view->selectionModel(), &QItemSelectionModel::currentRowChanged, this, &VariablesDock::onCurrentRowChanged);
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this, &VariablesDock::updateActions);
    connect(m_selection, &Selection::changed, this, &VariablesDock::onSelectionChanged);
    connect(m_selection, &Selection::focusFieldRequested, this, &VariablesDock::onFocusFieldRequested);
    onSelectionChanged(m_selection->current());
    updateActions();
    retranslate();
}

void VariablesDock::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDockWidget::changeEvent(event);
}

void VariablesDock::retranslate()
{
    setWindowTitle(title());
    const auto name = [](QAction* action, const QString& text, const QString& tip) {
        action->setText(text);
        action->setToolTip(tip);
    };
    name(m_addAction, tr("Add"), tr("Add a BOOL variable after the current one (Insert)"));
    name(m_removeAction, tr("Remove"), tr("Remove the selected variables"));
    name(m_duplicateAction, tr("Duplicate"), tr("Duplicate the selected variables"));
    name(m_upAction, tr("Move Up"), tr("Move the current variable up (declaration order)"));
    name(m_downAction, tr("Move Down"), tr("Move the current variable down (declaration order)"));
    name(m_sortAction, tr("Sort by Name"), tr("Sort the declarations by name (one undo step)"));
    name(m_copyAction, tr("Copy"), tr("Copy the selected variables as tab-separated rows"));
    name(m_pasteAction, tr("Paste"),
        tr("Paste rows from a spreadsheet: name, type, default, comment and kind, in this order or in the order "
           "a first row of column titles gives"));
    m_filterEdit->setPlaceholderText(tr("Filter"));
    m_filterEdit->setToolTip(
        tr("Show only the variables whose name, type, kind, default or comment contains this text"));
    m_model->retranslate();
    // A header may be longer in this language than the column is wide:
    // widen it, never narrow what the user chose.
    QHeaderView* header = m_view->horizontalHeader();
    for (int column : { VariablesTableModel::NameColumn, VariablesTableModel::TypeColumn,
             VariablesTableModel::KindColumn, VariablesTableModel::DefaultColumn })
        header->resizeSection(column, std::max(header->sectionSize(column), header->sectionSizeHint(column)));
}

// Named by retranslate().
void VariablesDock::createActions()
{
    const auto action = [this](const QIcon& icon) { return new QAction(icon, QString(), this); };
    m_addAction = action(toolIcon(ToolIcon::Add, this));
    m_removeAction = action(toolIcon(ToolIcon::Remove, this));
    m_duplicateAction = action(toolIcon(ToolIcon::Duplicate, this));
    m_upAction = action(toolIcon(ToolIcon::MoveUp, this));
    m_downAction = action(toolIcon(ToolIcon::MoveDown, this));
    m_sortAction = action(toolIcon(ToolIcon::SortByName, this));
    m_copyAction = action(QIcon());
    m_pasteAction = action(QIcon());
    // Shown in the context menu; the table's event filter handles the keys.
    m_addAction->setShortcut(Qt::Key_Insert);
    m_removeAction->setShortcut(QKeySequence::Delete);
    m_copyAction->setShortcut(QKeySequence::Copy);
    m_pasteAction->setShortcut(QKeySequence::Paste);
    for (QAction* a : { m_addAction, m_removeAction, m_copyAction, m_pasteAction })
        a->setShortcutContext(Qt::WidgetShortcut);

    connect(m_addAction, &QAction::triggered, this, &VariablesDock::addVariable);
    connect(m_removeAction, &QAction::triggered, this, &VariablesDock::removeSelected);
    connect(m_duplicateAction, &QAction::triggered, this, &VariablesDock::duplicateSelected);
    connect(m_upAction, &QAction::triggered, this, [this]() { moveCurrent(-1); });
    connect(m_downAction, &QAction::triggered, this, [this]() { moveCurrent(1); });
    connect(m_sortAction, &QAction::triggered, this, &VariablesDock::sortByName);
    connect(m_copyAction, &QAction::triggered, this, &VariablesDock::copy);
    connect(m_pasteAction, &QAction::triggered, this, &VariablesDock::paste);
}

bool VariablesDock::eventFilter(QObject* watched, QEvent* event)
{
    // The table's own keys win over window-wide shortcuts while it has the
    // focus (a cell editor has the focus to itself while editing).
    if (watched == m_view) {
        if (event->type() == QEvent::ShortcutOverride && isTableKey(static_cast<QKeyEvent*>(event))) {
            event->accept();
            return true;
        }
        if (event->type() == QEvent::KeyPress) {
            auto* key = static_cast<QKeyEvent*>(event);
            if (key->matches(QKeySequence::Copy)) {
                copy();
                return true;
            }
            if (key->matches(QKeySequence::Paste)) {
                paste();
                return true;
            }
            if (key->matches(QKeySequence::Delete)) {
                removeSelected();
                return true;
            }
            if (isInsertKey(key)) {
                addVariable();
                return true;
            }
        }
    }
    return QDockWidget::eventFilter(watched, event);
}

int VariablesDock::currentRow() const
{
    const QModelIndex current = m_proxy->mapToSource(m_view->currentIndex());
    return current.isValid() ? current.row() : -1;
}

QList<int> VariablesDock::selectedRows() const
{
    QList<int> rows;
    for (const QModelIndex& index : m_view->selectionModel()->selectedRows())
        rows << m_proxy->mapToSource(index).row();
    std::sort(rows.begin(), rows.end());
    return rows;
}

void VariablesDock::selectVariable(const QString& name, int column)
{
    const int row = m_model->rowOf(name);
    if (row < 0)
        return;
    QModelIndex index = m_proxy->mapFromSource(m_model->index(row, column));
    if (!index.isValid()) { // filtered out
        m_filterEdit->clear();
        index = m_proxy->mapFromSource(m_model->index(row, column));
    }
    const bool wasSyncing = m_syncingSelection;
    m_syncingSelection = true;
    m_view->selectionModel()->setCurrentIndex(index, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    m_view->scrollTo(index);
    m_syncingSelection = wasSyncing;
}

void VariablesDock::onSelectionChanged(const ElementRef& element)
{
    if (m_syncingSelection)
        return;
    if (element.kind == ElementRef::Kind::Variable) {
        selectVariable(element.id);
        return;
    }
    m_syncingSelection = true;
    m_view->selectionModel()->clearSelection();
    m_syncingSelection = false;
}

void VariablesDock::onFocusFieldRequested(const ElementRef& element, const QString& field)
{
    if (element.kind != ElementRef::Kind::Variable || m_model->rowOf(element.id) < 0)
        return;
    revealDock(this);
    const int column = VariablesTableModel::columnOfField(field);
    selectVariable(element.id, column >= 0 ? column : VariablesTableModel::NameColumn);
    m_view->setFocus(Qt::OtherFocusReason);
}

void VariablesDock::onCurrentRowChanged()
{
    updateActions();
    if (m_syncingSelection)
        return;
    const int row = currentRow();
    if (row < 0)
        return;
    m_syncingSelection = true;
    m_selection->select(ElementRef::variable(m_model->variableName(row)));
    m_syncingSelection = false;
}

void VariablesDock::onVariableRenamed(const QString& oldName, const QString& newName)
{
    const ElementRef& current = m_selection->current();
    if (current.kind == ElementRef::Kind::Variable && current.id.compare(oldName, Qt::CaseInsensitive) == 0) {
        m_syncingSelection = true;
        m_selection->select(ElementRef::variable(newName));
        m_syncingSelection = false;
    }
}

void VariablesDock::onModelReset()
{
    const ElementRef& current = m_selection->current();
    if (current.kind == ElementRef::Kind::Variable)
        selectVariable(current.id);
    updateActions();
}

void VariablesDock::updateActions()
{
    const int count = m_model->rowCount();
    const int row = currentRow();
    const bool selected = m_view->selectionModel()->hasSelection();
    m_removeAction->setEnabled(selected);
    m_duplicateAction->setEnabled(selected);
    m_copyAction->setEnabled(selected);
    m_upAction->setEnabled(row > 0);
    m_downAction->setEnabled(row >= 0 && row < count - 1);
    const std::vector<core::Variable>& variables = m_document->model().variables();
    const bool sorted = std::is_sorted(variables.begin(), variables.end(),
        [](const core::Variable& a, const core::Variable& b) { return lessByName(a.name, b.name); });
    m_sortAction->setEnabled(!sorted);
}

void VariablesDock::showMessage(const QString& message)
{
    m_messageLabel->setText(message);
    m_messageLabel->parentWidget()->show();
    m_messageTimer->start();
}

void VariablesDock::hideMessage()
{
    m_messageTimer->stop();
    m_messageLabel->parentWidget()->hide();
}

QString VariablesDock::freeVariableName() const
{
    for (int n = 1;; ++n) {
        const QString name = tr("Variable%1").arg(n);
        if (!m_document->model().variable(name.toStdString()))
            return name;
    }
}

void VariablesDock::addVariable()
{
    const int row = currentRow();
    core::Variable variable;
    variable.name = freeVariableName().toStdString();
    if (!m_document->push(new AddVariableCommand(*m_document, variable, row >= 0 ? row + 1 : -1)))
        return;
    const QString name = fromStd(variable.name);
    selectVariable(name);
    m_selection->select(ElementRef::variable(name));
    m_view->setFocus(Qt::OtherFocusReason);
    m_view->edit(m_view->currentIndex()); // the default name is only a placeholder
}

void VariablesDock::removeSelected()
{
    const QList<int> rows = selectedRows();
    if (rows.isEmpty())
        return;
    QStringList names;
    for (int row : rows)
        names << m_model->variableName(row);
    QUndoStack* stack = m_document->undoStack();
    if (names.size() > 1)
        beginWordedMacro(stack, [count = static_cast<int>(names.size())] {
            return tr("Remove %n variables", nullptr, count);
        });
    for (const QString& name : std::as_const(names))
        m_document->push(new RemoveVariableCommand(*m_document, name));
    if (names.size() > 1)
        stack->endMacro();
    // The variable that took the place of the first removed one.
    const int next = std::min(rows.front(), m_model->rowCount() - 1);
    if (next >= 0) {
        const QString name = m_model->variableName(next);
        selectVariable(name);
        m_selection->select(ElementRef::variable(name));
    } else {
        m_selection->clear();
    }
}

void VariablesDock::duplicateSelected()
{
    const QList<int> rows = selectedRows();
    if (rows.isEmpty())
        return;
    std::vector<core::Variable> copies;
    for (int row : rows)
        copies.push_back(m_document->model().variables()[static_cast<std::size_t>(row)]);
    const int index = rows.back() + 1;
    if (!m_document->push(new PasteVariablesCommand(*m_document, std::move(copies), index)))
        return;
    const QString name = m_model->variableName(index);
    selectVariable(name);
    m_selection->select(ElementRef::variable(name));
}

void VariablesDock::moveCurrent(int delta)
{
    const int row = currentRow();
    const int target = row + delta;
    if (row < 0 || target < 0 || target >= m_model->rowCount())
        return;
    const QString name = m_model->variableName(row);
    const int column = m_view->currentIndex().column();
    if (m_document->push(new MoveVariableCommand(*m_document, name, target)))
        selectVariable(name, std::max(column, 0));
}

void VariablesDock::sortByName()
{
    std::vector<std::string> names;
    for (const core::Variable& variable : m_document->model().variables())
        names.push_back(variable.name);
    std::stable_sort(names.begin(), names.end(), lessByName);
    if (std::equal(names.begin(), names.end(), m_document->model().variables().begin(),
            [](const std::string& name, const core::Variable& variable) { return name == variable.name; }))
        return;
    QUndoStack* stack = m_document->undoStack();
    beginWordedMacro(stack, [] { return tr("Sort variables by name"); });
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (m_document->model().variableIndex(names[i]) != static_cast<int>(i))
            m_document->push(new MoveVariableCommand(*m_document, fromStd(names[i]), static_cast<int>(i)));
    }
    stack->endMacro();
    onModelReset(); // the rows stayed; the selected variable moved
}

QString VariablesDock::copiedText() const
{
    std::vector<core::Variable> variables;
    for (int row : selectedRows())
        variables.push_back(m_document->model().variables()[static_cast<std::size_t>(row)]);
    return VariablesTableModel::formatRows(variables);
}

void VariablesDock::copy()
{
    if (m_view->selectionModel()->hasSelection())
        QGuiApplication::clipboard()->setText(copiedText());
}

void VariablesDock::paste()
{
    pasteVariables(QGuiApplication::clipboard()->text());
}

bool VariablesDock::pasteVariables(const QString& text)
{
    std::vector<core::Variable> variables;
    QString error;
    if (!VariablesTableModel::parseRows(text, &variables, &error)) {
        showMessage(error);
        return false;
    }
    const int row = currentRow();
    const int index = row >= 0 ? row + 1 : m_model->rowCount();
    QString failure;
    const QMetaObject::Connection connection
        = connect(m_document, &Document::editFailed, this, [&failure](const QString& message) { failure = message; });
    const bool ok = m_document->push(new PasteVariablesCommand(*m_document, std::move(variables), index));
    disconnect(connection);
    if (!ok) {
        showMessage(failure);
        return false;
    }
    const QString name = m_model->variableName(index);
    selectVariable(name);
    m_selection->select(ElementRef::variable(name));
    return true;
}

} // namespace editor
