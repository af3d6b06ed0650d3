#pragma once

#include "core/simulation/scenario.h"
#include "core/templates/packml/packmlscenario.h"
#include "core/templates/packml/packmlsimulator.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

class QTimer;

namespace editor {

class Document;

// The editor's simulation of a PackML model: a core::packml::PackmlSimulator
// built from the Document's model when the mode starts, the commands, mode
// requests and inputs the user plays, the trace, the history and the replay
// of a scenario. It has the shape of the GEMMA SimulationSession (run at a
// speed in batches of scans per timer tick, history of snapshots, replay)
// but drives another simulator, whose scans, inputs and scenarios differ;
// docs/packml.md ("Simulation in the editor") says why it is a class of its
// own. While active the Document is read-only; any change of the model ends
// the mode, since the simulator ran the old one.
//
// A command button or a mode request goes through the PackTags request as a
// scenario's `command` and `mode` lines do: CntrlCmd (UnitMode) is set and
// CmdChangeRequest (UnitModeChangeRequest) is TRUE for exactly one scan,
// FALSE again after it. A press after a scan in which the same request tag
// was TRUE (a press, by hand, a replay) waits a scan, so that the request
// can fall and rise again: no press is lost.
class PackmlSimulationSession : public QObject {
    Q_OBJECT

public:
    static constexpr int kMinSpeed = 1; // scans per second
    static constexpr int kMaxSpeed = 10000;
    static constexpr int kDefaultSpeed = 10;
    static constexpr int kTickMs = 16;
    static constexpr int kTraceCapacity = 10000; // the trace keeps the latest scans
    static constexpr int kHistoryCapacity = 1000; // scans one can step back through

    enum class ReplayState { None, Running, Finished };
    enum class RequestKind { Command, Mode };
    // A command pressed or a mode requested, and the scan that read it
    // (nullopt while it waits for its scan).
    struct Request {
        RequestKind kind = RequestKind::Command;
        int number = 0; // CntrlCmd, or the mode's number
        std::optional<core::packml::PackmlScanRecord> record;
    };

    explicit PackmlSimulationSession(Document* document, QObject* parent = nullptr);
    ~PackmlSimulationSession() override;

    bool isActive() const { return m_simulator != nullptr; }
    // Does nothing on a GEMMA model (SimulationSession plays those).
    void setActive(bool active);
    // The scan the user looks at: a past one while stepping through the
    // history, else the running simulator. nullptr while inactive.
    const core::packml::PackmlSimulator* simulator() const;
    const core::packml::PackmlSimulator* liveSimulator() const { return m_simulator.get(); }
    // What the scan shown did; nullptr at scan 0 (after a reset).
    const core::packml::PackmlScanRecord* shownRecord() const;

    bool isRunning() const;
    void run();
    void pause();
    void stepOnce();
    // Start state and mode, inputs at their defaults, trace and history
    // cleared; pauses and ends a replay.
    void reset();
    // Runs up to `scans` scans as one batch; stepped() once when any ran.
    void advance(std::int64_t scans);

    int speed() const { return m_speed; }
    void setSpeed(int scansPerSecond); // clamped to kMinSpeed..kMaxSpeed

    // Inputs: the user's input variables and the PackTags inputs. False with
    // the reason (English, from the simulator) when refused. Ends a replay.
    bool setInput(const QString& name, const core::cond::Value& value, QString* error = nullptr);
    bool setInputText(const QString& name, const QString& text, QString* error = nullptr);
    // The State Complete of an instance without GRAFCET set by hand (spec
    // §4's simulation aid, a scenario's `set complete`); nullopt gives the
    // skeleton's back. False with the reason (English) for an instance that
    // runs a GRAFCET. Ends a replay.
    bool setManualComplete(int instance, std::optional<bool> complete, QString* error = nullptr);
    // The instance of the current (mode, state) in the scan shown, an index
    // into PackmlProgram::instances; -1 for a wait state (no function block).
    int currentInstance() const;

    // One command or mode request for the next scan that can take it; a
    // second press before then replaces the first. Ends a replay.
    void pressCommand(core::packml::Command command);
    void requestMode(int mode);
    // The latest press, waiting or read by a scan; nullopt after a reset.
    const std::optional<Request>& lastRequest() const { return m_lastRequest; }

    // History. The view shows a past scan until it is back at the latest;
    // playing from a past scan continues from it and drops what followed.
    bool isViewingHistory() const { return m_viewed.has_value(); }
    std::int64_t viewedScan() const;
    std::int64_t latestScan() const;
    std::int64_t firstKeptScan() const;
    bool canStepBack() const;
    bool canStepForward() const;
    void stepBack();
    void stepForward();
    void showScan(std::int64_t scan); // clamped to the kept history; pauses a run

    // The latest scans since reset, oldest first (at most kTraceCapacity).
    const std::deque<core::packml::PackmlScanRecord>& trace() const { return m_trace; }

    // Reads, checks and starts a scenario from the start state; run() or
    // stepOnce() plays it. False with the problems (in the UI language)
    // when the file cannot be read or does not fit the model.
    bool startReplay(const QString& path, QString* error);
    bool startReplayText(std::string_view text, const QString& fileName, QString* error);
    ReplayState replayState() const { return m_replayState; }
    bool isReplaying() const { return m_replayState == ReplayState::Running; }
    QString replayFileName() const { return m_replayFile; }
    std::int64_t replayLength() const;
    int replayExpectationCount() const { return m_replayExpectations; }
    // Expectations that did not hold so far (kept after the replay finished).
    const std::vector<core::packml::PackmlScenarioFailure>& replayFailures() const { return m_replayFailures; }

signals:
    void activeChanged(bool active);
    void runningChanged(bool running);
    void speedChanged(int speed);
    // A batch of scans ran (or the start state came back after a reset).
    void stepped();
    // Inputs changed: by the user, a press read or released, a reset or a replay.
    void inputsChanged();
    void wasReset();
    void replayChanged();
    void historyMoved();

private:
    struct Snapshot {
        core::packml::PackmlSimulator simulator;
        std::optional<core::packml::PackmlScanRecord> record; // none for scan 0
        bool commandTagTrue = false; // CmdChangeRequest was TRUE in this scan
        bool modeTagTrue = false;    // UnitModeChangeRequest was TRUE in this scan
    };

    void onTick();
    void runScans(std::int64_t scans, qint64 budgetNs);
    void runOneScan();
    // Raises the request of the press waiting, if it can rise in this scan:
    // the kind raised, nullopt when none.
    std::optional<RequestKind> applyPendingRequest();
    // Is the request tag TRUE for the next scan: set so, or raised by the
    // replay's scenario in it?
    bool requestTagTrue(RequestKind kind) const;
    void clearSession();
    void keepSnapshot(std::optional<core::packml::PackmlScanRecord> record);
    void continueFromViewedScan();
    void finishReplay();
    void stopReplay();
    bool replayOver() const;

    Document* m_document;
    std::unique_ptr<core::packml::PackmlSimulator> m_simulator;
    QTimer* m_timer;
    QElapsedTimer m_clock;
    double m_owedScans = 0;
    int m_speed = kDefaultSpeed;

    std::deque<core::packml::PackmlScanRecord> m_trace;
    std::optional<Request> m_pending;     // waits for the next scan that can take it
    std::optional<Request> m_lastRequest; // the latest press, for the dock
    // The request tags were TRUE in the latest scan (by a press, by hand or
    // by a replay): a press waits a scan for the tag to fall first.
    bool m_commandTagTrue = false;
    bool m_modeTagTrue = false;

    std::deque<Snapshot> m_history; // oldest first; the last is the latest scan
    std::optional<std::size_t> m_viewed;

    ReplayState m_replayState = ReplayState::None;
    QString m_replayFile;
    int m_replayExpectations = 0;
    std::unique_ptr<core::Scenario> m_scenario;
    std::unique_ptr<core::packml::PackmlScenarioRunner> m_runner;
    std::vector<core::packml::PackmlScenarioFailure> m_replayFailures;
};

} // namespace editor
