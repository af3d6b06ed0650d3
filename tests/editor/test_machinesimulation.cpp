// The editor's simulation in closed loop (issue 35): a model with a virtual
// machine runs through core::machine::MachineLoop, its sensors shown but not
// set in the Simulation dock, its state kept in the history, reset with the
// simulator, and the shipped closed-loop scenario replaying as the command
// line plays it.

#include "editortestsupport.h"

#include "editor/app/languages.h"
#include "editor/document.h"
#include "editor/mainwindow.h"
#include "editor/simulation/simulationdock.h"
#include "editor/simulation/simulationsession.h"

#include "core/condition/conditionevaluator.h"
#include "core/formats/fileio.h"
#include "core/formats/modelfiles.h"
#include "core/machine/machineloop.h"
#include "core/simulation/scenario.h"

#include <QAbstractButton>
#include <QAction>
#include <QLabel>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <memory>
#include <string>
#include <vector>

using namespace editor;

namespace {

constexpr std::size_t kClamp = 0; // component indices in the example's machine
constexpr std::size_t kDrillHead = 1;
constexpr std::size_t kInfeed = 2;

bool boolValue(const core::Simulator& simulator, const char* name)
{
    return core::cond::isTrue(simulator.variable(name));
}

std::vector<double> positions(const core::machine::MachineState& state)
{
    std::vector<double> all;
    for (std::size_t i = 0; i < state.componentCount(); ++i)
        all.push_back(state.position(i));
    return all;
}

} // namespace

class TestMachineSimulation : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();

    void machineSensorsAreShownNotSet();
    void scansMoveTheMachine();
    void replayReachesWhatTheCommandLineReaches();
    void historyRestoresTheMachine();
    void resetResetsTheMachineToo();
    void recordingHoldsTheOperatorOnly();
    void openLoopScenarioReplaysWithTheMachineStill();
    void modelWithoutMachineStaysOpenLoop();
    void changingTheMachineEndsTheSimulation();
    void sensorFaultFromTheDockMenu();
    void injectedFaultsAreRecordedAndReplayed();
    void historyRestoresTheFaultsOfThen();
    void jamStopsTheComponentUntilCleared();
    void noFaultWhileReplaying();
    void shippedFaultScenarioReplays();

private:
    void startOnDrillingCell();
    int index(const char* variable) const;
    void pressStart();
    // Replays a recording from scan 0 in closed loop: every expectation met.
    void replayRecording(const QString& text);

    QTemporaryDir m_settingsDir;
    std::unique_ptr<Translators> m_translators;
    std::unique_ptr<MainWindow> m_window;
    SimulationSession* m_session = nullptr;
    SimulationDock* m_dock = nullptr;
};

void TestMachineSimulation::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    editortest::useTestSettings(m_settingsDir.path(), QStringLiteral("test_machinesimulation"));
}

void TestMachineSimulation::init()
{
    m_window = editortest::showEnglishMainWindow(m_translators);
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    m_session = m_window->simulationSession();
    m_dock = m_window->findChild<SimulationDock*>(QStringLiteral("simulationDock"));
    QVERIFY(m_session && m_dock);
}

void TestMachineSimulation::cleanup()
{
    if (m_window)
        m_window->document()->undoStack()->setClean();
    m_window.reset();
    m_translators.reset();
}

void TestMachineSimulation::startOnDrillingCell()
{
    QString error;
    QVERIFY2(m_window->document()->load(QStringLiteral(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json"), &error),
             qPrintable(error));
    QVERIFY(!m_window->document()->model().machine().empty());
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    QVERIFY(m_session->isActive());
}

int TestMachineSimulation::index(const char* variable) const
{
    return m_session->liveSimulator()->variableIndex(variable);
}

// As the start scenario plays it: pressed before scan 1, released before scan 3.
void TestMachineSimulation::pressStart()
{
    QVERIFY(m_session->setVariable(index("StartButton"), true));
    m_session->advance(2);
    QVERIFY(m_session->setVariable(index("StartButton"), false));
}

void TestMachineSimulation::replayRecording(const QString& text)
{
    QString error;
    QVERIFY2(m_session->startReplayText(text.toStdString(), QStringLiteral("recorded.scenario"), &error),
             qPrintable(error));
    QVERIFY(!m_session->replayIsOpenLoop());
    m_session->advance(m_session->replayLength());
    QCOMPARE(m_session->replayState(), SimulationSession::ReplayState::Finished);
    QVERIFY(m_session->replayFailures().empty());
}

void TestMachineSimulation::machineSensorsAreShownNotSet()
{
    startOnDrillingCell();
    QVERIFY(m_session->hasMachine());
    QVERIFY(m_session->isClosedLoop());
    const core::Simulator& simulator = *m_session->simulator();
    // The machine at rest writes its sensors before scan 1.
    QVERIFY(boolValue(simulator, "DrillHigh"));
    QVERIFY(boolValue(simulator, "Unclamped"));
    QVERIFY(boolValue(simulator, "EmergencyOk")); // a normally closed stop, released

    for (const char* sensor : {"DrillHigh", "DrillLow", "Unclamped", "Clamped", "PartPresent", "InfeedEmpty"}) {
        QVERIFY2(m_session->isMachineDriven(index(sensor)), sensor);
        QVERIFY2(!m_dock->toggleButton(QLatin1String(sensor)), sensor);
        QVERIFY2(!m_dock->pressButton(QLatin1String(sensor)), sensor);
        auto* shown = m_dock->findChild<QLabel*>(QStringLiteral("shown_") + QLatin1String(sensor));
        QVERIFY2(shown, sensor);
        QVERIFY2(shown->toolTip().contains(QStringLiteral("machine")), qPrintable(shown->toolTip()));
    }
    QCOMPARE(m_dock->findChild<QLabel*>(QStringLiteral("shown_DrillHigh"))->text(), QStringLiteral("TRUE"));
    QCOMPARE(m_session->machineOwner(index("Clamped")), QStringLiteral("Clamp"));
    // The operator's inputs stay toggles and push buttons.
    for (const char* input : {"StartButton", "StopButton", "ResetButton", "EmergencyOk"}) {
        QVERIFY2(!m_session->isMachineDriven(index(input)), input);
        QVERIFY2(m_dock->toggleButton(QLatin1String(input)), input);
        QVERIFY2(m_dock->pressButton(QLatin1String(input)), input);
    }

    QString error;
    QVERIFY(!m_session->setVariable(index("DrillHigh"), false, &error));
    QVERIFY2(error.contains(QStringLiteral("DrillHead")), qPrintable(error));
    QVERIFY(boolValue(*m_session->simulator(), "DrillHigh"));
    m_session->press(index("Clamped"));
    QVERIFY(!boolValue(*m_session->simulator(), "Clamped"));
}

void TestMachineSimulation::scansMoveTheMachine()
{
    startOnDrillingCell();
    pressStart();
    m_session->advance(1004 - 2); // warmed up: F1, the infeed runs
    QCOMPARE(m_session->simulator()->activeStepId(), std::string("F1"));
    const core::machine::MachineState* machine = m_session->machineState();
    QVERIFY(machine);
    QVERIFY(machine->hasPart(kInfeed));
    const double before = machine->position(kInfeed);
    m_session->advance(60);
    QVERIFY(m_session->machineState()->position(kInfeed) > before);
    m_session->advance(1124 - 1064); // the part reaches the sensor: the clamp closes
    QVERIFY(boolValue(*m_session->simulator(), "PartPresent"));
    QVERIFY(boolValue(*m_session->simulator(), "ClampOut"));
    // The cycle after that scan already moved the clamp one step of its 30.
    QVERIFY(m_session->machineState()->position(kClamp) > 0.0);
    QVERIFY(m_session->machineState()->position(kClamp) < 0.1);
    m_session->advance(15);
    QVERIFY(m_session->machineState()->position(kClamp) > 0.4);
    QVERIFY(m_session->machineState()->position(kClamp) < 0.6);
    // The dock follows the machine's sensors.
    m_session->advance(15);
    QVERIFY(boolValue(*m_session->simulator(), "Clamped"));
    QCOMPARE(m_dock->findChild<QLabel*>(QStringLiteral("shown_Clamped"))->text(), QStringLiteral("TRUE"));
}

void TestMachineSimulation::replayReachesWhatTheCommandLineReaches()
{
    startOnDrillingCell();
    QString error;
    QVERIFY2(m_session->startReplay(QStringLiteral(GGSTUDIO_EXAMPLES_DIR "/drilling-cell-start.scenario"), &error),
             qPrintable(error));
    QVERIFY(!m_session->replayIsOpenLoop());
    m_session->advance(m_session->replayLength() + 10);
    QCOMPARE(m_session->replayState(), SimulationSession::ReplayState::Finished);
    QVERIFY(m_session->replayFailures().empty());

    // The command line's runner: core's closed-loop scenario run.
    std::string text;
    QVERIFY(core::readFileLimited(GGSTUDIO_EXAMPLES_DIR "/drilling-cell-start.scenario", 1u << 20, text));
    const core::ScenarioParseResult parsed = core::parseScenario(text, "drilling-cell-start.scenario");
    QVERIFY(parsed.ok());
    core::Simulator simulator(m_window->document()->model());
    core::machine::MachineLoop loop(simulator, m_window->document()->model().machine());
    const core::ScenarioRunResult result = core::runScenario(parsed.scenario, loop);
    QVERIFY(result.passed());

    const core::Simulator& editor = *m_session->simulator();
    QCOMPARE(editor.scanCount(), simulator.scanCount());
    QCOMPARE(editor.activeStepId(), simulator.activeStepId());
    QCOMPARE(editor.activeNestedSteps("F1"), simulator.activeNestedSteps("F1"));
    for (std::size_t i = 0; i < simulator.variableNames().size(); ++i)
        QVERIFY2(editor.variableValue(i) == simulator.variableValue(i), simulator.variableNames()[i].c_str());
    QCOMPARE(positions(*m_session->machineState()), positions(loop.state()));
    QCOMPARE(m_session->machineState()->partsDelivered(kInfeed), loop.state().partsDelivered(kInfeed));
    QCOMPARE(m_session->machineState()->partsDelivered(kInfeed), std::int64_t{1});
}

void TestMachineSimulation::historyRestoresTheMachine()
{
    startOnDrillingCell();
    pressStart();
    m_session->advance(1130 - 2); // the clamp is closing
    std::vector<std::vector<double>> seen;
    for (int i = 0; i < 10; ++i) {
        seen.push_back(positions(*m_session->machineState()));
        m_session->advance(1);
    }
    QVERIFY(seen.front()[kClamp] < seen.back()[kClamp]);
    const std::int64_t latest = m_session->latestScan();
    m_session->showScan(latest - 10);
    QVERIFY(m_session->isViewingHistory());
    QCOMPARE(positions(*m_session->machineState()), seen.front());
    m_session->stepForward();
    QCOMPARE(positions(*m_session->machineState()), seen[1]);
    // The running machine stays where the latest scan left it.
    QVERIFY(m_session->isClosedLoop());
    // Playing on from the past scan plays the machine on from there too.
    m_session->advance(1);
    QVERIFY(!m_session->isViewingHistory());
    QCOMPARE(m_session->latestScan(), latest - 8);
    QCOMPARE(positions(*m_session->machineState()), seen[2]);
    QCOMPARE(core::cond::isTrue(m_session->simulator()->variable("Clamped")), false);
    m_session->advance(40);
    QVERIFY(boolValue(*m_session->simulator(), "Clamped"));
}

void TestMachineSimulation::resetResetsTheMachineToo()
{
    startOnDrillingCell();
    pressStart();
    m_session->advance(1140);
    QVERIFY(m_session->machineState()->position(kClamp) > 0.0);
    m_session->reset();
    QCOMPARE(m_session->simulator()->scanCount(), std::int64_t{0});
    QCOMPARE(m_session->machineState()->position(kClamp), 0.0);
    QCOMPARE(m_session->machineState()->position(kDrillHead), 0.0);
    QVERIFY(boolValue(*m_session->simulator(), "Unclamped"));
    QVERIFY(!boolValue(*m_session->simulator(), "Clamped"));
    QVERIFY(!boolValue(*m_session->simulator(), "PartPresent"));
}

void TestMachineSimulation::recordingHoldsTheOperatorOnly()
{
    startOnDrillingCell();
    pressStart();
    m_session->advance(1200);
    const QString text = QString::fromStdString(m_session->recordingText());
    QVERIFY2(text.contains(QStringLiteral("set StartButton = TRUE")), qPrintable(text));
    for (const char* sensor : {"DrillHigh", "Unclamped", "PartPresent", "Clamped", "InfeedEmpty"})
        QVERIFY2(!text.contains(QStringLiteral("set ") + QLatin1String(sensor)), qPrintable(text));
    // The recording replays in closed loop, every expectation met.
    replayRecording(text);
}

void TestMachineSimulation::openLoopScenarioReplaysWithTheMachineStill()
{
    startOnDrillingCell();
    QString error;
    QVERIFY2(
        m_session->startReplay(QStringLiteral(GGSTUDIO_EXAMPLES_DIR "/drilling-cell-open-loop.scenario"), &error),
        qPrintable(error));
    QVERIFY(m_session->replayIsOpenLoop());
    QVERIFY(!m_session->isClosedLoop());
    QVERIFY2(m_dock->replayLabel()->text().contains(QStringLiteral("open loop")),
             qPrintable(m_dock->replayLabel()->text()));
    m_session->advance(m_session->replayLength());
    QCOMPARE(m_session->replayState(), SimulationSession::ReplayState::Finished);
    QVERIFY(m_session->replayFailures().empty());
    QCOMPARE(m_session->machineState()->position(kClamp), 0.0); // the scenario set Clamped itself
    m_session->reset();
    QVERIFY(m_session->isClosedLoop());
    QVERIFY(boolValue(*m_session->simulator(), "DrillHigh"));
}

void TestMachineSimulation::modelWithoutMachineStaysOpenLoop()
{
    const core::LoadedModel loaded = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    QVERIFY(loaded.model);
    QVERIFY(loaded.model->setMachine({}).ok);
    m_window->document()->replaceModel(*loaded.model, QString(), core::ModelFormat::Native);
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    QVERIFY(m_session->isActive());
    QVERIFY(!m_session->hasMachine());
    QVERIFY(!m_session->machineState());
    QVERIFY(!boolValue(*m_session->simulator(), "DrillHigh"));
    QVERIFY(m_dock->toggleButton(QStringLiteral("DrillHigh")));
    QVERIFY(m_session->setVariable(index("DrillHigh"), true));
}

void TestMachineSimulation::changingTheMachineEndsTheSimulation()
{
    startOnDrillingCell();
    core::machine::Machine machine = m_window->document()->model().machine();
    machine.components.pop_back();
    // As an undo command would, outside the simulation's read-only lock.
    QVERIFY(m_window->document()->modelForCommands().setMachine(machine).ok);
    QVERIFY(!m_session->isActive());
}

// Right-click a sensor in the Simulation dock: stuck at FALSE, shown struck
// through, and the program reads FALSE whatever the machine does.
void TestMachineSimulation::sensorFaultFromTheDockMenu()
{
    startOnDrillingCell();
    auto* label = m_dock->findChild<QLabel*>(QStringLiteral("fault_Unclamped"));
    QVERIFY(label);
    QVERIFY(label->isHidden());
    QVERIFY(boolValue(*m_session->simulator(), "Unclamped"));
    QWidget* cell = label->parentWidget();
    QCOMPARE(cell->contextMenuPolicy(), Qt::CustomContextMenu);
    bool found = false;
    editortest::triggerInNextMenu({}, QStringLiteral("Stuck at FALSE"), &found);
    emit cell->customContextMenuRequested(QPoint(2, 2));
    QVERIFY(found);
    QCOMPARE(m_session->sensorFault(index("Unclamped")), core::machine::SensorFault::StuckFalse);
    // The reading shows before the next scan, as a scenario's fault line does.
    QVERIFY(!boolValue(*m_session->simulator(), "Unclamped"));
    QVERIFY(!label->isHidden());
    QCOMPARE(label->text(), QStringLiteral("stuck at FALSE"));
    m_session->advance(5);
    QVERIFY(!boolValue(*m_session->simulator(), "Unclamped"));

    editortest::triggerInNextMenu({}, QStringLiteral("Clear Fault"), &found);
    emit cell->customContextMenuRequested(QPoint(2, 2));
    QVERIFY(found);
    QVERIFY(boolValue(*m_session->simulator(), "Unclamped"));
    QVERIFY(label->isHidden());
    // An operator input has no fault menu: the user drives it.
    QVERIFY(!m_dock->findChild<QLabel*>(QStringLiteral("fault_StartButton")));
}

// A fault injected by hand is a line of the recording, and the recording
// replays it: the watchdog-less drilling cell waits forever for Clamped.
void TestMachineSimulation::injectedFaultsAreRecordedAndReplayed()
{
    startOnDrillingCell();
    pressStart();
    m_session->advance(50);
    QVERIFY(m_session->injectFault({core::machine::FaultKind::StuckFalse, "Clamped"}));
    m_session->advance(1200);
    const std::string stepThen = m_session->simulator()->activeStepId();
    QVERIFY(!boolValue(*m_session->simulator(), "Clamped"));
    QVERIFY(boolValue(*m_session->simulator(), "ClampOut")); // still waiting for the clamp
    const QString text = QString::fromStdString(m_session->recordingText());
    QVERIFY2(text.contains(QStringLiteral("at 53: fault Clamped stuck FALSE")), qPrintable(text));

    replayRecording(text);
    QCOMPARE(m_session->simulator()->activeStepId(), stepThen);
    QCOMPARE(m_session->sensorFault(index("Clamped")), core::machine::SensorFault::StuckFalse);
}

// Stepping back before a fault shows the sensor sound again; playing on
// from there plays without it.
void TestMachineSimulation::historyRestoresTheFaultsOfThen()
{
    startOnDrillingCell();
    m_session->advance(5);
    QVERIFY(m_session->injectFault({core::machine::FaultKind::StuckTrue, "DrillLow"}));
    m_session->advance(5);
    QVERIFY(boolValue(*m_session->simulator(), "DrillLow"));
    m_session->showScan(3);
    QCOMPARE(m_session->sensorFault(index("DrillLow")), core::machine::SensorFault::None);
    QVERIFY(!boolValue(*m_session->simulator(), "DrillLow"));
    QVERIFY(m_dock->findChild<QLabel*>(QStringLiteral("fault_DrillLow"))->isHidden());
    m_session->showScan(8);
    QCOMPARE(m_session->sensorFault(index("DrillLow")), core::machine::SensorFault::StuckTrue);
    QVERIFY(!m_dock->findChild<QLabel*>(QStringLiteral("fault_DrillLow"))->isHidden());

    m_session->showScan(3);
    m_session->advance(2);
    QVERIFY(!m_session->isViewingHistory());
    QCOMPARE(m_session->latestScan(), std::int64_t{5});
    QCOMPARE(m_session->sensorFault(index("DrillLow")), core::machine::SensorFault::None);
    QVERIFY(!boolValue(*m_session->simulator(), "DrillLow"));
    const QString text = QString::fromStdString(m_session->recordingText());
    QVERIFY2(!text.contains(QStringLiteral("fault")), qPrintable(text));
}

// A jammed clamp stays open while the program drives it; cleared, it closes.
void TestMachineSimulation::jamStopsTheComponentUntilCleared()
{
    startOnDrillingCell();
    QVERIFY(m_session->injectFault({core::machine::FaultKind::Jam, "Clamp"}));
    pressStart();
    m_session->advance(1124 - 2 + 40); // the part arrived and ClampOut has been on for 40 scans
    QVERIFY(boolValue(*m_session->simulator(), "ClampOut"));
    QCOMPARE(m_session->machineState()->position(kClamp), 0.0);
    QVERIFY(m_session->machineState()->jammed(kClamp));
    QVERIFY(m_session->injectFault({core::machine::FaultKind::Clear, "Clamp"}));
    m_session->advance(40);
    QVERIFY(boolValue(*m_session->simulator(), "Clamped"));
    // A lamp cannot jam: told why, nothing changed.
    QString error;
    QVERIFY(!m_session->injectFault({core::machine::FaultKind::Jam, "Ready"}, &error));
    QVERIFY2(error.contains(QStringLiteral("only cylinders and conveyors jam")), qPrintable(error));
}

void TestMachineSimulation::noFaultWhileReplaying()
{
    startOnDrillingCell();
    QString error;
    QVERIFY2(m_session->startReplay(QStringLiteral(GGSTUDIO_EXAMPLES_DIR "/drilling-cell-start.scenario"), &error),
             qPrintable(error));
    QVERIFY(!m_session->canInjectFault());
    QVERIFY(!m_session->injectFault({core::machine::FaultKind::StuckTrue, "Clamped"}, &error));
    QVERIFY2(error.contains(QStringLiteral("replay")), qPrintable(error));
    QCOMPARE(m_session->sensorFault(index("Clamped")), core::machine::SensorFault::None);
}

// The watchdog example's scenario, with its fault line, replays in the
// editor as on the command line: every expectation met.
void TestMachineSimulation::shippedFaultScenarioReplays()
{
    QString error;
    QVERIFY2(m_window->document()->load(
                 QStringLiteral(GGSTUDIO_EXAMPLES_DIR "/drilling-cell-watchdog.ggstudio.json"), &error),
             qPrintable(error));
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    QVERIFY(m_session->isActive());
    QVERIFY2(m_session->startReplay(QStringLiteral(GGSTUDIO_EXAMPLES_DIR "/drilling-cell-clamp-fault.scenario"), &error),
             qPrintable(error));
    QVERIFY(!m_session->replayIsOpenLoop());
    QVERIFY(m_session->replayExpectationCount() > 5);
    m_session->advance(m_session->replayLength());
    QCOMPARE(m_session->replayState(), SimulationSession::ReplayState::Finished);
    QVERIFY(m_session->replayFailures().empty());

    // The same fault line in an open-loop scenario (one that sets a sensor) is refused, located.
    const std::string openLoop = "at 1: set Clamped = TRUE\nat 2: fault Unclamped stuck FALSE\n";
    QVERIFY(!m_session->startReplayText(openLoop, QStringLiteral("open.scenario"), &error));
    QVERIFY2(error.contains(QStringLiteral("open.scenario:2:")) && error.contains(QStringLiteral("virtual machine")),
             qPrintable(error));
}

QTEST_MAIN(TestMachineSimulation)
#include "test_machinesimulation.moc"
