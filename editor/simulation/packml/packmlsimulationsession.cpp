#include "editor/simulation/packml/packmlsimulationsession.h"

#include "editor/document.h"
#include "editor/simulation/simulationpacing.h"
#include "editor/simulation/simulationtext.h"

#include "core/templates/packml/packtags.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QStringList>
#include <QTimer>

#include <algorithm>
#include <cmath>

namespace editor {

namespace {

using core::packml::PackmlScanRecord;

// The PackTags a request goes through (spec §6.3).
constexpr const char* kCommandNumberTag = "CntrlCmd";
constexpr const char* kCommandEdgeTag = "CmdChangeRequest";
constexpr const char* kModeNumberTag = "UnitMode";
constexpr const char* kModeEdgeTag = "UnitModeChangeRequest";

} // namespace

PackmlSimulationSession::PackmlSimulationSession(Document* document, QObject* parent)
    : QObject(parent)
    , m_document(document)
    , m_timer(new QTimer(this))
{
    Q_ASSERT(document);
    m_timer->setInterval(kTickMs);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &PackmlSimulationSession::onTick);

    // The simulator runs a copy of the program: any change of the model ends it.
    const auto end = [this] { setActive(false); };
    connect(m_document, &Document::modelReset, this, end);
    connect(m_document, &Document::variableChanged, this, end);
    connect(m_document, &Document::variablesChanged, this, end);
    connect(m_document, &Document::settingsChanged, this, end);
    connect(m_document, &Document::grafcetChanged, this, end);
    connect(m_document, &Document::packmlSettingsChanged, this, end);
    connect(m_document, &Document::commandChanged, this, end);
    connect(m_document, &Document::modesChanged, this, end);
    connect(m_document, &Document::modeChanged, this, end);
}

PackmlSimulationSession::~PackmlSimulationSession()
{
    m_runner.reset(); // refers to the scenario and the simulator
}

void PackmlSimulationSession::setActive(bool active)
{
    if (active == isActive())
        return;
    if (active) {
        if (!m_document->model().packml())
            return; // a GEMMA model: SimulationSession plays it
        m_simulator = std::make_unique<core::packml::PackmlSimulator>(m_document->model());
        clearSession();
        m_document->setReadOnly(true);
    } else {
        pause();
        stopReplay();
        m_simulator.reset();
        m_trace.clear();
        m_history.clear();
        m_viewed.reset();
        m_pending.reset();
        m_lastRequest.reset();
        m_document->setReadOnly(false);
    }
    emit activeChanged(active);
}

const core::packml::PackmlSimulator* PackmlSimulationSession::simulator() const
{
    if (m_viewed)
        return &m_history[*m_viewed].simulator;
    return m_simulator.get();
}

const PackmlScanRecord* PackmlSimulationSession::shownRecord() const
{
    if (m_history.empty())
        return nullptr;
    const Snapshot& shown = m_viewed ? m_history[*m_viewed] : m_history.back();
    return shown.record ? &*shown.record : nullptr;
}

bool PackmlSimulationSession::isRunning() const
{
    return m_timer->isActive();
}

void PackmlSimulationSession::run()
{
    if (!isActive() || isRunning())
        return;
    continueFromViewedScan();
    m_owedScans = 1; // the first scan comes with the first tick
    m_clock.start();
    m_timer->start();
    emit runningChanged(true);
}

void PackmlSimulationSession::pause()
{
    if (!isRunning())
        return;
    m_timer->stop();
    emit runningChanged(false);
}

void PackmlSimulationSession::stepOnce()
{
    advance(1);
}

void PackmlSimulationSession::reset()
{
    if (!isActive())
        return;
    pause();
    stopReplay();
    m_simulator->reset();
    clearSession();
    emit wasReset();
    emit inputsChanged();
    emit stepped();
}

void PackmlSimulationSession::clearSession()
{
    m_trace.clear();
    m_pending.reset();
    m_lastRequest.reset();
    m_commandTagTrue = false;
    m_modeTagTrue = false;
    const bool wasViewingHistory = isViewingHistory();
    m_viewed.reset();
    m_history.clear();
    keepSnapshot(std::nullopt); // scan 0: the start state
    if (wasViewingHistory)
        emit historyMoved();
}

void PackmlSimulationSession::setSpeed(int scansPerSecond)
{
    const int speed = std::clamp(scansPerSecond, kMinSpeed, kMaxSpeed);
    if (speed == m_speed)
        return;
    m_speed = speed;
    emit speedChanged(m_speed);
}

void PackmlSimulationSession::onTick()
{
    const double seconds = std::min(static_cast<double>(m_clock.nsecsElapsed()) / 1e9, simulationpacing::kMaxCatchUpSeconds);
    m_clock.restart();
    m_owedScans += seconds * m_speed;
    const double scans = std::floor(m_owedScans);
    m_owedScans -= scans;
    runScans(static_cast<std::int64_t>(scans), simulationpacing::kTickBudgetNs);
}

void PackmlSimulationSession::advance(std::int64_t scans)
{
    runScans(scans, -1);
}

bool PackmlSimulationSession::replayOver() const
{
    return m_runner && m_simulator->scanCount() >= m_scenario->lastScan();
}

void PackmlSimulationSession::runScans(std::int64_t scans, qint64 budgetNs)
{
    if (!isActive() || scans <= 0)
        return;
    continueFromViewedScan();
    QElapsedTimer clock;
    clock.start();
    std::int64_t ran = 0;
    for (; ran < scans && (budgetNs < 0 || ran == 0 || clock.nsecsElapsed() < budgetNs); ++ran) {
        // A division by zero stopped the program as it stops the PLC's task.
        if (m_simulator->fault()) {
            pause();
            break;
        }
        if (replayOver()) {
            finishReplay();
            break;
        }
        runOneScan();
    }
    if (replayOver())
        finishReplay();
    if (ran == 0)
        return;
    emit inputsChanged(); // a request read falls again; a replay sets inputs
    emit stepped();
}

void PackmlSimulationSession::runOneScan()
{
    const std::optional<RequestKind> raised = applyPendingRequest();
    const bool commandTag = requestTagTrue(RequestKind::Command);
    const bool modeTag = requestTagTrue(RequestKind::Mode);
    PackmlScanRecord record = m_runner ? m_runner->step() : m_simulator->scan();
    if (m_runner) {
        const auto& failures = m_runner->lastFailures();
        m_replayFailures.insert(m_replayFailures.end(), failures.begin(), failures.end());
    }
    // A request raised by a press is TRUE for the one scan that reads it.
    if (raised == RequestKind::Command)
        m_simulator->setInput(kCommandEdgeTag, false);
    if (raised == RequestKind::Mode)
        m_simulator->setInput(kModeEdgeTag, false);
    m_commandTagTrue = commandTag;
    m_modeTagTrue = modeTag;
    if (raised && m_lastRequest && !m_lastRequest->record)
        m_lastRequest->record = record;
    m_trace.push_back(record);
    if (m_trace.size() > static_cast<std::size_t>(kTraceCapacity))
        m_trace.pop_front();
    keepSnapshot(std::move(record));
}

bool PackmlSimulationSession::requestTagTrue(RequestKind kind) const
{
    const bool isCommand = kind == RequestKind::Command;
    if (m_simulator->value(isCommand ? kCommandEdgeTag : kModeEdgeTag) == std::optional<core::cond::Value>(true))
        return true;
    if (!m_runner)
        return false;
    const auto actionKind = isCommand ? core::ScenarioAction::Kind::Command : core::ScenarioAction::Kind::Mode;
    const std::int64_t next = m_simulator->scanCount() + 1;
    return std::any_of(m_scenario->actions.begin(), m_scenario->actions.end(),
                       [&](const core::ScenarioAction& action) { return action.scan == next && action.kind == actionKind; });
}

// Not when the same request tag was TRUE in the scan before (no edge then):
// the press waits a scan more.
std::optional<PackmlSimulationSession::RequestKind> PackmlSimulationSession::applyPendingRequest()
{
    if (!m_pending)
        return std::nullopt;
    const bool isCommand = m_pending->kind == RequestKind::Command;
    if (isCommand ? m_commandTagTrue : m_modeTagTrue)
        return std::nullopt;
    const std::string number = std::to_string(m_pending->number);
    m_simulator->setInputText(isCommand ? kCommandNumberTag : kModeNumberTag, number);
    m_simulator->setInput(isCommand ? kCommandEdgeTag : kModeEdgeTag, true);
    const RequestKind raised = m_pending->kind;
    m_pending.reset();
    return raised;
}

void PackmlSimulationSession::keepSnapshot(std::optional<PackmlScanRecord> record)
{
    m_history.push_back({*m_simulator, std::move(record), m_commandTagTrue, m_modeTagTrue});
    if (m_history.size() > static_cast<std::size_t>(kHistoryCapacity) + 1)
        m_history.pop_front();
}

bool PackmlSimulationSession::setInput(const QString& name, const core::cond::Value& value, QString* error)
{
    if (!isActive())
        return false;
    continueFromViewedScan();
    stopReplay();
    const core::Status status = m_simulator->setInput(name.toStdString(), value);
    if (!status) {
        if (error)
            *error = QString::fromStdString(status.message);
        return false;
    }
    emit inputsChanged();
    return true;
}

bool PackmlSimulationSession::setInputText(const QString& name, const QString& text, QString* error)
{
    if (!isActive())
        return false;
    continueFromViewedScan();
    stopReplay();
    const core::Status status = m_simulator->setInputText(name.toStdString(), text.toStdString());
    if (!status) {
        if (error)
            *error = QString::fromStdString(status.message);
        return false;
    }
    emit inputsChanged();
    return true;
}

bool PackmlSimulationSession::setManualComplete(int instance, std::optional<bool> complete, QString* error)
{
    if (!isActive())
        return false;
    continueFromViewedScan();
    stopReplay();
    const core::Status status = m_simulator->setManualComplete(instance, complete);
    if (!status) {
        if (error)
            *error = QString::fromStdString(status.message);
        return false;
    }
    emit inputsChanged();
    return true;
}

int PackmlSimulationSession::currentInstance() const
{
    const core::packml::PackmlSimulator* shown = simulator();
    if (!shown)
        return -1;
    const auto& instances = shown->program().instances;
    const core::packml::ProgramInstance* instance = shown->program().instance(shown->mode(), shown->state());
    return instance ? static_cast<int>(instance - instances.data()) : -1;
}

void PackmlSimulationSession::pressCommand(core::packml::Command command)
{
    if (!isActive())
        return;
    continueFromViewedScan();
    stopReplay();
    m_pending = Request{RequestKind::Command, static_cast<int>(command), std::nullopt};
    m_lastRequest = m_pending;
    emit inputsChanged();
}

void PackmlSimulationSession::requestMode(int mode)
{
    if (!isActive())
        return;
    continueFromViewedScan();
    stopReplay();
    m_pending = Request{RequestKind::Mode, mode, std::nullopt};
    m_lastRequest = m_pending;
    emit inputsChanged();
}

std::int64_t PackmlSimulationSession::viewedScan() const
{
    const core::packml::PackmlSimulator* shown = simulator();
    return shown ? shown->scanCount() : 0;
}

std::int64_t PackmlSimulationSession::latestScan() const
{
    return m_simulator ? m_simulator->scanCount() : 0;
}

std::int64_t PackmlSimulationSession::firstKeptScan() const
{
    return m_history.empty() ? latestScan() : m_history.front().simulator.scanCount();
}

bool PackmlSimulationSession::canStepBack() const
{
    return isActive() && viewedScan() > firstKeptScan();
}

bool PackmlSimulationSession::canStepForward() const
{
    return isActive() && isViewingHistory();
}

void PackmlSimulationSession::stepBack()
{
    if (canStepBack())
        showScan(viewedScan() - 1);
}

void PackmlSimulationSession::stepForward()
{
    if (canStepForward())
        showScan(viewedScan() + 1);
}

void PackmlSimulationSession::showScan(std::int64_t scan)
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
// from the history and the trace, and the simulator goes back to that
// scan. A replay goes on from there, its later failures dropped; a press
// or an input set there ends it (the callers stop it).
void PackmlSimulationSession::continueFromViewedScan()
{
    if (!m_viewed)
        return;
    m_history.erase(m_history.begin() + static_cast<std::ptrdiff_t>(*m_viewed) + 1, m_history.end());
    m_viewed.reset();
    // Assigned, not replaced: the replay's runner refers to this simulator.
    *m_simulator = m_history.back().simulator;
    m_commandTagTrue = m_history.back().commandTagTrue;
    m_modeTagTrue = m_history.back().modeTagTrue;
    m_pending.reset();
    const std::int64_t scan = m_simulator->scanCount();
    while (!m_trace.empty() && m_trace.back().scan > scan)
        m_trace.pop_back();
    if (m_lastRequest && (!m_lastRequest->record || m_lastRequest->record->scan > scan))
        m_lastRequest.reset();
    if (m_scenario) {
        std::erase_if(m_replayFailures, [scan](const core::packml::PackmlScenarioFailure& f) { return f.scan > scan; });
        if (scan < m_scenario->lastScan()) {
            m_runner = std::make_unique<core::packml::PackmlScenarioRunner>(*m_scenario, *m_simulator);
            m_replayState = ReplayState::Running;
        }
        emit replayChanged();
    }
    emit historyMoved();
}

bool PackmlSimulationSession::startReplay(const QString& path, QString* error)
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

bool PackmlSimulationSession::startReplayText(std::string_view text, const QString& fileName, QString* error)
{
    if (!isActive())
        return false;
    core::ScenarioParseResult parsed = core::parseScenario(text, fileName.toStdString());
    std::vector<core::ScenarioError> errors = parsed.errors;
    if (parsed.ok())
        errors = core::packml::validatePackmlScenario(parsed.scenario, *m_simulator);
    if (!errors.empty()) {
        if (error)
            *error = scenarioErrorListText(errors);
        return false;
    }
    pause();
    stopReplay();
    // A scenario starts from the start state with every SC from its skeleton.
    m_simulator->reset();
    for (std::size_t i = 0; i < m_simulator->program().instances.size(); ++i)
        if (m_simulator->manualComplete(static_cast<int>(i)))
            m_simulator->setManualComplete(static_cast<int>(i), std::nullopt);
    clearSession();
    m_scenario = std::make_unique<core::Scenario>(std::move(parsed.scenario));
    m_runner = std::make_unique<core::packml::PackmlScenarioRunner>(*m_scenario, *m_simulator);
    m_replayFile = fileName;
    m_replayExpectations = static_cast<int>(std::count_if(
        m_scenario->actions.begin(), m_scenario->actions.end(), [](const core::ScenarioAction& a) { return a.isExpectation(); }));
    m_replayState = ReplayState::Running;
    emit wasReset();
    emit inputsChanged();
    emit replayChanged();
    emit stepped();
    return true;
}

std::int64_t PackmlSimulationSession::replayLength() const
{
    return m_scenario ? m_scenario->lastScan() : 0;
}

void PackmlSimulationSession::finishReplay()
{
    m_runner.reset();
    pause();
    if (m_replayState == ReplayState::Running) {
        m_replayState = ReplayState::Finished;
        emit replayChanged();
    }
}

// The user takes over: the scenario is gone, its results with it.
void PackmlSimulationSession::stopReplay()
{
    m_runner.reset();
    const bool hadReplay = m_replayState != ReplayState::None;
    m_scenario.reset();
    m_replayState = ReplayState::None;
    m_replayFile.clear();
    m_replayExpectations = 0;
    m_replayFailures.clear();
    if (hadReplay)
        emit replayChanged();
}

} // namespace editor
