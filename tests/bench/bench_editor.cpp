// Catch2 BENCHMARKs of the editor's responsiveness, behind the figures of the
// README's Performance section:
//  - a keystroke in the condition editor until the problems list, the ST
//    preview and the chart label show the new condition, painting included;
//  - the same keystroke in a nested receptivity (the Nested Transition
//    dock), until the problems list, the function block in the preview and
//    the label in the GRAFCET's tab show it;
//  - one frame of simulation at 1,000 scans/s: the batch of scans one
//    16 ms timer tick runs, the chart marks and Simulation dock refresh,
//    and the repaint of the chart and the dock;
//  - one frame of the Machine tab at 1,000 scans/s: the drilling cell in
//    closed loop with its machine, the batch of scans, the items that moved
//    repainted (the budget: under 16 ms);
//  - opening the tab of a 60-step nested GRAFCET, until it is painted;
//  - linking two steps of the drilling cell's F1 by mouse (a drag from a
//    step's handle to another step), until the tab is repainted;
//  - the cold start to the first shown chart against a bare Qt window
//    (tests/bench/startupprobe.cpp), both started here alternately, on the
//    platform this process runs on.
// Run with `xvfb-run -a` (X11, as a user's start) or QT_QPA_PLATFORM=offscreen
// when there is no display. Nothing here asserts a time: the machine running
// the tests decides those.

#include <catch2/catch.hpp>

#include "benchrepeats.h"
#include "catchsession.h"
#include "modelfactory.h"

#include "editor/app/languages.h"
#include "editor/chart/gemma/chartscene.h"
#include "editor/chart/gemma/chartview.h"
#include "editor/chart/gemma/transitionitem.h"
#include "editor/chart/layoutconversion.h"
#include "editor/docks/conditionedit.h"
#include "editor/docks/gemma/transitiondock.h"
#include "editor/docks/grafcettransitiondock.h"
#include "editor/docks/problemsdock.h"
#include "editor/docks/stpreviewdock.h"
#include "editor/document.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetstepitem.h"
#include "editor/grafcet/grafcettransitionitem.h"
#include "editor/grafcet/grafcetview.h"
#include "editor/grafcet/linkdrag.h"
#include "editor/mainwindow.h"
#include "editor/selection.h"
#include "editor/machine/machinetab.h"
#include "editor/machine/machineview.h"
#include "editor/simulation/simulationdock.h"
#include "editor/simulation/simulationsession.h"
#include "editor/simulation/tracetablemodel.h"

#include <QApplication>
#include <QDeadlineTimer>
#include <QElapsedTimer>
#include <QPlainTextEdit>
#include <QProcess>
#include <QProcessEnvironment>
#include <QSet>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTabWidget>
#include <QTextCursor>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>
#include <QUndoStack>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <functional>
#include <iterator>
#include <numeric>
#include <vector>

namespace {

const QString kTransition = QStringLiteral("F1->A2");
constexpr int kTimedKeystrokes = 100;

double mean(const std::vector<double>& values)
{
    return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    const std::size_t middle = values.size() / 2;
    return values.size() % 2 ? values[middle] : (values[middle - 1] + values[middle]) / 2.0;
}

// Whether the problems list has a row whose message names `word` (nested
// problems stand under their GRAFCET's row).
bool problemsMention(const editor::ProblemsDock& dock, const QString& word)
{
    for (QTreeWidgetItemIterator it(dock.view()); *it; ++it) {
        if ((*it)->text(editor::ProblemsDock::MessageColumn).contains(word))
            return true;
    }
    return false;
}

// The CPU time this thread has used, in milliseconds.
double threadCpuMs()
{
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) * 1e3 + static_cast<double>(now.tv_nsec) / 1e6;
}

// Processes events until `shown` holds; false after 5 s.
template <typename Shown>
bool waitFor(const Shown& shown)
{
    const QDeadlineTimer deadline(5000);
    while (!shown()) {
        if (deadline.hasExpired())
            return false;
        QCoreApplication::processEvents(QEventLoop::AllEvents);
    }
    return true;
}

// Types x and Backspace in turn into `editor` until `shows(typed)` holds
// (views updated), then repaints `viewport`: as a Catch BENCHMARK, then
// timed one by one for the median and the slow tail, which Catch's mean
// hides on a loaded machine. `shows` must hold for `false` on entry.
void benchmarkKeystrokes(const char* name, QWidget* editor, QWidget* viewport,
                         const std::function<bool(bool typed)>& shows)
{
    bool typedLast = false;
    bool allShown = true;
    BENCHMARK(name)
    {
        typedLast = !typedLast;
        QTest::keyClick(editor, typedLast ? Qt::Key_X : Qt::Key_Backspace);
        allShown = waitFor([&] { return shows(typedLast); }) && allShown;
        viewport->repaint();
    };
    CHECK(allShown);

    std::vector<double> latencies;
    for (int i = 0; i < kTimedKeystrokes; ++i) {
        typedLast = !typedLast;
        QElapsedTimer timer;
        timer.start();
        QTest::keyClick(editor, typedLast ? Qt::Key_X : Qt::Key_Backspace);
        REQUIRE(waitFor([&] { return shows(typedLast); }));
        viewport->repaint();
        latencies.push_back(static_cast<double>(timer.nsecsElapsed()) / 1e6);
    }
    std::sort(latencies.begin(), latencies.end());
    std::printf("\n%s, %d keystrokes: mean %.2f ms, median %.2f ms, 90th percentile %.2f ms, max %.2f ms\n",
                name, kTimedKeystrokes, mean(latencies), median(latencies), latencies[latencies.size() * 9 / 10],
                latencies.back());
    std::fflush(stdout);
}

// The window with the realistic model, F1->A2 in the Transition dock and the
// ST preview in front.
struct EditingSession {
    editor::Translators translators;
    // Before the window: a later change of language rebuilds its docks.
    bool english = translators.setLanguage(QStringLiteral("en"));
    editor::MainWindow window{translators};
    editor::TransitionDock* transitionDock = nullptr;
    editor::StPreviewDock* previewDock = nullptr;
    editor::ProblemsDock* problemsDock = nullptr;
    editor::ConditionEdit* conditionEdit = nullptr;
    editor::TransitionItem* chartItem = nullptr;

    EditingSession()
    {
        REQUIRE(english);
        window.show();
        REQUIRE(QTest::qWaitForWindowExposed(&window));
        window.document()->replaceModel(factory::realisticModel(), QString(), core::ModelFormat::Native);
        window.selection()->select(editor::ElementRef::transition(kTransition));
        transitionDock = window.findChild<editor::TransitionDock*>();
        previewDock = window.findChild<editor::StPreviewDock*>();
        problemsDock = window.findChild<editor::ProblemsDock*>();
        REQUIRE(transitionDock);
        REQUIRE(previewDock);
        REQUIRE(problemsDock);
        transitionDock->show();
        transitionDock->raise();
        previewDock->show();
        previewDock->raise();
        conditionEdit = transitionDock->findChild<editor::ConditionEdit*>();
        chartItem = window.chartScene()->transitionItem(kTransition);
        REQUIRE(conditionEdit);
        REQUIRE(chartItem);
        window.activateWindow();
        conditionEdit->setFocus();
        QTextCursor cursor = conditionEdit->textCursor();
        cursor.movePosition(QTextCursor::End);
        conditionEdit->setTextCursor(cursor);
        QTest::qWait(50);
    }

    // Problems list, ST preview and chart label all show (or all no longer
    // show) the word.
    bool showsEverywhere(const QString& word, bool shown) const
    {
        return problemsMention(*problemsDock, word) == shown
            && previewDock->editor()->toPlainText().contains(word) == shown
            && chartItem->labelText().contains(word) == shown;
    }

    // Processes events until the views show the state; false after 5 s.
    bool waitUntilShown(const QString& word, bool shown) const
    {
        return waitFor([&] { return showsEverywhere(word, shown); });
    }
};

} // namespace

TEST_CASE("keystroke to updated view", "[editorbench]")
{
    EditingSession session;
    const QString original = session.conditionEdit->text();
    REQUIRE(original == QStringLiteral("NOT Stop"));
    REQUIRE(session.previewDock->isVisible());
    REQUIRE(session.conditionEdit->isVisible());
    // "Stopx" is an undeclared variable: an error in the problems list, a
    // problem comment in the preview, and the label's new text.
    const QString typed = QStringLiteral("Stopx");
    REQUIRE(session.waitUntilShown(typed, false));

    // The pairs of keystrokes check that both states are reached before timing.
    QTest::keyClick(session.conditionEdit, Qt::Key_X);
    REQUIRE(session.waitUntilShown(typed, true));
    QTest::keyClick(session.conditionEdit, Qt::Key_Backspace);
    REQUIRE(session.waitUntilShown(typed, false));
    REQUIRE(session.conditionEdit->text() == original);

    benchmarkKeystrokes("keystroke to updated view", session.conditionEdit, session.window.chartView()->viewport(),
                        [&](bool shown) { return session.showsEverywhere(typed, shown); });
}

TEST_CASE("keystroke in a nested receptivity to updated view", "[editorbench]")
{
    editor::Translators translators;
    REQUIRE(translators.setLanguage(QStringLiteral("en")));
    editor::MainWindow window{translators};
    window.show();
    REQUIRE(QTest::qWaitForWindowExposed(&window));
    QAction* drillingCell = window.findChild<QAction*>(QStringLiteral("example_0"));
    REQUIRE(drillingCell);
    drillingCell->trigger();
    const QString f1 = QStringLiteral("F1");
    REQUIRE(window.openNestedGrafcet(f1));
    window.selection()->select(editor::ElementRef::grafcetTransition(f1, 3));
    auto* dock = window.findChild<editor::GrafcetTransitionDock*>();
    auto* preview = window.findChild<editor::StPreviewDock*>();
    auto* problems = window.findChild<editor::ProblemsDock*>();
    REQUIRE(dock);
    REQUIRE(preview);
    REQUIRE(problems);
    dock->show();
    dock->raise();
    preview->show();
    preview->raise();
    editor::ConditionEdit* edit = dock->receptivityEdit();
    REQUIRE(edit->text() == QStringLiteral("DrillLow"));
    editor::GrafcetView* view = window.grafcetView(f1);
    window.activateWindow();
    edit->setFocus();
    QTextCursor cursor = edit->textCursor();
    cursor.movePosition(QTextCursor::End);
    edit->setTextCursor(cursor);
    QTest::qWait(50);

    // "DrillLowx" is undeclared: a problem, a comment in the function block, the label.
    const QString typed = QStringLiteral("DrillLowx");
    const auto shows = [&](bool shown) {
        editor::GrafcetTransitionItem* label = view->grafcetScene()->transitionItem(3);
        return problemsMention(*problems, typed) == shown
            && preview->editor()->toPlainText().contains(typed) == shown && label
            && label->labelText().contains(typed) == shown;
    };
    REQUIRE(waitFor([&] { return shows(false); }));
    QTest::keyClick(edit, Qt::Key_X);
    REQUIRE(waitFor([&] { return shows(true); }));
    QTest::keyClick(edit, Qt::Key_Backspace);
    REQUIRE(waitFor([&] { return shows(false); }));

    benchmarkKeystrokes("keystroke in a nested receptivity to updated view", edit, view->viewport(), shows);
}

TEST_CASE("Machine tab frame at 1,000 scans/s", "[editorbench]")
{
    editor::Translators translators;
    translators.setLanguage(QStringLiteral("en"));
    editor::MainWindow window(translators);
    window.resize(1366, 768);
    window.show();
    REQUIRE(QTest::qWaitForWindowExposed(&window));
    window.findChild<QAction*>(QStringLiteral("example_0"))->trigger(); // the drilling cell and its machine
    editor::MachineView* view = window.machineTab()->view();
    REQUIRE(view);
    window.centralTabs()->setCurrentWidget(view);
    editor::SimulationSession* session = window.simulationSession();
    session->setActive(true);
    REQUIRE(session->isClosedLoop());
    const int start = session->simulator()->variableIndex("StartButton");
    REQUIRE(session->setVariable(start, true));
    session->advance(2);
    REQUIRE(session->setVariable(start, false));
    session->advance(1100); // warmed up: the infeed, the clamp and the drill move from here
    QTest::qWait(50);

    const int scansPerFrame = 1000 * editor::SimulationSession::kTickMs / 1000;
    const std::int64_t scansBefore = session->simulator()->scanCount();
    BENCHMARK("Machine tab frame at 1,000 scans/s")
    {
        session->advance(scansPerFrame);
        view->viewport()->repaint();
    };
    CHECK(session->simulator()->scanCount() > scansBefore);
}

TEST_CASE("simulation frame at 1,000 scans/s", "[editorbench]")
{
    editor::Translators translators;
    translators.setLanguage(QStringLiteral("en"));
    editor::MainWindow window(translators);
    window.resize(1366, 768);
    window.show();
    REQUIRE(QTest::qWaitForWindowExposed(&window));
    window.document()->replaceModel(factory::realisticModel(), QString(), core::ModelFormat::Native);
    editor::SimulationSession* session = window.simulationSession();
    session->setActive(true);
    REQUIRE(session->isActive());
    auto* dock = window.findChild<editor::SimulationDock*>();
    REQUIRE(dock);
    REQUIRE(dock->isVisible());
    // The trace in front: its rows scroll every frame, the costliest tab.
    auto* tabs = dock->findChild<QTabWidget*>(QStringLiteral("simulationTabs"));
    REQUIRE(tabs);
    tabs->setCurrentIndex(1);
    // Inputs that make the line cycle A1 -> F1 -> A2 -> A1 for ever, so
    // nearly every frame moves the active step and the fired transition.
    for (const char* input : {"HomePosition", "AirPressureOk", "Start", "PreparationDone", "DoorClosed", "CycleEnd"})
        REQUIRE(session->setVariable(session->simulator()->variableIndex(input), true));
    session->advance(100);
    REQUIRE(!session->lastFiredTransition().isEmpty());
    QTest::qWait(50);

    // What one 16 ms tick does at 1,000 scans/s.
    const int scansPerFrame = 1000 * editor::SimulationSession::kTickMs / 1000;
    QWidget* viewport = window.chartView()->viewport();
    const std::int64_t scansBefore = session->simulator()->scanCount();
    BENCHMARK("simulation frame at 1,000 scans/s")
    {
        session->advance(scansPerFrame);
        viewport->repaint();
        dock->repaint();
    };
    CHECK(session->simulator()->scanCount() > scansBefore);
    // The frames did fire transitions: the marks and the trace had work to do.
    QSet<QString> fired;
    for (const core::ScanRecord& record : session->trace())
        fired.insert(QString::fromStdString(record.fired));
    CHECK(fired.size() >= 4); // A1->F1, F1->A2, A2->A1 and the scans that fire none
    CHECK(dock->traceModel()->rowCount() == static_cast<int>(session->trace().size()));
}

namespace {

struct StartupTimes {
    double fromProcessStart = 0.0; // wall time seen by the parent: exec, libraries, main(), first paint
    double fromMain = 0.0;         // what the probe measured itself, from main()
    double docksFromProcessStart = 0.0; // ggstudio: until the docks' contents are ready
};

// The platform the probes run on: this process's, so that `xvfb-run -a
// editor_benchmarks` measures an X11 start (a window mapped on a display)
// and QT_QPA_PLATFORM=offscreen one without any display.
QString probePlatform()
{
    return QGuiApplication::platformName();
}

// Where the probe keeps its settings and autosave: an empty folder (a first
// start), or one where a GG Studio window was opened and closed before (a
// start with a saved layout).
enum class ProbeSettings { FirstStart, SavedLayout };

QProcessEnvironment probeEnvironment(const QTemporaryDir& home)
{
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("QT_QPA_PLATFORM"), probePlatform());
    environment.insert(QStringLiteral("XDG_CONFIG_HOME"), home.filePath(QStringLiteral("config")));
    environment.insert(QStringLiteral("XDG_DATA_HOME"), home.filePath(QStringLiteral("data")));
    environment.insert(QStringLiteral("XDG_CACHE_HOME"), home.filePath(QStringLiteral("cache")));
    return environment;
}

void saveALayout(const QTemporaryDir& home)
{
    QProcess probe;
    probe.setProcessEnvironment(probeEnvironment(home));
    probe.start(QStringLiteral(GGSTUDIO_STARTUP_PROBE), {QStringLiteral("save-layout")});
    REQUIRE(probe.waitForFinished(60000));
    INFO("startup_probe save-layout: " << probe.readAllStandardError().toStdString());
    REQUIRE(probe.exitStatus() == QProcess::NormalExit);
    REQUIRE(probe.exitCode() == 0);
}

// Runs `startup_probe MODE` once. The probe prints its own figure once the
// window's first frame showing the chart has been painted and flushed; the
// time until that line arrives here is the cold start a user waits through.
// GG Studio's probe then prints when its docks are ready.
StartupTimes probeOnce(const QString& mode, ProbeSettings settings = ProbeSettings::FirstStart)
{
    QTemporaryDir home;
    REQUIRE(home.isValid());
    if (settings == ProbeSettings::SavedLayout)
        saveALayout(home);
    const int expectedLines = mode == QStringLiteral("ggstudio") ? 2 : 1;
    QProcess probe;
    probe.setProcessEnvironment(probeEnvironment(home));
    QElapsedTimer clock;
    clock.start();
    probe.start(QStringLiteral(GGSTUDIO_STARTUP_PROBE), {mode});
    QByteArray output;
    std::vector<double> arrivals;
    while (static_cast<int>(arrivals.size()) < expectedLines && probe.waitForReadyRead(60000)) {
        output += probe.readAllStandardOutput();
        while (static_cast<int>(arrivals.size()) < output.count('\n'))
            arrivals.push_back(static_cast<double>(clock.nsecsElapsed()) / 1e6);
    }
    REQUIRE(probe.waitForFinished(60000));
    output += probe.readAllStandardOutput();
    INFO("startup_probe " << mode.toStdString() << ": " << probe.readAllStandardError().toStdString());
    REQUIRE(probe.exitStatus() == QProcess::NormalExit);
    REQUIRE(probe.exitCode() == 0);
    REQUIRE(static_cast<int>(arrivals.size()) == expectedLines);
    bool ok = false;
    const double fromMain = QString::fromLocal8Bit(output.split('\n').constFirst()).trimmed().toDouble(&ok);
    REQUIRE(ok);
    REQUIRE(fromMain > 0.0);
    return {arrivals.front(), fromMain, arrivals.back()};
}

// GGSTUDIO_STARTUP_RUNS, default 10.
int startupRuns()
{
    bool ok = false;
    const int runs = qEnvironmentVariableIntValue("GGSTUDIO_STARTUP_RUNS", &ok);
    return ok && runs > 0 ? runs : 10;
}

} // namespace

TEST_CASE("opening the tab of a 60-step GRAFCET", "[editorbench]")
{
    editor::Translators translators;
    REQUIRE(translators.setLanguage(QStringLiteral("en")));
    editor::MainWindow window{translators};
    window.show();
    REQUIRE(QTest::qWaitForWindowExposed(&window));
    window.document()->replaceModel(factory::longGrafcetModel(60), QString(), core::ModelFormat::Native);
    QTabWidget* tabs = window.centralTabs();
    const QString f1 = QStringLiteral("F1");

    // Opened, laid out and painted once; then closed for the next opening.
    const auto openAndPaint = [&] {
        REQUIRE(window.openNestedGrafcet(f1));
        editor::GrafcetView* view = window.grafcetView(f1);
        view->viewport()->repaint();
        return view;
    };
    const auto close = [&](editor::GrafcetView* view) { emit tabs->tabCloseRequested(tabs->indexOf(view)); };
    editor::GrafcetView* first = openAndPaint();
    REQUIRE(first->grafcetScene()->layout().steps.size() == 60);
    close(first);
    REQUIRE(!window.grafcetView(f1));

    BENCHMARK("open, lay out and paint the tab, then close it")
    {
        close(openAndPaint());
    };

    std::vector<double> openings;
    for (int i = 0; i < 30; ++i) {
        QElapsedTimer timer;
        timer.start();
        editor::GrafcetView* view = openAndPaint();
        openings.push_back(static_cast<double>(timer.nsecsElapsed()) / 1e6);
        close(view);
        QCoreApplication::processEvents();
    }
    std::sort(openings.begin(), openings.end());
    std::printf("\nopening the tab of a 60-step GRAFCET until painted, 30 openings: median %.2f ms, max %.2f ms\n",
                median(openings), openings.back());
    std::fflush(stdout);
}

TEST_CASE("linking two steps by mouse until the tab is repainted", "[editorbench]")
{
    editor::Translators translators;
    REQUIRE(translators.setLanguage(QStringLiteral("en")));
    editor::MainWindow window{translators};
    window.resize(1366, 768);
    window.show();
    REQUIRE(QTest::qWaitForWindowExposed(&window));
    QAction* drillingCell = window.findChild<QAction*>(QStringLiteral("example_0"));
    REQUIRE(drillingCell);
    drillingCell->trigger();
    const QString f1 = QStringLiteral("F1");
    REQUIRE(window.openNestedGrafcet(f1));
    editor::GrafcetView* view = window.grafcetView(f1);
    editor::GrafcetScene* scene = view->grafcetScene();
    QWidget* viewport = view->viewport();
    QUndoStack* undo = window.document()->undoStack();
    QTest::qWait(50);

    // Step 6 (the end of the drilling branch) to step 1: a new jump, T9.
    constexpr int kFrom = 6;
    constexpr int kTo = 1;
    constexpr int kNewTransition = 9;
    const auto linkAndRepaint = [&] {
        view->ensureVisible(scene->stepItem(kFrom));
        const QPoint handle = view->mapFromScene(editor::LinkDrag::handlePosition(*scene->stepItem(kFrom)));
        QTest::mousePress(viewport, Qt::LeftButton, {}, handle);
        view->ensureVisible(scene->stepItem(kTo));
        const QPoint target = view->mapFromScene(editor::toQRectF(scene->stepItem(kTo)->layout().box).center());
        QTest::mouseMove(viewport, target);
        QTest::mouseRelease(viewport, Qt::LeftButton, {}, target);
        const bool linked = waitFor([&] { return scene->transitionItem(kNewTransition) != nullptr; });
        QCoreApplication::processEvents(); // what the edit queued: the checks' results, the docks
        viewport->repaint();
        return linked;
    };
    const auto undoAndRepaint = [&] {
        undo->undo();
        const bool unlinked = waitFor([&] { return scene->transitionItem(kNewTransition) == nullptr; });
        QCoreApplication::processEvents();
        viewport->repaint();
        return unlinked;
    };
    REQUIRE(!scene->transitionItem(kNewTransition));
    REQUIRE(linkAndRepaint());
    REQUIRE(undoAndRepaint());

    // Catch's mean includes the undo that puts the drawing back for the next link.
    bool allDone = true;
    BENCHMARK("link two steps by mouse and repaint, then undo and repaint")
    {
        allDone = linkAndRepaint() && undoAndRepaint() && allDone;
    };
    CHECK(allDone);

    // The main thread's CPU time beside the wall time: on a loaded machine
    // the wall time also counts the waits for a core.
    std::vector<double> links;
    std::vector<double> cpu;
    const int timedLinks = benchRepeats(60);
    for (int i = 0; i < timedLinks; ++i) {
        QElapsedTimer timer;
        const double cpuBefore = threadCpuMs();
        timer.start();
        REQUIRE(linkAndRepaint());
        links.push_back(static_cast<double>(timer.nsecsElapsed()) / 1e6);
        cpu.push_back(threadCpuMs() - cpuBefore);
        REQUIRE(undoAndRepaint());
    }
    std::printf("\nlinking two steps by mouse until the tab is repainted (drilling cell F1), %d links: "
                "mean %.2f ms, median %.2f ms, max %.2f ms; main thread's CPU time mean %.2f ms, median %.2f ms\n",
                timedLinks, mean(links), median(links), *std::max_element(links.begin(), links.end()), mean(cpu), median(cpu));
    std::fflush(stdout);
}

TEST_CASE("cold start to the first shown chart", "[editorbench]")
{
    // Alternately, so a change of the machine's load weighs on all alike.
    struct Start {
        QString mode;
        ProbeSettings settings;
    };
    const Start starts[] = {{QStringLiteral("bare"), ProbeSettings::FirstStart},
                            {QStringLiteral("ggstudio"), ProbeSettings::FirstStart},
                            {QStringLiteral("chart"), ProbeSettings::FirstStart},
                            {QStringLiteral("ggstudio"), ProbeSettings::SavedLayout}};
    constexpr std::size_t kStarts = std::size(starts);
    std::vector<std::vector<double>> process(kStarts);
    std::vector<std::vector<double>> fromMain(kStarts);
    std::vector<std::vector<double>> docksReady(kStarts);
    const int runs = startupRuns();
    for (int run = 0; run < runs; ++run) {
        for (std::size_t start = 0; start < kStarts; ++start) {
            const StartupTimes times = probeOnce(starts[start].mode, starts[start].settings);
            process[start].push_back(times.fromProcessStart);
            fromMain[start].push_back(times.fromMain);
            docksReady[start].push_back(times.docksFromProcessStart);
        }
    }
    const double bare = median(process[0]);
    const double ggstudio = median(process[1]);
    const double chart = median(process[2]);
    const double saved = median(process[3]);
    std::printf("\ncold start to the first shown chart (platform %s), median of %d runs each:\n"
                "                                           from process start   from main()\n"
                "  bare QMainWindow + empty QGraphicsView:  %8.1f ms          %8.1f ms\n"
                "  GG Studio on the template:               %8.1f ms          %8.1f ms\n"
                "    ... and its docks filled in:           %8.1f ms\n"
                "  the bare window with the chart alone:    %8.1f ms          %8.1f ms\n"
                "  ratio GG Studio / bare:                  %8.2f             %8.2f\n"
                "  GG Studio, layout saved by a previous start:\n"
                "                                           %8.1f ms          %8.1f ms\n"
                "    ... and its docks filled in:           %8.1f ms\n"
                "  ratio GG Studio (saved layout) / bare:   %8.2f             %8.2f\n\n",
                qPrintable(probePlatform()), runs, bare, median(fromMain[0]), ggstudio, median(fromMain[1]),
                median(docksReady[1]), chart, median(fromMain[2]), ggstudio / bare,
                median(fromMain[1]) / median(fromMain[0]), saved, median(fromMain[3]), median(docksReady[3]),
                saved / bare, median(fromMain[3]) / median(fromMain[0]));
    std::fflush(stdout);
}

int main(int argc, char* argv[])
{
    QApplication app(argc, argv);
    // The window reads and writes its settings and autosave files: keep the
    // user's own out of it.
    QTemporaryDir settingsDir;
    QStandardPaths::setTestModeEnabled(true);
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir.path());
    QApplication::setOrganizationName(QStringLiteral("GG Studio Benchmarks"));
    QApplication::setApplicationName(QStringLiteral("editor_benchmarks"));
    return runCatchSession(argc, argv);
}
