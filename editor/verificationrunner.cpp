#include "editor/verificationrunner.h"

#include "editor/document.h"
#include "editor/simulation/simulationsession.h"

#include "core/model/model.h"
#include "core/simulation/simulator.h"

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
    // The verifier polls `cancelled`, so the threads end soon.
    for (const Worker& worker : m_workers)
        worker.job->cancelled = true;
    for (const Worker& worker : m_workers) {
        worker.thread->wait();
        delete worker.thread;
    }
}

void VerificationRunner::start()
{
    const bool wasRunning = isRunning();
    if (wasRunning)
        m_current->cancelled = true;
    auto job = std::make_shared<Job>(m_document->model(), m_assumedAutomatic);
    job->exactTime = m_exactTime;
    m_current = job;
    m_wasCancelled = false;
    QThread* thread = QThread::create([job] { runJob(job); });
    thread->setObjectName(QStringLiteral("verification"));
    // Queued to this thread: the worker thread emits finished().
    connect(thread, &QThread::finished, this, [this, thread] { onThreadFinished(thread); });
    m_workers.push_back({thread, job});
    if (wasRunning)
        emit cancelled();
    thread->start(QThread::LowPriority);
    emit started();
}

void VerificationRunner::cancel()
{
    if (!isRunning())
        return;
    m_current->cancelled = true;
    m_current.reset();
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
        if (simulator->completeMode(step) == core::CompleteMode::Automatic)
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

void VerificationRunner::onThreadFinished(QThread* thread)
{
    const auto it = std::find_if(m_workers.begin(), m_workers.end(),
                                 [thread](const Worker& worker) { return worker.thread == thread; });
    if (it == m_workers.end())
        return;
    const std::shared_ptr<Job> job = it->job;
    m_workers.erase(it);
    thread->deleteLater();
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
