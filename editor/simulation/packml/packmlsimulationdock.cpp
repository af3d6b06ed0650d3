#include "editor/simulation/packml/packmlsimulationdock.h"

#include "editor/document.h"
#include "editor/simulation/packml/packmlsimulationsession.h"
#include "editor/simulation/packml/packmlsimulationtext.h"
#include "editor/simulation/packml/packmltracemodel.h"
#include "editor/simulation/packml/packmlvariablespanel.h"
#include "editor/simulation/simulationtext.h"
#include "editor/stdstring.h"

#include "core/templates/packml/packmlsimulator.h"

#include <QComboBox>
#include <QEvent>
#include <QFileDialog>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStyle>
#include <QTabWidget>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>

namespace editor {

namespace {

using core::packml::Command;

// Three buttons a row fit the dock column's 340 px at 1366 x 768 in every
// language (five overflowed it: "Unsuspend" was cut and the page scrolled sideways).
constexpr int kCommandColumns = 3;

QToolButton* toolButton(QWidget* parent, const QString& objectName, QStyle::StandardPixmap icon)
{
    auto* button = new QToolButton(parent);
    button->setObjectName(objectName);
    button->setIcon(parent->style()->standardIcon(icon));
    button->setAutoRaise(true);
    return button;
}

QLabel* sectionTitle(QWidget* parent)
{
    auto* label = new QLabel(parent);
    QFont font = label->font();
    font.setBold(true);
    label->setFont(font);
    return label;
}

void clearGrid(QGridLayout* grid)
{
    while (QLayoutItem* item = grid->takeAt(0)) {
        delete item->widget();
        delete item;
    }
}

// Does `state` in the current mode have a transition on `command`?
bool accepts(const core::packml::PackmlSimulator& simulator, Command command)
{
    const core::packml::ProgramMode* mode = simulator.program().mode(simulator.mode());
    const core::packml::ProgramState* state = mode ? mode->state(simulator.state()) : nullptr;
    if (!state)
        return false;
    for (const core::packml::ModeTransition& transition : state->transitions)
        if (transition.transition.trigger == core::packml::Trigger::Command && transition.transition.command == command)
            return true;
    return false;
}

QString commandText(Command command)
{
    return fromStd(std::string(core::packml::commandName(command))); // PackTags names in every language
}

} // namespace

QString PackmlSimulationDock::title()
{
    return tr("PackML Simulation");
}

PackmlSimulationDock::PackmlSimulationDock(PackmlSimulationSession* session, Document* document, QWidget* parent)
    : QDockWidget(title(), parent)
    , m_session(session)
    , m_document(document)
{
    setObjectName(QStringLiteral("packmlSimulationDock"));
    auto* content = new QWidget(this);
    auto* layout = new QVBoxLayout(content);
    layout->addWidget(buildControls());
    m_statusLabel = new QLabel(content);
    m_statusLabel->setObjectName(QStringLiteral("statusLabel"));
    m_statusLabel->setWordWrap(true);
    layout->addWidget(m_statusLabel);
    m_tabs = new QTabWidget(content);
    m_tabs->setObjectName(QStringLiteral("packmlSimulationTabs"));
    m_tabs->addTab(buildUnitTab(), QString());
    m_tabs->addTab(buildTraceTab(), QString());
    m_tabs->addTab(buildScenarioTab(), QString());
    layout->addWidget(m_tabs, 1);
    setWidget(content);
    connectSession();
    retranslate();
    rebuildForProgram();
}

QWidget* PackmlSimulationDock::buildControls()
{
    auto* bar = new QWidget(this);
    auto* row = new QHBoxLayout(bar);
    row->setContentsMargins(0, 0, 0, 0);
    m_startButton = new QPushButton(bar);
    m_startButton->setObjectName(QStringLiteral("startButton"));
    row->addWidget(m_startButton);
    m_runButton = toolButton(bar, QStringLiteral("runButton"), QStyle::SP_MediaPlay);
    m_runButton->setCheckable(true);
    m_stepButton = toolButton(bar, QStringLiteral("stepButton"), QStyle::SP_MediaSkipForward);
    m_backButton = toolButton(bar, QStringLiteral("stepBackButton"), QStyle::SP_MediaSeekBackward);
    m_forwardButton = toolButton(bar, QStringLiteral("stepForwardButton"), QStyle::SP_MediaSeekForward);
    m_resetButton = toolButton(bar, QStringLiteral("resetButton"), QStyle::SP_BrowserReload);
    m_endButton = toolButton(bar, QStringLiteral("endButton"), QStyle::SP_MediaStop);
    for (QToolButton* button : {m_runButton, m_stepButton, m_backButton, m_forwardButton, m_resetButton, m_endButton})
        row->addWidget(button);
    m_speedLabel = new QLabel(bar);
    m_speedSpin = new QSpinBox(bar);
    m_speedSpin->setObjectName(QStringLiteral("speedSpin"));
    m_speedSpin->setRange(PackmlSimulationSession::kMinSpeed, PackmlSimulationSession::kMaxSpeed);
    m_speedSpin->setValue(m_session->speed());
    m_speedLabel->setBuddy(m_speedSpin);
    row->addStretch(1);
    row->addWidget(m_speedLabel);
    row->addWidget(m_speedSpin);

    connect(m_startButton, &QPushButton::clicked, this, [this] { m_session->setActive(true); });
    connect(m_runButton, &QToolButton::toggled, this, [this](bool run) { run ? m_session->run() : m_session->pause(); });
    connect(m_stepButton, &QToolButton::clicked, m_session, &PackmlSimulationSession::stepOnce);
    connect(m_backButton, &QToolButton::clicked, m_session, &PackmlSimulationSession::stepBack);
    connect(m_forwardButton, &QToolButton::clicked, m_session, &PackmlSimulationSession::stepForward);
    connect(m_resetButton, &QToolButton::clicked, m_session, &PackmlSimulationSession::reset);
    connect(m_endButton, &QToolButton::clicked, this, [this] { m_session->setActive(false); });
    connect(m_speedSpin, &QSpinBox::valueChanged, m_session, &PackmlSimulationSession::setSpeed);
    return bar;
}

QWidget* PackmlSimulationDock::buildUnitTab()
{
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    auto* page = new QWidget(scroll);
    auto* layout = new QVBoxLayout(page);
    m_commandsTitle = sectionTitle(page);
    layout->addWidget(m_commandsTitle);
    m_commandsGrid = new QGridLayout();
    layout->addLayout(m_commandsGrid);
    m_requestLabel = new QLabel(page);
    m_requestLabel->setObjectName(QStringLiteral("requestLabel"));
    m_requestLabel->setWordWrap(true);
    layout->addWidget(m_requestLabel);
    m_modeTitle = sectionTitle(page);
    layout->addWidget(m_modeTitle);
    m_modeSelector = new QComboBox(page);
    m_modeSelector->setObjectName(QStringLiteral("modeSelector"));
    layout->addWidget(m_modeSelector);
    m_instanceTitle = sectionTitle(page);
    layout->addWidget(m_instanceTitle);
    m_instanceLabel = new QLabel(page);
    m_instanceLabel->setObjectName(QStringLiteral("instanceLabel"));
    m_instanceLabel->setWordWrap(true);
    layout->addWidget(m_instanceLabel);
    m_completeCombo = new QComboBox(page);
    m_completeCombo->setObjectName(QStringLiteral("completeCombo"));
    m_completeCombo->addItems({QString(), QString(), QString()}); // worded by retranslate()
    layout->addWidget(m_completeCombo);
    m_variables = new PackmlVariablesPanel(m_session, page);
    layout->addWidget(m_variables);
    layout->addStretch(1);
    scroll->setWidget(page);

    // Picking a mode requests it; the selector shows the current mode again
    // after the scan that read the request, granted or not.
    connect(m_modeSelector, &QComboBox::activated, this, [this](int index) {
        const int mode = m_modeSelector->itemData(index).toInt();
        if (m_session->isActive() && mode != m_session->simulator()->mode())
            m_session->requestMode(mode);
    });
    connect(m_completeCombo, &QComboBox::activated, this, [this](int index) {
        const std::optional<bool> complete = index == 0 ? std::nullopt : std::optional<bool>(index == 1);
        m_session->setManualComplete(m_session->currentInstance(), complete);
    });
    return scroll;
}

QWidget* PackmlSimulationDock::buildTraceTab()
{
    m_traceModel = new PackmlTraceModel(m_session, this);
    m_traceView = new QTableView(this);
    m_traceView->setObjectName(QStringLiteral("traceView"));
    m_traceView->setModel(m_traceModel);
    m_traceView->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_traceView->setSelectionMode(QAbstractItemView::SingleSelection);
    m_traceView->verticalHeader()->hide();
    m_traceView->horizontalHeader()->setStretchLastSection(true);
    // A click on a scan shows it, as stepping back to it does.
    connect(m_traceView, &QTableView::clicked, this, [this](const QModelIndex& index) {
        const QModelIndex scan = m_traceModel->index(index.row(), PackmlTraceModel::ScanColumn);
        m_session->showScan(scan.data().toLongLong());
    });
    return m_traceView;
}

QWidget* PackmlSimulationDock::buildScenarioTab()
{
    auto* page = new QWidget(this);
    auto* layout = new QVBoxLayout(page);
    m_replayButton = new QPushButton(page);
    m_replayButton->setObjectName(QStringLiteral("replayButton"));
    layout->addWidget(m_replayButton, 0, Qt::AlignLeft);
    m_replayLabel = new QLabel(page);
    m_replayLabel->setObjectName(QStringLiteral("replayLabel"));
    m_replayLabel->setWordWrap(true);
    layout->addWidget(m_replayLabel);
    m_failureList = new QListWidget(page);
    m_failureList->setObjectName(QStringLiteral("failureList"));
    layout->addWidget(m_failureList, 1);
    connect(m_replayButton, &QPushButton::clicked, this, &PackmlSimulationDock::openScenario);
    return page;
}

void PackmlSimulationDock::connectSession()
{
    connect(m_session, &PackmlSimulationSession::activeChanged, this, [this] {
        m_replayError.clear();
        rebuildForProgram();
    });
    connect(m_session, &PackmlSimulationSession::stepped, this, &PackmlSimulationDock::refresh);
    connect(m_session, &PackmlSimulationSession::inputsChanged, this, &PackmlSimulationDock::refresh);
    connect(m_session, &PackmlSimulationSession::historyMoved, this, &PackmlSimulationDock::refresh);
    connect(m_session, &PackmlSimulationSession::runningChanged, this, &PackmlSimulationDock::refreshControls);
    connect(m_session, &PackmlSimulationSession::replayChanged, this, &PackmlSimulationDock::refreshReplay);
    connect(m_session, &PackmlSimulationSession::speedChanged, this, [this](int speed) {
        const QSignalBlocker blocker(m_speedSpin);
        m_speedSpin->setValue(speed);
    });
}

void PackmlSimulationDock::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDockWidget::changeEvent(event);
}

void PackmlSimulationDock::retranslate()
{
    setWindowTitle(title());
    m_startButton->setText(tr("Start Simulation"));
    m_runButton->setToolTip(tr("Run or pause the scans"));
    m_stepButton->setToolTip(tr("Single scan"));
    m_backButton->setToolTip(tr("Step back: show the scan before"));
    m_forwardButton->setToolTip(tr("Step forward: show the scan after"));
    m_resetButton->setToolTip(tr("Reset: the initial state and mode, inputs at their defaults"));
    m_endButton->setToolTip(tr("End the simulation"));
    m_speedLabel->setText(tr("Scans/s:"));
    m_tabs->setTabText(0, tr("Unit"));
    m_tabs->setTabText(1, tr("Trace"));
    m_tabs->setTabText(2, tr("Scenario"));
    m_commandsTitle->setText(tr("Commands"));
    m_modeTitle->setText(tr("Unit mode"));
    m_modeSelector->setToolTip(tr("Pick a mode to request it: the mode manager grants it or says why not"));
    m_instanceTitle->setText(tr("Function block"));
    //: the State Complete of a state without nested GRAFCET: as the generated skeleton sets it
    m_completeCombo->setItemText(0, tr("SC from the skeleton"));
    m_completeCombo->setItemText(1, tr("SC = TRUE (by hand)"));
    m_completeCombo->setItemText(2, tr("SC = FALSE (by hand)"));
    m_completeCombo->setToolTip(tr("The State Complete of a state without nested GRAFCET, set by hand to hold an "
                                   "acting state or to complete Execute"));
    m_variables->retranslate();
    m_replayButton->setText(tr("Replay Scenario…"));
    m_traceModel->refresh();
    refresh();
}

void PackmlSimulationDock::clearProgramWidgets()
{
    m_commandButtons.clear();
    clearGrid(m_commandsGrid);
    m_modeSelector->clear();
}

// The program is known once the session is active: its edition's
// commands, its modes, its variables.
void PackmlSimulationDock::rebuildForProgram()
{
    clearProgramWidgets();
    if (m_session->isActive()) {
        addCommandButtons();
        addModes();
    }
    m_variables->rebuild();
    refresh();
}

void PackmlSimulationDock::addCommandButtons()
{
    const core::packml::Edition edition = m_session->simulator()->program().options.edition;
    int position = 0;
    for (int number = 1; number <= core::packml::kCommandCount; ++number) {
        const auto command = static_cast<Command>(number);
        if (!core::packml::commandInEdition(command, edition))
            continue;
        auto* button = new QPushButton(commandText(command), m_commandsGrid->parentWidget());
        button->setObjectName(QStringLiteral("command_") + commandText(command));
        connect(button, &QPushButton::clicked, this, [this, command] { m_session->pressCommand(command); });
        m_commandsGrid->addWidget(button, position / kCommandColumns, position % kCommandColumns);
        m_commandButtons.insert(number, button);
        ++position;
    }
}

void PackmlSimulationDock::addModes()
{
    for (const core::packml::ProgramMode& mode : m_session->simulator()->program().modes)
        m_modeSelector->addItem(QStringLiteral("%1 %2").arg(mode.number).arg(fromStd(mode.name)), mode.number);
}

QPushButton* PackmlSimulationDock::commandButton(Command command) const
{
    return m_commandButtons.value(static_cast<int>(command), nullptr);
}

bool PackmlSimulationDock::isCommandAccepted(Command command) const
{
    return m_session->isActive() && accepts(*m_session->simulator(), command);
}

QToolButton* PackmlSimulationDock::inputToggle(const QString& variable) const
{
    return m_variables->inputToggle(variable);
}

QLineEdit* PackmlSimulationDock::inputField(const QString& variable) const
{
    return m_variables->inputField(variable);
}

LampIndicator* PackmlSimulationDock::outputLamp(const QString& variable) const
{
    return m_variables->outputLamp(variable);
}

QLabel* PackmlSimulationDock::outputValue(const QString& variable) const
{
    return m_variables->outputValue(variable);
}

void PackmlSimulationDock::refresh()
{
    refreshControls();
    refreshStatus();
    refreshCommands();
    refreshRequest();
    m_variables->refresh();
    refreshInstance();
    refreshReplay();
    selectShownScan();
}

void PackmlSimulationDock::refreshControls()
{
    const bool active = m_session->isActive();
    m_startButton->setVisible(!active);
    for (QToolButton* button : {m_runButton, m_stepButton, m_resetButton, m_endButton})
        button->setEnabled(active);
    m_backButton->setEnabled(m_session->canStepBack());
    m_forwardButton->setEnabled(m_session->canStepForward());
    m_replayButton->setEnabled(active);
    m_tabs->widget(0)->setEnabled(active);
    const QSignalBlocker blocker(m_runButton);
    m_runButton->setChecked(m_session->isRunning());
    m_runButton->setIcon(style()->standardIcon(m_session->isRunning() ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
}

void PackmlSimulationDock::refreshStatus()
{
    const core::packml::PackmlSimulator* simulator = m_session->simulator();
    if (!simulator) {
        m_statusLabel->setText(tr("Start the simulation to play the unit's commands and modes."));
        return;
    }
    //: %1: a scan number, %2: a PackML state (Execute), %3: a unit mode (Production)
    QString text = tr("Scan %1: %2 in %3")
                       .arg(QString::number(static_cast<qlonglong>(simulator->scanCount())),
                            fromStd(std::string(core::packml::stateName(simulator->state()))),
                            packmlModeName(simulator->program(), simulator->mode()));
    if (m_session->isViewingHistory())
        //: %1: a status, %2: the latest scan
        text = tr("%1 (history; the latest scan is %2)").arg(text, QString::number(static_cast<qlonglong>(m_session->latestScan())));
    if (const auto& fault = simulator->fault())
        text += QLatin1Char('\n') + packmlFaultText(*fault);
    m_statusLabel->setText(text);
}

void PackmlSimulationDock::refreshCommands()
{
    if (!m_session->isActive())
        return;
    const QString state = fromStd(std::string(core::packml::stateName(m_session->simulator()->state())));
    for (auto it = m_commandButtons.cbegin(); it != m_commandButtons.cend(); ++it) {
        const auto command = static_cast<Command>(it.key());
        const bool accepted = isCommandAccepted(command);
        QFont font = it.value()->font();
        font.setBold(accepted);
        it.value()->setFont(font);
        it.value()->setToolTip(accepted ? tr("%1 is accepted in %2").arg(commandText(command), state)
                                        : tr("%1 is not accepted in %2: pressing it shows why").arg(commandText(command), state));
    }
    const QSignalBlocker blocker(m_modeSelector);
    m_modeSelector->setCurrentIndex(m_modeSelector->findData(m_session->simulator()->mode()));
}

void PackmlSimulationDock::refreshRequest()
{
    const auto& request = m_session->lastRequest();
    if (!m_session->isActive() || !request) {
        m_requestLabel->clear();
        return;
    }
    const auto kind = request->kind == PackmlSimulationSession::RequestKind::Mode ? PackmlRequestKind::Mode
                                                                                  : PackmlRequestKind::Command;
    const core::packml::PackmlProgram& program = m_session->simulator()->program();
    if (request->record) {
        m_requestLabel->setText(packmlRequestOutcomeText(kind, request->number, *request->record, program));
        return;
    }
    const QString name = kind == PackmlRequestKind::Mode ? packmlModeName(program, request->number)
                                                         : commandText(static_cast<Command>(request->number));
    m_requestLabel->setText(tr("%1: requested, read by the next scan").arg(name));
}

void PackmlSimulationDock::refreshInstance()
{
    const core::packml::PackmlSimulator* simulator = m_session->simulator();
    const int index = m_session->currentInstance();
    m_completeCombo->setVisible(false);
    if (!simulator) {
        m_instanceLabel->clear();
        return;
    }
    const QString state = fromStd(std::string(core::packml::stateName(simulator->state())));
    if (index < 0) {
        m_instanceLabel->setText(tr("%1 is a wait state: no function block runs in it").arg(state));
        return;
    }
    const core::packml::ProgramInstance& instance = simulator->program().instances[static_cast<std::size_t>(index)];
    const QString name = fromStd(instance.name);
    const QString complete = simulator->complete(index) ? QStringLiteral("TRUE") : QStringLiteral("FALSE");
    if (const core::NestedEngine* engine = simulator->engine(index)) {
        //: %1: a function block instance (Production_Execute), %2: step numbers, %3: TRUE or FALSE
        m_instanceLabel->setText(tr("%1: active steps %2, Complete = %3")
                                     .arg(name, stepNumbersText(engine->activeSteps()), complete));
        return;
    }
    m_instanceLabel->setText(tr("%1 runs no GRAFCET: Complete = %2").arg(name, complete));
    m_completeCombo->setVisible(true);
    const std::optional<bool> manual = simulator->manualComplete(index);
    const QSignalBlocker blocker(m_completeCombo);
    m_completeCombo->setCurrentIndex(!manual ? 0 : (*manual ? 1 : 2));
}

void PackmlSimulationDock::refreshReplay()
{
    m_failureList->clear();
    for (const core::packml::PackmlScenarioFailure& failure : m_session->replayFailures())
        m_failureList->addItem(packmlScenarioFailureText(failure));
    const QString file = m_session->replayFileName();
    const int expectations = m_session->replayExpectationCount();
    const int failed = static_cast<int>(m_session->replayFailures().size());
    switch (m_session->replayState()) {
    case PackmlSimulationSession::ReplayState::None: m_replayLabel->setText(m_replayError); break;
    case PackmlSimulationSession::ReplayState::Running:
        //: %1: a scenario file, %2: the scan shown, %3: its last scan
        m_replayLabel->setText(tr("Replaying %1: scan %2 of %3")
                                   .arg(file, QString::number(static_cast<qlonglong>(m_session->viewedScan())),
                                        QString::number(static_cast<qlonglong>(m_session->replayLength()))));
        break;
    case PackmlSimulationSession::ReplayState::Finished:
        m_replayLabel->setText(failed == 0 ? tr("%1 passed: all %2 expectation(s) met").arg(file).arg(expectations)
                                           : tr("%1 failed: %2 of %3 expectation(s) did not hold")
                                                 .arg(file)
                                                 .arg(failed)
                                                 .arg(expectations));
        break;
    }
}

void PackmlSimulationDock::selectShownScan()
{
    const int row = m_traceModel->rowOfScan(m_session->viewedScan());
    if (row < 0) {
        m_traceView->clearSelection();
        return;
    }
    m_traceView->selectRow(row);
    m_traceView->scrollTo(m_traceModel->index(row, 0));
}

bool PackmlSimulationDock::replayFile(const QString& path)
{
    QString error;
    const bool started = m_session->startReplay(path, &error);
    m_replayError = started ? QString() : tr("Cannot replay %1:\n%2").arg(path, error);
    refreshReplay();
    return started;
}

void PackmlSimulationDock::openScenario()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Replay Scenario"), QString(),
                                                      tr("Scenarios (*.scenario *.txt);;All files (*)"));
    if (!path.isEmpty())
        replayFile(path);
}

} // namespace editor
