#include "editor/simulation/faultmenu.h"

#include "editor/simulation/simulationsession.h"

#include <QAction>
#include <QCoreApplication>
#include <QMenu>
#include <QMessageBox>

namespace editor {

namespace {

struct FaultMenu {
    Q_DECLARE_TR_FUNCTIONS(FaultMenu)
};

void addFaultAction(QMenu& menu, const QString& text, SimulationSession& session, core::machine::Fault fault,
                    QWidget* parent)
{
    QAction* action = menu.addAction(text);
    action->setEnabled(session.canInjectFault());
    QObject::connect(action, &QAction::triggered, &menu, [&session, fault, parent] {
        QString error;
        if (!session.injectFault(fault, &error))
            QMessageBox::warning(parent, FaultMenu::tr("Fault not injected"), error);
    });
}

} // namespace

QString sensorFaultText(core::machine::SensorFault fault)
{
    using core::machine::SensorFault;
    switch (fault) {
    case SensorFault::None: return {};
    //: a fault of a sensor of the virtual machine, shown beside its value
    case SensorFault::StuckTrue: return FaultMenu::tr("stuck at TRUE");
    case SensorFault::StuckFalse: return FaultMenu::tr("stuck at FALSE");
    case SensorFault::Flicker: return FaultMenu::tr("flickering");
    }
    return {};
}

QString sensorFaultShortText(core::machine::SensorFault fault)
{
    using core::machine::SensorFault;
    switch (fault) {
    case SensorFault::None: return {};
    //: a sensor's fault where space is short (the Machine tab); TRUE and FALSE stay as they are
    case SensorFault::StuckTrue: return FaultMenu::tr("stuck TRUE");
    case SensorFault::StuckFalse: return FaultMenu::tr("stuck FALSE");
    case SensorFault::Flicker: return FaultMenu::tr("flicker");
    }
    return {};
}

void addSensorFaultActions(QMenu& menu, SimulationSession& session, const QString& sensor, QWidget* parent)
{
    using core::machine::FaultKind;
    const std::string target = sensor.toStdString();
    //: %1: a sensor variable of the virtual machine
    menu.addSection(FaultMenu::tr("Fault of %1").arg(sensor));
    addFaultAction(menu, FaultMenu::tr("Stuck at &TRUE"), session, {FaultKind::StuckTrue, target}, parent);
    addFaultAction(menu, FaultMenu::tr("Stuck at &FALSE"), session, {FaultKind::StuckFalse, target}, parent);
    addFaultAction(menu, FaultMenu::tr("F&licker"), session, {FaultKind::Flicker, target}, parent);
    const core::Simulator* simulator = session.liveSimulator();
    const int index = simulator ? simulator->variableIndex(target) : -1;
    if (session.sensorFault(index) != core::machine::SensorFault::None)
        addFaultAction(menu, FaultMenu::tr("&Clear Fault"), session, {FaultKind::Clear, target}, parent);
}

void addJamActions(QMenu& menu, SimulationSession& session, const QString& component, bool jammed, QWidget* parent)
{
    using core::machine::FaultKind;
    const std::string target = component.toStdString();
    //: %1: a cylinder or conveyor of the virtual machine
    menu.addSection(FaultMenu::tr("Fault of %1").arg(component));
    if (jammed)
        addFaultAction(menu, FaultMenu::tr("Clear &Jam"), session, {FaultKind::Clear, target}, parent);
    else
        addFaultAction(menu, FaultMenu::tr("&Jam"), session, {FaultKind::Jam, target}, parent);
}

} // namespace editor
