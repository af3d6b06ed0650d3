#pragma once

#include "core/machine/machineloop.h"
#include "core/simulation/scenario.h"
#include "core/simulation/simulator.h"

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

// The editor's simulation mode: a core::Simulator built from the Document's
// model when the mode starts, the inputs the user plays, and the trace.
// While active the Document is read-only; any change of the model (a file
// opened, a new model) ends the mode, since the simulator ran the old one.
//
// A timer drives the scans in batches on the GUI thread: every tick (about
// one frame) runs the scans owed at the chosen speed since the last tick and
// emits stepped() once, so 1,000 scans per second cost one UI update per
// frame, not 1,000. A tick stops its batch after a time budget, so a model
// whose scans are slow (a big GRAFCET under the search for stability) slows
// simulated time down instead of freezing the window (docs/design-notes.md).
//
// Everything the user does is kept from the last reset, so the session can
// be saved as a scenario file (the inputs and Complete settings of each
// scan, plus expectations for every transition that fired, every output
// that changed, every nested situation and Unstable that changed), and a
// scenario file can be replayed scan by scan, its expectations checked.
//
// The session also keeps the history of the run: a copy of the simulator
// after each of the latest kHistoryCapacity scans since reset (a copy shares
// the compiled program, so it is a few small vectors). stepBack() and
// stepForward() move the view through it: simulator() then returns the past
// scan's copy, so the chart, the dock's inputs, outputs, explanation and
// trace selection all show that scan. Playing from a past scan (a scan, Run,
// or an input changed) continues from it, like editing after an undo: the
// later history, trace and recording are dropped, so a saved scenario stays
// what was played. A replay played on from a past scan replays from there;
// an input changed there ends it.
//
// A model with a virtual machine runs in closed loop (docs/simulation.md,
// "The virtual machine"): through core::machine::MachineLoop, each scan is
// followed by one machine cycle whose sensors the next scan reads. The
// inputs the machine writes are not the user's (setVariable refuses them);
// the history keeps the machine's state and faults beside each simulator
// copy, and a reset or a replay resets both.
class SimulationSession : public QObject {
    Q_OBJECT

public:
    static constexpr int kMinSpeed = 1;      // scans per second
    static constexpr int kMaxSpeed = 10000;
    static constexpr int kDefaultSpeed = 10;
    static constexpr int kTickMs = 16;
    static constexpr int kTraceCapacity = 10000; // the trace keeps the latest scans
    // Expectations written for at most this many scans (firings, changed
    // outputs or nested situations): a session at 10,000 scans/s that fires
    // on most scans would otherwise grow without end.
    static constexpr int kRecordedScanCapacity = 100000;
    // Scans one can step back through (1,000 at 10,000 scans/s is a tenth
    // of a second; at 10 scans/s, 100 s).
    static constexpr int kHistoryCapacity = 1000;

    enum class ReplayState { None, Running, Finished };

    explicit SimulationSession(Document* document, QObject* parent = nullptr);
    ~SimulationSession() override;

    // The simulation mode: building the simulator and locking the Document.
    bool isActive() const { return m_simulator != nullptr; }
    void setActive(bool active);
    // The scan the user looks at: a past one while stepping through the
    // history, else the running simulator. nullptr while inactive.
    const core::Simulator* simulator() const;
    // The running simulator, whatever scan the view shows (nullptr while inactive).
    const core::Simulator* liveSimulator() const { return m_simulator.get(); }

    // Closed loop: whether the session runs the model's machine, and the
    // machine as it stands at the scan the view shows (nullptr while
    // inactive or without a machine).
    bool hasMachine() const { return m_loop != nullptr; }
    // Whether scans run the machine: with a machine, except while replaying
    // a scenario that sets the machine's sensors itself (replayIsOpenLoop()).
    bool isClosedLoop() const;
    const core::machine::MachineState* machineState() const;
    // Whether the machine writes this input (Simulator::variableNames()
    // index) at every cycle: a sensor, not the user's to set.
    bool isMachineDriven(int index) const;
    // The component whose sensor the input is; empty when none.
    QString machineOwner(int index) const;

    // Faults of the machine (docs/simulation.md, "Faults"), injected by the
    // user in closed loop before the next scan, as a scenario's `fault` line
    // is: a sensor's new reading shows at once, a jam holds from the next
    // machine cycle. Each goes into the recording, so a saved scenario
    // replays it. False with the reason when the fault does not apply to
    // the machine, or while a replay plays the inputs. Played from a past
    // scan, the later history is dropped first, like an input changed there.
    bool canInjectFault() const;
    bool injectFault(const core::machine::Fault& fault, QString* error = nullptr);
    // The fault of the input (Simulator::variableNames() index) at the scan shown.
    core::machine::SensorFault sensorFault(int index) const;

    // Linked to a digital twin over Modbus (editor/simulation/modbusconnection.h):
    // the twin drives the inputs, so the machine stands aside (no closed loop,
    // no input refused as the machine's); a run or replay is stopped.
    bool isLinked() const { return m_linked; }
    void setLinked(bool linked);

    bool isRunning() const;
    void run();
    void pause();
    void stepOnce();
    // Start state, inputs at their defaults, trace and recording cleared;
    // pauses and ends a replay. Complete settings are kept.
    void reset();
    // Runs up to `scans` scans as one batch and emits stepped() once when
    // any ran (a replay stops at its last scan). The timer calls it.
    void advance(std::int64_t scans);

    // History. The view shows a past scan until it is back at the latest.
    bool isViewingHistory() const { return m_viewed.has_value(); }
    std::int64_t viewedScan() const;         // scan number the view shows
    std::int64_t latestScan() const;         // scans run since reset
    std::int64_t firstKeptScan() const;      // the oldest scan one can go back to
    bool canStepBack() const;
    bool canStepForward() const;
    // Moves the view one scan back or ahead through the kept history;
    // pauses a run. Nothing happens at either end.
    void stepBack();
    void stepForward();
    // Shows the given scan, clamped to the kept history; pauses a run.
    void showScan(std::int64_t scan);

    int speed() const { return m_speed; }
    void setSpeed(int scansPerSecond); // clamped to kMinSpeed..kMaxSpeed

    // Inputs, by Simulator::variableNames() index. False with the reason
    // when the simulator refuses the value (wrong kind, out of range) or
    // the machine drives the input.
    bool setVariable(int index, const core::cond::Value& value, QString* error = nullptr);
    // A push button: TRUE from press() on. release() sets FALSE, but never
    // before a scan has read the TRUE: a press shorter than a scan is not lost.
    void press(int index);
    void release(int index);
    void setCompleteMode(const QString& stepId, core::CompleteMode mode);
    void setManualComplete(const QString& stepId, bool complete);

    // The latest scans since reset, oldest first (at most kTraceCapacity).
    const std::deque<core::ScanRecord>& trace() const { return m_trace; }
    // The transition that fired last up to the scan shown; empty when none has.
    QString lastFiredTransition() const;
    // Which token (Simulator::tokenNames() index) belongs to which transition.
    const std::vector<std::string>& tokenTransitions() const { return m_tokenTransitions; }

    // The session since the last reset, as the scenario writer takes it.
    core::ScenarioRecording recording() const;
    // Its scenario text: the recording, plus the step it ended in when it
    // ran on after the last change or firing.
    std::string recordingText() const;
    bool saveRecording(const QString& path, QString* error) const;

    // Reads, checks and starts a scenario from the start state (every
    // Complete automatic); run() or stepOnce() plays it. False with the
    // problems when the file cannot be read or does not fit the model.
    bool startReplay(const QString& path, QString* error);
    // The same from scenario text (a verification counterexample);
    // `fileName` names it in messages and in the Simulation dock.
    bool startReplayText(std::string_view text, const QString& fileName, QString* error);
    ReplayState replayState() const { return m_replayState; }
    // The replay sets the machine's sensors itself (an open-loop scenario,
    // a verification counterexample): it plays with the machine standing still.
    bool replayIsOpenLoop() const { return m_replayOpenLoop; }
    bool isReplaying() const { return m_replayState == ReplayState::Running; }
    QString replayFileName() const { return m_replayFile; }
    std::int64_t replayLength() const;
    int replayExpectationCount() const { return m_replayExpectations; }
    // Expectations that did not hold so far (kept after the replay finished).
    const std::vector<core::ScenarioFailure>& replayFailures() const { return m_replayFailures; }

signals:
    void activeChanged(bool active);
    void runningChanged(bool running);
    void speedChanged(int speed);
    // A batch of scans ran: state, trace and Complete outputs changed.
    void stepped();
    // Variables or Complete settings changed: by the user, a released
    // button, a reset or a replay.
    void inputsChanged();
    // The user chose a Complete mode (setCompleteMode), just before inputsChanged().
    void completeModeChosen(const QString& stepId);
    // Back to the start state: the trace was cleared.
    void wasReset();
    void replayChanged();
    // The view moved through the history, or came back to the latest scan.
    void historyMoved();

private:
    void onTick();
    // advance(), stopping after the first scan that ends past `budgetNs`
    // nanoseconds (no limit when negative).
    void runScans(std::int64_t scans, qint64 budgetNs);
    void onModelChanged();
    void clearSession();
    void afterScan(core::ScanRecord&& record);
    void keepSnapshot();
    // Before anything plays from a past scan or changes an input there: it
    // becomes the latest.
    enum class Continuation { Play, Edit };
    void continueFromViewedScan(Continuation how = Continuation::Play);
    void dropRecordingAfter(std::int64_t scan);
    void recordCompleteSettings(core::RecordedScan& changes);
    void finishReplay();
    void stopReplay();
    // The start state of the simulator, and of the machine in closed loop.
    void resetSimulation();
    core::ScanRecord runOneScan();
    // A runner for m_scenario, through the loop in closed loop.
    std::unique_ptr<core::ScenarioRunner> makeRunner();
    // Drops the inputs the machine wrote: a recording holds the operator's actions.
    void dropMachineInputs(std::vector<core::InputChange>& changes) const;
    std::optional<bool> completeSetting(const std::string& stepId) const;

    Document* m_document;
    std::unique_ptr<core::Simulator> m_simulator;
    std::unique_ptr<core::machine::MachineLoop> m_loop; // closed loop; refers to m_simulator
    QTimer* m_timer;
    QElapsedTimer m_clock;
    double m_owedScans = 0;
    int m_speed = kDefaultSpeed;

    std::deque<core::ScanRecord> m_trace;
    QString m_lastFired;
    std::vector<std::string> m_tokenTransitions;
    std::vector<int> m_pendingReleases;
    std::vector<std::int64_t> m_pressedAt; // scan count at press(), by variable index; -1 when not pressed
    std::vector<core::machine::Fault> m_pendingFaults; // injected since the last scan, for the recording

    // Recording since reset.
    std::vector<core::RecordedScan> m_changes;
    std::vector<core::ScanRecord> m_recorded; // the scans expectations are written for
    std::vector<std::optional<bool>> m_completeSettings; // last recorded, by nestedSteps() index

    // History: the simulator after each kept scan, oldest first (the first
    // entry after a reset is scan 0); the last one is the latest scan.
    struct Snapshot {
        core::Simulator simulator;
        QString lastFired; // since reset, up to this scan
        std::optional<core::machine::MachineLoop::Snapshot> machine; // closed loop only
    };
    std::deque<Snapshot> m_history;
    std::optional<std::size_t> m_viewed; // index into m_history of a past scan shown; empty: the latest

    // Replay.
    ReplayState m_replayState = ReplayState::None;
    QString m_replayFile;
    int m_replayExpectations = 0;
    bool m_replayOpenLoop = false;
    bool m_linked = false;
    std::unique_ptr<core::Scenario> m_scenario;
    std::unique_ptr<core::ScenarioRunner> m_runner;
    std::vector<core::ScenarioFailure> m_replayFailures;
};

} // namespace editor
