// Simulation > Connect... on the drilling cell, offscreen: the dialog's map,
// CSV load and save, connecting as a server (the dock says listening), a
// QModbusTcpClient twin pressing Start, Disconnect. 127.0.0.1 only, waits bounded.

#include "editortestsupport.h"
#include "tests/modbus/modbustestsupport.h"

#include "editor/app/languages.h"
#include "editor/document.h"
#include "editor/mainwindow.h"
#include "editor/simulation/modbusconnectdialog.h"
#include "editor/simulation/modbusconnection.h"
#include "editor/simulation/simulationdock.h"
#include "editor/simulation/simulationsession.h"

#include <QAction>
#include <QComboBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QModbusReply>
#include <QModbusTcpClient>
#include <QModbusTcpServer>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTableWidget>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <memory>

using namespace editor;

namespace test_modbusconnect {

using modbustest::freePort;

} // namespace test_modbusconnect

using namespace test_modbusconnect;

class TestModbusConnect : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();
    void dialogShowsTheMapAndLoadsCsv();
    void connectListenTwinAndDisconnect();
    void portInUseIsSaidAndNothingChanges();
    void clientModeShowsItsTwin();

private:
    QTemporaryDir m_settingsDir;
    std::unique_ptr<Translators> m_translators;
    std::unique_ptr<MainWindow> m_window;
};

void TestModbusConnect::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    editortest::useTestSettings(m_settingsDir.path(), QStringLiteral("test_modbusconnect"));
}

void TestModbusConnect::init()
{
    m_window = editortest::showEnglishMainWindow(m_translators);
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    QString error;
    QVERIFY2(m_window->document()->load(QStringLiteral(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json"), &error),
             qPrintable(error));
}

void TestModbusConnect::cleanup()
{
    if (m_window)
        m_window->document()->undoStack()->setClean();
    m_window.reset();
    m_translators.reset();
}

void TestModbusConnect::dialogShowsTheMapAndLoadsCsv()
{
    ModbusConnectDialog dialog(m_window->document()->model().variables());
    QCOMPARE(dialog.hostEdit()->text(), QStringLiteral("127.0.0.1"));
    QCOMPARE(dialog.portSpin()->value(), 1502);
    QCOMPARE(dialog.unitSpin()->value(), 1);
    QCOMPARE(dialog.mapTable()->rowCount(), 20); // 10 BOOL inputs, BatchSize, 9 outputs
    QCOMPARE(dialog.mapTable()->item(1, 0)->text(), QStringLiteral("StartButton"));
    QCOMPARE(dialog.mapTable()->item(1, 2)->text(), QStringLiteral("Coil"));
    QCOMPARE(dialog.mapTable()->item(1, 3)->text(), QStringLiteral("1"));
    dialog.roleCombo()->setCurrentIndex(1);
    QCOMPARE(dialog.mapTable()->item(1, 2)->text(), QStringLiteral("Discrete input"));
    QCOMPARE(dialog.options().map.role, core::modbusio::ModbusRole::Client);

    QTemporaryDir dir;
    const QString saved = dir.filePath(QStringLiteral("map.csv"));
    QVERIFY(dialog.saveMap(saved));
    QFile file(saved);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QVERIFY(file.readAll().startsWith("variable,table,address\nEmergencyOk,discrete-input,0\n"));

    const QString bad = dir.filePath(QStringLiteral("bad.csv"));
    QFile badFile(bad);
    QVERIFY(badFile.open(QIODevice::WriteOnly));
    badFile.write("StartButton,coil,1\n");
    badFile.close();
    QVERIFY(!dialog.loadMap(bad));
    QVERIFY(dialog.problemLabel()->isVisibleTo(&dialog));
    QVERIFY2(dialog.problemLabel()->text().contains(
                 QStringLiteral("Line 1, column 13: 'StartButton' is a BOOL input: in client mode it goes in the "
                                "discrete-input table, not coil")),
             qPrintable(dialog.problemLabel()->text()));
    QCOMPARE(dialog.mapTable()->rowCount(), 20); // the map in use stays

    const QString good = dir.filePath(QStringLiteral("good.csv"));
    QFile goodFile(good);
    QVERIFY(goodFile.open(QIODevice::WriteOnly));
    goodFile.write("StartButton,discrete-input,40\nSpindle,coil,7\n");
    goodFile.close();
    QVERIFY(dialog.loadMap(good));
    QCOMPARE(dialog.mapTable()->rowCount(), 2);
    QCOMPARE(dialog.mapTable()->item(0, 3)->text(), QStringLiteral("40"));
    QVERIFY(!dialog.problemLabel()->isVisibleTo(&dialog));
}

void TestModbusConnect::connectListenTwinAndDisconnect()
{
    auto* connectAction = m_window->findChild<QAction*>(QStringLiteral("modbusConnectAction"));
    auto* disconnectAction = m_window->findChild<QAction*>(QStringLiteral("modbusDisconnectAction"));
    QVERIFY(connectAction && disconnectAction);
    QCOMPARE(connectAction->text(), QStringLiteral("Co&nnect…"));
    QVERIFY(!disconnectAction->isEnabled());

    connectAction->trigger();
    auto* dialog = m_window->findChild<ModbusConnectDialog*>(QStringLiteral("modbusConnectDialog"));
    QVERIFY(dialog);
    QTRY_VERIFY_WITH_TIMEOUT(dialog->isVisible(), 2000);
    const int port = freePort();
    dialog->portSpin()->setValue(port);
    dialog->accept();

    ModbusConnection* connection = m_window->modbusConnection();
    SimulationSession* session = m_window->simulationSession();
    QVERIFY(connection->isConnected());
    QVERIFY(session->isActive());
    QVERIFY(session->isLinked());
    QVERIFY(disconnectAction->isEnabled());
    auto* run = m_window->findChild<QAction*>(QStringLiteral("runSimulationAction"));
    QVERIFY(run);
    QVERIFY(!run->isEnabled()); // the link's clock runs the scans
    auto* dock = m_window->findChild<SimulationDock*>(QStringLiteral("simulationDock"));
    QVERIFY(dock);
    QTRY_VERIFY_WITH_TIMEOUT(dock->linkLabel()->isVisible(), 2000);
    QCOMPARE(dock->linkLabel()->text(),
             QStringLiteral("Modbus server on 127.0.0.1:%1, unit 1, clients connected: 0").arg(port));
    // The machine stands aside: its sensors are the twin's to set.
    QVERIFY(!session->isMachineDriven(session->liveSimulator()->variableIndex("Unclamped")));

    QModbusTcpClient twin;
    twin.setConnectionParameter(QModbusDevice::NetworkAddressParameter, QStringLiteral("127.0.0.1"));
    twin.setConnectionParameter(QModbusDevice::NetworkPortParameter, port);
    twin.setTimeout(2000);
    QVERIFY(twin.connectDevice());
    QTRY_COMPARE_WITH_TIMEOUT(twin.state(), QModbusDevice::ConnectedState, 3000);
    QTRY_VERIFY_WITH_TIMEOUT(dock->linkLabel()->text().contains(QStringLiteral("clients connected: 1")), 3000);
    QModbusDataUnit coils(QModbusDataUnit::Coils, 1, 1); // StartButton
    coils.setValue(0, 1);
    QModbusReply* reply = twin.sendWriteRequest(coils, 1);
    QVERIFY(reply);
    QTRY_VERIFY_WITH_TIMEOUT(reply->isFinished(), 3000);
    QCOMPARE(reply->error(), QModbusDevice::NoError);
    delete reply;
    QTRY_VERIFY_WITH_TIMEOUT(dock->linkLabel()->text().contains(QStringLiteral("Set by the twin: StartButton = TRUE")),
                             3000);
    QTRY_COMPARE_WITH_TIMEOUT(session->liveSimulator()->activeStepId(), std::string("F2"), 3000);
    // Real time: the scans went on by themselves.
    const std::int64_t scans = session->latestScan();
    QTRY_VERIFY_WITH_TIMEOUT(session->latestScan() > scans + 3, 3000);

    twin.disconnectDevice();
    disconnectAction->trigger();
    QVERIFY(!connection->isConnected());
    QVERIFY(!session->isLinked());
    QVERIFY(!disconnectAction->isEnabled());
    QVERIFY(!dock->linkLabel()->isVisible());
    QVERIFY(run->isEnabled());
    QVERIFY(session->isMachineDriven(session->liveSimulator()->variableIndex("Unclamped")));
    const std::int64_t stopped = session->latestScan();
    QTest::qWait(100);
    QCOMPARE(session->latestScan(), stopped);

    // Leaving the simulation ends a link too.
    modbus::ModbusLinkOptions options;
    options.map = core::modbusio::defaultModbusMap(m_window->document()->model().variables(),
                                                   core::modbusio::ModbusRole::Server);
    options.port = freePort();
    QString error;
    QVERIFY2(connection->connectLink(options, &error), qPrintable(error));
    QVERIFY(disconnectAction->isEnabled());
    auto* simulate = m_window->findChild<QAction*>(QStringLiteral("simulateAction"));
    QVERIFY(simulate && simulate->isChecked());
    simulate->trigger();
    QVERIFY(!session->isActive());
    QVERIFY(!connection->isConnected());
    QVERIFY(!session->isLinked());
    QVERIFY(!disconnectAction->isEnabled());
}

void TestModbusConnect::portInUseIsSaidAndNothingChanges()
{
    QTcpServer taken;
    QVERIFY(taken.listen(QHostAddress::LocalHost, 0));
    ModbusConnection* connection = m_window->modbusConnection();
    modbus::ModbusLinkOptions options;
    options.map = core::modbusio::defaultModbusMap(m_window->document()->model().variables(), core::modbusio::ModbusRole::Server);
    options.port = taken.serverPort();
    QString error;
    QVERIFY(!connection->connectLink(options, &error));
    QVERIFY2(error.startsWith(QStringLiteral("cannot listen on 127.0.0.1:%1").arg(taken.serverPort())), qPrintable(error));
    QVERIFY(!connection->isConnected());
    QVERIFY(!m_window->simulationSession()->isLinked());
}

void TestModbusConnect::clientModeShowsItsTwin()
{
    QModbusTcpServer twin;
    const int port = freePort();
    QVERIFY(modbustest::startDrillingCellTwin(twin, port));
    twin.setData(QModbusDataUnit::InputRegisters, 0, 42); // BatchSize

    ModbusConnectDialog dialog(m_window->document()->model().variables());
    dialog.roleCombo()->setCurrentIndex(1);
    QCOMPARE(dialog.portSpin()->value(), 502);
    dialog.portSpin()->setValue(port);
    ModbusConnection* connection = m_window->modbusConnection();
    QString error;
    QVERIFY2(connection->connectLink(dialog.options(), &error), qPrintable(error));
    auto* dock = m_window->findChild<SimulationDock*>(QStringLiteral("simulationDock"));
    QVERIFY(dock);
    QTRY_COMPARE_WITH_TIMEOUT(dock->linkLabel()->text().section(QLatin1Char('\n'), 0, 0),
                              QStringLiteral("Modbus client of 127.0.0.1:%1: connected").arg(port), 3000);
    QTRY_COMPARE_WITH_TIMEOUT(m_window->simulationSession()->liveSimulator()->variable("BatchSize"),
                              core::cond::Value(std::int64_t{42}), 3000);
    // The twin's discrete inputs are all off: EmergencyOk (TRUE by default) and the
    // sensors the machine had set at rest went off too.
    QTRY_COMPARE_WITH_TIMEOUT(dock->linkLabel()->text().section(QLatin1Char('\n'), 1, 1),
                              QStringLiteral("Set by the twin: EmergencyOk = FALSE, Unclamped = FALSE, DrillHigh = FALSE, BatchSize = 42"), 3000);
    QSignalSpy left(&twin, &QModbusTcpServer::modbusClientDisconnected);
    connection->disconnectLink();
    QVERIFY(!connection->isConnected());
    // The twin sees the link leave before it goes (Qt frees the connection then).
    QTRY_COMPARE_WITH_TIMEOUT(left.count(), 1, 3000);
}

QTEST_MAIN(TestModbusConnect)
#include "test_modbusconnect.moc"
