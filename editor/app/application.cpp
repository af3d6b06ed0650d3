#include "editor/app/application.h"

#include "editor/app/autosave.h"
#include "editor/app/languages.h"
#include "editor/app/settings.h"
#include "editor/app/startupwarmup.h"
#include "editor/mainwindow.h"
#include "editor/style/windowbuttonstyle.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>

namespace editor {

int runApplication(int argc, char** argv, const StartupHooks& hooks)
{
    // Beside the platform's start-up (startupwarmup.h).
    StartupWarmUp warmUp;
    QApplication app(argc, argv);
    // Before any widget exists, so that every one is built with it.
    WindowButtonStyle::install();
    // Where QSettings and autosave keep their files.
    QApplication::setOrganizationName(QStringLiteral("GG Studio"));
    QApplication::setApplicationName(QStringLiteral("GG Studio"));
    QApplication::setApplicationVersion(QStringLiteral(GGSTUDIO_VERSION));

    // Translated before any widget exists, so every text starts right.
    Translators translators;
    translators.setLanguage(Settings().language());

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QApplication::translate("main", "Editor for the GEMMA-GRAFCET method of specifying machine operating modes"));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("model"),
                                 QApplication::translate("main", "The model file to open (GG Studio JSON, "
                                                                 "GG-Generator JSON or GG Studio PLCopen XML)."),
                                 QStringLiteral("[model]"));
    parser.process(app);

    warmUp.applicationReady();
    // Nothing above lays out text; the chart's labels below do.
    warmUp.waitForFontconfig();
    // The chart first: the docks fill in right after the first frame.
    MainWindow window(translators, MainWindow::DockContents::AfterFirstFrame);
    // After the first frame as well: the X11 platform renders the icon in
    // every size a window manager may ask for, a cost the chart need not wait for.
    QObject::connect(&window, &MainWindow::firstFrameShown, &app, [] {
        QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/ggstudio.svg")));
    }, Qt::QueuedConnection);
    if (hooks.windowCreated)
        hooks.windowCreated(window);
    window.show();
    if (!Autosave::pendingRecoveries().empty())
        window.offerRecovery();
    if (!parser.positionalArguments().isEmpty())
        window.openFile(parser.positionalArguments().constFirst());
    const int exitCode = app.exec();
    warmUp.finish();
    return exitCode;
}

} // namespace editor
