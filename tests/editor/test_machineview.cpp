// The Machine tab (issue 35): a schematic of the model's virtual machine
// beside the GEMMA chart, at rest outside the simulation, following the
// simulation, its history and replays, its operator inputs clickable, and
// a frame of it cheap while simulating at 1,000 scans/s.

#include "editortestsupport.h"

#include "editor/app/languages.h"
#include "editor/document.h"
#include "editor/machine/conveyoritem.h"
#include "editor/machine/cylinderitem.h"
#include "editor/machine/indicatoritem.h"
#include "editor/machine/machinescene.h"
#include "editor/machine/machinetab.h"
#include "editor/machine/machineview.h"
#include "editor/machine/operatoritem.h"
#include "editor/machine/partsourceitem.h"
#include "editor/mainwindow.h"
#include "editor/simulation/simulationsession.h"

#include "core/condition/conditionevaluator.h"
#include "core/formats/modelfiles.h"

#include <QAction>
#include <QApplication>
#include <QContextMenuEvent>
#include <QImage>
#include <QPainter>
#include <QTabBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <algorithm>
#include <memory>
#include <vector>

using namespace editor;

class TestMachineView : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();

    void tabComesAndGoesWithTheMachine();
    void restShowsTheMachineAtRest();
    void cellsNeverOverlapAndNameTheirVariables();
    void litSensorsAreDrawnLit();
    void cellsFollowTheDarkPalette();
    void followsTheSimulation();
    void followsTheHistory();
    void followsAReplay();
    void operatorInputsAreClickable();
    void framesFollowTheSimulation();
    void faultsFromTheSchematic();

private:
    void loadDrillingCell();
    void startSimulation();
    MachineScene* scene() const;
    MachineView* view() const;
    bool value(const char* variable) const;
    int index(const char* variable) const;
    QImage render() const;

    QTemporaryDir m_settingsDir;
    std::unique_ptr<Translators> m_translators;
    std::unique_ptr<MainWindow> m_window;
    SimulationSession* m_session = nullptr;
};

void TestMachineView::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    editortest::useTestSettings(m_settingsDir.path(), QStringLiteral("test_machineview"));
}

void TestMachineView::init()
{
    m_window = editortest::showEnglishMainWindow(m_translators);
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    m_session = m_window->simulationSession();
}

void TestMachineView::cleanup()
{
    if (m_window)
        m_window->document()->undoStack()->setClean();
    m_window.reset();
    m_translators.reset();
}

void TestMachineView::loadDrillingCell()
{
    QString error;
    QVERIFY2(m_window->document()->load(QStringLiteral(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json"), &error),
             qPrintable(error));
    QVERIFY(view());
}

void TestMachineView::startSimulation()
{
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    QVERIFY(m_session->isActive());
}

MachineView* TestMachineView::view() const
{
    return m_window->machineTab()->view();
}

MachineScene* TestMachineView::scene() const
{
    return view()->machineScene();
}

bool TestMachineView::value(const char* variable) const
{
    return core::cond::isTrue(m_session->simulator()->variable(variable));
}

int TestMachineView::index(const char* variable) const
{
    return m_session->liveSimulator()->variableIndex(variable);
}

QImage TestMachineView::render() const
{
    const QRectF rect = scene()->sceneRect();
    QImage image(rect.size().toSize(), QImage::Format_ARGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    scene()->render(&painter, QRectF(QPointF(0, 0), rect.size()), rect);
    return image;
}

void TestMachineView::tabComesAndGoesWithTheMachine()
{
    QTabWidget* tabs = m_window->centralTabs();
    QVERIFY(!view()); // the template has no machine
    QCOMPARE(tabs->count(), 1);
    loadDrillingCell();
    QCOMPARE(tabs->count(), 2);
    QCOMPARE(tabs->widget(1), view());
    QCOMPARE(tabs->tabText(1), QStringLiteral("Machine"));
    QVERIFY(!tabs->tabBar()->tabButton(1, QTabBar::RightSide)); // not closable
    // A GRAFCET tab opens after it; closing every GRAFCET tab keeps it.
    QVERIFY(m_window->openNestedGrafcet(QStringLiteral("F1")));
    QCOMPARE(tabs->count(), 3);
    QCOMPARE(tabs->widget(1), view());
    emit tabs->tabCloseRequested(1);
    QCOMPARE(tabs->widget(1), view());

    // The machine removed: the tab goes; back: it comes again.
    const core::machine::Machine machine = m_window->document()->model().machine();
    QVERIFY(m_window->document()->modelForCommands().setMachine({}).ok);
    QVERIFY(!view());
    QCOMPARE(tabs->count(), 2);
    QVERIFY(m_window->document()->modelForCommands().setMachine(machine).ok);
    QVERIFY(view());
    QCOMPARE(tabs->widget(1), view());
    m_window->document()->newFromTemplate();
    QVERIFY(!view());
}

void TestMachineView::restShowsTheMachineAtRest()
{
    loadDrillingCell();
    QVERIFY(!scene()->showsSimulation());
    QCOMPARE(scene()->componentCount(), std::size_t{9});
    auto* clamp = dynamic_cast<CylinderItem*>(scene()->componentItem(QStringLiteral("Clamp")));
    auto* infeed = dynamic_cast<ConveyorItem*>(scene()->componentItem(QStringLiteral("Infeed")));
    auto* magazine = dynamic_cast<PartSourceItem*>(scene()->componentItem(QStringLiteral("Magazine")));
    auto* ready = dynamic_cast<IndicatorItem*>(scene()->componentItem(QStringLiteral("Ready")));
    auto* stop = dynamic_cast<OperatorItem*>(scene()->componentItem(QStringLiteral("EmergencyStop")));
    QVERIFY(clamp && infeed && magazine && ready && stop);
    QCOMPARE(clamp->position(), 0.0);
    QVERIFY(scene()->signal(clamp->component(), core::machine::role::kDoubleRetracted));
    QVERIFY(!scene()->signal(clamp->component(), core::machine::role::kDoubleExtended));
    QVERIFY(!infeed->partRect().isEmpty()); // a part waits on the entry
    QCOMPARE(magazine->partsText(), QStringLiteral("Parts left: 9"));
    QVERIFY(!ready->isLit());
    QVERIFY(!stop->isActuated()); // normally closed, released: EmergencyOk TRUE
    QVERIFY(scene()->signal(stop->component(), core::machine::role::kOperatorInput));
    QVERIFY(!scene()->canOperate());
}

void TestMachineView::cellsNeverOverlapAndNameTheirVariables()
{
    loadDrillingCell();
    const core::machine::Machine& machine = m_window->document()->model().machine();
    for (std::size_t i = 0; i < scene()->componentCount(); ++i) {
        const QRectF cell = scene()->componentItem(i)->boundingRect();
        QVERIFY(scene()->sceneRect().contains(cell));
        for (std::size_t j = i + 1; j < scene()->componentCount(); ++j)
            QVERIFY2(!cell.intersects(scene()->componentItem(j)->boundingRect()), machine.components[i].name.c_str());
        const QStringList lines = scene()->componentItem(i)->roleLines();
        for (const std::string& wire : machine.components[i].wires)
            QVERIFY2(lines.join(QLatin1Char('\n')).contains(QString::fromStdString(wire)), qPrintable(lines.join('|')));
        QVERIFY(scene()->componentItem(i)->toolTip().contains(QString::fromStdString(machine.components[i].name)));
    }
    const QStringList clamp = scene()->componentItem(QStringLiteral("Clamp"))->roleLines();
    QCOMPARE(clamp, (QStringList{QStringLiteral("extend: ClampOut"), QStringLiteral("retract: ClampIn"),
                                 QStringLiteral("retracted: Unclamped"), QStringLiteral("extended: Clamped")}));
    // The whole schematic fits a laptop's central area without going below the readable scale.
    QVERIFY(scene()->sceneRect().width() * MachineView::kMinScale < 1000);
}

// The role lines' lamps: lit green while the variable is TRUE.
void TestMachineView::litSensorsAreDrawnLit()
{
    loadDrillingCell();
    MachineComponentItem* clamp = scene()->componentItem(QStringLiteral("Clamp"));
    const QRectF cell = clamp->boundingRect();
    const double firstLine = cell.bottom() - 6 - 4 * 17; // four role lines above the padding
    const auto lampAt = [&](int line) {
        const QPointF centre(cell.left() + 6 + 5.5, firstLine + line * 17 + 8.5);
        return render().pixelColor((centre - scene()->sceneRect().topLeft()).toPoint());
    };
    QCOMPARE(lampAt(2), MachineComponentItem::litColour());            // retracted: Unclamped TRUE
    QVERIFY(lampAt(3) != MachineComponentItem::litColour());           // extended: Clamped FALSE
}

// The cells take the palette's base and text colours: readable in a dark theme too.
void TestMachineView::cellsFollowTheDarkPalette()
{
    loadDrillingCell();
    const QPalette light = QApplication::palette();
    QPalette dark = light;
    dark.setColor(QPalette::Base, QColor(0x1e, 0x1e, 0x1e));
    dark.setColor(QPalette::Text, QColor(0xe8, 0xe8, 0xe8));
    dark.setColor(QPalette::Window, QColor(0x2b, 0x2b, 0x2b));
    QApplication::setPalette(dark);
    const QRectF cell = scene()->componentItem(QStringLiteral("Clamp"))->boundingRect();
    const QImage image = render();
    QApplication::setPalette(light);
    const QPointF inside = QPointF(cell.right() - 8, cell.top() + 8) - scene()->sceneRect().topLeft();
    QCOMPARE(image.pixelColor(inside.toPoint()), QColor(0x1e, 0x1e, 0x1e));
    // The name's text in the palette's light text colour somewhere in the header.
    bool lightText = false;
    for (int x = 0; x < 40 && !lightText; ++x) {
        for (int y = 0; y < 16 && !lightText; ++y) {
            const QPointF at = QPointF(cell.left() + 6 + x, cell.top() + 6 + y) - scene()->sceneRect().topLeft();
            lightText = image.pixelColor(at.toPoint()).lightness() > 180;
        }
    }
    QVERIFY(lightText);
}

void TestMachineView::followsTheSimulation()
{
    loadDrillingCell();
    const int builds = scene()->rebuildCount();
    auto* clamp = dynamic_cast<CylinderItem*>(scene()->componentItem(QStringLiteral("Clamp")));
    const double restTip = clamp->rodTipX();
    startSimulation();
    QVERIFY(scene()->showsSimulation());
    QVERIFY(scene()->canOperate());
    QVERIFY(m_session->setVariable(index("StartButton"), true));
    m_session->advance(2);
    QVERIFY(m_session->setVariable(index("StartButton"), false));
    m_session->advance(1139 - 2); // the clamp half way
    QVERIFY(clamp->position() > 0.4 && clamp->position() < 0.6);
    QVERIFY(clamp->rodTipX() > restTip);
    QVERIFY(dynamic_cast<IndicatorItem*>(scene()->componentItem(QStringLiteral("Ready")))->isLit());
    m_session->advance(20);
    QCOMPARE(clamp->position(), 1.0);
    QVERIFY(scene()->signal(clamp->component(), core::machine::role::kDoubleExtended));
    // A scan repaints what moved, and rebuilds nothing.
    m_session->advance(1);
    QVERIFY(scene()->lastRepaintCount() >= 1);
    QVERIFY(scene()->lastRepaintCount() <= 3);
    QCOMPARE(scene()->rebuildCount(), builds);
    // The simulation ends: back at rest.
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger(); // the action toggles
    QVERIFY(!m_session->isActive());
    QCOMPARE(clamp->position(), 0.0);
}

void TestMachineView::followsTheHistory()
{
    loadDrillingCell();
    startSimulation();
    QVERIFY(m_session->setVariable(index("StartButton"), true));
    m_session->advance(2);
    m_session->advance(1140);
    auto* clamp = dynamic_cast<CylinderItem*>(scene()->componentItem(QStringLiteral("Clamp")));
    const double latest = clamp->position();
    m_session->showScan(m_session->latestScan() - 10);
    QVERIFY(clamp->position() < latest);
    QCOMPARE(clamp->position(), m_session->machineState()->position(clamp->component()));
    QVERIFY(!scene()->signal(clamp->component(), core::machine::role::kDoubleExtended));
    m_session->showScan(m_session->latestScan());
    QCOMPARE(clamp->position(), latest);
}

void TestMachineView::followsAReplay()
{
    loadDrillingCell();
    startSimulation();
    QString error;
    QVERIFY2(m_session->startReplay(QStringLiteral(GGSTUDIO_EXAMPLES_DIR "/drilling-cell-start.scenario"), &error),
             qPrintable(error));
    QVERIFY(!scene()->canOperate()); // the replay plays the operator
    m_session->advance(1160);
    auto* drill = dynamic_cast<CylinderItem*>(scene()->componentItem(QStringLiteral("DrillHead")));
    QVERIFY(drill->position() > 0.0);
    QCOMPARE(dynamic_cast<CylinderItem*>(scene()->componentItem(QStringLiteral("Clamp")))->position(), 1.0);
}

void TestMachineView::operatorInputsAreClickable()
{
    loadDrillingCell();
    m_window->centralTabs()->setCurrentWidget(view());
    startSimulation();
    auto* start = dynamic_cast<OperatorItem*>(scene()->componentItem(QStringLiteral("Start")));
    auto* stop = dynamic_cast<OperatorItem*>(scene()->componentItem(QStringLiteral("EmergencyStop")));
    QVERIFY(start && stop);
    const QPoint startAt = view()->mapFromScene(start->controlRect().center());
    QTest::mousePress(view()->viewport(), Qt::LeftButton, {}, startAt);
    QVERIFY(value("StartButton"));
    QVERIFY(start->isActuated());
    QTest::mouseRelease(view()->viewport(), Qt::LeftButton, {}, startAt);
    QVERIFY(value("StartButton")); // held for at least one scan
    m_session->advance(1);
    QVERIFY(!value("StartButton"));
    QCOMPARE(m_session->simulator()->activeStepId(), std::string("F2"));
    QVERIFY(m_session->recordingText().find("set StartButton = TRUE") != std::string::npos);

    // The emergency stop latches at a click and is released by the next.
    const QPoint stopAt = view()->mapFromScene(stop->controlRect().center());
    QTest::mouseClick(view()->viewport(), Qt::LeftButton, {}, stopAt);
    QVERIFY(!value("EmergencyOk"));
    QVERIFY(stop->isActuated());
    QTest::mouseClick(view()->viewport(), Qt::LeftButton, {}, stopAt);
    QVERIFY(value("EmergencyOk"));
}

// Frames of the Machine tab while simulating at 1,000 scans/s (16 scans a
// frame): each runs its scans and repaints the schematic, which follows the
// moving machine. How long a frame takes is a figure for the benchmarks
// (editor_benchmarks "Machine tab frame at 1,000 scans/s"), not for a test.
void TestMachineView::framesFollowTheSimulation()
{
    loadDrillingCell();
    m_window->centralTabs()->setCurrentWidget(view());
    startSimulation();
    QVERIFY(m_session->setVariable(index("StartButton"), true));
    m_session->advance(2);
    QVERIFY(m_session->setVariable(index("StartButton"), false));
    m_session->advance(1100); // from here the infeed, the clamp and the drill move
    const std::int64_t firstScan = m_session->latestScan();
    const QImage before = view()->viewport()->grab().toImage();
    int changedFrames = 0;
    QImage previous = before;
    for (int frame = 0; frame < 60; ++frame) {
        m_session->advance(16);
        view()->viewport()->repaint();
        const QImage shown = view()->viewport()->grab().toImage();
        changedFrames += shown != previous ? 1 : 0;
        previous = shown;
    }
    QCOMPARE(m_session->latestScan(), firstScan + 60 * 16);
    QVERIFY(previous != before);
    QVERIFY2(changedFrames > 0, "the schematic never changed while the machine moved");
}

// Right-click a cylinder: its sensors' faults and a jam. A faulted sensor's
// lamp is struck through in red; the items repaint for a fault alone.
void TestMachineView::faultsFromTheSchematic()
{
    loadDrillingCell();
    m_window->centralTabs()->setCurrentWidget(view());
    startSimulation();
    MachineComponentItem* clamp = scene()->componentItem(QStringLiteral("Clamp"));
    const QPoint at = view()->mapFromScene(clamp->boundingRect().center());
    const auto rightClick = [&] {
        QContextMenuEvent event(QContextMenuEvent::Mouse, at, view()->viewport()->mapToGlobal(at));
        QApplication::sendEvent(view()->viewport(), &event);
    };
    bool found = false;
    editortest::triggerInNextMenu(QStringLiteral("Fault of Clamped"), QStringLiteral("Stuck at TRUE"), &found);
    rightClick();
    QVERIFY(found);
    QCOMPARE(m_session->sensorFault(index("Clamped")), core::machine::SensorFault::StuckTrue);
    QCOMPARE(m_session->sensorFault(index("Unclamped")), core::machine::SensorFault::None);
    QVERIFY(value("Clamped"));

    // The fourth role line (extended: Clamped): lit, and struck through in red.
    const QRectF cell = clamp->boundingRect();
    const QPointF lamp(cell.left() + 6 + 5.5, cell.bottom() - 6 - 4 * 17 + 3 * 17 + 8.5);
    const QPoint pixel = (lamp - scene()->sceneRect().topLeft()).toPoint();
    const QImage drawn = render();
    int reddest = 255; // the lowest green of a strongly red pixel on the stroke's diagonal
    for (int step = -4; step <= 4; ++step) {
        for (int dx = -1; dx <= 1; ++dx) {
            const QColor c = drawn.pixelColor(pixel + QPoint(step + dx, -step));
            if (c.red() > 150)
                reddest = std::min(reddest, c.green());
        }
    }
    QVERIFY2(reddest < 110, qPrintable(QString::number(reddest)));

    editortest::triggerInNextMenu({}, QStringLiteral("Jam"), &found);
    rightClick();
    QVERIFY(found);
    QVERIFY(m_session->machineState()->jammed(0));
    QVERIFY(scene()->jammed(0));
    editortest::triggerInNextMenu({}, QStringLiteral("Clear Jam"), &found);
    rightClick();
    QVERIFY(found);
    QVERIFY(!m_session->machineState()->jammed(0));

    // Outside the simulation the schematic offers no fault.
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    QVERIFY(!m_session->isActive());
    editortest::triggerInNextMenu({}, QStringLiteral("Jam"), &found);
    rightClick();
    QTest::qWait(20);
    QVERIFY(!found);
}

QTEST_MAIN(TestMachineView)
#include "test_machineview.moc"
