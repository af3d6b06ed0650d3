#pragma once

#include "core/verification/verification.h"

#include <QObject>
#include <QPointer>
#include <QString>
#include <QStringList>

#include <chrono>
#include <memory>
#include <optional>
#include <vector>

class QThread;

namespace editor {

class Document;
class SimulationSession;

// Runs core::verifyModel on a copy of the Document's model in a worker
// thread (a proof can take seconds; the window stays responsive) and keeps
// the last result. Starting again, or any change of the model, cancels a run
// under way; a change also marks the last result stale, since it describes
// a model that no longer is, until the next run.
//
// At most one worker computes at a time: a run started while an abandoned
// one is still ending (the verifier polls its cancel flag) waits for it, and
// a run started while another waits replaces it, so pressing F7 repeatedly
// never piles up threads. shutdown() cancels everything and joins the
// worker within a bounded time, for Quit.
//
// A nested step's Complete is assumed free (any value at any scan: it covers
// whatever the user's nested behaviour does) unless the simulation runs with
// that step's Complete automatic in the Simulation dock: then it is assumed
// automatic (TRUE at every scan, as the skeleton FB). A step set to manual
// stays free, since the user may set Complete at any time. A change of these
// assumptions, or of the way time is counted (exact time), like a change of
// the model, abandons a run under way; the last result keeps the assumptions
// it was computed with, so the window can tell that it no longer matches them.
// Only the user's choice of a Complete mode counts as such a change: the
// simulation starting or ending, a reset or a replay moves what the next run
// would assume, but changes none of the user's settings, so findings current
// before are current after. A new model (New, Open...) starts without result.
class VerificationRunner : public QObject {
    Q_OBJECT

public:
    // `session` may be null: every Complete is then free.
    VerificationRunner(Document* document, SimulationSession* session, QObject* parent = nullptr);
    ~VerificationRunner() override;

    // Verifies the current model; a run under way is abandoned.
    void start();
    void cancel();
    bool isRunning() const { return m_current != nullptr; }
    // Threads alive, the abandoned one still ending included: 0 or 1.
    int workerCount() const { return static_cast<int>(m_workers.size()); }
    // Cancels the run under way and any waiting one, then waits up to
    // `timeoutMs` for the worker to end. True when no worker is left.
    bool shutdown(int timeoutMs);

    bool hasResult() const { return m_result.has_value(); }
    // The last result; an empty one before the first run.
    const core::VerificationResult& result() const;
    // A finding of the last result, nullptr when out of range.
    const core::VerificationFinding* finding(int index) const;
    // The model changed since the last result was computed.
    bool isStale() const { return m_stale; }
    // Why the last run gave no result (out of memory...); empty otherwise.
    QString failure() const { return m_failure; }
    // The last run was abandoned (a change, not a new start), until the next start.
    bool wasCancelled() const { return m_wasCancelled; }

    // Whether the next runs count time in scans (every TON elapses exactly when
    // the PLC's would) instead of "may or may not have elapsed". A change
    // abandons a run under way and emits assumptionsChanged().
    void setExactTime(bool exact);
    bool exactTime() const { return m_exactTime; }
    // The same for the last result.
    bool resultExactTime() const { return m_resultExactTime; }

    // Whether the next runs explore the program with the model's machine
    // (closed loop, VerificationOptions::closedLoop) when it has one. A change
    // abandons a run under way and emits assumptionsChanged().
    void setWithMachine(bool withMachine);
    bool withMachine() const { return m_withMachine; }
    // Whether the next run would use a machine: asked for, and the model has one.
    bool nextRunClosedLoop() const;
    // Whether the last result was explored with the machine.
    bool resultClosedLoop() const { return hasResult() && m_result->closedLoop; }

    // Whether the next closed-loop runs also explore any single fault of the
    // machine (VerificationOptions::Faults::Single; docs/verification.md,
    // "Single faults (--faults single)"). Without the machine it has no
    // effect. A change abandons a run under way and emits assumptionsChanged().
    void setSingleFaults(bool singleFaults);
    bool singleFaults() const { return m_singleFaults; }
    // Whether the next run would explore single faults: asked for, in closed loop.
    bool nextRunSingleFaults() const { return m_singleFaults && nextRunClosedLoop(); }
    // Whether the last result was explored with single faults.
    bool resultSingleFaults() const { return hasResult() && m_result->singleFaults; }

    // How long the next runs may take before they stop, undecided where they
    // had to (GV100). Not an assumption: a change leaves a run under way and
    // the last result as they are.
    void setTimeLimit(std::chrono::milliseconds limit) { m_timeLimit = limit; }
    std::chrono::milliseconds timeLimit() const { return m_timeLimit; }

    // The nested steps whose Complete the next run assumes automatic, state order.
    QStringList assumedAutomatic() const { return m_assumedAutomatic; }
    // The same for the last result.
    QStringList resultAssumedAutomatic() const { return m_resultAutomatic; }
    // The last result was computed with other Complete assumptions, or another
    // way of counting time, than the next run would use. Its counterexamples
    // still fit the model (each is a run of it, replayed in the simulator), so
    // unlike isStale() this does not stop a replay.
    bool assumptionsDiffer() const
    {
        return completeAssumptionsDiffer() || timeCountingDiffers() || machineUseDiffers() || faultUseDiffers();
    }
    bool completeAssumptionsDiffer() const;
    bool timeCountingDiffers() const { return hasResult() && m_resultExactTime != m_exactTime; }
    bool machineUseDiffers() const { return hasResult() && resultClosedLoop() != nextRunClosedLoop(); }
    bool faultUseDiffers() const { return hasResult() && resultSingleFaults() != nextRunSingleFaults(); }

signals:
    void started();
    // A run ended: result() is new, or failure() says why there is none.
    void finished();
    // A run was abandoned: the model changed, or the user started again.
    void cancelled();
    void staleChanged(bool stale);
    // The result was dropped with the model it described (New, Open...).
    void resultCleared();
    // assumedAutomatic(), exactTime() or withMachine() changed (and with it maybe assumptionsDiffer()).
    void assumptionsChanged();

private:
    struct Job;
    struct Worker {
        QThread* thread;
        std::shared_ptr<Job> job;
    };

    // In the worker thread.
    static void runJob(const std::shared_ptr<Job>& job);
    void onModelChanged();
    void onModelReplaced();
    // `chosen`: the user chose a Complete mode; otherwise the simulation
    // started, ended or played a replay, which choose nothing.
    void onSessionChanged(bool chosen = false);
    QStringList sessionAutomaticSteps() const;
    void onThreadFinished(const Job* finishedJob);
    void launch(const std::shared_ptr<Job>& job);

    Document* m_document;
    QPointer<SimulationSession> m_session;
    std::shared_ptr<Job> m_current;   // the run whose result is wanted
    std::vector<Worker> m_workers;    // every thread not yet joined, an abandoned one included
    std::shared_ptr<Job> m_waiting;   // m_current, until the abandoned worker has ended
    std::optional<core::VerificationResult> m_result;
    QString m_failure;
    bool m_stale = false;
    bool m_wasCancelled = false;
    QStringList m_assumedAutomatic;
    // The Complete settings under which the last result counts as current:
    // what it assumed, moved along by the changes the user did not choose.
    QStringList m_currentWithAutomatic;
    bool m_exactTime = false;
    bool m_withMachine = false;
    bool m_singleFaults = false;
    std::chrono::milliseconds m_timeLimit = core::VerificationOptions().timeLimit;
    QStringList m_resultAutomatic;
    bool m_resultExactTime = false;
};

} // namespace editor
