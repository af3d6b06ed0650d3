// Verify in the editor: the action runs the verifier in a worker thread, the
// findings go to the Problems dock's Verification category, Show on Chart
// selects the element, Replay in Simulator plays the counterexample to the
// state it claims, and a change of the model marks the findings stale. The
// Complete modes of the Simulation dock decide which nested steps are
// verified with Complete automatic, and the panel says which.

#include "modelfactory.h"

#include "editortestsupport.h"

#include "editor/statusindicators.h"
#include "editor/secondarytext.h"
#include "editor/commands/setconditioncommand.h"
#include "editor/diagnostictext.h"
#include "editor/docks/elementlabels.h"
#include "editor/docks/problemsdock.h"
#include "editor/docks/verificationpanel.h"
#include "editor/document.h"
#include "editor/languages.h"
#include "editor/mainwindow.h"
#include "editor/selection.h"
#include "editor/simulation/simulationdock.h"
#include "editor/simulation/simulationsession.h"
#include "editor/verificationrunner.h"

#include <QToolButton>
#include <QAction>
#include <QComboBox>
#include <QApplication>
#include <QLabel>
#include <QSettings>
#include <QStatusBar>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>
#include <QUndoStack>

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
    void completeSettingChangeCancelsARunningVerification();
    void everyCodeHasATemplate();

private:
    void verifyAndWait();
    QTreeWidgetItem* row(const QString& code, const QString& element) const;
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

QTreeWidgetItem* TestVerification::row(const QString& code, const QString& element) const
{
    QTreeWidget* view = m_dock->verificationPanel()->view();
    for (int i = 0; i < view->topLevelItemCount(); ++i) {
        QTreeWidgetItem* item = view->topLevelItem(i);
        const core::VerificationFinding* finding = m_runner->finding(VerificationPanel::findingIndex(item));
        if (item->text(VerificationPanel::CodeColumn) == code && finding && !finding->elements.empty()
            && QString::fromStdString(finding->elements.front()) == element)
            return item;
    }
    return nullptr;
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

    // The simulation starts with every Complete automatic: the findings no
    // longer match what Verify would assume, yet their scenarios still replay.
    SimulationSession* session = m_window->simulationSession();
    QSignalSpy assumptionsChanged(m_runner, &VerificationRunner::assumptionsChanged);
    session->setActive(true);
    QCOMPARE(assumptionsChanged.size(), 1);
    QCOMPARE(m_runner->assumedAutomatic(), QStringList({"A7", "F1", "F4"}));
    QVERIFY(m_runner->assumptionsDiffer());
    QVERIFY(!m_runner->isStale());
    QVERIFY(panel->statusLabel()->text().contains(QStringLiteral("Complete settings changed since verification")));
    QCOMPARE(panel->assumptionsLabel()->text(), QStringLiteral("All Complete outputs free")); // the findings'
    QCOMPARE(m_dock->tabs()->tabText(1), QStringLiteral("Verification (outdated)"));
    QTreeWidgetItem* first = panel->view()->topLevelItem(0);
    QVERIFY(first);
    QCOMPARE(first->foreground(VerificationPanel::MessageColumn).color(),
             secondaryTextColor(panel->palette(), QPalette::Base));
    panel->view()->setCurrentItem(first);
    QVERIFY(panel->replayAction()->isEnabled());

    // Manual everywhere is free everywhere: the findings match again. Playing
    // an input changes no assumption.
    for (const QString& step : {QStringLiteral("A7"), QStringLiteral("F1"), QStringLiteral("F4")})
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

    // Leaving the simulation: every Complete free again.
    session->setActive(false);
    QVERIFY(m_runner->assumedAutomatic().isEmpty());
    QVERIFY(m_runner->assumptionsDiffer());
    verifyAndWait();
    QVERIFY(!deadF1F4());
    QCOMPARE(panel->assumptionsLabel()->text(), QStringLiteral("All Complete outputs free"));
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
    QVERIFY(m_window->statusBar()->currentMessage().contains(QStringLiteral("Complete settings changed")));
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
    // A code the editor does not know keeps the core's English message.
    core::VerificationFinding unknown;
    unknown.code = "GV999";
    unknown.message = "something new about F1->A2";
    QCOMPARE(verificationText(unknown), QStringLiteral("Something new about F1 → A2"));
}

QTEST_MAIN(TestVerification)
#include "test_verification.moc"
