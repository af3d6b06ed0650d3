// startup_probe MODE [ARGS...]: milliseconds from main() to the first shown chart.
//
//   bare      QApplication + QMainWindow whose central widget is an empty
//             QGraphicsView, at the size GG Studio's window first opens with.
//   ggstudio  GG Studio's real startup (editor::runApplication, as app/gui
//             runs it) on the template; ARGS go to it as its command line.
//             It prints a second line: the time until the docks' contents,
//             built after the first frame, are ready.
//   save-layout  GG Studio's real startup, closed by the probe once its
//             docks are built and on screen: it leaves the settings a
//             closed window saves (its layout), for a start with a saved
//             layout. It times nothing.
//   chart     for reference: the bare window with GG Studio's chart of the
//             template instead of the empty view (no docks, menus or
//             status bar) and GG Studio's start-up warm-up thread
//             (editor/app/startupwarmup.h), the least any start showing this
//             chart costs.
//
// The time runs from the first statement of main() until the window's first
// frame showing the view has been painted whole and flushed to the window
// system (FirstPaintProbe), and is printed as one number ("123.456") before
// the probe quits. It starts at main() rather than at the process
// start (/proc/self/stat) because that start is counted in clock ticks (10 ms
// here, as coarse as the figure itself) and because both modes are this one
// executable: loading it and its libraries costs them the same. The
// editor_benchmarks case "cold start" runs both modes alternately.

#include "editor/app/application.h"
#include "editor/app/startupwarmup.h"
#include "editor/chart/gemma/chartscene.h"
#include "editor/chart/gemma/chartview.h"
#include "editor/document.h"
#include "editor/mainwindow.h"
#include "editor/selection.h"

#include <QApplication>
#include <QEvent>
#include <QGraphicsScene>
#include <QGraphicsView>
#include <QMainWindow>
#include <QScreen>
#include <QTimer>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

void printElapsed(Clock::time_point start)
{
    const std::chrono::duration<double, std::milli> elapsed = Clock::now() - start;
    std::printf("%.3f\n", elapsed.count());
    std::fflush(stdout);
}

// Prints the time until the first frame that shows the watched widget is on
// its way to the screen, then quits the application unless told to go on.
// A window paints all its widgets into its backing store and flushes that to
// the window system in one go; a call posted when the widget's first paint
// begins runs once that is done, whatever else the frame paints after it.
// Posted before the paint, it also runs before anything the paint posts
// (GG Studio builds its docks' contents right after the first frame).
class FirstPaintProbe : public QObject {
public:
    FirstPaintProbe(QWidget* watched, Clock::time_point start, bool quit = true)
        : QObject(watched)
        , m_start(start)
        , m_quit(quit)
    {
        watched->installEventFilter(this);
    }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() != QEvent::Paint)
            return false;
        watched->removeEventFilter(this);
        QMetaObject::invokeMethod(this, [this] {
            printElapsed(m_start);
            if (m_quit)
                QCoreApplication::exit(0);
        }, Qt::QueuedConnection);
        return false;
    }

private:
    Clock::time_point m_start;
    bool m_quit;
};

// The size MainWindow opens with when no layout was saved.
QSize firstWindowSize()
{
    const QScreen* screen = QGuiApplication::primaryScreen();
    const QSize available = screen ? screen->availableSize() : QSize(1366, 768);
    return QSize(std::min(available.width(), 1600), std::min(available.height(), 1000));
}

int runBare(int argc, char** argv, Clock::time_point start, bool withChart)
{
    // The chart's text waits for fontconfig; GG Studio loads it beside the
    // display connection, and so does the chart-alone reference.
    std::optional<editor::StartupWarmUp> warmUp;
    if (withChart)
        warmUp.emplace();
    QApplication app(argc, argv);
    QMainWindow window;
    QGraphicsView* view = nullptr;
    if (withChart) {
        warmUp->applicationReady();
        warmUp->waitForFontconfig();
        auto* document = new editor::Document(&window);
        auto* scene = new editor::ChartScene(document, new editor::Selection(&window), &window);
        view = new editor::ChartView(scene, &window);
    } else {
        view = new QGraphicsView(new QGraphicsScene(&window), &window);
    }
    window.setCentralWidget(view);
    window.resize(firstWindowSize());
    new FirstPaintProbe(view->viewport(), start);
    window.show();
    const int exitCode = app.exec();
    if (warmUp)
        warmUp->finish();
    return exitCode;
}

int runGgStudio(int argc, char** argv, Clock::time_point start)
{
    editor::StartupHooks hooks;
    hooks.windowCreated = [start](editor::MainWindow& window) {
        new FirstPaintProbe(window.chartView()->viewport(), start, false);
        QObject::connect(&window, &editor::MainWindow::docksBecameReady, &window, [start] {
            printElapsed(start);
            QCoreApplication::exit(0);
        });
    };
    return editor::runApplication(argc, argv, hooks);
}

// As a user closing the window once it is all there; closing saves the layout.
int runSaveLayout(int argc, char** argv)
{
    editor::StartupHooks hooks;
    hooks.windowCreated = [](editor::MainWindow& window) {
        QObject::connect(&window, &editor::MainWindow::docksBecameReady, &window, [&window] {
            // Once the docks are laid out and painted: the layout records
            // which docks are behind a tab by what is on screen.
            QTimer::singleShot(200, &window, [&window] { window.close(); });
        });
    };
    return editor::runApplication(argc, argv, hooks);
}

} // namespace

int main(int argc, char* argv[])
{
    const Clock::time_point start = Clock::now();
    const std::string mode = argc < 2 ? std::string() : std::string(argv[1]);
    if (mode != "bare" && mode != "ggstudio" && mode != "chart" && mode != "save-layout") {
        std::fputs("usage: startup_probe bare|ggstudio|chart|save-layout [ARGS...]\n", stderr);
        return 2;
    }
    // The application sees its own name and ARGS, not MODE.
    std::vector<char*> arguments{argv[0]};
    arguments.insert(arguments.end(), argv + 2, argv + argc);
    arguments.push_back(nullptr);
    const int count = argc - 1;
    if (mode == "ggstudio")
        return runGgStudio(count, arguments.data(), start);
    if (mode == "save-layout")
        return runSaveLayout(count, arguments.data());
    return runBare(count, arguments.data(), start, mode == "chart");
}
