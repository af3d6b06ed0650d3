#include "editor/simulation/modbusconnection.h"

#include "editor/simulation/simulationsession.h"

namespace editor {

ModbusConnection::ModbusConnection(SimulationSession* session, QObject* parent) : QObject(parent), m_session(session)
{
    connect(m_session, &SimulationSession::activeChanged, this, [this](bool active) {
        if (!active)
            disconnectLink();
    });
}

ModbusConnection::~ModbusConnection()
{
    m_link.reset();
}

bool ModbusConnection::connectLink(modbus::ModbusLinkOptions options, QString* error)
{
    disconnectLink();
    if (!m_session->isActive())
        m_session->setActive(true);
    if (!m_session->isActive()) {
        if (error)
            *error = tr("The simulation could not start.");
        return false;
    }
    m_session->setLinked(true);
    modbus::ModbusScanHooks hooks;
    hooks.setInput = [this](const std::string& variable, const core::cond::Value& value, QString* reason) {
        const core::Simulator* simulator = m_session->liveSimulator();
        const int index = simulator ? simulator->variableIndex(variable) : -1;
        return index >= 0 && m_session->setVariable(index, value, reason);
    };
    hooks.value = [this](const std::string& variable) {
        const core::Simulator* simulator = m_session->liveSimulator();
        return simulator ? simulator->variable(variable) : core::cond::Value(false);
    };
    hooks.scan = [this] { m_session->stepOnce(); };
    options.cycleTimeMs = m_session->liveSimulator()->cycleTimeMs();
    m_link = std::make_unique<modbus::ModbusLink>(std::move(options), std::move(hooks));
    connect(m_link.get(), &modbus::ModbusLink::stateChanged, this, &ModbusConnection::statusChanged);
    connect(m_link.get(), &modbus::ModbusLink::clientsChanged, this, &ModbusConnection::statusChanged);
    connect(m_link.get(), &modbus::ModbusLink::linkError, this, &ModbusConnection::statusChanged);
    connect(m_link.get(), &modbus::ModbusLink::inputApplied, this, [this](const QString& variable, const QString& value) {
        m_recentInputs.append(variable + QStringLiteral(" = ") + value);
        while (m_recentInputs.size() > kRecentInputs)
            m_recentInputs.removeFirst();
        emit statusChanged();
    });
    if (!m_link->start(error)) {
        m_link.reset();
        m_session->setLinked(false);
        return false;
    }
    m_recentInputs.clear();
    emit connectedChanged(true);
    emit statusChanged();
    return true;
}

void ModbusConnection::disconnectLink()
{
    if (!m_link)
        return;
    m_link->stop();
    m_link.reset();
    m_recentInputs.clear();
    m_session->setLinked(false);
    emit connectedChanged(false);
    emit statusChanged();
}

QString ModbusConnection::statusText() const
{
    if (!m_link)
        return {};
    const modbus::ModbusLinkOptions& options = m_link->options();
    const QString where = QStringLiteral("%1:%2").arg(options.host).arg(options.port);
    QString text;
    if (m_link->isServer()) {
        text = tr("Modbus server on %1, unit %2, clients connected: %3")
                   .arg(where)
                   .arg(options.unitId)
                   .arg(m_link->clientCount());
    } else {
        switch (m_link->state()) {
        case modbus::ModbusLink::State::Connected: text = tr("Modbus client of %1: connected").arg(where); break;
        case modbus::ModbusLink::State::Connecting: text = tr("Modbus client of %1: connecting").arg(where); break;
        default: text = tr("Modbus client of %1: not connected, trying again").arg(where); break;
        }
    }
    if (!m_recentInputs.isEmpty())
        text += QLatin1Char('\n') + tr("Set by the twin: %1").arg(m_recentInputs.join(QStringLiteral(", ")));
    if (m_link->errorCount() > 0)
        text += QLatin1Char('\n') + tr("Errors: %1, the last: %2").arg(m_link->errorCount()).arg(m_link->lastError());
    return text;
}

} // namespace editor
