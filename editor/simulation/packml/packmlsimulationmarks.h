#pragma once

#include <QObject>

namespace editor {

class PackmlArrowItem;
class PackmlChartScene;
class PackmlSimulationSession;

// Shows a PackML simulation on the PackML chart: the chart shows the
// current unit mode (so a PackmlChartView's mode selector follows it), the
// current state is filled as the GEMMA chart fills its active step, and the
// transition the scan shown fired is drawn green (the Stop or Abort frame's
// arrow for those super-transitions). All of it for the scan the session
// shows, a past one while stepping through the history; the marks go when
// the simulation ends, the chart staying on the mode it showed last.
class PackmlSimulationMarks : public QObject {
    Q_OBJECT

public:
    PackmlSimulationMarks(PackmlSimulationSession* session, PackmlChartScene* scene, QObject* parent = nullptr);

    void update();

private:
    void clear();
    PackmlArrowItem* firedArrow() const;

    PackmlSimulationSession* m_session;
    PackmlChartScene* m_scene;
};

} // namespace editor
