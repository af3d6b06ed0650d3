#include "editor/simulation/packml/packmlsimulationmarks.h"

#include "editor/chart/packml/packmlarrowitem.h"
#include "editor/chart/packml/packmlchartscene.h"
#include "editor/chart/packml/packmlstateitem.h"
#include "editor/simulation/packml/packmlsimulationsession.h"

namespace editor {

PackmlSimulationMarks::PackmlSimulationMarks(PackmlSimulationSession* session, PackmlChartScene* scene, QObject* parent)
    : QObject(parent)
    , m_session(session)
    , m_scene(scene)
{
    connect(m_session, &PackmlSimulationSession::activeChanged, this, &PackmlSimulationMarks::update);
    connect(m_session, &PackmlSimulationSession::stepped, this, &PackmlSimulationMarks::update);
    connect(m_session, &PackmlSimulationSession::historyMoved, this, &PackmlSimulationMarks::update);
    // Showing another mode re-reads the items; the marks stay on them.
    connect(m_scene, &PackmlChartScene::modeChanged, this, &PackmlSimulationMarks::update);
    update();
}

void PackmlSimulationMarks::clear()
{
    for (PackmlStateItem* state : m_scene->states())
        state->setActiveInSimulation(false);
    for (PackmlArrowItem* arrow : m_scene->transitions())
        arrow->setFired(false);
    for (auto command : {core::packml::Command::Stop, core::packml::Command::Abort})
        if (PackmlArrowItem* arrow = m_scene->frameArrowItem(command))
            arrow->setFired(false);
}

// The arrow of the transition the scan shown fired; nullptr when none did.
PackmlArrowItem* PackmlSimulationMarks::firedArrow() const
{
    const core::packml::PackmlScanRecord* record = m_session->shownRecord();
    if (!record || !record->fired)
        return nullptr;
    const core::packml::TemplateTransition& fired = record->fired->transition;
    if (PackmlArrowItem* arrow = m_scene->transitionItem(fired.source, fired.target))
        return arrow;
    // Stop and Abort leave every state of their frame by the frame's one arrow.
    if (fired.trigger == core::packml::Trigger::Command)
        return m_scene->frameArrowItem(fired.command);
    return nullptr;
}

void PackmlSimulationMarks::update()
{
    clear();
    const core::packml::PackmlSimulator* simulator = m_session->simulator();
    if (!simulator)
        return;
    if (m_scene->mode() != simulator->mode()) {
        m_scene->setMode(simulator->mode());
        if (m_scene->mode() == simulator->mode())
            return; // marked by the update modeChanged called
    }
    if (PackmlStateItem* state = m_scene->stateItem(simulator->state()))
        state->setActiveInSimulation(true);
    if (PackmlArrowItem* arrow = firedArrow())
        arrow->setFired(true);
}

} // namespace editor
