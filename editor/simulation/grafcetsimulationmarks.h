#pragma once

#include <QHash>
#include <QObject>
#include <QString>

#include <functional>
#include <string_view>
#include <vector>

namespace core {
class NestedEngine;
class Simulator;
} // namespace core

namespace editor {

class GrafcetMarkLabelItem;
class GrafcetScene;
class SimulationSession;

// Whether the nested GRAFCET of `stepId` runs in the scan the simulator
// shows: its GEMMA step is the active one and its function block has been
// called since the step was entered (Entry is FALSE). In the scan that
// enters the step the FB has not run yet: its GRAFCET still stands as it
// was left, and starts from its initial steps in the next scan.
bool grafcetRuns(const core::Simulator& simulator, std::string_view stepId);

// What the marks show of one nested GRAFCET in the scan the session shows,
// from whichever simulator runs it (GEMMA's, or PackML's instances).
struct GrafcetSimulationSnapshot {
    const core::NestedEngine* engine = nullptr; // nullptr: nothing to mark (no simulation)
    bool runs = false;        // its function block has run since its owner was entered
    bool justEntered = false; // its owner was entered in that scan: it runs from the next one
    bool resumes = false;     // ...and goes on where it was paused (PackML's Execute)
    std::vector<int> fired;   // its transitions fired in that scan
    QString owner;            // how the caption names its owner: "F1", "Production_Execute"
};
using GrafcetSimulationSource = std::function<GrafcetSimulationSnapshot()>;

// Shows the simulation on the tab of one nested GRAFCET, as
// SimulationChartMarks does on the GEMMA chart, for the scan the session
// shows (the latest, or a past one of the history):
// - while its GRAFCET runs (grafcetRuns): each active step filled with the
//   IEC 60848 token in it, the transitions fired in the last scan with
//   their links in the chart's fired colour, the elapsed and preset time of
//   each timer of an active step under the receptivities that read it, and
//   every continuous action whose output the last call emitted lit;
// - otherwise its frozen situation, the steps its GRAFCET was left in,
//   greyed;
// - a caption above the drawing saying which of the two it is, and
//   Unstable when the last call found no stable situation.
// Updated once per batch of scans and whenever the view moves through the
// history; built at once for a tab opened during the simulation; every mark
// goes when the simulation mode ends. Lives as long as its scene (its parent).
class GrafcetSimulationMarks : public QObject {
    Q_OBJECT

public:
    enum class State { Off, Running, Frozen };

    GrafcetSimulationMarks(SimulationSession* session, GrafcetScene* scene, QObject* parent = nullptr);
    // Marks from another source; whoever makes it calls update() when the
    // scan shown changes (PackmlGrafcetMarks does for PackML).
    GrafcetSimulationMarks(GrafcetSimulationSource source, GrafcetScene* scene, QObject* parent = nullptr);

    State state() const { return m_state; }
    // The caption's text; empty while the simulation is off.
    QString captionText() const;

    void update();

private:
    void clear();
    void setCaption(const QString& text, bool warning);
    void forgetItems(); // the scene built its items again
    void showTimers(const core::NestedEngine& engine);

    GrafcetSimulationSource m_source;
    GrafcetScene* m_scene;
    State m_state = State::Off;
    GrafcetMarkLabelItem* m_caption = nullptr;
    QHash<int, GrafcetMarkLabelItem*> m_timers; // by transition number
};

} // namespace editor
