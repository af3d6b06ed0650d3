#pragma once

#include <QObject>

namespace editor {

class ChartScene;
class SimulationSession;

// Shows the simulation on the chart: the active step filled, the transition
// that fired last in green, the Complete of each nested step as a badge,
// each token as a dot on its transition's bar, and the GRAFCET mark of the
// step whose nested GRAFCET runs highlighted (grafcetRuns()). Updated once per batch of
// scans; the marks go when the simulation mode ends.
class SimulationChartMarks : public QObject {
    Q_OBJECT

public:
    SimulationChartMarks(SimulationSession* session, ChartScene* scene, QObject* parent = nullptr);

    void update();

private:
    SimulationSession* m_session;
    ChartScene* m_scene;
};

} // namespace editor
