// ggstudio-cli simulate --modbus-server against a QModbusTcpClient, on
// 127.0.0.1: the twin presses Start, reads the Spindle the program drives;
// --scans bounds the run. A port already taken and a bad HOST:PORT exit 2.

#include "modbustestsupport.h"

#include <QModbusReply>
#include <QModbusTcpClient>
#include <QModbusTcpServer>
#include <QProcess>
#include <QTcpServer>
#include <QTest>

namespace test_modbuscli {

using modbustest::freePort;

const QString kModel = QStringLiteral(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");

} // namespace test_modbuscli

using namespace test_modbuscli;

class TestModbusCli : public QObject {
    Q_OBJECT

private slots:
    void twinDrivesTheCliServer();
    void portInUseExits2();
    void badHostPortExits2();
    void printsTheMapAsCsv();
    void clientModeDrivesATwinServer();
    void clientWithoutTwinReportsAndRuns();
    void sigtermClosesCleanly();

private:
    QModbusReply* wait(QModbusReply* reply);
};

QModbusReply* TestModbusCli::wait(QModbusReply* reply)
{
    return modbustest::waitFor(reply, this);
}

void TestModbusCli::twinDrivesTheCliServer()
{
    const int port = freePort();
    QVERIFY(port > 0);
    QProcess cli;
    // 10 ms cycles: 1,000 scans are 10 s, time enough to connect under the sanitizers.
    cli.start(QStringLiteral(GGSTUDIO_CLI),
              {QStringLiteral("simulate"), kModel, QStringLiteral("--modbus-server"),
               QStringLiteral("127.0.0.1:%1").arg(port), QStringLiteral("--scans"), QStringLiteral("1000")});
    QVERIFY(cli.waitForStarted(5000));
    QModbusTcpClient client;
    client.setConnectionParameter(QModbusDevice::NetworkAddressParameter, QStringLiteral("127.0.0.1"));
    client.setConnectionParameter(QModbusDevice::NetworkPortParameter, port);
    client.setTimeout(2000);
    client.setNumberOfRetries(0);
    // The CLI listens once it has started: retry the connection for up to 5 s.
    for (int attempt = 0; attempt < 50 && client.state() != QModbusDevice::ConnectedState; ++attempt) {
        if (client.state() == QModbusDevice::UnconnectedState)
            client.connectDevice();
        QTest::qWait(100);
    }
    QCOMPARE(client.state(), QModbusDevice::ConnectedState);
    QModbusDataUnit coils(QModbusDataUnit::Coils, 7, 2); // Unclamped, DrillHigh: the rest position
    coils.setValue(0, 1);
    coils.setValue(1, 1);
    QModbusReply* rest = wait(client.sendWriteRequest(coils, 1));
    QVERIFY(rest);
    QCOMPARE(rest->error(), QModbusDevice::NoError);
    QModbusDataUnit start(QModbusDataUnit::Coils, 1, 1); // StartButton
    start.setValue(0, 1);
    QModbusReply* pressed = wait(client.sendWriteRequest(start, 1));
    QVERIFY(pressed);
    QCOMPARE(pressed->error(), QModbusDevice::NoError);
    bool spindle = false;
    for (int i = 0; i < 100 && !spindle; ++i) {
        QModbusReply* read = wait(client.sendReadRequest(QModbusDataUnit(QModbusDataUnit::DiscreteInputs, 4, 1), 1));
        QVERIFY(read);
        spindle = read->error() == QModbusDevice::NoError && read->result().value(0) == 1;
        if (!spindle)
            QTest::qWait(10);
    }
    QVERIFY(spindle);
    client.disconnectDevice();
    QVERIFY(cli.waitForFinished(30000));
    const QString out = QString::fromUtf8(cli.readAllStandardOutput());
    QVERIFY2(cli.exitStatus() == QProcess::NormalExit && cli.exitCode() == 0,
             qPrintable(out + QString::fromUtf8(cli.readAllStandardError())));
    QVERIFY2(out.contains(QStringLiteral("  coil 1                  StartButton (BOOL input)")), qPrintable(out));
    QVERIFY2(out.contains(QStringLiteral("listening on 127.0.0.1:%1, cycle time 10 ms, 1000 scans").arg(port)), qPrintable(out));
    QVERIFY2(out.contains(QStringLiteral(": modbus set StartButton = TRUE")), qPrintable(out));
    QVERIFY2(out.contains(QStringLiteral(": F2 fired A1->F2")), qPrintable(out));
    QVERIFY2(out.contains(QStringLiteral("modbus: 1 client(s) connected")), qPrintable(out));
    QVERIFY2(out.contains(QStringLiteral("stopped after 1000 scans, F2")), qPrintable(out));
}

void TestModbusCli::portInUseExits2()
{
    QTcpServer taken;
    QVERIFY(taken.listen(QHostAddress::LocalHost, 0));
    QProcess cli;
    cli.start(QStringLiteral(GGSTUDIO_CLI),
              {QStringLiteral("simulate"), kModel, QStringLiteral("--modbus-server"),
               QStringLiteral("127.0.0.1:%1").arg(taken.serverPort()), QStringLiteral("--scans"), QStringLiteral("5")});
    QVERIFY(cli.waitForFinished(30000));
    QCOMPARE(cli.exitCode(), 2);
    const QString err = QString::fromUtf8(cli.readAllStandardError());
    QVERIFY2(err.startsWith(QStringLiteral("ggstudio-cli: cannot listen on 127.0.0.1:%1: ").arg(taken.serverPort())),
             qPrintable(err));
}

void TestModbusCli::badHostPortExits2()
{
    QProcess cli;
    cli.start(QStringLiteral(GGSTUDIO_CLI),
              {QStringLiteral("simulate"), kModel, QStringLiteral("--modbus-client"), QStringLiteral("127.0.0.1")});
    QVERIFY(cli.waitForFinished(30000));
    QCOMPARE(cli.exitCode(), 2);
    QCOMPARE(QString::fromUtf8(cli.readAllStandardError()),
             QStringLiteral("ggstudio-cli: --modbus-client: '127.0.0.1': expected HOST:PORT (127.0.0.1:1502)\n"));
}

void TestModbusCli::printsTheMapAsCsv()
{
    QProcess cli;
    cli.start(QStringLiteral(GGSTUDIO_CLI),
              {QStringLiteral("simulate"), kModel, QStringLiteral("--modbus-client"), QStringLiteral("127.0.0.1:502"),
               QStringLiteral("--print-modbus-map")});
    QVERIFY(cli.waitForFinished(30000));
    QCOMPARE(cli.exitCode(), 0);
    const QString out = QString::fromUtf8(cli.readAllStandardOutput());
    QVERIFY2(out.startsWith(QStringLiteral("variable,table,address\nEmergencyOk,discrete-input,0\n")), qPrintable(out));
    QVERIFY2(out.contains(QStringLiteral("\nBatchSize,input-register,0\nClampOut,coil,0\n")), qPrintable(out));
}

void TestModbusCli::clientModeDrivesATwinServer()
{
    // The twin: discrete inputs 0..9 (the BOOL inputs), input register 0
    // (BatchSize), coils 0..8 (the outputs), as --print-modbus-map says.
    QModbusTcpServer twin;
    const int port = freePort();
    QVERIFY(modbustest::startDrillingCellTwin(twin, port));
    for (const quint16 input : {quint16(0), quint16(1), quint16(7), quint16(8)}) // EmergencyOk, StartButton, Unclamped, DrillHigh
        twin.setData(QModbusDataUnit::DiscreteInputs, input, 1);
    QProcess cli;
    cli.start(QStringLiteral(GGSTUDIO_CLI),
              {QStringLiteral("simulate"), kModel, QStringLiteral("--modbus-client"),
               QStringLiteral("127.0.0.1:%1").arg(port), QStringLiteral("--scans"), QStringLiteral("600")}); // 6 s: time to connect under the sanitizers
    QVERIFY(cli.waitForStarted(5000));
    quint16 spindle = 0;
    for (int i = 0; i < 1000 && spindle == 0; ++i) {
        QTest::qWait(10);
        twin.data(QModbusDataUnit::Coils, 4, &spindle);
    }
    QCOMPARE(spindle, quint16(1));
    for (int i = 0; i < 3000 && cli.state() != QProcess::NotRunning; ++i)
        QTest::qWait(10); // the twin answers on this thread: never block it
    QCOMPARE(cli.state(), QProcess::NotRunning);
    const QString out = QString::fromUtf8(cli.readAllStandardOutput());
    QVERIFY2(cli.exitCode() == 0, qPrintable(out + QString::fromUtf8(cli.readAllStandardError())));
    QVERIFY2(out.contains(QStringLiteral("Modbus map (client mode, unit 1):")), qPrintable(out));
    QVERIFY2(out.contains(QStringLiteral("modbus: connected to 127.0.0.1:%1").arg(port)), qPrintable(out));
    QVERIFY2(out.contains(QStringLiteral(": F2 fired A1->F2")), qPrintable(out));
    QVERIFY2(out.contains(QStringLiteral("stopped after 600 scans, F2")), qPrintable(out));
}

void TestModbusCli::clientWithoutTwinReportsAndRuns()
{
    const int port = freePort(); // nobody listens there
    QProcess cli;
    cli.start(QStringLiteral(GGSTUDIO_CLI),
              {QStringLiteral("simulate"), kModel, QStringLiteral("--modbus-client"),
               QStringLiteral("127.0.0.1:%1").arg(port), QStringLiteral("--scans"), QStringLiteral("150")});
    QVERIFY(cli.waitForFinished(30000));
    const QString err = QString::fromUtf8(cli.readAllStandardError());
    QCOMPARE(cli.exitCode(), 0);
    QVERIFY2(err.contains(QStringLiteral("modbus: 127.0.0.1:%1: ").arg(port)), qPrintable(err));
    QVERIFY(QString::fromUtf8(cli.readAllStandardOutput()).contains(QStringLiteral("stopped after 150 scans, A1")));
}

void TestModbusCli::sigtermClosesCleanly()
{
    const int port = freePort();
    QProcess cli;
    cli.start(QStringLiteral(GGSTUDIO_CLI), {QStringLiteral("simulate"), kModel, QStringLiteral("--modbus-server"),
                                             QStringLiteral("127.0.0.1:%1").arg(port)});
    QVERIFY(cli.waitForStarted(5000));
    QByteArray out;
    for (int i = 0; i < 100 && !out.contains("until SIGINT or SIGTERM"); ++i) {
        cli.waitForReadyRead(100);
        out += cli.readAllStandardOutput();
    }
    QVERIFY2(out.contains("listening on 127.0.0.1:"), out.constData());
    cli.terminate(); // SIGTERM
    QVERIFY(cli.waitForFinished(10000));
    out += cli.readAllStandardOutput();
    QCOMPARE(cli.exitStatus(), QProcess::NormalExit);
    QCOMPARE(cli.exitCode(), 0);
    QVERIFY2(out.contains("stopped after "), out.constData());
}

QTEST_GUILESS_MAIN(TestModbusCli)
#include "test_modbuscli.moc"
