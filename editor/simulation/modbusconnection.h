#pragma once

// Simulation > Connect: the GEMMA simulation session linked to a digital twin
// over Modbus TCP (docs/modbus.md) through editor/modbus's ModbusLink. While
// connected the link's clock runs the session's scans in real time at the
// model's cycle time (Run and Single Scan wait), the twin drives the inputs
// (the virtual machine stands aside) and the Simulation dock shows the
// link's status. Everything is asynchronous: the GUI never waits on the network.

#include "editor/modbus/modbuslink.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <memory>

namespace editor {

class SimulationSession;

class ModbusConnection : public QObject {
    Q_OBJECT

public:
    static constexpr int kRecentInputs = 5; // inputs the status lists

    explicit ModbusConnection(SimulationSession* session, QObject* parent = nullptr);
    ~ModbusConnection() override;

    // Starts the simulation if needed, then the link; false with the reason
    // (the port in use) when it cannot start.
    bool connectLink(modbus::ModbusLinkOptions options, QString* error);
    void disconnectLink();
    bool isConnected() const { return m_link != nullptr; }
    const modbus::ModbusLink* link() const { return m_link.get(); }

    // One line for the Simulation dock: "Modbus server 127.0.0.1:1502: 1
    // client connected", the last error, the inputs the twin wrote last. Empty
    // while disconnected.
    QString statusText() const;

signals:
    void connectedChanged(bool connected);
    void statusChanged();

private:
    SimulationSession* m_session;
    std::unique_ptr<modbus::ModbusLink> m_link;
    QStringList m_recentInputs; // "StartButton = TRUE", latest last
};

} // namespace editor
