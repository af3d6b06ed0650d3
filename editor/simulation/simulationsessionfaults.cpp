// SimulationSession's faults of the virtual machine (docs/simulation.md,
// "Faults"): what the Simulation dock's and the Machine tab's context menus
// inject, kept apart from the scan loop and the history.

#include "editor/simulation/simulationsession.h"

#include "editor/simulation/simulationtext.h"

namespace editor {

bool SimulationSession::canInjectFault() const
{
    return isActive() && isClosedLoop() && !isReplaying();
}

bool SimulationSession::injectFault(const core::machine::Fault& fault, QString* error)
{
    if (!canInjectFault()) {
        if (error) {
            *error = isReplaying() ? tr("The replay plays the machine's faults: stop it first")
                                   : tr("A fault needs the virtual machine running in closed loop");
        }
        return false;
    }
    if (const std::optional<core::machine::FaultRefusal> refusal = m_loop->checkFault(fault)) {
        if (error)
            *error = faultRefusalText(*refusal);
        return false;
    }
    continueFromViewedScan(Continuation::Edit);
    m_loop->applyFault(fault);
    m_pendingFaults.push_back(fault);
    emit inputsChanged();
    return true;
}

core::machine::SensorFault SimulationSession::sensorFault(int index) const
{
    // Linked to a twin, the machine stands aside: its faults do not show.
    if (!m_loop || m_linked || index < 0 || static_cast<std::size_t>(index) >= m_simulator->variableNames().size())
        return core::machine::SensorFault::None;
    const std::string& name = m_simulator->variableNames()[static_cast<std::size_t>(index)];
    if (m_viewed) {
        const std::optional<core::machine::MachineLoop::Snapshot>& then = m_history[*m_viewed].machine;
        return then ? m_loop->sensorFault(*then, name) : core::machine::SensorFault::None;
    }
    return m_loop->sensorFault(name);
}

} // namespace editor
