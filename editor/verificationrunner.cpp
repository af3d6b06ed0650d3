#include "editor/verificationrunner.h"

#include "editor/document.h"
#include "editor/simulation/simulationsession.h"

#include "core/model/model.h"
#include "core/simulation/simulator.h"

#include <QDeadlineTimer>
#include <QThread>

#include <algorithm>
#include <atomic>
#include <exception>
#include <map>
#include <new>
#include <string>
#include <vector>

namespace editor {

// What one run shares with its thread: the thread only reads `model`,
// `complete` and `cancelled` and writes `result` or `failure`, which the GUI
// thread reads after the thread finished. `automatic` is the GUI thread's.
struct VerificationRunner::Job {
    Job(const core::Model& m, const QStringList& automaticSteps)
        : model(m)
        , automatic(automaticSteps)
    {
        for (const QString& step : automaticSteps)
            complete[step.toStdString()] = core::CompleteAssumption::Automatic;
    }

    core::Model model;
    QStringList automatic;
    std::map<std::string, core::CompleteAssumption> complete;
    bool exactTime = false;
    bool withMachine = false;
    bool singleFaults = false;
    std::chrono::milliseconds timeLimit{0};
    std::atomic<bool> cancelled{false};
    core::VerificationResult result;
    std::string failure;
};

VerificationRunner::VerificationRunner(Document* document, SimulationSession* session, QObject* parent)
    : QObject(parent)
    , m_document(document)
    , m_session(session)
{
    Q_ASSERT(document);
    connect(m_document, &Document::modelReset, this, &VerificationRunner::onModelChanged);
    connect(m_document, &Document::modelReplaced, this, &VerificationRunner::onModelReplaced);
    connect(m_document, &Document::stepChanged, this, &VerificationRunner::onModelChanged);
    connect(m_document, &Document::transitionChanged, this, &VerificationRunner::onModelChanged);
    connect(m_document, &Document::variableChanged, this, &VerificationRunner::onModelChanged);
    connect(m_document, &Document::variablesChanged, this, &VerificationRunner::onModelChanged);
    connect(m_document, &Document::settingsChanged, this, &VerificationRunner::onModelChanged);
    connect(m_document, &Document::grafcetChanged, this, &VerificationRunner::onModelChanged);
    connect(m_document, &Document::packmlSettingsChanged, this, &VerificationRunner::onModelChanged);
    connect(m_document, &Document::commandChanged, this, &VerificationRunner::onModelChanged);
    connect(m_document, &Document::modesChanged, this, &VerificationRunner::onModelChanged);
    connect(m_document, &Document::modeChanged, this, &VerificationRunner::onModelChanged);
    connect(m_document, &Document::machineChanged, this, &VerificationRunner::onModelChanged);
    if (m_session) {
        // Complete modes change with the user's choice, a reset or a replay,
        // each followed by inputsChanged(); they exist while the mode is active.
        connect(m_session, &SimulationSession::activeChanged, this, [this] { onSessionChanged(); });
        connect(m_session, &SimulationSession::inputsChanged, this, [this] { onSessionChanged(); });
        connect(m_session, &SimulationSession::completeModeChosen, this, [this] { onSessionChanged(true); });
    }
    m_assumedAutomatic = sessionAutomaticSteps();
}

VerificationRunner::~VerificationRunner()
{
    // A running QThread must not be destroyed: wait for the rest of the run
    // after a shutdown() that timed out. The verifier polls `cancelled`
    // inside its scans, so the thread ends soon. Nobody is told of the
    // cancel: the listeners may be going too.
    blockSignals(true);
    shutdown(-1);
}

bool VerificationRunner::shutdown(int timeoutMs)
{
    cancel();
    for (const Worker& worker : m_workers)
        worker.job->cancelled = true;
    QDeadlineTimer deadline = timeoutMs < 0 ? QDeadlineTimer(QDeadlineTimer::Forever) : QDeadlineTimer(timeoutMs);
    for (auto it = m_workers.begin(); it != m_workers.end();) {
        if (!it->thread->wait(deadline))
            return false;
        delete it->thread;
        it = m_workers.erase(it);
    }
    return true;
}

void VerificationRunner::start()
{
    const bool wasRunning = isRunning();
    if (wasRunning)
        m_current->cancelled = true;
    auto job = std::make_shared<Job>(m_document->model(), m_assumedAutomatic);
    job->exactTime = m_exactTime;
    job->withMachine = m_withMachine;
    job->singleFaults = m_singleFaults;
    job->timeLimit = m_timeLimit;
    m_current = job;
    m_wasCancelled = false;
    if (wasRunning)
        emit cancelled();
    // A run abandoned before it started is simply dropped; one still ending
    // is waited for.
    m_waiting.reset();
    if (m_workers.empty())
        launch(job);
    else
        m_waiting = job;
    emit started();
}

void VerificationRunner::launch(const std::shared_ptr<Job>& job)
{
    QThread* thread = QThread::create([job] { runJob(job); });
    thread->setObjectName(QStringLiteral("verification"));
    // Queued to this thread: the worker thread emits finished().
    // By its job, which the queued call keeps alive: a thread that
    // shutdown() already deleted cannot be taken for a new one at its address.
    connect(thread, &QThread::finished, this, [this, job] { onThreadFinished(job.get()); });
    m_workers.push_back({thread, job});
    thread->start(QThread::LowPriority);
}

void VerificationRunner::cancel()
{
    if (!isRunning())
        return;
    m_current->cancelled = true;
    m_current.reset();
    m_waiting.reset();
    m_wasCancelled = true;
    emit cancelled();
}

const core::VerificationResult& VerificationRunner::result() const
{
    static const core::VerificationResult empty;
    return m_result ? *m_result : empty;
}

const core::VerificationFinding* VerificationRunner::finding(int index) const
{
    const std::vector<core::VerificationFinding>& findings = result().findings;
    if (index < 0 || static_cast<std::size_t>(index) >= findings.size())
        return nullptr;
    return &findings[static_cast<std::size_t>(index)];
}

void VerificationRunner::onModelChanged()
{
    cancel();
    if (m_result && !m_stale) {
        m_stale = true;
        emit staleChanged(true);
    }
}

void VerificationRunner::onModelReplaced()
{
    cancel();
    const bool had = m_result.has_value() || !m_failure.isEmpty();
    m_result.reset();
    m_failure.clear();
    m_stale = false;
    m_wasCancelled = false;
    m_resultAutomatic.clear();
    m_currentWithAutomatic.clear();
    if (had)
        emit resultCleared();
}

bool VerificationRunner::completeAssumptionsDiffer() const
{
    return hasResult() && m_assumedAutomatic != m_resultAutomatic && m_assumedAutomatic != m_currentWithAutomatic;
}

QStringList VerificationRunner::sessionAutomaticSteps() const
{
    QStringList steps;
    // The settings the user plays with, not those of a past scan looked at.
    const core::Simulator* simulator = m_session ? m_session->liveSimulator() : nullptr;
    if (!simulator)
        return steps;
    for (const std::string& step : simulator->nestedSteps()) {
        // A step with a nested GRAFCET takes its Complete from it: no assumption applies.
        if (!simulator->hasGrafcet(step) && simulator->completeMode(step) == core::CompleteMode::Automatic)
            steps << QString::fromStdString(step);
    }
    return steps;
}

void VerificationRunner::setExactTime(bool exact)
{
    if (exact == m_exactTime)
        return;
    m_exactTime = exact;
    if (isRunning() && m_current->exactTime != m_exactTime)
        cancel();
    emit assumptionsChanged();
}

void VerificationRunner::setWithMachine(bool withMachine)
{
    if (withMachine == m_withMachine)
        return;
    m_withMachine = withMachine;
    if (isRunning() && m_current->withMachine != m_withMachine)
        cancel();
    emit assumptionsChanged();
}

void VerificationRunner::setSingleFaults(bool singleFaults)
{
    if (singleFaults == m_singleFaults)
        return;
    m_singleFaults = singleFaults;
    if (isRunning() && m_current->singleFaults != m_singleFaults)
        cancel();
    emit assumptionsChanged();
}

bool VerificationRunner::nextRunClosedLoop() const
{
    core::VerificationOptions options;
    options.closedLoop = m_withMachine;
    return core::runsClosedLoop(m_document->model(), options);
}

// Called for every input the user plays: only a change of the assumptions
// counts, and only the user's choice makes the last result outdated or
// abandons a run (which then finishes as current with the new settings).
void VerificationRunner::onSessionChanged(bool chosen)
{
    QStringList automatic = sessionAutomaticSteps();
    if (automatic == m_assumedAutomatic)
        return;
    if (!chosen && !completeAssumptionsDiffer())
        m_currentWithAutomatic = automatic;
    m_assumedAutomatic = std::move(automatic);
    if (chosen && isRunning() && m_current->automatic != m_assumedAutomatic)
        cancel();
    emit assumptionsChanged();
}

void VerificationRunner::onThreadFinished(const Job* finishedJob)
{
    const auto it = std::find_if(m_workers.begin(), m_workers.end(),
                                 [finishedJob](const Worker& worker) { return worker.job.get() == finishedJob; });
    if (it == m_workers.end())
        return; // joined by shutdown()
    QThread* thread = it->thread;
    const std::shared_ptr<Job> job = it->job;
    m_workers.erase(it);
    thread->deleteLater();
    if (m_waiting) {
        launch(m_waiting);
        m_waiting.reset();
    }
    if (job != m_current)
        return; // abandoned
    m_current.reset();
    if (job->result.cancelled)
        return; // cancel() already said so
    const bool wasStale = m_stale;
    if (job->failure.empty()) {
        m_result = std::move(job->result);
        m_resultAutomatic = job->automatic;
        // No choice of the user came since the run started (it would have
        // abandoned it): the result is current with today's settings too.
        m_currentWithAutomatic = m_assumedAutomatic;
        m_resultExactTime = job->exactTime;
        m_failure.clear();
        m_stale = false;
    } else {
        m_failure = QString::fromStdString(job->failure);
    }
    emit finished();
    if (wasStale != m_stale)
        emit staleChanged(m_stale);
}

void VerificationRunner::runJob(const std::shared_ptr<Job>& job)
{
    core::VerificationOptions options;
    options.complete = job->complete;
    options.exactTime = job->exactTime;
    options.closedLoop = job->withMachine;
    if (job->singleFaults)
        options.faults = core::VerificationOptions::Faults::Single;
    options.timeLimit = job->timeLimit;
    options.cancelled = [job] { return job->cancelled.load(std::memory_order_relaxed); };
    try {
        job->result = core::verifyModel(job->model, options);
    } catch (const std::bad_alloc&) {
        job->failure = "not enough memory";
    } catch (const std::exception& e) {
        job->failure = e.what();
    }
    if (job->cancelled)
        job->result.cancelled = true;
}

} // namespace editor
