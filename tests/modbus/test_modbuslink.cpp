// The simulator as a Modbus TCP server and client (editor/modbus), on
// 127.0.0.1 only: a QModbusTcpClient writes inputs and reads outputs, raw
// sockets send bad frames and floods, a QModbusTcpServer plays the twin of
// client mode. Every wait is bounded.

#include "modbustestsupport.h"

#include "core/formats/modelfiles.h"
#include "core/link/modbusmap.h"
#include "core/simulation/simulator.h"
#include "editor/modbus/mappedmodbusserver.h"
#include "editor/modbus/modbuslink.h"

#include <QModbusReply>
#include <QModbusTcpClient>
#include <QModbusTcpServer>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QtEndian>
#include <QTest>

#include <memory>

using core::modbusio::ModbusRole;
using modbus::ModbusLink;

namespace test_modbuslink {

using modbustest::freePort;

std::unique_ptr<core::Model> drillingCell()
{
    core::LoadedModel loaded = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    return std::move(loaded.model);
}

// A Modbus request/response frame: MBAP header (transaction, protocol 0,
// length, unit) then the PDU.
QByteArray frame(quint16 transaction, quint8 unit, const QByteArray& pdu)
{
    QByteArray bytes(7, '\0');
    qToBigEndian<quint16>(transaction, bytes.data());
    qToBigEndian<quint16>(0, bytes.data() + 2);
    qToBigEndian<quint16>(static_cast<quint16>(pdu.size() + 1), bytes.data() + 4);
    bytes[6] = static_cast<char>(unit);
    return bytes + pdu;
}

// The exception code of a reply (0 when it is not an exception), read from
// its bytes: QModbusPdu's inline accessors trip UBSan on exception codes.
int exceptionOf(const QModbusReply* reply)
{
    const QByteArray bytes = modbus::pduBytes(reply->rawResult());
    return bytes.size() >= 2 && (static_cast<quint8>(bytes.at(0)) & 0x80) ? static_cast<quint8>(bytes.at(1)) : 0;
}

} // namespace test_modbuslink

using namespace test_modbuslink;

class TestModbusLink : public QObject {
    Q_OBJECT

private slots:
    void init();
    void cleanup();
    void hostPortParses();
    void coilDrivesDiscreteInputAfterAScan();
    void registerRoundTrip();
    void valueOutOfRangeIsRefused();
    void unmappedAddressGetsException02();
    void unsupportedFunctionGetsException01();
    void portInUseIsReported();
    void badFramesAndVanishingClients();
    void floodLeavesServerAndClockWorking();
    void clientModeDrivesATwin();

private:
    // Starts the simulator's server on a free port; false when it cannot.
    bool startServer(const core::modbusio::ModbusMap* map = nullptr);
    bool connectClient();
    // Sends and waits (bounded) for the reply; nullptr when none came.
    QModbusReply* wait(QModbusReply* reply);

    std::unique_ptr<core::Model> m_model;
    std::unique_ptr<core::Simulator> m_simulator;
    std::unique_ptr<ModbusLink> m_link;
    std::unique_ptr<QModbusTcpClient> m_client;
    int m_port = 0;
};

void TestModbusLink::init()
{
    m_model = drillingCell();
    QVERIFY(m_model);
    m_simulator = std::make_unique<core::Simulator>(*m_model);
}

void TestModbusLink::cleanup()
{
    if (m_client)
        m_client->disconnectDevice();
    m_client.reset();
    m_link.reset();
    m_simulator.reset();
    m_model.reset();
}

bool TestModbusLink::startServer(const core::modbusio::ModbusMap* map)
{
    m_port = freePort();
    modbus::ModbusLinkOptions options;
    options.map = map ? *map : core::modbusio::defaultModbusMap(m_model->variables(), ModbusRole::Server);
    options.port = m_port;
    options.cycleTimeMs = m_simulator->cycleTimeMs();
    m_link = std::make_unique<ModbusLink>(options, modbus::simulatorHooks(*m_simulator));
    QString error;
    const bool started = m_link->start(&error);
    if (!started)
        qWarning() << error;
    return started && m_link->state() == ModbusLink::State::Listening;
}

bool TestModbusLink::connectClient()
{
    m_client = std::make_unique<QModbusTcpClient>();
    m_client->setConnectionParameter(QModbusDevice::NetworkAddressParameter, QStringLiteral("127.0.0.1"));
    m_client->setConnectionParameter(QModbusDevice::NetworkPortParameter, m_port);
    m_client->setTimeout(2000);
    m_client->setNumberOfRetries(0);
    if (!m_client->connectDevice())
        return false;
    for (int i = 0; i < 200 && m_client->state() != QModbusDevice::ConnectedState; ++i)
        QTest::qWait(10);
    return m_client->state() == QModbusDevice::ConnectedState;
}

QModbusReply* TestModbusLink::wait(QModbusReply* reply)
{
    return modbustest::waitFor(reply, this);
}

void TestModbusLink::hostPortParses()
{
    QString host;
    int port = 0;
    QString error;
    QVERIFY(modbus::parseHostPort(QStringLiteral("127.0.0.1:1502"), host, port, error));
    QCOMPARE(host, QStringLiteral("127.0.0.1"));
    QCOMPARE(port, 1502);
    QVERIFY(modbus::parseHostPort(QStringLiteral("[::1]:502"), host, port, error));
    QCOMPARE(host, QStringLiteral("::1"));
    QVERIFY(!modbus::parseHostPort(QStringLiteral("127.0.0.1"), host, port, error));
    QCOMPARE(error, QStringLiteral("'127.0.0.1': expected HOST:PORT (127.0.0.1:1502)"));
    QVERIFY(!modbus::parseHostPort(QStringLiteral("localhost:99999"), host, port, error));
    QCOMPARE(error, QStringLiteral("'localhost:99999': the port is not a number in 1..65535"));
    QVERIFY(!modbus::parseHostPort(QStringLiteral("localhost:x"), host, port, error));
}

void TestModbusLink::coilDrivesDiscreteInputAfterAScan()
{
    QVERIFY(startServer());
    QVERIFY(connectClient());
    const core::modbusio::ModbusMap map = core::modbusio::defaultModbusMap(m_model->variables(), ModbusRole::Server);
    const int start = map.find("StartButton")->address;
    const int spindle = map.find("Spindle")->address;
    // Spindle is off before the start.
    QModbusReply* before = wait(m_client->sendReadRequest(QModbusDataUnit(QModbusDataUnit::DiscreteInputs, spindle, 1), 1));
    QVERIFY(before);
    QCOMPARE(before->error(), QModbusDevice::NoError);
    QCOMPARE(before->result().value(0), quint16(0));
    // EmergencyOk's default TRUE is in its coil from the start.
    QModbusReply* emergency = wait(m_client->sendReadRequest(QModbusDataUnit(QModbusDataUnit::Coils, map.find("EmergencyOk")->address, 1), 1));
    QVERIFY(emergency);
    QCOMPARE(emergency->result().value(0), quint16(1));

    // The machine's rest position, as its sensors say (no virtual machine while linked).
    for (const char* sensor : {"Unclamped", "DrillHigh"}) {
        QModbusDataUnit rest(QModbusDataUnit::Coils, map.find(sensor)->address, 1);
        rest.setValue(0, 1);
        QModbusReply* reply = wait(m_client->sendWriteRequest(rest, 1));
        QVERIFY(reply);
        QCOMPARE(reply->error(), QModbusDevice::NoError);
    }
    QModbusDataUnit press(QModbusDataUnit::Coils, start, 1);
    press.setValue(0, 1);
    QModbusReply* written = wait(m_client->sendWriteRequest(press, 1));
    QVERIFY(written);
    QCOMPARE(written->error(), QModbusDevice::NoError);
    bool on = false;
    for (int i = 0; i < 100 && !on; ++i) {
        QModbusReply* read = wait(m_client->sendReadRequest(QModbusDataUnit(QModbusDataUnit::DiscreteInputs, spindle, 1), 1));
        QVERIFY(read);
        on = read->error() == QModbusDevice::NoError && read->result().value(0) == 1;
        if (!on)
            QTest::qWait(5);
    }
    QVERIFY(on);
    QCOMPARE(m_simulator->activeStepId(), std::string("F2"));
    QVERIFY(m_link->scansRun() > 0);
}

void TestModbusLink::registerRoundTrip()
{
    QVERIFY(startServer());
    QVERIFY(connectClient());
    const int batch = core::modbusio::defaultModbusMap(m_model->variables(), ModbusRole::Server).find("BatchSize")->address;
    QModbusReply* initial = wait(m_client->sendReadRequest(QModbusDataUnit(QModbusDataUnit::HoldingRegisters, batch, 1), 1));
    QVERIFY(initial);
    QCOMPARE(initial->result().value(0), quint16(10)); // the default
    QModbusDataUnit unit(QModbusDataUnit::HoldingRegisters, batch, 1);
    unit.setValue(0, 25);
    QModbusReply* written = wait(m_client->sendWriteRequest(unit, 1));
    QVERIFY(written);
    QCOMPARE(written->error(), QModbusDevice::NoError);
    QTRY_COMPARE_WITH_TIMEOUT(m_simulator->variable("BatchSize"), core::cond::Value(std::int64_t{25}), 2000);
    QModbusReply* back = wait(m_client->sendReadRequest(QModbusDataUnit(QModbusDataUnit::HoldingRegisters, batch, 1), 1));
    QVERIFY(back);
    QCOMPARE(back->result().value(0), quint16(25));
    // A negative INT travels as two's complement.
    unit.setValue(0, 0xFFFE);
    QVERIFY(wait(m_client->sendWriteRequest(unit, 1)));
    QTRY_COMPARE_WITH_TIMEOUT(m_simulator->variable("BatchSize"), core::cond::Value(std::int64_t{-2}), 2000);
}

void TestModbusLink::valueOutOfRangeIsRefused()
{
    QVERIFY(m_model->addVariable({"Level", core::IecType::Usint, "", "", core::VariableKind::Input}));
    m_simulator = std::make_unique<core::Simulator>(*m_model);
    QVERIFY(startServer());
    QVERIFY(connectClient());
    const core::modbusio::ModbusMap map = core::modbusio::defaultModbusMap(m_model->variables(), ModbusRole::Server);
    const int level = map.find("Level")->address;
    QSignalSpy errors(m_link.get(), &ModbusLink::linkError);
    QModbusDataUnit unit(QModbusDataUnit::HoldingRegisters, level, 1);
    unit.setValue(0, 300);
    QModbusReply* reply = wait(m_client->sendWriteRequest(unit, 1));
    QVERIFY(reply);
    QCOMPARE(reply->error(), QModbusDevice::ProtocolError);
    QCOMPARE(exceptionOf(reply), int(QModbusPdu::IllegalDataValue));
    QCOMPARE(errors.count(), 1);
    QCOMPARE(errors.at(0).at(0).toString(),
             QStringLiteral("holding-register %1 (Level): 300 is out of range for USINT (0..255)").arg(level));
    QTest::qWait(3 * m_simulator->cycleTimeMs());
    QCOMPARE(m_simulator->variable("Level"), core::cond::Value(std::int64_t{0}));
    unit.setValue(0, 200);
    QModbusReply* good = wait(m_client->sendWriteRequest(unit, 1));
    QVERIFY(good);
    QCOMPARE(good->error(), QModbusDevice::NoError);
    QTRY_COMPARE_WITH_TIMEOUT(m_simulator->variable("Level"), core::cond::Value(std::int64_t{200}), 2000);
}

void TestModbusLink::unmappedAddressGetsException02()
{
    QVERIFY(startServer());
    QVERIFY(connectClient());
    const auto expect02 = [this](QModbusReply* reply) {
        QVERIFY(reply);
        QCOMPARE(reply->error(), QModbusDevice::ProtocolError);
        QCOMPARE(exceptionOf(reply), int(QModbusPdu::IllegalDataAddress));
    };
    // 10 coils (0..9), 9 discrete inputs (0..8), 1 holding register, no input register.
    expect02(wait(m_client->sendReadRequest(QModbusDataUnit(QModbusDataUnit::Coils, 500, 1), 1)));
    expect02(wait(m_client->sendReadRequest(QModbusDataUnit(QModbusDataUnit::Coils, 5, 6), 1)));
    expect02(wait(m_client->sendReadRequest(QModbusDataUnit(QModbusDataUnit::DiscreteInputs, 9, 1), 1)));
    expect02(wait(m_client->sendReadRequest(QModbusDataUnit(QModbusDataUnit::InputRegisters, 0, 1), 1)));
    QModbusDataUnit write(QModbusDataUnit::HoldingRegisters, 1, 1);
    write.setValue(0, 3);
    expect02(wait(m_client->sendWriteRequest(write, 1)));
    // A map with a gap: coil 1 is not mapped between 0 and 2.
    m_client->disconnectDevice();
    m_link.reset();
    const core::modbusio::ModbusMapParse parsed = core::modbusio::parseModbusMap(
        "StartButton,coil,0\nStopButton,coil,2\nSpindle,discrete-input,0\n", m_model->variables(), ModbusRole::Server);
    QVERIFY(parsed.ok());
    QVERIFY(startServer(&parsed.map));
    QVERIFY(connectClient());
    expect02(wait(m_client->sendReadRequest(QModbusDataUnit(QModbusDataUnit::Coils, 1, 1), 1)));
    expect02(wait(m_client->sendReadRequest(QModbusDataUnit(QModbusDataUnit::Coils, 0, 3), 1)));
    QModbusReply* fine = wait(m_client->sendReadRequest(QModbusDataUnit(QModbusDataUnit::Coils, 2, 1), 1));
    QVERIFY(fine);
    QCOMPARE(fine->error(), QModbusDevice::NoError);
}

void TestModbusLink::unsupportedFunctionGetsException01()
{
    QVERIFY(startServer());
    QVERIFY(connectClient());
    // FC 20, read file record; FC 24, read FIFO queue; FC 22, mask write register.
    for (const QModbusPdu::FunctionCode code : {QModbusPdu::ReadFileRecord, QModbusPdu::ReadFifoQueue, QModbusPdu::MaskWriteRegister}) {
        QModbusReply* reply = wait(m_client->sendRawRequest(QModbusRequest(code, QByteArray::fromHex("00000000000000")), 1));
        QVERIFY(reply);
        QCOMPARE(reply->error(), QModbusDevice::ProtocolError);
        QCOMPARE(exceptionOf(reply), int(QModbusPdu::IllegalFunction));
    }
    // The server still answers.
    QModbusReply* read = wait(m_client->sendReadRequest(QModbusDataUnit(QModbusDataUnit::Coils, 0, 2), 1));
    QVERIFY(read);
    QCOMPARE(read->error(), QModbusDevice::NoError);
}

void TestModbusLink::portInUseIsReported()
{
    QVERIFY(startServer());
    modbus::ModbusLinkOptions options = m_link->options();
    core::Simulator other(*m_model);
    ModbusLink second(options, modbus::simulatorHooks(other));
    QString error;
    QVERIFY(!second.start(&error));
    QVERIFY2(error.startsWith(QStringLiteral("cannot listen on 127.0.0.1:%1: ").arg(m_port)), qPrintable(error));
    QCOMPARE(second.state(), ModbusLink::State::Closed);
}

void TestModbusLink::badFramesAndVanishingClients()
{
    QVERIFY(startServer());
    const auto rawSocket = [this] {
        auto socket = std::make_unique<QTcpSocket>();
        socket->connectToHost(QHostAddress::LocalHost, static_cast<quint16>(m_port));
        return socket->waitForConnected(2000) ? std::move(socket) : nullptr;
    };
    // A truncated frame: the header promises 6 bytes of PDU, 3 come, then the client leaves.
    {
        auto socket = rawSocket();
        QVERIFY(socket);
        socket->write(frame(1, 1, QByteArray::fromHex("010000000a")).left(10));
        socket->waitForBytesWritten(1000);
        QTest::qWait(20);
        socket->abort();
    }
    // Garbage: a protocol id that is not Modbus, a length past 254, random bytes.
    {
        auto socket = rawSocket();
        QVERIFY(socket);
        QByteArray garbage = QByteArray::fromHex("0001abcd00060101000000010000ffff01");
        for (int i = 0; i < 64; ++i)
            garbage.append(static_cast<char>((i * 37 + 11) & 0xFF));
        socket->write(garbage);
        socket->waitForBytesWritten(1000);
        QTest::qWait(50);
        socket->abort();
    }
    // A client that vanishes in the middle of a valid request.
    for (int i = 0; i < 20; ++i) {
        auto socket = rawSocket();
        QVERIFY(socket);
        socket->write(frame(static_cast<quint16>(i), 1, QByteArray::fromHex("0100000001")).left(4 + i % 8));
        socket->waitForBytesWritten(1000);
        socket->abort();
    }
    // The server still answers a proper client, and the clock kept running.
    QVERIFY(connectClient());
    QModbusReply* read = wait(m_client->sendReadRequest(QModbusDataUnit(QModbusDataUnit::Coils, 0, 10), 1));
    QVERIFY(read);
    QCOMPARE(read->error(), QModbusDevice::NoError);
    QVERIFY(m_link->scansRun() > 0);
    QTRY_VERIFY_WITH_TIMEOUT(m_link->clientCount() == 1, 2000);
}

void TestModbusLink::floodLeavesServerAndClockWorking()
{
    QVERIFY(startServer());
    QTcpSocket socket;
    socket.connectToHost(QHostAddress::LocalHost, static_cast<quint16>(m_port));
    QVERIFY(socket.waitForConnected(2000));
    constexpr int kRequests = 2000;
    QByteArray flood;
    for (int i = 0; i < kRequests; ++i)
        flood += frame(static_cast<quint16>(i), 1, QByteArray::fromHex("0100000008")); // FC 1, coils 0..7
    const qint64 scansBefore = m_link->scansRun();
    const qint64 msBefore = m_link->elapsedMs();
    socket.write(flood);
    // Each answer is 10 bytes (MBAP 7 + FC, byte count, one byte of coils).
    QByteArray answers;
    for (int i = 0; i < 1000 && answers.size() < kRequests * 10; ++i) {
        QTest::qWait(10); // the server runs on this thread: never block it
        answers += socket.readAll();
    }
    QCOMPARE(answers.size(), kRequests * 10);
    QCOMPARE(static_cast<quint8>(answers.at(7)), quint8(1));
    // The simulation kept its clock: it ran at least half the scans real time asked for.
    QTest::qWait(100);
    const qint64 ranMs = m_link->elapsedMs() - msBefore;
    const qint64 ran = m_link->scansRun() - scansBefore;
    const qint64 owed = ranMs / m_simulator->cycleTimeMs();
    QVERIFY2(ran * 2 >= owed && ran <= owed + 1, qPrintable(QStringLiteral("%1 scans in %2 ms").arg(ran).arg(ranMs)));
    socket.abort();
    QVERIFY(connectClient());
    QModbusReply* read = wait(m_client->sendReadRequest(QModbusDataUnit(QModbusDataUnit::DiscreteInputs, 0, 9), 1));
    QVERIFY(read);
    QCOMPARE(read->error(), QModbusDevice::NoError);
}

void TestModbusLink::clientModeDrivesATwin()
{
    // The twin: a server with the client-mode tables of the drilling cell.
    const core::modbusio::ModbusMap map = core::modbusio::defaultModbusMap(m_model->variables(), ModbusRole::Client);
    QModbusTcpServer twin;
    m_port = freePort();
    QVERIFY(modbustest::startDrillingCellTwin(twin, m_port));
    twin.setData(QModbusDataUnit::DiscreteInputs, static_cast<quint16>(map.find("EmergencyOk")->address), 1);
    twin.setData(QModbusDataUnit::InputRegisters, static_cast<quint16>(map.find("BatchSize")->address), 7);

    modbus::ModbusLinkOptions options;
    options.map = map;
    options.port = m_port;
    options.cycleTimeMs = m_simulator->cycleTimeMs();
    options.requestTimeoutMs = 200;
    m_link = std::make_unique<ModbusLink>(options, modbus::simulatorHooks(*m_simulator));
    QString error;
    QVERIFY2(m_link->start(&error), qPrintable(error));
    QTRY_COMPARE_WITH_TIMEOUT(m_link->state(), ModbusLink::State::Connected, 3000);
    QTRY_COMPARE_WITH_TIMEOUT(m_simulator->variable("BatchSize"), core::cond::Value(std::int64_t{7}), 3000);
    twin.setData(QModbusDataUnit::DiscreteInputs, static_cast<quint16>(map.find("Unclamped")->address), 1);
    twin.setData(QModbusDataUnit::DiscreteInputs, static_cast<quint16>(map.find("DrillHigh")->address), 1);
    twin.setData(QModbusDataUnit::DiscreteInputs, static_cast<quint16>(map.find("StartButton")->address), 1);
    const quint16 spindle = static_cast<quint16>(map.find("Spindle")->address);
    quint16 value = 0;
    for (int i = 0; i < 300 && value == 0; ++i) {
        QTest::qWait(10);
        twin.data(QModbusDataUnit::Coils, spindle, &value);
    }
    QCOMPARE(value, quint16(1));
    QCOMPARE(m_simulator->activeStepId(), std::string("F2"));

    // The twin goes away: requests fail and are reported, the scans go on with the last inputs.
    QSignalSpy errors(m_link.get(), &ModbusLink::linkError);
    twin.disconnectDevice();
    QTRY_VERIFY_WITH_TIMEOUT(errors.count() > 0, 3000);
    const std::int64_t scans = m_link->scansRun();
    QTRY_VERIFY_WITH_TIMEOUT(m_link->scansRun() > scans + 5, 3000);
    QCOMPARE(m_simulator->variable("BatchSize"), core::cond::Value(std::int64_t{7}));
    QVERIFY(!m_link->lastError().isEmpty());
}

QTEST_GUILESS_MAIN(TestModbusLink)
#include "test_modbuslink.moc"
