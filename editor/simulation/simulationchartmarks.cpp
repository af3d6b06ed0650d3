#include "editor/simulation/simulationchartmarks.h"

#include "editor/chart/gemma/chartscene.h"
#include "editor/simulation/grafcetsimulationmarks.h"
#include "editor/simulation/simulationsession.h"
#include "editor/simulation/simulationtext.h"

#include <QHash>

namespace editor {

SimulationChartMarks::SimulationChartMarks(SimulationSession* session, ChartScene* scene, QObject* parent)
    : QObject(parent)
    , m_session(session)
    , m_scene(scene)
{
    connect(m_session, &SimulationSession::activeChanged, this, &SimulationChartMarks::update);
    connect(m_session, &SimulationSession::stepped, this, &SimulationChartMarks::update);
    connect(m_session, &SimulationSession::inputsChanged, this, &SimulationChartMarks::update);
    update();
}

void SimulationChartMarks::update()
{
    const core::Simulator* simulator = m_session->simulator();
    if (!simulator) {
        m_scene->clearSimulationMarks();
        return;
    }
    m_scene->setActiveStep(QString::fromStdString(simulator->activeStepId()));
    m_scene->setFiredTransition(m_session->lastFiredTransition());
    for (const std::string& step : simulator->nestedSteps()) {
        const QString id = QString::fromStdString(step);
        m_scene->setCompleteMark(id, simulator->complete(step));
        m_scene->setNestedRunning(id, grafcetRuns(*simulator, step)
                                          ? std::optional<QString>(stepNumbersText(simulator->activeNestedSteps(step)))
                                          : std::nullopt);
    }

    // Tokens grouped by transition, in tokenNames() order.
    QHash<QString, QList<bool>> tokens;
    const std::vector<bool> values = simulator->tokenValues();
    const std::vector<std::string>& owners = m_session->tokenTransitions();
    for (std::size_t i = 0; i < values.size() && i < owners.size(); ++i)
        tokens[QString::fromStdString(owners[i])] << values[i];
    for (auto it = tokens.cbegin(); it != tokens.cend(); ++it)
        m_scene->setTokenMarks(it.key(), it.value());
}

} // namespace editor
