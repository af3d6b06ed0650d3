#include "editor/docks/verificationpanel.h"

#include "editor/diagnostictext.h"
#include "editor/docks/elementlabels.h"
#include "editor/docks/wrappingitemdelegate.h"
#include "editor/docks/wrappinglabel.h"
#include "editor/secondarytext.h"
#include "editor/selection.h"
#include "editor/severityicon.h"
#include "editor/verificationrunner.h"

#include <QAction>
#include <QClipboard>
#include <QEvent>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QStyle>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <numeric>

namespace editor {

namespace {

constexpr int kIndexRole = Qt::UserRole;

QString elementText(const std::string& id)
{
    const QString text = QString::fromStdString(id);
    return text.contains(QLatin1String("->")) ? transitionLabel(text) : text;
}

QString elementsText(const core::VerificationFinding& finding)
{
    QStringList parts;
    for (const std::string& id : finding.elements)
        parts << elementText(id);
    return parts.join(QStringLiteral(", "));
}

ElementRef elementRef(const std::string& id)
{
    const QString text = QString::fromStdString(id);
    return text.contains(QLatin1String("->")) ? ElementRef::transition(text) : ElementRef::step(text);
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
{
    Q_ASSERT(runner && selection);
    setObjectName(QStringLiteral("verificationPanel"));
    m_verifyAction->setObjectName(QStringLiteral("panelVerifyAction"));
    m_showAction->setObjectName(QStringLiteral("showOnChartAction"));
    m_replayAction->setObjectName(QStringLiteral("replayCounterexampleAction"));
    connect(m_verifyAction, &QAction::triggered, m_runner, &VerificationRunner::start);
    connect(m_showAction, &QAction::triggered, this, [this] { showOnChart(m_view->currentItem()); });
    connect(m_replayAction, &QAction::triggered, this, [this] { replay(m_view->currentItem()); });

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
    m_view->setRootIsDecorated(false);
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
    layout->addWidget(m_view, 1);

    connect(m_runner, &VerificationRunner::started, this, &VerificationPanel::refreshStatus);
    connect(m_runner, &VerificationRunner::cancelled, this, &VerificationPanel::refreshStatus);
    connect(m_runner, &VerificationRunner::finished, this, &VerificationPanel::refresh);
    connect(m_runner, &VerificationRunner::staleChanged, this, &VerificationPanel::refresh);
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
void VerificationPanel::retranslate()
{
    m_verifyAction->setText(tr("&Verify"));
    m_verifyAction->setToolTip(tr("Explore every input sequence of the GEMMA layer and report what cannot happen"));
    m_showAction->setText(tr("&Show on Chart"));
    m_showAction->setToolTip(tr("Select the element of the finding on the chart"));
    m_replayAction->setText(tr("&Replay in Simulator"));
    m_copyAction->setText(tr("&Copy"));
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
    // The same finding stays current: entering the simulation to replay one
    // refreshes the list (the Complete assumptions change).
    const int current = findingIndex(m_view->currentItem());
    m_view->clear();
    const std::vector<core::VerificationFinding>& findings = m_runner->result().findings;
    // A stale finding is greyed: it describes the model, or assumptions, as they were.
    const bool stale = m_runner->isStale() || m_runner->assumptionsDiffer();
    const QBrush grey(secondaryTextColor(palette(), QPalette::Base));
    // Errors first: the core orders by code, and the violations matter most.
    std::vector<std::size_t> order(findings.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return findings[a].severity < findings[b].severity; });
    QList<QTreeWidgetItem*> items;
    for (std::size_t i : order) {
        const core::VerificationFinding& finding = findings[i];
        const QString message = verificationText(finding);
        const QString scans =
            finding.counterexample ? QString::number(finding.counterexample->scans) : QString();
        auto* item = new QTreeWidgetItem(
            {QString::fromStdString(finding.code), elementsText(finding), scans, message});
        item->setIcon(CodeColumn, severityIcon(finding.severity));
        item->setToolTip(CodeColumn, severityText(finding.severity));
        item->setToolTip(ElementColumn, item->text(ElementColumn));
        item->setToolTip(MessageColumn, message);
        item->setTextAlignment(ScansColumn, Qt::AlignRight | Qt::AlignVCenter);
        item->setData(0, kIndexRole, static_cast<int>(i));
        for (int column = 0; stale && column < m_view->columnCount(); ++column)
            item->setForeground(column, grey);
        items << item;
    }
    m_view->addTopLevelItems(items);
    auto same = std::find_if(items.cbegin(), items.cend(),
                             [current](const QTreeWidgetItem* item) { return findingIndex(item) == current; });
    if (same != items.cend())
        m_view->setCurrentItem(*same, 0, QItemSelectionModel::NoUpdate);
    else if (!items.isEmpty())
        m_view->setCurrentItem(items.front(), 0, QItemSelectionModel::NoUpdate);
    refreshStatus();
    updateActions();
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
    } else if (m_runner->assumptionsDiffer()) {
        text = tr("Complete settings changed since verification: verify again to update the findings.");
    } else {
        const core::VerificationResult& result = m_runner->result();
        const QString configurations = QString::number(static_cast<qulonglong>(result.configurations));
        if (result.violated())
            text = tr("Some properties do not hold (%1 configurations explored).").arg(configurations);
        else if (!result.findings.empty())
            text = tr("Every property holds; see the notes (%1 configurations explored).").arg(configurations);
        else
            text = tr("Every property holds (%1 configurations explored).").arg(configurations);
    }
    m_statusLabel->setText(text);
    refreshAssumptions();
}

// What the shown findings assume, else what Verify will assume.
void VerificationPanel::refreshAssumptions()
{
    const QStringList automatic =
        m_runner->hasResult() ? m_runner->resultAssumedAutomatic() : m_runner->assumedAutomatic();
    const QString text = automatic.isEmpty()
        ? tr("All Complete outputs free")
        : tr("Assumed Complete automatic: %1").arg(automatic.join(QStringLiteral(", ")));
    m_assumptionsLabel->setText(text);
    m_assumptionsLabel->setToolTip(
        text + QLatin1Char('\n')
        + tr("Free: the nested behaviour may complete at any scan, or never. Automatic: Complete is TRUE at "
             "every scan, as the skeleton function block. Verify assumes automatic the nested steps whose "
             "Complete is Automatic in the Simulation dock while the simulation runs; all others are free."));
}

void VerificationPanel::updateActions()
{
    const core::VerificationFinding* finding = m_runner->finding(findingIndex(m_view->currentItem()));
    m_showAction->setEnabled(finding && !finding->elements.empty());
    // A stale counterexample may not fit the model any more.
    m_replayAction->setEnabled(finding && finding->counterexample && !m_runner->isStale());
    m_replayAction->setToolTip(m_runner->isStale()
                                   ? tr("The model changed since verification: verify again to replay")
                                   : tr("Start the simulation and replay the scans that lead to the finding"));
}

void VerificationPanel::showOnChart(const QTreeWidgetItem* item)
{
    const core::VerificationFinding* finding = m_runner->finding(findingIndex(item));
    if (finding && !finding->elements.empty())
        m_selection->select(elementRef(finding->elements.front()));
}

void VerificationPanel::replay(const QTreeWidgetItem* item)
{
    const int index = findingIndex(item);
    const core::VerificationFinding* finding = m_runner->finding(index);
    if (finding && finding->counterexample && !m_runner->isStale())
        emit replayRequested(index);
}

void VerificationPanel::copySelected()
{
    QStringList lines;
    for (int i = 0; i < m_view->topLevelItemCount(); ++i) {
        const QTreeWidgetItem* item = m_view->topLevelItem(i);
        if (item->isSelected())
            lines << QStringLiteral("%1\t%2\t%3")
                         .arg(item->text(CodeColumn), item->text(ElementColumn), item->text(MessageColumn));
    }
    if (!lines.isEmpty())
        QGuiApplication::clipboard()->setText(lines.join(QLatin1Char('\n')) + QLatin1Char('\n'));
}

} // namespace editor
