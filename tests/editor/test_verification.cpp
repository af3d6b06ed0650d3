// Verify in the editor: the action runs the verifier in a worker thread, the
// findings go to the Problems dock's Verification category, Show on Chart
// selects the element, Replay in Simulator plays the counterexample to the
// state it claims, and a change of the model marks the findings stale. The
// Complete modes of the Simulation dock decide which nested steps are
// verified with Complete automatic, and the panel says which.

#include "modelfactory.h"

#include "editortestsupport.h"

#include "editor/app/languages.h"
#include "editor/app/settings.h"
#include "editor/commands/propertycommands.h"
#include "editor/commands/removemachinecomponentcommand.h"
#include "editor/commands/setconditioncommand.h"
#include "editor/docks/problemsdock.h"
#include "editor/docks/propertiespanel.h"
#include "editor/docks/propertiestablemodel.h"
#include "editor/docks/verificationpanel.h"
#include "editor/docks/wrappinglabel.h"
#include "editor/document.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetstepitem.h"
#include "editor/grafcet/grafcettransitionitem.h"
#include "editor/grafcet/grafcetview.h"
#include "editor/mainwindow.h"
#include "editor/selection.h"
#include "editor/simulation/simulationdock.h"
#include "editor/simulation/simulationsession.h"
#include "editor/style/secondarytext.h"
#include "editor/text/diagnostictext.h"
#include "editor/text/displaytext.h"
#include "editor/text/elementlabels.h"
#include "editor/text/propertyproblemtext.h"
#include "editor/verificationrunner.h"
#include "editor/window/statusindicators.h"

#include "core/formats/modelfiles.h"
#include "core/verification/property.h"

#include <QToolButton>
#include <QAction>
#include <QComboBox>
#include <QSpinBox>
#include <QApplication>
#include <QClipboard>
#include <QTreeWidgetItemIterator>
#include <QLabel>
#include <QSettings>
#include <QStatusBar>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTableView>
#include <QTreeWidget>
#include <QUndoStack>

#include <algorithm>
#include <chrono>
#include <memory>

using namespace editor;

namespace {

constexpr int kVerifyTimeoutMs = 60000;

// The realistic model whose D2 can never be left: D2->A5 is never TRUE.
core::Model modelWithStuckStep()
{
    core::Model model = factory::realisticModel();
    if (!model.setCondition("D2->A5", "Acknowledge AND NOT Acknowledge"))
        qFatal("cannot seed the defect");
    return model;
}

// F1->A2 is TRUE and waits for F1.Complete; F1->F4 does not wait. With
// F1's Complete free, F1->F4 fires whenever Complete is FALSE; automatic,
// F1->A2 always fires first and F1->F4 is dead (GV102).
core::Model modelWaitingForComplete()
{
    core::Model model = factory::realisticModel();
    if (!model.setCondition("F1->A2", "TRUE") || !model.setTokens("F1->A2", {}) || !model.setNegated("F1->F4", true)
        || !model.setTokens("F1->F4", {}))
        qFatal("cannot build the model");
    return model;
}

// The step the counterexample ends in: its last `expect step`.
QString expectedStep(const core::Counterexample& counterexample)
{
    QString step;
    for (const core::ScenarioAction& action : counterexample.scenario.actions) {
        if (action.kind == core::ScenarioAction::Kind::ExpectStep)
            step = QString::fromStdString(action.name);
    }
    return step;
}

} // namespace

class TestVerification : public QObject {
    Q_OBJECT

private slots:
    void exactTimeFromTheMenu();
    void withMachineFromTheMenu();
    void singleFaultsFromTheMenu();
    void faultedIsAWordOfPropertiesWithSingleFaults();
    void timeLimitFromThePanel();
    void initTestCase();
    void init();
    void cleanup();

    void verifyListsTheDefect();
    void cleanModelHasNoViolation();
    void showOnChartSelectsTheElement();
    void replayReachesTheCounterexampleState();
    void modelEditMarksResultsStale();
    void statusBarCountsTheFindings();
    void modelEditCancelsARunningVerification();
    void languageChangeKeepsTheFindings();
    void simulationCompleteModesAreAssumed();
    void simulationAndReplayKeepTheFindingsCurrent();
    void newOrOpenedModelStartsWithoutFindings();
    void completeSettingChangeCancelsARunningVerification();
    void everyCodeHasATemplate();

    // Both layers, on the shipped faulty example.
    void nestedFindingsSitUnderTheirGemmaStep();
    void copyTakesChildRowsAndGroups();
    void showOnChartOpensTheNestedTabAndSelects();
    void statusCountsProgramStatesAndListsAbstractions();
    void propertyFindingsShowTheirText();
    void longPropertyIsCutAndNeverWidensTheWindow();
    void replayOfANestedFindingShowsItsGrafcet();
    void everyBothLayersCodeIsWorded();
    void stepsWithAGrafcetAreNeverAssumedAutomatic();
    void undecidedPropertyIsNeverCalledHolding();

private:
    void verifyAndWait();
    void loadFaultyExample();
    QTreeWidgetItem* row(const QString& code, const QString& element) const;
    QTreeWidgetItem* groupRow(const QString& stepId) const;
    void setCompleteMode(const QString& step, const QString& mode);

    QTemporaryDir m_settingsDir;
    std::unique_ptr<Translators> m_translators;
    std::unique_ptr<MainWindow> m_window;
    VerificationRunner* m_runner = nullptr;
    ProblemsDock* m_dock = nullptr;
};

void TestVerification::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    editortest::useTestSettings(m_settingsDir.path(), QStringLiteral("test_verification"));
}

void TestVerification::init()
{
    m_translators = std::make_unique<Translators>();
    m_translators->setLanguage(QStringLiteral("en"));
    m_window = editortest::showMainWindow(*m_translators);
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    m_runner = m_window->verificationRunner();
    m_dock = m_window->findChild<ProblemsDock*>(QStringLiteral("problemsDock"));
    QVERIFY(m_runner);
    QVERIFY(m_dock && m_dock->verificationPanel());
    m_window->document()->replaceModel(modelWithStuckStep(), QString(), core::ModelFormat::Native);
}

void TestVerification::cleanup()
{
    if (m_window)
        m_window->document()->undoStack()->setClean(); // no "save changes?" on close
    m_window.reset();
    m_translators.reset();
}

void TestVerification::verifyAndWait()
{
    auto* verify = m_window->findChild<QAction*>(QStringLiteral("verifyAction"));
    QVERIFY(verify);
    QSignalSpy finished(m_runner, &VerificationRunner::finished);
    verify->trigger();
    QVERIFY(m_runner->isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(finished.size() == 1, kVerifyTimeoutMs);
    QVERIFY(!m_runner->isRunning());
    QVERIFY2(m_runner->failure().isEmpty(), qPrintable(m_runner->failure()));
    QVERIFY(m_runner->hasResult());
    QVERIFY(!m_runner->isStale());
}

// Any row, top-level or under a GEMMA step.
QTreeWidgetItem* TestVerification::row(const QString& code, const QString& element) const
{
    for (QTreeWidgetItemIterator it(m_dock->verificationPanel()->view()); *it; ++it) {
        QTreeWidgetItem* item = *it;
        const core::VerificationFinding* finding = m_runner->finding(VerificationPanel::findingIndex(item));
        if (item->text(VerificationPanel::CodeColumn) == code && finding && !finding->elements.empty()
            && QString::fromStdString(finding->elements.front()) == element)
            return item;
    }
    return nullptr;
}

// The top-level row that groups the findings about the nested GRAFCET of `stepId`.
QTreeWidgetItem* TestVerification::groupRow(const QString& stepId) const
{
    QTreeWidget* view = m_dock->verificationPanel()->view();
    for (int i = 0; i < view->topLevelItemCount(); ++i) {
        QTreeWidgetItem* item = view->topLevelItem(i);
        if (VerificationPanel::findingIndex(item) < 0 && item->text(VerificationPanel::CodeColumn).startsWith(stepId + ' '))
            return item;
    }
    return nullptr;
}

void TestVerification::loadFaultyExample()
{
    const core::LoadedModel loaded = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell-faulty.ggstudio.json");
    QVERIFY(loaded.model);
    m_window->document()->replaceModel(*loaded.model, QString(), core::ModelFormat::Native);
}

// As the user does it: the step's combo box in the Simulation dock.
void TestVerification::setCompleteMode(const QString& step, const QString& mode)
{
    auto* dock = m_window->findChild<SimulationDock*>(QStringLiteral("simulationDock"));
    QVERIFY(dock);
    QComboBox* combo = dock->completeModeCombo(step);
    QVERIFY(combo);
    const int index = combo->findText(mode);
    QVERIFY(index >= 0);
    combo->setCurrentIndex(index);
}

void TestVerification::verifyListsTheDefect()
{
    auto* verify = m_window->findChild<QAction*>(QStringLiteral("verifyAction"));
    QVERIFY(verify);
    QCOMPARE(verify->shortcut(), QKeySequence(Qt::Key_F7));
    verifyAndWait();

    const core::VerificationResult& result = m_runner->result();
    QVERIFY(result.violated());
    QTreeWidget* view = m_dock->verificationPanel()->view();
    QCOMPARE(view->topLevelItemCount(), static_cast<int>(result.findings.size()));

    QTreeWidgetItem* stuck = row(QStringLiteral("GV106"), QStringLiteral("D2"));
    QVERIFY2(stuck, "D2 stuck is listed");
    QCOMPARE(stuck->text(VerificationPanel::ElementColumn), QStringLiteral("D2"));
    QVERIFY(stuck->text(VerificationPanel::MessageColumn).contains(QStringLiteral("D2")));
    QVERIFY(!stuck->text(VerificationPanel::ScansColumn).isEmpty()); // it has a counterexample
    QTreeWidgetItem* dead = row(QStringLiteral("GV102"), QStringLiteral("D2->A5"));
    QVERIFY2(dead, "the dead D2->A5 is listed");
    QVERIFY(dead->text(VerificationPanel::ElementColumn).startsWith(QStringLiteral("D2 → A5")));

    // The live checks stay in their own category; Verify brought this one forward.
    QVERIFY(m_dock->isVisible());
    QCOMPARE(m_dock->tabs()->currentWidget(), m_dock->verificationPanel());
    QCOMPARE(m_dock->tabs()->tabText(1), QStringLiteral("Verification (%1)").arg(result.findings.size()));
    QCOMPARE(m_dock->view()->topLevelItemCount(), static_cast<int>(m_window->document()->diagnostics().size()));
    QVERIFY(m_dock->verificationPanel()->statusLabel()->text().contains(QStringLiteral("do not hold")));
}

void TestVerification::cleanModelHasNoViolation()
{
    m_window->document()->replaceModel(factory::realisticModel(), QString(), core::ModelFormat::Native);
    verifyAndWait();
    const core::VerificationResult& result = m_runner->result();
    QVERIFY(result.exhaustive);
    for (const core::VerificationFinding& finding : result.findings)
        QVERIFY2(finding.severity == core::Severity::Info, finding.message.c_str());
    QVERIFY(!row(QStringLiteral("GV106"), QStringLiteral("D2")));
    QVERIFY(m_dock->verificationPanel()->statusLabel()->text().startsWith(QStringLiteral("Every property holds")));
}

void TestVerification::showOnChartSelectsTheElement()
{
    verifyAndWait();
    VerificationPanel* panel = m_dock->verificationPanel();
    QTreeWidgetItem* dead = row(QStringLiteral("GV102"), QStringLiteral("D2->A5"));
    QVERIFY(dead);
    panel->view()->setCurrentItem(dead);
    QVERIFY(panel->showOnChartAction()->isEnabled());
    panel->showOnChartAction()->trigger();
    QCOMPARE(m_window->selection()->current(), ElementRef::transition(QStringLiteral("D2->A5")));

    QTreeWidgetItem* stuck = row(QStringLiteral("GV106"), QStringLiteral("D2"));
    QVERIFY(stuck);
    emit panel->view()->itemActivated(stuck, 0); // double-click or Enter
    QCOMPARE(m_window->selection()->current(), ElementRef::step(QStringLiteral("D2")));
}

void TestVerification::replayReachesTheCounterexampleState()
{
    verifyAndWait();
    VerificationPanel* panel = m_dock->verificationPanel();
    QTreeWidgetItem* stuck = row(QStringLiteral("GV106"), QStringLiteral("D2"));
    QVERIFY(stuck);
    const core::VerificationFinding* finding = m_runner->finding(VerificationPanel::findingIndex(stuck));
    QVERIFY(finding && finding->counterexample);
    QVERIFY(finding->counterexample->confirmed);
    QCOMPARE(expectedStep(*finding->counterexample), QStringLiteral("D2"));

    panel->view()->setCurrentItem(stuck);
    QVERIFY(panel->replayAction()->isEnabled());
    panel->replayAction()->trigger();

    SimulationSession* session = m_window->simulationSession();
    QVERIFY(session->isActive());
    QVERIFY(m_window->document()->isReadOnly());
    auto* simulationDock = m_window->findChild<SimulationDock*>(QStringLiteral("simulationDock"));
    QVERIFY(simulationDock && simulationDock->isVisible());
    QVERIFY(session->replayFileName().contains(QStringLiteral("GV106")));
    // Paused at scan 0 so the user can step through it; Run plays the rest.
    QVERIFY(session->isReplaying());
    QVERIFY(!session->isRunning());
    QCOMPARE(session->simulator()->scanCount(), std::int64_t{0});
    m_window->findChild<QAction*>(QStringLiteral("runSimulationAction"))->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(session->replayState(), SimulationSession::ReplayState::Finished, 20000);
    QVERIFY(session->replayFailures().empty());
    QCOMPARE(session->simulator()->scanCount(), finding->counterexample->scans);
    QCOMPARE(QString::fromStdString(session->simulator()->activeStepId()), QStringLiteral("D2"));
    // Entering the simulation is no change of the model: the Complete
    // assumptions may differ now, but a counterexample sets Complete itself.
    QVERIFY(!m_runner->isStale());
    QCOMPARE(panel->view()->currentItem(), row(QStringLiteral("GV106"), QStringLiteral("D2")));
    QVERIFY(panel->replayAction()->isEnabled());
}

void TestVerification::statusBarCountsTheFindings()
{
    auto* counter = m_window->findChild<ProblemCounter*>();
    QVERIFY(counter);
    auto* button = counter->findChild<QToolButton*>(QStringLiteral("problemCountButton"));
    QVERIFY(!button->text().contains(QStringLiteral("Verification")));
    verifyAndWait();
    const int findings = int(m_runner->result().findings.size());
    QVERIFY(findings > 0);
    QCOMPARE(counter->findingCount(), findings);
    QVERIFY2(button->text().contains(QStringLiteral("Verification: %1 finding").arg(findings)),
             qPrintable(button->text()));
    // An edit makes them outdated, and the counter says so.
    Document* document = m_window->document();
    QVERIFY(document->push(new SetConditionCommand(*document, QStringLiteral("A6->A1"), QStringLiteral("HomePosition"))));
    QVERIFY2(button->text().contains(QStringLiteral("Verification (outdated)")), qPrintable(button->text()));
}

void TestVerification::modelEditMarksResultsStale()
{
    verifyAndWait();
    VerificationPanel* panel = m_dock->verificationPanel();
    QTreeWidgetItem* stuck = row(QStringLiteral("GV106"), QStringLiteral("D2"));
    QVERIFY(stuck);
    const QColor normal = stuck->foreground(VerificationPanel::MessageColumn).color();
    const int count = panel->view()->topLevelItemCount();

    Document* document = m_window->document();
    QVERIFY(document->push(new SetConditionCommand(*document, QStringLiteral("A6->A1"), QStringLiteral("HomePosition"))));
    QVERIFY(m_runner->isStale());
    // Still listed, greyed, with a note; a stale counterexample is not replayed.
    QCOMPARE(panel->view()->topLevelItemCount(), count);
    stuck = row(QStringLiteral("GV106"), QStringLiteral("D2"));
    QVERIFY(stuck);
    const QColor grey = secondaryTextColor(panel->palette(), QPalette::Base);
    QCOMPARE(stuck->foreground(VerificationPanel::MessageColumn).color(), grey);
    QVERIFY(normal != grey);
    QVERIFY(panel->statusLabel()->text().contains(QStringLiteral("Model changed since verification")));
    QCOMPARE(m_dock->tabs()->tabText(1), QStringLiteral("Verification (outdated)"));
    // In a narrow dock the status wraps: its label is as high as its lines
    // need and as wide as the panel, never cut.
    panel->resize(280, 400);
    panel->show();
    QApplication::processEvents();
    QLabel* status = panel->statusLabel();
    QVERIFY(status->wordWrap());
    QVERIFY(status->width() <= panel->width());
    QVERIFY2(status->height() >= status->heightForWidth(status->width()),
             qPrintable(QStringLiteral("%1 < %2").arg(status->height()).arg(status->heightForWidth(status->width()))));
    QVERIFY(status->heightForWidth(status->width()) > status->fontMetrics().height() * 3 / 2); // more than one line
    panel->view()->setCurrentItem(stuck);
    QVERIFY(!panel->replayAction()->isEnabled());
    QVERIFY(panel->showOnChartAction()->isEnabled());

    // Undo is a change too; verifying again brings the findings up to date.
    document->undoStack()->undo();
    QVERIFY(m_runner->isStale());
    verifyAndWait();
    stuck = row(QStringLiteral("GV106"), QStringLiteral("D2"));
    QVERIFY(stuck);
    QVERIFY(stuck->foreground(VerificationPanel::MessageColumn).color() != grey);
    panel->view()->setCurrentItem(stuck);
    QVERIFY(panel->replayAction()->isEnabled());
}

void TestVerification::modelEditCancelsARunningVerification()
{
    QSignalSpy cancelled(m_runner, &VerificationRunner::cancelled);
    QSignalSpy finished(m_runner, &VerificationRunner::finished);
    m_window->findChild<QAction*>(QStringLiteral("verifyAction"))->trigger();
    QVERIFY(m_runner->isRunning());
    // Its result arrives through the event loop, which has not run yet.
    Document* document = m_window->document();
    QVERIFY(document->push(new SetConditionCommand(*document, QStringLiteral("A6->A1"), QStringLiteral("HomePosition"))));
    QVERIFY(!m_runner->isRunning());
    QCOMPARE(cancelled.size(), 1);
    QTest::qWait(300);
    QCOMPARE(finished.size(), 0);
    QVERIFY(!m_runner->hasResult());

    // Verifying again while a run is under way abandons the first one.
    m_runner->start();
    m_runner->start();
    QCOMPARE(cancelled.size(), 2);
    QTRY_VERIFY_WITH_TIMEOUT(finished.size() == 1, kVerifyTimeoutMs);
    QTest::qWait(100);
    QCOMPARE(finished.size(), 1);
    QVERIFY(m_runner->hasResult());
}

void TestVerification::languageChangeKeepsTheFindings()
{
    verifyAndWait();
    const QString english = row(QStringLiteral("GV106"), QStringLiteral("D2"))->text(VerificationPanel::MessageColumn);
    QVERIFY(m_translators->setLanguage(QStringLiteral("fr")));
    // The panel rewords its findings in the new language.
    QTRY_VERIFY(m_window->findChild<ProblemsDock*>(QStringLiteral("problemsDock"))->windowTitle()
                != QStringLiteral("Problems"));
    m_dock = m_window->findChild<ProblemsDock*>(QStringLiteral("problemsDock"));
    QTreeWidgetItem* stuck = row(QStringLiteral("GV106"), QStringLiteral("D2"));
    QVERIFY(stuck);
    QVERIFY(stuck->text(VerificationPanel::MessageColumn) != english);
    QVERIFY(stuck->text(VerificationPanel::MessageColumn).contains(QStringLiteral("D2")));
    const QString assumptions = m_dock->verificationPanel()->assumptionsLabel()->text();
    QVERIFY(!assumptions.isEmpty());
    QVERIFY(assumptions != QStringLiteral("All Complete outputs free"));
    m_translators->setLanguage(QStringLiteral("en"));
}

void TestVerification::simulationCompleteModesAreAssumed()
{
    m_window->document()->replaceModel(modelWaitingForComplete(), QString(), core::ModelFormat::Native);
    VerificationPanel* panel = m_dock->verificationPanel();
    const auto deadF1F4 = [this] { return row(QStringLiteral("GV102"), QStringLiteral("F1->F4")); };

    // Without the simulation every Complete is free: F1->F4 can fire.
    QVERIFY(m_runner->assumedAutomatic().isEmpty());
    verifyAndWait();
    QVERIFY(!deadF1F4());
    QCOMPARE(panel->assumptionsLabel()->text(), QStringLiteral("All Complete outputs free"));
    const QString freeStatus = panel->statusLabel()->text();

    // The simulation starts with every Complete automatic: the next Verify
    // would assume that, but the user changed no setting, so the findings
    // stay current, with the assumptions they were computed with.
    SimulationSession* session = m_window->simulationSession();
    QSignalSpy assumptionsChanged(m_runner, &VerificationRunner::assumptionsChanged);
    session->setActive(true);
    QCOMPARE(assumptionsChanged.size(), 1);
    QCOMPARE(m_runner->assumedAutomatic(), QStringList({"A7", "F1", "F4"}));
    QVERIFY(!m_runner->assumptionsDiffer());
    QVERIFY(!m_runner->isStale());
    QCOMPARE(panel->statusLabel()->text(), freeStatus);
    QCOMPARE(panel->assumptionsLabel()->text(), QStringLiteral("All Complete outputs free")); // the findings'

    // A Complete mode the user changes does make them outdated, yet their scenarios still replay.
    setCompleteMode(QStringLiteral("A7"), QStringLiteral("Manual"));
    QVERIFY(m_runner->assumptionsDiffer());
    QVERIFY(panel->statusLabel()->text().contains(QStringLiteral("Complete settings changed since verification")));
    QCOMPARE(m_dock->tabs()->tabText(1), QStringLiteral("Verification (outdated)"));
    QTreeWidgetItem* first = panel->view()->topLevelItem(0);
    QVERIFY(first);
    QCOMPARE(first->foreground(VerificationPanel::MessageColumn).color(),
             secondaryTextColor(panel->palette(), QPalette::Base));
    panel->view()->setCurrentItem(first);
    QVERIFY(panel->replayAction()->isEnabled());

    // Manual everywhere is free everywhere: the findings match again. Playing
    // an input changes no assumption.
    for (const QString& step : {QStringLiteral("F1"), QStringLiteral("F4")})
        setCompleteMode(step, QStringLiteral("Manual"));
    QVERIFY(m_runner->assumedAutomatic().isEmpty());
    QVERIFY(!m_runner->assumptionsDiffer());
    QCOMPARE(panel->statusLabel()->text(), freeStatus);
    QCOMPARE(m_dock->tabs()->tabText(1), QStringLiteral("Verification (%1)").arg(m_runner->result().findings.size()));
    const int changes = assumptionsChanged.size();
    QVERIFY(session->setVariable(0, true));
    QCOMPARE(assumptionsChanged.size(), changes);

    // F1 automatic: F1->A2 always fires first, F1->F4 is dead.
    setCompleteMode(QStringLiteral("F1"), QStringLiteral("Automatic"));
    QCOMPARE(m_runner->assumedAutomatic(), QStringList({"F1"}));
    QVERIFY(m_runner->assumptionsDiffer());
    verifyAndWait();
    QVERIFY(!m_runner->assumptionsDiffer());
    QTreeWidgetItem* dead = deadF1F4();
    QVERIFY2(dead, "F1->F4 is dead when F1 completes at once");
    QVERIFY(!dead->text(VerificationPanel::ScansColumn).isEmpty());
    QCOMPARE(panel->assumptionsLabel()->text(), QStringLiteral("Assumed Complete automatic: F1"));
    QVERIFY(panel->statusLabel()->text().contains(QStringLiteral("do not hold")));

    // Leaving the simulation: the next Verify assumes every Complete free
    // again, and the findings stay current with what they assumed.
    session->setActive(false);
    QVERIFY(m_runner->assumedAutomatic().isEmpty());
    QVERIFY(!m_runner->assumptionsDiffer());
    QCOMPARE(panel->assumptionsLabel()->text(), QStringLiteral("Assumed Complete automatic: F1"));
    verifyAndWait();
    QVERIFY(!deadF1F4());
    QCOMPARE(panel->assumptionsLabel()->text(), QStringLiteral("All Complete outputs free"));
}

// Starting a simulation, replaying a finding and stopping change none of
// the user's settings: the findings stay current (issue #32).
void TestVerification::simulationAndReplayKeepTheFindingsCurrent()
{
    verifyAndWait();
    VerificationPanel* panel = m_dock->verificationPanel();
    const QString status = panel->statusLabel()->text();
    const QString tab = m_dock->tabs()->tabText(1);
    QVERIFY(!tab.contains(QStringLiteral("outdated")));
    const auto current = [&] {
        QVERIFY(!m_runner->isStale());
        QVERIFY(!m_runner->assumptionsDiffer());
        QCOMPARE(panel->statusLabel()->text(), status);
        QCOMPARE(m_dock->tabs()->tabText(1), tab);
        QTreeWidgetItem* stuck = row(QStringLiteral("GV106"), QStringLiteral("D2"));
        QVERIFY(stuck);
        QVERIFY(stuck->foreground(VerificationPanel::MessageColumn).color()
                != secondaryTextColor(panel->palette(), QPalette::Base));
    };

    SimulationSession* session = m_window->simulationSession();
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    QVERIFY(session->isActive());
    current();
    QVERIFY(session->setVariable(0, true));
    m_window->findChild<QAction*>(QStringLiteral("resetSimulationAction"))->trigger();
    current();
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    QVERIFY(!session->isActive());
    current();

    // Replay in Simulator, played to its end, then the simulation stopped.
    panel->view()->setCurrentItem(row(QStringLiteral("GV106"), QStringLiteral("D2")));
    panel->replayAction()->trigger();
    QVERIFY(session->isReplaying());
    current();
    m_window->findChild<QAction*>(QStringLiteral("runSimulationAction"))->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(session->replayState(), SimulationSession::ReplayState::Finished, 20000);
    current();
    session->setActive(false);
    current();
}

// A new or opened model is another model: the findings of the last one go
// with it, whichever way it came (New, Open, an example, a recovery).
void TestVerification::newOrOpenedModelStartsWithoutFindings()
{
    VerificationPanel* panel = m_dock->verificationPanel();
    auto* counter = m_window->findChild<ProblemCounter*>();
    QVERIFY(counter);
    const QString notVerified = panel->statusLabel()->text();
    QCOMPARE(notVerified, QStringLiteral("Not verified yet."));
    const auto noFindings = [&](const char* how) {
        QVERIFY2(!m_runner->hasResult(), how);
        QVERIFY2(!m_runner->isStale(), how);
        QCOMPARE(panel->view()->topLevelItemCount(), 0);
        QCOMPARE(panel->statusLabel()->text(), notVerified);
        QCOMPARE(m_dock->tabs()->tabText(1), QStringLiteral("Verification"));
        QCOMPARE(counter->findingCount(), 0);
    };
    const auto verifyFindsSome = [&] {
        verifyAndWait();
        QVERIFY(panel->view()->topLevelItemCount() > 0);
    };

    verifyFindsSome();
    editortest::answerNewModel("templateGemma");
    m_window->findChild<QAction*>(QStringLiteral("newAction"))->trigger();
    noFindings("New");

    m_window->document()->replaceModel(modelWithStuckStep(), QString(), core::ModelFormat::Native);
    verifyFindsSome();
    QVERIFY(m_window->openFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell-faulty.ggstudio.json"));
    noFindings("Open");

    verifyFindsSome();
    m_window->findChild<QAction*>(QStringLiteral("example_0"))->trigger();
    noFindings("an example");

    // A verification under way is abandoned with the model it verifies.
    m_window->findChild<QAction*>(QStringLiteral("verifyAction"))->trigger();
    QVERIFY(m_runner->isRunning());
    m_window->document()->replaceModel(modelWithStuckStep(), QString(), core::ModelFormat::Native); // a recovery
    QVERIFY(!m_runner->isRunning());
    QTest::qWait(200);
    noFindings("a recovery");
}

void TestVerification::completeSettingChangeCancelsARunningVerification()
{
    SimulationSession* session = m_window->simulationSession();
    session->setActive(true);
    QSignalSpy cancelled(m_runner, &VerificationRunner::cancelled);
    QSignalSpy finished(m_runner, &VerificationRunner::finished);

    // An input played is no change of the assumptions: the run goes on.
    m_window->findChild<QAction*>(QStringLiteral("verifyAction"))->trigger();
    QVERIFY(m_runner->isRunning());
    QVERIFY(session->setVariable(0, true));
    QVERIFY(m_runner->isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(finished.size() == 1, kVerifyTimeoutMs);
    QCOMPARE(cancelled.size(), 0);
    QCOMPARE(m_runner->resultAssumedAutomatic(), QStringList({"A7", "F1", "F4"}));

    // A Complete mode changed is: the run under way assumed the old one.
    m_runner->start();
    QVERIFY(m_runner->isRunning());
    setCompleteMode(QStringLiteral("F4"), QStringLiteral("Manual"));
    QVERIFY(!m_runner->isRunning());
    QCOMPARE(cancelled.size(), 1);
    QVERIFY(m_runner->wasCancelled());
    QVERIFY(m_window->statusBar()->currentMessage().contains(QStringLiteral("the Complete settings")));
    QTest::qWait(300);
    QCOMPARE(finished.size(), 1);
    // The last result stays, with what it assumed.
    QCOMPARE(m_runner->resultAssumedAutomatic(), QStringList({"A7", "F1", "F4"}));
    QVERIFY(m_runner->assumptionsDiffer());
    QCOMPARE(m_dock->verificationPanel()->assumptionsLabel()->text(),
             QStringLiteral("Assumed Complete automatic: A7, F1, F4"));
}

void TestVerification::everyCodeHasATemplate()
{
    namespace gv = core::verification;
    // Each code with the arguments the verifier gives: the element, then the elements it names.
    const std::vector<std::vector<std::string>> shapes{
        {gv::kIncomplete},
        {gv::kIncomplete, "F1"},
        {gv::kUnreachableStep, "F2"},
        {gv::kUnreachableStep, "F2", "A1->F2"},
        {gv::kDeadTransition, "A1->F1"},
        {gv::kDeadTransition, "A1->F1", "A1->F4", "A1->F2"},
        {gv::kAlwaysTrue, "F->D1"},
        {gv::kAlwaysTrue, "A1->F4", "A1->F2"},
        {gv::kOverlap, "A1->F4", "A1->F2"},
        {gv::kNoReturn, "F1"},
        {gv::kStuck, "D2"},
        {gv::kNoEmergencyStop, "F2"},
        {gv::kNoEmergencyStop, "F1", "F->D1"},
    };
    for (const std::vector<std::string>& shape : shapes) {
        core::VerificationFinding finding;
        finding.code = shape.front();
        finding.arguments.assign(shape.begin() + 1, shape.end());
        finding.elements = finding.arguments;
        finding.message = "untranslated";
        const QString text = verificationText(finding);
        QVERIFY2(text != QStringLiteral("Untranslated"), finding.code.c_str());
        if (!finding.arguments.empty()) {
            // Transitions are named as in the Problems dock and the chart: "A1 → F4".
            const QString first = QString::fromStdString(finding.arguments.front());
            const QString named = first.contains(QStringLiteral("->")) ? transitionLabel(first) : first;
            QVERIFY2(text.contains(named), qPrintable(text));
        }
        QVERIFY2(!text.contains(QStringLiteral("->")), qPrintable(text));
    }
    // An unconfirmed claim says so.
    core::VerificationFinding unconfirmed;
    unconfirmed.code = gv::kStuck;
    unconfirmed.severity = core::Severity::Info;
    unconfirmed.arguments = unconfirmed.elements = {"F1"};
    unconfirmed.counterexample = core::Counterexample{};
    QVERIFY(verificationText(unconfirmed).contains(QStringLiteral("Not confirmed")));
    // Of both layers: whether the search for a run that replays was cut or found none to the end.
    unconfirmed.origin = core::FindingOrigin::BothLayers;
    const QString cutShort = QStringLiteral("stopped at the time or size limit");
    QVERIFY(verificationText(unconfirmed).contains(QStringLiteral("does not replay in the simulator.")));
    QVERIFY(!verificationText(unconfirmed).contains(cutShort));
    unconfirmed.replaySearchCut = true;
    QVERIFY(verificationText(unconfirmed).contains(cutShort));
    // A code the editor does not know keeps the core's English message.
    core::VerificationFinding unknown;
    unknown.code = "GV999";
    unknown.message = "something new about F1->A2";
    QCOMPARE(verificationText(unknown), QStringLiteral("Something new about F1 → A2"));
}

// The findings about a nested GRAFCET are children of a row of their GEMMA
// step, which carries the worst severity, expanded; the others stay at the
// top; errors come first at each level.
void TestVerification::nestedFindingsSitUnderTheirGemmaStep()
{
    loadFaultyExample();
    verifyAndWait();
    const core::VerificationResult& result = m_runner->result();
    QVERIFY(result.bothLayers);
    QTreeWidget* view = m_dock->verificationPanel()->view();

    QTreeWidgetItem* f2 = groupRow(QStringLiteral("F2"));
    QVERIFY2(f2, "a row for F2's nested GRAFCET");
    QCOMPARE(f2->text(VerificationPanel::CodeColumn), QStringLiteral("F2 Preparation run: nested GRAFCET"));
    QVERIFY(f2->isExpanded());
    QVERIFY(f2->isFirstColumnSpanned());
    QTreeWidgetItem* never = row(QStringLiteral("GV110"), QStringLiteral("F2/4"));
    QVERIFY(never);
    QCOMPARE(never->parent(), f2);
    QCOMPARE(never->text(VerificationPanel::ElementColumn), QStringLiteral("F2: step 4"));
    QTreeWidgetItem* dead = row(QStringLiteral("GV111"), QStringLiteral("F2/T4"));
    QVERIFY(dead);
    QCOMPARE(dead->parent(), f2);
    QCOMPARE(dead->text(VerificationPanel::ElementColumn), QStringLiteral("F2: T4"));
    // GV115 of F2 is an error: the group's first child and its icon.
    QCOMPARE(f2->child(0)->text(VerificationPanel::CodeColumn), QStringLiteral("GV115"));
    QCOMPARE(f2->icon(VerificationPanel::CodeColumn).cacheKey() == QIcon().cacheKey(), false);
    QCOMPARE(f2->toolTip(VerificationPanel::CodeColumn).contains(QStringLiteral("F2")), true);

    // Every finding is listed once; those without a GEMMA step at the top.
    int rows = 0;
    for (QTreeWidgetItemIterator it(view); *it; ++it) {
        const int index = VerificationPanel::findingIndex(*it);
        if (index < 0)
            continue;
        ++rows;
        const core::VerificationFinding& finding = result.findings[static_cast<std::size_t>(index)];
        if (finding.gemmaStep.empty())
            QVERIFY(!(*it)->parent());
        else
            QVERIFY((*it)->parent() && (*it)->parent() == groupRow(QString::fromStdString(finding.gemmaStep)));
    }
    QCOMPARE(rows, static_cast<int>(result.findings.size()));
    QVERIFY(!row(QStringLiteral("GV106"), QStringLiteral("A6"))->parent());
    QVERIFY(groupRow(QStringLiteral("A6")));

    // Errors first among the children and among the top-level rows (a group
    // counts with its worst finding).
    const auto severityOf = [&](const QTreeWidgetItem* item) {
        const int index = VerificationPanel::findingIndex(item);
        return index >= 0 ? result.findings[static_cast<std::size_t>(index)].severity
                          : result.findings[static_cast<std::size_t>(VerificationPanel::findingIndex(item->child(0)))]
                                .severity;
    };
    for (int i = 1; i < view->topLevelItemCount(); ++i)
        QVERIFY(severityOf(view->topLevelItem(i - 1)) <= severityOf(view->topLevelItem(i)));
    for (int i = 1; i < f2->childCount(); ++i)
        QVERIFY(severityOf(f2->child(i - 1)) <= severityOf(f2->child(i)));

    // A collapsed group stays collapsed when the list is refreshed (a language change).
    f2->setExpanded(false);
    m_translators->setLanguage(QStringLiteral("de"));
    m_translators->setLanguage(QStringLiteral("en"));
    QVERIFY(groupRow(QStringLiteral("F2")));
    QVERIFY(!groupRow(QStringLiteral("F2"))->isExpanded());
    QVERIFY(groupRow(QStringLiteral("A6"))->isExpanded());
}

// Copy takes a selected child row, and a selected group with its findings;
// the current child row stays current across a refresh.
void TestVerification::copyTakesChildRowsAndGroups()
{
    loadFaultyExample();
    verifyAndWait();
    VerificationPanel* panel = m_dock->verificationPanel();
    QTreeWidget* view = panel->view();
    QAction* copyAction = nullptr;
    for (QAction* action : view->actions()) {
        if (action->text() == QStringLiteral("&Copy"))
            copyAction = action;
    }
    QVERIFY(copyAction);

    QTreeWidgetItem* never = row(QStringLiteral("GV110"), QStringLiteral("F2/4"));
    QVERIFY(never);
    view->setCurrentItem(never);
    QCOMPARE(view->selectedItems(), QList<QTreeWidgetItem*>{never});
    copyAction->trigger();
    const QString line = QApplication::clipboard()->text();
    QVERIFY2(line.startsWith(QStringLiteral("GV110\tF2: step 4\tStep 4 of the nested GRAFCET of F2")), qPrintable(line));
    QCOMPARE(line.count(QLatin1Char('\n')), 1);

    QTreeWidgetItem* f2 = groupRow(QStringLiteral("F2"));
    view->setCurrentItem(f2);
    copyAction->trigger();
    const QStringList lines = QApplication::clipboard()->text().split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 1 + f2->childCount());
    QCOMPARE(lines.front(), f2->text(VerificationPanel::CodeColumn));
    QVERIFY(lines.contains(line.trimmed()));

    // The current child row survives the refresh of a language change.
    view->setCurrentItem(row(QStringLiteral("GV111"), QStringLiteral("F2/T4")));
    m_translators->setLanguage(QStringLiteral("de"));
    QTreeWidgetItem* current = view->currentItem();
    QVERIFY(current);
    const core::VerificationFinding* finding = m_runner->finding(VerificationPanel::findingIndex(current));
    QVERIFY(finding);
    QCOMPARE(finding->code, std::string("GV111"));
    QCOMPARE(finding->elements.front(), std::string("F2/T4"));
    // A group row stays current too.
    view->setCurrentItem(groupRow(QStringLiteral("A6")));
    m_translators->setLanguage(QStringLiteral("en"));
    QCOMPARE(view->currentItem(), groupRow(QStringLiteral("A6")));
    QVERIFY(!panel->showOnChartAction()->isEnabled()); // a group names no element
}

// Show on Chart of a nested finding opens the tab of its GRAFCET and
// selects the nested step or transition there.
void TestVerification::showOnChartOpensTheNestedTabAndSelects()
{
    loadFaultyExample();
    verifyAndWait();
    VerificationPanel* panel = m_dock->verificationPanel();
    QVERIFY(!m_window->grafcetView(QStringLiteral("F2")));

    QTreeWidgetItem* never = row(QStringLiteral("GV110"), QStringLiteral("F2/4"));
    QVERIFY(never);
    panel->view()->setCurrentItem(never);
    QVERIFY(panel->showOnChartAction()->isEnabled());
    panel->showOnChartAction()->trigger();
    QCOMPARE(m_window->selection()->current(), ElementRef::grafcetStep(QStringLiteral("F2"), 4));
    GrafcetView* f2 = m_window->grafcetView(QStringLiteral("F2"));
    QVERIFY2(f2, "the nested tab of F2 is opened");
    QCOMPARE(m_window->centralTabs()->currentWidget(), f2);
    QVERIFY(f2->grafcetScene()->stepItem(4));
    QTRY_VERIFY(f2->grafcetScene()->stepItem(4)->isSelected());

    // Back on the GEMMA chart, a dead nested transition brings the tab forward again.
    m_window->centralTabs()->setCurrentIndex(0);
    QTreeWidgetItem* dead = row(QStringLiteral("GV111"), QStringLiteral("A6/T2"));
    QVERIFY(dead);
    emit panel->view()->itemActivated(dead, 0);
    QCOMPARE(m_window->selection()->current(), ElementRef::grafcetTransition(QStringLiteral("A6"), 2));
    GrafcetView* a6 = m_window->grafcetView(QStringLiteral("A6"));
    QVERIFY(a6);
    QCOMPARE(m_window->centralTabs()->currentWidget(), a6);
    QVERIFY(a6->grafcetScene()->transitionItem(2));
    QTRY_VERIFY(a6->grafcetScene()->transitionItem(2)->isSelected());
    QVERIFY(!f2->grafcetScene()->stepItem(4)->isSelected());

    // A selection of two nested transitions: the first is shown.
    QTreeWidgetItem* together = row(QStringLiteral("GV114"), QStringLiteral("F2/T1"));
    QVERIFY(together);
    QCOMPARE(together->text(VerificationPanel::ElementColumn), QStringLiteral("F2: T1, F2: T2"));
    panel->showOnChart(together);
    QCOMPARE(m_window->selection()->current(), ElementRef::grafcetTransition(QStringLiteral("F2"), 1));
    QCOMPARE(m_window->centralTabs()->currentWidget(), f2);
}

void TestVerification::statusCountsProgramStatesAndListsAbstractions()
{
    loadFaultyExample();
    verifyAndWait();
    const core::VerificationResult& result = m_runner->result();
    QVERIFY(result.programStates > 0);
    QVERIFY(!result.abstractions.empty());
    VerificationPanel* panel = m_dock->verificationPanel();
    const QString status = panel->statusLabel()->text();
    QVERIFY2(status.contains(QStringLiteral("%1 program states of both layers").arg(result.programStates)),
             qPrintable(status));
    QVERIFY2(status.contains(QStringLiteral("%1 configurations").arg(result.configurations)), qPrintable(status));
    const QString toolTip = panel->assumptionsLabel()->toolTip();
    QVERIFY(toolTip.contains(QStringLiteral("The exploration of both layers abstracted:")));
    for (const std::string& line : result.abstractions)
        QVERIFY2(toolTip.contains(QString::fromStdString(line)), line.c_str());

    // Without nested GRAFCETs only the GEMMA layer is explored, as before.
    m_window->document()->replaceModel(modelWithStuckStep(), QString(), core::ModelFormat::Native);
    verifyAndWait();
    QVERIFY(!m_runner->result().bothLayers);
    QVERIFY(!panel->statusLabel()->text().contains(QStringLiteral("program states")));
    QVERIFY(!panel->assumptionsLabel()->toolTip().contains(QStringLiteral("abstracted")));
}

// The panel's time limit is the next runs' and is remembered; a run that
// reaches it reports what is undecided (GV100), and more time decides it.
void TestVerification::timeLimitFromThePanel()
{
    VerificationPanel* panel = m_dock->verificationPanel();
    QSpinBox* box = panel->timeLimitBox();
    QCOMPARE(box->value(), Settings::kDefaultVerificationSeconds);
    QCOMPARE(m_runner->timeLimit(), std::chrono::milliseconds(4000));
    box->setValue(90);
    QCOMPARE(m_runner->timeLimit(), std::chrono::milliseconds(90000));
    QCOMPARE(Settings().verificationTimeLimitSeconds(), 90);

    // Thousands of program states: 1 ms (below the box's 1 s) is sure to stop it.
    m_window->document()->replaceModel(factory::bothLayersStressModel(), QString(), core::ModelFormat::Native);
    m_runner->setTimeLimit(std::chrono::milliseconds(1));
    verifyAndWait();
    QVERIFY(!m_runner->result().exhaustive);
    const auto& findings = m_runner->result().findings;
    QVERIFY(std::any_of(findings.begin(), findings.end(),
                        [](const core::VerificationFinding& f) { return f.code == core::verification::kIncomplete; }));
    box->setValue(60);
    verifyAndWait();
    QVERIFY(m_runner->result().exhaustive);
    box->setValue(Settings::kDefaultVerificationSeconds); // the next tests start from the default
}

// A property finding names the property in the element column and has no
// element to show on the chart.
// Simulation > Verify with Exact Time counts time in scans: the timers are no
// longer among what the exploration abstracted.
void TestVerification::exactTimeFromTheMenu()
{
    loadFaultyExample();
    const auto timerAbstracted = [this] {
        for (const std::string& line : m_runner->result().abstractions) {
            if (line.find("timers") != std::string::npos)
                return true;
        }
        return false;
    };
    verifyAndWait();
    QVERIFY(timerAbstracted());
    auto* exact = m_window->findChild<QAction*>(QStringLiteral("verifyExactTimeAction"));
    QVERIFY(exact && exact->isCheckable());
    VerificationPanel* panel = m_dock->verificationPanel();
    QSignalSpy assumptionsChanged(m_runner, &VerificationRunner::assumptionsChanged);
    exact->setChecked(true);
    QVERIFY(m_runner->exactTime());
    QCOMPARE(assumptionsChanged.size(), 1);
    // The findings were computed with time abstracted: outdated, still replayable.
    QVERIFY(m_runner->assumptionsDiffer());
    QVERIFY(!m_runner->isStale());
    QVERIFY(panel->statusLabel()->text().contains(QStringLiteral("Exact time switched on since verification")));
    QCOMPARE(m_dock->tabs()->tabText(1), QStringLiteral("Verification (outdated)"));
    QVERIFY(!panel->assumptionsLabel()->text().contains(QStringLiteral("Exact time"))); // the findings'
    verifyAndWait();
    QVERIFY(!m_runner->assumptionsDiffer());
    QVERIFY(m_runner->result().bothLayers);
    QVERIFY(!timerAbstracted());
    QVERIFY(panel->assumptionsLabel()->text().endsWith(QStringLiteral("Exact time")));
    QCOMPARE(m_dock->tabs()->tabText(1), QStringLiteral("Verification (%1)").arg(m_runner->result().findings.size()));

    // Switched off during a run: the run counted time exactly, it is abandoned.
    m_runner->start();
    QVERIFY(m_runner->isRunning());
    QSignalSpy cancelled(m_runner, &VerificationRunner::cancelled);
    exact->setChecked(false);
    QVERIFY(!m_runner->isRunning());
    QCOMPARE(cancelled.size(), 1);
    QVERIFY(m_runner->wasCancelled());
    QVERIFY(m_runner->timeCountingDiffers());
    QVERIFY(panel->statusLabel()->text().contains(QStringLiteral("Exact time switched off since verification")));
    QVERIFY(m_window->statusBar()->currentMessage().contains(QStringLiteral("Exact Time changed")));
    // Back as the findings were computed: they match again.
    exact->setChecked(true);
    QVERIFY(!m_runner->assumptionsDiffer());
    exact->setChecked(false);
}

// Simulation > Verify with the Machine explores the program with the model's
// machine: two limit switches of one cylinder are TRUE together for arbitrary
// sensors, never with the machine. Offered only while the model has a machine.
void TestVerification::withMachineFromTheMenu()
{
    auto* withMachine = m_window->findChild<QAction*>(QStringLiteral("verifyWithMachineAction"));
    QVERIFY(withMachine && withMachine->isCheckable());
    loadFaultyExample(); // no machine
    QVERIFY(!withMachine->isEnabled());

    const core::LoadedModel loaded = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    QVERIFY(loaded.model && !loaded.model->machine().empty());
    m_window->document()->replaceModel(*loaded.model, QString(), core::ModelFormat::Native);
    QVERIFY(withMachine->isEnabled());
    QVERIFY(m_window->document()->modelForCommands().addProperty({"never Clamped AND Unclamped", ""}).ok);
    const std::size_t property = m_window->document()->model().properties().size() - 1;
    verifyAndWait();
    QVERIFY(!m_runner->resultClosedLoop());
    QVERIFY(!m_runner->result().propertyHolds.at(property)); // any sensors: both switches at once

    VerificationPanel* panel = m_dock->verificationPanel();
    QSignalSpy assumptionsChanged(m_runner, &VerificationRunner::assumptionsChanged);
    withMachine->setChecked(true);
    QCOMPARE(assumptionsChanged.size(), 1);
    QVERIFY(m_runner->machineUseDiffers());
    QVERIFY(!m_runner->isStale());
    QVERIFY(panel->statusLabel()->text().contains(QStringLiteral("The machine is used since verification")));
    verifyAndWait();
    QVERIFY(m_runner->resultClosedLoop());
    QVERIFY(!m_runner->assumptionsDiffer());
    QVERIFY(m_runner->result().propertyHolds.at(property));
    QVERIFY(panel->assumptionsLabel()->text().endsWith(QStringLiteral("With the machine")));

    // Editing the machine makes the findings stale, as any edit of the model.
    Document* document = m_window->document();
    document->undoStack()->push(new RemoveMachineComponentCommand(*document, document->model().machine().components.size() - 1));
    QVERIFY(m_runner->isStale());
    document->undoStack()->undo();
    withMachine->setChecked(false);
    QVERIFY(m_runner->machineUseDiffers());
}

// Simulation > Verify with Single Faults, offered only while verifying with
// the machine: the clamp's two switches, never TRUE together with the
// machine, are under a single fault (Clamped stuck TRUE).
void TestVerification::singleFaultsFromTheMenu()
{
    auto* withMachine = m_window->findChild<QAction*>(QStringLiteral("verifyWithMachineAction"));
    auto* singleFaults = m_window->findChild<QAction*>(QStringLiteral("verifySingleFaultsAction"));
    QVERIFY(withMachine && singleFaults && singleFaults->isCheckable());
    loadFaultyExample(); // no machine
    QVERIFY(!singleFaults->isEnabled());

    const core::LoadedModel loaded = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    QVERIFY(loaded.model && !loaded.model->machine().empty());
    m_window->document()->replaceModel(*loaded.model, QString(), core::ModelFormat::Native);
    QVERIFY(withMachine->isEnabled());
    QVERIFY(!singleFaults->isEnabled()); // not verifying with the machine yet
    withMachine->setChecked(true);
    QVERIFY(singleFaults->isEnabled());
    QVERIFY(m_window->document()->modelForCommands().addProperty({"never Clamped AND Unclamped", ""}).ok);
    const std::size_t property = m_window->document()->model().properties().size() - 1;
    verifyAndWait();
    QVERIFY(m_runner->resultClosedLoop());
    QVERIFY(!m_runner->resultSingleFaults());
    QVERIFY(m_runner->result().propertyHolds.at(property));

    VerificationPanel* panel = m_dock->verificationPanel();
    QSignalSpy assumptionsChanged(m_runner, &VerificationRunner::assumptionsChanged);
    singleFaults->setChecked(true);
    QCOMPARE(assumptionsChanged.size(), 1);
    QVERIFY(m_runner->faultUseDiffers());
    QVERIFY(panel->statusLabel()->text().contains(QStringLiteral("Single faults switched on")));
    verifyAndWait();
    QVERIFY(m_runner->resultSingleFaults());
    QVERIFY(!m_runner->assumptionsDiffer());
    QVERIFY(m_runner->result().faultChoices > 0);
    QCOMPARE(m_runner->result().propertyVerdicts.at(property).outcome, core::PropertyOutcome::Violated);
    QVERIFY(panel->assumptionsLabel()->text().endsWith(QStringLiteral("Single faults")));

    // `faulted` outside such a run: the Properties panel's wording of GP007.
    const std::vector<core::PropertyProblem> problems
        = core::checkProperty(m_window->document()->model(), "never faulted AND in F1");
    QCOMPARE(problems.size(), std::size_t(1));
    QCOMPARE(editor::propertyProblemText(problems.front()),
             QStringLiteral("'faulted' is only defined when verifying with single faults (Simulation > Verify with "
                            "Single Faults, with the machine)"));

    // Without the machine, single faults are not offered and change nothing.
    withMachine->setChecked(false);
    QVERIFY(!singleFaults->isEnabled());
    QVERIFY(!m_runner->nextRunSingleFaults());
    singleFaults->setChecked(false);
}

// The Properties panel checks a property as the next run will: `faulted`
// is GP007 there unless that run has single faults.
void TestVerification::faultedIsAWordOfPropertiesWithSingleFaults()
{
    auto* withMachine = m_window->findChild<QAction*>(QStringLiteral("verifyWithMachineAction"));
    auto* singleFaults = m_window->findChild<QAction*>(QStringLiteral("verifySingleFaultsAction"));
    const core::LoadedModel loaded = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    QVERIFY(loaded.model);
    m_window->document()->replaceModel(*loaded.model, QString(), core::ModelFormat::Native);
    QVERIFY(m_window->document()->modelForCommands().addProperty({"never 2s/faulted AND in F1", ""}).ok);
    PropertiesTableModel* table = m_dock->propertiesPanel()->tableModel();
    table->reload();
    const int row = table->loadedRows() - 1;
    QCOMPARE(table->problems(row).size(), std::size_t(1));
    QCOMPARE(table->problems(row).front().code, std::string("GP007"));

    withMachine->setChecked(true);
    QCOMPARE(table->problems(row).size(), std::size_t(1)); // with the machine, still no faults
    singleFaults->setChecked(true);
    QVERIFY(table->problems(row).empty());
    withMachine->setChecked(false); // the next run has no faults again
    QCOMPARE(table->problems(row).size(), std::size_t(1));
    singleFaults->setChecked(false);
}

void TestVerification::propertyFindingsShowTheirText()
{
    loadFaultyExample();
    const QString violated = QStringLiteral("never in F2 AND Clamped");
    const QString holds = QStringLiteral("never DrillDown AND DrillUp");
    const QString unusable = QStringLiteral("never NoSuchInput");
    for (const QString& text : {violated, holds, unusable})
        QVERIFY(m_window->document()->modelForCommands().addProperty({text.toStdString(), ""}).ok);
    verifyAndWait();
    VerificationPanel* panel = m_dock->verificationPanel();
    const std::vector<std::pair<QString, QString>> expected{
        {QStringLiteral("GV120"), violated}, {QStringLiteral("GV121"), holds}, {QStringLiteral("GV122"), unusable}};
    for (const auto& [code, text] : expected) {
        QTreeWidgetItem* found = nullptr;
        for (QTreeWidgetItemIterator it(panel->view()); *it; ++it) {
            if ((*it)->text(VerificationPanel::CodeColumn) == code)
                found = *it;
        }
        QVERIFY2(found, qPrintable(code));
        QVERIFY(!found->parent());
        QCOMPARE(found->text(VerificationPanel::ElementColumn), text);
        QVERIFY2(found->text(VerificationPanel::MessageColumn).contains(QStringLiteral("'%1'").arg(text)),
                 qPrintable(found->text(VerificationPanel::MessageColumn)));
        panel->view()->setCurrentItem(found);
        QVERIFY(!panel->showOnChartAction()->isEnabled());
        const ElementRef before = m_window->selection()->current();
        panel->showOnChart(found);
        QCOMPARE(m_window->selection()->current(), before);
        if (code == QStringLiteral("GV120"))
            QVERIFY(panel->replayAction()->isEnabled()); // its counterexample
    }
}

// Replay in Simulator of a nested finding reaches its situation on both
// layers and ends with the nested GRAFCET's tab in front.
void TestVerification::replayOfANestedFindingShowsItsGrafcet()
{
    loadFaultyExample();
    verifyAndWait();
    VerificationPanel* panel = m_dock->verificationPanel();
    QTreeWidgetItem* together = row(QStringLiteral("GV114"), QStringLiteral("F2/T1"));
    QVERIFY(together);
    const core::VerificationFinding* finding = m_runner->finding(VerificationPanel::findingIndex(together));
    QVERIFY(finding && finding->counterexample && finding->counterexample->confirmed);
    QCOMPARE(finding->gemmaStep, std::string("F2"));

    panel->view()->setCurrentItem(together);
    QVERIFY(panel->replayAction()->isEnabled());
    panel->replayAction()->trigger();
    SimulationSession* session = m_window->simulationSession();
    QVERIFY(session->isReplaying());
    GrafcetView* f2 = m_window->grafcetView(QStringLiteral("F2"));
    QVERIFY2(f2, "the replay opens F2's nested GRAFCET");
    QCOMPARE(m_window->centralTabs()->currentWidget(), f2);
    // The user looks at the GEMMA chart meanwhile: the end of the replay brings the tab back.
    m_window->centralTabs()->setCurrentIndex(0);
    m_window->findChild<QAction*>(QStringLiteral("runSimulationAction"))->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(session->replayState(), SimulationSession::ReplayState::Finished, 20000);
    QVERIFY(session->replayFailures().empty()); // the expectations on both layers held
    QCOMPARE(session->simulator()->scanCount(), finding->counterexample->scans);
    QCOMPARE(QString::fromStdString(session->simulator()->activeStepId()), QStringLiteral("F2"));
    QCOMPARE(m_window->centralTabs()->currentWidget(), f2);

    // A GEMMA-layer finding's replay leaves the tabs as they are.
    QTreeWidgetItem* stuck = row(QStringLiteral("GV106"), QStringLiteral("A6"));
    QVERIFY(stuck);
    m_window->centralTabs()->setCurrentIndex(0);
    panel->view()->setCurrentItem(stuck);
    panel->replayAction()->trigger();
    m_window->findChild<QAction*>(QStringLiteral("runSimulationAction"))->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(session->replayState(), SimulationSession::ReplayState::Finished, 20000);
    QCOMPARE(m_window->centralTabs()->currentIndex(), 0);
}

// Each code of the exploration of both layers, with the arguments
// bothlayers.cpp gives it, is worded in the UI language: not the English
// fallback, naming its arguments, and an unconfirmed one says so.
void TestVerification::everyBothLayersCodeIsWorded()
{
    namespace gv = core::verification;
    struct Shape {
        const char* code;
        std::vector<std::string> elements;
        std::vector<std::string> arguments;
        int property = -1;
    };
    const std::vector<Shape> shapes{
        {gv::kIncomplete, {"model"}, {"model"}},
        {gv::kUnreachableStep, {"F1", "F2->F1"}, {}}, // the arguments left to the elements
        {gv::kDeadTransition, {"F2->F1"}, {}},
        {gv::kNestedStepNeverActive, {"F1/5"}, {"F1", "5"}},
        {gv::kNestedTransitionDead, {"F1/T3"}, {"F1", "3"}},
        {gv::kUnsafeNestedStep, {"F1/3"}, {"F1", "3"}},
        {gv::kUnstableReachable, {"F1"}, {"F1"}},
        {gv::kBranchesTogether, {"F1/T1", "F1/T2"}, {"F1", "1", "1", "2"}},
        {gv::kNeverComplete, {"F1", "F1->A2"}, {"F1", "F1->A2"}},
        {gv::kNeverComplete, {"F1"}, {"F1"}},
        {gv::kWaitsForNoComplete, {"F1->A2"}, {"F1->A2", "F1"}},
        {gv::kStoredRace, {"F1/2", "F1/3"}, {"F1", "2", "3", "Counter"}},
        {gv::kOutputOnEmergencyStop, {"D1"}, {"D1", "DrillDown"}},
        {gv::kStoredOutputOnEmergencyStop, {"D1"}, {"D1", "Marker"}},
        {gv::kPropertyViolated, {}, {"never A AND B"}, 0},
        {gv::kPropertyHolds, {}, {"never A AND B"}, 0},
        {gv::kPropertyUnusable, {}, {"never A AND", "column 12: expected an operand"}, 0},
        {gv::kPropertyUnusable, {}, {"", ""}, 0},
        {gv::kPropertyUndecided, {}, {"never Count > 2", "no violation found in 12 states"}, 0},
    };
    for (const Shape& shape : shapes) {
        core::VerificationFinding finding;
        finding.code = shape.code;
        finding.elements = shape.elements;
        finding.arguments = shape.arguments;
        finding.property = shape.property;
        finding.message = "untranslated";
        const QString text = verificationText(finding);
        QVERIFY2(!text.isEmpty() && text != QStringLiteral("Untranslated"), shape.code);
        for (const std::string& argument : shape.arguments.empty() ? shape.elements : shape.arguments) {
            const QString named = QString::fromStdString(argument).contains(QStringLiteral("->"))
                ? transitionLabel(QString::fromStdString(argument))
                : QString::fromStdString(argument);
            if (shape.code != std::string(gv::kIncomplete))
                QVERIFY2(text.contains(named), qPrintable(shape.code + QStringLiteral(": ") + text));
        }
        QVERIFY2(!text.contains(QStringLiteral("->")), qPrintable(text));
    }
    // An unconfirmed nested claim says so.
    core::VerificationFinding unconfirmed;
    unconfirmed.code = gv::kUnsafeNestedStep;
    unconfirmed.severity = core::Severity::Info;
    unconfirmed.gemmaStep = "F1";
    unconfirmed.elements = {"F1/3"};
    unconfirmed.arguments = {"F1", "3"};
    unconfirmed.origin = core::FindingOrigin::BothLayers;
    unconfirmed.counterexample = core::Counterexample{};
    QVERIFY(verificationText(unconfirmed).contains(QStringLiteral("Not confirmed")));
    unconfirmed.counterexample->confirmed = true;
    unconfirmed.severity = core::Severity::Warning;
    QVERIFY(!verificationText(unconfirmed).contains(QStringLiteral("Not confirmed")));
    // A GEMMA-layer claim kept when both layers were explored says on which layer.
    core::VerificationFinding kept;
    kept.code = gv::kAlwaysTrue;
    kept.severity = core::Severity::Warning;
    kept.elements = {"F1->A2", "F1->A3"};
    kept.arguments = {"F1->A2", "F1->A3"};
    kept.origin = core::FindingOrigin::GemmaLayerKept;
    kept.counterexample = core::Counterexample{};
    QVERIFY(verificationText(kept).contains(QStringLiteral("decided on the GEMMA layer")));
    kept.counterexample->confirmed = true;
    QVERIFY(!verificationText(kept).contains(QStringLiteral("Not confirmed")));
}

// A step with a nested GRAFCET takes its Complete from it: the verification
// ignores any assumption about it, so the tab must not claim one.
void TestVerification::stepsWithAGrafcetAreNeverAssumedAutomatic()
{
    loadFaultyExample();
    SimulationSession* session = m_window->simulationSession();
    session->setActive(true); // every Complete automatic in the Simulation dock
    const core::Model& model = m_window->document()->model();
    QVERIFY(model.effectiveGrafcet("F2"));
    for (const QString& step : m_runner->assumedAutomatic())
        QVERIFY2(!model.effectiveGrafcet(step.toStdString()), qPrintable(step));
    QVERIFY(!m_runner->assumedAutomatic().contains(QStringLiteral("F2")));
    session->setActive(false);
}

// A property of 50,000 letters, with a comment of five million: the tables,
// the messages quoting it and their tooltips show a bounded start of it
// (laying out megabytes froze the window), and no panel grows wider than
// the window (the problem under the editor was as wide as the name).
void TestVerification::longPropertyIsCutAndNeverWidensTheWindow()
{
    const int windowWidth = m_window->width();
    Document* document = m_window->document();
    const QString ghost = QStringLiteral("Ghost") + QString(50000, QLatin1Char('x'));
    const QString property = QStringLiteral("never ") + ghost;
    const QString comment(5000000, QLatin1Char('c'));
    QVERIFY(document->push(new AddPropertyCommand(*document, {property.toStdString(), comment.toStdString()}, 0)));
    m_dock->show();
    m_dock->raise();
    m_dock->showProperties();
    auto* panel = m_dock->findChild<PropertiesPanel*>(QStringLiteral("propertiesPanel"));
    QVERIFY(panel);
    panel->setCurrentRow(0);
    panel->view()->viewport()->repaint();
    QApplication::processEvents();

    const auto bounded = [](const QString& text, qsizetype limit) {
        return text.size() <= limit + 1 && !text.isEmpty();
    };
    PropertiesTableModel* table = panel->tableModel();
    QCOMPARE(table->index(0, PropertiesTableModel::TextColumn).data(Qt::EditRole).toString(), property);
    QVERIFY(bounded(table->index(0, PropertiesTableModel::TextColumn).data().toString(), kShownTextLimit));
    QVERIFY(bounded(table->index(0, PropertiesTableModel::CommentColumn).data().toString(), kShownTextLimit));
    QVERIFY(table->index(0, PropertiesTableModel::TextColumn).data().toString().endsWith(QChar(0x2026)));
    QVERIFY(bounded(table->index(0, PropertiesTableModel::TextColumn).data(Qt::ToolTipRole).toString(),
                    kToolTipTextLimit + kToolTipTextLimit / 50));
    auto* problem = panel->findChild<WrappingLabel*>(QStringLiteral("propertyProblem"));
    QVERIFY(problem && problem->isVisibleTo(panel));
    QVERIFY2(bounded(problem->text(), 2 * kShownTextLimit), qPrintable(problem->text().left(100)));
    QVERIFY(m_window->minimumSizeHint().width() <= windowWidth);
    QCOMPARE(m_window->width(), windowWidth);
    QVERIFY(m_dock->width() <= windowWidth);

    // The finding about it quotes its start.
    verifyAndWait();
    m_dock->showVerification();
    QTreeWidgetItem* found = nullptr;
    for (QTreeWidgetItemIterator it(m_dock->verificationPanel()->view()); *it && !found; ++it) {
        const core::VerificationFinding* finding = m_runner->finding(VerificationPanel::findingIndex(*it));
        if (finding && finding->property == 0)
            found = *it;
    }
    QVERIFY(found);
    for (int column : {int(VerificationPanel::ElementColumn), int(VerificationPanel::MessageColumn)}) {
        QVERIFY2(bounded(found->text(column), 3 * kShownTextLimit), // quotes the property and why
                 qPrintable(QString::number(found->text(column).size()) + QStringLiteral(": ")
                            + found->text(column).left(400)));
        QVERIFY(bounded(found->toolTip(column), kToolTipTextLimit + kToolTipTextLimit / 50));
    }
    m_dock->verificationPanel()->view()->viewport()->repaint();
    QApplication::processEvents();
    QVERIFY(m_window->minimumSizeHint().width() <= windowWidth);
    QCOMPARE(m_window->width(), windowWidth);
}

// PartCount only grows, but numeric memories are abstracted: the verifier can
// neither prove "never PartCount < 0" nor find a run breaking it. The panel and
// the status bar say undecided, never that every property holds.
void TestVerification::undecidedPropertyIsNeverCalledHolding()
{
    const core::LoadedModel loaded = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    QVERIFY(loaded.model);
    m_window->document()->replaceModel(*loaded.model, QString(), core::ModelFormat::Native);
    QVERIFY(m_window->document()->modelForCommands().addProperty({"never PartCount < 0", ""}).ok);
    verifyAndWait();
    const core::VerificationResult& result = m_runner->result();
    QVERIFY(!result.violated());
    QVERIFY(result.undecided());
    bool listed = false;
    for (QTreeWidgetItemIterator it(m_dock->verificationPanel()->view()); *it; ++it)
        listed = listed
            || ((*it)->text(VerificationPanel::CodeColumn) == QStringLiteral("GV123")
                && (*it)->text(VerificationPanel::ElementColumn) == QStringLiteral("never PartCount < 0"));
    QVERIFY2(listed, "the undecided property is listed as GV123");
    const QString status = m_dock->verificationPanel()->statusLabel()->text();
    QVERIFY2(status.contains(QStringLiteral("undecided")), qPrintable(status));
    QVERIFY2(!status.contains(QStringLiteral("Every property holds")), qPrintable(status));
    const QString bar = m_window->statusBar()->currentMessage();
    QVERIFY2(bar.contains(QStringLiteral("undecided")), qPrintable(bar));
}

QTEST_MAIN(TestVerification)
#include "test_verification.moc"

