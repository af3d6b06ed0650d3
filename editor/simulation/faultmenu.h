#pragma once

// The context menus that inject faults into the running virtual machine
// (docs/simulation.md, "Faults"): right-click a sensor in the Simulation
// dock or on the Machine tab, or a cylinder or conveyor there. Each action
// goes through SimulationSession::injectFault, so the recording keeps it.

#include "core/machine/fault.h"

#include <QString>

class QMenu;
class QWidget;

namespace editor {

class SimulationSession;

// "stuck at TRUE", "stuck at FALSE", "flickering"; empty for None.
QString sensorFaultText(core::machine::SensorFault fault);
// The same in a narrow place (a role line of the Machine tab): "stuck TRUE".
QString sensorFaultShortText(core::machine::SensorFault fault);

// Stuck at TRUE, Stuck at FALSE, Flicker, and Clear Fault when the sensor
// has one; disabled when the session cannot take a fault now. A refused
// fault is told in a message box over `parent`.
void addSensorFaultActions(QMenu& menu, SimulationSession& session, const QString& sensor, QWidget* parent);
// Jam, or Clear Jam when the component is jammed.
void addJamActions(QMenu& menu, SimulationSession& session, const QString& component, bool jammed, QWidget* parent);

} // namespace editor
