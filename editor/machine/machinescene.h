#pragma once

// The Machine tab's scene: a schematic of the model's virtual machine, one
// item per component in the cells of machinelayout.h. Outside the
// simulation it shows the machine at rest (cylinders retracted, parts on
// the conveyors' entries, operator inputs at their rest values); while
// simulating, the machine at the scan the session shows, so it follows the
// runs, the history and the replays. A scan only asks the items whose look
// changed to repaint; the items are rebuilt only when the description
// changes (docs/simulation.md, "The virtual machine").

#include "core/machine/fault.h"
#include "core/machine/machine.h"
#include "core/machine/machinestate.h"

#include <QGraphicsScene>

#include <memory>
#include <vector>

namespace editor {

class Document;
class MachineComponentItem;
class SimulationSession;

class MachineScene : public QGraphicsScene {
    Q_OBJECT

public:
    MachineScene(Document* document, SimulationSession* session, QObject* parent = nullptr);
    ~MachineScene() override;

    // The description drawn (the model's, as of the last rebuild).
    const core::machine::Machine& machine() const { return m_machine; }
    // The machine as shown: the session's at the scan in view, else at rest.
    const core::machine::MachineState& state() const;
    // Whether the items show the running simulation rather than the rest state.
    bool showsSimulation() const;
    // The value shown for a component's role; FALSE when unwired.
    bool signal(std::size_t component, std::size_t role) const;
    // The fault of a component's sensor role at the scan shown; None at rest.
    core::machine::SensorFault sensorFault(std::size_t component, std::size_t role) const;
    // Whether the component is jammed at the scan shown.
    bool jammed(std::size_t component) const;
    SimulationSession* session() const { return m_session; }

    std::size_t componentCount() const { return m_items.size(); }
    MachineComponentItem* componentItem(std::size_t component) const { return m_items[component]; }
    MachineComponentItem* componentItem(const QString& name) const;
    // Times the items were built (the benchmark checks a scan rebuilds nothing).
    int rebuildCount() const { return m_rebuilds; }
    // Items asked to repaint by the last refresh().
    int lastRepaintCount() const { return m_lastRepaints; }

    // Clicks on the operator's inputs, played through the session (so a
    // recording holds them): while simulating in closed loop, not replaying.
    bool canOperate() const;
    void pressOperator(std::size_t component);
    void releaseOperator(std::size_t component);

    // Repaints the items whose look changed.
    void refresh();

private:
    void rebuild();
    void onActiveChanged(bool active);
    int liveIndex(std::size_t component, std::size_t role) const;

    Document* m_document;
    SimulationSession* m_session;
    core::machine::Machine m_machine;
    std::unique_ptr<core::machine::MachineState> m_rest;
    std::vector<std::vector<char>> m_restValues;   // by component and role
    std::vector<std::vector<int>> m_liveIndices;   // the running simulator's variable indices; -1 unwired
    bool m_live = false; // the session runs this description
    std::vector<MachineComponentItem*> m_items;
    int m_rebuilds = 0;
    int m_lastRepaints = 0;
};

} // namespace editor
