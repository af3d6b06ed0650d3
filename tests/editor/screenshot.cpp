// ggstudio_screenshot OUT.png WIDTH HEIGHT [MODEL] [--select ID] [--raise DOCK]... [--show-hidden] [--language CODE]
//                     [--export-chart FILE.svg|png|pdf] [--dialog ACTION]
//                     [--simulate] [--input NAME=VALUE]... [--scans N] [--back N] [--replay FILE]
//                     [--replay-scans N] [--simulation-tab INDEX] [--verify] [--grafcet STEP]...
//                     [--problems-tab INDEX] [--machine]
//
// Opens the real main window at WIDTH x HEIGHT (optionally on a model file,
// with a step or transition selected, a dock brought to the front) and
// saves a picture of it: to look at the layout without a display
// (QT_QPA_PLATFORM=offscreen). --select takes a step ("F1"), a transition
// ("F1->A2"), or a nested GRAFCET's step ("F1/3") or transition ("F1/T2"),
// which opens that GRAFCET's tab. The selection can also come from the
// GGSTUDIO_SELECT environment variable; --export-chart also writes the
// chart as File > Export Chart does. --dialog triggers the window's action
// of that object name ("modelSettingsAction", "exportPlcOpenAction"...) and
// saves a picture of the first dialog it opens instead of the window. --simulate starts the simulation
// mode, then sets the --input values and runs the --scans in the order they are given
// (`--input A=TRUE --scans 2 --input B=TRUE --scans 5`: A before the first scan, B after the
// second); --back N then steps back N scans through the history; --replay FILE then starts that scenario's replay (paused at scan 0) and
// plays its first --replay-scans N scans. Settings go to a temporary folder,
// so the picture shows the default layout whatever the user's settings.
// --grafcet STEP opens the tab of that step's nested GRAFCET (several: the
// last one in front); with --simulate it shows the simulation's marks.
// --verify runs Simulation > Verify and waits for its findings.
// --problems-tab shows that tab of the Problems dock (0 checks, 1 verification, 2 properties).
// --machine brings the Machine tab (the model's virtual machine) to the front.

#include "editor/app/languages.h"
#include "editor/chart/gemma/chartscene.h"
#include "editor/chart/gemma/chartview.h"
#include "editor/export/chartexport.h"
#include "editor/mainwindow.h"
#include "editor/selection.h"
#include "editor/document.h"
#include "editor/machine/machinetab.h"
#include "editor/machine/machineview.h"
#include "editor/simulation/packml/packmlsimulationsession.h"
#include "editor/simulation/simulationsession.h"
#include "editor/style/windowbuttonstyle.h"
#include "editor/verificationrunner.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QSettings>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <cstdio>

namespace {

int usage()
{
    std::fputs("usage: ggstudio_screenshot OUT.png WIDTH HEIGHT [MODEL] [--select ID] [--raise DOCK]... "
               "[--show-hidden] [--language CODE] [--export-chart FILE] [--dialog ACTION] "
               "[--simulate] [--input NAME=VALUE]... [--scans N] [--back N] [--replay FILE] [--replay-scans N] "
               "[--simulation-tab INDEX] [--verify] [--grafcet STEP]... [--problems-tab INDEX] [--machine]\n",
               stderr);
    return 2;
}

// Triggers the action and saves the first modal dialog it opens (or the
// window it shows); closes every dialog after it, so the action returns.
int grabDialog(QWidget& window, const QString& actionName, const QString& out)
{
    auto* action = window.findChild<QAction*>(actionName);
    if (!action) {
        std::fprintf(stderr, "ggstudio_screenshot: no action named %s\n", qPrintable(actionName));
        return 2;
    }
    bool grabbed = false;
    bool saved = false;
    QTimer poll;
    poll.setInterval(100);
    QObject::connect(&poll, &QTimer::timeout, [&] {
        QWidget* modal = QApplication::activeModalWidget();
        if (!modal)
            return;
        if (!grabbed) {
            grabbed = true;
            saved = modal->grab().save(out);
        }
        modal->close();
    });
    poll.start();
    action->trigger();
    poll.stop();
    // An action that opens a window of its own (Help > User Guide): that window.
    for (QWidget* top : QApplication::topLevelWidgets()) {
        if (!grabbed && top != &window && top->isVisible() && top->isWindow() && !top->inherits("QMenu")) {
            grabbed = true;
            QApplication::processEvents();
            saved = top->grab().save(out);
        }
    }
    if (!grabbed)
        std::fprintf(stderr, "ggstudio_screenshot: %s opened no dialog\n", qPrintable(actionName));
    else if (!saved)
        std::fprintf(stderr, "ggstudio_screenshot: cannot write %s\n", qPrintable(out));
    return grabbed && saved ? 0 : 1;
}

// "F1", "F1->A2", or a nested element: "F1/3" (step 3 of F1's GRAFCET), "F1/T2" (its transition 2).
editor::ElementRef selectionOf(const QString& text)
{
    if (text.contains(QLatin1Char('/'))) {
        const QString stepId = text.section(QLatin1Char('/'), 0, 0);
        const QString nested = text.section(QLatin1Char('/'), 1);
        if (nested.startsWith(QLatin1Char('T'), Qt::CaseInsensitive))
            return editor::ElementRef::grafcetTransition(stepId, nested.mid(1).toInt());
        return editor::ElementRef::grafcetStep(stepId, nested.toInt());
    }
    return text.contains(QLatin1String("->")) ? editor::ElementRef::transition(text) : editor::ElementRef::step(text);
}

// Replays `scenario` (none when empty) for `scans` scans in either
// simulation session; false, with the reason on stderr, when it cannot start.
template <typename Session>
bool replayed(Session& session, const QString& scenario, int scans)
{
    if (scenario.isEmpty())
        return true;
    QString error;
    if (!session.startReplay(scenario, &error)) {
        std::fprintf(stderr, "ggstudio_screenshot: --replay %s: %s\n", qPrintable(scenario), qPrintable(error));
        return false;
    }
    session.advance(scans);
    return true;
}

} // namespace

int main(int argc, char* argv[])
{
    QApplication app(argc, argv);
    editor::WindowButtonStyle::install(); // as the application does
    QTemporaryDir settingsDir;
    QStandardPaths::setTestModeEnabled(true);
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir.path());
    QApplication::setOrganizationName(QStringLiteral("GG Studio Screenshot"));
    QApplication::setApplicationName(QStringLiteral("ggstudio_screenshot"));

    QStringList positional;
    QStringList docks;
    QString selected = qEnvironmentVariable("GGSTUDIO_SELECT");
    QString language = QStringLiteral("en");
    QString chartFile;
    QString dialogAction;
    bool showHidden = false;
    bool simulate = false;
    bool verify = false;
    // The --input and --scans of the simulation, in their order: an input
    // ("NAME=VALUE"), or a number of scans.
    struct Play {
        QString input;
        int scans = 0;
    };
    QList<Play> plays;
    int back = 0;
    QString replay;
    int replayScans = 0;
    int simulationTab = 0;
    int problemsTab = -1;
    bool machine = false;
    QStringList grafcets; // the GEMMA steps whose nested GRAFCETs' tabs are opened
    const QStringList args = app.arguments().mid(1);
    for (qsizetype i = 0; i < args.size(); ++i) {
        if (args[i] == QLatin1String("--select") && i + 1 < args.size())
            selected = args[++i];
        else if (args[i] == QLatin1String("--raise") && i + 1 < args.size())
            docks << args[++i];
        else if (args[i] == QLatin1String("--language") && i + 1 < args.size())
            language = args[++i];
        else if (args[i] == QLatin1String("--dialog") && i + 1 < args.size())
            dialogAction = args[++i];
        else if (args[i] == QLatin1String("--export-chart") && i + 1 < args.size())
            chartFile = args[++i];
        else if (args[i] == QLatin1String("--show-hidden"))
            showHidden = true;
        else if (args[i] == QLatin1String("--simulate"))
            simulate = true;
        else if (args[i] == QLatin1String("--verify"))
            verify = true;
        else if (args[i] == QLatin1String("--input") && i + 1 < args.size())
            plays.append({args[++i], 0});
        else if (args[i] == QLatin1String("--scans") && i + 1 < args.size())
            plays.append({QString(), args[++i].toInt()});
        else if (args[i] == QLatin1String("--back") && i + 1 < args.size())
            back = args[++i].toInt();
        else if (args[i] == QLatin1String("--replay") && i + 1 < args.size())
            replay = args[++i];
        else if (args[i] == QLatin1String("--replay-scans") && i + 1 < args.size())
            replayScans = args[++i].toInt();
        else if (args[i] == QLatin1String("--simulation-tab") && i + 1 < args.size())
            simulationTab = args[++i].toInt();
        else if (args[i] == QLatin1String("--problems-tab") && i + 1 < args.size())
            problemsTab = args[++i].toInt();
        else if (args[i] == QLatin1String("--grafcet") && i + 1 < args.size())
            grafcets << args[++i];
        else if (args[i] == QLatin1String("--machine"))
            machine = true;
        else if (args[i].startsWith(QLatin1String("--")))
            return usage();
        else
            positional << args[i];
    }
    if (positional.size() < 3 || positional.size() > 4)
        return usage();
    bool okWidth = false;
    bool okHeight = false;
    const int width = positional[1].toInt(&okWidth);
    const int height = positional[2].toInt(&okHeight);
    if (!okWidth || !okHeight || width < 200 || height < 200 || width > 8000 || height > 8000) {
        std::fputs("ggstudio_screenshot: WIDTH and HEIGHT must be whole numbers from 200 to 8000\n", stderr);
        return 2;
    }

    editor::Translators translators;
    translators.setLanguage(language);
    editor::MainWindow window(translators);
    window.resize(width, height);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window))
        return 1;
    // The default layout for this window size, as a first start on a screen
    // of that size has it (the window was built at the offscreen screen's).
    window.findChild<QAction*>(QStringLiteral("resetLayoutAction"))->trigger();
    if (positional.size() == 4 && !window.openFile(positional[3]))
        return 1;
    if (showHidden)
        window.findChild<QAction*>(QStringLiteral("showHiddenAction"))->setChecked(true);
    for (const QString& grafcet : grafcets) {
        if (!window.openNestedGrafcet(grafcet)) {
            std::fprintf(stderr, "ggstudio_screenshot: %s has no nested GRAFCET\n", qPrintable(grafcet));
            return 2;
        }
    }
    if (!selected.isEmpty())
        window.selection()->select(selectionOf(selected));
    for (const QString& name : docks) {
        auto* dock = window.findChild<QDockWidget*>(name);
        if (!dock) {
            std::fprintf(stderr, "ggstudio_screenshot: no dock named %s\n", qPrintable(name));
            return 2;
        }
        dock->show();
        dock->raise();
    }
    if (verify) {
        window.findChild<QAction*>(QStringLiteral("verifyAction"))->trigger();
        editor::VerificationRunner* runner = window.verificationRunner();
        if (!QTest::qWaitFor([runner] { return !runner->isRunning(); }, 120000)) {
            std::fputs("ggstudio_screenshot: the verification did not finish\n", stderr);
            return 1;
        }
    }
    // A PackML model: its session plays the scans and the replay (its inputs are set in its dock).
    if (simulate && window.document()->model().packml()) {
        window.findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
        auto* session = window.findChild<editor::PackmlSimulationSession*>();
        for (const Play& play : plays)
            session->advance(play.scans);
        if (!replayed(*session, replay, replayScans))
            return 2;
        if (auto* tabs = window.findChild<QTabWidget*>(QStringLiteral("packmlSimulationTabs")))
            tabs->setCurrentIndex(simulationTab);
    } else if (simulate) {
        window.findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
        editor::SimulationSession* session = window.simulationSession();
        for (const Play& play : plays) {
            if (play.input.isEmpty()) {
                session->advance(play.scans);
                continue;
            }
            const QString& input = play.input;
            const QString name = input.section(QLatin1Char('='), 0, 0);
            const int index = session->simulator()->variableIndex(name.toStdString());
            const auto status = index < 0 ? core::Status::failure("", "unknown variable")
                                           : window.simulationSession()->simulator()->variableType(index)
                                                         == core::IecType::Bool
                                               ? core::Status::success()
                                               : core::Status::failure("", "not a BOOL");
            if (!status) {
                std::fprintf(stderr, "ggstudio_screenshot: --input %s: %s\n", qPrintable(input),
                             status.message.c_str());
                return 2;
            }
            session->setVariable(index, input.section(QLatin1Char('='), 1).compare(QLatin1String("TRUE"),
                                                                                 Qt::CaseInsensitive) == 0);
        }
        for (int i = 0; i < back; ++i)
            session->stepBack();
        if (!replayed(*session, replay, replayScans))
            return 2;
        if (auto* tabs = window.findChild<QTabWidget*>(QStringLiteral("simulationTabs")))
            tabs->setCurrentIndex(simulationTab);
    }
    if (auto* tabs = window.findChild<QTabWidget*>(QStringLiteral("problemsTabs")); tabs && problemsTab >= 0)
        tabs->setCurrentIndex(problemsTab);
    if (machine) {
        if (!window.machineTab()->view()) {
            std::fputs("ggstudio_screenshot: --machine: the model has no machine\n", stderr);
            return 2;
        }
        window.centralTabs()->setCurrentWidget(window.machineTab()->view());
    }
    QTest::qWait(50);
    window.chartView()->zoomToFit();
    QApplication::processEvents();

    if (!chartFile.isEmpty()) {
        editor::ChartExport chart(*window.chartScene());
        editor::ChartExport::Format format;
        QString error;
        if (!editor::ChartExport::formatForPath(chartFile, &format) || !chart.write(chartFile, format, &error)) {
            std::fprintf(stderr, "ggstudio_screenshot: cannot export the chart to %s %s\n", qPrintable(chartFile),
                         qPrintable(error));
            return 1;
        }
    }
    if (!dialogAction.isEmpty())
        return grabDialog(window, dialogAction, positional[0]);
    if (!window.grab().save(positional[0])) {
        std::fprintf(stderr, "ggstudio_screenshot: cannot write %s\n", qPrintable(positional[0]));
        return 1;
    }
    return 0;
}
