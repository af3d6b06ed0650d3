#pragma once

// What the Modbus tests share (tests/modbus, tests/editor/test_modbusconnect):
// a free port on 127.0.0.1, a bounded wait for a reply, and a twin server
// shaped like the drilling cell's client map. 127.0.0.1 only.

#include <QModbusDataUnit>
#include <QModbusReply>
#include <QModbusTcpServer>
#include <QObject>
#include <QString>
#include <QTcpServer>
#include <QTest>

namespace modbustest {

// A port nothing listens on now (0 when none could be found).
inline int freePort()
{
    QTcpServer probe;
    if (!probe.listen(QHostAddress::LocalHost, 0))
        return 0;
    const int port = probe.serverPort();
    probe.close();
    return port;
}

// Waits at most 3 s for the reply, which `owner` then owns; nullptr when it
// was never sent or never finished.
inline QModbusReply* waitFor(QModbusReply* reply, QObject* owner)
{
    if (!reply)
        return nullptr;
    reply->setParent(owner);
    for (int i = 0; i < 300 && !reply->isFinished(); ++i)
        QTest::qWait(10);
    return reply->isFinished() ? reply : nullptr;
}

// The twin of client mode, as `simulate --print-modbus-map` gives the
// drilling cell's client map: discrete inputs 0..9 (the BOOL inputs), input
// register 0 (BatchSize), coils 0..8 (the outputs); unit 1 on 127.0.0.1:port.
inline bool startDrillingCellTwin(QModbusTcpServer& twin, int port)
{
    QModbusDataUnitMap tables;
    tables.insert(QModbusDataUnit::DiscreteInputs, QModbusDataUnit(QModbusDataUnit::DiscreteInputs, 0, 10));
    tables.insert(QModbusDataUnit::InputRegisters, QModbusDataUnit(QModbusDataUnit::InputRegisters, 0, 1));
    tables.insert(QModbusDataUnit::Coils, QModbusDataUnit(QModbusDataUnit::Coils, 0, 9));
    if (!twin.setMap(tables))
        return false;
    twin.setConnectionParameter(QModbusDevice::NetworkAddressParameter, QStringLiteral("127.0.0.1"));
    twin.setConnectionParameter(QModbusDevice::NetworkPortParameter, port);
    twin.setServerAddress(1);
    return twin.connectDevice();
}

} // namespace modbustest
