#include "editor/docks/gemma/stepdock.h"

#include "editor/commands/initialsteprule.h"
#include "editor/commands/setinitialstepcommand.h"
#include "editor/commands/setstepcommentcommand.h"
#include "editor/commands/setstephiddencommand.h"
#include "editor/commands/setsteptypecommand.h"
#include "editor/docks/diagnosticlist.h"
#include "editor/docks/gemma/startguide.h"
#include "editor/docks/undoshortcutfilter.h"
#include "editor/docks/wrappinglabel.h"
#include "editor/document.h"
#include "editor/grafcet/nestedgrafcetavailable.h"
#include "editor/selection.h"
#include "editor/stdstring.h"
#include "editor/style/secondarytext.h"
#include "editor/style/severityicon.h"
#include "editor/text/diagnostictext.h"
#include "editor/text/elementlabels.h"
#include "editor/text/gemmastatenames.h"

#include "core/model/model.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QStyle>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace editor {

namespace {

constexpr int kTransitionIdRole = Qt::UserRole;

QLabel* sectionLabel(QWidget* parent)
{
    auto* label = new QLabel(parent);
    QFont font = label->font();
    font.setBold(true);
    label->setFont(font);
    return label;
}

// A text field a few lines high: the dock must fit beside the chart at 1366x768.
int linesHeight(const QWidget* widget, int lines)
{
    return widget->fontMetrics().lineSpacing() * lines + 2 * widget->style()->pixelMetric(QStyle::PM_DefaultFrameWidth)
        + 8;
}

QString hiddenToolTip()
{
    return StepDock::tr("A hidden step is not part of this machine: it generates no code, and its "
                        "transitions are not effective.");
}

} // namespace

QString StepDock::title()
{
    return tr("Step");
}

StepDock::StepDock(Document* document, Selection* selection, QWidget* parent)
    : PropertyDock(ElementRef::Kind::Step, title(), document, selection, parent)
{
    setObjectName(QStringLiteral("stepDock"));
    // In a scroll area that gives the form the height there is: the
    // transition lists grow with the dock, and a dock shorter than the form
    // (it shares its column with the Variables dock) scrolls instead of
    // making the window taller than a laptop screen.
    setPages(scrolling(createForm()));
    m_startGuide = new StartGuide;
    setIdlePage(scrolling(m_startGuide));
    retranslate();
}

void StepDock::retranslate()
{
    setWindowTitle(title());
    setPlaceholder(tr("Select a step in the chart to see and edit its properties."));
    m_openGrafcetButton->setText(tr("Open Nested GRAFCET"));
    m_openGrafcetButton->setToolTip(tr("Show the nested GRAFCET of this step in a tab beside the GEMMA chart "
                                       "(double-click the step on the chart does the same)"));
    for (int i = 0; i < m_typeCombo->count(); ++i)
        m_typeCombo->setItemText(i, stepTypeText(static_cast<core::StepType>(m_typeCombo->itemData(i).toInt())));
    m_typeCombo->setToolTip(tr("Simple step: no nested behaviour.\n"
                               "Macro-step: its transitions wait until the nested behaviour is complete.\n"
                               "Enclosing step: its transitions fire whatever the nested behaviour is doing."));
    m_typeLabel->setText(tr("&Type:"));
    m_initialCheck->setText(tr("&Initial"));
    m_hiddenCheck->setText(tr("&Hidden"));
    m_hiddenCheck->setToolTip(hiddenToolTip());
    m_commentLabel->setText(tr("&Comment:"));
    m_commentEdit->setPlaceholderText(tr("What this state does on this machine"));
    m_incomingHeading->setText(tr("Incoming transitions"));
    m_outgoingHeading->setText(tr("Outgoing transitions, by priority"));
    for (QTreeWidget* list : {m_incomingList, m_outgoingList}) {
        list->setHeaderLabels({tr("Transition"), tr("Condition")});
        list->setToolTip(tr("Click a transition to select it"));
    }
}

QWidget* StepDock::createForm()
{
    auto* form = new QWidget;
    auto* layout = new QVBoxLayout(form);
    layout->setContentsMargins(6, 6, 6, 6);
    layout->setSpacing(6);

    auto* header = new QHBoxLayout;
    m_idLabel = new QLabel(form);
    m_idLabel->setObjectName(QStringLiteral("idLabel"));
    QFont idFont = m_idLabel->font();
    idFont.setBold(true);
    idFont.setPointSizeF(idFont.pointSizeF() * 1.3);
    m_idLabel->setFont(idFont);
    m_nameLabel = new WrappingLabel(form);
    m_nameLabel->setObjectName(QStringLiteral("nameLabel"));
    m_nameLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    header->addWidget(m_idLabel, 0, Qt::AlignTop);
    header->addWidget(m_nameLabel, 1);
    layout->addLayout(header);
    m_familyLabel = new QLabel(form);
    m_familyLabel->setEnabled(false); // secondary text
    layout->addWidget(m_familyLabel);

    auto* fields = new QFormLayout;
    fields->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_typeCombo = new QComboBox(form);
    m_typeCombo->setObjectName(QStringLiteral("typeCombo"));
    for (core::StepType type : { core::StepType::Simple, core::StepType::Macro, core::StepType::Enclosing })
        m_typeCombo->addItem(QString(), static_cast<int>(type));
    connect(m_typeCombo, &QComboBox::currentIndexChanged, this, &StepDock::onTypeChosen);
    m_typeLabel = new QLabel(form);
    m_typeLabel->setBuddy(m_typeCombo);
    fields->addRow(m_typeLabel, m_typeCombo);

    auto* flags = new QHBoxLayout;
    m_initialCheck = new QCheckBox(form);
    m_initialCheck->setObjectName(QStringLiteral("initialCheck"));
    connect(m_initialCheck, &QCheckBox::toggled, this, &StepDock::onInitialToggled);
    m_hiddenCheck = new QCheckBox(form);
    m_hiddenCheck->setObjectName(QStringLiteral("hiddenCheck"));
    connect(m_hiddenCheck, &QCheckBox::toggled, this, &StepDock::onHiddenToggled);
    flags->addWidget(m_initialCheck);
    flags->addWidget(m_hiddenCheck);
    flags->addStretch();
    fields->addRow(flags);

    m_openGrafcetButton = new QPushButton(form);
    m_openGrafcetButton->setObjectName(QStringLiteral("openGrafcetButton"));
    connect(m_openGrafcetButton, &QPushButton::clicked, this, [this] { emit openGrafcetRequested(stepId()); });
    fields->addRow(m_openGrafcetButton);

    m_commentEdit = new QPlainTextEdit(form);
    m_commentEdit->setObjectName(QStringLiteral("commentEdit"));
    m_commentEdit->setPlaceholderText(tr("What this state does on this machine"));
    m_commentEdit->setTabChangesFocus(true);
    m_commentEdit->setUndoRedoEnabled(false);
    m_commentEdit->setFixedHeight(linesHeight(m_commentEdit, 3));
    UndoShortcutFilter::install(m_commentEdit);
    connect(m_commentEdit, &QPlainTextEdit::textChanged, this, &StepDock::onCommentEdited);
    m_commentLabel = new QLabel(form);
    m_commentLabel->setBuddy(m_commentEdit);
    fields->addRow(m_commentLabel, m_commentEdit);
    layout->addLayout(fields);

    m_incomingHeading = sectionLabel(form);
    layout->addWidget(m_incomingHeading);
    m_incomingList = createTransitionList(QStringLiteral("incomingList"));
    layout->addWidget(m_incomingList, 1);
    m_outgoingHeading = sectionLabel(form);
    layout->addWidget(m_outgoingHeading);
    m_outgoingList = createTransitionList(QStringLiteral("outgoingList"));
    layout->addWidget(m_outgoingList, 2);

    m_problemList = new DiagnosticList(form);
    m_problemList->setObjectName(QStringLiteral("problemList"));
    layout->addWidget(m_problemList);
    return form;
}

QTreeWidget* StepDock::createTransitionList(const QString& objectName)
{
    auto* list = new QTreeWidget;
    list->setObjectName(objectName);
    list->setColumnCount(2);
    list->setRootIsDecorated(false);
    list->setUniformRowHeights(true);
    list->setAllColumnsShowFocus(true);
    list->setMinimumHeight(linesHeight(list, 4));
    list->header()->setStretchLastSection(true);
    list->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    connect(list, &QTreeWidget::itemClicked, this, &StepDock::onTransitionClicked);
    connect(list, &QTreeWidget::itemActivated, this, &StepDock::onTransitionClicked);
    return list;
}

void StepDock::focusField(const QString& field)
{
    QWidget* target = m_typeCombo;
    if (field == QLatin1String("initial") || field == QLatin1String("hidden"))
        target = m_hiddenCheck; // a hidden initial step: show it, or make another step initial
    else if (field == QLatin1String("incoming"))
        target = m_incomingList;
    else if (field == QLatin1String("outgoing"))
        target = m_outgoingList;
    else if (field == QLatin1String("comment"))
        target = m_commentEdit;
    target->setFocus(Qt::OtherFocusReason);
}

void StepDock::refreshForm()
{
    const core::Step* step = document()->model().step(stepId().toStdString());
    m_idLabel->setText(stepId());
    m_nameLabel->setText(officialStateName(stepId()));
    m_familyLabel->setText(tr("%1 · state number %2").arg(officialFamilyName(step->family)).arg(step->number));
    {
        const QSignalBlocker blocker(m_typeCombo);
        m_typeCombo->setCurrentIndex(m_typeCombo->findData(static_cast<int>(step->type)));
    }
    {
        const QSignalBlocker blocker(m_initialCheck);
        m_initialCheck->setChecked(step->initial);
        // Exactly one step is initial: it changes by making another one initial.
        const QString refusal = InitialStepRule::initialRefusal(document()->model(), stepId());
        m_initialCheck->setEnabled(!step->initial && refusal.isEmpty());
        m_initialCheck->setToolTip(step->initial
                ? tr("%1 is the initial step. There is always exactly one initial step: to change it, "
                     "make another step initial.")
                      .arg(stepId())
                : !refusal.isEmpty()
                ? refusal
                : tr("Make %1 the initial step (the PLC starts in it). The current initial step is %2.")
                      .arg(stepId(), fromStd(document()->model().initialStep().id)));
    }
    {
        const QSignalBlocker blocker(m_hiddenCheck);
        m_hiddenCheck->setChecked(step->hidden);
        // A file may hide its initial step: the box stays enabled to show it.
        const QString refusal = InitialStepRule::hidingRefusal(document()->model(), stepId());
        m_hiddenCheck->setEnabled(refusal.isEmpty());
        m_hiddenCheck->setToolTip(refusal.isEmpty() ? hiddenToolTip() : refusal);
    }
    // A macro or enclosing step without one yet opens on the offer to create its usual shape.
    m_openGrafcetButton->setVisible(canOpenNestedGrafcet(document()->model(), stepId()));
    const QString comment = fromStd(step->comment);
    if (m_commentEdit->toPlainText() != comment) {
        // Only when it differs: rewriting the text under the user's cursor
        // while they type would move the cursor.
        const QSignalBlocker blocker(m_commentEdit);
        m_commentEdit->setPlainText(comment);
        m_commentEdit->moveCursor(QTextCursor::End);
    }
    refreshTransitions();
    refreshProblems();
}

void StepDock::refreshTransitions()
{
    const core::Model& model = document()->model();
    const std::string id = stepId().toStdString();
    const core::Step* step = model.step(id);
    fillList(m_incomingList, model.incoming(id), false);

    std::vector<const core::Transition*> outgoing;
    // The family transition leaves every F state, before its own transitions.
    if (step->family == core::Family::F) {
        for (const core::Transition* family : model.outgoing(core::kFamilySource))
            outgoing.push_back(family);
    }
    for (const core::Transition* transition : model.outgoing(id))
        outgoing.push_back(transition);
    fillList(m_outgoingList, outgoing, true);
}

void StepDock::fillList(QTreeWidget* list, const std::vector<const core::Transition*>& transitions, bool outgoing)
{
    // Refilled on every edit (typing a comment too): keep where the user was.
    const QString current
        = list->currentItem() ? list->currentItem()->data(0, kTransitionIdRole).toString() : QString();
    const int scroll = list->verticalScrollBar()->value();
    list->clear();
    for (const core::Transition* transition : transitions) {
        QTreeWidgetItem* item = transitionItem(*transition, outgoing);
        list->addTopLevelItem(item);
        if (item->data(0, kTransitionIdRole).toString() == current)
            list->setCurrentItem(item);
    }
    list->verticalScrollBar()->setValue(scroll);
}

QTreeWidgetItem* StepDock::transitionItem(const core::Transition& transition, bool outgoing) const
{
    const core::Model& model = document()->model();
    const QString id = fromStd(transition.id);
    QString text;
    if (!outgoing) {
        //: an incoming transition: its source, an arrow
        text = transition.isFamilyTransition() ? tr("F (family) →") : tr("%1 →").arg(fromStd(transition.source));
    } else if (transition.isFamilyTransition()) {
        //: the family transition in the outgoing list of an F state
        text = tr("F: → %1").arg(fromStd(transition.target));
    } else {
        const int priority = model.priority(transition.id);
        //: an outgoing transition: priority, arrow, target ("1: → F4"); – when it has none
        text = tr("%1: → %2").arg(priority > 0 ? QString::number(priority) : tr("–"), fromStd(transition.target));
    }
    if (transition.negated && !transition.isFamilyTransition()) {
        //: a negated transition in the Step dock's lists: the entry, then the mark
        text = tr("%1 (negated)").arg(text);
    }
    auto* item = new QTreeWidgetItem({ text, fromStd(transition.condition) });
    item->setData(0, kTransitionIdRole, id);

    QStringList tip { transitionLabel(transition) };
    if (transition.isFamilyTransition())
        tip << tr("Family transition: evaluated before the own transitions of every visible F state.");
    if (transition.negated)
        tip << tr("Negated");
    if (!transition.condition.empty())
        tip << tr("Condition: %1").arg(fromStd(transition.condition));
    const QString reason = ineffectiveReason(model, transition);
    if (!reason.isEmpty()) {
        tip << tr("Not effective (%1): generates no code.").arg(reason);
        const QColor grey = secondaryTextColor(palette(), QPalette::Base);
        QFont font = item->font(0);
        font.setItalic(true);
        for (int column = 0; column < 2; ++column) {
            item->setForeground(column, grey);
            item->setFont(column, font);
        }
    } else if (document()->hasProblems(ElementRef::transition(id))) {
        const bool error = core::hasErrors(document()->diagnosticsFor(ElementRef::transition(id)));
        item->setIcon(1, severityIcon(error ? core::Severity::Error : core::Severity::Warning));
    }
    item->setToolTip(0, tip.join(QLatin1Char('\n')));
    item->setToolTip(1, tip.join(QLatin1Char('\n')));
    return item;
}

void StepDock::refreshProblems()
{
    m_problemList->setDiagnostics(document()->diagnosticsFor(element()));
}

void StepDock::onTypeChosen(int index)
{
    if (stepId().isEmpty() || index < 0)
        return;
    const auto type = static_cast<core::StepType>(m_typeCombo->itemData(index).toInt());
    document()->push(new SetStepTypeCommand(*document(), stepId(), type));
    refresh(); // a refused edit puts the combo back
}

void StepDock::onInitialToggled(bool checked)
{
    if (stepId().isEmpty())
        return;
    if (checked)
        document()->push(new SetInitialStepCommand(*document(), stepId()));
    refresh();
}

void StepDock::onHiddenToggled(bool checked)
{
    if (stepId().isEmpty())
        return;
    document()->push(new SetStepHiddenCommand(*document(), stepId(), checked));
    refresh();
}

void StepDock::onCommentEdited()
{
    if (stepId().isEmpty())
        return;
    document()->push(new SetStepCommentCommand(*document(), stepId(), m_commentEdit->toPlainText()));
}

void StepDock::onTransitionClicked(QTreeWidgetItem* item)
{
    if (item)
        selection()->select(ElementRef::transition(item->data(0, kTransitionIdRole).toString()));
}

} // namespace editor
