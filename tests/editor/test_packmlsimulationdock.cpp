// The PackML Simulation dock (issue 34, Simulation), driven through its
// widgets on the Capper of spec §6.6: the command buttons and what became
// of a press, the mode selector, the inputs and outputs, the trace with the
// drop reasons worded, history, run, and a scenario replayed.

#include "packmlcappermodel.h"
#include "editor/document.h"
#include "editor/simulation/lampindicator.h"
#include "editor/simulation/packml/packmlsimulationdock.h"
#include "editor/simulation/packml/packmlsimulationsession.h"
#include "editor/simulation/packml/packmltracemodel.h"

#include "core/formats/modelfiles.h"
#include "core/templates/packml/packmlmodel.h"

#include <QComboBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>

#include <memory>

using namespace editor;
using core::packml::Command;
using core::packml::State;

namespace {

using packmltest::capper;

} // namespace

class TestPackmlSimulationDock : public QObject {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void startButtonBuildsTheUnitsControls();
    void commandButtonsPlayTheCapper();
    void acceptedCommandsAreBold();
    void modeSelectorRequestsAMode();
    void packTagsFieldsDriveTheRequestsByHand();
    void outputsAsLampsAndValues();
    void functionBlockOfTheCurrentState();
    void completeOfASkeletonSetByHand();
    void historyButtonsShowPastScans();
    void runButtonRunsAndPauses();
    void scenarioReplayedWithItsResult();
    void scenarioThatDoesNotFitIsExplained();
    void endButtonEndsTheSimulation();
    void divisionByZeroStopsTheRunAndSaysWhere();

private:
    void start();
    void writeScenario(const QString& name, const char* text);
    QString traceCell(int row, int column) const;

    std::unique_ptr<Document> m_document;
    std::unique_ptr<PackmlSimulationSession> m_session;
    std::unique_ptr<PackmlSimulationDock> m_dock;
    QTemporaryDir m_dir;
};

void TestPackmlSimulationDock::init()
{
    m_document = std::make_unique<Document>(capper());
    m_session = std::make_unique<PackmlSimulationSession>(m_document.get());
    m_dock = std::make_unique<PackmlSimulationDock>(m_session.get(), m_document.get());
    m_dock->resize(700, 600);
    m_dock->show();
}

void TestPackmlSimulationDock::cleanup()
{
    m_dock.reset();
    m_session.reset();
    m_document.reset();
}

void TestPackmlSimulationDock::start()
{
    QTest::mouseClick(m_dock->startButton(), Qt::LeftButton);
    QVERIFY(m_session->isActive());
}

void TestPackmlSimulationDock::writeScenario(const QString& name, const char* text)
{
    QFile file(m_dir.filePath(name));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(text);
}

QString TestPackmlSimulationDock::traceCell(int row, int column) const
{
    return m_dock->traceModel()->index(row, column).data().toString();
}

void TestPackmlSimulationDock::startButtonBuildsTheUnitsControls()
{
    QCOMPARE(m_dock->objectName(), QStringLiteral("packmlSimulationDock"));
    QCOMPARE(m_dock->windowTitle(), PackmlSimulationDock::title());
    QVERIFY(m_dock->startButton()->isVisible());
    QVERIFY(!m_dock->commandButton(Command::Reset));
    start();
    QVERIFY(!m_dock->startButton()->isVisible());
    // Edition 2015: nine commands, no Complete.
    for (Command command : {Command::Reset, Command::Start, Command::Stop, Command::Hold, Command::Unhold,
                            Command::Suspend, Command::Unsuspend, Command::Abort, Command::Clear})
        QVERIFY(m_dock->commandButton(command));
    QVERIFY(!m_dock->commandButton(Command::Complete));
    QCOMPARE(m_dock->modeSelector()->count(), 2);
    QCOMPARE(m_dock->modeSelector()->currentText(), QStringLiteral("1 Production"));
    QCOMPARE(m_dock->modeSelector()->itemText(1), QStringLiteral("3 Manual"));
    QVERIFY(m_dock->inputToggle(QStringLiteral("Homed")));
    QVERIFY(m_dock->inputToggle(QStringLiteral("CmdChangeRequest")));
    QVERIFY(m_dock->inputField(QStringLiteral("CntrlCmd")));
    QVERIFY(m_dock->outputLamp(QStringLiteral("HomeAxis")));
    QVERIFY(m_dock->outputValue(QStringLiteral("StateCurrent")));
    QCOMPARE(m_dock->statusLabel()->text(), QStringLiteral("Scan 0: Stopped in Production"));
}

void TestPackmlSimulationDock::commandButtonsPlayTheCapper()
{
    start();
    QTest::mouseClick(m_dock->commandButton(Command::Reset), Qt::LeftButton);
    QCOMPARE(m_dock->requestLabel()->text(), QStringLiteral("Reset: requested, read by the next scan"));
    QTest::mouseClick(m_dock->stepButton(), Qt::LeftButton);
    QCOMPARE(m_dock->statusLabel()->text(), QStringLiteral("Scan 1: Resetting in Production"));
    QCOMPARE(m_dock->requestLabel()->text(), QStringLiteral("Reset: fired Stopped-Reset->Resetting"));
    QTest::mouseClick(m_dock->inputToggle(QStringLiteral("Homed")), Qt::LeftButton);
    QCOMPARE(m_session->simulator()->value("Homed"), std::optional<core::cond::Value>(true));
    QTest::mouseClick(m_dock->stepButton(), Qt::LeftButton);
    QCOMPARE(m_session->simulator()->state(), State::Idle);
    QTest::mouseClick(m_dock->commandButton(Command::Hold), Qt::LeftButton);
    QTest::mouseClick(m_dock->stepButton(), Qt::LeftButton);
    QCOMPARE(m_dock->requestLabel()->text(), QStringLiteral("Hold is not accepted in Idle"));
    // The trace: one row per scan, the drop and its reason in words.
    QCOMPARE(m_dock->traceModel()->rowCount(), 3);
    QCOMPARE(traceCell(0, PackmlTraceModel::FiredColumn), QStringLiteral("Stopped-Reset->Resetting"));
    QCOMPARE(traceCell(1, PackmlTraceModel::StateColumn), QStringLiteral("Idle"));
    QCOMPARE(traceCell(2, PackmlTraceModel::ModeColumn), QStringLiteral("Production"));
    QCOMPARE(traceCell(2, PackmlTraceModel::DroppedColumn), QStringLiteral("Hold is not accepted in Idle"));
    QCOMPARE(m_dock->traceView()->selectionModel()->selectedRows().value(0).row(), 2);
}

void TestPackmlSimulationDock::acceptedCommandsAreBold()
{
    start();
    // Stopped in Production: Reset and Abort are accepted, Start is not.
    QVERIFY(m_dock->isCommandAccepted(Command::Reset));
    QVERIFY(m_dock->commandButton(Command::Reset)->font().bold());
    QVERIFY(m_dock->isCommandAccepted(Command::Abort));
    QVERIFY(!m_dock->isCommandAccepted(Command::Start));
    QVERIFY(!m_dock->commandButton(Command::Start)->font().bold());
    QVERIFY(m_dock->commandButton(Command::Start)->isEnabled()); // pressed, it says why it is dropped
    QTest::mouseClick(m_dock->commandButton(Command::Reset), Qt::LeftButton);
    QTest::mouseClick(m_dock->inputToggle(QStringLiteral("Homed")), Qt::LeftButton);
    m_session->advance(2);
    QCOMPARE(m_session->simulator()->state(), State::Idle);
    QVERIFY(m_dock->commandButton(Command::Start)->font().bold());
    QVERIFY(!m_dock->commandButton(Command::Reset)->font().bold());
}

void TestPackmlSimulationDock::modeSelectorRequestsAMode()
{
    start();
    QComboBox* selector = m_dock->modeSelector();
    selector->setCurrentIndex(1);
    emit selector->activated(1); // as a pick in the list does
    QCOMPARE(m_dock->requestLabel()->text(), QStringLiteral("Manual: requested, read by the next scan"));
    QTest::mouseClick(m_dock->stepButton(), Qt::LeftButton);
    QCOMPARE(m_session->simulator()->mode(), 3);
    QCOMPARE(selector->currentText(), QStringLiteral("3 Manual"));
    QCOMPARE(m_dock->requestLabel()->text(), QStringLiteral("Manual: granted"));
    QCOMPARE(m_dock->statusLabel()->text(), QStringLiteral("Scan 1: Stopped in Manual"));
    QCOMPARE(traceCell(0, PackmlTraceModel::FiredColumn), QStringLiteral("mode Production → Manual"));
}

void TestPackmlSimulationDock::packTagsFieldsDriveTheRequestsByHand()
{
    start();
    QLineEdit* command = m_dock->inputField(QStringLiteral("CntrlCmd"));
    command->setFocus();
    command->selectAll();
    QTest::keyClicks(command, QStringLiteral("1"));
    QTest::keyClick(command, Qt::Key_Return);
    QCOMPARE(m_session->simulator()->value("CntrlCmd"), std::optional<core::cond::Value>(std::int64_t(1)));
    QTest::mouseClick(m_dock->inputToggle(QStringLiteral("CmdChangeRequest")), Qt::LeftButton);
    QTest::mouseClick(m_dock->stepButton(), Qt::LeftButton);
    QCOMPARE(m_session->simulator()->state(), State::Resetting);
    // A value that does not fit is refused and the field shows the value again.
    command->setFocus();
    command->selectAll();
    QTest::keyClicks(command, QStringLiteral("TRUE"));
    QTest::keyClick(command, Qt::Key_Return);
    QVERIFY(!command->toolTip().isEmpty());
    command->clearFocus();
    m_session->stepOnce();
    QCOMPARE(command->text(), QStringLiteral("1"));
}

void TestPackmlSimulationDock::outputsAsLampsAndValues()
{
    start();
    QVERIFY(!m_dock->outputLamp(QStringLiteral("HomeAxis"))->isOn());
    QCOMPARE(m_dock->outputValue(QStringLiteral("StateCurrent"))->text(), QStringLiteral("2"));
    QTest::mouseClick(m_dock->commandButton(Command::Reset), Qt::LeftButton);
    m_session->advance(2);
    QVERIFY(m_dock->outputLamp(QStringLiteral("HomeAxis"))->isOn());
    QCOMPARE(m_dock->outputValue(QStringLiteral("StateCurrent"))->text(), QStringLiteral("15"));
}

void TestPackmlSimulationDock::functionBlockOfTheCurrentState()
{
    start();
    QCOMPARE(m_dock->instanceLabel()->text(), QStringLiteral("Stopped is a wait state: no function block runs in it"));
    QTest::mouseClick(m_dock->commandButton(Command::Reset), Qt::LeftButton);
    m_session->advance(2);
    QCOMPARE(m_dock->instanceLabel()->text(), QStringLiteral("Production_Resetting: active steps 1, Complete = FALSE"));
    QVERIFY(m_dock->completeCombo()->isHidden()); // its GRAFCET writes Complete
}

// Manual's Execute has no GRAFCET: its SC, FALSE from the skeleton, set TRUE by hand and back.
void TestPackmlSimulationDock::completeOfASkeletonSetByHand()
{
    start();
    m_session->requestMode(3);
    m_session->stepOnce();
    QTest::mouseClick(m_dock->commandButton(Command::Reset), Qt::LeftButton);
    m_session->advance(2);
    QTest::mouseClick(m_dock->commandButton(Command::Start), Qt::LeftButton);
    m_session->advance(2);
    QCOMPARE(m_session->simulator()->state(), State::Execute);
    QCOMPARE(m_dock->instanceLabel()->text(), QStringLiteral("Manual_Execute runs no GRAFCET: Complete = FALSE"));
    QVERIFY(!m_dock->completeCombo()->isHidden());
    QCOMPARE(m_dock->completeCombo()->currentIndex(), 0);
    m_dock->completeCombo()->setCurrentIndex(1);
    emit m_dock->completeCombo()->activated(1);
    QCOMPARE(m_session->simulator()->manualComplete(m_session->currentInstance()), std::optional<bool>(true));
    m_session->stepOnce();
    QCOMPARE(m_dock->instanceLabel()->text(), QStringLiteral("Manual_Execute runs no GRAFCET: Complete = TRUE"));
    QCOMPARE(m_dock->completeCombo()->currentIndex(), 1);
    // Manual disables Completing: the SC leads nowhere, Execute stays.
    QCOMPARE(m_session->simulator()->state(), State::Execute);
    emit m_dock->completeCombo()->activated(0);
    QCOMPARE(m_session->simulator()->manualComplete(m_session->currentInstance()), std::nullopt);
    m_session->stepOnce();
    QCOMPARE(m_dock->completeCombo()->currentIndex(), 0);
}

void TestPackmlSimulationDock::historyButtonsShowPastScans()
{
    start();
    QVERIFY(!m_dock->stepBackButton()->isEnabled());
    QTest::mouseClick(m_dock->commandButton(Command::Reset), Qt::LeftButton);
    m_session->advance(3);
    QTest::mouseClick(m_dock->stepBackButton(), Qt::LeftButton);
    QTest::mouseClick(m_dock->stepBackButton(), Qt::LeftButton);
    QCOMPARE(m_dock->statusLabel()->text(), QStringLiteral("Scan 1: Resetting in Production (history; the latest scan is 3)"));
    QCOMPARE(m_dock->traceView()->selectionModel()->selectedRows().value(0).row(), 0);
    QVERIFY(m_dock->stepForwardButton()->isEnabled());
    QTest::mouseClick(m_dock->stepForwardButton(), Qt::LeftButton);
    QTest::mouseClick(m_dock->stepForwardButton(), Qt::LeftButton);
    QVERIFY(!m_dock->stepForwardButton()->isEnabled());
    QCOMPARE(m_dock->statusLabel()->text(), QStringLiteral("Scan 3: Resetting in Production"));
    // A click on a row of the trace shows its scan.
    QTableView* trace = m_dock->traceView();
    const QRect row = trace->visualRect(m_dock->traceModel()->index(1, PackmlTraceModel::StateColumn));
    QTest::mouseClick(trace->viewport(), Qt::LeftButton, {}, row.center());
    QCOMPARE(m_session->viewedScan(), 2);
}

void TestPackmlSimulationDock::runButtonRunsAndPauses()
{
    start();
    m_dock->speedSpin()->setValue(1000);
    QCOMPARE(m_session->speed(), 1000);
    QTest::mouseClick(m_dock->runButton(), Qt::LeftButton);
    QVERIFY(m_session->isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(m_session->latestScan() >= 50, 5000);
    QTest::mouseClick(m_dock->runButton(), Qt::LeftButton);
    QVERIFY(!m_session->isRunning());
    QTest::mouseClick(m_dock->resetButton(), Qt::LeftButton);
    QCOMPARE(m_session->latestScan(), 0);
    QCOMPARE(m_dock->traceModel()->rowCount(), 0);
}

void TestPackmlSimulationDock::scenarioReplayedWithItsResult()
{
    start();
    writeScenario(QStringLiteral("good.scenario"), "at 1: command Reset\n"
                                                   "at 2: set Homed = TRUE\n"
                                                   "at 2: expect state Idle\n"
                                                   "at 3: expect mode Production\n");
    QVERIFY(m_dock->replayFile(m_dir.filePath(QStringLiteral("good.scenario"))));
    QCOMPARE(m_dock->replayLabel()->text(), QStringLiteral("Replaying good.scenario: scan 0 of 3"));
    m_session->advance(10);
    QCOMPARE(m_dock->replayLabel()->text(), QStringLiteral("good.scenario passed: all 2 expectation(s) met"));
    QCOMPARE(m_dock->failureList()->count(), 0);

    writeScenario(QStringLiteral("bad.scenario"), "at 1: command Reset\n"
                                                  "at 1: expect state Idle\n");
    QVERIFY(m_dock->replayFile(m_dir.filePath(QStringLiteral("bad.scenario"))));
    m_session->advance(10);
    QCOMPARE(m_dock->replayLabel()->text(), QStringLiteral("bad.scenario failed: 1 of 1 expectation(s) did not hold"));
    QCOMPARE(m_dock->failureList()->count(), 1);
    QCOMPARE(m_dock->failureList()->item(0)->text(), QStringLiteral("scan 1: expected state Idle, the state is Resetting"));
}

void TestPackmlSimulationDock::scenarioThatDoesNotFitIsExplained()
{
    start();
    writeScenario(QStringLiteral("wrong.scenario"), "at 1: mode Automatic\n");
    QVERIFY(!m_dock->replayFile(m_dir.filePath(QStringLiteral("wrong.scenario"))));
    QVERIFY2(m_dock->replayLabel()->text().contains(QStringLiteral("unknown unit mode 'Automatic'")),
             qPrintable(m_dock->replayLabel()->text()));
}

void TestPackmlSimulationDock::endButtonEndsTheSimulation()
{
    start();
    QVERIFY(m_document->isReadOnly());
    QTest::mouseClick(m_dock->findChild<QToolButton*>(QStringLiteral("endButton")), Qt::LeftButton);
    QVERIFY(!m_session->isActive());
    QVERIFY(!m_document->isReadOnly());
    QVERIFY(!m_dock->commandButton(Command::Reset));
    QVERIFY(m_dock->startButton()->isVisible());
}

void TestPackmlSimulationDock::divisionByZeroStopsTheRunAndSaysWhere()
{
    core::Model model = core::packml::newModel(core::packml::Edition::Y2015);
    for (const char* name : {"Count", "Batch"})
        QVERIFY(model.addVariable({name, core::IecType::Int, {}, {}, core::VariableKind::Input}).ok);
    QVERIFY(model.setCommandCondition(Command::Reset, "Count / Batch > 1").ok);
    cleanup();
    m_document = std::make_unique<Document>(model);
    m_session = std::make_unique<PackmlSimulationSession>(m_document.get());
    m_dock = std::make_unique<PackmlSimulationDock>(m_session.get(), m_document.get());
    start();
    QTest::mouseClick(m_dock->stepButton(), Qt::LeftButton);
    QVERIFY(m_session->simulator()->fault().has_value());
    const QString status = m_dock->statusLabel()->text();
    QVERIFY2(status.contains(QStringLiteral("Stopped at scan 1: integer division by zero in the condition of the Reset "
                                            "command (Count / Batch in 'Count / Batch > 1')")),
             qPrintable(status));
    // No scan runs until a reset.
    m_session->advance(3);
    QCOMPARE(m_session->latestScan(), 1);
    QTest::mouseClick(m_dock->resetButton(), Qt::LeftButton);
    QVERIFY(!m_session->simulator()->fault().has_value());
}

QTEST_MAIN(TestPackmlSimulationDock)
#include "test_packmlsimulationdock.moc"
