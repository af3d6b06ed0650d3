#include "editor/simulation/simulationdock.h"

#include "editor/chart/chartstyle.h"
#include "editor/document.h"
#include "editor/simulation/faultmenu.h"
#include "editor/simulation/lampindicator.h"
#include "editor/simulation/simulationsession.h"
#include "editor/simulation/simulationtext.h"
#include "editor/simulation/tracetablemodel.h"
#include "editor/simulation/valuecolours.h"
#include "editor/style/secondarytext.h"
#include "editor/text/elementlabels.h"
#include "editor/text/gemmastatenames.h"

#include "core/model/model.h"
#include "core/simulation/simulator.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QEvent>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QSplitter>
#include <QStackedWidget>
#include <QStyle>
#include <QTabWidget>
#include <QTableView>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

namespace editor {

namespace {

enum Page { OffPage, OnPage };
enum Tab { ExplanationTab, TraceTab, ScenarioTab };

// Doubles hold integers exactly up to 2^53: the spin boxes of LINT and
// ULINT stop there, far beyond any count or setpoint a GEMMA condition reads.
constexpr double kExactIntegerLimit = 9007199254740992.0;
// REAL and LREAL spin boxes: wide enough for any physical quantity, narrow
// enough for the box to show its text.
constexpr double kRealLimit = 1e9;
constexpr int kRealDecimals = 3;

struct NumberRange {
    double min;
    double max;
};

NumberRange rangeOf(core::IecType type)
{
    switch (type) {
    case core::IecType::Sint: return {-128, 127};
    case core::IecType::Int: return {-32768, 32767};
    case core::IecType::Dint: return {-2147483648.0, 2147483647.0};
    case core::IecType::Lint: return {-kExactIntegerLimit, kExactIntegerLimit};
    case core::IecType::Usint: return {0, 255};
    case core::IecType::Uint: return {0, 65535};
    case core::IecType::Udint: return {0, 4294967295.0};
    case core::IecType::Ulint: return {0, kExactIntegerLimit};
    case core::IecType::Real:
    case core::IecType::Lreal:
    case core::IecType::Bool: break;
    }
    return {-kRealLimit, kRealLimit};
}

bool fitsInt(core::IecType type)
{
    switch (type) {
    case core::IecType::Sint:
    case core::IecType::Int:
    case core::IecType::Dint:
    case core::IecType::Usint:
    case core::IecType::Uint: return true;
    default: return false;
    }
}

double numberOf(const core::cond::Value& value)
{
    if (const auto* i = std::get_if<std::int64_t>(&value))
        return static_cast<double>(*i);
    if (const auto* d = std::get_if<double>(&value))
        return *d;
    return std::get<bool>(value) ? 1 : 0;
}

bool boolOf(const core::cond::Value& value)
{
    const auto* b = std::get_if<bool>(&value);
    return b && *b;
}

QString boolText(bool value)
{
    return value ? QStringLiteral("TRUE") : QStringLiteral("FALSE");
}

QString statusText(const core::TransitionExplanation& explanation)
{
    switch (explanation.status) {
    case core::TransitionStatus::Fires: return SimulationDock::tr("fires in the next scan");
    case core::TransitionStatus::ConditionFalse: return SimulationDock::tr("condition FALSE");
    case core::TransitionStatus::WaitingForComplete: return SimulationDock::tr("waits for Complete");
    case core::TransitionStatus::PreemptedByHigherPriority:
        return SimulationDock::tr("preempted by %1").arg(transitionLabel(QString::fromStdString(explanation.preemptedBy)));
    case core::TransitionStatus::Unusable: return SimulationDock::tr("condition unusable (always FALSE)");
    }
    return {};
}

// Where a run-time fault happened, worded from its parts so that it translates.
QString faultPlaceText(const core::SimulationFault& fault)
{
    const QString step = QString::fromStdString(fault.stepId);
    if (!fault.transitionId.empty())
        return SimulationDock::tr("the condition of %1").arg(transitionLabel(QString::fromStdString(fault.transitionId)));
    if (fault.actionIndex < 0)
        return SimulationDock::tr("the receptivity of T%1 of %2").arg(fault.nestedTransition).arg(step);
    return SimulationDock::tr("action %1 of step %2 of %3").arg(fault.actionIndex + 1).arg(fault.nestedStep).arg(step);
}

// The fault that stopped the run, as the dock shows it under the active step.
QString faultText(const core::SimulationFault& fault)
{
    return SimulationDock::tr("Stopped at scan %1: integer division by zero in %2 (%3 in '%4'). On the PLC the task "
                              "stops with a fault; Reset to run again.")
        .arg(QString::number(static_cast<qlonglong>(fault.scan)), faultPlaceText(fault),
             QString::fromStdString(fault.division), QString::fromStdString(fault.text));
}

QString nestedStatusText(core::NestedTransitionStatus status)
{
    switch (status) {
    case core::NestedTransitionStatus::Fires: return SimulationDock::tr("fires in the next scan");
    case core::NestedTransitionStatus::UpstreamInactive: return SimulationDock::tr("upstream step not active");
    case core::NestedTransitionStatus::ReceptivityFalse: return SimulationDock::tr("receptivity FALSE");
    case core::NestedTransitionStatus::Unusable: return SimulationDock::tr("receptivity unusable (always FALSE)");
    case core::NestedTransitionStatus::NotCalled: return SimulationDock::tr("not called");
    }
    return {};
}

QColor nestedStatusColor(core::NestedTransitionStatus status)
{
    switch (status) {
    case core::NestedTransitionStatus::Fires: return QColor(0x1e, 0x8e, 0x3e);
    case core::NestedTransitionStatus::Unusable: return QColor(0xc6, 0x28, 0x28);
    default: break;
    }
    return {};
}

QColor statusColor(core::TransitionStatus status)
{
    switch (status) {
    case core::TransitionStatus::Fires: return QColor(0x1e, 0x8e, 0x3e);
    case core::TransitionStatus::WaitingForComplete: return QColor(0xb0, 0x6a, 0x00);
    case core::TransitionStatus::Unusable: return QColor(0xc6, 0x28, 0x28);
    case core::TransitionStatus::ConditionFalse:
    case core::TransitionStatus::PreemptedByHigherPriority: break;
    }
    return {};
}

QToolButton* toolButton(QWidget* parent, const QString& objectName, QStyle::StandardPixmap icon)
{
    auto* button = new QToolButton(parent);
    button->setObjectName(objectName);
    button->setIcon(parent->style()->standardIcon(icon));
    button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    button->setAutoRaise(true);
    return button;
}

QLabel* sectionLabel(const QString& text, QWidget* parent)
{
    auto* label = new QLabel(text, parent);
    QFont font = label->font();
    font.setBold(true);
    label->setFont(font);
    return label;
}

// A GRAFCET of thousands of transitions (issue 32) would fill the
// explanation with rows saying "upstream step not active", rebuilt at every
// frame of a run: beyond this many transitions only those whose upstream
// steps are all active are listed, and the others counted in one row.
constexpr std::size_t kMaxListedNestedTransitions = 100;

bool isListed(const core::NestedExplanation& nested, const core::NestedTransitionExplanation& transition)
{
    return nested.transitions.size() <= kMaxListedNestedTransitions
        || transition.status != core::NestedTransitionStatus::UpstreamInactive;
}

} // namespace

QString SimulationDock::title()
{
    return tr("Simulation");
}

QKeySequence SimulationDock::singleScanShortcut()
{
    return QKeySequence(Qt::Key_F10);
}

// Next to F10 (Single Scan): Shift goes back, Ctrl forward again.
QKeySequence SimulationDock::stepBackShortcut()
{
    return QKeySequence(Qt::SHIFT | Qt::Key_F10);
}

QKeySequence SimulationDock::stepForwardShortcut()
{
    return QKeySequence(Qt::CTRL | Qt::Key_F10);
}

SimulationDock::SimulationDock(SimulationSession* session, Document* document, QWidget* parent)
    : QDockWidget(title(), parent)
    , m_session(session)
    , m_document(document)
{
    setObjectName(QStringLiteral("simulationDock"));
    m_pages = new QStackedWidget(this);
    m_pages->addWidget(createOffPage());
    m_pages->addWidget(createOnPage());
    setWidget(m_pages);

    connect(m_session, &SimulationSession::activeChanged, this, &SimulationDock::onActiveChanged);
    connect(m_session, &SimulationSession::runningChanged, this, &SimulationDock::onRunningChanged);
    connect(m_session, &SimulationSession::stepped, this, &SimulationDock::onStepped);
    connect(m_session, &SimulationSession::inputsChanged, this, [this] {
        syncInputs();
        syncCompletes();
        refreshExplanation();
    });
    connect(m_session, &SimulationSession::wasReset, m_traceModel, &TraceTableModel::reload);
    connect(m_session, &SimulationSession::replayChanged, this, &SimulationDock::refreshReplay);
    connect(m_session, &SimulationSession::historyMoved, this, &SimulationDock::onHistoryMoved);
    connect(m_session, &SimulationSession::speedChanged, this, [this](int speed) {
        const QSignalBlocker blocker(m_speedSpin);
        m_speedSpin->setValue(speed);
    });
    setFixedTexts();
    onActiveChanged(m_session->isActive());
}

void SimulationDock::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDockWidget::changeEvent(event);
}

// The texts of the running session too: the input rows are built again with
// the session's values, the explanation, status and replay worded again.
void SimulationDock::retranslate()
{
    setFixedTexts();
    m_traceModel->retranslate();
    onRunningChanged(m_session->isRunning());
    if (m_session->isActive()) {
        buildInputRows();
        refreshStatus();
        refreshUnstable();
        m_shownExplanation.clear();
        refreshExplanation();
    }
    refreshReplay();
}

// The texts that do not depend on the session.
void SimulationDock::setFixedTexts()
{
    setWindowTitle(title());
    m_introLabel->setText(tr("The simulation runs the model scan by scan, as the generated program runs on "
                             "the PLC: play the inputs, watch the active step and see why each transition "
                             "fires or not. Editing is locked while it runs."));
    m_startButton->setText(tr("Start Simulation"));
    m_tabs->setTabText(ExplanationTab, tr("Explanation"));
    m_tabs->setTabText(TraceTab, tr("Trace"));
    m_tabs->setTabText(ScenarioTab, tr("Scenario"));
    m_runButton->setToolTip(tr("Run scans at the chosen speed; press again to pause"));
    m_stepButton->setText(tr("Scan"));
    m_stepButton->setToolTip(tr("Run a single scan"));
    m_backButton->setText(tr("Back"));
    m_backButton->setToolTip(tr("Show the previous scan of the history (%1); a scan or Run from a past scan "
                                "continues from it and drops the later scans")
                                 .arg(stepBackShortcut().toString(QKeySequence::NativeText)));
    m_backButton->setAccessibleName(m_backButton->text());
    m_forwardButton->setText(tr("Forward"));
    m_forwardButton->setToolTip(tr("Show the next scan of the history (%1)")
                                    .arg(stepForwardShortcut().toString(QKeySequence::NativeText)));
    m_forwardButton->setAccessibleName(m_forwardButton->text());
    m_resetButton->setText(tr("Reset"));
    m_resetButton->setAccessibleName(m_resetButton->text());
    m_resetButton->setToolTip(tr("Back to the initial step, the inputs to their defaults; clears the trace"));
    m_endButton->setText(tr("End"));
    m_endButton->setAccessibleName(m_endButton->text());
    m_endButton->setToolTip(tr("End the simulation and unlock editing"));
    m_speedLabel->setText(tr("&Speed:"));
    m_speedSpin->setSuffix(tr(" scans/s"));
    m_speedSpin->setToolTip(tr("Scans per second (the model's cycle time only sets the simulated time)"));
    m_explanationView->setHeaderLabels({tr("Transition"), tr("Next scan")});
    m_recordButton->setText(tr("&Record as Scenario…"));
    m_recordButton->setToolTip(tr("Save this session since the last reset as a scenario file: the inputs of "
                                  "each scan, and expectations for every transition that fired, every output "
                                  "that changed and every nested situation that changed"));
    m_replayButton->setText(tr("Re&play Scenario…"));
    m_replayButton->setToolTip(tr("Run a scenario file from the initial step and check its expectations"));
}

QWidget* SimulationDock::createOffPage()
{
    auto* page = new QWidget(this);
    auto* layout = new QVBoxLayout(page);
    m_introLabel = new QLabel(page);
    m_introLabel->setWordWrap(true);
    m_startButton = new QPushButton(page);
    m_startButton->setObjectName(QStringLiteral("startButton"));
    connect(m_startButton, &QPushButton::clicked, this, [this] { m_session->setActive(true); });
    layout->addWidget(m_introLabel);
    layout->addWidget(m_startButton, 0, Qt::AlignLeft);
    layout->addStretch();
    return page;
}

void SimulationDock::setLinkStatus(const QString& text)
{
    m_linkLabel->setText(text);
    m_linkLabel->setVisible(!text.isEmpty());
}

QWidget* SimulationDock::createOnPage()
{
    auto* page = new QWidget(this);
    auto* layout = new QVBoxLayout(page);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(createControls());
    m_linkLabel = new QLabel(page);
    m_linkLabel->setObjectName(QStringLiteral("modbusLinkLabel"));
    m_linkLabel->setWordWrap(true);
    m_linkLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_linkLabel->setContentsMargins(6, 4, 6, 4);
    m_linkLabel->hide();
    layout->addWidget(m_linkLabel);

    auto* splitter = new QSplitter(Qt::Vertical, page);
    splitter->setChildrenCollapsible(false);
    auto* scroll = new QScrollArea(splitter);
    scroll->setObjectName(QStringLiteral("inputsArea"));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    m_inputsWidget = new QWidget(scroll);
    m_inputsWidget->setObjectName(QStringLiteral("inputsPanel"));
    m_inputsLayout = new QGridLayout(m_inputsWidget);
    m_inputsLayout->setContentsMargins(6, 4, 6, 4);
    m_inputsLayout->setVerticalSpacing(2);
    scroll->setWidget(m_inputsWidget);

    m_tabs = new QTabWidget(splitter);
    m_tabs->setObjectName(QStringLiteral("simulationTabs"));
    m_tabs->setDocumentMode(true);
    m_tabs->insertTab(ExplanationTab, createExplanationTab(), QString());
    m_tabs->insertTab(TraceTab, createTraceTab(), QString());
    m_tabs->insertTab(ScenarioTab, createScenarioTab(), QString());
    splitter->addWidget(scroll);
    splitter->addWidget(m_tabs);
    // The sizes are proportions: the inputs get the larger part.
    scroll->setMinimumHeight(fontMetrics().height() * 3);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);
    splitter->setSizes({3000, 2000});
    layout->addWidget(splitter, 1);
    return page;
}

QWidget* SimulationDock::createControls()
{
    auto* controls = new QWidget(this);
    auto* layout = new QVBoxLayout(controls);
    layout->setContentsMargins(4, 2, 4, 2);
    layout->setSpacing(0);

    auto* buttons = new QHBoxLayout;
    buttons->setSpacing(2);
    m_runButton = toolButton(controls, QStringLiteral("runButton"), QStyle::SP_MediaPlay);
    m_runButton->setCheckable(true);
    connect(m_runButton, &QToolButton::toggled, this, [this](bool run) {
        if (run)
            m_session->run();
        else
            m_session->pause();
    });
    m_stepButton = toolButton(controls, QStringLiteral("stepButton"), QStyle::SP_MediaSkipForward);
    connect(m_stepButton, &QToolButton::clicked, m_session, &SimulationSession::stepOnce);
    m_backButton = toolButton(controls, QStringLiteral("stepBackButton"), QStyle::SP_ArrowBack);
    connect(m_backButton, &QToolButton::clicked, m_session, &SimulationSession::stepBack);
    m_forwardButton = toolButton(controls, QStringLiteral("stepForwardButton"), QStyle::SP_ArrowForward);
    connect(m_forwardButton, &QToolButton::clicked, m_session, &SimulationSession::stepForward);
    m_resetButton = toolButton(controls, QStringLiteral("resetButton"), QStyle::SP_MediaSkipBackward);
    connect(m_resetButton, &QToolButton::clicked, m_session, &SimulationSession::reset);
    m_endButton = toolButton(controls, QStringLiteral("endButton"), QStyle::SP_MediaStop);
    connect(m_endButton, &QToolButton::clicked, this, [this] { m_session->setActive(false); });
    // Icons alone (their text is the tooltip's and the screen reader's): with
    // words the row would widen the dock column beyond its 1366 x 768 width
    // in French or German ("Réinitialiser", "Zurücksetzen"), even before a
    // simulation, since the dock is as wide as its widest page.
    for (QToolButton* button : {m_backButton, m_forwardButton, m_resetButton, m_endButton})
        button->setToolButtonStyle(Qt::ToolButtonIconOnly);
    buttons->addWidget(m_runButton);
    buttons->addWidget(m_stepButton);
    buttons->addWidget(m_backButton);
    buttons->addWidget(m_forwardButton);
    buttons->addWidget(m_resetButton);
    buttons->addStretch();
    buttons->addWidget(m_endButton);
    layout->addLayout(buttons);

    auto* speedRow = new QHBoxLayout;
    speedRow->setContentsMargins(4, 0, 4, 0);
    m_speedLabel = new QLabel(controls);
    m_speedSpin = new QSpinBox(controls);
    m_speedSpin->setObjectName(QStringLiteral("speedSpin"));
    m_speedSpin->setRange(SimulationSession::kMinSpeed, SimulationSession::kMaxSpeed);
    m_speedSpin->setValue(m_session->speed());
    m_speedSpin->setKeyboardTracking(false);
    m_speedLabel->setBuddy(m_speedSpin);
    connect(m_speedSpin, &QSpinBox::valueChanged, m_session, &SimulationSession::setSpeed);
    m_statusLabel = new QLabel(controls);
    m_statusLabel->setObjectName(QStringLiteral("statusLabel"));
    m_statusLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // On a line of its own: "Scan 10 of 12 (history) · 0.10 s" beside the
    // speed box would not fit the dock column at 1366 x 768.
    m_statusLabel->setContentsMargins(4, 0, 4, 0);
    speedRow->addWidget(m_speedLabel);
    speedRow->addWidget(m_speedSpin);
    speedRow->addStretch();
    layout->addLayout(speedRow);
    layout->addWidget(m_statusLabel);
    m_unstableLabel = new QLabel(controls);
    m_unstableLabel->setObjectName(QStringLiteral("unstableLabel"));
    m_unstableLabel->setWordWrap(true);
    m_unstableLabel->setContentsMargins(4, 2, 4, 2);
    m_unstableLabel->setStyleSheet(QStringLiteral("QLabel { color: #b3261e; font-weight: bold; }"));
    m_unstableLabel->hide();
    layout->addWidget(m_unstableLabel);
    return controls;
}

QWidget* SimulationDock::createExplanationTab()
{
    auto* tab = new QWidget(this);
    auto* layout = new QVBoxLayout(tab);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(4);
    m_activeLabel = new QLabel(tab);
    m_activeLabel->setObjectName(QStringLiteral("activeStepLabel"));
    m_activeLabel->setWordWrap(true);
    m_activeLabel->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Minimum);
    m_explanationView = new QTreeWidget(tab);
    m_explanationView->setObjectName(QStringLiteral("explanationView"));
    m_explanationView->setColumnCount(2);
    m_explanationView->setUniformRowHeights(true);
    m_explanationView->setSelectionMode(QAbstractItemView::NoSelection);
    m_explanationView->header()->setStretchLastSection(true);
    // The active step's label wraps (a run-time fault takes four lines): in a
    // short dock the list gives way down to its header and two rows.
    m_explanationView->setMinimumHeight(3 * m_explanationView->fontMetrics().height() + 12);
    m_explanationView->header()->resizeSection(TransitionColumn, 130);
    layout->addWidget(m_activeLabel);
    layout->addWidget(m_explanationView, 1);
    return tab;
}

QWidget* SimulationDock::createTraceTab()
{
    m_traceModel = new TraceTableModel(m_session, this);
    m_traceView = new QTableView(this);
    m_traceView->setObjectName(QStringLiteral("traceView"));
    m_traceView->setModel(m_traceModel);
    m_traceView->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_traceView->setWordWrap(false);
    m_traceView->verticalHeader()->hide();
    m_traceView->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_traceView->verticalHeader()->setDefaultSectionSize(m_traceView->fontMetrics().height() + 4);
    m_traceView->horizontalHeader()->setStretchLastSection(true);
    m_traceView->horizontalHeader()->setHighlightSections(false);
    const int digit = m_traceView->fontMetrics().horizontalAdvance(QLatin1Char('0'));
    m_traceView->setColumnWidth(TraceTableModel::ScanColumn, digit * 8);
    m_traceView->setColumnWidth(TraceTableModel::StepColumn, digit * 5);
    m_traceView->setColumnWidth(TraceTableModel::FiredColumn, digit * 10);
    m_traceView->setColumnWidth(TraceTableModel::EntryColumn, digit * 7);
    m_traceView->setColumnWidth(TraceTableModel::TokensColumn, digit * 14);
    // A row clicked is a scan to look at again.
    connect(m_traceView, &QTableView::clicked, this, &SimulationDock::showTraceRow);
    connect(m_traceView, &QTableView::activated, this, &SimulationDock::showTraceRow);
    return m_traceView;
}

QWidget* SimulationDock::createScenarioTab()
{
    m_scenarioTab = new QWidget(this);
    auto* layout = new QVBoxLayout(m_scenarioTab);
    layout->setContentsMargins(4, 4, 4, 4);
    auto* buttons = new QHBoxLayout;
    m_recordButton = new QPushButton(m_scenarioTab);
    m_recordButton->setObjectName(QStringLiteral("recordButton"));
    connect(m_recordButton, &QPushButton::clicked, this, &SimulationDock::recordScenario);
    m_replayButton = new QPushButton(m_scenarioTab);
    m_replayButton->setObjectName(QStringLiteral("replayButton"));
    connect(m_replayButton, &QPushButton::clicked, this, &SimulationDock::replayScenario);
    buttons->addWidget(m_recordButton);
    buttons->addWidget(m_replayButton);
    buttons->addStretch();
    m_replayLabel = new QLabel(m_scenarioTab);
    m_replayLabel->setObjectName(QStringLiteral("replayLabel"));
    m_replayLabel->setWordWrap(true);
    m_failureList = new QListWidget(m_scenarioTab);
    m_failureList->setObjectName(QStringLiteral("failureList"));
    m_failureList->setWordWrap(true);
    layout->addLayout(buttons);
    layout->addWidget(m_replayLabel);
    // Shown only when an expectation failed: an empty list would be a large empty box.
    layout->addWidget(m_failureList, 1);
    m_failureList->hide();
    layout->addStretch();
    return m_scenarioTab;
}

void SimulationDock::buildInputRows()
{
    m_inputRows.clear();
    m_completeRows.clear();
    while (QLayoutItem* item = m_inputsLayout->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    const core::Simulator* simulator = m_session->simulator();
    if (!simulator)
        return;
    int row = 0;
    m_inputsLayout->addWidget(sectionLabel(tr("Inputs"), m_inputsWidget), row++, 0, 1, 2);
    const int count = static_cast<int>(simulator->variableNames().size());
    const auto isInput = [simulator](int i) {
        return simulator->variableKind(static_cast<std::size_t>(i)) == core::VariableKind::Input;
    };
    const auto isUsers = [this, &isInput](int i) { return isInput(i) && !m_session->isMachineDriven(i); };
    for (int i = 0; i < count; ++i) {
        if (!isUsers(i))
            continue;
        if (simulator->variableType(static_cast<std::size_t>(i)) == core::IecType::Bool)
            addBoolRow(i, row++);
        else
            addNumberRow(i, row++);
    }
    // In closed loop the machine writes its sensors: shown like outputs, never set.
    bool sensorsTitled = false;
    for (int i = 0; i < count; ++i) {
        if (!isInput(i) || isUsers(i))
            continue;
        if (!sensorsTitled) {
            m_inputsLayout->addWidget(sectionLabel(tr("Sensors (set by the machine)"), m_inputsWidget), row++, 0, 1, 2);
            sensorsTitled = true;
        }
        addValueRow(i, row++);
    }
    // What the program writes is shown, not set (a scenario may not set it either).
    bool outputsTitled = false;
    for (int i = 0; i < count; ++i) {
        if (isInput(i))
            continue;
        if (!outputsTitled) {
            m_inputsLayout->addWidget(sectionLabel(tr("Outputs and internal variables"), m_inputsWidget), row++, 0, 1,
                                      2);
            outputsTitled = true;
        }
        addValueRow(i, row++);
    }
    if (simulator->variableNames().empty()) {
        auto* none = new QLabel(tr("The model declares no variables."), m_inputsWidget);
        useSecondaryText(none);
        m_inputsLayout->addWidget(none, row++, 0, 1, 2);
    }
    if (!simulator->nestedSteps().empty()) {
        auto* title = sectionLabel(tr("Complete of nested steps"), m_inputsWidget);
        title->setToolTip(tr("Automatic: the skeleton function block completes at once. Manual: you play the "
                             "nested behaviour and set Complete yourself."));
        m_inputsLayout->addWidget(title, row++, 0, 1, 2);
        for (const std::string& step : simulator->nestedSteps())
            addCompleteRow(QString::fromStdString(step), row++);
    }
    m_inputsLayout->setColumnStretch(1, 1);
    m_inputsLayout->setRowStretch(row, 1);
    syncInputs();
    syncCompletes();
}

void SimulationDock::addBoolRow(int index, int row)
{
    const core::Simulator* simulator = m_session->simulator();
    InputRow input;
    input.variable = index;
    input.name = QString::fromStdString(simulator->variableNames()[static_cast<std::size_t>(index)]);
    auto* label = new QLabel(input.name, m_inputsWidget);
    if (const core::Variable* variable = m_document->model().variable(input.name.toStdString()))
        label->setToolTip(QString::fromStdString(variable->comment));

    auto* cell = new QWidget(m_inputsWidget);
    auto* layout = new QHBoxLayout(cell);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(4);
    // Tool buttons: compact enough for a row to fit the dock's narrow column.
    const int buttonWidth = fontMetrics().horizontalAdvance(QStringLiteral("FALSE")) + 18;
    auto* toggle = new QToolButton(cell);
    toggle->setObjectName(QStringLiteral("toggle_") + input.name);
    toggle->setCheckable(true);
    toggle->setMinimumWidth(buttonWidth);
    toggle->setToolTip(tr("Switch %1 between TRUE and FALSE").arg(input.name));
    connect(toggle, &QToolButton::toggled, this, [this, index](bool checked) {
        m_session->setVariable(index, checked);
    });
    auto* press = new QToolButton(cell);
    press->setText(tr("Press"));
    press->setObjectName(QStringLiteral("press_") + input.name);
    press->setMinimumWidth(buttonWidth);
    press->setToolTip(tr("TRUE while held down, like a push button (for at least one scan)"));
    connect(press, &QToolButton::pressed, this, [this, index] { m_session->press(index); });
    connect(press, &QToolButton::released, this, [this, index] { m_session->release(index); });
    layout->addWidget(toggle);
    layout->addWidget(press);
    layout->addStretch();
    label->setBuddy(toggle);
    m_inputsLayout->addWidget(label, row, 0);
    m_inputsLayout->addWidget(cell, row, 1);
    input.toggle = toggle;
    input.press = press;
    m_inputRows << input;
}

void SimulationDock::addValueRow(int index, int row)
{
    const core::Simulator* simulator = m_session->simulator();
    InputRow output;
    output.variable = index;
    output.name = QString::fromStdString(simulator->variableNames()[static_cast<std::size_t>(index)]);
    auto* label = new QLabel(output.name, m_inputsWidget);
    if (const core::Variable* variable = m_document->model().variable(output.name.toStdString()))
        label->setToolTip(QString::fromStdString(variable->comment));
    const QString owner = m_session->machineOwner(index);
    const QString toolTip = owner.isEmpty()
                                ? tr("Written by the program: %1 is not an input").arg(output.name)
                                : tr("Written by the machine: %1 is a sensor of %2").arg(output.name, owner);
    output.shown = new QLabel(m_inputsWidget);
    output.shown->setObjectName(QStringLiteral("shown_") + output.name);
    output.shown->setToolTip(toolTip);
    auto* cell = new QWidget(m_inputsWidget);
    auto* layout = new QHBoxLayout(cell);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(6);
    // A BOOL as a signal lamp with its value beside it: plain text, not a
    // button's look, since it cannot be switched.
    if (simulator->variableType(static_cast<std::size_t>(index)) == core::IecType::Bool) {
        output.lamp = new LampIndicator(cell);
        output.lamp->setObjectName(QStringLiteral("lamp_") + output.name);
        output.lamp->setToolTip(toolTip);
        // In the column of the toggles' text: the lamp where a button's edge is.
        layout->addSpacing(4);
        layout->addWidget(output.lamp);
    }
    layout->addWidget(output.shown);
    output.label = label;
    // A machine's sensor takes faults from its context menu (docs/simulation.md, "Faults").
    if (!owner.isEmpty()) {
        output.fault = new QLabel(cell);
        output.fault->setObjectName(QStringLiteral("fault_") + output.name);
        output.fault->setStyleSheet(QStringLiteral("QLabel { color: %1; }").arg(chartstyle::problemColor().name()));
        output.fault->hide();
        layout->addWidget(output.fault);
        const QString tip = toolTip + QLatin1Char('\n') + tr("Right-click to inject a fault");
        for (QWidget* widget : {static_cast<QWidget*>(label), cell}) {
            widget->setToolTip(tip);
            widget->setContextMenuPolicy(Qt::CustomContextMenu);
            connect(widget, &QWidget::customContextMenuRequested, this,
                    [this, name = output.name, widget](const QPoint& at) { showSensorFaultMenu(name, widget, at); });
        }
    }
    layout->addStretch();
    m_inputsLayout->addWidget(label, row, 0);
    m_inputsLayout->addWidget(cell, row, 1);
    m_inputRows << output;
}

void SimulationDock::showSensorFaultMenu(const QString& sensor, QWidget* over, const QPoint& at)
{
    QMenu menu(this);
    addSensorFaultActions(menu, *m_session, sensor, this);
    menu.exec(over->mapToGlobal(at));
}

// A faulted sensor's name is struck through, its fault written beside its value.
void SimulationDock::syncSensorFault(const InputRow& row)
{
    const QString fault = sensorFaultText(m_session->sensorFault(row.variable));
    if (row.fault->text() == fault)
        return;
    row.fault->setText(fault);
    row.fault->setVisible(!fault.isEmpty());
    QFont font = row.label->font();
    font.setStrikeOut(!fault.isEmpty());
    row.label->setFont(font);
}

void SimulationDock::addNumberRow(int index, int row)
{
    const core::Simulator* simulator = m_session->simulator();
    const core::IecType type = simulator->variableType(static_cast<std::size_t>(index));
    InputRow input;
    input.variable = index;
    input.name = QString::fromStdString(simulator->variableNames()[static_cast<std::size_t>(index)]);
    auto* label = new QLabel(input.name, m_inputsWidget);
    QString toolTip = QString::fromUtf8(core::iecTypeName(type).data(), static_cast<qsizetype>(core::iecTypeName(type).size()));
    if (const core::Variable* variable = m_document->model().variable(input.name.toStdString())) {
        if (!variable->comment.empty())
            toolTip += QStringLiteral(": ") + QString::fromStdString(variable->comment);
    }
    label->setToolTip(toolTip);

    const NumberRange range = rangeOf(type);
    QWidget* editor = nullptr;
    if (fitsInt(type)) {
        auto* spin = new QSpinBox(m_inputsWidget);
        spin->setRange(static_cast<int>(range.min), static_cast<int>(range.max));
        connect(spin, &QSpinBox::valueChanged, this, [this, index](int value) { setNumber(index, value); });
        editor = spin;
    } else {
        auto* spin = new QDoubleSpinBox(m_inputsWidget);
        spin->setDecimals(core::isRealType(type) ? kRealDecimals : 0);
        spin->setRange(range.min, range.max);
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, index](double value) { setNumber(index, value); });
        editor = spin;
    }
    editor->setObjectName(QStringLiteral("value_") + input.name);
    editor->setToolTip(toolTip);
    static_cast<QAbstractSpinBox*>(editor)->setKeyboardTracking(false);
    // As wide as the toggle and Press buttons of the BOOL rows: a REAL's
    // range would otherwise make it wider than the dock.
    const int buttonWidth = fontMetrics().horizontalAdvance(QStringLiteral("FALSE")) + 18;
    editor->setFixedWidth(2 * buttonWidth + 4);
    label->setBuddy(editor);
    m_inputsLayout->addWidget(label, row, 0);
    m_inputsLayout->addWidget(editor, row, 1);
    input.editor = editor;
    m_inputRows << input;
}

void SimulationDock::setNumber(int index, double value)
{
    const core::Simulator* simulator = m_session->simulator();
    if (!simulator)
        return;
    const core::IecType type = simulator->variableType(static_cast<std::size_t>(index));
    const core::cond::Value typed = core::isRealType(type) ? core::cond::Value(value)
                                                           : core::cond::Value(static_cast<std::int64_t>(std::llround(value)));
    m_session->setVariable(index, typed);
}

void SimulationDock::addCompleteRow(const QString& stepId, int row)
{
    CompleteRow complete;
    complete.stepId = stepId;
    // The step id with its Complete output as the chart draws it: a "C"
    // badge, green when TRUE.
    auto* name = new QWidget(m_inputsWidget);
    auto* nameLayout = new QHBoxLayout(name);
    nameLayout->setContentsMargins(0, 0, 0, 0);
    nameLayout->setSpacing(6);
    auto* label = new QLabel(stepId, name);
    label->setToolTip(officialStateName(stepId));
    complete.output = new QLabel(QStringLiteral("C"), name);
    complete.output->setObjectName(QStringLiteral("completeOutput_") + stepId);
    complete.output->setAlignment(Qt::AlignCenter);
    complete.output->setFixedSize(fontMetrics().height(), fontMetrics().height());
    nameLayout->addWidget(label);
    nameLayout->addWidget(complete.output);
    nameLayout->addStretch();
    auto* cell = new QWidget(m_inputsWidget);
    auto* layout = new QHBoxLayout(cell);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(4);
    complete.mode = new QComboBox(cell);
    complete.mode->setObjectName(QStringLiteral("completeMode_") + stepId);
    complete.mode->addItem(tr("Automatic"), static_cast<int>(core::CompleteMode::Automatic));
    complete.mode->addItem(tr("Manual"), static_cast<int>(core::CompleteMode::Manual));
    complete.mode->setToolTip(tr("How %1's function block sets Complete").arg(stepId));
    connect(complete.mode, &QComboBox::currentIndexChanged, this, [this, stepId](int index) {
        m_session->setCompleteMode(stepId, index == 1 ? core::CompleteMode::Manual : core::CompleteMode::Automatic);
    });
    complete.manual = new QCheckBox(tr("Complete"), cell);
    complete.manual->setObjectName(QStringLiteral("completeValue_") + stepId);
    complete.manual->setToolTip(tr("The value the nested behaviour gives Complete (manual mode)"));
    connect(complete.manual, &QCheckBox::toggled, this,
            [this, stepId](bool checked) { m_session->setManualComplete(stepId, checked); });
    layout->addWidget(complete.mode);
    layout->addWidget(complete.manual);
    layout->addStretch();
    label->setBuddy(complete.mode);
    m_inputsLayout->addWidget(name, row, 0);
    m_inputsLayout->addWidget(cell, row, 1);
    m_completeRows << complete;
}

QAbstractButton* SimulationDock::toggleButton(const QString& variable) const
{
    for (const InputRow& row : m_inputRows) {
        if (row.name.compare(variable, Qt::CaseInsensitive) == 0)
            return row.toggle;
    }
    return nullptr;
}

QAbstractButton* SimulationDock::pressButton(const QString& variable) const
{
    for (const InputRow& row : m_inputRows) {
        if (row.name.compare(variable, Qt::CaseInsensitive) == 0)
            return row.press;
    }
    return nullptr;
}

QWidget* SimulationDock::valueEditor(const QString& variable) const
{
    for (const InputRow& row : m_inputRows) {
        if (row.name.compare(variable, Qt::CaseInsensitive) == 0)
            return row.editor;
    }
    return nullptr;
}

QComboBox* SimulationDock::completeModeCombo(const QString& stepId) const
{
    for (const CompleteRow& row : m_completeRows) {
        if (row.stepId == stepId)
            return row.mode;
    }
    return nullptr;
}

QCheckBox* SimulationDock::manualCompleteCheck(const QString& stepId) const
{
    for (const CompleteRow& row : m_completeRows) {
        if (row.stepId == stepId)
            return row.manual;
    }
    return nullptr;
}

void SimulationDock::onActiveChanged(bool active)
{
    m_pages->setCurrentIndex(active ? OnPage : OffPage);
    m_shownExplanation.clear();
    buildInputRows();
    m_traceModel->reload();
    onRunningChanged(m_session->isRunning());
    onStepped();
    refreshUnstable(); // hidden when the simulation ends
    refreshReplay();
}

void SimulationDock::onHistoryMoved()
{
    m_traceModel->sync();
    refreshStatus();
    refreshHistoryButtons();
    selectViewedScan();
}

void SimulationDock::refreshHistoryButtons()
{
    m_backButton->setEnabled(m_session->canStepBack());
    m_forwardButton->setEnabled(m_session->canStepForward());
}

void SimulationDock::selectViewedScan()
{
    if (!m_session->isViewingHistory()) {
        if (m_traceView->selectionModel()->hasSelection() && m_traceView->property("historySelection").toBool())
            m_traceView->clearSelection();
        m_traceView->setProperty("historySelection", false);
        return;
    }
    const std::deque<core::ScanRecord>& trace = m_session->trace();
    if (trace.empty())
        return;
    const std::int64_t row = m_session->viewedScan() - trace.front().scan;
    if (row < 0 || row >= m_traceModel->rowCount()) {
        m_traceView->clearSelection(); // scan 0 has no row
    } else {
        const QModelIndex index = m_traceModel->index(static_cast<int>(row), TraceTableModel::ScanColumn);
        m_traceView->selectionModel()->setCurrentIndex(
            index, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
        m_traceView->scrollTo(index);
    }
    m_traceView->setProperty("historySelection", true);
}

void SimulationDock::showTraceRow(const QModelIndex& index)
{
    const std::deque<core::ScanRecord>& trace = m_session->trace();
    if (!index.isValid() || static_cast<std::size_t>(index.row()) >= trace.size())
        return;
    m_session->showScan(trace[static_cast<std::size_t>(index.row())].scan);
}

void SimulationDock::onRunningChanged(bool running)
{
    const QSignalBlocker blocker(m_runButton);
    m_runButton->setChecked(running);
    m_runButton->setText(running ? tr("Pause") : tr("Run"));
    m_runButton->setIcon(style()->standardIcon(running ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    if (m_session->isReplaying())
        refreshReplayLabel(); // paused or playing
}

void SimulationDock::onStepped()
{
    if (!m_session->isActive())
        return;
    refreshStatus();
    refreshHistoryButtons();
    if (m_session->isReplaying())
        refreshReplayLabel(); // the scan reached, or the end of the replay
    if (m_session->replayFailures().size() != static_cast<std::size_t>(m_failureList->count()))
        refreshFailureList();
    syncCompletes();
    syncOutputs();
    refreshUnstable();
    refreshExplanation();

    // Follow the new scans only when the user is looking at the latest ones.
    QScrollBar* bar = m_traceView->verticalScrollBar();
    const bool atBottom = bar->value() >= bar->maximum();
    m_traceModel->sync();
    if (m_session->isViewingHistory())
        selectViewedScan();
    else if (atBottom && m_traceView->isVisible())
        m_traceView->scrollToBottom();
}

void SimulationDock::refreshStatus()
{
    const core::Simulator* simulator = m_session->simulator();
    const double seconds = static_cast<double>(simulator->simulatedTimeMs()) / 1000.0;
    const QString scan = QLocale().toString(static_cast<qlonglong>(simulator->scanCount()));
    const QString time = QLocale().toString(seconds, 'f', 2);
    if (m_session->isViewingHistory())
        //: %1 of %2: the past scan shown and the latest scan run; %3: its simulated time in seconds
        m_statusLabel->setText(tr("Scan %1 of %2 (history) · %3 s")
                                   .arg(scan, QLocale().toString(static_cast<qlonglong>(m_session->latestScan())),
                                        time));
    else
        m_statusLabel->setText(tr("Scan %1 · %2 s").arg(scan, time));
}

// The GRAFCETs whose call in the scan shown ended still evolving (until
// stable, spec grafcet-layer.md §4.2): in red under the controls, whatever
// tab is in front.
void SimulationDock::refreshUnstable()
{
    const core::Simulator* simulator = m_session->simulator();
    QStringList steps;
    if (simulator) {
        for (const std::string& step : simulator->nestedSteps()) {
            if (simulator->nestedCalled(step) && simulator->unstable(step))
                steps << QString::fromStdString(step);
        }
    }
    if (steps.isEmpty()) {
        m_unstableLabel->hide();
        m_unstableLabel->clear();
        return;
    }
    //: Unstable is the name of the function block's output (not translated); %1: macro-steps or enclosing steps
    const QString text = tr("Unstable: the GRAFCET of %1 found no stable situation in this scan; its last "
                            "evolution still fired.")
                             .arg(steps.join(QStringLiteral(", ")));
    if (m_unstableLabel->text() != text)
        m_unstableLabel->setText(text);
    m_unstableLabel->show();
}

void SimulationDock::syncOutputs()
{
    const core::Simulator* simulator = m_session->simulator();
    if (!simulator)
        return;
    for (const InputRow& row : std::as_const(m_inputRows)) {
        if (!row.shown)
            continue;
        const core::cond::Value value = simulator->variableValue(static_cast<std::size_t>(row.variable));
        const bool isBool = simulator->variableType(static_cast<std::size_t>(row.variable)) == core::IecType::Bool;
        const QString text = isBool ? boolText(boolOf(value)) : QString::fromStdString(core::cond::formatValue(value));
        if (row.lamp)
            row.lamp->setOn(boolOf(value));
        if (row.fault)
            syncSensorFault(row);
        if (row.shown->text() == text)
            continue; // a style sheet costs a restyle: only when the value changes
        row.shown->setText(text);
        if (isBool) // the lamp's colours in text, bold: the value reads without the lamp too
            row.shown->setStyleSheet(QStringLiteral("QLabel { color: %1; font-weight: bold; }")
                                         .arg(boolOf(value) ? QStringLiteral("#14632b") : QStringLiteral("#4a525c")));
    }
}

void SimulationDock::syncInputs()
{
    const core::Simulator* simulator = m_session->simulator();
    if (!simulator)
        return;
    syncOutputs();
    for (const InputRow& row : std::as_const(m_inputRows)) {
        const core::cond::Value value = simulator->variableValue(static_cast<std::size_t>(row.variable));
        if (row.toggle) {
            const QSignalBlocker blocker(row.toggle);
            const bool on = boolOf(value);
            row.toggle->setChecked(on);
            row.toggle->setText(boolText(on));
            // A style sheet costs a restyle: only when the value changes.
            if (const QVariant shown = row.toggle->property("value"); !shown.isValid() || shown.toBool() != on) {
                row.toggle->setProperty("value", on);
                row.toggle->setStyleSheet(valueStyleSheet("QToolButton", on));
            }
        } else if (auto* spin = qobject_cast<QSpinBox*>(row.editor)) {
            const QSignalBlocker blocker(spin);
            spin->setValue(static_cast<int>(numberOf(value)));
        } else if (auto* spin = qobject_cast<QDoubleSpinBox*>(row.editor)) {
            const QSignalBlocker blocker(spin);
            spin->setValue(numberOf(value));
        }
    }
    // A replay plays the inputs.
    m_inputsWidget->setEnabled(!m_session->isReplaying());
}

void SimulationDock::syncCompletes()
{
    const core::Simulator* simulator = m_session->simulator();
    if (!simulator)
        return;
    for (const CompleteRow& row : std::as_const(m_completeRows)) {
        const std::string id = row.stepId.toStdString();
        const bool manual = simulator->completeMode(id) == core::CompleteMode::Manual;
        {
            const QSignalBlocker blocker(row.mode);
            row.mode->setCurrentIndex(manual ? 1 : 0);
        }
        {
            const QSignalBlocker blocker(row.manual);
            row.manual->setChecked(simulator->manualComplete(id));
        }
        row.manual->setEnabled(manual);
        const bool output = simulator->complete(id);
        // A style sheet costs a restyle: only when the value changes.
        const QVariant shown = row.output->property("complete");
        if (shown.isValid() && shown.toBool() == output)
            continue;
        row.output->setProperty("complete", output);
        row.output->setToolTip(tr("%1.Complete = %2 (after the last call of its function block)")
                                   .arg(row.stepId, boolText(output)));
        row.output->setStyleSheet(valueStyleSheet("QLabel", output));
    }
}

void SimulationDock::refreshExplanation()
{
    const core::Simulator* simulator = m_session->simulator();
    if (!simulator)
        return;
    const QString active = QString::fromStdString(simulator->activeStepId());
    const std::vector<core::TransitionExplanation> explanations = simulator->explain();

    const core::NestedExplanation nested = simulator->explainNested(active.toStdString());
    const core::NestedEngine* engine = simulator->grafcetEngine(active.toStdString());

    QStringList shown{active, boolText(simulator->entry())};
    if (const std::optional<core::SimulationFault>& fault = simulator->fault())
        shown << faultText(*fault);
    for (const core::TransitionExplanation& e : explanations) {
        shown << QString::fromStdString(e.transitionId) << QString::number(static_cast<int>(e.status))
              << QString::fromStdString(e.preemptedBy);
        for (const core::ExplanationReason& reason : e.reasons)
            shown << QString::fromStdString(core::toText(reason)); // retranslate() clears the cache
        shown << QString();
    }
    if (engine) {
        shown << stepNumbersText(engine->activeSteps()) << stepNumbersText(nested.situation)
              << boolText(nested.initialization) << boolText(engine->unstable());
        for (const core::NestedTimerState& timer : engine->timers())
            shown << QString::number(timer.elapsedMs);
        for (std::size_t i = 0; i < engine->outputNames().size(); ++i)
            shown << boolText(engine->output(i));
        for (const core::NestedTransitionExplanation& t : nested.transitions) {
            if (!isListed(nested, t))
                continue;
            shown << QString::number(t.number) << QString::number(static_cast<int>(t.status));
            for (const core::ExplanationReason& reason : t.reasons)
                shown << QString::fromStdString(core::toText(reason));
        }
    }
    if (shown == m_shownExplanation)
        return;
    m_shownExplanation = shown;

    QString activeText = active.isEmpty()
        ? tr("No visible step is active (State = %1).").arg(simulator->activeStepNumber())
        : tr("Active step: <b>%1</b> %2 · Entry = %3")
              .arg(active, officialStateName(active).toHtmlEscaped(), boolText(simulator->entry()));
    if (const std::optional<core::SimulationFault>& fault = simulator->fault())
        activeText += QStringLiteral("<br><span style=\"color:%1\">%2</span>")
                          .arg(chartstyle::problemColor().name(), faultText(*fault).toHtmlEscaped());
    m_activeLabel->setText(activeText);

    m_explanationView->clear();
    for (const core::TransitionExplanation& e : explanations) {
        auto* item = new QTreeWidgetItem(m_explanationView);
        QString name = transitionLabel(QString::fromStdString(e.transitionId));
        if (e.family)
            name = tr("%1 (family)").arg(name);
        item->setText(TransitionColumn, name);
        item->setText(StatusColumn, statusText(e));
        item->setToolTip(TransitionColumn, QString::fromStdString(e.transitionId));
        const QColor color = statusColor(e.status);
        if (color.isValid())
            item->setForeground(StatusColumn, color);
        for (const core::ExplanationReason& reason : e.reasons) {
            const QString text = explanationReasonText(reason);
            auto* child = new QTreeWidgetItem(item);
            child->setText(TransitionColumn, text);
            child->setToolTip(TransitionColumn, text);
            child->setFirstColumnSpanned(true);
        }
    }
    if (explanations.empty()) {
        auto* item = new QTreeWidgetItem(m_explanationView);
        item->setText(TransitionColumn, tr("The active step has no transition to evaluate."));
        item->setFirstColumnSpanned(true);
    }
    if (engine)
        addNestedExplanation(*engine, nested);
    m_explanationView->expandAll();
}

// The nested GRAFCET of the active step: its state after the last scan
// (active steps, timers, the outputs it drives, Unstable), then why each of
// its transitions fires or not in the next scan.
void SimulationDock::addNestedExplanation(const core::NestedEngine& engine, const core::NestedExplanation& nested)
{
    const QString step = QString::fromStdString(nested.stepId);
    auto* grafcet = new QTreeWidgetItem(m_explanationView);
    const std::vector<int> activeSteps = engine.activeSteps();
    grafcet->setText(TransitionColumn, activeSteps.empty()
                                           //: %1: a macro-step or enclosing step
                                           ? tr("GRAFCET of %1: no step active").arg(step)
                                           //: %1: a macro-step or enclosing step; %2: its active steps ("3, 5")
                                           : tr("GRAFCET of %1: steps %2").arg(step, stepNumbersText(activeSteps)));
    if (nested.initialization)
        grafcet->setText(StatusColumn, tr("initialised again in the next scan (steps %1)")
                                           .arg(stepNumbersText(nested.situation)));
    else if (nested.untilStable)
        grafcet->setText(StatusColumn, tr("first evolution of the next scan"));
    grafcet->setToolTip(TransitionColumn, nested.untilStable
                            ? tr("Until stable: the next scan's first evolution is explained; later evolutions "
                                 "of the same scan follow with edges FALSE.")
                            : tr("One evolution per scan."));
    auto addState = [grafcet](const QString& text) {
        auto* item = new QTreeWidgetItem(grafcet);
        item->setText(TransitionColumn, text);
        item->setToolTip(TransitionColumn, text);
        item->setFirstColumnSpanned(true);
    };
    for (const core::NestedTimerState& timer : engine.timers())
        //: %1: a timer of a time-dependent receptivity; %2: its step; %3 of %4: elapsed and set time in ms
        addState(tr("%1 (step %2): %3 ms of %4 ms")
                     .arg(QString::fromStdString(timer.name))
                     .arg(timer.step)
                     .arg(timer.elapsedMs)
                     .arg(timer.durationMs));
    QStringList outputs;
    for (std::size_t i = 0; i < engine.outputNames().size(); ++i)
        outputs << QStringLiteral("%1 = %2").arg(QString::fromStdString(engine.outputNames()[i]), boolText(engine.output(i)));
    if (!outputs.isEmpty())
        //: the outputs a nested GRAFCET drives, with their values ("Spindle = TRUE, Marker = FALSE")
        addState(tr("Outputs: %1").arg(outputs.join(QStringLiteral(", "))));
    if (nested.untilStable)
        addState(QStringLiteral("Unstable = %1").arg(boolText(engine.unstable()))); // code in every language
    const auto unlisted = std::count_if(nested.transitions.begin(), nested.transitions.end(),
                                        [&nested](const core::NestedTransitionExplanation& t) {
                                            return !isListed(nested, t);
                                        });
    if (unlisted > 0)
        //: the transitions of a large nested GRAFCET left out of the explanation
        addState(tr("%n other transition(s): an upstream step is not active", nullptr, int(unlisted)));
    for (const core::NestedTransitionExplanation& t : nested.transitions) {
        if (!isListed(nested, t))
            continue;
        auto* item = new QTreeWidgetItem(grafcet);
        //: a transition of a nested GRAFCET: its number, upstream and downstream steps
        item->setText(TransitionColumn, tr("T%1 (%2 → %3)")
                                            .arg(t.number)
                                            .arg(stepNumbersText(t.upstream), stepNumbersText(t.downstream)));
        item->setToolTip(TransitionColumn, QString::fromStdString(t.receptivity));
        item->setText(StatusColumn, nestedStatusText(t.status));
        const QColor color = nestedStatusColor(t.status);
        if (color.isValid())
            item->setForeground(StatusColumn, color);
        for (const core::ExplanationReason& reason : t.reasons) {
            const QString text = explanationReasonText(reason);
            auto* child = new QTreeWidgetItem(item);
            child->setText(TransitionColumn, text);
            child->setToolTip(TransitionColumn, text);
            child->setFirstColumnSpanned(true);
        }
    }
}

void SimulationDock::refreshReplay()
{
    refreshReplayLabel();
    refreshFailureList();
    m_recordButton->setEnabled(m_session->isActive() && !m_session->isReplaying());
    syncInputs();
}

void SimulationDock::refreshReplayLabel()
{
    const std::size_t failures = m_session->replayFailures().size();
    const QString file = m_session->replayFileName();
    QString text;
    switch (m_session->replayState()) {
    case SimulationSession::ReplayState::None:
        text = tr("Record this session as a scenario file, or replay one.");
        break;
    case SimulationSession::ReplayState::Running: {
        const QString scan = QString::number(m_session->latestScan());
        const QString length = QString::number(m_session->replayLength());
        if (m_session->isRunning())
            //: %1: the scenario file; %2 of %3: the scan reached and the scenario's last scan
            text = tr("Replaying %1: scan %2 of %3.").arg(file, scan, length);
        else
            //: %1: the scenario file; %2 of %3: the scan reached and the scenario's last scan; %4: a key (F10)
            text = tr("Replay of %1: paused at scan %2 of %3. Press %4 to step, or Run to play the rest.")
                       .arg(file, scan, length,
                            singleScanShortcut().toString(QKeySequence::NativeText));
        break;
    }
    case SimulationSession::ReplayState::Finished: {
        const int expectations = m_session->replayExpectationCount();
        if (failures == 0)
            text = tr("%1: every expectation met (%2).").arg(file).arg(expectations);
        else
            text = tr("%1: %2 of %3 expectations failed.").arg(file).arg(failures).arg(expectations);
        break;
    }
    }
    if (m_session->replayState() != SimulationSession::ReplayState::None && m_session->replayIsOpenLoop())
        text += QLatin1Char(' ') + tr("It sets the machine's sensors itself: played in open loop, the machine stands still.");
    if (m_replayLabel->text() != text)
        m_replayLabel->setText(text);
}

void SimulationDock::refreshFailureList()
{
    m_failureList->clear();
    for (const core::ScenarioFailure& failure : m_session->replayFailures()) {
        auto* item = new QListWidgetItem(tr("Line %1: %2").arg(failure.line).arg(scenarioFailureText(failure)),
                                         m_failureList);
        item->setForeground(QColor(0xc6, 0x28, 0x28));
    }
    m_failureList->setVisible(m_failureList->count() > 0);
}

void SimulationDock::recordScenario()
{
    const QString suggestion = QFileInfo(m_document->filePath()).completeBaseName();
    const QString base = suggestion.isEmpty() ? tr("session") : suggestion + QStringLiteral("-session");
    const QString dir = m_document->filePath().isEmpty() ? QDir::homePath()
                                                         : QFileInfo(m_document->filePath()).absolutePath();
    QString path = QFileDialog::getSaveFileName(this, tr("Record as Scenario"),
                                                QDir(dir).filePath(base + QStringLiteral(".scenario")),
                                                tr("Simulation scenarios (*.scenario *.txt);;All files (*)"));
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".scenario");
    QString error;
    if (!m_session->saveRecording(path, &error)) {
        QMessageBox::critical(this, tr("Record as Scenario"),
                              tr("Could not write %1.").arg(QDir::toNativeSeparators(path)) + QStringLiteral("\n\n")
                                  + error);
        return;
    }
    m_replayLabel->setText(tr("Recorded %1 scans to %2.")
                               .arg(m_session->simulator()->scanCount())
                               .arg(QDir::toNativeSeparators(path)));
}

void SimulationDock::replayScenario()
{
    const QString dir = m_document->filePath().isEmpty() ? QDir::homePath()
                                                         : QFileInfo(m_document->filePath()).absolutePath();
    const QString path = QFileDialog::getOpenFileName(this, tr("Replay Scenario"), dir,
                                                      tr("Simulation scenarios (*.scenario *.txt);;All files (*)"));
    if (path.isEmpty())
        return;
    QString error;
    if (!m_session->startReplay(path, &error)) {
        QMessageBox box(QMessageBox::Warning, tr("Replay Scenario"),
                        tr("Could not replay %1.").arg(QDir::toNativeSeparators(path)), QMessageBox::Ok, this);
        box.setInformativeText(error);
        box.exec();
        return;
    }
    // Paused at scan 0: F10 steps through it, Run plays the rest.
    m_tabs->setCurrentIndex(ScenarioTab);
}

} // namespace editor
