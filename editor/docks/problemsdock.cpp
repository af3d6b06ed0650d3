#include "editor/docks/problemsdock.h"

#include "editor/docks/declarationfix.h"
#include "editor/docks/propertiespanel.h"
#include "editor/docks/propertiestablemodel.h"
#include "editor/docks/verificationpanel.h"
#include "editor/docks/wrappingitemdelegate.h"
#include "editor/document.h"
#include "editor/selection.h"
#include "editor/stdstring.h"
#include "editor/style/severityicon.h"
#include "editor/text/diagnostictext.h"
#include "editor/text/elementlabels.h"
#include "editor/text/packmldiagnostictext.h"
#include "editor/verificationrunner.h"

#include <QAction>
#include <QClipboard>
#include <QEvent>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeySequence>
#include <QScrollBar>
#include <QStyle>
#include <QTabWidget>
#include <QToolButton>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>
#include <QVBoxLayout>

#include <algorithm>

namespace editor {

namespace {

enum Role {
    SeverityRole = Qt::UserRole,
    KindRole,
    IdRole,
    FieldRole,
    KeyRole,   // identifies the problem across refreshes
    GroupRole, // on the row of a nested GRAFCET's problems: its GEMMA step id
    NumberRole, // a nested step or transition number
    DiagnosticRole, // a problem's index in Document::diagnostics(), until the next refresh
};

ElementRef::Kind kindOf(core::Diagnostic::Target target)
{
    switch (target) {
    case core::Diagnostic::Target::Step:
        return ElementRef::Kind::Step;
    case core::Diagnostic::Target::GrafcetStep:
        return ElementRef::Kind::GrafcetStep;
    case core::Diagnostic::Target::GrafcetTransition:
        return ElementRef::Kind::GrafcetTransition;
    case core::Diagnostic::Target::Transition:
        return ElementRef::Kind::Transition;
    case core::Diagnostic::Target::Variable:
        return ElementRef::Kind::Variable;
    case core::Diagnostic::Target::Model:
        return ElementRef::Kind::Model;
    case core::Diagnostic::Target::Mode:
    case core::Diagnostic::Target::Command:
    case core::Diagnostic::Target::ModeState:
    case core::Diagnostic::Target::Request:
        // PackML elements: the editor has no view of them to select yet.
        return ElementRef::Kind::None;
    case core::Diagnostic::Target::MachineComponent:
        // The editor has no view of the machine yet.
        return ElementRef::Kind::None;
    }
    return ElementRef::Kind::None;
}

QString elementText(const core::Diagnostic& diagnostic)
{
    const QString element = fromStd(diagnostic.element);
    switch (diagnostic.target) {
    case core::Diagnostic::Target::Transition:
        return transitionLabel(element);
    case core::Diagnostic::Target::Model:
        return ProblemsDock::tr("Model");
    case core::Diagnostic::Target::GrafcetStep:
        //: A step of the nested GRAFCET of a GEMMA step: "F1 step 3"
        return ProblemsDock::tr("%1 step %2").arg(element).arg(diagnostic.nestedNumber);
    case core::Diagnostic::Target::GrafcetTransition:
        //: A transition of the nested GRAFCET of a GEMMA step: "F1 T2"
        return ProblemsDock::tr("%1 T%2").arg(element).arg(diagnostic.nestedNumber);
    case core::Diagnostic::Target::Mode:
    case core::Diagnostic::Target::Command:
    case core::Diagnostic::Target::ModeState:
    case core::Diagnostic::Target::Request:
        return packmlElementText(diagnostic);
    case core::Diagnostic::Target::MachineComponent:
        //: A component of the virtual machine: "machine component Clamp"
        return ProblemsDock::tr("machine component %1").arg(element);
    default:
        return element;
    }
}

// The field a dock focuses: an action's field names its index ("action:2").
QString fieldOf(const core::Diagnostic& diagnostic)
{
    const QString field = fromStd(diagnostic.field);
    if (field == QLatin1String("action") && diagnostic.actionIndex >= 0)
        return field + QLatin1Char(':') + QString::number(diagnostic.actionIndex);
    return field;
}

QString keyOf(const core::Diagnostic& diagnostic)
{
    return QStringLiteral("%1|%2|%3|%4|%5|%6")
        .arg(fromStd(diagnostic.code), fromStd(diagnostic.element), fromStd(diagnostic.field))
        .arg(diagnostic.span ? static_cast<qlonglong>(diagnostic.span->begin) : -1)
        .arg(diagnostic.nestedNumber)
        .arg(diagnostic.actionIndex);
}

} // namespace

QString ProblemsDock::title()
{
    return tr("Problems");
}

ProblemsDock::ProblemsDock(Document* document, Selection* selection, QWidget* parent)
    : ProblemsDock(document, selection, nullptr, parent)
{
}

ProblemsDock::ProblemsDock(Document* document, Selection* selection, VerificationRunner* verification,
                           QWidget* parent)
    : QDockWidget(title(), parent)
    , m_document(document)
    , m_selection(selection)
    , m_view(new QTreeWidget)
    , m_verification(verification)
{
    setObjectName(QStringLiteral("problemsDock"));

    auto* content = new QWidget(this);
    auto* layout = new QVBoxLayout(content);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    auto* bar = new QHBoxLayout;
    bar->setContentsMargins(4, 2, 4, 2);
    bar->setSpacing(2);
    m_errorsButton = createFilterButton(core::Severity::Error, QStringLiteral("errorsButton"));
    m_warningsButton = createFilterButton(core::Severity::Warning, QStringLiteral("warningsButton"));
    m_infoButton = createFilterButton(core::Severity::Info, QStringLiteral("infoButton"));
    bar->addWidget(m_errorsButton);
    bar->addWidget(m_warningsButton);
    bar->addWidget(m_infoButton);
    bar->addStretch();
    layout->addLayout(bar);

    m_view->setParent(content);
    m_view->setObjectName(QStringLiteral("problemsView"));
    m_view->setColumnCount(3);
    // Decorated: the problems of a nested GRAFCET open and close under its row.
    m_view->setRootIsDecorated(true);
    connect(m_view, &QTreeWidget::itemCollapsed, this, [this](QTreeWidgetItem* item) {
        m_collapsedGroups.insert(item->data(0, GroupRole).toString());
    });
    connect(m_view, &QTreeWidget::itemExpanded, this, [this](QTreeWidgetItem* item) {
        m_collapsedGroups.remove(item->data(0, GroupRole).toString());
    });
    // The messages wrap: in the dock column beside the chart a message is
    // wider than its column, and a cut message says too little.
    new WrappingItemDelegate(m_view, MessageColumn);
    m_view->setAllColumnsShowFocus(true);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->setTextElideMode(Qt::ElideRight);
    m_view->header()->setStretchLastSection(true);
    // The code whole, with its icon and, under a GRAFCET's row, the indentation.
    m_view->header()->setSectionResizeMode(CodeColumn, QHeaderView::ResizeToContents);
    m_view->header()->resizeSection(ElementColumn, 90);
    m_view->setToolTip(QString());
    m_view->setContextMenuPolicy(Qt::ActionsContextMenu);
    m_copyAction = new QAction(m_view);
    connect(m_copyAction, &QAction::triggered, this, &ProblemsDock::copySelected);
    m_view->addAction(m_copyAction);
    m_declareAction = new QAction(m_view);
    m_declareAction->setObjectName(QStringLiteral("declareVariableAction"));
    m_declareAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Period));
    m_declareAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_declareAction->setVisible(false);
    connect(m_declareAction, &QAction::triggered, this, &ProblemsDock::declareCurrent);
    m_view->addAction(m_declareAction);
    connect(m_view, &QTreeWidget::currentItemChanged, this, &ProblemsDock::updateDeclareAction);
    // The guess reads every use of the name: an edit elsewhere may change it.
    connect(m_document, &Document::grafcetChanged, this, &ProblemsDock::updateDeclareAction);
    connect(m_document, &Document::transitionChanged, this, &ProblemsDock::updateDeclareAction);
    connect(m_document, &Document::readOnlyChanged, this, &ProblemsDock::updateDeclareAction);
    connect(m_view, &QTreeWidget::itemActivated, this, &ProblemsDock::activate);
    layout->addWidget(m_view, 1);
    if (m_verification) {
        m_tabs = new QTabWidget(this);
        m_tabs->setObjectName(QStringLiteral("problemsTabs"));
        m_tabs->setDocumentMode(true);
        m_verificationPanel = new VerificationPanel(m_verification, m_selection);
        m_tabs->addTab(content, QString());
        m_tabs->addTab(m_verificationPanel, QString());
        m_propertiesPanel = new PropertiesPanel(m_document);
        m_tabs->addTab(m_propertiesPanel, QString());
        // With single faults on, `faulted` is a word of the properties (docs/verification.md).
        const auto offerFaultAtoms = [this] {
            m_propertiesPanel->tableModel()->setFaultAtoms(m_verification->nextRunSingleFaults());
        };
        connect(m_verification, &VerificationRunner::assumptionsChanged, m_propertiesPanel, offerFaultAtoms);
        connect(m_document, &Document::machineChanged, m_propertiesPanel, offerFaultAtoms);
        connect(m_document, &Document::modelReset, m_propertiesPanel, offerFaultAtoms);
        connect(m_document, &Document::propertiesChanged, this, &ProblemsDock::updateTabTexts);
        connect(m_document, &Document::modelReset, this, &ProblemsDock::updateTabTexts);
        connect(m_verification, &VerificationRunner::finished, this, &ProblemsDock::updateTabTexts);
        connect(m_verification, &VerificationRunner::staleChanged, this, &ProblemsDock::updateTabTexts);
        connect(m_verification, &VerificationRunner::resultCleared, this, &ProblemsDock::updateTabTexts);
        connect(m_verification, &VerificationRunner::assumptionsChanged, this, &ProblemsDock::updateTabTexts);
        setWidget(m_tabs);
    } else {
        setWidget(content);
    }

    connect(m_document, &Document::diagnosticsChanged, this, &ProblemsDock::refresh);
    connect(m_document, &Document::modelReset, this, &ProblemsDock::refresh);
    retranslate();
}

void ProblemsDock::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDockWidget::changeEvent(event);
}

// The messages too: they are worded in the UI language when listed.
void ProblemsDock::retranslate()
{
    setWindowTitle(title());
    m_view->setHeaderLabels({ tr("Code"), tr("Element"), tr("Message") });
    m_copyAction->setText(tr("&Copy"));
    refresh();
}

QToolButton* ProblemsDock::createFilterButton(core::Severity severity, const QString& objectName)
{
    auto* button = new QToolButton;
    button->setObjectName(objectName);
    button->setCheckable(true);
    button->setChecked(true);
    button->setAutoRaise(true);
    button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    button->setIcon(severityIcon(severity));
    button->setIconSize(QSize(16, 16));
    connect(button, &QToolButton::toggled, this, &ProblemsDock::applyFilter);
    return button;
}

bool ProblemsDock::isShown(core::Severity severity) const
{
    switch (severity) {
    case core::Severity::Error:
        return m_errorsButton->isChecked();
    case core::Severity::Warning:
        return m_warningsButton->isChecked();
    case core::Severity::Info:
        return m_infoButton->isChecked();
    }
    return true;
}

void ProblemsDock::refresh()
{
    const QTreeWidgetItem* current = m_view->currentItem();
    const QString currentKey = current ? current->data(0, KeyRole).toString() : QString();
    const int scroll = m_view->verticalScrollBar()->value();

    m_view->clear();
    QList<QTreeWidgetItem*> topLevel;
    QHash<QString, QTreeWidgetItem*> groups;
    QTreeWidgetItem* newCurrent = nullptr;
    const std::vector<core::Diagnostic>& diagnostics = m_document->diagnostics();
    for (std::size_t index = 0; index < diagnostics.size(); ++index) {
        const core::Diagnostic& diagnostic = diagnostics[index];
        const QString message = diagnosticText(diagnostic);
        auto* item = new QTreeWidgetItem({ fromStd(diagnostic.code), elementText(diagnostic), message });
        item->setIcon(CodeColumn, severityIcon(diagnostic.severity));
        item->setToolTip(CodeColumn, severityText(diagnostic.severity));
        item->setToolTip(MessageColumn, message);
        item->setData(0, SeverityRole, static_cast<int>(diagnostic.severity));
        item->setData(0, KindRole, static_cast<int>(kindOf(diagnostic.target)));
        item->setData(0, IdRole, fromStd(diagnostic.element));
        item->setData(0, FieldRole, fieldOf(diagnostic));
        item->setData(0, NumberRole, diagnostic.nestedNumber);
        item->setData(0, KeyRole, keyOf(diagnostic));
        item->setData(0, DiagnosticRole, static_cast<qulonglong>(index));
        if (!newCurrent && !currentKey.isEmpty() && item->data(0, KeyRole).toString() == currentKey)
            newCurrent = item;
        const bool nested = diagnostic.target == core::Diagnostic::Target::GrafcetStep
                         || diagnostic.target == core::Diagnostic::Target::GrafcetTransition;
        if (nested)
            grafcetGroup(fromStd(diagnostic.element), topLevel, groups)->addChild(item);
        else
            topLevel << item;
    }
    m_view->addTopLevelItems(topLevel);
    for (auto it = groups.cbegin(); it != groups.cend(); ++it)
        it.value()->setExpanded(!m_collapsedGroups.contains(it.key()));
    updateGroupTexts();
    if (newCurrent)
        m_view->setCurrentItem(newCurrent);
    applyFilter();
    updateFilterButtons();
    updateDeclareAction();
    m_view->verticalScrollBar()->setValue(scroll);
}

const core::Diagnostic* ProblemsDock::currentDiagnostic() const
{
    const QTreeWidgetItem* item = m_view->currentItem();
    const QVariant index = item ? item->data(0, DiagnosticRole) : QVariant();
    const std::vector<core::Diagnostic>& diagnostics = m_document->diagnostics();
    if (!index.isValid() || index.toULongLong() >= diagnostics.size())
        return nullptr;
    return &diagnostics[index.toULongLong()];
}

void ProblemsDock::updateDeclareAction()
{
    const core::Diagnostic* diagnostic = currentDiagnostic();
    const std::optional<DeclarationFix> fix
        = diagnostic ? DeclarationFix::of(m_document->model(), *diagnostic) : std::nullopt;
    m_declareAction->setVisible(fix.has_value());
    m_declareAction->setEnabled(fix.has_value() && !m_document->isReadOnly());
    m_declareAction->setText(fix ? fix->text() : QString());
}

void ProblemsDock::declareCurrent()
{
    const core::Diagnostic* diagnostic = currentDiagnostic();
    if (!diagnostic)
        return;
    if (const std::optional<DeclarationFix> fix = DeclarationFix::of(m_document->model(), *diagnostic))
        fix->apply(*m_document);
}

QTreeWidgetItem* ProblemsDock::grafcetGroup(const QString& stepId, QList<QTreeWidgetItem*>& topLevel,
                                            QHash<QString, QTreeWidgetItem*>& groups) const
{
    QTreeWidgetItem*& group = groups[stepId];
    if (!group) {
        group = new QTreeWidgetItem;
        group->setData(0, GroupRole, stepId);
        // Activating the group selects its GEMMA step.
        group->setData(0, KindRole, static_cast<int>(ElementRef::Kind::Step));
        group->setData(0, IdRole, stepId);
        group->setData(0, KeyRole, QStringLiteral("group|") + stepId);
        topLevel << group;
    }
    return group;
}

// "F1 GRAFCET: 3 problems", with the worst severity's icon.
void ProblemsDock::updateGroupTexts()
{
    for (int i = 0; i < m_view->topLevelItemCount(); ++i) {
        QTreeWidgetItem* group = m_view->topLevelItem(i);
        const QString stepId = group->data(0, GroupRole).toString();
        if (stepId.isEmpty())
            continue;
        auto worst = core::Severity::Info;
        for (int c = 0; c < group->childCount(); ++c)
            worst = std::min(worst, static_cast<core::Severity>(group->child(c)->data(0, SeverityRole).toInt()));
        group->setData(0, SeverityRole, static_cast<int>(worst));
        group->setIcon(CodeColumn, severityIcon(worst));
        //: The row that holds the problems of a GEMMA step's nested GRAFCET: "F1 GRAFCET"
        group->setText(ElementColumn, tr("%1 GRAFCET").arg(stepId));
        // A singular text of its own, as the filter buttons: English has no "%n" form for one.
        const int count = group->childCount();
        group->setText(MessageColumn, count == 1 ? tr("Nested GRAFCET of %1: 1 problem").arg(stepId)
                                                 : tr("Nested GRAFCET of %1: %n problems", nullptr, count).arg(stepId));
    }
}

void ProblemsDock::updateFilterButtons()
{
    int counts[3] = { 0, 0, 0 };
    for (const core::Diagnostic& diagnostic : m_document->diagnostics())
        ++counts[static_cast<int>(diagnostic.severity)];
    const int errors = counts[static_cast<int>(core::Severity::Error)];
    const int warnings = counts[static_cast<int>(core::Severity::Warning)];
    const int infos = counts[static_cast<int>(core::Severity::Info)];
    // Singular texts of their own: English has no "%n" form for one.
    m_errorsButton->setText(errors == 1 ? tr("1 error") : tr("%n errors", nullptr, errors));
    m_warningsButton->setText(warnings == 1 ? tr("1 warning") : tr("%n warnings", nullptr, warnings));
    m_infoButton->setText(infos == 1 ? tr("1 info") : tr("%n infos", nullptr, infos));
    m_errorsButton->setToolTip(tr("Show or hide the errors"));
    m_warningsButton->setToolTip(tr("Show or hide the warnings"));
    m_infoButton->setToolTip(tr("Show or hide the information messages"));
    updateTabTexts();
}

void ProblemsDock::updateTabTexts()
{
    if (!m_tabs)
        return;
    const std::size_t diagnostics = m_document->diagnostics().size();
    m_tabs->setTabText(0, tr("Checks (%1)").arg(diagnostics));
    const core::VerificationResult& result = m_verification->result();
    QString verification = tr("Verification");
    if (m_verification->hasResult())
        verification = m_verification->isStale() || m_verification->assumptionsDiffer()
                           ? tr("Verification (outdated)")
                           : tr("Verification (%1)").arg(result.findings.size());
    m_tabs->setTabText(1, verification);
    // The worst severity found, at a glance.
    QIcon icon;
    if (m_verification->hasResult() && !result.findings.empty()) {
        core::Severity worst = core::Severity::Info;
        for (const core::VerificationFinding& finding : result.findings)
            worst = std::min(worst, finding.severity);
        icon = severityIcon(worst);
    }
    m_tabs->setTabIcon(1, icon);
    const std::size_t properties = m_document->model().properties().size();
    m_tabs->setTabText(2, properties == 0 ? PropertiesPanel::title()
                                          : tr("%1 (%2)").arg(PropertiesPanel::title()).arg(properties));
}

void ProblemsDock::showProperties()
{
    if (m_tabs)
        m_tabs->setCurrentWidget(m_propertiesPanel);
}

void ProblemsDock::showVerification()
{
    if (m_tabs)
        m_tabs->setCurrentWidget(m_verificationPanel);
}

void ProblemsDock::applyFilter()
{
    for (int i = 0; i < m_view->topLevelItemCount(); ++i) {
        QTreeWidgetItem* item = m_view->topLevelItem(i);
        if (item->childCount() == 0) {
            item->setHidden(!isShown(static_cast<core::Severity>(item->data(0, SeverityRole).toInt())));
            continue;
        }
        // A GRAFCET group: its shown problems, and itself while it has one.
        bool anyShown = false;
        for (int c = 0; c < item->childCount(); ++c) {
            QTreeWidgetItem* child = item->child(c);
            const bool shown = isShown(static_cast<core::Severity>(child->data(0, SeverityRole).toInt()));
            child->setHidden(!shown);
            anyShown = anyShown || shown;
        }
        item->setHidden(!anyShown);
    }
}

void ProblemsDock::activate(QTreeWidgetItem* item)
{
    if (!item)
        return;
    ElementRef element;
    element.kind = static_cast<ElementRef::Kind>(item->data(0, KindRole).toInt());
    element.id = item->data(0, IdRole).toString();
    if (element.isNested())
        element.number = item->data(0, NumberRole).toInt();
    m_selection->select(element, item->data(0, FieldRole).toString());
}

void ProblemsDock::copySelected()
{
    QStringList lines;
    for (QTreeWidgetItemIterator it(m_view); *it; ++it) {
        const QTreeWidgetItem* item = *it;
        const bool problem = item->data(0, GroupRole).toString().isEmpty();
        if (problem && (item->isSelected() || (item->parent() && item->parent()->isSelected())) && !item->isHidden())
            lines << QStringLiteral("%1\t%2\t%3")
                         .arg(item->text(CodeColumn), item->text(ElementColumn), item->text(MessageColumn));
    }
    if (!lines.isEmpty())
        QGuiApplication::clipboard()->setText(lines.join(QLatin1Char('\n')) + QLatin1Char('\n'));
}

} // namespace editor
