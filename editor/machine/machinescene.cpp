#include "editor/machine/machinescene.h"

#include "editor/document.h"
#include "editor/machine/conveyoritem.h"
#include "editor/machine/cylinderitem.h"
#include "editor/machine/indicatoritem.h"
#include "editor/machine/machinelayout.h"
#include "editor/machine/operatoritem.h"
#include "editor/machine/partsourceitem.h"
#include "editor/simulation/simulationsession.h"

#include "core/condition/conditionevaluator.h"
#include "core/model/iectypes.h"

#include <string>

namespace editor {

namespace {

using core::machine::ComponentKind;

MachineComponentItem* makeItem(MachineScene& scene, std::size_t component, ComponentKind kind, const QRectF& cell)
{
    switch (kind) {
    case ComponentKind::DoubleActingCylinder:
    case ComponentKind::SingleActingCylinder: return new CylinderItem(scene, component, cell);
    case ComponentKind::Conveyor: return new ConveyorItem(scene, component, cell);
    case ComponentKind::PartSource: return new PartSourceItem(scene, component, cell);
    case ComponentKind::Lamp:
    case ComponentKind::DelayedSensor: return new IndicatorItem(scene, component, cell);
    case ComponentKind::PushButton:
    case ComponentKind::Selector:
    case ComponentKind::EmergencyStop: return new OperatorItem(scene, component, cell);
    }
    return nullptr;
}

} // namespace

MachineScene::MachineScene(Document* document, SimulationSession* session, QObject* parent)
    : QGraphicsScene(parent)
    , m_document(document)
    , m_session(session)
{
    connect(m_document, &Document::machineChanged, this, &MachineScene::rebuild);
    connect(m_document, &Document::modelReset, this, &MachineScene::rebuild);
    connect(m_session, &SimulationSession::activeChanged, this, &MachineScene::onActiveChanged);
    connect(m_session, &SimulationSession::stepped, this, &MachineScene::refresh);
    connect(m_session, &SimulationSession::inputsChanged, this, &MachineScene::refresh);
    connect(m_session, &SimulationSession::historyMoved, this, &MachineScene::refresh);
    rebuild();
    if (m_session->isActive())
        onActiveChanged(true);
}

MachineScene::~MachineScene() = default;

// The rest state: the machine's own reset, its signals in a table of its own.
void MachineScene::rebuild()
{
    m_live = false; // a new description: the session, running the old one, is ending
    m_machine = m_document->model().machine();
    std::vector<std::string> names;
    const auto wire = [&names](std::string_view name, core::machine::SignalDirection) {
        for (std::size_t i = 0; i < names.size(); ++i) {
            if (core::equalsIgnoreCase(names[i], name))
                return static_cast<int>(i);
        }
        names.emplace_back(name);
        return static_cast<int>(names.size() - 1);
    };
    m_rest = std::make_unique<core::machine::MachineState>(m_machine, m_document->model().settings().cycleTimeMs, wire);
    std::vector<char> restByName(names.size(), 0);
    const std::vector<core::machine::SignalSlot>& table = m_rest->signalSlots();
    for (std::size_t slot = 0; slot < table.size(); ++slot) {
        if (table[slot].direction != core::machine::SignalDirection::Actuator && table[slot].variable >= 0)
            restByName[static_cast<std::size_t>(table[slot].variable)] = m_rest->signal(slot) ? 1 : 0;
    }
    m_restValues.assign(m_machine.components.size(), {});
    for (std::size_t c = 0; c < m_machine.components.size(); ++c) {
        for (const std::string& variable : m_machine.components[c].wires)
        {
            const auto name = variable.empty() ? restByName.size() : static_cast<std::size_t>(wire(variable, {}));
            m_restValues[c].push_back(name < restByName.size() ? restByName[name] : 0);
        }
    }

    clear();
    m_items.clear();
    const std::vector<QRectF> cells = machinelayout::placeComponents(m_machine);
    for (std::size_t c = 0; c < m_machine.components.size(); ++c) {
        MachineComponentItem* item = makeItem(*this, c, m_machine.components[c].kind, cells[c]);
        addItem(item);
        m_items.push_back(item);
    }
    setSceneRect(itemsBoundingRect().adjusted(-machinelayout::kGap, -machinelayout::kGap, machinelayout::kGap,
                                              machinelayout::kGap));
    ++m_rebuilds;
    refresh();
}

void MachineScene::onActiveChanged(bool active)
{
    m_live = active && m_session->hasMachine();
    m_liveIndices.assign(m_machine.components.size(), {});
    if (m_live) {
        const core::Simulator& simulator = *m_session->liveSimulator();
        for (std::size_t c = 0; c < m_machine.components.size(); ++c) {
            for (const std::string& variable : m_machine.components[c].wires)
                m_liveIndices[c].push_back(variable.empty() ? -1 : simulator.variableIndex(variable));
        }
    }
    refresh();
}

bool MachineScene::showsSimulation() const
{
    return m_live && m_session->isActive() && m_session->machineState();
}

const core::machine::MachineState& MachineScene::state() const
{
    return showsSimulation() ? *m_session->machineState() : *m_rest;
}

int MachineScene::liveIndex(std::size_t component, std::size_t role) const
{
    const std::vector<int>& roles = m_liveIndices[component];
    return role < roles.size() ? roles[role] : -1;
}

bool MachineScene::signal(std::size_t component, std::size_t role) const
{
    if (!showsSimulation()) {
        const std::vector<char>& roles = m_restValues[component];
        return role < roles.size() && roles[role] != 0;
    }
    const int index = liveIndex(component, role);
    return index >= 0 && core::cond::isTrue(m_session->simulator()->variableValue(static_cast<std::size_t>(index)));
}

core::machine::SensorFault MachineScene::sensorFault(std::size_t component, std::size_t role) const
{
    if (!showsSimulation())
        return core::machine::SensorFault::None;
    return m_session->sensorFault(liveIndex(component, role));
}

bool MachineScene::jammed(std::size_t component) const
{
    return showsSimulation() && state().jammed(component);
}

MachineComponentItem* MachineScene::componentItem(const QString& name) const
{
    for (std::size_t c = 0; c < m_machine.components.size(); ++c) {
        if (QString::fromStdString(m_machine.components[c].name) == name)
            return m_items[c];
    }
    return nullptr;
}

void MachineScene::refresh()
{
    m_lastRepaints = 0;
    for (MachineComponentItem* item : m_items)
        m_lastRepaints += item->refresh() ? 1 : 0;
}

bool MachineScene::canOperate() const
{
    return showsSimulation() && m_session->isClosedLoop() && !m_session->isReplaying();
}

// A normally closed push button opens while pressed: FALSE, back to TRUE at the release.
void MachineScene::pressOperator(std::size_t component)
{
    if (!canOperate())
        return;
    const int index = liveIndex(component, core::machine::role::kOperatorInput);
    if (index < 0)
        return;
    const core::machine::Component& description = m_machine.components[component];
    const bool normallyClosed = description.contact == core::machine::Contact::NormallyClosed;
    if (description.kind != ComponentKind::PushButton)
        m_session->setVariable(index, !signal(component, core::machine::role::kOperatorInput));
    else if (normallyClosed)
        m_session->setVariable(index, false);
    else
        m_session->press(index);
}

void MachineScene::releaseOperator(std::size_t component)
{
    const core::machine::Component& description = m_machine.components[component];
    const int index = liveIndex(component, core::machine::role::kOperatorInput);
    if (!canOperate() || index < 0 || description.kind != ComponentKind::PushButton)
        return;
    if (description.contact == core::machine::Contact::NormallyClosed)
        m_session->setVariable(index, true);
    else
        m_session->release(index);
}

} // namespace editor
