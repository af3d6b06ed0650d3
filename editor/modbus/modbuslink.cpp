#include "editor/modbus/modbuslink.h"

#include "editor/modbus/mappedmodbusserver.h"

#include "core/simulation/simulator.h"

#include <QModbusReply>
#include <QModbusTcpClient>
#include <QModbusTcpConnectionObserver>
#include <QTcpSocket>
#include <QTimer>
#include <QUrl>
#include <QVariant>

#include <algorithm>

namespace modbus {

using core::modbusio::ModbusEntry;
using core::modbusio::ModbusTable;

namespace modbuslink {

// Counts the server's clients as they connect (QModbusTcpServer signals only
// their leaving).
class ClientCounter : public QModbusTcpConnectionObserver {
public:
    explicit ClientCounter(std::function<void(QTcpSocket*)> onAccept) : m_onAccept(std::move(onAccept)) {}
    bool acceptNewConnection(QTcpSocket* socket) override
    {
        m_onAccept(socket);
        return true;
    }

private:
    std::function<void(QTcpSocket*)> m_onAccept;
};

QString tableText(ModbusTable table)
{
    return QString::fromStdString(std::string(core::modbusio::modbusTableName(table)));
}

} // namespace modbuslink

ModbusScanHooks simulatorHooks(core::Simulator& simulator)
{
    ModbusScanHooks hooks;
    hooks.setInput = [&simulator](const std::string& variable, const core::cond::Value& value, QString* error) {
        const core::Status status = simulator.setVariable(variable, value);
        if (!status && error)
            *error = QString::fromStdString(status.message);
        return static_cast<bool>(status);
    };
    hooks.value = [&simulator](const std::string& variable) { return simulator.variable(variable); };
    hooks.scan = [&simulator] { simulator.step(); };
    return hooks;
}

bool parseHostPort(const QString& text, QString& host, int& port, QString& error)
{
    const qsizetype colon = text.lastIndexOf(QLatin1Char(':'));
    if (colon <= 0) {
        error = QStringLiteral("'%1': expected HOST:PORT (127.0.0.1:1502)").arg(text);
        return false;
    }
    bool ok = false;
    const int value = text.mid(colon + 1).toInt(&ok);
    if (!ok || value < 1 || value > 65535) {
        error = QStringLiteral("'%1': the port is not a number in 1..65535").arg(text);
        return false;
    }
    host = text.left(colon);
    if (host.startsWith(QLatin1Char('[')) && host.endsWith(QLatin1Char(']')))
        host = host.mid(1, host.size() - 2);
    port = value;
    return true;
}

ModbusLink::ModbusLink(ModbusLinkOptions options, ModbusScanHooks hooks, QObject* parent)
    : QObject(parent), m_options(std::move(options)), m_hooks(std::move(hooks)), m_timer(new QTimer(this))
{
    m_timer->setTimerType(Qt::PreciseTimer);
    m_timer->setSingleShot(true); // armed for each scan's due time (onTick)
    connect(m_timer, &QTimer::timeout, this, &ModbusLink::onTick);
}

ModbusLink::~ModbusLink()
{
    stop();
}

qint64 ModbusLink::elapsedMs() const
{
    return m_clock.isValid() ? m_clock.elapsed() : 0;
}

int ModbusLink::boundPort() const
{
    return m_options.port;
}

void ModbusLink::setState(State state)
{
    if (m_state == state)
        return;
    m_state = state;
    emit stateChanged();
}

void ModbusLink::report(const QString& message)
{
    m_lastError = message;
    ++m_errors;
    emit linkError(message);
}

bool ModbusLink::start(QString* error)
{
    stop();
    const std::vector<ModbusEntry>& entries = m_options.map.entries;
    m_applied.assign(entries.size(), {});
    m_received.assign(entries.size(), {});
    // The image starts from the simulator's values: defaults are not overwritten by zeros.
    for (std::size_t i = 0; i < entries.size(); ++i) {
        m_applied[i] = core::modbusio::encodeModbusValue(entries[i].type, m_hooks.value(entries[i].variable));
        m_received[i] = m_applied[i];
    }
    if (isServer()) {
        m_server = new MappedModbusServer(m_options.map, this);
        m_server->setConnectionParameter(QModbusDevice::NetworkAddressParameter, m_options.host);
        m_server->setConnectionParameter(QModbusDevice::NetworkPortParameter, m_options.port);
        m_server->setServerAddress(m_options.unitId);
        m_server->installConnectionObserver(new modbuslink::ClientCounter([this](QTcpSocket* socket) { // the server owns it
            m_sockets.emplace_back(socket);
            ++m_clients;
            emit clientsChanged(m_clients);
        }));
        connect(m_server, &QModbusTcpServer::modbusClientDisconnected, this, [this] {
            m_clients = std::max(0, m_clients - 1);
            emit clientsChanged(m_clients);
        });
        connect(m_server, &MappedModbusServer::writeRefused, this, &ModbusLink::report);
        for (std::size_t i = 0; i < entries.size(); ++i) {
            for (int w = 0; w < entries[i].width; ++w)
                m_server->setData(registerType(entries[i].table), static_cast<quint16>(entries[i].address + w),
                                  m_applied[i][static_cast<std::size_t>(w)]);
        }
        if (!m_server->connectDevice() || m_server->state() != QModbusDevice::ConnectedState) {
            const QString reason = tr("cannot listen on %1:%2: %3")
                                       .arg(m_options.host)
                                       .arg(m_options.port)
                                       .arg(m_server->errorString());
            if (error)
                *error = reason;
            delete m_server;
            m_server = nullptr;
            return false;
        }
        setState(State::Listening);
    } else {
        m_client = new QModbusTcpClient(this);
        m_client->setConnectionParameter(QModbusDevice::NetworkAddressParameter, m_options.host);
        m_client->setConnectionParameter(QModbusDevice::NetworkPortParameter, m_options.port);
        m_client->setTimeout(m_options.requestTimeoutMs);
        m_client->setNumberOfRetries(0);
        connect(m_client, &QModbusDevice::stateChanged, this, [this](QModbusDevice::State state) {
            if (state == QModbusDevice::ConnectedState)
                setState(State::Connected);
            else if (state == QModbusDevice::ConnectingState)
                setState(State::Connecting);
            else if (m_client)
                setState(State::Closed);
        });
        connect(m_client, &QModbusDevice::errorOccurred, this, [this](QModbusDevice::Error e) {
            if (e == QModbusDevice::ConnectionError && m_client)
                report(QStringLiteral("%1:%2: %3").arg(m_options.host).arg(m_options.port).arg(m_client->errorString()));
        });
        setState(State::Connecting);
        if (!m_client->connectDevice()) {
            const QString reason = tr("cannot connect to %1:%2: %3")
                                       .arg(m_options.host)
                                       .arg(m_options.port)
                                       .arg(m_client->errorString());
            if (error)
                *error = reason;
            delete m_client;
            m_client = nullptr;
            setState(State::Closed);
            return false;
        }
    }
    m_scans = 0;
    m_scheduled = 0;
    m_errors = 0;
    m_lastError.clear();
    m_pendingRequests = 0;
    m_clock.start();
    m_timer->start(m_options.cycleTimeMs);
    return true;
}

void ModbusLink::stop()
{
    m_timer->stop();
    if (m_server) {
        // Qt frees a connection's buffer when its socket is destroyed while
        // the server still lives (not when the server goes first): abort and
        // delete each first, so that none is left behind.
        for (const QPointer<QTcpSocket>& socket : m_sockets) {
            if (socket)
                socket->abort();
            delete socket.data();
        }
        m_sockets.clear();
        m_server->disconnectDevice();
        delete m_server;
        m_server = nullptr;
    }
    if (m_client) {
        QModbusTcpClient* client = m_client;
        m_client = nullptr; // its replies, finishing now, see the link stopped
        client->disconnectDevice();
        delete client;
    }
    if (m_clients != 0) {
        m_clients = 0;
        emit clientsChanged(0);
    }
    m_clock.invalidate();
    setState(State::Closed);
}

void ModbusLink::onTick()
{
    if (!m_clock.isValid() || m_options.cycleTimeMs <= 0)
        return;
    const std::int64_t due = m_clock.elapsed() / m_options.cycleTimeMs;
    std::int64_t owed = due - m_scheduled;
    if (owed > kMaxCatchUpScans) {
        m_scheduled += owed - kMaxCatchUpScans; // late time dropped: simulated time runs slower
        owed = kMaxCatchUpScans;
    }
    // A client that lost its twin tries again about once a second.
    if (m_client && m_client->state() == QModbusDevice::UnconnectedState && due % std::max<std::int64_t>(1, 1000 / m_options.cycleTimeMs) == 0 && owed > 0)
        m_client->connectDevice();
    for (std::int64_t i = 0; i < owed && m_clock.isValid(); ++i) {
        runCycle();
        ++m_scheduled;
    }
    // The next scan at its due time, not a timer period late: the latency a
    // twin sees is then the model's, plus the network's.
    if (m_clock.isValid()) {
        const qint64 next = (m_scheduled + 1) * m_options.cycleTimeMs - m_clock.elapsed();
        m_timer->start(static_cast<int>(std::clamp<qint64>(next, 0, m_options.cycleTimeMs)));
    }
}

void ModbusLink::runCycle()
{
    if (m_server)
        applyServerInputs();
    else
        applyClientInputs();
    m_hooks.scan();
    ++m_scans;
    if (m_server) {
        publishServerOutputs();
    } else {
        // Both only when the last cycle's requests are answered: a slow twin
        // never piles requests up.
        if (m_pendingRequests == 0) {
            sendClientWrites();
            sendClientReads();
        }
    }
    emit scanned(m_scans);
}

void ModbusLink::applyServerInputs()
{
    const std::vector<ModbusEntry>& entries = m_options.map.entries;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const ModbusEntry& entry = entries[i];
        if (entry.kind != core::VariableKind::Input)
            continue;
        std::vector<std::uint16_t> registers(static_cast<std::size_t>(entry.width));
        for (int w = 0; w < entry.width; ++w)
            m_server->data(registerType(entry.table), static_cast<quint16>(entry.address + w),
                           &registers[static_cast<std::size_t>(w)]);
        if (core::modbusio::isBitTable(entry.table))
            registers[0] = registers[0] != 0 ? 1 : 0;
        if (registers == m_applied[i])
            continue;
        m_applied[i] = registers;
        std::string problem;
        const std::optional<core::cond::Value> value = core::modbusio::decodeModbusValue(entry.type, registers.data(), problem);
        QString refusal;
        if (!value) {
            refusal = QString::fromStdString(problem);
        } else if (!m_hooks.setInput(entry.variable, *value, &refusal)) {
        } else {
            emit inputApplied(QString::fromStdString(entry.variable), QString::fromStdString(core::cond::formatValue(*value)));
            continue;
        }
        report(QStringLiteral("%1 %2 (%3): %4")
                   .arg(modbuslink::tableText(entry.table))
                   .arg(entry.address)
                   .arg(QString::fromStdString(entry.variable), refusal));
    }
}

void ModbusLink::publishServerOutputs()
{
    const std::vector<ModbusEntry>& entries = m_options.map.entries;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const ModbusEntry& entry = entries[i];
        if (entry.kind != core::VariableKind::Output)
            continue;
        std::vector<std::uint16_t> registers = core::modbusio::encodeModbusValue(entry.type, m_hooks.value(entry.variable));
        if (registers == m_applied[i])
            continue;
        for (int w = 0; w < entry.width; ++w)
            m_server->setData(registerType(entry.table), static_cast<quint16>(entry.address + w),
                              registers[static_cast<std::size_t>(w)]);
        m_applied[i] = std::move(registers);
    }
}

void ModbusLink::applyClientInputs()
{
    const std::vector<ModbusEntry>& entries = m_options.map.entries;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const ModbusEntry& entry = entries[i];
        if (entry.kind != core::VariableKind::Input || m_received[i] == m_applied[i])
            continue;
        m_applied[i] = m_received[i];
        std::string problem;
        const std::optional<core::cond::Value> value =
            core::modbusio::decodeModbusValue(entry.type, m_received[i].data(), problem);
        QString refusal;
        if (!value) {
            refusal = QString::fromStdString(problem);
        } else if (m_hooks.setInput(entry.variable, *value, &refusal)) {
            emit inputApplied(QString::fromStdString(entry.variable), QString::fromStdString(core::cond::formatValue(*value)));
            continue;
        }
        report(QStringLiteral("%1 %2 of %3:%4 (%5): %6")
                   .arg(modbuslink::tableText(entry.table))
                   .arg(entry.address)
                   .arg(m_options.host)
                   .arg(m_options.port)
                   .arg(QString::fromStdString(entry.variable), refusal));
    }
}

namespace modbuslink {

// Consecutive bits or registers of one table, at most one request's worth.
struct Run {
    ModbusTable table;
    int start = 0;
    int count = 0;
    std::vector<std::size_t> entries;
};

std::vector<Run> runsOf(const std::vector<ModbusEntry>& entries, core::VariableKind kind)
{
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        if (entries[i].kind == kind)
            order.push_back(i);
    }
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        if (entries[a].table != entries[b].table)
            return entries[a].table < entries[b].table;
        return entries[a].address < entries[b].address;
    });
    std::vector<Run> runs;
    for (std::size_t i : order) {
        const ModbusEntry& entry = entries[i];
        const int limit = core::modbusio::isBitTable(entry.table) ? 1968 : 123; // FC 15 and 16's largest
        if (!runs.empty() && runs.back().table == entry.table && runs.back().start + runs.back().count == entry.address
            && runs.back().count + entry.width <= limit) {
            runs.back().count += entry.width;
            runs.back().entries.push_back(i);
        } else {
            runs.push_back({entry.table, entry.address, entry.width, {i}});
        }
    }
    return runs;
}

} // namespace modbuslink

void ModbusLink::sendClientWrites()
{
    if (!m_client || m_client->state() != QModbusDevice::ConnectedState)
        return;
    const std::vector<ModbusEntry>& entries = m_options.map.entries;
    for (const modbuslink::Run& run : modbuslink::runsOf(entries, core::VariableKind::Output)) {
        QModbusDataUnit unit(registerType(run.table), run.start, static_cast<quint16>(run.count));
        for (std::size_t i : run.entries) {
            const std::vector<std::uint16_t> registers = core::modbusio::encodeModbusValue(entries[i].type, m_hooks.value(entries[i].variable));
            for (int w = 0; w < entries[i].width; ++w)
                unit.setValue(entries[i].address + w - run.start, registers[static_cast<std::size_t>(w)]);
        }
        QModbusReply* reply = m_client->sendWriteRequest(unit, m_options.unitId);
        const QString what = tr("write of %1 %2..%3 to %4:%5")
                                 .arg(modbuslink::tableText(run.table))
                                 .arg(run.start)
                                 .arg(run.start + run.count - 1)
                                 .arg(m_options.host)
                                 .arg(m_options.port);
        track(reply, what, {});
    }
}

// Counts the request until it finishes; a failure is reported (the scan
// keeps its last inputs), a success handed to `onSuccess`.
void ModbusLink::track(QModbusReply* reply, const QString& what, std::function<void(const QModbusReply&)> onSuccess)
{
    if (!reply) {
        report(what + QStringLiteral(": ") + m_client->errorString());
        return;
    }
    ++m_pendingRequests;
    connect(reply, &QModbusReply::finished, this, [this, reply, what, onSuccess = std::move(onSuccess)] {
        reply->deleteLater();
        m_pendingRequests = std::max(0, m_pendingRequests - 1);
        if (!m_client)
            return;
        if (reply->error() != QModbusDevice::NoError)
            report(what + QStringLiteral(": ") + reply->errorString());
        else if (onSuccess)
            onSuccess(*reply);
    });
}

void ModbusLink::sendClientReads()
{
    if (!m_client || m_client->state() != QModbusDevice::ConnectedState)
        return;
    const std::vector<ModbusEntry>& entries = m_options.map.entries;
    for (const modbuslink::Run& run : modbuslink::runsOf(entries, core::VariableKind::Input)) {
        QModbusReply* reply = m_client->sendReadRequest(
            QModbusDataUnit(registerType(run.table), run.start, static_cast<quint16>(run.count)), m_options.unitId);
        const QString what = tr("read of %1 %2..%3 from %4:%5")
                                 .arg(modbuslink::tableText(run.table))
                                 .arg(run.start)
                                 .arg(run.start + run.count - 1)
                                 .arg(m_options.host)
                                 .arg(m_options.port);
        track(reply, what, [this, run](const QModbusReply& answered) {
            const QModbusDataUnit unit = answered.result();
            for (std::size_t i : run.entries) {
                const ModbusEntry& entry = m_options.map.entries[i];
                for (int w = 0; w < entry.width; ++w) {
                    const qsizetype at = entry.address + w - unit.startAddress();
                    if (at >= 0 && at < unit.valueCount())
                        m_received[i][static_cast<std::size_t>(w)] =
                            core::modbusio::isBitTable(entry.table) ? (unit.value(at) != 0 ? 1 : 0) : unit.value(at);
                }
            }
        });
    }
}

} // namespace modbus
