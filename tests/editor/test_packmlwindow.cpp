// A PackML model in the main window (issue 34): the PackML chart in the
// first tab, the docks and actions of its template, File > New's choice,
// the example, its GRAFCET tabs, the pictures of its chart and its code in
// the Structured Text dock.

#include "editortestsupport.h"
#include "editor/app/examplemodels.h"
#include "editor/app/languages.h"
#include "editor/chart/gemma/chartview.h"
#include "editor/chart/packml/packmlchartcontextmenu.h"
#include "editor/chart/packml/packmlchartscene.h"
#include "editor/chart/packml/packmlchartview.h"
#include "editor/docks/stpreviewdock.h"
#include "editor/document.h"
#include "editor/export/exportactions.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetview.h"
#include "editor/mainwindow.h"
#include "editor/docks/verificationpanel.h"
#include "editor/selection.h"
#include "editor/text/diagnostictext.h"
#include "editor/verificationrunner.h"
#include "editor/simulation/packml/packmlsimulationsession.h"
#include "editor/simulation/simulationsession.h"
#include "editor/window/newmodeldialog.h"

#include "core/formats/modelfiles.h"
#include "core/templates/packml/packmlconfiguration.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QImage>
#include <QMenu>
#include <QMessageBox>
#include <QSignalSpy>
#include <QPlainTextEdit>
#include <QRadioButton>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTextBlock>
#include <QUndoStack>
#include <QTest>
#include <QTimer>

#include <memory>

using namespace editor;

namespace {

const QString kBottleFiller = QStringLiteral(GGSTUDIO_EXAMPLES_DIR "/bottle-filler.ggstudio.json");

bool dockShown(const MainWindow& window, const char* name)
{
    auto* dock = window.findChild<QDockWidget*>(QLatin1String(name));
    return dock && !dock->isHidden();
}

bool dockOffered(const MainWindow& window, const char* name)
{
    auto* dock = window.findChild<QDockWidget*>(QLatin1String(name));
    return dock && dock->toggleViewAction()->isVisible();
}

} // namespace

class TestPackmlWindow : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();

    void openingAPackmlModelShowsItsChart();
    void goingBackToGemmaBringsTheGemmaChartBack();
    void newAsksForTheTemplate();
    void cancellingNewKeepsTheModel();
    void examplesListTheBottleFiller();
    void doubleClickOpensTheGrafcetOfTheModeShown();
    void stateWithoutGrafcetOpensNoTab();
    void grafcetTabClosesWhenItsChoiceGoes();
    void contextMenuOpensTheGrafcetAndEditsTheCommand();
    void chartPicturesAreThePackmlChart();
    void structuredTextIsThePackmlProgramAndFollowsTheState();
    void resetKeepsTheTemplateAndItsEdition();
    void simulateRunsThePackmlSimulation();
    void verifyFindsAStuckStateAndReplaysItsCounterexample();

private:
    QTemporaryDir m_settingsDir;
    std::unique_ptr<Translators> m_translators;
    std::unique_ptr<MainWindow> m_window;
};

void TestPackmlWindow::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    editortest::useTestSettings(m_settingsDir.path(), QStringLiteral("test_packmlwindow"));
}

void TestPackmlWindow::init()
{
    m_window = editortest::showEnglishMainWindow(m_translators);
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
}

void TestPackmlWindow::cleanup()
{
    m_window.reset();
    m_translators.reset();
}

void TestPackmlWindow::openingAPackmlModelShowsItsChart()
{
    QVERIFY(m_window->openFile(kBottleFiller));
    QCOMPARE(m_window->document()->model().templateKind(), core::TemplateKind::PackML);
    QTabWidget* tabs = m_window->centralTabs();
    auto* chart = qobject_cast<PackmlChartView*>(tabs->widget(0));
    QVERIFY(chart);
    QVERIFY(chart->isVisible());
    QCOMPARE(tabs->tabText(0), QStringLiteral("PackML Chart"));
    QVERIFY(!m_window->chartView()->isVisible());
    // The chart shows the model's initial mode, and the model's modes to pick from.
    QCOMPARE(chart->chartScene()->mode(), m_window->document()->model().packml()->initialMode);
    QCOMPARE(chart->modeSelector()->count(), int(m_window->document()->model().packml()->modes.size()));

    // The GEMMA docks and actions go; the shared docks stay.
    QVERIFY(!dockShown(*m_window, "stepDock"));
    QVERIFY(!dockShown(*m_window, "transitionDock"));
    QVERIFY(!dockOffered(*m_window, "stepDock"));
    QVERIFY(!dockOffered(*m_window, "simulationDock"));
    QVERIFY(dockOffered(*m_window, "variablesDock"));
    QVERIFY(dockOffered(*m_window, "problemsDock"));
    for (const char* packml : {"packmlStateDock", "packmlCommandsDock", "packmlModesDock"}) {
        QVERIFY2(dockOffered(*m_window, packml), packml);
        QVERIFY2(dockShown(*m_window, packml), packml);
    }
    // A GRAFCET tab in front: the State and Commands panels give way to the nested ones.
    QVERIFY(m_window->openNestedGrafcet(QStringLiteral("1/Execute")));
    QVERIFY(!dockShown(*m_window, "packmlStateDock"));
    QVERIFY(!dockShown(*m_window, "packmlCommandsDock"));
    QVERIFY(dockShown(*m_window, "grafcetStepDock"));
    QVERIFY(dockShown(*m_window, "packmlModesDock"));
    m_window->centralTabs()->setCurrentIndex(0);
    QVERIFY(dockShown(*m_window, "packmlStateDock"));
    QVERIFY(!dockShown(*m_window, "grafcetStepDock"));
    QVERIFY(!m_window->findChild<QAction*>(QStringLiteral("hideSelectionAction"))->isVisible());
    QVERIFY(!m_window->exportActions()->ggGeneratorAction()->isVisible());
    QVERIFY(m_window->exportActions()->plcOpenAction()->isEnabled());
}

void TestPackmlWindow::goingBackToGemmaBringsTheGemmaChartBack()
{
    QVERIFY(m_window->openFile(kBottleFiller));
    m_window->findChild<QAction*>(QStringLiteral("example_0"))->trigger(); // the drilling cell
    QTabWidget* tabs = m_window->centralTabs();
    QCOMPARE(tabs->widget(0), static_cast<QWidget*>(m_window->chartView()));
    QCOMPARE(tabs->tabText(0), QStringLiteral("GEMMA Chart"));
    QVERIFY(m_window->chartView()->isVisible());
    QVERIFY(dockOffered(*m_window, "stepDock"));
    QVERIFY(dockShown(*m_window, "stepDock"));
    QVERIFY(dockOffered(*m_window, "simulationDock"));
    for (const char* packml : {"packmlStateDock", "packmlCommandsDock", "packmlModesDock"}) {
        QVERIFY2(!dockOffered(*m_window, packml), packml);
        QVERIFY2(!dockShown(*m_window, packml), packml);
    }
    QVERIFY(m_window->findChild<QAction*>(QStringLiteral("hideSelectionAction"))->isVisible());
    QVERIFY(m_window->exportActions()->ggGeneratorAction()->isVisible());
    QVERIFY(m_window->openNestedGrafcet(QStringLiteral("F1")));
    // The drilling cell has a machine: its tab comes right after the chart.
    QCOMPARE(tabs->tabText(1), QStringLiteral("Machine"));
    QCOMPARE(tabs->tabText(tabs->currentIndex()), QStringLiteral("F1 Normal production"));
}

void TestPackmlWindow::newAsksForTheTemplate()
{
    editortest::answerNewModel("templatePackml2022");
    m_window->findChild<QAction*>(QStringLiteral("newAction"))->trigger();
    const core::Model& model = m_window->document()->model();
    QVERIFY(model.packml());
    QCOMPARE(model.packml()->options.edition, core::packml::Edition::Y2022);
    QVERIFY(qobject_cast<PackmlChartView*>(m_window->centralTabs()->widget(0)));
    QVERIFY(!m_window->document()->isModified());

    // The dialog offers the last choice again; GEMMA is still one click away.
    QTimer::singleShot(0, [] {
        const auto poll = [](const auto& self) -> void {
            auto* dialog = qobject_cast<NewModelDialog*>(QApplication::activeModalWidget());
            if (!dialog) {
                QTimer::singleShot(10, [self] { self(self); });
                return;
            }
            QCOMPARE(dialog->choice(), NewModelDialog::Choice::Packml2022);
            dialog->setChoice(NewModelDialog::Choice::Gemma);
            dialog->accept();
        };
        poll(poll);
    });
    m_window->findChild<QAction*>(QStringLiteral("newAction"))->trigger();
    QVERIFY(!m_window->document()->model().packml());
    QCOMPARE(m_window->centralTabs()->widget(0), static_cast<QWidget*>(m_window->chartView()));
}

void TestPackmlWindow::cancellingNewKeepsTheModel()
{
    QVERIFY(m_window->openFile(kBottleFiller));
    editortest::answerNewModel("");
    m_window->findChild<QAction*>(QStringLiteral("newAction"))->trigger();
    QCOMPARE(m_window->document()->filePath(), kBottleFiller);
}

void TestPackmlWindow::examplesListTheBottleFiller()
{
    const std::vector<ExampleModel> examples = exampleModels();
    const auto bottle = std::find_if(examples.begin(), examples.end(), [](const ExampleModel& example) {
        return example.fileName == QLatin1String("bottle-filler.ggstudio.json");
    });
    QVERIFY(bottle != examples.end());
    const auto index = std::distance(examples.begin(), bottle);
    m_window->findChild<QAction*>(QStringLiteral("example_%1").arg(index))->trigger();
    QVERIFY(m_window->document()->model().packml());
    QVERIFY(m_window->document()->filePath().isEmpty());
    QVERIFY(qobject_cast<PackmlChartView*>(m_window->centralTabs()->widget(0)));
    // The example is clean: nothing to report.
    for (const core::Diagnostic& diagnostic : m_window->document()->diagnostics())
        QVERIFY2(diagnostic.severity == core::Severity::Info, diagnostic.code.c_str());
}

void TestPackmlWindow::doubleClickOpensTheGrafcetOfTheModeShown()
{
    QVERIFY(m_window->openFile(kBottleFiller));
    auto* chart = qobject_cast<PackmlChartView*>(m_window->centralTabs()->widget(0));
    QVERIFY(chart);
    const std::string key = core::packml::grafcetKey(1, core::packml::State::Execute);
    QVERIFY(m_window->document()->model().grafcet(key));
    emit chart->stateDoubleClicked(1, QStringLiteral("Execute"));
    QTabWidget* tabs = m_window->centralTabs();
    QCOMPARE(tabs->count(), 2);
    auto* view = qobject_cast<GrafcetView*>(tabs->currentWidget());
    QVERIFY(view);
    QCOMPARE(view->grafcetScene()->stepId(), QString::fromStdString(key));
    QCOMPARE(tabs->tabText(1), QStringLiteral("Production · Execute"));
    QVERIFY(view->grafcetScene()->stepItem(1));
    // The Structured Text dock shows that GRAFCET's function block.
    auto* st = m_window->findChild<StPreviewDock*>();
    QVERIFY(st);
    st->raise();
    QTRY_VERIFY2(st->editor()->toPlainText().startsWith(QStringLiteral("FUNCTION_BLOCK Production_Execute_FB")),
                 qPrintable(st->editor()->toPlainText().left(60)));
}

void TestPackmlWindow::stateWithoutGrafcetOpensNoTab()
{
    QVERIFY(m_window->openFile(kBottleFiller));
    auto* chart = qobject_cast<PackmlChartView*>(m_window->centralTabs()->widget(0));
    const int tabs = m_window->centralTabs()->count(); // those the file had open
    emit chart->stateDoubleClicked(1, QStringLiteral("Idle")); // a wait state
    emit chart->stateDoubleClicked(1, QStringLiteral("Nonsense"));
    QCOMPARE(m_window->centralTabs()->count(), tabs);
    QVERIFY(!m_window->openNestedGrafcet(QStringLiteral("1/Idle")));
    QVERIFY(!m_window->openNestedGrafcet(QStringLiteral("F1"))); // a GEMMA step in a PackML model
}

void TestPackmlWindow::grafcetTabClosesWhenItsChoiceGoes()
{
    QVERIFY(m_window->openFile(kBottleFiller));
    const QString key = QString::fromStdString(core::packml::grafcetKey(1, core::packml::State::Execute));
    QVERIFY(m_window->openNestedGrafcet(key));
    QCOMPARE(m_window->centralTabs()->count(), 2);
    core::Model changed(m_window->document()->model());
    QVERIFY(changed.setGrafcetChoice(1, core::packml::State::Execute, core::packml::GrafcetChoice::none()));
    m_window->document()->replaceModel(changed, QString(), core::ModelFormat::Native);
    QCOMPARE(m_window->centralTabs()->count(), 1);
}

void TestPackmlWindow::contextMenuOpensTheGrafcetAndEditsTheCommand()
{
    QVERIFY(m_window->openFile(kBottleFiller));
    auto* chart = qobject_cast<PackmlChartView*>(m_window->centralTabs()->widget(0));
    PackmlChartContextMenu menus(*m_window->document(), *chart->chartScene(), {});
    connect(&menus, &PackmlChartContextMenu::openGrafcetRequested, m_window.get(), &MainWindow::openNestedGrafcet);

    QMenu state;
    menus.populate(&state, ElementRef::packmlState(QStringLiteral("Execute"), 1));
    auto* open = state.findChild<QAction*>(QStringLiteral("openGrafcetAction"));
    QVERIFY(open);
    open->trigger();
    QCOMPARE(m_window->centralTabs()->count(), 2);
    // Choose Its GRAFCET puts the focus on the mode's choice in the State panel.
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    auto* choose = state.findChild<QAction*>(QStringLiteral("chooseGrafcetAction"));
    QVERIFY(choose);
    choose->trigger();
    auto* stateDock = m_window->findChild<QDockWidget*>(QStringLiteral("packmlStateDock"));
    auto* choice = stateDock->findChild<QComboBox*>(QStringLiteral("choice_1"));
    QVERIFY(choice);
    QTRY_VERIFY(choice->hasFocus());
    QMenu idle; // a wait state holds no GRAFCET
    menus.populate(&idle, ElementRef::packmlState(QStringLiteral("Idle"), 1));
    QVERIFY(!idle.findChild<QAction*>(QStringLiteral("openGrafcetAction")));
    QVERIFY(!idle.findChild<QAction*>(QStringLiteral("chooseGrafcetAction")));

    QSignalSpy focus(m_window->selection(), &Selection::focusFieldRequested);
    QMenu transition;
    menus.populate(&transition, ElementRef::packmlTransition(QStringLiteral("Idle"), QStringLiteral("Starting"), 1));
    auto* edit = transition.findChild<QAction*>(QStringLiteral("editCommandConditionAction"));
    QVERIFY(edit);
    QCOMPARE(edit->text(), QStringLiteral("Edit the Start &Condition…"));
    edit->trigger();
    QCOMPARE(m_window->selection()->current(), ElementRef::packmlCommand(QStringLiteral("Start")));
    QCOMPARE(focus.count(), 1);
    QCOMPARE(focus.first().at(1).toString(), QStringLiteral("condition"));
    QMenu sc; // a State Complete transition has no command
    menus.populate(&sc, ElementRef::packmlTransition(QStringLiteral("Starting"), QStringLiteral("Execute"), 1));
    QVERIFY(!sc.findChild<QAction*>(QStringLiteral("editCommandConditionAction")));

    // Show in Mode moves the chart to another mode.
    QMenu sheet;
    menus.populate(&sheet, ElementRef());
    auto* manual = sheet.findChild<QAction*>(QStringLiteral("showMode_3"));
    QVERIFY(manual);
    manual->trigger();
    QCOMPARE(chart->chartScene()->mode(), 3);
    QCOMPARE(chart->modeSelector()->currentData().toInt(), 3);
}

void TestPackmlWindow::chartPicturesAreThePackmlChart()
{
    QVERIFY(m_window->openFile(kBottleFiller));
    m_window->centralTabs()->setCurrentIndex(0); // the chart, not a GRAFCET tab the file had open
    QTemporaryDir dir;
    const QString png = dir.filePath(QStringLiteral("chart.png"));
    QString error;
    QVERIFY2(m_window->exportActions()->writeChart(png, ChartExport::Format::Png, &error), qPrintable(error));
    const QImage image(png);
    QVERIFY(!image.isNull());
    const QRectF sheet = qobject_cast<PackmlChartView*>(m_window->centralTabs()->widget(0))->chartScene()->sceneRect();
    // The PackML sheet at twice its size, with its margin: not the GEMMA sheet.
    QVERIFY2(std::abs(image.width() - 2 * (sheet.width() + 24)) <= 2,
             qPrintable(QStringLiteral("%1 for a sheet of %2").arg(image.width()).arg(sheet.width())));
    const QString svg = dir.filePath(QStringLiteral("chart.svg"));
    QVERIFY2(m_window->exportActions()->writeChart(svg, ChartExport::Format::Svg, &error), qPrintable(error));
    QFile file(svg);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray text = file.readAll();
    QVERIFY(text.contains("PackML chart drawn by GG Studio"));
    QVERIFY(text.contains("Execute"));
    const QString pdf = dir.filePath(QStringLiteral("chart.pdf"));
    QVERIFY2(m_window->exportActions()->writeChart(pdf, ChartExport::Format::Pdf, &error), qPrintable(error));
    QVERIFY(QFileInfo(pdf).size() > 1000);
}

void TestPackmlWindow::structuredTextIsThePackmlProgramAndFollowsTheState()
{
    QVERIFY(m_window->openFile(kBottleFiller));
    m_window->centralTabs()->setCurrentIndex(0); // the chart, not a GRAFCET tab the file had open
    auto* st = m_window->findChild<StPreviewDock*>();
    QVERIFY(st);
    st->show();
    st->raise();
    QTRY_VERIFY2(st->editor()->toPlainText().startsWith(QStringLiteral("PROGRAM ")),
                 qPrintable(st->editor()->toPlainText().left(60)));
    m_window->selection()->select(ElementRef::packmlState(QStringLiteral("Execute"), 1));
    QTRY_VERIFY(!st->editor()->extraSelections().isEmpty());
    const QTextCursor first = st->editor()->extraSelections().first().cursor;
    QCOMPARE(first.block().text(), QStringLiteral("    6: (* Execute *)"));
}

void TestPackmlWindow::resetKeepsTheTemplateAndItsEdition()
{
    editortest::answerNewModel("templatePackml2022");
    m_window->findChild<QAction*>(QStringLiteral("newAction"))->trigger();
    Document* document = m_window->document();
    core::Model changed(document->model());
    QVERIFY(changed.addMode(4, "Cleaning"));
    document->replaceModel(changed, QString(), core::ModelFormat::Native);
    QVERIFY(document->model().packml()->mode(4));
    // Reset to Template, as its question's Reset answers it.
    QTimer::singleShot(0, [] {
        const auto poll = [](const auto& self) -> void {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!box) {
                QTimer::singleShot(10, [self] { self(self); });
                return;
            }
            box->button(QMessageBox::Reset)->click();
        };
        poll(poll);
    });
    m_window->findChild<QAction*>(QStringLiteral("resetAction"))->trigger();
    QVERIFY(document->model().packml());
    QVERIFY(!document->model().packml()->mode(4));
    QCOMPARE(document->model().packml()->options.edition, core::packml::Edition::Y2022);
    document->undoStack()->undo();
    QVERIFY(document->model().packml()->mode(4));
}

void TestPackmlWindow::simulateRunsThePackmlSimulation()
{
    QVERIFY(m_window->openFile(kBottleFiller));
    auto* simulate = m_window->findChild<QAction*>(QStringLiteral("simulateAction"));
    QVERIFY(simulate->isEnabled());
    simulate->trigger();
    auto* session = m_window->findChild<PackmlSimulationSession*>();
    QVERIFY(session);
    QVERIFY(session->isActive());
    QVERIFY(!m_window->simulationSession()->isActive()); // GEMMA's stays off
    QVERIFY(m_window->document()->isReadOnly());
    QVERIFY(dockShown(*m_window, "packmlSimulationDock"));
    QVERIFY(!dockShown(*m_window, "simulationDock"));
    QVERIFY(!m_window->findChild<QAction*>(QStringLiteral("undoAction"))->isEnabled());

    // The window's scan commands drive it: Reset from Stopped, then one scan.
    const std::int64_t before = session->latestScan();
    m_window->findChild<QAction*>(QStringLiteral("singleScanAction"))->trigger();
    QCOMPARE(session->latestScan(), before + 1);
    session->pressCommand(core::packml::Command::Reset);
    m_window->findChild<QAction*>(QStringLiteral("singleScanAction"))->trigger();
    QVERIFY(m_window->findChild<QAction*>(QStringLiteral("stepBackAction"))->isEnabled());

    simulate->trigger();
    QVERIFY(!session->isActive());
    QVERIFY(!m_window->document()->isReadOnly());
    QVERIFY(!dockShown(*m_window, "packmlSimulationDock") || dockOffered(*m_window, "packmlSimulationDock"));
}

// The Capper with a Resetting GRAFCET that can stop short of Complete
// (tests/cli/data, the command-line tests' model).
void TestPackmlWindow::verifyFindsAStuckStateAndReplaysItsCounterexample()
{
    QVERIFY(m_window->openFile(QStringLiteral(GGSTUDIO_CLI_TEST_DATA_DIR "/packml-capper-stuck.json")));
    auto* verify = m_window->findChild<QAction*>(QStringLiteral("verifyAction"));
    QVERIFY(verify->isEnabled());
    VerificationRunner* runner = m_window->verificationRunner();
    QSignalSpy finished(runner, &VerificationRunner::finished);
    verify->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(finished.size() == 1, 60000);
    QVERIFY2(runner->failure().isEmpty(), qPrintable(runner->failure()));
    int stuck = -1;
    const std::vector<core::VerificationFinding>& findings = runner->result().findings;
    for (std::size_t i = 0; i < findings.size(); ++i) {
        if (findings[i].code == "GV130")
            stuck = static_cast<int>(i);
    }
    QVERIFY(stuck >= 0);
    const core::VerificationFinding& finding = findings[std::size_t(stuck)];
    // Worded for the user, located on the state in its mode.
    QVERIFY2(verificationText(finding).startsWith(QStringLiteral("In Production, the GRAFCET of Resetting")),
             qPrintable(verificationText(finding)));
    QVERIFY(finding.location);
    QCOMPARE(finding.location->state, std::string("Resetting"));
    QVERIFY(finding.counterexample && finding.counterexample->confirmed);

    // Replay in Simulator: the PackML simulation plays the counterexample.
    auto* panel = m_window->findChild<VerificationPanel*>();
    QVERIFY(panel);
    emit panel->replayRequested(stuck);
    auto* session = m_window->findChild<PackmlSimulationSession*>();
    QVERIFY(session->isActive());
    QVERIFY(session->isReplaying());
    QVERIFY(dockShown(*m_window, "packmlSimulationDock"));
    session->advance(session->replayLength());
    QCOMPARE(session->liveSimulator()->state(), core::packml::State::Resetting);
}

QTEST_MAIN(TestPackmlWindow)
#include "test_packmlwindow.moc"
