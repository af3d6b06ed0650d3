#include "editor/docks/propertiespanel.h"

#include "editor/commands/propertycommands.h"
#include "editor/docks/conditionedit.h"
#include "editor/docks/propertiestablemodel.h"
#include "editor/docks/toolicons.h"
#include "editor/docks/wrappinglabel.h"
#include "editor/document.h"
#include "editor/text/displaytext.h"
#include "editor/text/propertyproblemtext.h"

#include "core/model/model.h"

#include <QAction>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QTableView>
#include <QToolBar>
#include <QVBoxLayout>

namespace editor {

QString PropertiesPanel::title()
{
    return tr("Properties");
}

PropertiesPanel::PropertiesPanel(Document* document, QWidget* parent)
    : QWidget(parent)
    , m_document(document)
    , m_model(new PropertiesTableModel(document, this))
    , m_view(new QTableView(this))
    , m_editLabel(new QLabel(this))
    , m_edit(new ConditionEdit(this))
    , m_problemLabel(new WrappingLabel(this))
{
    setObjectName(QStringLiteral("propertiesPanel"));
    createActions();
    // Small margins and a short table: the tab must not make the Problems dock, and with it the
    // window, taller than the laptop screens the default layout is made for.
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 0, 2, 2);
    layout->setSpacing(2);
    auto* toolbar = new QToolBar(this);
    toolbar->setIconSize(QSize(16, 16));
    toolbar->addActions({m_addAction, m_removeAction, m_upAction, m_downAction});
    m_view->setObjectName(QStringLiteral("propertiesView"));
    m_view->setModel(m_model);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_view->setWordWrap(true);
    m_view->setMinimumHeight(m_view->horizontalHeader()->sizeHint().height() + m_view->verticalHeader()->defaultSectionSize());
    m_view->addActions({m_addAction, m_removeAction});
    layout->addWidget(m_view, 1);
    m_edit->setObjectName(QStringLiteral("propertyEdit"));
    m_editLabel->setBuddy(m_edit);
    // The buttons share the label's row: one row less of minimum height.
    auto* editRow = new QHBoxLayout;
    editRow->addWidget(m_editLabel);
    editRow->addStretch();
    editRow->addWidget(toolbar);
    layout->addLayout(editRow);
    layout->addWidget(m_edit);
    m_problemLabel->setObjectName(QStringLiteral("propertyProblem"));
    // A word wider than the panel (a name of a thousand letters, quoted) is
    // cut at the panel's edge, not made the panel's minimum width: the dock
    // column, and with it the window, would grow past the screen.
    m_problemLabel->setSizePolicy(QSizePolicy::Ignored, m_problemLabel->sizePolicy().verticalPolicy());
    layout->addWidget(m_problemLabel);

    connect(m_edit, &ConditionEdit::textEdited, this, [this](const QString& text) {
        if (currentRow() >= 0)
            m_document->push(new SetPropertyTextCommand(*m_document, currentRow(), text));
    });
    connect(m_view->selectionModel(), &QItemSelectionModel::currentRowChanged, this, [this] {
        refreshEditor();
        updateActions();
    });
    connect(m_model, &QAbstractItemModel::modelReset, this, [this] {
        // A new selection model is not made on reset: the current row is re-set by the caller.
        refreshEditor();
        updateActions();
    });
    connect(document, &Document::propertiesChanged, this, &PropertiesPanel::onPropertiesChanged);
    connect(document, &Document::modelReset, this, &PropertiesPanel::onPropertiesChanged);
    for (auto signal : {&Document::variablesChanged, &Document::settingsChanged})
        connect(document, signal, this, &PropertiesPanel::onOtherChange);
    connect(document, &Document::variableChanged, this, &PropertiesPanel::onOtherChange);
    connect(document, &Document::stepChanged, this, &PropertiesPanel::onOtherChange);
    connect(document, &Document::grafcetChanged, this, &PropertiesPanel::onOtherChange);
    retranslate();
    setCurrentRow(0);
    updateActions();
}

void PropertiesPanel::createActions()
{
    const auto action = [this](const QIcon& icon) { return new QAction(icon, QString(), this); };
    m_addAction = action(toolIcon(ToolIcon::Add, this));
    m_removeAction = action(toolIcon(ToolIcon::Remove, this));
    m_upAction = action(toolIcon(ToolIcon::MoveUp, this));
    m_downAction = action(toolIcon(ToolIcon::MoveDown, this));
    m_addAction->setObjectName(QStringLiteral("addPropertyAction"));
    m_removeAction->setObjectName(QStringLiteral("removePropertyAction"));
    m_upAction->setObjectName(QStringLiteral("movePropertyUpAction"));
    m_downAction->setObjectName(QStringLiteral("movePropertyDownAction"));
    m_addAction->setShortcut(QKeySequence(Qt::Key_Insert));
    m_removeAction->setShortcut(QKeySequence::Delete);
    for (QAction* a : {m_addAction, m_removeAction})
        a->setShortcutContext(Qt::WidgetShortcut);
    connect(m_addAction, &QAction::triggered, this, &PropertiesPanel::addProperty);
    connect(m_removeAction, &QAction::triggered, this, &PropertiesPanel::removeCurrent);
    connect(m_upAction, &QAction::triggered, this, [this] { moveCurrent(-1); });
    connect(m_downAction, &QAction::triggered, this, [this] { moveCurrent(1); });
}

void PropertiesPanel::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void PropertiesPanel::retranslate()
{
    m_addAction->setText(tr("Add Property"));
    m_addAction->setToolTip(tr("Add a property after the current one (Insert)"));
    m_removeAction->setText(tr("Remove Property"));
    m_removeAction->setToolTip(tr("Remove the current property (Delete)"));
    m_upAction->setText(tr("Move Up"));
    m_downAction->setText(tr("Move Down"));
    m_editLabel->setText(tr("&Property:"));
    m_edit->setPlaceholderText(tr("never A_Plus AND A_Minus"));
    const QString syntax = (tr("Write never P or always P, where P is a condition over the variables that may "
                              "also use in S (the GEMMA step S is active), S.Xn (step n of S's nested GRAFCET "
                              "is active) and a -> b (if a then b). Verify (F7) proves or refutes each one."));
    m_edit->setToolTip(syntax);
    m_view->setToolTip(syntax);
    refreshEditor();
}

int PropertiesPanel::currentRow() const
{
    const QModelIndex current = m_view->currentIndex();
    return current.isValid() ? current.row() : -1;
}

void PropertiesPanel::setCurrentRow(int row)
{
    if (row < 0 || row >= m_model->rowCount())
        return;
    m_view->setCurrentIndex(m_model->index(row, PropertiesTableModel::TextColumn));
}

void PropertiesPanel::addProperty()
{
    const int at = currentRow() < 0 ? m_model->rowCount() : currentRow() + 1;
    if (!m_document->push(new AddPropertyCommand(*m_document, core::UserProperty{}, at)))
        return;
    setCurrentRow(at);
    m_edit->setFocus(Qt::OtherFocusReason);
}

void PropertiesPanel::removeCurrent()
{
    const int row = currentRow();
    if (row < 0)
        return;
    m_document->push(new RemovePropertyCommand(*m_document, row));
    setCurrentRow(std::min(row, m_model->rowCount() - 1));
}

void PropertiesPanel::moveCurrent(int delta)
{
    const int row = currentRow();
    const int to = row + delta;
    if (row < 0 || to < 0 || to >= m_model->rowCount())
        return;
    if (m_document->push(new MovePropertyCommand(*m_document, row, to)))
        setCurrentRow(to);
}

void PropertiesPanel::onPropertiesChanged()
{
    const int row = currentRow();
    if (m_model->loadedRows() != static_cast<int>(m_document->model().properties().size())) {
        m_model->reload();
        setCurrentRow(std::min(row < 0 ? 0 : row, m_model->rowCount() - 1));
    } else {
        m_model->recheck();
    }
    refreshEditor();
    updateActions();
}

void PropertiesPanel::onOtherChange()
{
    m_model->recheck();
    refreshEditor();
}

// The current property in the editor, what the verifier cannot check underlined.
void PropertiesPanel::refreshEditor()
{
    const int row = currentRow();
    const auto& properties = m_document->model().properties();
    const bool shown = row >= 0 && row < static_cast<int>(properties.size());
    m_edit->setEnabled(shown);
    const QString text = shown ? QString::fromStdString(properties[static_cast<std::size_t>(row)].text) : QString();
    m_edit->setText(text);
    QList<ConditionEdit::Problem> problems;
    QStringList messages;
    for (const core::PropertyProblem& problem : m_model->problems(row)) {
        ConditionEdit::Problem underlined;
        underlined.begin = ConditionEdit::positionOfByte(text, problem.span.begin);
        underlined.end = ConditionEdit::positionOfByte(text, problem.span.end);
        underlined.message = propertyProblemText(problem);
        problems << underlined;
        messages << underlined.message;
    }
    m_edit->setProblems(problems);
    QStringList names;
    for (const core::Variable& variable : m_document->model().variables())
        names << QString::fromStdString(variable.name);
    m_edit->setVariableNames(names);
    m_problemLabel->setText(messages.join(QLatin1Char('\n')));
    m_problemLabel->setToolTip(boundedToolTip(m_problemLabel->text()));
    m_problemLabel->setVisible(!messages.isEmpty());
}

void PropertiesPanel::updateActions()
{
    const int row = currentRow();
    m_removeAction->setEnabled(row >= 0);
    m_upAction->setEnabled(row > 0);
    m_downAction->setEnabled(row >= 0 && row + 1 < m_model->rowCount());
}

} // namespace editor
