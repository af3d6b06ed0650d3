// The chart exports (SVG, PNG, PDF, print) never cut a condition short: the
// numbering of the conditions that need a note, the wrapping and paging of
// the Conditions list, and the files written. A nested GRAFCET exports too,
// over as many pages as it needs.

#include "editor/chart/gemma/chartscene.h"
#include "editor/chart/gemma/transitionitem.h"
#include "editor/commands/setconditioncommand.h"
#include "editor/commands/setstephiddencommand.h"
#include "editor/document.h"
#include "editor/export/chartexport.h"
#include "editor/export/conditionnotes.h"
#include "editor/grafcet/grafcetexport.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/selection.h"

#include "core/formats/modelfiles.h"

#include "modelfactory.h"

#include <QFile>
#include <QImage>
#include <QPrinter>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QtMath>

using namespace editor;

namespace {

const QString kLong = QStringLiteral(
    "Start AND NOT Stop AND Door_Closed AND Pressure_OK AND Air_OK AND Guard_Locked AND Conveyor_Ready");

// One unit per character: the wrapping tests measure without a font.
double characters(const QString& text)
{
    return double(text.size());
}

QByteArray readAll(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// The text of a PDF as pdftotext reads it, pages separated by form feeds;
// empty when pdftotext is not installed.
QString pdfText(const QString& path)
{
    const QString tool = QStandardPaths::findExecutable(QStringLiteral("pdftotext"));
    if (tool.isEmpty())
        return {};
    QProcess process;
    process.start(tool, {QStringLiteral("-layout"), path, QStringLiteral("-")});
    if (!process.waitForFinished(30000))
        return {};
    return QString::fromUtf8(process.readAllStandardOutput());
}

} // namespace

class TestChartExport : public QObject {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void notesAreNumberedInTheOrderGiven();
    void noteTextNamesTheTransition();
    void wrappingNeverCutsAnything();
    void pagesBreakBetweenLines();
    void listSharesThePageUnlessTheChartShrinksTooMuch();
    void sceneNotesFollowVisibility();

    void grafcetPagesBreakBetweenElements();
    void grafcetExportsAsSvgPngAndPdf();
    void longGrafcetGoesOverSeveralReadablePages();

    void svgListsALongConditionInFull();
    void svgOfShortConditionsIsUnchanged();
    void pngGrowsByTheList();
    void pdfListsALongConditionInFull();
    void pdfPutsALongListOnFollowingPages();
    void printListsALongConditionInFull();

private:
    QString exportTo(const QString& name);

    QTemporaryDir m_files;
    Document* m_document = nullptr;
    Selection* m_selection = nullptr;
    ChartScene* m_scene = nullptr;
};

void TestChartExport::init()
{
    m_document = new Document;
    m_selection = new Selection;
    m_scene = new ChartScene(m_document, m_selection);
}

void TestChartExport::cleanup()
{
    delete m_scene;
    delete m_selection;
    delete m_document;
}

namespace {

int pdfPages(const QString& text)
{
    return int(text.count(QLatin1Char('\f'))) + (text.endsWith(QLatin1Char('\f')) ? 0 : 1);
}

} // namespace

void TestChartExport::grafcetPagesBreakBetweenElements()
{
    // A page 100 high would cut the element from 90 to 130: it starts the next page.
    QCOMPARE(GrafcetExport::pageStarts({{90, 130}}, 300, 100), (QList<double>{0, 89, 189, 289}));
    // An element taller than half a page is cut rather than looped on.
    QCOMPARE(GrafcetExport::pageStarts({{10, 200}}, 250, 100), (QList<double>{0, 100, 200}));
    QCOMPARE(GrafcetExport::pageStarts({}, 80, 100), (QList<double>{0}));
}

void TestChartExport::grafcetExportsAsSvgPngAndPdf()
{
    const core::LoadedModel example = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    QVERIFY(example.ok());
    m_document->replaceModel(*example.model, QString(), core::ModelFormat::Native);
    GrafcetScene scene(m_document, QStringLiteral("F1"));
    GrafcetExport picture(scene);
    QString error;
    const QString svg = m_files.filePath(QStringLiteral("f1.svg"));
    QVERIFY2(picture.write(svg, ChartExport::Format::Svg, &error), qPrintable(error));
    const QByteArray svgText = readAll(svg);
    QVERIFY(svgText.contains("DrillLow"));
    QVERIFY(svgText.contains("PartPresent AND Unclamped"));
    QVERIFY(!svgText.contains("Stop procedures")); // the GRAFCET, not the GEMMA sheet

    const QString png = m_files.filePath(QStringLiteral("f1.png"));
    QVERIFY2(picture.write(png, ChartExport::Format::Png, &error), qPrintable(error));
    const QImage image(png);
    QCOMPARE(image.height(), qCeil(scene.sceneRect().height() * 2));

    const QString pdf = m_files.filePath(QStringLiteral("f1.pdf"));
    QVERIFY2(picture.write(pdf, ChartExport::Format::Pdf, &error), qPrintable(error));
    const QString text = pdfText(pdf);
    if (text.isEmpty())
        QSKIP("pdftotext is not installed");
    QVERIFY(text.contains(QStringLiteral("DrillLow")));
    QCOMPARE(pdfPages(text), 1);
}

void TestChartExport::longGrafcetGoesOverSeveralReadablePages()
{
    core::Model model = m_document->model();
    QVERIFY(model.setStepType("F1", core::StepType::Macro).ok);
    QVERIFY(model.setGrafcet("F1", factory::loopedSequence(60)).ok);
    m_document->replaceModel(model, QString(), core::ModelFormat::Native);
    GrafcetScene scene(m_document, QStringLiteral("F1"));
    QCOMPARE(scene.layout().steps.size(), std::size_t(60));
    const QString pdf = m_files.filePath(QStringLiteral("long.pdf"));
    QString error;
    QVERIFY2(GrafcetExport(scene).write(pdf, ChartExport::Format::Pdf, &error), qPrintable(error));
    const QString text = pdfText(pdf);
    if (text.isEmpty())
        QSKIP("pdftotext is not installed");
    QVERIFY2(pdfPages(text) >= 3, qPrintable(QString::number(pdfPages(text))));
    // Nothing lost across the page breaks, and no step cut by one: every
    // receptivity and every action is there once.
    for (int n = 1; n <= 60; ++n) {
        QCOMPARE(text.count(QRegularExpression(QStringLiteral("\\bGo%1\\b").arg(n))), 1);
        QCOMPARE(text.count(QRegularExpression(QStringLiteral("\\bOut%1\\b").arg(n))), 1);
    }
}

QString TestChartExport::exportTo(const QString& name)
{
    const QString path = m_files.filePath(name);
    ChartExport::Format format;
    if (!ChartExport::formatForPath(path, &format))
        return {};
    QString error;
    if (!ChartExport(*m_scene).write(path, format, &error)) {
        qWarning("%s", qPrintable(error));
        return {};
    }
    return path;
}

void TestChartExport::notesAreNumberedInTheOrderGiven()
{
    const QList<LabelFit> labels{
        {"A1->F1", "Start", true, true},              // fits
        {"F1->A2", "long one", true, false},          // 1
        {"F1->F4", "hidden one", false, false},       // not drawn
        {"A2->A1", QString(), true, false},           // nothing to list
        {"F->D1", "family", true, false},             // 2
    };
    const QList<ConditionNote> notes = numberConditionNotes(labels);
    QCOMPARE(notes.size(), 2);
    QCOMPARE(notes[0].number, 1);
    QCOMPARE(notes[0].transitionId, QString("F1->A2"));
    QCOMPARE(notes[0].condition, QString("long one"));
    QCOMPARE(notes[1].number, 2);
    QCOMPARE(notes[1].transitionId, QString("F->D1"));
    QVERIFY(numberConditionNotes({{"A1->F1", "Start", true, true}}).isEmpty());
}

void TestChartExport::noteTextNamesTheTransition()
{
    QCOMPARE(conditionNoteText({1, "F1->A2", "Start AND Go"}), QString("[1] F1 → A2: Start AND Go"));
    QCOMPARE(conditionNoteText({12, "F->D1", "Emergency"}), QString("[12] F (family) → D1: Emergency"));
}

void TestChartExport::wrappingNeverCutsAnything()
{
    const QString text = "[1] F1 → A2: " + kLong;
    const QStringList lines = wrapText(text, 30, 25, characters);
    QVERIFY(lines.size() > 3);
    QVERIFY(lines[0].size() <= 30);
    for (const QString& line : lines) {
        QVERIFY2(line.size() <= 30, qPrintable(line));
        QVERIFY(!line.startsWith(' ') && !line.endsWith(' '));
    }
    for (qsizetype i = 1; i < lines.size(); ++i)
        QVERIFY2(lines[i].size() <= 25, qPrintable(lines[i]));
    QCOMPARE(lines.join(' '), text);

    // A word wider than a line is broken between its characters.
    const QString word = "Very_long_identifier_without_any_space_at_all";
    const QStringList broken = wrapText("x " + word, 10, 10, characters);
    QCOMPARE(broken.first(), QString("x"));
    QCOMPARE(broken.mid(1).join(QString()), word);
    for (const QString& line : broken)
        QVERIFY(line.size() <= 10);

    // Short text is one line; a line too narrow for a character still holds one.
    QCOMPARE(wrapText("Start AND Go", 100, 100, characters), QStringList{"Start AND Go"});
    QCOMPARE(wrapText("ab", 0.5, 0.5, characters), (QStringList{"a", "b"}));
    QVERIFY(wrapText(QString(), 10, 10, characters).isEmpty());
}

void TestChartExport::pagesBreakBetweenLines()
{
    QCOMPARE(pageBreaks({}, 100), QList<int>());
    QCOMPARE(pageBreaks({20, 10, 10}, 100), QList<int>{0});
    QCOMPARE(pageBreaks({20, 10, 10, 10, 10}, 35), (QList<int>{0, 2}));
    QCOMPARE(pageBreaks({20, 10, 10, 10, 10}, 25), (QList<int>{0, 1, 3}));
    // A line taller than a page has a page of its own.
    QCOMPARE(pageBreaks({10, 50, 10}, 30), (QList<int>{0, 1, 2}));
}

void TestChartExport::listSharesThePageUnlessTheChartShrinksTooMuch()
{
    const QSizeF chart(1500, 1000);
    const QSizeF page(3000, 3000); // room under the chart: 1000 units at scale 2
    PagePlan plan = planPages(chart, 0, page);
    QCOMPARE(plan.scale, 2.0);
    QVERIFY(plan.listBelowChart);
    plan = planPages(chart, 400, page); // fits without shrinking
    QCOMPARE(plan.scale, 2.0);
    QVERIFY(plan.listBelowChart);
    plan = planPages(chart, 700, page); // shrinks the chart by 12 %
    QVERIFY(plan.listBelowChart);
    QCOMPARE(plan.scale, 3000.0 / 1700.0);
    plan = planPages(chart, 1000, page); // would shrink it by 25 %
    QVERIFY(!plan.listBelowChart);
    QCOMPARE(plan.scale, 2.0);
}

void TestChartExport::sceneNotesFollowVisibility()
{
    QVERIFY(conditionNotes(*m_scene).isEmpty());
    m_document->push(new SetConditionCommand(*m_document, "F1->A2", "NOT Stop"));
    m_document->push(new SetConditionCommand(*m_document, "A2->A1", kLong));
    m_document->push(new SetConditionCommand(*m_document, "A1->F1", kLong + " AND Again"));
    QList<ConditionNote> notes = conditionNotes(*m_scene);
    QCOMPARE(notes.size(), 2);
    // Template order, whatever the order of the edits.
    QCOMPARE(notes[0].transitionId, QString("A1->F1"));
    QCOMPARE(notes[0].condition, kLong + " AND Again");
    QCOMPARE(notes[1].transitionId, QString("A2->A1"));
    QCOMPARE(notes[1].number, 2);

    // A hidden transition is listed only when hidden elements are shown.
    m_document->push(new SetStepHiddenCommand(*m_document, "A2", true));
    notes = conditionNotes(*m_scene);
    QCOMPARE(notes.size(), 1);
    QCOMPARE(notes[0].transitionId, QString("A1->F1"));
    m_scene->setShowHidden(true);
    QCOMPARE(conditionNotes(*m_scene).size(), 2);
}

void TestChartExport::svgListsALongConditionInFull()
{
    m_document->push(new SetConditionCommand(*m_document, "F1->A2", kLong));
    TransitionItem* item = m_scene->transitionItem("F1->A2");
    const QString onScreen = item->displayedCondition();
    QVERIFY(onScreen.endsWith(QChar(0x2026)));

    const QString path = exportTo("long.svg");
    QVERIFY(!path.isEmpty());
    const QString svg = QString::fromUtf8(readAll(path));
    QVERIFY2(svg.contains(kLong), "the condition in full");
    QVERIFY(svg.contains(">Conditions<"));
    QVERIFY(svg.contains("[1] F1 → A2: " + kLong));
    // At the transition: the start of the condition and the marker.
    static const QRegularExpression marker(QStringLiteral(">: Start[^<]*\u2026\\[1\\]<"));
    QVERIFY2(marker.match(svg).hasMatch(), "the label ends in its note marker");

    // The screen is as it was, the tooltip still in full.
    QCOMPARE(item->noteNumber(), 0);
    QCOMPARE(item->displayedCondition(), onScreen);
    QVERIFY(item->toolTipText().contains(kLong));
}

void TestChartExport::svgOfShortConditionsIsUnchanged()
{
    m_document->push(new SetConditionCommand(*m_document, "F1->A2", "NOT Stop"));
    const QString path = exportTo("short.svg");
    QVERIFY(!path.isEmpty());
    const QString svg = QString::fromUtf8(readAll(path));
    QVERIFY(svg.contains(">: NOT Stop<"));
    QVERIFY(!svg.contains("Conditions"));
    QVERIFY(!svg.contains("[1]"));
    // As large as the sheet with its margin, nothing more.
    const QRectF paper = m_scene->sceneRect().adjusted(-12, -12, 12, 12);
    const QString viewBox = QStringLiteral("viewBox=\"0 0 %1 %2\"").arg(paper.width()).arg(paper.height());
    QVERIFY2(svg.contains(viewBox), qPrintable(svg.left(400)));

    // A long condition makes the picture taller, not wider.
    m_document->push(new SetConditionCommand(*m_document, "F1->A2", kLong));
    const QString taller = QString::fromUtf8(readAll(exportTo("long.svg")));
    static const QRegularExpression box(QStringLiteral("viewBox=\"0 0 ([0-9.]+) ([0-9.]+)\""));
    const QRegularExpressionMatch match = box.match(taller);
    QVERIFY(match.hasMatch());
    QCOMPARE(match.captured(1).toDouble(), paper.width());
    QVERIFY(match.captured(2).toDouble() > paper.height() + 30);
}

void TestChartExport::pngGrowsByTheList()
{
    const QImage plain(exportTo("plain.png"));
    QVERIFY(!plain.isNull());
    m_document->push(new SetConditionCommand(*m_document, "F1->A2", kLong));
    m_document->push(new SetConditionCommand(*m_document, "F1->F4", kLong + " AND More"));
    const QImage noted(exportTo("noted.png"));
    QVERIFY(!noted.isNull());
    QCOMPARE(noted.width(), plain.width());
    // A heading and two one-line notes, at 2 pixels per unit.
    const ConditionList list(conditionNotes(*m_scene), 1000);
    QCOMPARE(list.lineCount(), 3);
    QVERIFY(list.height() > 40);
    QVERIFY2(std::abs(noted.height() - plain.height() - 2 * list.height()) <= 2,
             qPrintable(QString("%1 %2 %3").arg(noted.height()).arg(plain.height()).arg(list.height())));
    // The list is drawn: the strip under the sheet has ink in it.
    bool ink = false;
    for (int y = plain.height(); y < noted.height() && !ink; ++y) {
        for (int x = 0; x < noted.width() && !ink; ++x)
            ink = qGray(noted.pixel(x, y)) < 128;
    }
    QVERIFY(ink);
}

void TestChartExport::pdfListsALongConditionInFull()
{
    m_document->push(new SetConditionCommand(*m_document, "F1->A2", kLong));
    const QString path = exportTo("long.pdf");
    QVERIFY(!path.isEmpty());
    const QString text = pdfText(path);
    if (text.isEmpty())
        QSKIP("pdftotext is not installed");
    QVERIFY2(text.simplified().contains("[1] F1 → A2: " + kLong), qPrintable(text));
    QCOMPARE(text.count(QChar('\f')), 1); // one page

    m_document->undoStack()->undo();
    const QString shortText = pdfText(exportTo("short.pdf"));
    QVERIFY(!shortText.contains("Conditions"));
    QVERIFY(!shortText.contains("[1]"));
}

void TestChartExport::pdfPutsALongListOnFollowingPages()
{
    // Every transition with a long condition: the list does not fit under the chart.
    QStringList conditions;
    int n = 0;
    for (const TransitionItem* item : m_scene->transitions()) {
        const QString condition = QStringLiteral("Cond%1 AND ").arg(++n) + kLong;
        conditions << condition;
        m_document->push(new SetConditionCommand(*m_document, item->id(), condition));
    }
    const ConditionList list(conditionNotes(*m_scene), m_scene->sceneRect().width());
    QCOMPARE(list.lineCount(), m_scene->transitions().size() + 1);
    const QString path = exportTo("many.pdf");
    QVERIFY(!path.isEmpty());
    const QString text = pdfText(path);
    if (text.isEmpty())
        QSKIP("pdftotext is not installed");
    QVERIFY2(text.count(QChar('\f')) >= 2, qPrintable(text));
    const QString flat = text.simplified();
    for (const QString& condition : std::as_const(conditions))
        QVERIFY2(flat.contains(condition), qPrintable(condition));
}

void TestChartExport::printListsALongConditionInFull()
{
    m_document->push(new SetConditionCommand(*m_document, "F1->A2", kLong));
    const QString path = m_files.filePath("printed.pdf");
    {
        QPrinter printer(QPrinter::HighResolution);
        printer.setOutputFormat(QPrinter::PdfFormat);
        printer.setOutputFileName(path);
        printer.setPageOrientation(QPageLayout::Landscape);
        QVERIFY(ChartExport(*m_scene).print(printer));
    }
    QVERIFY(readAll(path).startsWith("%PDF"));
    const QString text = pdfText(path);
    if (text.isEmpty())
        QSKIP("pdftotext is not installed");
    QVERIFY2(text.simplified().contains("[1] F1 → A2: " + kLong), qPrintable(text));
}

QTEST_MAIN(TestChartExport)
#include "test_chartexport.moc"
