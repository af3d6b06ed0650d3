// The PackML simulation on the PackML chart (issue 34, Simulation): the
// current state filled, the transition that fired green, the chart and its
// mode selector on the current mode, for the scan shown; on the Capper.

#include "packmlcappermodel.h"
#include "editor/chart/chartstyle.h"
#include "editor/chart/packml/packmlarrowitem.h"
#include "editor/chart/packml/packmlchartscene.h"
#include "editor/chart/packml/packmlchartview.h"
#include "editor/chart/packml/packmlstateitem.h"
#include "editor/document.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetstepitem.h"
#include "editor/grafcet/grafcettransitionitem.h"
#include "editor/simulation/packml/packmlgrafcetmarks.h"
#include "editor/selection.h"
#include "editor/simulation/packml/packmlsimulationmarks.h"
#include "editor/simulation/packml/packmlsimulationsession.h"

#include "core/formats/modelfiles.h"

#include <QComboBox>
#include <QTest>

#include <memory>

using namespace editor;
using core::packml::Command;
using core::packml::State;

namespace {

using packmltest::capper;

using packmltest::kManual;
using packmltest::kProduction;

} // namespace

class TestPackmlSimulationMarks : public QObject {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void currentStateIsFilled();
    void firedTransitionIsGreen();
    void stopFiresTheFramesArrow();
    void chartAndSelectorFollowTheCurrentMode();
    void historyShowsThePastScansMarks();
    void endingTheSimulationClearsTheMarks();
    void nestedGrafcetOfTheCurrentStateRuns();
    void nestedGrafcetOfAnotherStateIsGreyed();

private:
    QList<State> activeStates() const;
    int firedArrows() const;

    std::unique_ptr<Document> m_document;
    std::unique_ptr<Selection> m_selection;
    std::unique_ptr<PackmlChartScene> m_scene;
    std::unique_ptr<PackmlChartView> m_view;
    std::unique_ptr<PackmlSimulationSession> m_session;
    std::unique_ptr<PackmlSimulationMarks> m_marks;
};

void TestPackmlSimulationMarks::init()
{
    m_document = std::make_unique<Document>(capper());
    m_selection = std::make_unique<Selection>();
    m_scene = std::make_unique<PackmlChartScene>(&m_document->model(), m_selection.get());
    m_view = std::make_unique<PackmlChartView>(m_scene.get());
    m_session = std::make_unique<PackmlSimulationSession>(m_document.get());
    m_marks = std::make_unique<PackmlSimulationMarks>(m_session.get(), m_scene.get());
    m_session->setActive(true);
}

void TestPackmlSimulationMarks::cleanup()
{
    m_marks.reset();
    m_session.reset();
    m_view.reset();
    m_scene.reset();
    m_selection.reset();
    m_document.reset();
}

QList<State> TestPackmlSimulationMarks::activeStates() const
{
    QList<State> states;
    for (const PackmlStateItem* item : m_scene->states())
        if (item->isActiveInSimulation())
            states << item->state();
    return states;
}

int TestPackmlSimulationMarks::firedArrows() const
{
    int fired = 0;
    for (const PackmlArrowItem* item : m_scene->transitions())
        fired += item->isFired() ? 1 : 0;
    for (Command command : {Command::Stop, Command::Abort})
        fired += m_scene->frameArrowItem(command)->isFired() ? 1 : 0;
    return fired;
}

void TestPackmlSimulationMarks::currentStateIsFilled()
{
    QCOMPARE(activeStates(), QList<State>{State::Stopped});
    QCOMPARE(m_scene->stateItem(State::Stopped)->fillColor(), chartstyle::activeFillColor());
    QVERIFY(m_scene->stateItem(State::Idle)->fillColor() != chartstyle::activeFillColor());
    m_session->pressCommand(Command::Reset);
    m_session->stepOnce();
    QCOMPARE(activeStates(), QList<State>{State::Resetting});
}

void TestPackmlSimulationMarks::firedTransitionIsGreen()
{
    QCOMPARE(firedArrows(), 0);
    m_session->pressCommand(Command::Reset);
    m_session->stepOnce();
    PackmlArrowItem* reset = m_scene->transitionItem(State::Stopped, State::Resetting);
    QVERIFY(reset);
    QVERIFY(reset->isFired());
    QCOMPARE(reset->inkColor(), chartstyle::firedColor());
    QCOMPARE(firedArrows(), 1);
    m_session->stepOnce(); // nothing fires: the mark goes
    QCOMPARE(firedArrows(), 0);
}

void TestPackmlSimulationMarks::stopFiresTheFramesArrow()
{
    m_session->pressCommand(Command::Reset);
    m_session->advance(2);
    m_session->pressCommand(Command::Stop);
    m_session->stepOnce();
    QCOMPARE(m_session->simulator()->state(), State::Stopped);
    QVERIFY(m_scene->frameArrowItem(Command::Stop)->isFired());
    QCOMPARE(firedArrows(), 1);
}

void TestPackmlSimulationMarks::chartAndSelectorFollowTheCurrentMode()
{
    QCOMPARE(m_scene->mode(), kProduction);
    QCOMPARE(m_view->modeSelector()->currentData().toInt(), kProduction);
    m_session->requestMode(kManual);
    m_session->stepOnce();
    QCOMPARE(m_scene->mode(), kManual);
    QCOMPARE(m_view->modeSelector()->currentData().toInt(), kManual);
    QCOMPARE(activeStates(), QList<State>{State::Stopped});
    // While simulating, the chart stays on the mode the unit is in.
    m_scene->setMode(kProduction);
    QCOMPARE(m_scene->mode(), kManual);
    m_session->pressCommand(Command::Reset);
    m_session->stepOnce();
    QCOMPARE(activeStates(), QList<State>{State::Idle}); // Manual skips Resetting
}

void TestPackmlSimulationMarks::historyShowsThePastScansMarks()
{
    m_session->requestMode(kManual);
    m_session->stepOnce();
    m_session->pressCommand(Command::Reset);
    m_session->advance(2);
    QCOMPARE(activeStates(), QList<State>{State::Idle});
    m_session->showScan(0);
    QCOMPARE(activeStates(), QList<State>{State::Stopped});
    QCOMPARE(m_scene->mode(), kProduction);
    QCOMPARE(firedArrows(), 0);
    m_session->showScan(3);
    QCOMPARE(activeStates(), QList<State>{State::Idle});
    QCOMPARE(m_scene->mode(), kManual);
}

void TestPackmlSimulationMarks::endingTheSimulationClearsTheMarks()
{
    m_session->pressCommand(Command::Reset);
    m_session->stepOnce();
    m_session->setActive(false);
    QVERIFY(activeStates().isEmpty());
    QCOMPARE(firedArrows(), 0);
}

// Production's Execute: 1 N Cap -Capped-> 2 N Eject (spec §6.6).
void TestPackmlSimulationMarks::nestedGrafcetOfTheCurrentStateRuns()
{
    GrafcetScene scene(m_document.get(), QStringLiteral("1/Execute"));
    GrafcetSimulationMarks* marks = addPackmlGrafcetMarks(m_session.get(), &scene, &scene);
    QCOMPARE(marks->state(), GrafcetSimulationMarks::State::Frozen); // as it was left: never run
    m_session->pressCommand(Command::Reset);
    QVERIFY(m_session->setInput(QStringLiteral("Homed"), true));
    m_session->advance(2);
    QCOMPARE(m_session->simulator()->state(), State::Idle);
    m_session->pressCommand(Command::Start);
    m_session->stepOnce();
    QCOMPARE(m_session->simulator()->state(), State::Execute);
    QCOMPARE(marks->captionText(), QStringLiteral("Production_Execute has just been entered: its GRAFCET starts from "
                                                  "its initial steps in the next scan"));
    m_session->stepOnce();
    QCOMPARE(marks->state(), GrafcetSimulationMarks::State::Running);
    QCOMPARE(scene.stepItem(1)->simulationMark(), GrafcetStepItem::SimulationMark::Active);
    QCOMPARE(scene.stepItem(2)->simulationMark(), GrafcetStepItem::SimulationMark::None);
    QVERIFY(!scene.transitionItem(1)->isFired());
    QVERIFY(m_session->setInput(QStringLiteral("Capped"), true));
    m_session->stepOnce();
    QCOMPARE(scene.stepItem(1)->simulationMark(), GrafcetStepItem::SimulationMark::None);
    QCOMPARE(scene.stepItem(2)->simulationMark(), GrafcetStepItem::SimulationMark::Active);
    QVERIFY(scene.transitionItem(1)->isFired());
    QCOMPARE(marks->captionText(), QStringLiteral("Production_Execute is active: its GRAFCET runs (step(s) 2)"));
    // Back in the history: the scan before, its situation.
    m_session->stepBack();
    QCOMPARE(scene.stepItem(1)->simulationMark(), GrafcetStepItem::SimulationMark::Active);
    QVERIFY(!scene.transitionItem(1)->isFired());
    m_session->setActive(false);
    QCOMPARE(marks->state(), GrafcetSimulationMarks::State::Off);
    QCOMPARE(scene.stepItem(1)->simulationMark(), GrafcetStepItem::SimulationMark::None);
}

void TestPackmlSimulationMarks::nestedGrafcetOfAnotherStateIsGreyed()
{
    GrafcetScene scene(m_document.get(), QStringLiteral("1/Resetting"));
    GrafcetSimulationMarks* marks = addPackmlGrafcetMarks(m_session.get(), &scene, &scene);
    m_session->pressCommand(Command::Reset);
    m_session->advance(2);
    QVERIFY(m_session->setInput(QStringLiteral("Homed"), true));
    m_session->advance(2); // SC: Resetting-SC->Idle
    QCOMPARE(m_session->simulator()->state(), State::Idle);
    QCOMPARE(marks->state(), GrafcetSimulationMarks::State::Frozen);
    QCOMPARE(scene.stepItem(2)->simulationMark(), GrafcetStepItem::SimulationMark::Frozen);
    QCOMPARE(marks->captionText(),
             QStringLiteral("Production_Resetting is not active: its GRAFCET is shown greyed, as it was left"));
}

QTEST_MAIN(TestPackmlSimulationMarks)
#include "test_packmlsimulationmarks.moc"
