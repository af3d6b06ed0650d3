#include "editor/docks/grafcetstepdock.h"

#include "editor/chart/chartstyle.h"
#include "editor/commands/addgrafcetactioncommand.h"
#include "editor/commands/movegrafcetactioncommand.h"
#include "editor/commands/removegrafcetactioncommand.h"
#include "editor/commands/renumbergrafcetstepcommand.h"
#include "editor/commands/setgrafcetstepcommentcommand.h"
#include "editor/commands/setgrafcetstepinitialcommand.h"
#include "editor/docks/choicedelegate.h"
#include "editor/docks/diagnosticlist.h"
#include "editor/docks/doubleclickedit.h"
#include "editor/docks/gemma/stepdock.h"
#include "editor/docks/grafcetactiondelegate.h"
#include "editor/docks/grafcetactionparts.h"
#include "editor/docks/grafcetactionsmodel.h"
#include "editor/docks/toolicons.h"
#include "editor/docks/undoshortcutfilter.h"
#include "editor/docks/wrappinglabel.h"
#include "editor/document.h"
#include "editor/selection.h"
#include "editor/stdstring.h"
#include "editor/style/secondarytext.h"
#include "editor/text/gemmastatenames.h"

#include "core/model/model.h"

#include <QAction>
#include <QCheckBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QPlainTextEdit>
#include <QScrollArea>
#include <QSet>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStyle>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>

namespace editor {

namespace {

constexpr int kMaxStepNumber = 9999;

int linesHeight(const QWidget* widget, int lines)
{
    return widget->fontMetrics().lineSpacing() * lines + 2 * widget->style()->pixelMetric(QStyle::PM_DefaultFrameWidth)
        + 8;
}

WrappingLabel* problemLabel(const QString& objectName, QWidget* parent)
{
    auto* label = new WrappingLabel(parent);
    label->setObjectName(objectName);
    QPalette palette = label->palette();
    palette.setColor(QPalette::WindowText, chartstyle::problemColor());
    label->setPalette(palette);
    label->hide();
    return label;
}

void showMessage(WrappingLabel* label, const QString& message)
{
    label->setText(message);
    label->setVisible(!message.isEmpty());
}

// An icon, as in the Variables panel: four worded buttons beside "Actions:"
// would widen the dock column in French or German. The words are the
// tooltip's and the screen reader's.
QToolButton* toolButton(const QString& objectName, ToolIcon icon, QWidget* parent)
{
    auto* button = new QToolButton(parent);
    button->setObjectName(objectName);
    button->setIcon(toolIcon(icon, parent));
    button->setIconSize(QSize(16, 16));
    button->setAutoRaise(true);
    button->setToolButtonStyle(Qt::ToolButtonIconOnly);
    return button;
}

} // namespace

QString GrafcetStepDock::title()
{
    return tr("Nested Step");
}

GrafcetStepDock::GrafcetStepDock(Document* document, Selection* selection, QWidget* parent)
    : PropertyDock(ElementRef::Kind::GrafcetStep, title(), document, selection, parent)
{
    setObjectName(QStringLiteral("grafcetStepDock"));
    // The actions' checks and completion depend on the declared variables.
    refreshOnVariableChanges();
    setPages(scrolling(createForm()));
    retranslate();
}

void GrafcetStepDock::retranslate()
{
    // Its tab shows only while a GRAFCET tab is in front, the GEMMA Step
    // dock hidden (DockContext): the short title keeps the three tabs of the
    // column whole at 1366 x 768 in German. The View menu says which it is.
    setWindowTitle(StepDock::title());
    toggleViewAction()->setText(title());
    setPlaceholder(tr("Select a step in a nested GRAFCET's tab to see and edit its number, comment and actions."));
    m_numberLabel->setText(tr("&Number:"));
    m_numberSpin->setToolTip(tr("Unique in this GRAFCET; its activity is X<number>. The transitions and the "
                                "X<number> of the receptivities and actions follow a new number."));
    m_initialCheck->setText(tr("&Initial"));
    m_initialCheck->setToolTip(tr("Active when the GEMMA state is entered (a GRAFCET needs at least one)"));
    m_commentLabel->setText(tr("&Comment:"));
    m_commentEdit->setPlaceholderText(tr("What the machine does in this step"));
    m_actionsLabel->setText(tr("&Actions:"));
    m_addButton->setText(tr("Add"));
    m_addButton->setToolTip(tr("Add an action after the current one"));
    m_removeButton->setText(tr("Remove"));
    m_removeButton->setToolTip(tr("Remove the current action"));
    m_upButton->setText(tr("Up"));
    m_upButton->setToolTip(tr("Run the current action earlier"));
    m_downButton->setText(tr("Down"));
    m_downButton->setToolTip(tr("Run the current action later"));
    m_actionsModel->retranslate();
}

QWidget* GrafcetStepDock::createForm()
{
    auto* form = new QWidget;
    auto* layout = new QVBoxLayout(form);
    layout->setContentsMargins(6, 6, 6, 6);
    layout->setSpacing(6);

    m_titleLabel = new QLabel(form);
    m_titleLabel->setObjectName(QStringLiteral("titleLabel"));
    QFont titleFont = m_titleLabel->font();
    titleFont.setBold(true);
    titleFont.setPointSizeF(titleFont.pointSizeF() * 1.3);
    m_titleLabel->setFont(titleFont);
    layout->addWidget(m_titleLabel);
    m_grafcetLabel = new WrappingLabel(form);
    m_grafcetLabel->setObjectName(QStringLiteral("grafcetLabel"));
    useSecondaryText(m_grafcetLabel);
    layout->addWidget(m_grafcetLabel);

    auto* fields = new QFormLayout;
    fields->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_numberSpin = new QSpinBox(form);
    m_numberSpin->setObjectName(QStringLiteral("numberSpin"));
    // 0 can be typed, to be refused with the reason: a minimum of 1 would
    // silently put back the number the user did not want.
    m_numberSpin->setRange(0, kMaxStepNumber);
    m_numberSpin->setKeyboardTracking(false); // one command per number, not per digit
    UndoShortcutFilter::installAfterCommit(m_numberSpin);
    connect(m_numberSpin, &QSpinBox::valueChanged, this, &GrafcetStepDock::onNumberChosen);
    m_initialCheck = new QCheckBox(form);
    m_initialCheck->setObjectName(QStringLiteral("nestedInitialCheck"));
    connect(m_initialCheck, &QCheckBox::toggled, this, &GrafcetStepDock::onInitialToggled);
    auto* numberRow = new QHBoxLayout;
    numberRow->addWidget(m_numberSpin);
    numberRow->addSpacing(12);
    numberRow->addWidget(m_initialCheck);
    numberRow->addStretch();
    m_numberLabel = new QLabel(form);
    m_numberLabel->setBuddy(m_numberSpin);
    fields->addRow(m_numberLabel, numberRow);
    m_numberMessage = problemLabel(QStringLiteral("numberMessage"), form);
    fields->addRow(m_numberMessage);

    m_commentEdit = new QPlainTextEdit(form);
    m_commentEdit->setObjectName(QStringLiteral("nestedCommentEdit"));
    m_commentEdit->setTabChangesFocus(true);
    m_commentEdit->setUndoRedoEnabled(false); // the document's undo stack is the history
    m_commentEdit->setFixedHeight(linesHeight(m_commentEdit, 2));
    UndoShortcutFilter::install(m_commentEdit);
    connect(m_commentEdit, &QPlainTextEdit::textChanged, this, &GrafcetStepDock::onCommentEdited);
    m_commentLabel = new QLabel(form);
    m_commentLabel->setBuddy(m_commentEdit);
    fields->addRow(m_commentLabel, m_commentEdit);
    layout->addLayout(fields);

    layout->addWidget(createActionsArea(form), 1);
    m_problemList = new DiagnosticList(form);
    m_problemList->setDocument(document());
    m_problemList->setObjectName(QStringLiteral("problemList"));
    layout->addWidget(m_problemList);
    return form;
}

QWidget* GrafcetStepDock::createActionsArea(QWidget* parent)
{
    auto* area = new QWidget(parent);
    auto* layout = new QVBoxLayout(area);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(3);
    auto* header = new QHBoxLayout;
    m_actionsLabel = new QLabel(area);
    header->addWidget(m_actionsLabel);
    header->addStretch();
    m_addButton = toolButton(QStringLiteral("addActionButton"), ToolIcon::Add, area);
    m_removeButton = toolButton(QStringLiteral("removeActionButton"), ToolIcon::Remove, area);
    m_upButton = toolButton(QStringLiteral("moveActionUpButton"), ToolIcon::MoveUp, area);
    m_downButton = toolButton(QStringLiteral("moveActionDownButton"), ToolIcon::MoveDown, area);
    for (QToolButton* button : {m_addButton, m_removeButton, m_upButton, m_downButton})
        header->addWidget(button);
    connect(m_addButton, &QToolButton::clicked, this, &GrafcetStepDock::onAddAction);
    connect(m_removeButton, &QToolButton::clicked, this, &GrafcetStepDock::onRemoveAction);
    connect(m_upButton, &QToolButton::clicked, this, [this] { onMoveAction(-1); });
    connect(m_downButton, &QToolButton::clicked, this, [this] { onMoveAction(1); });
    layout->addLayout(header);

    m_actionsModel = new GrafcetActionsModel(document(), this);
    connect(m_actionsModel, &GrafcetActionsModel::editRefused, this,
            [this](const QString& message) { showMessage(m_actionMessage, message); });
    m_actionsView = new QTableView(area);
    m_actionsView->setObjectName(QStringLiteral("actionsView"));
    m_actionsView->setModel(m_actionsModel);
    m_actionsView->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_actionsView->setSelectionMode(QAbstractItemView::SingleSelection);
    m_actionsView->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                                   | QAbstractItemView::AnyKeyPressed);
    m_actionsView->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    QHeaderView* columns = m_actionsView->horizontalHeader();
    columns->setSectionResizeMode(QHeaderView::ResizeToContents);
    columns->setSectionResizeMode(GrafcetActionsModel::OperandColumn, QHeaderView::Stretch);
    m_actionsView->setMinimumHeight(linesHeight(m_actionsView, 5));
    m_actionsView->setItemDelegateForColumn(
        GrafcetActionsModel::TimingColumn,
        new ChoiceDelegate(
            [] {
                QList<ChoiceDelegate::Choice> choices;
                for (core::ActionTiming timing : {core::ActionTiming::Continuous, core::ActionTiming::OnActivation,
                                                  core::ActionTiming::OnDeactivation})
                    choices.append({GrafcetActionsModel::timingText(timing), GrafcetActionsModel::timingValue(timing)});
                return choices;
            },
            QStringLiteral("timingCombo"), m_actionsView));
    m_actionsView->setItemDelegateForColumn(
        GrafcetActionsModel::QualifierColumn,
        new ChoiceDelegate(
            [] {
                QList<ChoiceDelegate::Choice> choices;
                using Q = GrafcetActionParts::Qualifier;
                for (Q qualifier : {Q::N, Q::S, Q::R, Q::Assign}) {
                    const QString text = GrafcetActionParts::qualifierText(qualifier);
                    choices.append({text, text});
                }
                return choices;
            },
            QStringLiteral("qualifierCombo"), m_actionsView));
    auto* textDelegate = new GrafcetActionDelegate(m_actionsModel, [this] { return writableVariables(); }, m_actionsView);
    connect(textDelegate, &GrafcetActionDelegate::problemTyped, this,
            [this](const QString& problem) { showActionProblem(problem); });
    connect(textDelegate, &QAbstractItemDelegate::closeEditor, this, [this] { showActionProblem(); });
    m_actionsView->setItemDelegateForColumn(GrafcetActionsModel::VariableColumn, textDelegate);
    m_actionsView->setItemDelegateForColumn(GrafcetActionsModel::OperandColumn, textDelegate);
    leaveOnCancelledEdit(m_actionsView);
    DoubleClickEdit::install(m_actionsView);
    connect(m_actionsView->selectionModel(), &QItemSelectionModel::currentRowChanged, this, [this] {
        refreshActionButtons();
        showActionProblem();
    });
    connect(m_actionsModel, &QAbstractItemModel::modelReset, this, &GrafcetStepDock::refreshActionButtons);
    m_actionsLabel->setBuddy(m_actionsView);
    layout->addWidget(m_actionsView, 1);
    m_actionMessage = problemLabel(QStringLiteral("actionMessage"), area);
    layout->addWidget(m_actionMessage);
    return area;
}

// Esc in a cell's editor cancels the edit (the delegate's doing) and, as Esc
// in the other fields, goes back to the drawing: one key, not two.
void GrafcetStepDock::leaveOnCancelledEdit(QAbstractItemView* view)
{
    QSet<QAbstractItemDelegate*> delegates; // one delegate may edit several columns
    for (int column = 0; column < GrafcetActionsModel::ColumnCount; ++column)
        delegates.insert(view->itemDelegateForColumn(column));
    delegates.remove(nullptr);
    for (QAbstractItemDelegate* delegate : std::as_const(delegates)) {
        connect(delegate, &QAbstractItemDelegate::closeEditor, this,
                [this](QWidget*, QAbstractItemDelegate::EndEditHint hint) {
                    if (hint == QAbstractItemDelegate::RevertModelCache)
                        emit leaveRequested();
                });
    }
}

const core::GrafcetStep* GrafcetStepDock::step() const
{
    const core::Grafcet* grafcet = document()->model().grafcet(elementId().toStdString());
    return grafcet ? grafcet->step(elementNumber()) : nullptr;
}

void GrafcetStepDock::refreshForm()
{
    const core::GrafcetStep* shown = step();
    const QString stepId = elementId();
    //: A step of the nested GRAFCET of a GEMMA step: "F1 step 3"
    m_titleLabel->setText(tr("%1 step %2").arg(stepId).arg(shown->number));
    m_grafcetLabel->setText(tr("In the nested GRAFCET of %1 %2").arg(stepId, officialStateName(stepId)));
    if (m_numberSpin->value() != shown->number || !m_numberSpin->hasFocus()) {
        const QSignalBlocker blocker(m_numberSpin);
        m_numberSpin->setValue(shown->number);
    }
    {
        const QSignalBlocker blocker(m_initialCheck);
        m_initialCheck->setChecked(shown->initial);
    }
    const QString comment = fromStd(shown->comment);
    if (m_commentEdit->toPlainText() != comment) {
        // Only when it differs: rewriting the text under the cursor would move it.
        const QSignalBlocker blocker(m_commentEdit);
        m_commentEdit->setPlainText(comment);
        m_commentEdit->moveCursor(QTextCursor::End);
    }
    m_actionsModel->setStep(stepId, shown->number);
    refreshActionButtons();
    showActionProblem();
    m_problemList->setDiagnostics(document()->diagnosticsFor(element()));
}

void GrafcetStepDock::refreshActionButtons()
{
    const int row = m_actionsView->currentIndex().row();
    const int count = m_actionsModel->rowCount();
    m_removeButton->setEnabled(row >= 0 && row < count);
    m_upButton->setEnabled(row > 0 && row < count);
    m_downButton->setEnabled(row >= 0 && row + 1 < count);
}

// What is wrong with the current action: as typed while a cell is edited,
// else what the checks say of it.
void GrafcetStepDock::showActionProblem(const QString& typed)
{
    const int row = m_actionsView->currentIndex().row();
    showMessage(m_actionMessage, !typed.isEmpty() ? typed : row >= 0 ? m_actionsModel->problemText(row) : QString());
}

QStringList GrafcetStepDock::writableVariables() const
{
    QStringList names;
    for (const core::Variable& variable : document()->model().variables()) {
        if (variable.kind != core::VariableKind::Input) // inputs are never written by actions
            names << fromStd(variable.name);
    }
    names << QStringLiteral("Complete");
    return names;
}

void GrafcetStepDock::focusField(const QString& field)
{
    if (field == QLatin1String("main")) {
        focusFirstAction();
    } else if (field == QLatin1String("comment")) {
        m_commentEdit->setFocus(Qt::OtherFocusReason);
    } else if (field.startsWith(QLatin1String("action"))) {
        // "action:2": the action of index 2.
        const int row = field.section(QLatin1Char(':'), 1).toInt();
        m_actionsView->setFocus(Qt::OtherFocusReason);
        if (row >= 0 && row < m_actionsModel->rowCount())
            m_actionsView->setCurrentIndex(m_actionsModel->index(row, GrafcetActionsModel::VariableColumn));
    } else {
        m_numberSpin->setFocus(Qt::OtherFocusReason);
        m_numberSpin->selectAll();
    }
}

// What the step does is what Enter on it is for: its first action's
// variable, open to type over, or the Add button when it has none.
void GrafcetStepDock::focusFirstAction()
{
    if (m_actionsModel->rowCount() == 0) {
        m_addButton->setFocus(Qt::OtherFocusReason);
        return;
    }
    const QModelIndex cell = m_actionsModel->index(0, GrafcetActionsModel::VariableColumn);
    m_actionsView->setFocus(Qt::OtherFocusReason);
    m_actionsView->setCurrentIndex(cell);
    m_actionsView->edit(cell);
}

void GrafcetStepDock::onNumberChosen(int number)
{
    const QString stepId = elementId();
    const int current = elementNumber();
    if (stepId.isEmpty() || number == current)
        return;
    const core::Grafcet* grafcet = document()->model().grafcet(stepId.toStdString());
    const QString refusal = number < 1 ? tr("Step numbers start at 1: %1 is not a step number.").arg(number)
        : grafcet && grafcet->step(number)
        ? tr("%1 already has a step %2: choose another number.").arg(stepId).arg(number)
        : QString();
    if (!refusal.isEmpty()) {
        showMessage(m_numberMessage, refusal);
        const QSignalBlocker blocker(m_numberSpin);
        m_numberSpin->setValue(current);
        return;
    }
    showMessage(m_numberMessage, QString());
    followNumber(number);
    if (document()->push(new RenumberGrafcetStepCommand(*document(), stepId, current, number)))
        selection()->select(ElementRef::grafcetStep(stepId, number));
    else
        followNumber(current);
}

void GrafcetStepDock::onInitialToggled(bool checked)
{
    if (!elementId().isEmpty())
        document()->push(new SetGrafcetStepInitialCommand(*document(), elementId(), elementNumber(), checked));
    refresh();
}

void GrafcetStepDock::onCommentEdited()
{
    if (!elementId().isEmpty())
        document()->push(new SetGrafcetStepCommentCommand(*document(), elementId(), elementNumber(),
                                                          m_commentEdit->toPlainText()));
}

void GrafcetStepDock::onAddAction()
{
    const int current = m_actionsView->currentIndex().row();
    const int row = current >= 0 ? current + 1 : m_actionsModel->rowCount();
    // An empty continuous action: the Variable cell opens for it at once.
    const core::GrafcetAction action{core::ActionTiming::Continuous, ""};
    if (!document()->push(new AddGrafcetActionCommand(*document(), elementId(), elementNumber(), row, action)))
        return;
    const QModelIndex cell = m_actionsModel->index(row, GrafcetActionsModel::VariableColumn);
    m_actionsView->setCurrentIndex(cell);
    m_actionsView->edit(cell);
}

void GrafcetStepDock::onRemoveAction()
{
    const int row = m_actionsView->currentIndex().row();
    if (row < 0)
        return;
    if (document()->push(new RemoveGrafcetActionCommand(*document(), elementId(), elementNumber(), row))) {
        const int next = std::min(row, m_actionsModel->rowCount() - 1);
        if (next >= 0)
            m_actionsView->setCurrentIndex(m_actionsModel->index(next, GrafcetActionsModel::VariableColumn));
    }
}

void GrafcetStepDock::onMoveAction(int offset)
{
    const QModelIndex current = m_actionsView->currentIndex();
    const int to = current.row() + offset;
    if (!current.isValid() || to < 0 || to >= m_actionsModel->rowCount())
        return;
    if (document()->push(new MoveGrafcetActionCommand(*document(), elementId(), elementNumber(), current.row(), to)))
        m_actionsView->setCurrentIndex(m_actionsModel->index(to, current.column()));
}

} // namespace editor
