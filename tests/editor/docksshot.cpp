// docks_screenshot OUT_DIR [SIDE_WIDTH SIDE_HEIGHT]
//
// Renders each dock of the editor, filled from the realistic bottle-filling
// model of the test support (plus one broken condition), into
// OUT_DIR/<objectName>.png at the size a dock gets beside the chart
// (default 340 x 560 for the Step and Transition docks, 900 x 260 for the
// bottom ones), the Transition dock also on the broken condition
// (transitionDock-error.png) and its condition editor enlarged
// (conditionEdit-zoom.png), to look at them without a display
// (QT_QPA_PLATFORM=offscreen).

#include "editor/commands/setconditioncommand.h"
#include "editor/docks/gemma/stepdock.h"
#include "editor/docks/gemma/transitiondock.h"
#include "editor/docks/problemsdock.h"
#include "editor/docks/stpreviewdock.h"
#include "editor/docks/variablesdock.h"
#include "editor/document.h"
#include "editor/selection.h"

#include "modelfactory.h"

#include <QApplication>
#include <QDir>
#include <QPixmap>

#include <cstdio>

namespace {

bool save(QWidget& dock, const QSize& size, const QString& directory)
{
    dock.resize(size);
    dock.show();
    QApplication::processEvents();
    QApplication::processEvents();
    const QString path = QDir(directory).filePath(dock.objectName() + QStringLiteral(".png"));
    if (!dock.grab().save(path)) {
        std::fprintf(stderr, "cannot write %s\n", qPrintable(path));
        return false;
    }
    std::printf("%s\n", qPrintable(path));
    return true;
}

} // namespace

int main(int argc, char* argv[])
{
    QApplication app(argc, argv);
    const QStringList args = app.arguments().mid(1);
    if (args.size() != 1 && args.size() != 3) {
        std::fputs("usage: docks_screenshot OUT_DIR [SIDE_WIDTH SIDE_HEIGHT]\n", stderr);
        return 2;
    }
    const QSize side = args.size() == 3 ? QSize(args[1].toInt(), args[2].toInt()) : QSize(340, 560);
    const QSize bottom(900, 260);

    editor::Document document;
    document.replaceModel(factory::realisticModel(), QString(), core::ModelFormat::Native);
    // One broken condition, to see the underline and the problem rows.
    document.push(new editor::SetConditionCommand(document, "A1->F4", "Start AND Mode = 2 AND Unknwn"));
    editor::Selection selection;

    editor::StepDock step(&document, &selection);
    editor::TransitionDock transition(&document, &selection);
    editor::VariablesDock variables(&document, &selection);
    editor::ProblemsDock problems(&document, &selection);
    editor::StPreviewDock preview(&document, &selection);

    bool ok = true;
    selection.select(editor::ElementRef::step("F1"));
    ok = save(step, side, args[0]) && ok;
    ok = save(preview, bottom, args[0]) && ok;
    selection.select(editor::ElementRef::transition("F1->A2"));
    ok = save(transition, side, args[0]) && ok;
    transition.setObjectName("transitionDock-error");
    selection.select(editor::ElementRef::transition("A1->F4"));
    ok = save(transition, side, args[0]) && ok;
    // The condition with its underlines, enlarged.
    if (auto* condition = transition.findChild<QWidget*>(QStringLiteral("conditionEdit"))) {
        const QPixmap pixmap = condition->grab();
        ok = pixmap.scaled(pixmap.size() * 3).save(QDir(args[0]).filePath(QStringLiteral("conditionEdit-zoom.png")))
            && ok;
    }
    selection.select(editor::ElementRef::variable(QString::fromStdString(document.model().variables()[2].name)));
    ok = save(variables, bottom, args[0]) && ok;
    ok = save(problems, bottom, args[0]) && ok;
    return ok ? 0 : 1;
}
