// The PackML simulation session (issue 34, Simulation): commands and mode
// requests through the PackTags requests for one scan, inputs, run at a
// speed, history, reset, replay of a scenario with its expectations, the
// drop reasons worded, on the Capper of spec §6.6.

#include "packmlcappermodel.h"
#include "editor/document.h"
#include "editor/simulation/packml/packmlsimulationsession.h"
#include "editor/simulation/packml/packmlsimulationtext.h"

#include "core/formats/modelfiles.h"

#include <QSignalSpy>
#include <QTest>

#include <memory>

using namespace editor;
using core::packml::Command;
using core::packml::State;

namespace {

using packmltest::capper;

using packmltest::kManual;
using packmltest::kProduction;

// The Capper's walk of the core's scenario test, as a scenario file.
constexpr const char* kCapperScenario = "at 1: command Reset\n"
                                        "at 1: expect fired Stopped-Reset->Resetting\n"
                                        "at 2: expect variable HomeAxis = TRUE\n"
                                        "at 4: set Homed = TRUE\n"
                                        "at 4: expect state Idle\n"
                                        "at 6: command Start\n"
                                        "at 6: expect state Execute\n"
                                        "at 8: mode Manual\n"
                                        "at 8: expect mode Production\n"
                                        "at 10: command Stop\n"
                                        "at 10: expect state Stopped\n"
                                        "at 12: mode Manual\n"
                                        "at 12: expect mode Manual\n"
                                        "at 14: command Reset\n"
                                        "at 14: expect state Idle\n";

QString outcomeOf(const PackmlSimulationSession& session)
{
    const auto& request = session.lastRequest();
    if (!request || !request->record)
        return {};
    const auto kind = request->kind == PackmlSimulationSession::RequestKind::Mode ? PackmlRequestKind::Mode
                                                                                  : PackmlRequestKind::Command;
    return packmlRequestOutcomeText(kind, request->number, *request->record, session.simulator()->program());
}

} // namespace

class TestPackmlSimulation : public QObject {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void activeLocksTheDocumentAndStartsInTheInitialState();
    void capperThroughCommandsAndModes();
    void aPressRightAfterAnotherWaitsAScan();
    void aPressAfterARequestByHandWaitsAScan();
    void aPressAfterAReplaysCommandWaitsAScan();
    void droppedCommandIsWorded();
    void refusedModeNamesWhereItIsGranted();
    void inputsRefusedWithTheirReason();
    void manualCompleteOnlyWithoutGrafcet();
    void historyShowsRecordedScans();
    void playingFromAPastScanDropsWhatFollowed();
    void resetGoesBackToTheStart();
    void runsAtItsSpeed();
    void replayOfTheCapperScenarioPasses();
    void replayReportsFailedExpectations();
    void replayRefusesAScenarioThatDoesNotFit();
    void aPressEndsTheReplay();
    void aNewModelEndsTheSimulation();
    void aGemmaModelIsNotSimulatedHere();

private:
    void stepTo(std::int64_t scan);

    std::unique_ptr<Document> m_document;
    std::unique_ptr<PackmlSimulationSession> m_session;
};

void TestPackmlSimulation::init()
{
    m_document = std::make_unique<Document>(capper());
    m_session = std::make_unique<PackmlSimulationSession>(m_document.get());
    m_session->setActive(true);
}

void TestPackmlSimulation::cleanup()
{
    m_session.reset();
    m_document.reset();
}

void TestPackmlSimulation::stepTo(std::int64_t scan)
{
    m_session->advance(scan - m_session->latestScan());
    QCOMPARE(m_session->latestScan(), scan);
}

void TestPackmlSimulation::activeLocksTheDocumentAndStartsInTheInitialState()
{
    QVERIFY(m_document->isReadOnly());
    QCOMPARE(m_session->simulator()->state(), State::Stopped);
    QCOMPARE(m_session->simulator()->mode(), kProduction);
    QCOMPARE(m_session->latestScan(), 0);
    QVERIFY(m_session->shownRecord() == nullptr);
    QSignalSpy active(m_session.get(), &PackmlSimulationSession::activeChanged);
    m_session->setActive(false);
    QVERIFY(!m_document->isReadOnly());
    QVERIFY(m_session->simulator() == nullptr);
    QCOMPARE(active.count(), 1);
}

// The walk of spec §6.6's Capper through the PackTags requests.
void TestPackmlSimulation::capperThroughCommandsAndModes()
{
    m_session->pressCommand(Command::Reset);
    stepTo(1);
    QCOMPARE(m_session->simulator()->state(), State::Resetting);
    QCOMPARE(outcomeOf(*m_session), QStringLiteral("Reset: fired Stopped-Reset->Resetting"));
    // The request rose for that scan only.
    QCOMPARE(m_session->simulator()->value("CmdChangeRequest"), std::optional<core::cond::Value>(false));
    stepTo(2);
    QCOMPARE(m_session->simulator()->value("HomeAxis"), std::optional<core::cond::Value>(true));
    stepTo(3);
    QVERIFY(m_session->setInput(QStringLiteral("Homed"), true));
    stepTo(4);
    QCOMPARE(m_session->simulator()->state(), State::Idle);
    stepTo(5);
    m_session->pressCommand(Command::Start);
    stepTo(6);
    QCOMPARE(m_session->simulator()->state(), State::Execute);
    stepTo(7);
    QCOMPARE(m_session->simulator()->value("Cap"), std::optional<core::cond::Value>(true));
    m_session->requestMode(kManual);
    stepTo(8);
    QCOMPARE(m_session->simulator()->mode(), kProduction);
    stepTo(9);
    m_session->pressCommand(Command::Stop);
    stepTo(10);
    QCOMPARE(m_session->simulator()->state(), State::Stopped);
    stepTo(11);
    m_session->requestMode(kManual);
    stepTo(12);
    QCOMPARE(m_session->simulator()->mode(), kManual);
    QCOMPARE(outcomeOf(*m_session), QStringLiteral("Manual: granted"));
    stepTo(13);
    m_session->pressCommand(Command::Reset);
    stepTo(14);
    QCOMPARE(m_session->simulator()->state(), State::Idle); // Manual skips Resetting
    QCOMPARE(m_session->trace().size(), std::size_t(14));
    QVERIFY(m_session->trace()[13].fired.has_value());
}

// The request tag was TRUE in scan 1: it must be FALSE for a scan before it
// can rise again, so the Stop pressed after scan 1 is read by scan 3.
void TestPackmlSimulation::aPressRightAfterAnotherWaitsAScan()
{
    m_session->pressCommand(Command::Reset);
    stepTo(1);
    m_session->pressCommand(Command::Stop);
    stepTo(2);
    QCOMPARE(m_session->simulator()->state(), State::Resetting);
    QVERIFY(!m_session->lastRequest()->record);
    stepTo(3);
    QCOMPARE(m_session->simulator()->state(), State::Stopped);
    QCOMPARE(m_session->lastRequest()->record->scan, 3);
    QCOMPARE(outcomeOf(*m_session), QStringLiteral("Stop: fired Resetting-Stop->Stopped"));
}

// The same with CmdChangeRequest raised by hand, as an HMI would.
void TestPackmlSimulation::aPressAfterARequestByHandWaitsAScan()
{
    QVERIFY(m_session->setInputText(QStringLiteral("CntrlCmd"), QStringLiteral("1")));
    QVERIFY(m_session->setInput(QStringLiteral("CmdChangeRequest"), true));
    stepTo(1);
    QCOMPARE(m_session->simulator()->state(), State::Resetting);
    QVERIFY(m_session->setInput(QStringLiteral("CmdChangeRequest"), false));
    m_session->pressCommand(Command::Stop);
    stepTo(2);
    QCOMPARE(m_session->simulator()->state(), State::Resetting);
    stepTo(3);
    QCOMPARE(m_session->simulator()->state(), State::Stopped);
}

// And after a command of a replay, in its last scan.
void TestPackmlSimulation::aPressAfterAReplaysCommandWaitsAScan()
{
    QVERIFY(m_session->startReplayText("at 1: command Reset\n", QStringLiteral("s"), nullptr));
    stepTo(1);
    QCOMPARE(m_session->replayState(), PackmlSimulationSession::ReplayState::Finished);
    m_session->pressCommand(Command::Stop);
    stepTo(2);
    QCOMPARE(m_session->simulator()->state(), State::Resetting);
    stepTo(3);
    QCOMPARE(m_session->simulator()->state(), State::Stopped);
}

void TestPackmlSimulation::droppedCommandIsWorded()
{
    m_session->pressCommand(Command::Hold);
    stepTo(1);
    QCOMPARE(m_session->simulator()->state(), State::Stopped);
    QCOMPARE(outcomeOf(*m_session), QStringLiteral("Hold is not accepted in Stopped"));
    const core::packml::PackmlScanRecord* record = m_session->shownRecord();
    QVERIFY(record);
    // The Capper's NOT KeyManual requests Production, the current mode, in scan 1: said too.
    QCOMPARE(record->dropped.size(), std::size_t(2));
    QCOMPARE(packmlDroppedText(record->dropped[0], m_session->simulator()->program()),
             QStringLiteral("Production is requested: it is already the current mode"));
}

void TestPackmlSimulation::refusedModeNamesWhereItIsGranted()
{
    m_session->pressCommand(Command::Reset);
    QVERIFY(m_session->setInput(QStringLiteral("Homed"), true));
    stepTo(2);
    QCOMPARE(m_session->simulator()->state(), State::Idle);
    m_session->pressCommand(Command::Start);
    stepTo(4);
    QCOMPARE(m_session->simulator()->state(), State::Execute);
    m_session->requestMode(kManual);
    stepTo(5);
    QCOMPARE(m_session->simulator()->mode(), kProduction);
    const QString text = outcomeOf(*m_session);
    QVERIFY2(text.startsWith(QStringLiteral("Manual cannot be entered in Execute: Production allows no mode change "
                                            "there; it can be entered in Stopped")),
             qPrintable(text));
}

void TestPackmlSimulation::inputsRefusedWithTheirReason()
{
    QString error;
    QVERIFY(!m_session->setInput(QStringLiteral("HomeAxis"), true, &error)); // an output
    QVERIFY(!error.isEmpty());
    QVERIFY(m_session->setInputText(QStringLiteral("CntrlCmd"), QStringLiteral("1")));
    QVERIFY(m_session->setInputText(QStringLiteral("CmdChangeRequest"), QStringLiteral("TRUE")));
    stepTo(1);
    QCOMPARE(m_session->simulator()->state(), State::Resetting); // the raw PackTags request
}

void TestPackmlSimulation::manualCompleteOnlyWithoutGrafcet()
{
    QCOMPARE(m_session->currentInstance(), -1); // Stopped: a wait state
    m_session->pressCommand(Command::Reset);
    stepTo(1);
    const int resetting = m_session->currentInstance();
    QVERIFY(resetting >= 0);
    QCOMPARE(m_session->simulator()->program().instances[std::size_t(resetting)].name, std::string("Production_Resetting"));
    QString error;
    QVERIFY(!m_session->setManualComplete(resetting, true, &error)); // its GRAFCET writes Complete
    QVERIFY(!error.isEmpty());
    const auto* manualExecute = m_session->simulator()->program().instance(kManual, State::Execute);
    const int index = static_cast<int>(manualExecute - m_session->simulator()->program().instances.data());
    QVERIFY(m_session->setManualComplete(index, true));
    QCOMPARE(m_session->simulator()->manualComplete(index), std::optional<bool>(true));
    // A replay starts with every SC from its skeleton.
    QVERIFY(m_session->startReplayText("at 1: expect state Stopped\n", QStringLiteral("s"), nullptr));
    QCOMPARE(m_session->simulator()->manualComplete(index), std::nullopt);
}

void TestPackmlSimulation::historyShowsRecordedScans()
{
    m_session->pressCommand(Command::Reset);
    QVERIFY(m_session->setInput(QStringLiteral("Homed"), true));
    stepTo(3);
    QCOMPARE(m_session->simulator()->state(), State::Idle);
    QSignalSpy moved(m_session.get(), &PackmlSimulationSession::historyMoved);
    m_session->stepBack();
    m_session->stepBack();
    QVERIFY(m_session->isViewingHistory());
    QCOMPARE(m_session->viewedScan(), 1);
    QCOMPARE(m_session->simulator()->state(), State::Resetting);
    QCOMPARE(m_session->shownRecord()->scan, 1);
    QCOMPARE(m_session->liveSimulator()->scanCount(), 3);
    m_session->stepForward();
    m_session->stepForward();
    QVERIFY(!m_session->isViewingHistory());
    QCOMPARE(m_session->simulator()->state(), State::Idle);
    QCOMPARE(moved.count(), 4);
    m_session->showScan(0);
    QVERIFY(!m_session->canStepBack());
    QCOMPARE(m_session->simulator()->state(), State::Stopped);
}

void TestPackmlSimulation::playingFromAPastScanDropsWhatFollowed()
{
    m_session->pressCommand(Command::Reset);
    stepTo(3);
    m_session->showScan(1);
    m_session->pressCommand(Command::Stop); // from scan 1: scans 2 and 3 go
    QCOMPARE(m_session->latestScan(), 1);
    QCOMPARE(m_session->trace().size(), std::size_t(1));
    // The request was TRUE in scan 1: the Stop waits for scan 3.
    stepTo(3);
    QCOMPARE(m_session->simulator()->state(), State::Stopped);
    QCOMPARE(m_session->lastRequest()->record->scan, 3);
}

void TestPackmlSimulation::resetGoesBackToTheStart()
{
    m_session->pressCommand(Command::Reset);
    stepTo(2);
    QSignalSpy reset(m_session.get(), &PackmlSimulationSession::wasReset);
    m_session->reset();
    QCOMPARE(reset.count(), 1);
    QCOMPARE(m_session->latestScan(), 0);
    QCOMPARE(m_session->simulator()->state(), State::Stopped);
    QVERIFY(m_session->trace().empty());
    QVERIFY(!m_session->lastRequest());
    QVERIFY(!m_session->canStepBack());
}

void TestPackmlSimulation::runsAtItsSpeed()
{
    m_session->setSpeed(1000);
    QCOMPARE(m_session->speed(), 1000);
    m_session->setSpeed(1'000'000);
    QCOMPARE(m_session->speed(), PackmlSimulationSession::kMaxSpeed);
    QSignalSpy running(m_session.get(), &PackmlSimulationSession::runningChanged);
    m_session->run();
    QVERIFY(m_session->isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(m_session->latestScan() >= 100, 5000);
    m_session->pause();
    QVERIFY(!m_session->isRunning());
    QCOMPARE(running.count(), 2);
}

void TestPackmlSimulation::replayOfTheCapperScenarioPasses()
{
    QString error;
    QVERIFY2(m_session->startReplayText(kCapperScenario, QStringLiteral("capper.scenario"), &error), qPrintable(error));
    QVERIFY(m_session->isReplaying());
    QCOMPARE(m_session->replayLength(), 14);
    QCOMPARE(m_session->replayExpectationCount(), 8);
    m_session->advance(100);
    QCOMPARE(m_session->latestScan(), 14); // the replay stops at its last scan
    QCOMPARE(m_session->replayState(), PackmlSimulationSession::ReplayState::Finished);
    QVERIFY(m_session->replayFailures().empty());
    QCOMPARE(m_session->simulator()->state(), State::Idle);
    QCOMPARE(m_session->simulator()->mode(), kManual);
}

void TestPackmlSimulation::replayReportsFailedExpectations()
{
    QString error;
    QVERIFY(m_session->startReplayText("at 1: command Reset\n"
                                       "at 2: expect state Idle\n"
                                       "at 2: expect mode Manual\n",
                                       QStringLiteral("wrong.scenario"), &error));
    m_session->advance(2);
    QCOMPARE(m_session->replayState(), PackmlSimulationSession::ReplayState::Finished);
    QCOMPARE(m_session->replayFailures().size(), std::size_t(2));
    QCOMPARE(packmlScenarioFailureText(m_session->replayFailures()[0]),
             QStringLiteral("scan 2: expected state Idle, the state is Resetting"));
    QCOMPARE(packmlScenarioFailureText(m_session->replayFailures()[1]),
             QStringLiteral("scan 2: expected mode Manual, the mode is Production"));
    // Back to scan 1 and played on: the failures of scan 2 are checked again, once.
    m_session->showScan(1);
    m_session->stepOnce();
    QCOMPARE(m_session->replayFailures().size(), std::size_t(2));
}

void TestPackmlSimulation::replayRefusesAScenarioThatDoesNotFit()
{
    QString error;
    QVERIFY(!m_session->startReplayText("at 1: command Jump\n", QStringLiteral("bad.scenario"), &error));
    QVERIFY2(error.contains(QStringLiteral("unknown command 'Jump'")), qPrintable(error));
    QCOMPARE(m_session->replayState(), PackmlSimulationSession::ReplayState::None);
}

void TestPackmlSimulation::aPressEndsTheReplay()
{
    QVERIFY(m_session->startReplayText(kCapperScenario, QStringLiteral("capper.scenario"), nullptr));
    m_session->advance(2);
    m_session->pressCommand(Command::Stop);
    QCOMPARE(m_session->replayState(), PackmlSimulationSession::ReplayState::None);
    stepTo(4);
    QCOMPARE(m_session->simulator()->state(), State::Stopped);
}

void TestPackmlSimulation::aNewModelEndsTheSimulation()
{
    m_document->replaceModel(capper(), QString(), core::ModelFormat::Native);
    QVERIFY(!m_session->isActive());
    QVERIFY(!m_document->isReadOnly());
}

void TestPackmlSimulation::aGemmaModelIsNotSimulatedHere()
{
    m_session->setActive(false);
    m_document->newFromTemplate(); // GEMMA
    QSignalSpy active(m_session.get(), &PackmlSimulationSession::activeChanged);
    m_session->setActive(true);
    QVERIFY(!m_session->isActive());
    QVERIFY(!m_document->isReadOnly());
    QCOMPARE(active.count(), 0);
}

QTEST_MAIN(TestPackmlSimulation)
#include "test_packmlsimulation.moc"
