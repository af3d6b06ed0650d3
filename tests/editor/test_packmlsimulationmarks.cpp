// The PackML simulation on the PackML chart (issue 34, Simulation): the
// current state filled, the transition that fired green, the chart and its
// mode selector on the current mode, for the scan shown; on the Capper.

#include "editor/chart/chartstyle.h"
#include "editor/chart/packml/packmlarrowitem.h"
#include "editor/chart/packml/packmlchartscene.h"
#include "editor/chart/packml/packmlchartview.h"
#include "editor/chart/packml/packmlstateitem.h"
#include "editor/document.h"
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

core::Model capper()
{
    core::LoadedModel loaded = core::loadModelFile(GGSTUDIO_CORE_TEST_DATA_DIR "/packml-capper.json");
    if (!loaded.model)
        qFatal("cannot load the Capper");
    return *loaded.model;
}

constexpr int kProduction = 1;
constexpr int kManual = 3;

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

QTEST_MAIN(TestPackmlSimulationMarks)
#include "test_packmlsimulationmarks.moc"
