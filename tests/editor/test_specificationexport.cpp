// File > Export Specification: one PDF of the whole model, read back with
// poppler-utils (pdfinfo, pdftotext; installed by .ci/install-deps, the tests
// skip when they are missing). Each nested GRAFCET starts a page of its own,
// nothing is cut short (every state, variable, condition and receptivity is
// there in full, a long GRAFCET and a long table go on over several pages),
// no two words overlap and none leaves its page, and a failed write leaves
// the file on disk as it was.

#include "editortestsupport.h"
#include "modelfactory.h"
#include "pdfpages.h"
#include "readonlyfolder.h"

#include "editor/app/languages.h"
#include "editor/document.h"
#include "editor/export/exportactions.h"
#include "editor/export/exportoptionsdialog.h"
#include "editor/export/specificationexport.h"
#include "editor/grafcet/grafcettransitionitem.h"
#include "editor/machine/machinetext.h"
#include "editor/mainwindow.h"
#include "editor/text/gemmastatenames.h"

#include "core/codegen/stgenerator.h"
#include "core/formats/modelfiles.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QMenu>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

#include <algorithm>
#include <cmath>

using namespace editor;

using namespace pdfpages;

class TestSpecificationExport : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();

    void eachGrafcetStartsAPageOfItsOwn();
    void machineHasASectionOfItsOwn();
    void everyTextOfTheExampleIsThereInFull();
    void wordsNeitherOverlapNorLeaveTheirPage();
    void longGrafcetSpansSeveralPages();
    void longTableBreaksBetweenRowsAndKeepsEveryWord();
    void longNameAndConditionsWrap();
    void controlCharactersAreWrittenOut();
    void wordLongerThanAPageWrapsWhole();
    void modelWithoutGrafcetsOrVariables();
    void failedWriteLeavesTheFileUntouched();
    void fileMenuOffersTheExport();

private:
    // The example with nested GRAFCETs, exported; empty on failure.
    QString exportExample(const QString& name);
    QString exportModel(const core::Model& model, const QString& name);

    QTemporaryDir m_settings;
    QTemporaryDir m_files;
};

void TestSpecificationExport::initTestCase()
{
    QVERIFY(m_settings.isValid());
    QVERIFY(m_files.isValid());
    editortest::useTestSettings(m_settings.path(), QStringLiteral("test_specificationexport"));
}

QString TestSpecificationExport::exportModel(const core::Model& model, const QString& name)
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

QString TestSpecificationExport::exportExample(const QString& name)
{
    const core::LoadedModel example = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    if (!example.ok())
        return {};
    return exportModel(*example.model, name);
}

void TestSpecificationExport::eachGrafcetStartsAPageOfItsOwn()
{
    const QString path = exportExample(QStringLiteral("drilling.pdf"));
    QVERIFY(!path.isEmpty());
    QVERIFY(readAll(path).startsWith("%PDF"));
    if (!havePoppler())
        QSKIP("pdfinfo or pdftotext is not installed (poppler-utils)");

    const core::LoadedModel example = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    const core::Model& model = *example.model;
    QStringList titles;
    for (const core::Step& step : model.steps()) {
        if (model.effectiveGrafcet(step.id))
            titles << SpecificationExport::grafcetTitle(QString::fromStdString(step.id));
    }
    QCOMPARE(titles.size(), 4); // F1, F2, F3 and A6
    QCOMPARE(titles.front(), QStringLiteral("A6 Operative part reset to initial state"));

    const QStringList pages = pageTexts(path, QStringLiteral("-layout"));
    const int pageCount = pdfinfoPages(path);
    QCOMPARE(int(pages.size()), pageCount);
    // Title, chart, states and variables, one page at least per GRAFCET, code.
    QVERIFY2(pageCount >= 4 + int(titles.size()), qPrintable(QString::number(pageCount)));

    QList<int> titlePages;
    for (const QString& title : std::as_const(titles)) {
        QList<int> headed;
        for (int i = 0; i < pages.size(); ++i) {
            const QStringList lines = trimmedLines(pages[i]);
            if (lines.contains(title)) {
                headed << i;
                // At the page's top: under the running header, nothing before it.
                QVERIFY2(lines.size() >= 2 && lines[1] == title, qPrintable(pages[i]));
            }
        }
        QCOMPARE(headed.size(), 1);
        titlePages << headed.front();
    }
    // Each on a page of its own, in state order, after the chart and tables.
    for (int i = 1; i < titlePages.size(); ++i)
        QVERIFY(titlePages[i] > titlePages[i - 1]);
    QVERIFY(titlePages.front() >= 3);

    // Every page numbered, out of the page count.
    for (int i = 0; i < pages.size(); ++i)
        QVERIFY2(pages[i].contains(QStringLiteral("Page %1 of %2").arg(i + 1).arg(pageCount)), qPrintable(pages[i]));
    // The GEMMA chart's page is landscape, the others portrait.
    const QString info = QString::fromUtf8(
        run(tool("pdfinfo"), {QStringLiteral("-f"), QStringLiteral("1"), QStringLiteral("-l"),
                              QString::number(pageCount), path}));
    static const QRegularExpression landscape(QStringLiteral(R"(Page\s+2 size:\s+84[12](\.\d+)? x 595)"));
    static const QRegularExpression portrait(QStringLiteral(R"(Page\s+1 size:\s+595(\.\d+)? x 84[12])"));
    QVERIFY2(info.contains(landscape), qPrintable(info));
    QVERIFY2(info.contains(portrait), qPrintable(info));
    // The contents give each GRAFCET's page.
    for (int i = 0; i < titles.size(); ++i) {
        const QRegularExpression entry(QStringLiteral("^\\s*%1\\s+%2\\s*$")
                                           .arg(QRegularExpression::escape(titles[i]))
                                           .arg(titlePages[i] + 1),
                                       QRegularExpression::MultilineOption);
        QVERIFY2(entry.match(pages[0]).hasMatch(), qPrintable(pages[0]));
    }
}

// The drilling cell's machine: a page headed "Machine" in the contents, every
// component with its kind and wiring, then its schematic; a model without a
// machine has no such section.
void TestSpecificationExport::machineHasASectionOfItsOwn()
{
    const QString path = exportExample(QStringLiteral("drilling-machine.pdf"));
    QVERIFY(!path.isEmpty());
    if (!havePoppler())
        QSKIP("pdfinfo or pdftotext is not installed (poppler-utils)");
    const core::LoadedModel example = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    const core::machine::Machine& machine = example.model->machine();
    QVERIFY(!machine.empty());

    const QStringList pages = pageTexts(path, QStringLiteral("-layout"));
    int machinePage = -1;
    for (int i = 1; i < pages.size() && machinePage < 0; ++i) {
        const QStringList lines = trimmedLines(pages[i]);
        if (lines.size() >= 2 && lines[1] == QStringLiteral("Machine"))
            machinePage = i;
    }
    QVERIFY2(machinePage > 0, "a page starts with the Machine heading");
    const QRegularExpression entry(QStringLiteral("^\\s*Machine\\s+%1\\s*$").arg(machinePage + 1),
                                   QRegularExpression::MultilineOption);
    QVERIFY2(entry.match(pages[0]).hasMatch(), qPrintable(pages[0]));
    // The section's pages: their running header names it.
    QString section;
    for (int i = machinePage; i < pages.size() && trimmedLines(pages[i]).value(0).endsWith(QStringLiteral("Machine"));
         ++i)
        section += pages[i];
    const QString text = section.simplified();
    for (const core::machine::Component& component : machine.components) {
        QVERIFY2(text.contains(QString::fromStdString(component.name)), component.name.c_str());
        // The kind's words: a narrow column wraps them onto lines of their own.
        for (const QString& word : machinetext::kindName(component.kind).split(QLatin1Char(' ')))
            QVERIFY2(text.contains(word), qPrintable(word));
        for (const std::string& wire : component.wires) {
            if (!wire.empty())
                QVERIFY2(text.contains(QString::fromStdString(wire)), wire.c_str());
        }
    }
    QVERIFY(text.contains(QStringLiteral("The machine at rest")));

    const core::LoadedModel faulty = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell-faulty.ggstudio.json");
    QVERIFY(faulty.ok() && faulty.model->machine().empty());
    const QString without = exportModel(*faulty.model, QStringLiteral("faulty-no-machine.pdf"));
    QVERIFY(!without.isEmpty());
    for (const QString& page : pageTexts(without, QStringLiteral("-layout"))) {
        const QStringList lines = trimmedLines(page);
        QVERIFY(lines.size() < 2 || lines[1] != QStringLiteral("Machine"));
    }
}

void TestSpecificationExport::everyTextOfTheExampleIsThereInFull()
{
    const QString path = exportExample(QStringLiteral("drilling-text.pdf"));
    QVERIFY(!path.isEmpty());
    if (!havePoppler())
        QSKIP("pdfinfo or pdftotext is not installed (poppler-utils)");
    const QString text = flat(pageTexts(path, QStringLiteral("-raw")));

    const core::LoadedModel example = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    const core::Model& model = *example.model;
    QVERIFY(text.contains(QStringLiteral("Drilling cell DC-1")));
    QVERIFY(text.contains(QStringLiteral("File not saved yet"))); // a Document of its own
    for (const core::Step& step : model.steps()) {
        const QString id = QString::fromStdString(step.id);
        const QString comment = QString::fromStdString(step.comment).simplified();
        if (step.hidden) {
            if (!comment.isEmpty())
                QVERIFY2(!text.contains(comment), qPrintable(comment));
            continue;
        }
        QVERIFY2(text.contains(id + QLatin1Char(' ') + officialStateName(id)), qPrintable(id));
        QVERIFY2(text.contains(comment), qPrintable(comment));
    }
    for (const core::Variable& variable : model.variables()) {
        QVERIFY2(text.contains(QString::fromStdString(variable.name)), variable.name.c_str());
        QVERIFY2(text.contains(QString::fromStdString(variable.comment).simplified()), variable.comment.c_str());
    }
    for (const core::Transition& transition : model.transitions()) {
        if (model.isEffective(transition) && !transition.condition.empty())
            QVERIFY2(text.contains(QString::fromStdString(transition.condition)), transition.id.c_str());
    }
    for (const auto& [stepId, grafcet] : model.grafcets()) {
        for (const core::GrafcetTransition& transition : grafcet.transitions()) {
            const QString drawn =
                GrafcetTransitionItem::drawnReceptivity(QString::fromStdString(transition.receptivity));
            QVERIFY2(text.contains(drawn), qPrintable(stepId.c_str() + QStringLiteral(": ") + drawn));
        }
        for (const core::GrafcetStep& step : grafcet.steps()) {
            if (!step.comment.empty())
                QVERIFY2(text.contains(QString::fromStdString(step.comment)), step.comment.c_str());
        }
    }
    // The code's outline: every POU with its interface.
    const core::PlcProject project = core::buildPlcProject(model, model.settings().dialect);
    for (const core::PlcPou& pou : project.pous) {
        const QString keyword = pou.kind == core::PouKind::Program ? QStringLiteral("PROGRAM ")
                                                                   : QStringLiteral("FUNCTION_BLOCK ");
        QVERIFY2(text.contains(keyword + QString::fromStdString(pou.name)), pou.name.c_str());
        for (const core::PlcVariable& output : pou.outputs)
            QVERIFY2(text.contains(QStringLiteral("VAR_OUTPUT ") + QString::fromStdString(output.name)),
                     output.name.c_str());
    }
    QVERIFY(text.contains(QStringLiteral("MainTask: cyclic, every T#10ms, priority 1")));
    // Nothing elided: the only "…" is the dialect's own name's.
    QString rest = text;
    rest.remove(ExportOptionsDialog::dialectText(model.settings().dialect));
    QVERIFY2(!rest.contains(QChar(0x2026)), qPrintable(rest));
}

void TestSpecificationExport::wordsNeitherOverlapNorLeaveTheirPage()
{
    const QString path = exportExample(QStringLiteral("drilling-boxes.pdf"));
    QVERIFY(!path.isEmpty());
    if (!havePoppler())
        QSKIP("pdfinfo or pdftotext is not installed (poppler-utils)");
    checkLayout(path);
}

void TestSpecificationExport::longGrafcetSpansSeveralPages()
{
    core::Model model;
    QVERIFY(model.setStepType("F1", core::StepType::Macro).ok);
    QVERIFY(model.setGrafcet("F1", factory::loopedSequence(60)).ok);
    const QString path = exportModel(model, QStringLiteral("long.pdf"));
    QVERIFY(!path.isEmpty());
    if (!havePoppler())
        QSKIP("pdfinfo or pdftotext is not installed (poppler-utils)");
    const QStringList pages = pageTexts(path, QStringLiteral("-layout"));
    QCOMPARE(int(pages.size()), pdfinfoPages(path));
    int first = -1;
    int continued = 0;
    for (int i = 0; i < pages.size(); ++i) {
        const QStringList lines = trimmedLines(pages[i]);
        if (lines.contains(QStringLiteral("F1 Normal production")))
            first = i;
        if (lines.size() >= 2 && lines[1] == QStringLiteral("Nested GRAFCET of F1, continued")) {
            QVERIFY(first >= 0 && i > first);
            ++continued;
        }
    }
    QVERIFY(first >= 0);
    QVERIFY2(continued >= 2, qPrintable(QString::number(continued)));
    // Nothing lost across the page breaks, and no step cut by one: every
    // receptivity and every action once, in the order of the sequence.
    const QString drawn = pages.mid(first, continued + 1).join(QLatin1Char('\n'));
    QCOMPARE(numberedWords(drawn, QStringLiteral("Go")), oneTo(60));
    QCOMPARE(numberedWords(drawn, QStringLiteral("Out")), oneTo(60));
}

void TestSpecificationExport::longTableBreaksBetweenRowsAndKeepsEveryWord()
{
    core::Model model;
    // 60 variables with comments of 40 numbered words: the table goes over
    // several pages; and one comment longer than a page.
    int word = 0;
    for (int v = 1; v <= 60; ++v) {
        QStringList words;
        for (int i = 0; i < 40; ++i)
            words << QStringLiteral("w%1").arg(++word);
        QVERIFY(model.addVariable({QStringLiteral("Var%1").arg(v).toStdString(), core::IecType::Bool, {},
                                   words.join(' ').toStdString()})
                    .ok);
    }
    const int tableWords = word;
    QStringList huge;
    for (int i = 1; i <= 2500; ++i)
        huge << QStringLiteral("h%1").arg(i);
    QVERIFY(model.setStepComment("F1", huge.join(' ').toStdString()).ok);

    const QString path = exportModel(model, QStringLiteral("table.pdf"));
    QVERIFY(!path.isEmpty());
    if (!havePoppler())
        QSKIP("pdfinfo or pdftotext is not installed (poppler-utils)");
    const QStringList raw = pageTexts(path, QStringLiteral("-raw"));
    const QString text = raw.join(QLatin1Char('\n'));
    QCOMPARE(numberedWords(text, QStringLiteral("w")), oneTo(tableWords));
    QCOMPARE(numberedWords(text, QStringLiteral("h")), oneTo(2500));
    QCOMPARE(numberedWords(text, QStringLiteral("Var")), oneTo(60));

    // The header row again on every page the tables go on to.
    const QStringList pages = pageTexts(path, QStringLiteral("-layout"));
    static const QRegularExpression variablesHeader(QStringLiteral(R"(^\s*Name\s+Kind\s+Type\s+Default\s+Comment\s*$)"),
                                                    QRegularExpression::MultilineOption);
    static const QRegularExpression statesHeader(QStringLiteral(R"(^\s*State\s+Name\s+Type\s+GRAFCET\s+Comment\s*$)"),
                                                 QRegularExpression::MultilineOption);
    int variablePages = 0;
    int statePages = 0;
    for (const QString& page : pages) {
        if (page.contains(QRegularExpression(QStringLiteral(R"(\bVar\d+\b)")))) {
            QVERIFY2(variablesHeader.match(page).hasMatch(), qPrintable(page));
            ++variablePages;
        }
        if (page.contains(QRegularExpression(QStringLiteral(R"(\bh\d+\b)")))) {
            QVERIFY2(statesHeader.match(page).hasMatch(), qPrintable(page));
            ++statePages;
        }
    }
    QVERIFY2(variablePages >= 2, qPrintable(QString::number(variablePages)));
    QVERIFY2(statePages >= 2, qPrintable(QString::number(statePages)));
}

void TestSpecificationExport::longNameAndConditionsWrap()
{
    const core::LoadedModel example = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    QVERIFY(example.ok());
    core::Model model(*example.model);
    QStringList name;
    for (int i = 1; i <= 30; ++i)
        name << QStringLiteral("Line%1").arg(i);
    QVERIFY(model.setName(name.join(' ').toStdString()).ok);
    // Every effective transition with a condition too long for its label:
    // the Conditions list goes on after the chart's page.
    QStringList conditions;
    for (const core::Transition& transition : model.transitions()) {
        if (!model.isEffective(transition))
            continue;
        QString condition = QStringLiteral("StartButton");
        for (int i = 0; i < 12; ++i)
            condition += QStringLiteral(" AND EmergencyOk");
        condition += QStringLiteral(" AND Cond%1").arg(conditions.size() + 1);
        conditions << condition;
        QVERIFY(model.setCondition(transition.id, condition.toStdString()).ok);
    }
    const QString path = exportModel(model, QStringLiteral("long-name.pdf"));
    QVERIFY(!path.isEmpty());
    if (!havePoppler())
        QSKIP("pdfinfo or pdftotext is not installed (poppler-utils)");
    checkLayout(path, false);
    if (QTest::currentTestFailed())
        return;

    const QStringList pages = pageTexts(path, QStringLiteral("-layout"));
    // The name whole in the running header of every page (wrapped clear of
    // the section) and on the title page.
    for (const QString& page : pages)
        QCOMPARE(numberedWords(page, QStringLiteral("Line")).mid(0, 30), oneTo(30));
    QStringList chartPages;
    for (const QString& page : pages) {
        if (page.contains(QStringLiteral("GEMMA chart")) && !page.contains(QStringLiteral("Contents")))
            chartPages << page;
    }
    QVERIFY2(chartPages.size() >= 2, qPrintable(QString::number(chartPages.size())));
    const QString chart = flat(chartPages);
    for (const QString& condition : std::as_const(conditions))
        QVERIFY2(chart.contains(condition), qPrintable(condition));
}

// A right-to-left override in the model's name would turn the title around,
// a control character would vanish: both are written out, where they are.
void TestSpecificationExport::controlCharactersAreWrittenOut()
{
    core::Model model = factory::realisticModel();
    QVERIFY(model.setName(QStringLiteral("Cell \u202Eevil\u0007 end").toStdString()).ok);
    const QString path = exportModel(model, QStringLiteral("controls.pdf"));
    QVERIFY(!path.isEmpty());
    if (!havePoppler())
        QSKIP("pdfinfo or pdftotext is not installed (poppler-utils)");
    const QStringList pages = pageTexts(path, QStringLiteral("-raw"));
    QVERIFY(!pages.isEmpty());
    // The title, and the running header of every page.
    for (const QString& page : pages)
        QVERIFY2(page.contains(QStringLiteral("Cell <U+202E>evil<U+0007> end")), qPrintable(page.left(300)));
    QVERIFY(!flat(pages).contains(QChar(0x202E)));
}

// A word of a million characters (a comment pasted without spaces) wraps,
// broken between its characters at each line's end: every character is on
// a page, in order, and no line leaves its page.
void TestSpecificationExport::wordLongerThanAPageWrapsWhole()
{
    core::Model model = factory::realisticModel();
    QString word;
    word.reserve(1000000);
    while (word.size() < 1000000)
        word += QStringLiteral("жзий");
    QVERIFY(!model.variables().empty());
    QVERIFY(model.setVariableComment(model.variables().front().name, word.toStdString()).ok);
    const QString path = exportModel(model, QStringLiteral("long-word.pdf"));
    QVERIFY(!path.isEmpty());
    if (!havePoppler())
        QSKIP("pdfinfo or pdftotext is not installed (poppler-utils)");
    // Letters no other text of the document has.
    static const QRegularExpression pieceOfTheWord(QStringLiteral("^[жзий]+$"));
    QString found;
    for (const PageWords& page : pageWords(path)) {
        const QRectF sheet(QPointF(0, 0), page.size);
        for (const Word& piece : page.words) {
            QVERIFY2(sheet.contains(piece.box), qPrintable(piece.text.left(40)));
            if (pieceOfTheWord.match(piece.text).hasMatch())
                found += piece.text;
        }
    }
    QCOMPARE(found.size(), word.size());
    QVERIFY(found == word);
}

void TestSpecificationExport::modelWithoutGrafcetsOrVariables()
{
    const QString path = exportModel(core::Model(), QStringLiteral("template.pdf"));
    QVERIFY(!path.isEmpty());
    if (!havePoppler())
        QSKIP("pdfinfo or pdftotext is not installed (poppler-utils)");
    const QStringList pages = pageTexts(path, QStringLiteral("-layout"));
    QCOMPARE(int(pages.size()), pdfinfoPages(path));
    const QString text = flat(pages);
    QVERIFY(text.contains(QStringLiteral("No variables are declared.")));
    QVERIFY(!text.contains(QStringLiteral("Nested GRAFCETs")));
    QVERIFY(text.contains(QStringLiteral("FUNCTION_BLOCK A7_FB"))); // a skeleton
    QVERIFY(text.contains(QStringLiteral("not written yet")));
}

void TestSpecificationExport::failedWriteLeavesTheFileUntouched()
{
    const core::LoadedModel example = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    QVERIFY(example.ok());
    Document document(*example.model);
    SpecificationExport specification(document);

    // Under a file, as if it were a folder.
    const QString blocker = m_files.filePath(QStringLiteral("blocker"));
    {
        QFile file(blocker);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("not a folder");
    }
    QString error;
    QVERIFY(!specification.writePdf(blocker + QStringLiteral("/spec.pdf"), &error));
    QVERIFY(!error.isEmpty());
    QCOMPARE(readAll(blocker), QByteArray("not a folder"));

    // A folder that takes no new file, with a specification already in it.
#ifdef _WIN32
    QSKIP("needs POSIX permissions");
#else
    const QString folder = m_files.filePath(QStringLiteral("readonly"));
    QVERIFY(QDir().mkpath(folder));
    const QString existing = folder + QStringLiteral("/spec.pdf");
    {
        QFile file(existing);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("the old specification");
    }
    const testsupport::ReadOnlyFolder readOnly(QFile::encodeName(folder).toStdString());
    if (!readOnly.effective())
        QSKIP("cannot make a folder read-only here");
    error.clear();
    QVERIFY(!specification.writePdf(existing, &error));
    QVERIFY2(error.contains(existing), qPrintable(error)); // says where
    QCOMPARE(readAll(existing), QByteArray("the old specification"));
#endif
}

void TestSpecificationExport::fileMenuOffersTheExport()
{
    Translators translators;
    translators.setLanguage(QStringLiteral("en"));
    MainWindow window(translators);
    auto* fileMenu = window.findChild<QMenu*>(QStringLiteral("fileMenu"));
    QVERIFY(fileMenu);
    QAction* action = window.exportActions()->specificationAction();
    QVERIFY(fileMenu->actions().contains(action));
    QCOMPARE(action->objectName(), QStringLiteral("exportSpecificationAction"));
    QCOMPARE(action->text(), QStringLiteral("Export Speci&fication…"));
    // Right after Export Chart.
    const qsizetype index = fileMenu->actions().indexOf(action);
    QCOMPARE(fileMenu->actions().value(index - 1), window.exportActions()->chartAction());

    const core::LoadedModel example = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    QVERIFY(example.ok());
    QCOMPARE(ExportActions::suggestedSpecificationName(QStringLiteral("/x/drilling.ggstudio.json"), *example.model),
             QStringLiteral("Drilling cell DC-1 specification.pdf"));
    core::Model unnamed;
    QVERIFY(unnamed.setName("A/B").ok);
    QCOMPARE(ExportActions::suggestedSpecificationName(QString(), unnamed), QStringLiteral("A_B specification.pdf"));

    // What the action writes after its dialog.
    const QString path = m_files.filePath(QStringLiteral("window.pdf"));
    QString error;
    QVERIFY2(window.exportActions()->writeSpecification(path, &error), qPrintable(error));
    QVERIFY(readAll(path).startsWith("%PDF"));
}

QTEST_MAIN(TestSpecificationExport)
#include "test_specificationexport.moc"
