#include "editor/simulation/simulationsession.h"

#include "editor/document.h"
#include "editor/simulation/simulationpacing.h"
#include "editor/simulation/simulationtext.h"

#include "core/formats/fileio.h"
#include "core/machine/closedloopscenario.h"

#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QTimer>

#include <algorithm>
#include <cmath>

namespace editor {

SimulationSession::SimulationSession(Document* document, QObject* parent)
    : QObject(parent)
    , m_document(document)
    , m_timer(new QTimer(this))
{
    Q_ASSERT(document);
    m_timer->setInterval(kTickMs);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &SimulationSession::onTick);

    // The simulator runs a copy of the program: any change of the model ends it.
    connect(m_document, &Document::modelReset, this, &SimulationSession::onModelChanged);
    connect(m_document, &Document::stepChanged, this, &SimulationSession::onModelChanged);
    connect(m_document, &Document::transitionChanged, this, &SimulationSession::onModelChanged);
    connect(m_document, &Document::variableChanged, this, &SimulationSession::onModelChanged);
    connect(m_document, &Document::variablesChanged, this, &SimulationSession::onModelChanged);
    connect(m_document, &Document::settingsChanged, this, &SimulationSession::onModelChanged);
    connect(m_document, &Document::machineChanged, this, &SimulationSession::onModelChanged);
}

SimulationSession::~SimulationSession()
{
    m_runner.reset(); // refers to the scenario, the simulator and the loop
    m_loop.reset();   // refers to the simulator
}

void SimulationSession::setActive(bool active)
{
    if (active == isActive())
        return;
    if (active) {
        m_simulator = std::make_unique<core::Simulator>(m_document->model());
        if (!m_document->model().machine().empty())
            m_loop = std::make_unique<core::machine::MachineLoop>(*m_simulator, m_document->model().machine());
        m_tokenTransitions.clear();
        for (const std::string& name : m_simulator->tokenNames()) {
            std::string transition;
            for (const core::GemmaStep& step : m_simulator->program().steps) {
                for (const core::GemmaToken& token : step.tokens) {
                    if (token.name == name)
                        transition = token.transitionId;
                }
            }
            m_tokenTransitions.push_back(transition);
        }
        clearSession();
        m_document->setReadOnly(true);
    } else {
        pause();
        stopReplay();
        m_runner.reset();
        m_loop.reset();
        m_simulator.reset();
        m_trace.clear();
        m_lastFired.clear();
        m_history.clear();
        m_viewed.reset();
        m_document->setReadOnly(false);
    }
    emit activeChanged(active);
}

void SimulationSession::onModelChanged()
{
    setActive(false);
}

bool SimulationSession::isRunning() const
{
    return m_timer->isActive();
}

const core::Simulator* SimulationSession::simulator() const
{
    if (m_viewed)
        return &m_history[*m_viewed].simulator;
    return m_simulator.get();
}

void SimulationSession::run()
{
    if (!isActive() || isRunning() || m_linked) // linked: the link's clock runs the scans
        return;
    continueFromViewedScan();
    // The first scan comes with the first tick rather than a whole period later.
    m_owedScans = 1;
    m_clock.start();
    m_timer->start();
    emit runningChanged(true);
}

void SimulationSession::pause()
{
    if (!isRunning())
        return;
    m_timer->stop();
    emit runningChanged(false);
}

void SimulationSession::stepOnce()
{
    advance(1);
}

void SimulationSession::reset()
{
    if (!isActive())
        return;
    pause();
    stopReplay();
    resetSimulation();
    clearSession();
    emit wasReset();
    emit inputsChanged();
    emit stepped();
}

void SimulationSession::clearSession()
{
    m_trace.clear();
    m_lastFired.clear();
    m_pendingReleases.clear();
    m_pendingFaults.clear();
    m_pressedAt.assign(m_simulator->variableNames().size(), -1);
    m_changes.clear();
    m_recorded.clear();
    // Manual settings kept across the reset are recorded at scan 1: a
    // scenario starts with every Complete automatic.
    m_completeSettings.assign(m_simulator->nestedSteps().size(), std::nullopt);
    const bool wasViewingHistory = isViewingHistory();
    m_viewed.reset();
    m_history.clear();
    keepSnapshot(); // scan 0: the start state
    if (wasViewingHistory)
        emit historyMoved();
}

void SimulationSession::setSpeed(int scansPerSecond)
{
    const int speed = std::clamp(scansPerSecond, kMinSpeed, kMaxSpeed);
    if (speed == m_speed)
        return;
    m_speed = speed;
    emit speedChanged(m_speed);
}

void SimulationSession::onTick()
{
    const double seconds = std::min(static_cast<double>(m_clock.nsecsElapsed()) / 1e9, simulationpacing::kMaxCatchUpSeconds);
    m_clock.restart();
    m_owedScans += seconds * m_speed;
    const double scans = std::floor(m_owedScans);
    m_owedScans -= scans;
    runScans(static_cast<std::int64_t>(scans), simulationpacing::kTickBudgetNs);
}

void SimulationSession::advance(std::int64_t scans)
{
    runScans(scans, -1);
}

void SimulationSession::runScans(std::int64_t scans, qint64 budgetNs)
{
    if (!isActive() || scans <= 0)
        return;
    continueFromViewedScan();
    const bool hadPendingReleases = !m_pendingReleases.empty();
    QElapsedTimer clock;
    clock.start();
    std::int64_t ran = 0;
    for (; ran < scans && (budgetNs < 0 || ran == 0 || clock.nsecsElapsed() < budgetNs); ++ran) {
        // An integer division by zero stopped the program, as it stops the
        // PLC's task (core::Simulator::fault()): no scan runs until a reset.
        if (m_simulator->fault()) {
            pause();
            break;
        }
        if (m_runner && m_simulator->scanCount() >= m_scenario->lastScan()) {
            finishReplay();
            break;
        }
        core::ScanRecord record = m_runner ? m_runner->step() : runOneScan();
        if (m_runner) {
            const std::vector<core::ScenarioFailure>& failures = m_runner->lastFailures();
            m_replayFailures.insert(m_replayFailures.end(), failures.begin(), failures.end());
        }
        afterScan(std::move(record));
    }
    // A replay whose last scan just ran ends now rather than on the next press.
    if (m_runner && m_simulator->scanCount() >= m_scenario->lastScan())
        finishReplay();
    if (ran == 0)
        return;
    if (hadPendingReleases || m_runner || m_replayState == ReplayState::Finished)
        emit inputsChanged();
    emit stepped();
}

void SimulationSession::afterScan(core::ScanRecord&& record)
{
    // A released push button goes FALSE once a scan has read its TRUE.
    for (int index : m_pendingReleases)
        m_simulator->setVariableAt(static_cast<std::size_t>(index), false);
    m_pendingReleases.clear();

    core::RecordedScan changes;
    changes.scan = record.scan;
    changes.inputs = record.changedInputs;
    dropMachineInputs(changes.inputs);
    recordCompleteSettings(changes);
    changes.faults = std::move(m_pendingFaults);
    m_pendingFaults.clear();
    if (!changes.inputs.empty() || !changes.completes.empty() || !changes.faults.empty())
        m_changes.push_back(std::move(changes));

    if (!record.fired.empty())
        m_lastFired = QString::fromStdString(record.fired);
    // The scans a recording writes expectations for: firings, outputs that
    // changed, nested situations and Unstable that changed.
    if (m_recorded.size() < static_cast<std::size_t>(kRecordedScanCapacity)
        && core::recordWorthKeeping(record, m_trace.empty() ? nullptr : &m_trace.back()))
        m_recorded.push_back(record);
    m_trace.push_back(std::move(record));
    if (m_trace.size() > static_cast<std::size_t>(kTraceCapacity))
        m_trace.pop_front();
    keepSnapshot();
}

// After the releases: a snapshot is the simulator as a pause after that
// scan leaves it, so continuing from it plays exactly as continuing then.
void SimulationSession::keepSnapshot()
{
    std::optional<core::machine::MachineLoop::Snapshot> machine;
    if (m_loop)
        machine = m_loop->snapshot();
    m_history.push_back({*m_simulator, m_lastFired, std::move(machine)});
    // The oldest entry is the scan the first step back of the kept ones lands on.
    if (m_history.size() > static_cast<std::size_t>(kHistoryCapacity) + 1)
        m_history.pop_front();
}

QString SimulationSession::lastFiredTransition() const
{
    return m_viewed ? m_history[*m_viewed].lastFired : m_lastFired;
}

std::int64_t SimulationSession::viewedScan() const
{
    const core::Simulator* shown = simulator();
    return shown ? shown->scanCount() : 0;
}

std::int64_t SimulationSession::latestScan() const
{
    return m_simulator ? m_simulator->scanCount() : 0;
}

std::int64_t SimulationSession::firstKeptScan() const
{
    return m_history.empty() ? latestScan() : m_history.front().simulator.scanCount();
}

bool SimulationSession::canStepBack() const
{
    return isActive() && viewedScan() > firstKeptScan();
}

bool SimulationSession::canStepForward() const
{
    return isActive() && isViewingHistory();
}

void SimulationSession::stepBack()
{
    if (canStepBack())
        showScan(viewedScan() - 1);
}

void SimulationSession::stepForward()
{
    if (canStepForward())
        showScan(viewedScan() + 1);
}

void SimulationSession::showScan(std::int64_t scan)
{
    if (!isActive() || m_history.empty())
        return;
    pause();
    const std::int64_t first = firstKeptScan();
    const std::int64_t target = std::clamp(scan, first, latestScan());
    std::optional<std::size_t> viewed;
    if (target < latestScan())
        viewed = static_cast<std::size_t>(target - first);
    if (viewed == m_viewed)
        return;
    m_viewed = viewed;
    emit historyMoved();
    emit inputsChanged();
    emit stepped();
}

// Like an edit after an undo: the scans after the one shown are dropped
// from the history, the trace and the recording, and the simulator goes
// back to that scan. Played on, a replay goes on from there, its later
// failures dropped; an input changed there ends it: the user plays from then.
void SimulationSession::continueFromViewedScan(Continuation how)
{
    if (!m_viewed)
        return;
    m_history.erase(m_history.begin() + static_cast<std::ptrdiff_t>(*m_viewed) + 1, m_history.end());
    m_viewed.reset();
    // Assigned, not replaced: the replay's runner refers to this simulator.
    *m_simulator = m_history.back().simulator;
    if (m_loop && m_history.back().machine)
        m_loop->restore(*m_history.back().machine);
    m_lastFired = m_history.back().lastFired;
    const std::int64_t scan = m_simulator->scanCount();
    while (!m_trace.empty() && m_trace.back().scan > scan)
        m_trace.pop_back();
    dropRecordingAfter(scan);
    m_pendingReleases.clear();
    m_pendingFaults.clear();
    std::fill(m_pressedAt.begin(), m_pressedAt.end(), -1);
    if (m_scenario && how == Continuation::Edit) {
        stopReplay();
    } else if (m_scenario) {
        std::erase_if(m_replayFailures, [scan](const core::ScenarioFailure& f) { return f.scan > scan; });
        if (scan < m_scenario->lastScan()) {
            m_runner = makeRunner();
            m_replayState = ReplayState::Running;
        }
        emit replayChanged();
    }
    emit historyMoved();
}

void SimulationSession::dropRecordingAfter(std::int64_t scan)
{
    std::erase_if(m_changes, [scan](const core::RecordedScan& changes) { return changes.scan > scan; });
    std::erase_if(m_recorded, [scan](const core::ScanRecord& record) { return record.scan > scan; });
    // The Complete settings last recorded, as they stood after that scan.
    const std::vector<std::string>& steps = m_simulator->nestedSteps();
    m_completeSettings.assign(steps.size(), std::nullopt);
    for (const core::RecordedScan& changes : m_changes) {
        for (const core::RecordedScan::CompleteSetting& setting : changes.completes) {
            const auto step = std::find(steps.begin(), steps.end(), setting.stepId);
            if (step != steps.end())
                m_completeSettings[static_cast<std::size_t>(step - steps.begin())] = setting.manualValue;
        }
    }
}

std::optional<bool> SimulationSession::completeSetting(const std::string& stepId) const
{
    if (m_simulator->completeMode(stepId) == core::CompleteMode::Automatic)
        return std::nullopt;
    return m_simulator->manualComplete(stepId);
}

// The Complete settings the scan ran with, where they differ from the last
// ones recorded.
void SimulationSession::recordCompleteSettings(core::RecordedScan& changes)
{
    const std::vector<std::string>& steps = m_simulator->nestedSteps();
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const std::optional<bool> setting = completeSetting(steps[i]);
        if (setting != m_completeSettings[i]) {
            m_completeSettings[i] = setting;
            changes.completes.push_back({steps[i], setting});
        }
    }
}

bool SimulationSession::setVariable(int index, const core::cond::Value& value, QString* error)
{
    if (!isActive())
        return false;
    if (isMachineDriven(index)) {
        if (error)
            *error = tr("%1 is a sensor of the machine's %2: the machine sets it")
                         .arg(QString::fromStdString(m_simulator->variableNames()[static_cast<std::size_t>(index)]),
                              machineOwner(index));
        return false;
    }
    continueFromViewedScan(Continuation::Edit);
    const core::Status status = m_simulator->setVariableAt(static_cast<std::size_t>(index), value);
    if (!status) {
        if (error)
            *error = QString::fromStdString(status.message);
        return false;
    }
    emit inputsChanged();
    return true;
}

void SimulationSession::press(int index)
{
    if (!isActive() || index < 0 || static_cast<std::size_t>(index) >= m_pressedAt.size() || isMachineDriven(index))
        return;
    continueFromViewedScan(Continuation::Edit);
    m_pendingReleases.erase(std::remove(m_pendingReleases.begin(), m_pendingReleases.end(), index),
                            m_pendingReleases.end());
    m_pressedAt[static_cast<std::size_t>(index)] = m_simulator->scanCount();
    setVariable(index, true);
}

void SimulationSession::release(int index)
{
    if (!isActive() || index < 0 || static_cast<std::size_t>(index) >= m_pressedAt.size() || isMachineDriven(index))
        return;
    continueFromViewedScan(Continuation::Edit);
    std::int64_t& pressedAt = m_pressedAt[static_cast<std::size_t>(index)];
    const bool scanned = pressedAt < 0 || m_simulator->scanCount() > pressedAt;
    pressedAt = -1;
    if (scanned)
        setVariable(index, false);
    else
        m_pendingReleases.push_back(index);
}

void SimulationSession::setCompleteMode(const QString& stepId, core::CompleteMode mode)
{
    if (!isActive())
        return;
    continueFromViewedScan(Continuation::Edit);
    if (m_simulator->setCompleteMode(stepId.toStdString(), mode)) {
        emit completeModeChosen(stepId);
        emit inputsChanged();
    }
}

void SimulationSession::setManualComplete(const QString& stepId, bool complete)
{
    if (!isActive())
        return;
    continueFromViewedScan(Continuation::Edit);
    if (m_simulator->setComplete(stepId.toStdString(), complete))
        emit inputsChanged();
}

core::ScenarioRecording SimulationSession::recording() const
{
    core::ScenarioRecording recording;
    if (!isActive())
        return recording;
    const std::string name = m_document->model().settings().name;
    recording.title = "GG Studio simulation of " + (name.empty() ? std::string("an untitled model") : name) + ", "
                    + std::to_string(m_simulator->scanCount()) + " scans, recorded "
                    + QDateTime::currentDateTime().toString(Qt::ISODate).toStdString();
    if (m_recorded.size() >= static_cast<std::size_t>(kRecordedScanCapacity))
        recording.title += "\nExpectations only for the first " + std::to_string(kRecordedScanCapacity)
                         + " scans that fired or changed an output or a nested situation.";
    recording.changes = m_changes;
    recording.records = m_recorded;
    recording.nestedSteps = m_simulator->nestedSteps();
    return recording;
}

std::string SimulationSession::recordingText() const
{
    const core::ScenarioRecording session = recording();
    std::string text = core::writeScenario(session);
    if (!isActive())
        return text;
    // The session may go on after its last change or firing: the replay
    // runs as long and checks where it ended.
    std::int64_t last = 0;
    for (const core::RecordedScan& scan : session.changes)
        last = std::max(last, scan.scan);
    for (const core::ScanRecord& record : session.records)
        last = std::max(last, record.scan);
    const std::int64_t scans = m_simulator->scanCount();
    const std::string step = m_simulator->activeStepId();
    if (scans > last && !step.empty())
        text += "at " + std::to_string(scans) + ": expect step " + step + "\n";
    return text;
}

// Through core's writer, like every save: atomic, and never onto a FIFO or
// a device.
bool SimulationSession::saveRecording(const QString& path, QString* error) const
{
    const core::Status status = core::writeFileAtomically(QFile::encodeName(path).toStdString(), recordingText());
    if (!status && error)
        *error = QString::fromStdString(status.message);
    return status.ok;
}

bool SimulationSession::startReplay(const QString& path, QString* error)
{
    if (!isActive())
        return false;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        if (error)
            *error = file.errorString();
        return false;
    }
    const QByteArray text = file.readAll();
    return startReplayText(std::string_view(text.constData(), static_cast<std::size_t>(text.size())),
                           QFileInfo(path).fileName(), error);
}

bool SimulationSession::startReplayText(std::string_view text, const QString& fileName, QString* error)
{
    if (!isActive())
        return false;
    core::ScenarioParseResult parsed = core::parseScenario(text, fileName.toStdString());
    std::vector<core::ScenarioError> errors = parsed.errors;
    if (parsed.ok())
        errors = core::validateScenario(parsed.scenario, *m_simulator,
                                        m_loop ? core::FaultLines::CheckedByMachine : core::FaultLines::Refused);
    // A scenario that plays the machine's sensors itself (an open-loop
    // scenario, a verification counterexample) replays in open loop: the
    // machine stands still, as `ggstudio-cli simulate --open-loop` plays it;
    // its fault lines, which need the machine, are refused then.
    bool openLoop = false;
    if (parsed.ok() && errors.empty() && m_loop) {
        const std::vector<core::ScenarioError> closedLoop =
            core::machine::validateClosedLoopScenario(parsed.scenario, *m_loop);
        const bool onlySetsSensors = std::all_of(closedLoop.begin(), closedLoop.end(), [](const core::ScenarioError& e) {
            return e.kind == core::ScenarioError::Kind::MachineSensor;
        });
        openLoop = !closedLoop.empty() && onlySetsSensors;
        errors = openLoop ? core::validateScenario(parsed.scenario, *m_simulator) : closedLoop;
    }
    if (!errors.empty()) {
        if (error)
            *error = scenarioErrorListText(errors);
        return false;
    }

    pause();
    stopReplay();
    m_replayOpenLoop = openLoop;
    // A scenario starts from the program's start state with every Complete automatic.
    resetSimulation();
    for (const std::string& step : m_simulator->nestedSteps()) {
        m_simulator->setCompleteMode(step, core::CompleteMode::Automatic);
        m_simulator->setComplete(step, false);
    }
    clearSession();
    m_scenario = std::make_unique<core::Scenario>(std::move(parsed.scenario));
    m_runner = makeRunner();
    m_replayFile = fileName;
    m_replayExpectations = static_cast<int>(std::count_if(m_scenario->actions.begin(), m_scenario->actions.end(),
                                                          [](const core::ScenarioAction& a) {
                                                              return a.isExpectation();
                                                          }));
    m_replayState = ReplayState::Running;
    emit wasReset();
    emit inputsChanged();
    emit replayChanged();
    emit stepped();
    return true;
}

std::int64_t SimulationSession::replayLength() const
{
    return m_scenario ? m_scenario->lastScan() : 0;
}

void SimulationSession::finishReplay()
{
    m_runner.reset();
    m_replayState = ReplayState::Finished;
    pause();
    emit replayChanged();
}

void SimulationSession::stopReplay()
{
    const bool changed = m_replayState != ReplayState::None;
    m_runner.reset();
    m_scenario.reset();
    m_replayFailures.clear();
    m_replayFile.clear();
    m_replayExpectations = 0;
    m_replayOpenLoop = false;
    m_replayState = ReplayState::None;
    if (changed)
        emit replayChanged();
}

const core::machine::MachineState* SimulationSession::machineState() const
{
    if (!m_loop)
        return nullptr;
    if (m_viewed)
        return m_history[*m_viewed].machine ? &m_history[*m_viewed].machine->machine : nullptr;
    return &m_loop->state();
}

void SimulationSession::setLinked(bool linked)
{
    if (linked == m_linked)
        return;
    if (linked) {
        pause();
        stopReplay();
    }
    m_linked = linked;
    if (isActive()) // leaving the simulation ends a link after the simulator is gone
        emit inputsChanged();
}

bool SimulationSession::isMachineDriven(int index) const
{
    if (!m_loop || m_linked || index < 0 || static_cast<std::size_t>(index) >= m_simulator->variableNames().size())
        return false;
    return m_loop->drivesVariable(m_simulator->variableNames()[static_cast<std::size_t>(index)]);
}

QString SimulationSession::machineOwner(int index) const
{
    if (!isMachineDriven(index))
        return {};
    const core::machine::Component* owner =
        m_loop->sensorOwner(m_simulator->variableNames()[static_cast<std::size_t>(index)]);
    return owner ? QString::fromStdString(owner->name) : QString();
}

bool SimulationSession::isClosedLoop() const
{
    return m_loop && !m_replayOpenLoop && !m_linked;
}

// An open-loop replay starts from the machine at rest too, but with the
// inputs at their defaults: the scenario sets the sensors.
void SimulationSession::resetSimulation()
{
    if (m_loop)
        m_loop->reset();
    if (!isClosedLoop())
        m_simulator->reset();
}

core::ScanRecord SimulationSession::runOneScan()
{
    return isClosedLoop() ? m_loop->step() : m_simulator->step();
}

std::unique_ptr<core::ScenarioRunner> SimulationSession::makeRunner()
{
    if (isClosedLoop())
        return std::make_unique<core::ScenarioRunner>(*m_scenario, *m_loop);
    return std::make_unique<core::ScenarioRunner>(*m_scenario, *m_simulator);
}

void SimulationSession::dropMachineInputs(std::vector<core::InputChange>& changes) const
{
    if (!m_loop)
        return;
    std::erase_if(changes, [this](const core::InputChange& change) { return m_loop->drivesVariable(change.variable); });
}

} // namespace editor
