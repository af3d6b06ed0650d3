#pragma once

#include "core/verification.h"

#include <QObject>
#include <QString>

#include <memory>
#include <optional>
#include <vector>

class QThread;

namespace editor {

class Document;

// Runs core::verifyModel on a copy of the Document's model in a worker
// thread (a proof can take seconds; the window stays responsive) and keeps
// the last result. Starting again, or any change of the model, cancels a run
// under way; a change also marks the last result stale, since it describes
// a model that no longer is, until the next run.
//
// Every nested step's Complete is assumed free (any value at any scan): it
// covers whatever the user's nested behaviour does, so a "never" claim holds
// for every behaviour and a counterexample sets Complete as it needs.
class VerificationRunner : public QObject {
    Q_OBJECT

public:
    explicit VerificationRunner(Document* document, QObject* parent = nullptr);
    ~VerificationRunner() override;

    // Verifies the current model; a run under way is abandoned.
    void start();
    void cancel();
    bool isRunning() const { return m_current != nullptr; }

    bool hasResult() const { return m_result.has_value(); }
    // The last result; an empty one before the first run.
    const core::VerificationResult& result() const;
    // A finding of the last result, nullptr when out of range.
    const core::VerificationFinding* finding(int index) const;
    // The model changed since the last result was computed.
    bool isStale() const { return m_stale; }
    // Why the last run gave no result (out of memory...); empty otherwise.
    QString failure() const { return m_failure; }

signals:
    void started();
    // A run ended: result() is new, or failure() says why there is none.
    void finished();
    // A run was abandoned: the model changed, or the user started again.
    void cancelled();
    void staleChanged(bool stale);

private:
    struct Job;
    struct Worker {
        QThread* thread;
        std::shared_ptr<Job> job;
    };

    // In the worker thread.
    static void runJob(const std::shared_ptr<Job>& job);
    void onModelChanged();
    void onThreadFinished(QThread* thread);

    Document* m_document;
    std::shared_ptr<Job> m_current;   // the run whose result is wanted
    std::vector<Worker> m_workers;    // every thread not yet joined, abandoned ones included
    std::optional<core::VerificationResult> m_result;
    QString m_failure;
    bool m_stale = false;
};

} // namespace editor
