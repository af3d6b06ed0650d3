// Simulation on both layers (issue 18): the tabs of the nested GRAFCETs show
// the simulation (tokens on the active steps, the transitions fired in the
// last scan, running timers, lit actions; the other tabs greyed), the GEMMA
// chart shows which GRAFCET runs, the Simulation dock shows outputs as lamps
// and Unstable. On the shipped drilling cell, each mark checked against
// what the simulator holds and against what is painted.

#include "editortestsupport.h"

#include "editor/app/languages.h"
#include "editor/chart/chartstyle.h"
#include "editor/chart/gemma/chartscene.h"
#include "editor/chart/gemma/stepitem.h"
#include "editor/chart/layoutconversion.h"
#include "editor/document.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetstepitem.h"
#include "editor/grafcet/grafcettransitionitem.h"
#include "editor/grafcet/grafcetview.h"
#include "editor/grafcet/grafcetwiringitem.h"
#include "editor/mainwindow.h"
#include "editor/simulation/grafcetmarklabelitem.h"
#include "editor/simulation/grafcetsimulationmarks.h"
#include "editor/simulation/lampindicator.h"
#include "editor/simulation/simulationdock.h"
#include "editor/simulation/simulationsession.h"

#include "core/condition/conditionevaluator.h"
#include "core/formats/modelfiles.h"
#include "core/simulation/simulator.h"

#include <QAction>
#include <QImage>
#include <QLabel>
#include <QPainter>
#include <QScrollBar>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <algorithm>
#include <memory>

using namespace editor;

namespace {

using Mark = GrafcetStepItem::SimulationMark;

QList<GrafcetMarkLabelItem*> labels(const QGraphicsScene& scene, GrafcetMarkLabelItem::Kind kind)
{
    QList<GrafcetMarkLabelItem*> found;
    for (QGraphicsItem* item : scene.items()) {
        if (item->type() == GrafcetMarkLabelItem::Type) {
            auto* label = static_cast<GrafcetMarkLabelItem*>(item);
            if (label->kind() == kind)
                found << label;
        }
    }
    return found;
}

GrafcetMarkLabelItem* timerLabel(const QGraphicsScene& scene, int transition)
{
    for (GrafcetMarkLabelItem* label : labels(scene, GrafcetMarkLabelItem::Kind::Timer)) {
        if (label->transition() == transition)
            return label;
    }
    return nullptr;
}

// The scene as the view paints it, two pixels per unit, and where a scene
// point lands in it.
struct Picture {
    QImage image;
    QRectF source;
    QColor at(QPointF scenePoint) const
    {
        const QPointF p = (scenePoint - source.topLeft()) * 2;
        return image.pixelColor(qRound(p.x() - 0.5), qRound(p.y() - 0.5));
    }
};

Picture paint(QGraphicsScene& scene)
{
    Picture picture;
    picture.source = scene.sceneRect();
    picture.image = QImage((picture.source.size() * 2).toSize(), QImage::Format_ARGB32);
    picture.image.fill(Qt::white);
    QPainter painter(&picture.image);
    scene.render(&painter, QRectF(picture.image.rect()), picture.source);
    return picture;
}

// Close enough to `expected` (antialiasing aside).
bool near(const QColor& actual, const QColor& expected)
{
    return std::abs(actual.red() - expected.red()) + std::abs(actual.green() - expected.green())
               + std::abs(actual.blue() - expected.blue())
        < 40;
}

QString describe(const QColor& colour)
{
    return colour.name();
}

// What is wrong with the marks of `scene` for the scan `simulator` shows,
// empty when nothing: a token on exactly the steps the simulator reports
// active (filled while the GRAFCET runs, grey otherwise), the transitions it
// reports fired in the last scan marked (bar and links) while it runs, and
// none otherwise; checked on the items and on the painted picture.
QString marksMismatch(GrafcetScene& scene, const core::Simulator& simulator)
{
    const std::string id = scene.stepId().toStdString();
    const bool runs = grafcetRuns(simulator, id);
    const std::vector<int> active = simulator.activeNestedSteps(id);
    const std::vector<int> firedNumbers = runs ? simulator.firedNestedTransitions(id) : std::vector<int>{};
    const Picture picture = paint(scene);
    QStringList problems;
    for (const core::GrafcetStepLayout& step : scene.layout().steps) {
        const GrafcetStepItem* item = scene.stepItem(step.number);
        const bool isActive = std::find(active.begin(), active.end(), step.number) != active.end();
        const Mark expected = !isActive ? Mark::None : runs ? Mark::Active : Mark::Frozen;
        if (item->simulationMark() != expected)
            problems << QStringLiteral("step %1: mark %2, expected %3")
                            .arg(step.number)
                            .arg(static_cast<int>(item->simulationMark()))
                            .arg(static_cast<int>(expected));
        const QColor token = picture.at(item->tokenRect().center());
        const QColor painted = expected == Mark::Active   ? chartstyle::tokenColor()
                               : expected == Mark::Frozen ? chartstyle::frozenTokenColor()
                                                          : chartstyle::stepFillColor();
        if (!near(token, painted))
            problems << QStringLiteral("step %1: token place painted %2, expected %3")
                            .arg(step.number)
                            .arg(describe(token), describe(painted));
    }
    QList<int> fired;
    for (int number : firedNumbers)
        fired << number;
    for (const core::GrafcetTransitionLayout& transition : scene.layout().transitions) {
        const GrafcetTransitionItem* item = scene.transitionItem(transition.number);
        const bool expected = fired.contains(transition.number);
        if (item->isFired() != expected)
            problems << QStringLiteral("T%1: fired %2").arg(transition.number).arg(item->isFired());
        const QColor bar = picture.at(toQPointF(transition.barCenter));
        if (!near(bar, expected ? chartstyle::firedColor() : chartstyle::inkColor()))
            problems << QStringLiteral("T%1: bar painted %2").arg(transition.number).arg(describe(bar));
    }
    if (scene.wiringItem()->firedTransitions() != fired)
        problems << QStringLiteral("links of the fired transitions not marked");
    return problems.join(QLatin1Char('\n'));
}

} // namespace

class TestGrafcetSimulation : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();

    void tabsShowTheSimulationOfBothLayers();
    void marksFollowTheHistoryAndTheReplay();
    void marksGoWhenTheSimulationEnds();
    void captionIsInSight();
    void drawingStaysFromScanToScan();
    void outputsAreReadOnlyLamps();
    void unstableIsShown();

private:
    void startOnDrillingCell();
    void set(const char* variable, bool value);
    void scan(int count = 1);
    GrafcetScene* openGrafcet(const char* stepId);
    GrafcetSimulationMarks* marksOf(GrafcetScene* scene) const;

    QTemporaryDir m_settingsDir;
    std::unique_ptr<Translators> m_translators;
    std::unique_ptr<MainWindow> m_window;
    SimulationSession* m_session = nullptr;
    SimulationDock* m_dock = nullptr;
};

void TestGrafcetSimulation::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    editortest::useTestSettings(m_settingsDir.path(), QStringLiteral("test_grafcetsimulation"));
}

void TestGrafcetSimulation::init()
{
    m_translators = std::make_unique<Translators>();
    m_translators->setLanguage(QStringLiteral("en"));
    m_window = editortest::showMainWindow(*m_translators);
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    m_session = m_window->simulationSession();
    m_dock = m_window->findChild<SimulationDock*>(QStringLiteral("simulationDock"));
    QVERIFY(m_session && m_dock);
}

void TestGrafcetSimulation::cleanup()
{
    if (m_window)
        m_window->document()->undoStack()->setClean();
    m_window.reset();
    m_translators.reset();
}

// A1 initial; A1 -> F2 on StartButton; F2 warms up (1 -> 3 on DrillHigh,
// 10s/X3 to 4, S Complete), F2 -> F1 then drills.
void TestGrafcetSimulation::startOnDrillingCell()
{
    const core::LoadedModel loaded = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    QVERIFY(loaded.model);
    // In open loop, the sensors set by hand: the machine taken out
    // (test_machinesimulation.cpp plays the example closed loop).
    QVERIFY(loaded.model->setMachine({}).ok);
    m_window->document()->replaceModel(*loaded.model, QString(), core::ModelFormat::Native);
}

void TestGrafcetSimulation::set(const char* variable, bool value)
{
    const int index = m_session->simulator()->variableIndex(variable);
    QVERIFY2(index >= 0, variable);
    QVERIFY(m_session->setVariable(index, value));
}

void TestGrafcetSimulation::scan(int count)
{
    m_session->advance(count);
}

GrafcetScene* TestGrafcetSimulation::openGrafcet(const char* stepId)
{
    if (!m_window->openNestedGrafcet(QLatin1String(stepId)))
        return nullptr;
    GrafcetView* view = m_window->grafcetView(QLatin1String(stepId));
    return view ? view->grafcetScene() : nullptr;
}

GrafcetSimulationMarks* TestGrafcetSimulation::marksOf(GrafcetScene* scene) const
{
    return scene->findChild<GrafcetSimulationMarks*>();
}

void TestGrafcetSimulation::tabsShowTheSimulationOfBothLayers()
{
    startOnDrillingCell();
    GrafcetScene* f2 = openGrafcet("F2"); // opened before the simulation: no marks yet
    QVERIFY(f2 && marksOf(f2));
    QCOMPARE(marksOf(f2)->state(), GrafcetSimulationMarks::State::Off);
    QVERIFY(labels(*f2, GrafcetMarkLabelItem::Kind::Caption).isEmpty());
    const QRectF drawing = f2->sceneRect();
    QCOMPARE(drawing, f2->drawingRect());

    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    QVERIFY(m_session->isActive());
    const core::Simulator* simulator = m_session->simulator();
    // A1 is active: F2 has not run, nothing is marked but the caption.
    QCOMPARE(marksOf(f2)->state(), GrafcetSimulationMarks::State::Frozen);
    QVERIFY2(marksOf(f2)->captionText().contains(QLatin1String("F2 is not active")),
             qPrintable(marksOf(f2)->captionText()));
    QVERIFY(f2->sceneRect().top() < drawing.top()); // room for the caption above the drawing
    QVERIFY(f2->sceneRect().contains(drawing));
    QString mismatch = marksMismatch(*f2, *simulator);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));

    set("DrillHigh", true);
    set("Unclamped", true);
    set("StartButton", true);
    scan(); // A1 -> F2: F2's function block runs from the next scan
    simulator = m_session->simulator();
    QCOMPARE(simulator->activeStepId(), std::string("F2"));
    QCOMPARE(marksOf(f2)->state(), GrafcetSimulationMarks::State::Frozen);
    QVERIFY2(marksOf(f2)->captionText().contains(QLatin1String("next scan")), qPrintable(marksOf(f2)->captionText()));
    QVERIFY(!m_window->chartScene()->stepItem(QStringLiteral("F2"))->nestedRunning());

    scan(); // F2's entry scan: Initialization, then 1 -> 3 (T2, DrillHigh)
    set("StartButton", false); // as examples/drilling-cell-open-loop.scenario plays it
    QCOMPARE(marksOf(f2)->state(), GrafcetSimulationMarks::State::Running);
    QCOMPARE(simulator->activeNestedSteps("F2"), std::vector<int>{3});
    QCOMPARE(simulator->firedNestedTransitions("F2"), std::vector<int>{2});
    mismatch = marksMismatch(*f2, *simulator);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
    QCOMPARE(f2->stepItem(3)->simulationMark(), Mark::Active);
    QVERIFY(f2->transitionItem(2)->isFired());
    QCOMPARE(f2->wiringItem()->firedTransitions(), QList<int>{2});
    // One active step: singular.
    QVERIFY2(marksOf(f2)->captionText().contains(QLatin1String("runs (step 3)")),
             qPrintable(marksOf(f2)->captionText()));
    // Step 3 drives Spindle (action 0); its stored PartCount := 0 (action 1) is no output.
    QCOMPARE(f2->stepItem(3)->litActions(), QList<int>{0});
    QVERIFY(core::cond::isTrue(simulator->variable("Spindle")));
    {
        const Picture picture = paint(*f2);
        const core::GrafcetActionLayout& spindle = f2->stepItem(3)->layout().actions[0];
        const core::GrafcetActionLayout& count = f2->stepItem(3)->layout().actions[1];
        const QPointF inside(3.5, 3.5);
        QVERIFY(near(picture.at(toQRectF(spindle.box).topLeft() + inside), chartstyle::litActionFillColor()));
        QVERIFY(near(picture.at(toQRectF(count.box).topLeft() + inside), chartstyle::stepFillColor()));
    }
    // The timer of 10s/X3, under T4's receptivity: elapsed and preset.
    GrafcetMarkLabelItem* timer = timerLabel(*f2, 4);
    QVERIFY(timer);
    QCOMPARE(timer->text(), QStringLiteral("0.00 / 10 s"));
    QCOMPARE(labels(*f2, GrafcetMarkLabelItem::Kind::Timer).size(), 1);
    const QRectF receptivity = toQRectF(f2->transitionItem(4)->layout().labelRect);
    const QRectF timerBox = timer->sceneBoundingRect();
    QVERIFY(timerBox.top() >= receptivity.bottom() - 1);
    QVERIFY(timerBox.left() >= receptivity.left() - 2);
    // It stands clear of every step box and action box.
    for (const core::GrafcetStepLayout& step : f2->layout().steps) {
        QVERIFY(!timerBox.intersects(toQRectF(step.box)));
        for (const core::GrafcetActionLayout& action : step.actions)
            QVERIFY(!timerBox.intersects(toQRectF(action.box)));
    }

    // The GEMMA chart: F2's GRAFCET mark says it runs, with its steps.
    StepItem* chartF2 = m_window->chartScene()->stepItem(QStringLiteral("F2"));
    QCOMPARE(chartF2->nestedRunning(), std::optional<QString>(QStringLiteral("3")));
    QVERIFY2(chartF2->toolTipText().contains(QLatin1String("Its GRAFCET runs: steps 3 active")),
             qPrintable(chartF2->toolTipText()));
    QVERIFY(!m_window->chartScene()->stepItem(QStringLiteral("F1"))->nestedRunning());

    scan(51); // nothing fires; the timer counts
    mismatch = marksMismatch(*f2, *simulator);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
    QVERIFY(!f2->transitionItem(2)->isFired());
    const core::NestedTimerState state = simulator->nestedTimers("F2").front();
    QCOMPARE(state.elapsedMs, 500);
    QCOMPARE(timerLabel(*f2, 4)->text(), QStringLiteral("0.50 / 10 s"));
    QCOMPARE(timerLabel(*f2, 4)->tone(), GrafcetMarkLabelItem::Tone::Running);

    // A tab opened during the simulation is marked at once: F1 has not run.
    GrafcetScene* f1 = openGrafcet("F1");
    QVERIFY(f1);
    QCOMPARE(marksOf(f1)->state(), GrafcetSimulationMarks::State::Frozen);
    mismatch = marksMismatch(*f1, *simulator);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
    QVERIFY(labels(*f1, GrafcetMarkLabelItem::Kind::Timer).isEmpty());
    QCOMPARE(labels(*f1, GrafcetMarkLabelItem::Kind::Caption).size(), 1);

    // On to F1 (10 s of warm-up, F2 -> F1): F2's tab is frozen in step 4, greyed.
    scan(1004 - 53);
    QCOMPARE(simulator->scanCount(), 1004);
    QCOMPARE(simulator->activeStepId(), std::string("F1"));
    QCOMPARE(marksOf(f1)->state(), GrafcetSimulationMarks::State::Running);
    QCOMPARE(marksOf(f2)->state(), GrafcetSimulationMarks::State::Frozen);
    QCOMPARE(simulator->activeNestedSteps("F2"), std::vector<int>{4});
    mismatch = marksMismatch(*f2, *simulator);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
    mismatch = marksMismatch(*f1, *simulator);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
    QCOMPARE(f2->stepItem(4)->simulationMark(), Mark::Frozen);
    QVERIFY(f2->stepItem(3)->litActions().isEmpty()); // a frozen GRAFCET drives nothing
    QVERIFY(labels(*f2, GrafcetMarkLabelItem::Kind::Timer).isEmpty());
    QCOMPARE(f1->stepItem(1)->simulationMark(), Mark::Active);
    QVERIFY2(marksOf(f2)->captionText().contains(QLatin1String("greyed")), qPrintable(marksOf(f2)->captionText()));
    QVERIFY(!chartF2->nestedRunning());
    QCOMPARE(m_window->chartScene()->stepItem(QStringLiteral("F1"))->nestedRunning(),
             std::optional<QString>(QStringLiteral("1")));

    // Drill: the part present, clamped; 2 -> 3 and 5 in parallel.
    set("PartPresent", true);
    scan();
    QCOMPARE(simulator->activeNestedSteps("F1"), std::vector<int>{2});
    QVERIFY(f1->transitionItem(1)->isFired());
    set("Unclamped", false);
    set("Clamped", true);
    scan();
    QCOMPARE(simulator->activeNestedSteps("F1"), (std::vector<int>{3, 5}));
    mismatch = marksMismatch(*f1, *simulator);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
    QCOMPARE(f1->stepItem(3)->simulationMark(), Mark::Active);
    QCOMPARE(f1->stepItem(5)->simulationMark(), Mark::Active);
    QVERIFY(f1->transitionItem(2)->isFired());
    // Step 3: Spindle, DrillDown, and Coolant only IF NOT DrillHigh (DrillHigh is TRUE).
    QCOMPARE(f1->stepItem(3)->litActions(), (QList<int>{0, 1}));
    QCOMPARE(f1->stepItem(5)->litActions(), QList<int>{0}); // Marker
    QVERIFY(timerLabel(*f1, 4)); // 2s/X5
}

void TestGrafcetSimulation::marksFollowTheHistoryAndTheReplay()
{
    startOnDrillingCell();
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    GrafcetScene* f2 = openGrafcet("F2");
    QVERIFY(f2);
    set("DrillHigh", true);
    set("Unclamped", true);
    set("StartButton", true);
    scan(4);
    QVERIFY(!f2->transitionItem(2)->isFired());
    QCOMPARE(timerLabel(*f2, 4)->text(), QStringLiteral("0.01 / 10 s"));

    // Back to scan 3, then 2: the scan that fired T2 shows it fired again.
    m_session->stepBack();
    QCOMPARE(m_session->viewedScan(), 3);
    QCOMPARE(timerLabel(*f2, 4)->text(), QStringLiteral("0.00 / 10 s"));
    QVERIFY(!f2->transitionItem(2)->isFired());
    m_session->stepBack();
    QCOMPARE(m_session->viewedScan(), 2);
    QString mismatch = marksMismatch(*f2, *m_session->simulator());
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
    QVERIFY(f2->transitionItem(2)->isFired());
    QCOMPARE(f2->stepItem(3)->simulationMark(), Mark::Active);
    // Scan 1: F2 entered, its GRAFCET not yet run.
    m_session->stepBack();
    QCOMPARE(marksOf(f2)->state(), GrafcetSimulationMarks::State::Frozen);
    QCOMPARE(f2->stepItem(3)->simulationMark(), Mark::None);
    QVERIFY(!f2->transitionItem(2)->isFired());
    QVERIFY(labels(*f2, GrafcetMarkLabelItem::Kind::Timer).isEmpty());
    QVERIFY(!m_window->chartScene()->stepItem(QStringLiteral("F2"))->nestedRunning());
    // Forward again.
    m_session->stepForward();
    QVERIFY(f2->transitionItem(2)->isFired());
    QCOMPARE(f2->stepItem(3)->simulationMark(), Mark::Active);
    m_session->stepForward();
    m_session->stepForward();
    QVERIFY(!m_session->isViewingHistory());
    QCOMPARE(timerLabel(*f2, 4)->text(), QStringLiteral("0.01 / 10 s"));
    mismatch = marksMismatch(*f2, *m_session->simulator());
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));

    // The shipped open-loop scenario replayed (the editor's simulation does not
    // run the machine yet): back at scan 0, then scan by scan.
    QString error;
    QVERIFY2(m_session->startReplay(GGSTUDIO_EXAMPLES_DIR "/drilling-cell-open-loop.scenario", &error),
             qPrintable(error));
    QCOMPARE(f2->stepItem(3)->simulationMark(), Mark::None);
    QCOMPARE(marksOf(f2)->state(), GrafcetSimulationMarks::State::Frozen);
    scan(2);
    QCOMPARE(f2->stepItem(3)->simulationMark(), Mark::Active);
    QVERIFY(f2->transitionItem(2)->isFired());
    GrafcetScene* f1 = openGrafcet("F1");
    scan(1013 - 2);
    QVERIFY(m_session->replayFailures().empty());
    mismatch = marksMismatch(*f1, *m_session->simulator());
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
    QCOMPARE(f1->stepItem(3)->simulationMark(), Mark::Active);
    QCOMPARE(f1->stepItem(5)->simulationMark(), Mark::Active);
    QCOMPARE(f2->stepItem(4)->simulationMark(), Mark::Frozen);
}

void TestGrafcetSimulation::marksGoWhenTheSimulationEnds()
{
    startOnDrillingCell();
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    GrafcetScene* f2 = openGrafcet("F2");
    set("DrillHigh", true);
    set("Unclamped", true);
    set("StartButton", true);
    scan(2);
    QCOMPARE(f2->stepItem(3)->simulationMark(), Mark::Active);
    QVERIFY(m_window->chartScene()->stepItem(QStringLiteral("F2"))->nestedRunning());

    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    QVERIFY(!m_session->isActive());
    QCOMPARE(marksOf(f2)->state(), GrafcetSimulationMarks::State::Off);
    for (const core::GrafcetStepLayout& step : f2->layout().steps) {
        QCOMPARE(f2->stepItem(step.number)->simulationMark(), Mark::None);
        QVERIFY(f2->stepItem(step.number)->litActions().isEmpty());
    }
    for (const core::GrafcetTransitionLayout& transition : f2->layout().transitions)
        QVERIFY(!f2->transitionItem(transition.number)->isFired());
    QVERIFY(f2->wiringItem()->firedTransitions().isEmpty());
    QVERIFY(labels(*f2, GrafcetMarkLabelItem::Kind::Timer).isEmpty());
    QVERIFY(labels(*f2, GrafcetMarkLabelItem::Kind::Caption).isEmpty());
    QCOMPARE(f2->sceneRect(), f2->drawingRect());
    QVERIFY(!m_window->chartScene()->stepItem(QStringLiteral("F2"))->nestedRunning());
    // Painted plain again: the token's place is the step's white.
    const Picture picture = paint(*f2);
    QVERIFY(near(picture.at(f2->stepItem(3)->tokenRect().center()), chartstyle::stepFillColor()));

    // A new simulation starts from scratch: nothing left of the old one.
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    QCOMPARE(f2->stepItem(3)->simulationMark(), Mark::None);
    QCOMPARE(labels(*f2, GrafcetMarkLabelItem::Kind::Caption).size(), 1);
}

// F1's drawing is taller than its tab: shown from its top, it stays at the
// top when the caption comes above it, so the caption is in sight.
void TestGrafcetSimulation::captionIsInSight()
{
    startOnDrillingCell();
    GrafcetScene* f1 = openGrafcet("F1");
    QVERIFY(f1);
    GrafcetView* view = m_window->grafcetView(QStringLiteral("F1"));
    QVERIFY(QTest::qWaitForWindowExposed(view));
    QScrollBar* bar = view->verticalScrollBar();
    QVERIFY(bar->maximum() > bar->minimum());
    QCOMPARE(bar->value(), bar->minimum());
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    const QList<GrafcetMarkLabelItem*> captions = labels(*f1, GrafcetMarkLabelItem::Kind::Caption);
    QCOMPARE(captions.size(), 1);
    const QRectF caption = captions.front()->sceneBoundingRect();
    QVERIFY(view->viewport()->rect().contains(view->mapFromScene(caption.topLeft())));
    QVERIFY(caption.bottom() <= f1->drawingRect().top() + core::kGrafcetMargin); // above the drawing
    // Scrolled down by the user, the view stays where it is.
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    bar->setValue(bar->maximum());
    const int scrolled = bar->value();
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    QVERIFY(std::abs(bar->value() - scrolled) <= 30);
    QVERIFY(bar->value() > bar->minimum());
}

void TestGrafcetSimulation::drawingStaysFromScanToScan()
{
    startOnDrillingCell();
    GrafcetScene* f2 = openGrafcet("F2");
    QVERIFY(f2);
    GrafcetView* view = m_window->grafcetView(QStringLiteral("F2"));
    QVERIFY(QTest::qWaitForWindowExposed(view));
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    const auto stepOnScreen = [view, f2] {
        return view->mapFromScene(f2->stepItem(1)->sceneBoundingRect().center());
    };
    const QPoint before = stepOnScreen();
    const QString notActive = marksOf(f2)->captionText();
    set("DrillHigh", true);
    set("Unclamped", true);
    set("StartButton", true);
    for (int i = 0; i < 3; ++i) {
        scan();
        QCOMPARE(stepOnScreen(), before);
    }
    QVERIFY(marksOf(f2)->captionText() != notActive); // the caption changed, and its width with it
    QVERIFY(f2->sceneRect().width() < view->viewport()->width()); // nothing scrolls: the alignment decides
}

void TestGrafcetSimulation::outputsAreReadOnlyLamps()
{
    startOnDrillingCell();
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    const core::Simulator* simulator = m_session->simulator();
    int lamps = 0;
    for (std::size_t i = 0; i < simulator->variableNames().size(); ++i) {
        const QString name = QString::fromStdString(simulator->variableNames()[i]);
        auto* lamp = m_dock->findChild<LampIndicator*>(QStringLiteral("lamp_") + name);
        const bool written = simulator->variableKind(i) != core::VariableKind::Input;
        const bool isBool = simulator->variableType(i) == core::IecType::Bool;
        QCOMPARE(lamp != nullptr, written && isBool);
        if (lamp) {
            ++lamps;
            QTRY_VERIFY(lamp->isVisible()); // shown with its row, once the events ran
            QCOMPARE(lamp->focusPolicy(), Qt::NoFocus);
            // Beside its value, on the row of its name.
            auto* shown = m_dock->findChild<QLabel*>(QStringLiteral("shown_") + name);
            QVERIFY(shown);
            QCOMPARE(shown->text(), QStringLiteral("FALSE"));
            const int lampY = lamp->mapTo(m_dock, lamp->rect().center()).y();
            QVERIFY(qAbs(lampY - shown->mapTo(m_dock, shown->rect().center()).y()) <= 2);
            QVERIFY(lamp->mapTo(m_dock, QPoint(0, 0)).x() < shown->mapTo(m_dock, QPoint(0, 0)).x());
        }
    }
    QVERIFY(lamps >= 5);

    auto* spindle = m_dock->findChild<LampIndicator*>(QStringLiteral("lamp_Spindle"));
    auto* spindleText = m_dock->findChild<QLabel*>(QStringLiteral("shown_Spindle"));
    QVERIFY(spindle && spindleText);
    QVERIFY(!spindle->isOn());
    const auto lampColour = [](LampIndicator* lamp) {
        const QImage image = lamp->grab().toImage();
        return image.pixelColor(image.width() / 2 + image.width() / 5, image.height() / 2 + image.height() / 5);
    };
    QVERIFY(near(lampColour(spindle), LampIndicator::offColour()));
    set("DrillHigh", true);
    set("Unclamped", true);
    set("StartButton", true);
    scan(2); // F2 warms up: step 3 drives Spindle
    QVERIFY(core::cond::isTrue(simulator->variable("Spindle")));
    QVERIFY(spindle->isOn());
    QCOMPARE(spindleText->text(), QStringLiteral("TRUE"));
    QVERIFY(near(lampColour(spindle), LampIndicator::onColour()));
    // Read only: a click changes nothing.
    QTest::mouseClick(spindle, Qt::LeftButton);
    QTest::mouseClick(spindleText, Qt::LeftButton);
    QVERIFY(core::cond::isTrue(simulator->variable("Spindle")));
    QVERIFY(spindle->isOn());
    // Back in the history, the lamp shows that scan's value.
    m_session->stepBack();
    m_session->stepBack();
    QVERIFY(!spindle->isOn());
    QCOMPARE(spindleText->text(), QStringLiteral("FALSE"));
}

// Under *until stable*, a GRAFCET that cycles without end: the dock says
// Unstable, and so does the caption of its tab.
void TestGrafcetSimulation::unstableIsShown()
{
    core::Model model;
    QVERIFY(model.addVariable({"A", core::IecType::Bool, "", "", core::VariableKind::Input}));
    QVERIFY(model.setInitialStep("F1"));
    QVERIFY(model.setCondition("F1->A2", "FALSE"));
    model.setEvolutionRule(core::EvolutionRule::UntilStable);
    QVERIFY(model.addGrafcetStep("F1", {1, true, "", {{core::ActionTiming::OnActivation, "S Complete"}}}));
    QVERIFY(model.addGrafcetStep("F1", {2, false, "", {}}));
    QVERIFY(model.addGrafcetTransition("F1", {1, {1}, {2}, "A"}));
    QVERIFY(model.addGrafcetTransition("F1", {2, {2}, {1}, "A"}));
    m_window->document()->replaceModel(model, QString(), core::ModelFormat::Native);
    GrafcetScene* f1 = openGrafcet("F1");
    QVERIFY(f1);
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    QLabel* unstable = m_dock->unstableLabel();
    QVERIFY(unstable);
    scan(2);
    QVERIFY(!m_session->simulator()->unstable("F1"));
    QVERIFY(unstable->isHidden());
    QCOMPARE(labels(*f1, GrafcetMarkLabelItem::Kind::Caption).front()->tone(), GrafcetMarkLabelItem::Tone::Running);

    set("A", true);
    scan();
    QVERIFY(m_session->simulator()->unstable("F1"));
    QVERIFY(!unstable->isHidden());
    QVERIFY2(unstable->text().contains(QLatin1String("Unstable")) && unstable->text().contains(QLatin1String("F1")),
             qPrintable(unstable->text()));
    QCOMPARE(labels(*f1, GrafcetMarkLabelItem::Kind::Caption).front()->tone(), GrafcetMarkLabelItem::Tone::Warning);
    QVERIFY(marksOf(f1)->captionText().contains(QLatin1String("Unstable")));
    // Both transitions fired in the scan: the search went round.
    QCOMPARE(f1->wiringItem()->firedTransitions(), (QList<int>{1, 2}));

    set("A", false);
    scan();
    QVERIFY(!m_session->simulator()->unstable("F1"));
    QVERIFY(unstable->isHidden());
    m_session->stepBack(); // the unstable scan again
    QVERIFY(!unstable->isHidden());
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    QVERIFY(unstable->isHidden());
}

QTEST_MAIN(TestGrafcetSimulation)
#include "test_grafcetsimulation.moc"
