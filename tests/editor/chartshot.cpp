// chart_screenshot OUT.png [WIDTH HEIGHT] [--template] [--show-hidden] [--select ID] [--hide ID]...
//                  [--model FILE] [--export]
//
// Renders the chart as the editor shows it, fitted into a WIDTH x HEIGHT view
// (default 1366 x 768), to look at the drawing without a display
// (QT_QPA_PLATFORM=offscreen). By default the chart shows the realistic
// bottle-filling model of the test support; --template shows the bare
// template (every condition empty, so every transition is marked); --model
// shows a model file. --export writes OUT through the chart export instead
// (SVG, PNG or PDF after its extension; WIDTH and HEIGHT do not apply).

#include "editor/chart/gemma/chartscene.h"
#include "editor/chart/gemma/chartview.h"
#include "editor/document.h"
#include "editor/export/chartexport.h"
#include "editor/selection.h"

#include "modelfactory.h"

#include <QApplication>
#include <QPixmap>
#include <QStringList>
#include <QTextStream>

#include <cstdio>

namespace {

int usage()
{
    std::fputs("usage: chart_screenshot OUT.png [WIDTH HEIGHT] [--template] [--show-hidden] [--select ID] [--hide ID]...\n"
               "                        [--model FILE] [--export]\n",
               stderr);
    return 2;
}

} // namespace

int main(int argc, char* argv[])
{
    QApplication app(argc, argv);
    QStringList args = app.arguments().mid(1);

    bool bareTemplate = false;
    bool showHidden = false;
    bool exportChart = false;
    QString modelFile;
    QString selected;
    QStringList hiddenSteps;
    QStringList positional;
    for (qsizetype i = 0; i < args.size(); ++i) {
        if (args[i] == "--template")
            bareTemplate = true;
        else if (args[i] == "--show-hidden")
            showHidden = true;
        else if (args[i] == "--select" && i + 1 < args.size())
            selected = args[++i];
        else if (args[i] == "--hide" && i + 1 < args.size())
            hiddenSteps << args[++i];
        else if (args[i] == "--model" && i + 1 < args.size())
            modelFile = args[++i];
        else if (args[i] == "--export")
            exportChart = true;
        else if (args[i].startsWith("--"))
            return usage();
        else
            positional << args[i];
    }
    if (positional.size() != 1 && positional.size() != 3)
        return usage();
    int width = 1366;
    int height = 768;
    if (positional.size() == 3) {
        bool okWidth = false;
        bool okHeight = false;
        width = positional[1].toInt(&okWidth);
        height = positional[2].toInt(&okHeight);
        if (!okWidth || !okHeight || width < 100 || height < 100 || width > 8000 || height > 8000) {
            std::fputs("chart_screenshot: WIDTH and HEIGHT must be whole numbers from 100 to 8000\n", stderr);
            return 2;
        }
    }

    editor::Document document;
    if (!modelFile.isEmpty()) {
        QString error;
        if (!document.load(modelFile, &error)) {
            std::fprintf(stderr, "chart_screenshot: %s\n", qPrintable(error));
            return 1;
        }
    } else if (!bareTemplate) {
        document.replaceModel(factory::realisticModel(), QString(), core::ModelFormat::Native);
    }
    for (const QString& step : hiddenSteps) {
        if (!document.modelForCommands().setStepHidden(step.toStdString(), true))
            std::fprintf(stderr, "chart_screenshot: no step %s to hide\n", qPrintable(step));
    }
    editor::Selection selection;
    editor::ChartScene scene(&document, &selection);
    scene.setShowHidden(showHidden);
    if (!selected.isEmpty())
        selection.select(selected.contains("->") ? editor::ElementRef::transition(selected)
                                                 : editor::ElementRef::step(selected));

    const QString out = positional[0];
    if (exportChart) {
        editor::ChartExport::Format format;
        QString error;
        if (!editor::ChartExport::formatForPath(out, &format) || !editor::ChartExport(scene).write(out, format, &error)) {
            std::fprintf(stderr, "chart_screenshot: cannot write %s %s\n", qPrintable(out), qPrintable(error));
            return 1;
        }
        return 0;
    }

    editor::ChartView view(&scene);
    view.resize(width, height);
    view.show();
    view.zoomToFit();
    QApplication::processEvents();

    if (!view.grab().save(out)) {
        std::fprintf(stderr, "chart_screenshot: cannot write %s\n", qPrintable(out));
        return 1;
    }
    return 0;
}
