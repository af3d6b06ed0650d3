// GG Studio: the GEMMA-GRAFCET editor. Usage: ggstudio [MODEL]

#include "editor/autosave.h"
#include "editor/languages.h"
#include "editor/mainwindow.h"
#include "editor/settings.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>

int main(int argc, char* argv[])
{
    QApplication app(argc, argv);
    // Where QSettings and autosave keep their files.
    QApplication::setOrganizationName(QStringLiteral("GG Studio"));
    QApplication::setApplicationName(QStringLiteral("GG Studio"));
    QApplication::setApplicationVersion(QStringLiteral(GGSTUDIO_VERSION));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/ggstudio.svg")));

    // Translated before any widget exists, so every text starts right.
    editor::Translators translators;
    translators.setLanguage(editor::Settings().language());

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

    editor::MainWindow window(translators);
    window.show();
    if (!editor::Autosave::pendingRecoveries().empty())
        window.offerRecovery();
    if (!parser.positionalArguments().isEmpty())
        window.openFile(parser.positionalArguments().constFirst());
    return app.exec();
}
