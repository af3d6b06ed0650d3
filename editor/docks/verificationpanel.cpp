#include "editor/docks/verificationpanel.h"

#include "editor/app/settings.h"
#include "editor/docks/wrappingitemdelegate.h"
#include "editor/docks/wrappinglabel.h"
#include "editor/selection.h"
#include "editor/style/secondarytext.h"
#include "editor/style/severityicon.h"
#include "editor/text/diagnostictext.h"
#include "editor/text/displaytext.h"
#include "editor/text/elementlabels.h"
#include "editor/text/gemmastatenames.h"
#include "editor/verificationrunner.h"

#include <QAction>
#include <QClipboard>
#include <QEvent>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSpinBox>
#include <QStyle>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <QTreeWidgetItemIterator>

#include <algorithm>
#include <map>
#include <numeric>
#include <optional>

namespace editor {

namespace {

constexpr int kIndexRole = Qt::UserRole;
// On the row of a GEMMA step that groups the findings about its nested GRAFCET: the step id.
constexpr int kGroupRole = Qt::UserRole + 1;

// A nested element as the core names it: "F1/5" (step 5 of F1's GRAFCET) or
// "F1/T3" (its transition 3).
struct NestedElement {
    QString stepId;
    int number = 0;
    bool transition = false;
};

std::optional<NestedElement> nestedElement(const std::string& id)
{
    const QString text = QString::fromStdString(id);
    const qsizetype slash = text.lastIndexOf(QLatin1Char('/'));
    if (slash <= 0)
        return std::nullopt;
    NestedElement element{text.left(slash), 0, text.at(slash + 1) == QLatin1Char('T')};
    bool ok = false;
    element.number = text.mid(slash + (element.transition ? 2 : 1)).toInt(&ok);
    if (!ok)
        return std::nullopt;
    return element;
}

// The whole model (GV100 of the exploration of both layers) is no element of a chart.
bool isModel(const std::string& id)
{
    return id == "model";
}

QString elementText(const std::string& id)
{
    if (const std::optional<NestedElement> nested = nestedElement(id))
        return nested->transition
            //: A transition of a nested GRAFCET: %1 the GEMMA step, %2 its number
            ? VerificationPanel::tr("%1: T%2").arg(nested->stepId).arg(nested->number)
            //: A step of a nested GRAFCET: %1 the GEMMA step, %2 its number
            : VerificationPanel::tr("%1: step %2").arg(nested->stepId).arg(nested->number);
    if (isModel(id))
        return VerificationPanel::tr("Model");
    const QString text = QString::fromStdString(id);
    return text.contains(QLatin1String("->")) ? transitionLabel(text) : text;
}

// A property finding names no element: the property's text stands for it,
// cut before the view lays out megabytes of it.
QString elementsText(const core::VerificationFinding& finding)
{
    if (finding.property >= 0 && !finding.arguments.empty())
        return elidedText(QString::fromStdString(finding.arguments.front()));
    QStringList parts;
    for (const std::string& id : finding.elements)
        parts << elementText(id);
    return parts.join(QStringLiteral(", "));
}

// What Show on Chart selects for an element id; a null ref for none.
ElementRef elementRef(const std::string& id)
{
    if (const std::optional<NestedElement> nested = nestedElement(id))
        return nested->transition ? ElementRef::grafcetTransition(nested->stepId, nested->number)
                                  : ElementRef::grafcetStep(nested->stepId, nested->number);
    if (isModel(id))
        return {};
    const QString text = QString::fromStdString(id);
    return text.contains(QLatin1String("->")) ? ElementRef::transition(text) : ElementRef::step(text);
}

// A PackML finding points where the checks' diagnostics do: a mode, a
// state in a mode, a command.
ElementRef packmlElementRef(const core::Diagnostic& location)
{
    using Target = core::Diagnostic::Target;
    switch (location.target) {
    case Target::Mode: return ElementRef::packmlMode(location.mode);
    case Target::ModeState: return ElementRef::packmlState(QString::fromStdString(location.state), location.mode);
    case Target::Command: return ElementRef::packmlCommand(QString::fromStdString(location.element));
    default: return {};
    }
}

ElementRef firstElementRef(const core::VerificationFinding* finding)
{
    if (finding && finding->location)
        return packmlElementRef(*finding->location);
    return finding && !finding->elements.empty() ? elementRef(finding->elements.front()) : ElementRef{};
}

QString groupTitle(const QString& stepId)
{
    const QString name = officialStateName(stepId);
    const QString step = name.isEmpty() ? stepId : QStringLiteral("%1 %2").arg(stepId, name);
    //: The row that groups the findings about the nested GRAFCET of a GEMMA step, e.g. "F1 Normal production"
    return VerificationPanel::tr("%1: nested GRAFCET").arg(step);
}

QString copiedLine(const QTreeWidgetItem* item)
{
    if (!item->data(0, kGroupRole).toString().isEmpty())
        return item->text(VerificationPanel::CodeColumn);
    return QStringLiteral("%1\t%2\t%3")
        .arg(item->text(VerificationPanel::CodeColumn), item->text(VerificationPanel::ElementColumn),
             item->text(VerificationPanel::MessageColumn));
}

QToolButton* toolButton(QAction* action, QWidget* parent)
{
    auto* button = new QToolButton(parent);
    button->setDefaultAction(action);
    button->setAutoRaise(true);
    button->setToolButtonStyle(Qt::ToolButtonTextOnly);
    return button;
}

} // namespace

VerificationPanel::VerificationPanel(VerificationRunner* runner, Selection* selection, QWidget* parent)
    : QWidget(parent)
    , m_runner(runner)
    , m_selection(selection)
    , m_view(new QTreeWidget(this))
    , m_statusLabel(new WrappingLabel(this))
    , m_assumptionsLabel(new WrappingLabel(this))
    , m_verifyAction(new QAction(this))
    , m_showAction(new QAction(this))
    , m_replayAction(new QAction(this))
    , m_copyAction(new QAction(m_view))
    , m_timeLimitLabel(new QLabel(this))
    , m_timeLimitBox(new QSpinBox(this))
{
    Q_ASSERT(runner && selection);
    setObjectName(QStringLiteral("verificationPanel"));
    m_verifyAction->setObjectName(QStringLiteral("panelVerifyAction"));
    m_showAction->setObjectName(QStringLiteral("showOnChartAction"));
    m_replayAction->setObjectName(QStringLiteral("replayCounterexampleAction"));
    connect(m_verifyAction, &QAction::triggered, m_runner, &VerificationRunner::start);
    connect(m_showAction, &QAction::triggered, this, [this] { showOnChart(m_view->currentItem()); });
    connect(m_replayAction, &QAction::triggered, this, [this] { replay(m_view->currentItem()); });

    setUpTimeLimit();

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    auto* bar = new QHBoxLayout;
    bar->setContentsMargins(4, 2, 4, 2);
    bar->setSpacing(4);
    auto* verifyButton = toolButton(m_verifyAction, this);
    verifyButton->setObjectName(QStringLiteral("verifyButton"));
    bar->addWidget(verifyButton);
    bar->addStretch(1);
    bar->addWidget(toolButton(m_showAction, this));
    bar->addWidget(toolButton(m_replayAction, this));
    layout->addLayout(bar);
    // A row of its own: beside the buttons it would widen the dock column.
    auto* limitRow = new QHBoxLayout;
    limitRow->setContentsMargins(6, 0, 4, 2);
    limitRow->setSpacing(4);
    limitRow->addWidget(m_timeLimitLabel);
    limitRow->addWidget(m_timeLimitBox);
    limitRow->addStretch(1);
    layout->addLayout(limitRow);
    // The status and the assumptions on lines of their own, wrapped: in the
    // dock column a status such as "Model changed since verification:
    // verify again…" is wider than the dock, and it must never be cut.
    m_statusLabel->setObjectName(QStringLiteral("verificationStatus"));
    m_statusLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_statusLabel->setContentsMargins(6, 0, 6, 2);
    layout->addWidget(m_statusLabel);
    m_assumptionsLabel->setObjectName(QStringLiteral("verificationAssumptions"));
    m_assumptionsLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_assumptionsLabel->setContentsMargins(6, 0, 6, 2);
    layout->addWidget(m_assumptionsLabel);

    m_view->setObjectName(QStringLiteral("verificationView"));
    m_view->setColumnCount(4);
    m_view->setRootIsDecorated(false); // until findings are grouped under a GEMMA step
    m_view->setIndentation(10);
    new WrappingItemDelegate(m_view, MessageColumn); // the messages wrap, never cut
    m_view->setAllColumnsShowFocus(true);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->header()->setStretchLastSection(true);
    // Narrow enough to leave the message most of the dock column.
    m_view->header()->resizeSection(CodeColumn, 72);
    m_view->header()->resizeSection(ElementColumn, 100);
    m_view->header()->resizeSection(ScansColumn, 46);
    m_view->setContextMenuPolicy(Qt::ActionsContextMenu);
    auto* separator = new QAction(m_view);
    separator->setSeparator(true);
    connect(m_copyAction, &QAction::triggered, this, &VerificationPanel::copySelected);
    m_view->addActions({m_showAction, m_replayAction, separator, m_copyAction});
    connect(m_view, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) { showOnChart(item); });
    connect(m_view, &QTreeWidget::currentItemChanged, this, &VerificationPanel::updateActions);
    // A group the user collapsed stays collapsed when the findings are listed again.
    connect(m_view, &QTreeWidget::itemCollapsed, this, [this](const QTreeWidgetItem* item) {
        if (const QString group = item->data(0, kGroupRole).toString(); !group.isEmpty())
            m_collapsedGroups.insert(group);
    });
    connect(m_view, &QTreeWidget::itemExpanded, this, [this](const QTreeWidgetItem* item) {
        m_collapsedGroups.remove(item->data(0, kGroupRole).toString());
    });
    layout->addWidget(m_view, 1);

    connect(m_runner, &VerificationRunner::started, this, &VerificationPanel::refreshStatus);
    connect(m_runner, &VerificationRunner::cancelled, this, &VerificationPanel::refreshStatus);
    connect(m_runner, &VerificationRunner::finished, this, &VerificationPanel::refresh);
    connect(m_runner, &VerificationRunner::staleChanged, this, &VerificationPanel::refresh);
    connect(m_runner, &VerificationRunner::resultCleared, this, &VerificationPanel::refresh);
    connect(m_runner, &VerificationRunner::assumptionsChanged, this, &VerificationPanel::refresh);
    retranslate();
}

void VerificationPanel::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

// The findings too: they are worded in the UI language when listed.
void VerificationPanel::setUpTimeLimit()
{
    m_timeLimitBox->setObjectName(QStringLiteral("verificationTimeLimit"));
    m_timeLimitBox->setRange(Settings::kMinVerificationSeconds, Settings::kMaxVerificationSeconds);
    m_timeLimitBox->setValue(Settings().verificationTimeLimitSeconds());
    m_timeLimitLabel->setBuddy(m_timeLimitBox);
    m_runner->setTimeLimit(std::chrono::seconds(m_timeLimitBox->value()));
    connect(m_timeLimitBox, &QSpinBox::valueChanged, this, [this](int seconds) {
        m_runner->setTimeLimit(std::chrono::seconds(seconds));
        Settings().setVerificationTimeLimitSeconds(seconds);
    });
}

void VerificationPanel::retranslate()
{
    m_verifyAction->setText(tr("&Verify"));
    m_verifyAction->setToolTip(tr("Explore every input sequence of the GEMMA layer and report what cannot happen"));
    m_showAction->setText(tr("&Show on Chart"));
    m_showAction->setToolTip(tr("Select the element of the finding on the chart"));
    m_replayAction->setText(tr("&Replay in Simulator"));
    m_copyAction->setText(tr("&Copy"));
    m_timeLimitLabel->setText(tr("&Time limit:"));
    //: The unit after the verification's time limit: "4 s"
    m_timeLimitBox->setSuffix(tr(" s"));
    const QString limitTip = tr("How long a verification may run. Past it, what is not decided yet is reported "
                                "as undecided (GV100) with how far the exploration got: give more time and verify "
                                "again.");
    m_timeLimitLabel->setToolTip(limitTip);
    m_timeLimitBox->setToolTip(limitTip);
    m_view->setHeaderLabels({tr("Code"), tr("Element"), tr("Scans"), tr("Message")});
    m_view->headerItem()->setToolTip(ScansColumn, tr("Scans of the counterexample, which the simulator can replay"));
    refresh();
}

int VerificationPanel::findingIndex(const QTreeWidgetItem* item)
{
    return item ? item->data(0, kIndexRole).toInt() : -1;
}

void VerificationPanel::refresh()
{
    // The same finding (or group) stays current: entering the simulation to
    // replay one refreshes the list (the Complete assumptions change).
    const QTreeWidgetItem* currentItem = m_view->currentItem();
    const int current = findingIndex(currentItem);
    const QString currentGroup = currentItem ? currentItem->data(0, kGroupRole).toString() : QString();
    m_view->clear();
    const std::vector<core::VerificationFinding>& findings = m_runner->result().findings;
    // A stale finding is greyed: it describes the model, or assumptions, as they were.
    const bool stale = m_runner->isStale() || m_runner->assumptionsDiffer();
    // Errors first: the core orders by code, and the violations matter most.
    std::vector<std::size_t> order(findings.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return findings[a].severity < findings[b].severity; });
    // The findings about a nested GRAFCET under their GEMMA step, whose row
    // takes the place of its worst finding.
    QList<QTreeWidgetItem*> items;
    std::map<std::string, QTreeWidgetItem*> groups;
    for (std::size_t i : order) {
        const core::VerificationFinding& finding = findings[i];
        QTreeWidgetItem* item = findingItem(finding, static_cast<int>(i), stale);
        if (finding.gemmaStep.empty()) {
            items << item;
            continue;
        }
        QTreeWidgetItem*& group = groups[finding.gemmaStep];
        if (!group) {
            group = groupItem(QString::fromStdString(finding.gemmaStep), finding.severity, stale);
            items << group;
        }
        group->addChild(item);
    }
    showGrouped(!groups.empty());
    m_view->addTopLevelItems(items);
    for (const auto& [stepId, group] : groups) {
        group->setFirstColumnSpanned(true);
        group->setExpanded(!m_collapsedGroups.contains(QString::fromStdString(stepId)));
    }
    QTreeWidgetItem* same = nullptr;
    for (QTreeWidgetItemIterator it(m_view); *it && !same; ++it) {
        const QString group = (*it)->data(0, kGroupRole).toString();
        if (group.isEmpty() ? findingIndex(*it) == current && current >= 0 : group == currentGroup)
            same = *it;
    }
    if (!same && !items.isEmpty())
        same = items.front();
    if (same)
        m_view->setCurrentItem(same, 0, QItemSelectionModel::NoUpdate);
    refreshStatus();
    updateActions();
}

QTreeWidgetItem* VerificationPanel::findingItem(const core::VerificationFinding& finding, int index, bool stale) const
{
    const QString message = verificationText(finding);
    const QString scans = finding.counterexample ? QString::number(finding.counterexample->scans) : QString();
    auto* item = new QTreeWidgetItem({QString::fromStdString(finding.code), elementsText(finding), scans, message});
    item->setIcon(CodeColumn, severityIcon(finding.severity));
    item->setToolTip(CodeColumn, severityText(finding.severity));
    item->setToolTip(ElementColumn, boundedToolTip(item->text(ElementColumn)));
    item->setToolTip(MessageColumn, boundedToolTip(message));
    item->setTextAlignment(ScansColumn, Qt::AlignRight | Qt::AlignVCenter);
    item->setData(0, kIndexRole, index);
    if (stale)
        greyOut(item);
    return item;
}

// `worst`: the severity of its first finding, errors coming first.
QTreeWidgetItem* VerificationPanel::groupItem(const QString& stepId, core::Severity worst, bool stale) const
{
    auto* item = new QTreeWidgetItem({groupTitle(stepId)});
    item->setIcon(CodeColumn, severityIcon(worst));
    item->setToolTip(CodeColumn, tr("The findings about the nested GRAFCET of %1").arg(stepId));
    item->setData(0, kIndexRole, -1);
    item->setData(0, kGroupRole, stepId);
    QFont font = item->font(CodeColumn);
    font.setBold(true);
    item->setFont(CodeColumn, font);
    if (stale)
        greyOut(item);
    return item;
}

// The branches take room from the code column: it grows by their indents,
// so that the codes of the nested findings are not cut, taken from the
// elements, so that the messages keep their width in the dock column.
void VerificationPanel::showGrouped(bool grouped)
{
    if (grouped == m_view->rootIsDecorated())
        return;
    const int indents = (grouped ? 2 : -2) * m_view->indentation();
    QHeaderView* header = m_view->header();
    header->resizeSection(CodeColumn, header->sectionSize(CodeColumn) + indents);
    header->resizeSection(ElementColumn, header->sectionSize(ElementColumn) - indents);
    m_view->setRootIsDecorated(grouped);
}

void VerificationPanel::greyOut(QTreeWidgetItem* item) const
{
    const QBrush grey(secondaryTextColor(palette(), QPalette::Base));
    for (int column = 0; column < m_view->columnCount(); ++column)
        item->setForeground(column, grey);
}

void VerificationPanel::refreshStatus()
{
    QString text;
    if (m_runner->isRunning()) {
        text = tr("Verifying…");
    } else if (!m_runner->failure().isEmpty()) {
        text = tr("Verification failed: %1.").arg(m_runner->failure());
    } else if (!m_runner->hasResult()) {
        text = tr("Not verified yet.");
    } else if (m_runner->isStale()) {
        text = tr("Model changed since verification: verify again to update the findings.");
    } else if (m_runner->completeAssumptionsDiffer()) {
        text = tr("Complete settings changed since verification: verify again to update the findings.");
    } else if (m_runner->timeCountingDiffers()) {
        text = m_runner->exactTime()
            ? tr("Exact time switched on since verification: verify again to update the findings.")
            : tr("Exact time switched off since verification: verify again to update the findings.");
    } else if (m_runner->machineUseDiffers()) {
        text = m_runner->nextRunClosedLoop()
            ? tr("The machine is used since verification: verify again to update the findings.")
            : tr("The machine is no longer used since verification: verify again to update the findings.");
    } else if (m_runner->faultUseDiffers()) {
        text = m_runner->nextRunSingleFaults()
            ? tr("Single faults switched on since verification: verify again to update the findings.")
            : tr("Single faults switched off since verification: verify again to update the findings.");
    } else {
        const core::VerificationResult& result = m_runner->result();
        const QString configurations = QString::number(static_cast<qulonglong>(result.configurations));
        const QString states = QString::number(static_cast<qulonglong>(result.programStates));
        if (!result.bothLayers) {
            if (result.violated())
                text = tr("Some properties do not hold (%1 configurations explored).").arg(configurations);
            else if (result.undecided())
                text = tr("Nothing is violated, but some properties are undecided: see the findings (%1 "
                          "configurations explored).")
                           .arg(configurations);
            else if (!result.findings.empty())
                text = tr("Every property holds; see the notes (%1 configurations explored).").arg(configurations);
            else
                text = tr("Every property holds (%1 configurations explored).").arg(configurations);
        } else if (result.violated()) {
            text = tr("Some properties do not hold (%1 configurations of the GEMMA layer and %2 program states of "
                      "both layers explored).")
                       .arg(configurations, states);
        } else if (result.undecided()) {
            text = tr("Nothing is violated, but some properties are undecided: see the findings (%1 configurations "
                      "of the GEMMA layer and %2 program states of both layers explored).")
                       .arg(configurations, states);
        } else if (!result.findings.empty()) {
            text = tr("Every property holds; see the notes (%1 configurations of the GEMMA layer and %2 program "
                      "states of both layers explored).")
                       .arg(configurations, states);
        } else {
            text = tr("Every property holds (%1 configurations of the GEMMA layer and %2 program states of both "
                      "layers explored).")
                       .arg(configurations, states);
        }
    }
    m_statusLabel->setText(text);
    refreshAssumptions();
}

// What the shown findings assume, else what Verify will assume.
void VerificationPanel::refreshAssumptions()
{
    const QStringList automatic =
        m_runner->hasResult() ? m_runner->resultAssumedAutomatic() : m_runner->assumedAutomatic();
    const bool exactTime = m_runner->hasResult() ? m_runner->resultExactTime() : m_runner->exactTime();
    const bool closedLoop = m_runner->hasResult() ? m_runner->resultClosedLoop() : m_runner->nextRunClosedLoop();
    const bool singleFaults
        = m_runner->hasResult() ? m_runner->resultSingleFaults() : m_runner->nextRunSingleFaults();
    QString text = automatic.isEmpty()
        ? tr("All Complete outputs free")
        : tr("Assumed Complete automatic: %1").arg(automatic.join(QStringLiteral(", ")));
    if (exactTime)
        text += QStringLiteral(" \u00b7 ") + tr("Exact time");
    if (closedLoop)
        text += QStringLiteral(" \u00b7 ") + tr("With the machine");
    if (singleFaults)
        text += QStringLiteral(" \u00b7 ") + tr("Single faults");
    m_assumptionsLabel->setText(text);
    QString toolTip = text + QLatin1Char('\n')
        + tr("Free: the nested behaviour may complete at any scan, or never. Automatic: Complete is TRUE at "
             "every scan, as the skeleton function block. Verify assumes automatic the nested steps whose "
             "Complete is Automatic in the Simulation dock while the simulation runs; all others are free.");
    if (exactTime)
        toolTip += QLatin1Char('\n') + tr("Exact time: every timer elapses exactly when the PLC's would, counted in "
                                           "scans (Simulation > Verify with Exact Time).");
    if (closedLoop)
        toolTip += QLatin1Char('\n') + tr("With the machine: the sensors the model's machine drives follow it, "
                                            "scan by scan, instead of taking any value (Simulation > Verify with "
                                            "the Machine).");
    if (singleFaults)
        toolTip += QLatin1Char('\n') + tr("Single faults: any one sensor stuck or flickering, or one cylinder or "
                                            "conveyor jammed, from any scan on (Simulation > Verify with Single "
                                            "Faults).");
    // The core's lines are English, like the command line's "abstracted:" lines.
    const std::vector<std::string>& abstractions = m_runner->result().abstractions;
    if (m_runner->hasResult() && !abstractions.empty()) {
        toolTip += QStringLiteral("\n\n") + tr("The exploration of both layers abstracted:");
        for (const std::string& line : abstractions)
            toolTip += QStringLiteral("\n\u2022 ") + QString::fromStdString(line);
    }
    m_assumptionsLabel->setToolTip(toolTip);
}

void VerificationPanel::updateActions()
{
    const core::VerificationFinding* finding = m_runner->finding(findingIndex(m_view->currentItem()));
    m_showAction->setEnabled(!firstElementRef(finding).isNull());
    // A stale counterexample may not fit the model any more; one that does
    // not replay shows nothing.
    m_replayAction->setEnabled(finding && finding->counterexample && finding->counterexample->confirmed
                               && !m_runner->isStale());
    m_replayAction->setToolTip(m_runner->isStale()
                                   ? tr("The model changed since verification: verify again to replay")
                                   : tr("Start the simulation and replay the scans that lead to the finding"));
}

void VerificationPanel::showOnChart(const QTreeWidgetItem* item)
{
    const ElementRef ref = firstElementRef(m_runner->finding(findingIndex(item)));
    if (!ref.isNull())
        m_selection->select(ref); // a nested element opens its GRAFCET's tab (MainWindow)
}

void VerificationPanel::replay(const QTreeWidgetItem* item)
{
    const int index = findingIndex(item);
    const core::VerificationFinding* finding = m_runner->finding(index);
    if (finding && finding->counterexample && finding->counterexample->confirmed && !m_runner->isStale())
        emit replayRequested(index);
}

// A selected group row copies its title and all its findings.
void VerificationPanel::copySelected()
{
    QStringList lines;
    for (QTreeWidgetItemIterator it(m_view); *it; ++it) {
        const QTreeWidgetItem* item = *it;
        if (item->isSelected() || (item->parent() && item->parent()->isSelected()))
            lines << copiedLine(item);
    }
    if (!lines.isEmpty())
        QGuiApplication::clipboard()->setText(lines.join(QLatin1Char('\n')) + QLatin1Char('\n'));
}

} // namespace editor
