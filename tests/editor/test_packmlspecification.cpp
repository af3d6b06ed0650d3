// File > Export Specification for a PackML model: the title page, the chart
// of each unit mode on a landscape page of its own, the commands, the modes
// and what each runs in its acting states and Execute, the variables, each
// own GRAFCET from a page headed "Production · Execute" and the code
// outline; read back with poppler-utils (the tests skip without them).

#include "editortestsupport.h"
#include "pdfpages.h"

#include "editor/app/languages.h"
#include "editor/document.h"
#include "editor/export/exportactions.h"
#include "editor/export/specificationexport.h"
#include "editor/mainwindow.h"

#include "core/formats/modelfiles.h"
#include "core/templates/packml/packmlmodel.h"

#include <QAction>
#include <QTemporaryDir>
#include <QTest>

using namespace editor;
using namespace pdfpages;

namespace {

const QString kBottleFiller = QStringLiteral(GGSTUDIO_EXAMPLES_DIR "/bottle-filler.ggstudio.json");

bool landscape(const PageWords& page)
{
    return page.size.width() > page.size.height();
}

} // namespace

class TestPackmlSpecification : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();

    void everyTextOfTheBottleFillerIsThere();
    void oneChartPagePerMode();
    void eachOwnGrafcetStartsAPageOfItsOwn();
    void wordsNeitherOverlapNorLeaveTheirPage();
    void whatEachModeRunsIsSaid();
    void fileMenuActionWritesItForAPackmlModel();

private:
    QString exportModel(const core::Model& model, const QString& name);
    QString exportBottleFiller(const QString& name);

    QTemporaryDir m_settings;
    QTemporaryDir m_files;
};

void TestPackmlSpecification::initTestCase()
{
    QVERIFY(m_settings.isValid());
    QVERIFY(m_files.isValid());
    editortest::useTestSettings(m_settings.path(), QStringLiteral("test_packmlspecification"));
}

QString TestPackmlSpecification::exportModel(const core::Model& model, const QString& name)
{
    Document document(model);
    const QString path = m_files.filePath(name);
    QString error;
    if (!SpecificationExport(document).writePdf(path, &error)) {
        qWarning("%s", qPrintable(error));
        return {};
    }
    return path;
}

QString TestPackmlSpecification::exportBottleFiller(const QString& name)
{
    const core::LoadedModel example = core::loadModelFile(kBottleFiller.toStdString());
    if (!example.ok())
        return {};
    return exportModel(*example.model, name);
}

void TestPackmlSpecification::everyTextOfTheBottleFillerIsThere()
{
    const QString path = exportBottleFiller(QStringLiteral("bottle.pdf"));
    QVERIFY(!path.isEmpty());
    QVERIFY(readAll(path).startsWith("%PDF"));
    if (!havePoppler())
        QSKIP("pdfinfo or pdftotext is not installed (poppler-utils)");
    const core::LoadedModel example = core::loadModelFile(kBottleFiller.toStdString());
    QVERIFY(example.ok());
    const core::Model& model = *example.model;
    const core::packml::Configuration& configuration = *model.packml();

    const QString text = flat(pageTexts(path, QStringLiteral("-raw")));
    for (const QString& expected : {QStringLiteral("PackML specification"), QStringLiteral("PackML, 2015 edition"),
                                    QStringLiteral("Initial unit mode 1 Production"), QStringLiteral("10 ms"),
                                    QStringLiteral("PROGRAM BottleFiller"),
                                    QStringLiteral("FUNCTION_BLOCK Production_Execute_FB"),
                                    QStringLiteral("BottleFiller calls it while the unit is in Execute")})
        QVERIFY2(text.contains(expected), qPrintable(expected));
    for (const core::packml::CommandInfo& info : core::packml::allCommands()) {
        const core::packml::CommandSetting& setting = configuration.command(info.command);
        if (!core::packml::commandInEdition(info.command, configuration.options.edition))
            continue;
        QVERIFY2(text.contains(QString::fromStdString(setting.condition).simplified()),
                 qPrintable(QString::fromStdString(setting.condition)));
        QVERIFY2(text.contains(QString::fromStdString(setting.comment).simplified()),
                 qPrintable(QString::fromStdString(setting.comment)));
    }
    for (const core::packml::Mode& mode : configuration.modes) {
        QVERIFY(text.contains(QString::fromStdString(std::string(mode.displayName()))));
        QVERIFY(text.contains(QString::fromStdString(mode.request)));
        QVERIFY(text.contains(QString::fromStdString(mode.comment).simplified()));
    }
    for (const auto& [key, grafcet] : model.grafcets()) {
        const auto parsed = core::packml::parseGrafcetKey(key);
        QVERIFY(parsed);
        const core::packml::Mode* mode = configuration.mode(parsed->first);
        const QString heading = QString::fromStdString(std::string(mode->displayName())) + QStringLiteral(" · ")
                                + QString::fromStdString(std::string(core::packml::stateName(parsed->second)));
        QVERIFY2(text.contains(heading), qPrintable(heading));
    }
    for (const core::Variable& variable : model.variables())
        QVERIFY2(text.contains(QString::fromStdString(variable.name)), variable.name.c_str());
}

void TestPackmlSpecification::oneChartPagePerMode()
{
    const QString path = exportBottleFiller(QStringLiteral("charts.pdf"));
    QVERIFY(!path.isEmpty());
    if (!havePoppler())
        QSKIP("pdfinfo or pdftotext is not installed (poppler-utils)");
    const QList<PageWords> pages = pageWords(path);
    const QStringList texts = pageTexts(path, QStringLiteral("-raw"));
    QCOMPARE(texts.size(), pages.size());
    QStringList landscapes;
    for (qsizetype i = 0; i < pages.size(); ++i) {
        if (landscape(pages[i]))
            landscapes << texts[i].simplified();
    }
    QCOMPARE(landscapes.size(), 2); // Production and Manual
    QVERIFY(landscapes[0].contains(QStringLiteral("Unit mode 1 Production")));
    QVERIFY(landscapes[1].contains(QStringLiteral("Unit mode 3 Manual")));
    for (const QString& chart : std::as_const(landscapes)) {
        for (const char* state : {"Stopped", "Idle", "Execute", "Aborted"})
            QVERIFY2(chart.contains(QLatin1String(state)), state);
    }
    // The charts follow the title page, one after the other.
    QVERIFY(!landscape(pages[0]));
    QVERIFY(landscape(pages[1]));
    QVERIFY(landscape(pages[2]));
    QVERIFY(!landscape(pages[3]));
}

void TestPackmlSpecification::eachOwnGrafcetStartsAPageOfItsOwn()
{
    const QString path = exportBottleFiller(QStringLiteral("grafcets.pdf"));
    QVERIFY(!path.isEmpty());
    if (!havePoppler())
        QSKIP("pdfinfo or pdftotext is not installed (poppler-utils)");
    const QStringList pages = pageTexts(path, QStringLiteral("-layout"));
    QStringList headed;
    for (const QString& page : pages) {
        const QStringList lines = trimmedLines(page);
        // The running header's line, then the page's heading. Own GRAFCETs
        // only, in mode then state-number order.
        if (lines.size() > 1 && lines[1].contains(QStringLiteral(" · ")))
            headed << lines[1];
    }
    QCOMPARE(headed,
             QStringList({QStringLiteral("Production · Starting"), QStringLiteral("Production · Execute"),
                          QStringLiteral("Production · Stopping"), QStringLiteral("Production · Aborting"),
                          QStringLiteral("Production · Resetting"), QStringLiteral("Manual · Execute")}));
    // Manual runs Production's Stopping and Aborting: said in its table, not drawn twice.
    const QString text = flat(pageTexts(path, QStringLiteral("-raw")));
    QVERIFY(text.contains(QStringLiteral("Same as mode 1 Production: Production · Stopping")));
    QVERIFY(text.contains(QStringLiteral("Same as mode 1 Production: Production · Aborting")));
}

void TestPackmlSpecification::wordsNeitherOverlapNorLeaveTheirPage()
{
    const QString path = exportBottleFiller(QStringLiteral("layout.pdf"));
    QVERIFY(!path.isEmpty());
    if (!havePoppler())
        QSKIP("pdfinfo or pdftotext is not installed (poppler-utils)");
    checkLayout(path);
}

void TestPackmlSpecification::whatEachModeRunsIsSaid()
{
    core::Model model = core::packml::newModel();
    QVERIFY(model.setGrafcetChoice(1, core::packml::State::Execute, core::packml::GrafcetChoice::own()).ok);
    QVERIFY(model.setGrafcetChoice(2, core::packml::State::Execute, core::packml::GrafcetChoice::sameAs(1)).ok);
    core::packml::StateSet disabled{core::packml::State::Clearing};
    QVERIFY(model.setModeDisabled(3, disabled).ok);
    const QString path = exportModel(model, QStringLiteral("choices.pdf"));
    QVERIFY(!path.isEmpty());
    if (!havePoppler())
        QSKIP("pdfinfo or pdftotext is not installed (poppler-utils)");
    const QString text = flat(pageTexts(path, QStringLiteral("-raw")));
    for (const QString& expected :
         {QStringLiteral("Nested GRAFCETs in 1 Production"), QStringLiteral("Own: Production · Execute"),
          QStringLiteral("Nested GRAFCETs in 2 Maintenance"),
          QStringLiteral("Same as mode 1 Production: Production · Execute"),
          QStringLiteral("None: the mode disables this state"), QStringLiteral("None: the state completes at once"),
          QStringLiteral("None: Execute waits for a command"), QStringLiteral("This GRAFCET has no steps yet.")})
        QVERIFY2(text.contains(expected), qPrintable(expected));
    // Three modes, three charts.
    const QList<PageWords> pages = pageWords(path);
    QCOMPARE(std::count_if(pages.begin(), pages.end(), landscape), 3);
}

void TestPackmlSpecification::fileMenuActionWritesItForAPackmlModel()
{
    Translators translators;
    translators.setLanguage(QStringLiteral("en"));
    MainWindow window(translators);
    QVERIFY(window.openFile(kBottleFiller));
    QAction* action = window.exportActions()->specificationAction();
    QVERIFY(action->isEnabled());
    const QString path = m_files.filePath(QStringLiteral("window.pdf"));
    QString error;
    QVERIFY2(window.exportActions()->writeSpecification(path, &error), qPrintable(error));
    QVERIFY(readAll(path).startsWith("%PDF"));
    if (!havePoppler())
        QSKIP("pdfinfo or pdftotext is not installed (poppler-utils)");
    QVERIFY(flat(pageTexts(path, QStringLiteral("-raw"))).contains(QStringLiteral("PackML specification")));
}

QTEST_MAIN(TestPackmlSpecification)
#include "test_packmlspecification.moc"
