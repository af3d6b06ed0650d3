// packml_chart_screenshot OUT.png W H MODEL [--mode N] [--language fr] [--select STATE]
//
// Renders the PackML chart as the editor shows it (mode selector above the
// sheet fitted into a W x H view) to look at the drawing without a display
// (QT_QPA_PLATFORM=offscreen). MODEL is a PackML model file, or "new" or
// "new2022" for a new model of that edition.

#include "core/formats/modelfiles.h"
#include "core/templates/packml/packmlmodel.h"
#include "editor/app/languages.h"
#include "editor/chart/packml/packmlchartscene.h"
#include "editor/chart/packml/packmlchartview.h"
#include "editor/selection.h"

#include <QApplication>
#include <QFile>
#include <QPixmap>

#include <cstdio>

namespace {

int usage()
{
    std::fputs("usage: packml_chart_screenshot OUT.png W H MODEL [--mode N] [--language fr] [--select STATE]\n", stderr);
    return 2;
}

} // namespace

int main(int argc, char* argv[])
{
    QApplication app(argc, argv);
    const QStringList args = app.arguments().mid(1);
    QStringList positional;
    int mode = -1;
    QString language;
    QString selected;
    for (qsizetype i = 0; i < args.size(); ++i) {
        if (args[i] == "--mode" && i + 1 < args.size())
            mode = args[++i].toInt();
        else if (args[i] == "--language" && i + 1 < args.size())
            language = args[++i];
        else if (args[i] == "--select" && i + 1 < args.size())
            selected = args[++i];
        else if (args[i].startsWith("--"))
            return usage();
        else
            positional << args[i];
    }
    if (positional.size() != 4)
        return usage();
    const int width = positional[1].toInt();
    const int height = positional[2].toInt();
    if (width < 100 || height < 100 || width > 8000 || height > 8000)
        return usage();

    core::Model model;
    if (positional[3] == "new" || positional[3] == "new2022") {
        model.assign(core::packml::newModel(positional[3] == "new" ? core::packml::Edition::Y2015
                                                                   : core::packml::Edition::Y2022));
    } else {
        core::LoadedModel loaded = core::loadModelFile(QFile::encodeName(positional[3]).toStdString());
        if (!loaded.model) {
            std::fprintf(stderr, "packml_chart_screenshot: cannot load %s\n", qPrintable(positional[3]));
            return 1;
        }
        model.assign(*loaded.model);
    }
    editor::Translators translators;
    translators.setLanguage(language.isEmpty() ? QStringLiteral("en") : language);

    editor::Selection selection;
    editor::PackmlChartScene scene(&model, &selection);
    if (mode >= 0)
        scene.setMode(mode);
    if (!selected.isEmpty())
        selection.select(editor::ElementRef::packmlState(selected, scene.mode()));
    editor::PackmlChartView view(&scene);
    view.resize(width, height);
    view.show();
    QApplication::processEvents();
    if (!view.grab().save(positional[0])) {
        std::fprintf(stderr, "packml_chart_screenshot: cannot write %s\n", qPrintable(positional[0]));
        return 1;
    }
    return 0;
}
