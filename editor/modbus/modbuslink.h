#pragma once

// The simulator's Modbus TCP link (docs/modbus.md): a Qt Core + Network +
// SerialBus library, without Widgets, shared by the editor and ggstudio-cli.
//
// The link owns the real-time scan clock. Every cycle time (the model's) it
// 1. applies the inputs the twin wrote since the last scan (server mode: the
//    coils and holding registers clients wrote; client mode: the last replies
//    to its reads of the twin's discrete inputs and input registers),
// 2. runs one scan through the hooks,
// 3. publishes the outputs (server mode: into its discrete inputs and input
//    registers; client mode: written to the twin's coils and holding
//    registers, then the next reads are sent).
// A single-shot precise timer is armed for each scan's due time (multiples
// of the cycle time since start()). A late tick catches up at most kMaxCatchUpScans scans; the rest of the late
// time is dropped (simulated time then runs slower than real time): the clock
// never spins.

#include "core/condition/conditionevaluator.h"
#include "core/link/modbusmap.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QString>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

class QModbusReply;
class QModbusTcpClient;
class QTcpSocket;
class QTimer;

namespace core {
class Simulator;
}

namespace modbus {

class MappedModbusServer;

// What the link drives: the simulator, or the editor's session around it.
struct ModbusScanHooks {
    // Sets an input (the name as the map spells it); false with a reason when refused.
    std::function<bool(const std::string& variable, const core::cond::Value& value, QString* error)> setInput;
    // The current value of a variable.
    std::function<core::cond::Value(const std::string& variable)> value;
    // Runs one scan.
    std::function<void()> scan;
};

// Hooks that drive a bare simulator (the command-line tool, the tests).
ModbusScanHooks simulatorHooks(core::Simulator& simulator);

struct ModbusLinkOptions {
    core::modbusio::ModbusMap map;          // its role says server or client
    QString host = QStringLiteral("127.0.0.1");
    int port = 1502;
    int unitId = 1;
    int cycleTimeMs = 20;
    int requestTimeoutMs = 1000;        // client mode: a reply later than this is an error
};

// "127.0.0.1:1502" → host and port; false with a message ("'x:99999': the port
// is not a number in 1..65535") when it does not read.
bool parseHostPort(const QString& text, QString& host, int& port, QString& error);

class ModbusLink : public QObject {
    Q_OBJECT

public:
    static constexpr int kMaxCatchUpScans = 4;

    enum class State { Closed, Listening, Connecting, Connected };

    ModbusLink(ModbusLinkOptions options, ModbusScanHooks hooks, QObject* parent = nullptr);
    ~ModbusLink() override;

    // Server mode: listens and starts the clock; false with `error` ("port
    // 1502 on 127.0.0.1: address in use") when it cannot listen. Client mode:
    // starts connecting (connected() or linkError() follow) and the clock.
    bool start(QString* error);
    void stop();

    State state() const { return m_state; }
    const ModbusLinkOptions& options() const { return m_options; }
    bool isServer() const { return m_options.map.role == core::modbusio::ModbusRole::Server; }
    int clientCount() const { return m_clients; }  // server mode
    std::int64_t scansRun() const { return m_scans; }
    qint64 elapsedMs() const;                      // since start()
    QString lastError() const { return m_lastError; }
    std::int64_t errorCount() const { return m_errors; }
    // The port listened on (server mode, after start()).
    int boundPort() const;

signals:
    void stateChanged();
    void clientsChanged(int count);
    // An input the twin changed was applied before a scan.
    void inputApplied(const QString& variable, const QString& value);
    // A problem that did not stop the link: a value refused, a request that
    // failed or timed out (client mode). The message names what and where.
    void linkError(const QString& message);
    // A scan ran (after its outputs were published).
    void scanned(std::int64_t scans);

private:
    void onTick();
    void runCycle();
    void applyServerInputs();
    void publishServerOutputs();
    void applyClientInputs();
    void sendClientWrites();
    void sendClientReads();
    void track(QModbusReply* reply, const QString& what, std::function<void(const QModbusReply&)> onSuccess);
    void report(const QString& message);
    void setState(State state);

    ModbusLinkOptions m_options;
    ModbusScanHooks m_hooks;
    QTimer* m_timer;
    QElapsedTimer m_clock;
    std::int64_t m_scans = 0;       // scans run since start()
    std::int64_t m_scheduled = 0;   // scans the clock has accounted for (run or dropped)
    State m_state = State::Closed;
    int m_clients = 0;
    QString m_lastError;
    std::int64_t m_errors = 0;

    MappedModbusServer* m_server = nullptr;
    std::vector<QPointer<QTcpSocket>> m_sockets; // server mode: the clients' sockets
    QModbusTcpClient* m_client = nullptr;
    // Client mode: the input registers (bits as 0/1) last read, by map entry
    // index; what was last applied, to apply only changes.
    std::vector<std::vector<std::uint16_t>> m_received;
    std::vector<std::vector<std::uint16_t>> m_applied;
    int m_pendingRequests = 0;
};

} // namespace modbus
