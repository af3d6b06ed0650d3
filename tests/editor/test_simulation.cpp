// The editor's simulation mode: the editing lock, the chart marks, the
// Simulation dock's inputs, Complete, explanation and trace, recording and
// replaying scenarios, and the batching that keeps 1,000 scans/s at one UI
// update per frame.

#include "modelfactory.h"

#include "editortestsupport.h"

#include "editor/app/languages.h"
#include "editor/chart/gemma/chartscene.h"
#include "editor/chart/gemma/stepitem.h"
#include "editor/chart/gemma/transitionitem.h"
#include "editor/commands/setconditioncommand.h"
#include "editor/document.h"
#include "editor/mainwindow.h"
#include "editor/simulation/simulationdock.h"
#include "editor/simulation/simulationsession.h"
#include "editor/simulation/simulationtext.h"
#include "editor/simulation/tracetablemodel.h"
#include "editor/simulation/valuecolours.h"
#include "editor/style/secondarytext.h"
#include "editor/text/elementlabels.h"
#include "editor/window/statusindicators.h"

#include "core/condition/conditionevaluator.h"
#include "core/formats/modelfiles.h"
#include "core/machine/closedloopscenario.h"
#include "core/machine/machineloop.h"
#include "core/simulation/scenario.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QFileDialog>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTabWidget>
#include <QToolButton>
#include <QTableView>
#include <QTemporaryDir>
#include <QRegularExpression>
#include <QTest>
#include <QTimer>
#include <QTreeWidget>
#include <QUndoStack>

#include <functional>
#include <memory>
#include <set>

#include <sys/stat.h>

using namespace editor;

namespace {

bool boolValue(const core::Simulator& simulator, const char* name)
{
    return core::cond::isTrue(simulator.variable(name));
}

// Every text of the explanation view, reasons included.
QStringList explanationTexts(const QTreeWidget& view)
{
    QStringList texts;
    for (int i = 0; i < view.topLevelItemCount(); ++i) {
        const QTreeWidgetItem* item = view.topLevelItem(i);
        texts << item->text(0) + QStringLiteral(" | ") + item->text(1);
        for (int j = 0; j < item->childCount(); ++j)
            texts << item->child(j)->text(0);
    }
    return texts;
}

// Every text of the explanation view at any depth (a nested GRAFCET's
// reasons are two levels down), "text | status" where there is a status.
QStringList allExplanationTexts(const QTreeWidget& view)
{
    QStringList texts;
    const std::function<void(const QTreeWidgetItem*)> walk = [&](const QTreeWidgetItem* item) {
        texts << (item->text(1).isEmpty() ? item->text(0) : item->text(0) + QStringLiteral(" | ") + item->text(1));
        for (int i = 0; i < item->childCount(); ++i)
            walk(item->child(i));
    };
    for (int i = 0; i < view.topLevelItemCount(); ++i)
        walk(view.topLevelItem(i));
    return texts;
}

bool anyContains(const QStringList& texts, const QString& part)
{
    for (const QString& text : texts) {
        if (text.contains(part))
            return true;
    }
    return false;
}

} // namespace

class TestSimulation : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();

    void simulationLocksEditing();
    void windowLocksEditingWidgets();
    void changingTheModelEndsTheSimulation();
    void inputsMoveTheActiveStepOnTheChart();
    void momentaryPressIsTrueThenFalse();
    void trueAndFalseAreToldApartByColour();
    void outputsAreShownNotSet();
    void manualCompleteHoldsAMacroStep();
    void explanationNamesTheReasons();
    void explanationIsInTheUiLanguage();
    void nestedExplanationShowsTheGrafcet();
    void nestedExplanationIsInTheUiLanguage();
    void replayFailuresAreInTheUiLanguage();
    void scenarioErrorsAreInTheUiLanguage();
    void unusableConditionIsInTheUiLanguage();
    void divisionByZeroStopsTheRunAndSaysWhere();
    void traceTableHasOneRowPerScan();
    void recordedSessionReplaysWithEveryExpectationMet();
    void recordingNeverReplacesAFifo();
    void recordedNestedSessionReplays();
    void replayShowsFailedExpectations();
    void thousandScansPerSecondRunInBatches();
    void stepBackShowsThePastScan();
    void playingFromAPastScanDropsTheLaterHistory();
    void historyIsBounded();
    void replayStartsPausedAtScanZero();
    void replayFromTheDockStartsPaused();
    void steppingBackInAReplayReplaysFromThere();
    void scenarioTabHasNoEmptyFailureBox();
    void languageChangeKeepsTheSimulation();

private:
    void startOnRealisticModel();
    void startOnDrillingCell();
    void openWindow();
    void reopenInFrench();
    void click(const QString& variable);
    void scan(int count = 1);
    void clickButton(const char* objectName, int times = 1);
    QString writeScenario(const char* name, const char* text);

    QTemporaryDir m_settingsDir;
    QTemporaryDir m_files;
    std::unique_ptr<Translators> m_translators;
    std::unique_ptr<MainWindow> m_window;
    SimulationSession* m_session = nullptr;
    SimulationDock* m_dock = nullptr;
};

void TestSimulation::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    QVERIFY(m_files.isValid());
    editortest::useTestSettings(m_settingsDir.path(), QStringLiteral("test_simulation"));
}

void TestSimulation::init()
{
    m_translators = std::make_unique<Translators>();
    m_translators->setLanguage(QStringLiteral("en"));
    openWindow();
}

// The window in the translators' language, shown, with its session and dock.
void TestSimulation::openWindow()
{
    m_window = editortest::showMainWindow(*m_translators);
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    m_session = m_window->simulationSession();
    m_dock = m_window->findChild<SimulationDock*>(QStringLiteral("simulationDock"));
    QVERIFY(m_session);
    QVERIFY(m_dock);
}

void TestSimulation::cleanup()
{
    if (m_window)
        m_window->document()->undoStack()->setClean(); // no "save changes?" on close
    m_window.reset();
    m_translators.reset();
}

void TestSimulation::startOnRealisticModel()
{
    m_window->document()->replaceModel(factory::realisticModel(), QString(), core::ModelFormat::Native);
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    QVERIFY(m_session->isActive());
    QCOMPARE(m_window->chartScene()->activeStep(), QStringLiteral("A6"));
}

// The shipped example with nested GRAFCETs (A1 initial; F2 warms up, F1 drills).
void TestSimulation::startOnDrillingCell()
{
    const core::LoadedModel loaded = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    QVERIFY(loaded.model);
    // In open loop, the sensors set by hand: the machine taken out
    // (test_machinesimulation.cpp plays the example closed loop).
    QVERIFY(loaded.model->setMachine({}).ok);
    m_window->document()->replaceModel(*loaded.model, QString(), core::ModelFormat::Native);
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    QVERIFY(m_session->isActive());
    QCOMPARE(m_window->chartScene()->activeStep(), QStringLiteral("A1"));
}

// A new window in French, as if the user had started GG Studio in French.
void TestSimulation::reopenInFrench()
{
    m_window->document()->undoStack()->setClean();
    m_window.reset();
    QVERIFY(m_translators->setLanguage(QStringLiteral("fr")));
    openWindow();
}

void TestSimulation::click(const QString& variable)
{
    QAbstractButton* toggle = m_dock->toggleButton(variable);
    QVERIFY2(toggle, qPrintable(variable));
    QTest::mouseClick(toggle, Qt::LeftButton);
}

void TestSimulation::scan(int count)
{
    auto* button = m_dock->findChild<QAbstractButton*>(QStringLiteral("stepButton"));
    QVERIFY(button);
    for (int i = 0; i < count; ++i)
        QTest::mouseClick(button, Qt::LeftButton);
}

void TestSimulation::clickButton(const char* objectName, int times)
{
    auto* button = m_dock->findChild<QAbstractButton*>(QLatin1String(objectName));
    QVERIFY2(button, objectName);
    for (int i = 0; i < times; ++i)
        QTest::mouseClick(button, Qt::LeftButton);
}

QString TestSimulation::writeScenario(const char* name, const char* text)
{
    const QString path = m_files.filePath(QLatin1String(name));
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return {};
    file.write(text);
    return path;
}

void TestSimulation::simulationLocksEditing()
{
    Document document;
    SimulationSession session(&document);
    QSignalSpy failures(&document, &Document::editFailed);

    session.setActive(true);
    QVERIFY(document.isReadOnly());
    QVERIFY(!document.push(new SetConditionCommand(document, QStringLiteral("A6->A1"), QStringLiteral("TRUE"))));
    QCOMPARE(failures.size(), 1);
    QCOMPARE(failures.first().first().toString(), QStringLiteral("Stop the simulation to edit the model"));
    QCOMPARE(document.model().transition("A6->A1")->condition, std::string());
    QCOMPARE(document.undoStack()->count(), 0);

    session.setActive(false);
    QVERIFY(!document.isReadOnly());
    QVERIFY(document.push(new SetConditionCommand(document, QStringLiteral("A6->A1"), QStringLiteral("TRUE"))));
    QCOMPARE(document.model().transition("A6->A1")->condition, std::string("TRUE"));
}

void TestSimulation::windowLocksEditingWidgets()
{
    Document* document = m_window->document();
    QVERIFY(document->push(new SetConditionCommand(*document, QStringLiteral("A6->A1"), QStringLiteral("TRUE"))));
    auto* simulate = m_window->findChild<QAction*>(QStringLiteral("simulateAction"));
    auto* undo = m_window->findChild<QAction*>(QStringLiteral("undoAction"));
    auto* settings = m_window->findChild<QAction*>(QStringLiteral("modelSettingsAction"));
    auto* stepDock = m_window->findChild<QDockWidget*>(QStringLiteral("stepDock"));
    auto* variablesDock = m_window->findChild<QDockWidget*>(QStringLiteral("variablesDock"));
    QVERIFY(simulate && undo && settings && stepDock && variablesDock);
    QCOMPARE(simulate->shortcut(), QKeySequence(Qt::Key_F5));
    QVERIFY(undo->isEnabled());

    simulate->trigger();
    QVERIFY(simulate->isChecked());
    QVERIFY(document->isReadOnly());
    QVERIFY(!undo->isEnabled());
    QVERIFY(!settings->isEnabled());
    QVERIFY(!stepDock->widget()->isEnabled());
    QVERIFY(!variablesDock->widget()->isEnabled());
    QVERIFY(m_dock->isVisible());
    auto* indicator = m_window->findChild<StatusBadge*>(QStringLiteral("simulationIndicator"));
    QVERIFY(indicator && indicator->isVisible());
    // On its badge, in the padding before the text.
    const QImage badge = indicator->grab().toImage();
    QCOMPARE(badge.pixelColor(3, badge.height() / 2), StatusBadge::badgeColor());

    simulate->trigger();
    QVERIFY(!simulate->isChecked());
    QVERIFY(!document->isReadOnly());
    QVERIFY(undo->isEnabled());
    QVERIFY(settings->isEnabled());
    QVERIFY(stepDock->widget()->isEnabled());
    QVERIFY(variablesDock->widget()->isEnabled());
    QVERIFY(m_window->chartScene()->activeStep().isEmpty());
}

void TestSimulation::changingTheModelEndsTheSimulation()
{
    startOnRealisticModel();
    m_window->document()->replaceModel(core::Model(), QString(), core::ModelFormat::Native);
    QVERIFY(!m_session->isActive());
    QVERIFY(!m_window->document()->isReadOnly());
    QVERIFY(!m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->isChecked());
    QVERIFY(m_window->chartScene()->activeStep().isEmpty());
}

void TestSimulation::inputsMoveTheActiveStepOnTheChart()
{
    startOnRealisticModel();
    ChartScene* scene = m_window->chartScene();
    scan();
    QCOMPARE(scene->activeStep(), QStringLiteral("A6"));
    QVERIFY(scene->firedTransition().isEmpty());

    click(QStringLiteral("HomePosition"));
    click(QStringLiteral("AirPressureOk"));
    QVERIFY(boolValue(*m_session->simulator(), "HomePosition"));
    QCOMPARE(m_dock->toggleButton(QStringLiteral("HomePosition"))->text(), QStringLiteral("TRUE"));
    scan();
    QCOMPARE(scene->activeStep(), QStringLiteral("A1"));
    QCOMPARE(scene->firedTransition(), QStringLiteral("A6->A1"));
    QVERIFY(scene->stepItem(QStringLiteral("A1"))->isActive());
    QVERIFY(!scene->stepItem(QStringLiteral("A6"))->isActive());
    QVERIFY(scene->transitionItem(QStringLiteral("A6->A1"))->isFired());

    for (const char* name : {"Start", "PreparationDone", "DoorClosed"})
        click(QString::fromLatin1(name));
    scan();
    QCOMPARE(scene->activeStep(), QStringLiteral("F1"));
    QCOMPARE(scene->firedTransition(), QStringLiteral("A1->F1"));
    QVERIFY(!scene->transitionItem(QStringLiteral("A6->A1"))->isFired());
    // F1 is a macro-step: its Complete shows on it; the tokens of its
    // transitions show on their bars (Stop's normally-closed token is set).
    QVERIFY(scene->stepItem(QStringLiteral("F1"))->completeMark().has_value());
    QVERIFY(!scene->stepItem(QStringLiteral("A1"))->completeMark().has_value());
    QCOMPARE(scene->transitionItem(QStringLiteral("F1->A2"))->tokenMarks(), QList<bool>{true});
    QCOMPARE(scene->transitionItem(QStringLiteral("F1->D2"))->tokenMarks(), QList<bool>{false});
    QVERIFY(scene->transitionItem(QStringLiteral("A6->A1"))->tokenMarks().isEmpty());

    // A number typed in its spin box reaches the simulator.
    auto* count = qobject_cast<QSpinBox*>(m_dock->valueEditor(QStringLiteral("BottleCount")));
    QVERIFY(count);
    QCOMPARE(count->maximum(), 32767);
    count->setValue(42);
    QCOMPARE(m_session->simulator()->variable("BottleCount"), core::cond::Value(std::int64_t{42}));
    QVERIFY(m_dock->statusLabel()->text().contains(QStringLiteral("Scan 3")));
}

void TestSimulation::trueAndFalseAreToldApartByColour()
{
    for (bool value : {true, false}) {
        const ValueColours colours = valueColours(value);
        QVERIFY(contrastRatio(colours.text, colours.background) >= kMinimumTextContrast);
    }
    QVERIFY(valueColours(true).background != valueColours(false).background);

    startOnRealisticModel();
    QAbstractButton* toggle = m_dock->toggleButton(QStringLiteral("Stop"));
    QVERIFY(toggle);
    const QString falseBackground = valueColours(false).background.name();
    const QString trueBackground = valueColours(true).background.name();
    QCOMPARE(toggle->text(), QStringLiteral("FALSE"));
    QVERIFY2(toggle->styleSheet().contains(falseBackground), qPrintable(toggle->styleSheet()));
    QTest::mouseClick(toggle, Qt::LeftButton);
    QCOMPARE(toggle->text(), QStringLiteral("TRUE"));
    QVERIFY2(toggle->styleSheet().contains(trueBackground), qPrintable(toggle->styleSheet()));
    // Drawn so: the button's middle has the TRUE colour.
    const QImage picture = toggle->grab().toImage();
    QCOMPARE(QColor(picture.pixel(picture.width() / 2, 2)).name(), trueBackground);
}

void TestSimulation::outputsAreShownNotSet()
{
    startOnDrillingCell();
    const core::Model& model = m_window->document()->model();
    int outputs = 0;
    for (const core::Variable& variable : model.variables()) {
        const QString name = QString::fromStdString(variable.name);
        auto* shown = m_dock->findChild<QLabel*>(QStringLiteral("shown_") + name);
        if (variable.kind == core::VariableKind::Input) {
            QVERIFY2(!shown, qPrintable(name));
            QVERIFY2(m_dock->toggleButton(name) || m_dock->valueEditor(name), qPrintable(name));
            continue;
        }
        ++outputs;
        // What the program writes has no toggle: it is shown, with its value.
        QVERIFY2(shown, qPrintable(name));
        QVERIFY(!m_dock->toggleButton(name) && !m_dock->pressButton(name) && !m_dock->valueEditor(name));
        QCOMPARE(shown->text(), QString::fromStdString(core::cond::formatValue(
                                    m_session->simulator()->variable(variable.name))));
    }
    QVERIFY(outputs >= 3);
    // The values follow the scans: start the machine; each scan the labels
    // read what the simulator holds, and some output becomes TRUE.
    QTest::mouseClick(m_dock->toggleButton(QStringLiteral("StartButton")), Qt::LeftButton);
    bool sawTrue = false;
    for (int i = 0; i < 40; ++i) {
        scan();
        for (QLabel* label : m_dock->findChildren<QLabel*>(QRegularExpression(QStringLiteral("^shown_")))) {
            const std::string name = label->objectName().mid(6).toStdString();
            QCOMPARE(label->text(), QString::fromStdString(core::cond::formatValue(m_session->simulator()->variable(name))));
            sawTrue = sawTrue || label->text() == QLatin1String("TRUE");
        }
    }
    QVERIFY(sawTrue);
}

void TestSimulation::momentaryPressIsTrueThenFalse()
{
    startOnRealisticModel();
    QAbstractButton* press = m_dock->pressButton(QStringLiteral("Stop"));
    QAbstractButton* toggle = m_dock->toggleButton(QStringLiteral("Stop"));
    QVERIFY(press && toggle);
    const core::Simulator& simulator = *m_session->simulator();

    // Held over a scan: TRUE while held, FALSE on release.
    QTest::mousePress(press, Qt::LeftButton);
    QVERIFY(boolValue(simulator, "Stop"));
    QVERIFY(toggle->isChecked());
    scan();
    QVERIFY(boolValue(simulator, "Stop"));
    QTest::mouseRelease(press, Qt::LeftButton);
    QVERIFY(!boolValue(simulator, "Stop"));
    QVERIFY(!toggle->isChecked());
    scan();

    // Released before any scan ran: the next scan still reads TRUE, then FALSE.
    QTest::mousePress(press, Qt::LeftButton);
    QTest::mouseRelease(press, Qt::LeftButton);
    QVERIFY(boolValue(simulator, "Stop"));
    scan();
    const core::ScanRecord& record = m_session->trace().back();
    QCOMPARE(record.changedInputs.size(), std::size_t{1});
    QCOMPARE(record.changedInputs.front().variable, std::string("Stop"));
    QCOMPARE(record.changedInputs.front().value, core::cond::Value(true));
    QVERIFY(!boolValue(simulator, "Stop"));
    QVERIFY(!toggle->isChecked());
}

void TestSimulation::manualCompleteHoldsAMacroStep()
{
    startOnRealisticModel();
    QComboBox* mode = m_dock->completeModeCombo(QStringLiteral("F1"));
    QCheckBox* manual = m_dock->manualCompleteCheck(QStringLiteral("F1"));
    QVERIFY(mode && manual);
    QVERIFY(!manual->isEnabled());
    mode->setCurrentIndex(1); // Manual, Complete unchecked
    QCOMPARE(m_session->simulator()->completeMode("F1"), core::CompleteMode::Manual);
    QVERIFY(manual->isEnabled());

    for (const char* name : {"HomePosition", "AirPressureOk", "Start", "PreparationDone", "DoorClosed"})
        click(QString::fromLatin1(name));
    scan(2);
    QCOMPARE(m_window->chartScene()->activeStep(), QStringLiteral("F1"));
    // F1 -> A2 (NOT Stop, with a token) is ready but waits for Complete.
    scan(20);
    QCOMPARE(m_window->chartScene()->activeStep(), QStringLiteral("F1"));
    QCOMPARE(m_window->chartScene()->stepItem(QStringLiteral("F1"))->completeMark(), std::optional<bool>(false));

    QTest::mouseClick(manual, Qt::LeftButton);
    QVERIFY(m_session->simulator()->manualComplete("F1"));
    scan();
    QCOMPARE(m_window->chartScene()->activeStep(), QStringLiteral("A2"));
    QCOMPARE(m_window->chartScene()->firedTransition(), QStringLiteral("F1->A2"));

    // In automatic mode, the same model leaves F1 by itself.
    m_session->reset();
    mode->setCurrentIndex(0);
    for (const char* name : {"HomePosition", "AirPressureOk", "Start", "PreparationDone", "DoorClosed"})
        click(QString::fromLatin1(name));
    scan(22);
    QVERIFY(m_window->chartScene()->activeStep() != QStringLiteral("F1"));
}

void TestSimulation::explanationNamesTheReasons()
{
    startOnRealisticModel();
    QTreeWidget* view = m_dock->explanationView();
    QStringList texts = explanationTexts(*view);
    QVERIFY2(anyContains(texts, QStringLiteral("HomePosition = FALSE")), qPrintable(texts.join('\n')));
    QVERIFY(anyContains(texts, QStringLiteral("condition FALSE")));

    // The explanation predicts the next scan: it follows the inputs at once.
    click(QStringLiteral("HomePosition"));
    click(QStringLiteral("AirPressureOk"));
    texts = explanationTexts(*view);
    QVERIFY2(anyContains(texts, transitionLabel(QStringLiteral("A6->A1")) + QStringLiteral(" | fires")),
             qPrintable(texts.join('\n')));

    m_dock->completeModeCombo(QStringLiteral("F1"))->setCurrentIndex(1);
    for (const char* name : {"Start", "PreparationDone", "DoorClosed"})
        click(QString::fromLatin1(name));
    scan(4);
    QCOMPARE(m_window->chartScene()->activeStep(), QStringLiteral("F1"));
    texts = explanationTexts(*view);
    QVERIFY2(anyContains(texts, QStringLiteral("waits for Complete")), qPrintable(texts.join('\n')));
    QVERIFY(anyContains(texts, QStringLiteral("F1.Complete = FALSE")));
    QVERIFY(m_dock->findChild<QLabel*>(QStringLiteral("activeStepLabel"))->text().contains(QStringLiteral("F1")));
}

void TestSimulation::explanationIsInTheUiLanguage()
{
    reopenInFrench();
    startOnRealisticModel();
    QTreeWidget* view = m_dock->explanationView();
    click(QStringLiteral("HomePosition"));
    click(QStringLiteral("AirPressureOk"));
    scan();
    QCOMPARE(m_window->chartScene()->activeStep(), QStringLiteral("A1"));

    // A1 -> F4 and A1 -> F2 both hold: the first by priority fires.
    click(QStringLiteral("VerifyMode"));
    click(QStringLiteral("Start"));
    QStringList texts = explanationTexts(*view);
    QVERIFY2(texts.contains(transitionLabel(QStringLiteral("A1->F4")) + QStringLiteral(" est franchie en premier")),
             qPrintable(texts.join('\n')));
    QVERIFY2(!anyContains(texts, QStringLiteral("fires first")), qPrintable(texts.join('\n')));

    // In F1, F1 -> D1 reads MotorOverload OR Temperature > MaxTemperature: both FALSE.
    click(QStringLiteral("VerifyMode"));
    click(QStringLiteral("PreparationDone"));
    click(QStringLiteral("DoorClosed"));
    scan();
    QCOMPARE(m_window->chartScene()->activeStep(), QStringLiteral("F1"));
    texts = explanationTexts(*view);
    const QString temperature = QString::fromStdString(
        core::cond::formatValue(m_session->simulator()->variable("Temperature")));
    const QString maximum = QString::fromStdString(
        core::cond::formatValue(m_session->simulator()->variable("MaxTemperature")));
    QVERIFY2(texts.contains(QStringLiteral("Temperature > MaxTemperature est FALSE (Temperature = %1, MaxTemperature = %2)")
                                .arg(temperature, maximum)),
             qPrintable(texts.join('\n')));
    QVERIFY(texts.contains(QStringLiteral("MotorOverload = FALSE")));
    // The entry scan resets F1's tokens: the token of NOT Stop reads FALSE.
    QVERIFY2(anyContains(texts, QStringLiteral(" = FALSE (mémoire de NOT Stop)")), qPrintable(texts.join('\n')));
    QVERIFY2(!anyContains(texts, QStringLiteral(" is FALSE")), qPrintable(texts.join('\n')));
}

void TestSimulation::nestedExplanationShowsTheGrafcet()
{
    startOnDrillingCell();
    QTreeWidget* view = m_dock->explanationView();
    // A1 has no GRAFCET: nothing nested is shown.
    QVERIFY(!anyContains(allExplanationTexts(*view), QStringLiteral("GRAFCET of")));

    click(QStringLiteral("DrillHigh"));
    click(QStringLiteral("Unclamped"));
    click(QStringLiteral("StartButton"));
    scan(); // A1 -> F2: the next scan is F2's entry scan
    QCOMPARE(m_window->chartScene()->activeStep(), QStringLiteral("F2"));
    QStringList texts = allExplanationTexts(*view);
    QVERIFY2(texts.contains(QStringLiteral("GRAFCET of F2: no step active | initialised again in the next scan (steps 1)")),
             qPrintable(texts.join('\n')));
    // Predicted on the initial situation: 1 -> 3 on DrillHigh fires, 1 -> 2 on NOT DrillHigh does not.
    QVERIFY2(texts.contains(QStringLiteral("T2 (1 → 3) | fires in the next scan")), qPrintable(texts.join('\n')));
    QVERIFY(texts.contains(QStringLiteral("T1 (1 → 2) | receptivity FALSE")));
    QVERIFY(texts.contains(QStringLiteral("DrillHigh = TRUE")));
    QVERIFY(texts.contains(QStringLiteral("T4 (3 → 4) | upstream step not active")));
    QVERIFY(texts.contains(QStringLiteral("step 3 is not active")));

    scan(2); // the entry scan (1 -> 3), then one scan in step 3
    texts = allExplanationTexts(*view);
    QVERIFY2(texts.contains(QStringLiteral("GRAFCET of F2: steps 3")), qPrintable(texts.join('\n')));
    // Its state: the timer, the outputs it drives.
    QVERIFY2(texts.contains(QStringLiteral("GG_T3_10000ms (step 3): 0 ms of 10000 ms")), qPrintable(texts.join('\n')));
    QVERIFY(anyContains(texts, QStringLiteral("Outputs: ")));
    QVERIFY(anyContains(texts, QStringLiteral("Spindle = TRUE")));
    QVERIFY2(texts.contains(QStringLiteral("10s/X3 is FALSE: step 3 active for 10 ms of 10000 ms")),
             qPrintable(texts.join('\n')));
}

void TestSimulation::nestedExplanationIsInTheUiLanguage()
{
    reopenInFrench();
    startOnDrillingCell();
    click(QStringLiteral("DrillHigh"));
    click(QStringLiteral("Unclamped"));
    click(QStringLiteral("StartButton"));
    scan(3);
    const QStringList texts = allExplanationTexts(*m_dock->explanationView());
    QVERIFY2(texts.contains(QStringLiteral("GRAFCET de F2 : étapes 3")), qPrintable(texts.join('\n')));
    QVERIFY2(texts.contains(QStringLiteral("10s/X3 est FALSE : étape 3 active depuis 10 ms sur 10000 ms")),
             qPrintable(texts.join('\n')));
    QVERIFY2(texts.contains(QStringLiteral("l'étape 1 n'est pas active")), qPrintable(texts.join('\n')));
    QVERIFY2(!anyContains(texts, QStringLiteral("not active")), qPrintable(texts.join('\n')));
    QVERIFY2(!anyContains(texts, QStringLiteral("receptivity")), qPrintable(texts.join('\n')));
}

void TestSimulation::replayFailuresAreInTheUiLanguage()
{
    reopenInFrench();
    startOnRealisticModel();
    const QString path = m_files.filePath(QStringLiteral("french.scenario"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write("at 1: set HomePosition = TRUE\n"
               "at 2: expect step A1\n"
               "at 2: expect fired A6->A1\n");
    file.close();
    QString error;
    QVERIFY2(m_session->startReplay(path, &error), qPrintable(error));
    m_session->advance(10);
    QCOMPARE(m_session->replayState(), SimulationSession::ReplayState::Finished);
    QCOMPARE(m_dock->failureList()->count(), 2);
    QCOMPARE(m_dock->failureList()->item(0)->text(),
             QStringLiteral("Ligne 2\u00a0: cycle 2\u00a0: étape A1 attendue, l'étape active est A6"));
    QCOMPARE(m_dock->failureList()->item(1)->text(),
             QStringLiteral("Ligne 3\u00a0: cycle 2\u00a0: A6->A1 devait être franchie, aucune transition ne l'a été"));
}

void TestSimulation::scenarioErrorsAreInTheUiLanguage()
{
    // In English the editor words every kind of error as the core does.
    const core::Simulator simulator(factory::realisticModel());
    const char* const lines[] = {
        "set A = TRUE", "at", "at 0: set A = TRUE", "at 99999999999999: set A = TRUE", "at 3 set", "at 3: put",
        "at 3: set = 1", "at 3: set complete", "at 3: set complete F1 TRUE", "at 3: set A TRUE", "at 3: set A = ,",
        "at 3: set complete F1 = soon", "at 3: set A = 1 B = 2", "at 3: expect", "at 3: expect step :",
        "at 3: expect fired", "at 3: expect token", "at 3: expect token T TRUE", "at 3: expect token T = yes",
        "at 3: expect variable", "at 3: expect entry", "at 3: expect fired none now", "at 1: set Nope = TRUE",
        "at 2: set BatchSize = 40000", "at 2: expect step F3", "at 2: expect step Q7", "at 3: expect fired A1->F5",
        "at 3: expect fired A1->Z1", "at 4: set complete F2 = TRUE", "at 4: expect token Start_F1_1_MEM = TRUE",
        "at 1: set HomePosition\xff = TRUE", "at 2: set HomePosition = TRUE\nat 2: set HomePosition = FALSE",
        "at 2: set complete F1 = TRUE\nat 2: set complete F1 = auto", "at 3: fault", "at 3: fault Start",
        "at 3: fault Start stuck TRUE",
    };
    std::set<core::ScenarioError::Kind> kinds;
    for (const char* line : lines) {
        const core::ScenarioParseResult parsed = core::parseScenario(line, "s.txt");
        const std::vector<core::ScenarioError> errors =
            parsed.ok() ? core::validateScenario(parsed.scenario, simulator) : parsed.errors;
        QCOMPARE(errors.size(), std::size_t{1});
        kinds.insert(errors.front().kind);
        QCOMPARE(scenarioErrorText(errors.front()), QString::fromStdString(errors.front().toString()));
    }
    QCOMPARE(kinds.size(), std::size(lines));

    // The fault lines refused by a machine (the drilling cell's).
    const core::LoadedModel cell = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    QVERIFY(cell.model);
    core::Simulator cellSimulator(*cell.model);
    const core::machine::MachineLoop loop(cellSimulator, cell.model->machine());
    const char* const faults[] = {"at 1: fault StartButton stuck TRUE", "at 1: fault ClampOut flicker",
                                  "at 1: fault Nobody jam", "at 1: fault Ready jam", "at 1: fault Nobody clear"};
    std::set<core::ScenarioError::Kind> faultKinds;
    for (const char* line : faults) {
        const core::ScenarioParseResult parsed = core::parseScenario(line, "f.txt");
        QVERIFY(parsed.ok());
        const std::vector<core::ScenarioError> errors = core::machine::validateClosedLoopScenario(parsed.scenario, loop);
        QCOMPARE(errors.size(), std::size_t{1});
        faultKinds.insert(errors.front().kind);
        QCOMPARE(scenarioErrorText(errors.front()), QString::fromStdString(errors.front().toString()));
    }
    QCOMPARE(faultKinds.size(), std::size(faults));

    // In French, a replay refuses the file with the reasons in French, the names as written.
    reopenInFrench();
    startOnRealisticModel();
    const QString path = m_files.filePath(QStringLiteral("erreurs.scenario"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write("at 1: set HomePosition TRUE\n"
               "at 2: expect\n");
    file.close();
    QString error;
    QVERIFY(!m_session->startReplay(path, &error));
    QCOMPARE(error, QStringLiteral("erreurs.scenario:1:24: '=' attendu après le nom de variable, trouvé 'TRUE'\n"
                                   "erreurs.scenario:2:13: step, fired, token, variable, entry, complete ou nested attendu "
                                   "après 'expect', trouvé la fin de la ligne"));
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write("at 1: set NoSuchInput = TRUE\n"
               "at 2: expect step Q7\n"
               "at 3: set BatchSize = 40000\n");
    file.close();
    QVERIFY(!m_session->startReplay(path, &error));
    QCOMPARE(error, QStringLiteral("erreurs.scenario:1:11: variable 'NoSuchInput' inconnue\n"
                                   "erreurs.scenario:2:19: étape 'Q7' inconnue\n"
                                   "erreurs.scenario:3:23: BatchSize est de type INT\u00a0: '40000' est hors limites "
                                   "pour INT (-32768..32767)"));
}

// The Simulation dock words a condition that does not parse as the Problems dock does.
void TestSimulation::unusableConditionIsInTheUiLanguage()
{
    reopenInFrench();
    core::Model model = factory::realisticModel();
    QVERIFY(model.setCondition("A6->A1", "HomePosition AND"));
    m_window->document()->replaceModel(std::move(model), QString(), core::ModelFormat::Native);
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    QVERIFY(m_session->isActive());
    const QStringList texts = explanationTexts(*m_dock->explanationView());
    QVERIFY2(texts.contains(QStringLiteral("Erreur de syntaxe dans la réceptivité de A6 \u2192 A1\u00a0: opérande attendu "
                                           "après 'AND'.")),
             qPrintable(texts.join('\n')));
}

// FaultCount is 0 at start: the PLC's task stops on the integer division in
// scan 1, and so does the simulation, saying where, in the UI's language;
// no later scan runs until Reset.
void TestSimulation::divisionByZeroStopsTheRunAndSaysWhere()
{
    reopenInFrench();
    core::Model model = factory::realisticModel();
    QVERIFY(model.setCondition("A6->A1", "HomePosition AND BatchSize / FaultCount > 1"));
    m_window->document()->replaceModel(std::move(model), QString(), core::ModelFormat::Native);
    m_window->findChild<QAction*>(QStringLiteral("simulateAction"))->trigger();
    QVERIFY(m_session->isActive());
    scan(3);
    QVERIFY(m_session->simulator()->fault());
    QCOMPARE(m_session->simulator()->scanCount(), std::int64_t{1});
    const QString label = m_dock->findChild<QLabel*>(QStringLiteral("activeStepLabel"))->text();
    QVERIFY2(label.contains(QStringLiteral("Arrêt au cycle 1 : division entière par zéro dans la réceptivité de "
                                           "A6 \u2192 A1 (BatchSize / FaultCount")),
             qPrintable(label));
    clickButton("resetButton", 1);
    QVERIFY(!m_session->simulator()->fault());
}

void TestSimulation::traceTableHasOneRowPerScan()
{
    startOnRealisticModel();
    TraceTableModel* model = m_dock->traceModel();
    QCOMPARE(model->rowCount(), 0);
    click(QStringLiteral("HomePosition"));
    click(QStringLiteral("AirPressureOk"));
    scan(3);
    QCOMPARE(model->rowCount(), 3);
    QCOMPARE(model->index(0, TraceTableModel::ScanColumn).data().toString(), QStringLiteral("1"));
    QCOMPARE(model->index(0, TraceTableModel::StepColumn).data().toString(), QStringLiteral("A1"));
    QCOMPARE(model->index(0, TraceTableModel::FiredColumn).data().toString(), transitionLabel(QStringLiteral("A6->A1")));
    QCOMPARE(model->index(0, TraceTableModel::EntryColumn).data().toString(), QStringLiteral("TRUE"));
    QCOMPARE(model->index(0, TraceTableModel::InputsColumn).data().toString(),
             QStringLiteral("AirPressureOk = TRUE, HomePosition = TRUE")); // declaration order
    QVERIFY(model->index(1, TraceTableModel::FiredColumn).data().toString().isEmpty());
    QVERIFY(model->index(1, TraceTableModel::InputsColumn).data().toString().isEmpty());

    // The table keeps the latest scans.
    m_session->advance(SimulationSession::kTraceCapacity + 500);
    QCOMPARE(model->rowCount(), SimulationSession::kTraceCapacity);
    QCOMPARE(model->index(0, TraceTableModel::ScanColumn).data().toString(), QStringLiteral("504"));
    QCOMPARE(model->index(model->rowCount() - 1, TraceTableModel::ScanColumn).data().toString(),
             QString::number(SimulationSession::kTraceCapacity + 503));

    m_session->reset();
    QCOMPARE(model->rowCount(), 0);
}

void TestSimulation::recordedSessionReplaysWithEveryExpectationMet()
{
    startOnRealisticModel();
    m_dock->completeModeCombo(QStringLiteral("F1"))->setCurrentIndex(1);
    click(QStringLiteral("HomePosition"));
    click(QStringLiteral("AirPressureOk"));
    scan(2);
    for (const char* name : {"Start", "PreparationDone", "DoorClosed"})
        click(QString::fromLatin1(name));
    scan(3);
    QTest::mousePress(m_dock->pressButton(QStringLiteral("Stop")), Qt::LeftButton);
    QTest::mouseRelease(m_dock->pressButton(QStringLiteral("Stop")), Qt::LeftButton);
    scan(2);
    QTest::mouseClick(m_dock->manualCompleteCheck(QStringLiteral("F1")), Qt::LeftButton);
    scan(3);
    QCOMPARE(m_window->chartScene()->activeStep(), QStringLiteral("A2"));
    const std::int64_t scans = m_session->simulator()->scanCount();

    const QString path = m_files.filePath(QStringLiteral("session.scenario"));
    QString error;
    QVERIFY2(m_session->saveRecording(path, &error), qPrintable(error));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(file.readAll());
    QVERIFY2(text.contains(QStringLiteral("at 1: set complete F1 = FALSE")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("expect fired A6->A1")), qPrintable(text));
    QVERIFY(text.contains(QStringLiteral("expect fired F1->A2")));
    QVERIFY(text.contains(QStringLiteral("set Stop = TRUE")));
    QVERIFY(text.contains(QStringLiteral("set Stop = FALSE")));
    QVERIFY2(text.trimmed().endsWith(QStringLiteral("at %1: expect step A2").arg(scans)), qPrintable(text));

    // Replayed from the start, with the user's Complete setting gone.
    m_dock->completeModeCombo(QStringLiteral("F1"))->setCurrentIndex(0);
    QSignalSpy replay(m_session, &SimulationSession::replayChanged);
    QVERIFY2(m_session->startReplay(path, &error), qPrintable(error));
    QVERIFY(m_session->isReplaying());
    QCOMPARE(m_session->simulator()->scanCount(), std::int64_t{0});
    QVERIFY(!m_dock->findChild<QWidget*>(QStringLiteral("inputsPanel"))->isEnabled());
    m_session->advance(1000);
    QCOMPARE(m_session->replayState(), SimulationSession::ReplayState::Finished);
    QCOMPARE(m_session->simulator()->scanCount(), scans);
    QVERIFY(m_session->replayFailures().empty());
    QVERIFY(m_session->replayExpectationCount() >= 6);
    QCOMPARE(m_dock->failureList()->count(), 0);
    QVERIFY2(m_dock->replayLabel()->text().contains(QStringLiteral("every expectation met")),
             qPrintable(m_dock->replayLabel()->text()));
    QCOMPARE(m_window->chartScene()->activeStep(), QStringLiteral("A2"));
    QVERIFY(m_dock->findChild<QWidget*>(QStringLiteral("inputsPanel"))->isEnabled());
    QVERIFY(replay.size() >= 2);
}

// Outputs and nested situations that changed are written back, and the file replays.
void TestSimulation::recordedNestedSessionReplays()
{
    startOnDrillingCell();
    for (const char* name : {"DrillHigh", "Unclamped", "StartButton"})
        click(QString::fromLatin1(name));
    scan(3);
    click(QStringLiteral("StartButton"));
    m_session->advance(1000); // F2's 10 s warm-up at 10 ms
    QCOMPARE(m_window->chartScene()->activeStep(), QStringLiteral("F1"));
    click(QStringLiteral("PartPresent"));
    scan(2);
    click(QStringLiteral("Unclamped"));
    click(QStringLiteral("Clamped"));
    scan(2);
    QCOMPARE(m_session->simulator()->activeNestedSteps("F1"), (std::vector<int>{3, 5}));
    const std::int64_t scans = m_session->simulator()->scanCount();

    const QString path = m_files.filePath(QStringLiteral("nested.scenario"));
    QString error;
    QVERIFY2(m_session->saveRecording(path, &error), qPrintable(error));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(file.readAll());
    QVERIFY2(text.contains(QStringLiteral("at 2: expect nested F2 steps 3\n")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("at 2: expect variable Spindle = TRUE\n")), qPrintable(text));
    // PartPresent was set before F1's entry scan: it starts in 1 and evolves to 2 in that scan.
    QVERIFY2(text.contains(QStringLiteral("expect nested F1 steps 2\n")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("expect nested F1 steps 3, 5\n")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("expect variable Marker = TRUE\n")), qPrintable(text));

    QVERIFY2(m_session->startReplay(path, &error), qPrintable(error));
    m_session->advance(5000);
    QCOMPARE(m_session->replayState(), SimulationSession::ReplayState::Finished);
    QCOMPARE(m_session->simulator()->scanCount(), scans);
    for (const core::ScenarioFailure& failure : m_session->replayFailures())
        qWarning("%s", core::toText(failure).c_str());
    QVERIFY(m_session->replayFailures().empty());
    QVERIFY(m_session->replayExpectationCount() >= 15);
}

void TestSimulation::recordingNeverReplacesAFifo()
{
    startOnRealisticModel();
    scan(2);
    const QString path = m_files.filePath(QStringLiteral("pipe.scenario"));
    QCOMPARE(::mkfifo(QFile::encodeName(path).constData(), 0644), 0);
    QString error;
    QVERIFY(!m_session->saveRecording(path, &error));
    QVERIFY2(error.contains(QStringLiteral("it is a named pipe (FIFO), not a regular file")), qPrintable(error));
    struct stat status {};
    QCOMPARE(::lstat(QFile::encodeName(path).constData(), &status), 0);
    QVERIFY(S_ISFIFO(status.st_mode));
}

void TestSimulation::replayShowsFailedExpectations()
{
    startOnRealisticModel();
    const QString path = m_files.filePath(QStringLiteral("wrong.scenario"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write("# A6 needs the air pressure too\n"
               "at 1: set HomePosition = TRUE\n"
               "at 2: expect step A1\n"
               "at 3: expect step A6\n");
    file.close();
    QString error;
    QVERIFY2(m_session->startReplay(path, &error), qPrintable(error));
    m_session->advance(10);
    QCOMPARE(m_session->replayState(), SimulationSession::ReplayState::Finished);
    QCOMPARE(m_session->simulator()->scanCount(), std::int64_t{3});
    QCOMPARE(m_session->replayFailures().size(), std::size_t{1});
    QCOMPARE(m_dock->failureList()->count(), 1);
    QVERIFY2(m_dock->failureList()->item(0)->text().startsWith(QStringLiteral("Line 3:")),
             qPrintable(m_dock->failureList()->item(0)->text()));
    QVERIFY(m_dock->replayLabel()->text().contains(QStringLiteral("1 of 2 expectations failed")));

    // A file that does not fit the model is refused with the reason.
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write("at 1: set NoSuchInput = TRUE\n");
    file.close();
    QVERIFY(!m_session->startReplay(path, &error));
    QVERIFY2(error.contains(QStringLiteral("NoSuchInput")), qPrintable(error));
    QVERIFY2(error.contains(QStringLiteral("wrong.scenario:1:")), qPrintable(error));
}

void TestSimulation::thousandScansPerSecondRunInBatches()
{
    startOnRealisticModel();
    auto* speed = m_dock->findChild<QSpinBox*>(QStringLiteral("speedSpin"));
    QVERIFY(speed);
    QCOMPARE(speed->maximum(), SimulationSession::kMaxSpeed);
    speed->setValue(1000);
    QCOMPARE(m_session->speed(), 1000);

    QSignalSpy stepped(m_session, &SimulationSession::stepped);
    QElapsedTimer clock;
    auto* run = m_dock->findChild<QAbstractButton*>(QStringLiteral("runButton"));
    // The clock starts before the session's own, so that it never reads less
    // time than the session was given (a slow click must not fail the check).
    clock.start();
    QTest::mouseClick(run, Qt::LeftButton);
    QVERIFY(m_session->isRunning());
    QTest::qWait(600);
    QTest::mouseClick(run, Qt::LeftButton);
    const double seconds = static_cast<double>(clock.elapsed()) / 1000.0;
    QVERIFY(!m_session->isRunning());

    const std::int64_t scans = m_session->simulator()->scanCount();
    const auto updates = static_cast<std::int64_t>(stepped.size());
    qInfo("%lld scans in %lld UI updates over %.2f s", static_cast<long long>(scans),
          static_cast<long long>(updates), seconds);
    // Never ahead of the clock, and not far behind it (a late tick catches up
    // at most 0.1 s: a loaded machine loses some).
    QVERIFY(scans <= static_cast<std::int64_t>(seconds * 1000) + 2);
    QVERIFY(scans >= 200);
    // Batches: about one update per 16 ms frame, each running ~16 scans.
    QVERIFY(updates >= 1);
    QVERIFY2(updates * 5 <= scans, "the session emits about one update per frame, not one per scan");
    QCOMPARE(m_dock->traceModel()->rowCount(), static_cast<int>(scans));
}

void TestSimulation::languageChangeKeepsTheSimulation()
{
    startOnRealisticModel();
    click(QStringLiteral("HomePosition"));
    scan(2);
    // The docks are built again in the new language; the session stays.
    QVERIFY(m_translators->setLanguage(QStringLiteral("es")));
    QTRY_COMPARE(m_window->findChild<SimulationDock*>(QStringLiteral("simulationDock"))->windowTitle(),
                 QStringLiteral("Simulación"));
    m_dock = m_window->findChild<SimulationDock*>(QStringLiteral("simulationDock"));
    QVERIFY(m_session->isActive());
    QCOMPARE(m_session->simulator()->scanCount(), std::int64_t{2});
    QVERIFY(m_dock->toggleButton(QStringLiteral("HomePosition"))->isChecked());
    QCOMPARE(m_dock->traceModel()->rowCount(), 2);
    QVERIFY(!m_window->findChild<QDockWidget*>(QStringLiteral("stepDock"))->widget()->isEnabled());
    scan();
    QCOMPARE(m_session->simulator()->scanCount(), std::int64_t{3});
}

namespace {

// What the chart and the dock show of one scan, to compare a past scan
// shown again with the scan when it ran.
struct ShownScan {
    QString activeStep;
    QString fired;
    QList<bool> tokensOfF1A2;
    QStringList inputTexts;
    QString activeLabel;
    QStringList explanation;

    bool operator==(const ShownScan&) const = default;
};

ShownScan shownScan(const MainWindow& window, const SimulationDock& dock)
{
    ShownScan shown;
    ChartScene* scene = window.chartScene();
    shown.activeStep = scene->activeStep();
    shown.fired = scene->firedTransition();
    shown.tokensOfF1A2 = scene->transitionItem(QStringLiteral("F1->A2"))->tokenMarks();
    for (const char* name : {"HomePosition", "AirPressureOk", "Start", "PreparationDone", "DoorClosed"})
        shown.inputTexts << dock.toggleButton(QString::fromLatin1(name))->text();
    shown.activeLabel = dock.findChild<QLabel*>(QStringLiteral("activeStepLabel"))->text();
    shown.explanation = explanationTexts(*dock.explanationView());
    return shown;
}

} // namespace

namespace QTest {
template<> char* toString(const ShownScan& shown)
{
    const QStringList parts{shown.activeStep, shown.fired, shown.inputTexts.join(QLatin1Char(',')), shown.activeLabel,
                            shown.explanation.join(QLatin1Char('/'))};
    return qstrdup(parts.join(QStringLiteral(" | ")).toUtf8().constData());
}
} // namespace QTest

// Five scans with inputs changed; three back is scan 2 as it was shown then,
// forward again goes through the kept scans to the latest.
void TestSimulation::stepBackShowsThePastScan()
{
    startOnRealisticModel();
    QAbstractButton* back = m_dock->stepBackButton();
    QAbstractButton* forward = m_dock->stepForwardButton();
    QVERIFY(!back->isEnabled());
    QVERIFY(!forward->isEnabled());
    scan();
    click(QStringLiteral("HomePosition"));
    click(QStringLiteral("AirPressureOk"));
    scan(); // scan 2: A6 -> A1
    const ShownScan scan2 = shownScan(*m_window, *m_dock);
    QCOMPARE(scan2.activeStep, QStringLiteral("A1"));
    for (const char* name : {"Start", "PreparationDone", "DoorClosed"})
        click(QString::fromLatin1(name));
    scan(); // scan 3: A1 -> F1
    const ShownScan scan3 = shownScan(*m_window, *m_dock);
    QCOMPARE(scan3.activeStep, QStringLiteral("F1"));
    click(QStringLiteral("DoorClosed"));
    scan(2);
    const ShownScan scan5 = shownScan(*m_window, *m_dock);
    QVERIFY(back->isEnabled());
    QVERIFY(!forward->isEnabled());

    clickButton("stepBackButton", 3);
    QVERIFY(m_session->isViewingHistory());
    QCOMPARE(m_session->viewedScan(), std::int64_t{2});
    QCOMPARE(m_session->liveSimulator()->scanCount(), std::int64_t{5}); // nothing ran
    QCOMPARE(shownScan(*m_window, *m_dock), scan2);
    QVERIFY2(m_dock->statusLabel()->text().startsWith(QStringLiteral("Scan 2 of 5 (history)")),
             qPrintable(m_dock->statusLabel()->text()));
    // The trace shows which scan it is.
    const QModelIndexList selected = m_dock->traceView()->selectionModel()->selectedRows();
    QCOMPARE(selected.size(), 1);
    QCOMPARE(selected.first().row(), 1);
    QVERIFY(forward->isEnabled());

    // Forward, by the Simulation menu's shortcut.
    auto* stepForward = m_window->findChild<QAction*>(QStringLiteral("stepForwardAction"));
    QVERIFY(stepForward && stepForward->isEnabled());
    QCOMPARE(stepForward->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_F10));
    stepForward->trigger();
    QCOMPARE(m_session->viewedScan(), std::int64_t{3});
    QCOMPARE(shownScan(*m_window, *m_dock), scan3);
    clickButton("stepForwardButton", 2);
    QVERIFY(!m_session->isViewingHistory());
    QCOMPARE(shownScan(*m_window, *m_dock), scan5);
    QVERIFY(m_dock->statusLabel()->text().startsWith(QStringLiteral("Scan 5 ·")));
    QVERIFY(m_dock->traceView()->selectionModel()->selectedRows().isEmpty());
    QVERIFY(!forward->isEnabled());

    // Back to the start state, by Shift+F10; no further.
    auto* stepBack = m_window->findChild<QAction*>(QStringLiteral("stepBackAction"));
    QCOMPARE(stepBack->shortcut(), QKeySequence(Qt::SHIFT | Qt::Key_F10));
    for (int i = 0; i < 6; ++i)
        QTest::keyClick(m_window.get(), Qt::Key_F10, Qt::ShiftModifier);
    QCOMPARE(m_session->viewedScan(), std::int64_t{0});
    QCOMPARE(m_window->chartScene()->activeStep(), QStringLiteral("A6"));
    QCOMPARE(m_dock->toggleButton(QStringLiteral("HomePosition"))->text(), QStringLiteral("FALSE"));
    QVERIFY(!back->isEnabled());
    QVERIFY(!stepBack->isEnabled());
    // A trace row clicked shows its scan.
    const QModelIndex row4 = m_dock->traceModel()->index(3, TraceTableModel::ScanColumn);
    QTest::mouseClick(m_dock->traceView()->viewport(), Qt::LeftButton, {},
                      m_dock->traceView()->visualRect(row4).center());
    QCOMPARE(m_session->viewedScan(), std::int64_t{4});
}

// Like an edit after an undo: a scan from a past scan drops the later ones
// from the history, the trace and the recording; the saved scenario replays.
void TestSimulation::playingFromAPastScanDropsTheLaterHistory()
{
    startOnRealisticModel();
    click(QStringLiteral("HomePosition"));
    click(QStringLiteral("AirPressureOk"));
    scan(2);
    for (const char* name : {"Start", "PreparationDone", "DoorClosed"})
        click(QString::fromLatin1(name));
    scan(3); // A1 -> F1 at scan 3, then on
    QVERIFY(m_session->recording().records.back().scan >= 3);
    clickButton("stepBackButton", 4); // scan 1: A1, the start inputs set
    QCOMPARE(m_window->chartScene()->activeStep(), QStringLiteral("A1"));

    // Another future: DoorClosed alone is not enough to start.
    click(QStringLiteral("DoorClosed"));
    QVERIFY(!m_session->isViewingHistory()); // changing an input continues from scan 1
    QCOMPARE(m_session->latestScan(), std::int64_t{1});
    QCOMPARE(m_dock->traceModel()->rowCount(), 1);
    scan(2);
    QCOMPARE(m_session->latestScan(), std::int64_t{3});
    QCOMPARE(m_window->chartScene()->activeStep(), QStringLiteral("A1"));
    QVERIFY(!m_dock->stepForwardButton()->isEnabled());
    QCOMPARE(m_dock->traceModel()->rowCount(), 3);
    QCOMPARE(m_dock->traceModel()->index(2, TraceTableModel::StepColumn).data().toString(), QStringLiteral("A1"));
    const core::ScenarioRecording recording = m_session->recording();
    QCOMPARE(recording.changes.size(), std::size_t{2}); // scan 1's and DoorClosed at scan 2
    QCOMPARE(recording.changes.back().scan, std::int64_t{2});
    QCOMPARE(recording.records.size(), std::size_t{1}); // A6 -> A1 only
    QVERIFY(m_session->trace().back().scan == 3);

    // Run from a past scan continues from it too.
    clickButton("stepBackButton");
    QTest::mouseClick(m_dock->findChild<QAbstractButton*>(QStringLiteral("runButton")), Qt::LeftButton);
    QVERIFY(m_session->isRunning());
    QVERIFY(!m_session->isViewingHistory());
    QCOMPARE(m_session->latestScan(), std::int64_t{2});
    m_session->pause();

    const QString path = m_files.filePath(QStringLiteral("branched.scenario"));
    QString error;
    QVERIFY2(m_session->saveRecording(path, &error), qPrintable(error));
    const std::int64_t scans = m_session->latestScan();
    QVERIFY2(m_session->startReplay(path, &error), qPrintable(error));
    m_session->run();
    QTRY_COMPARE(m_session->replayState(), SimulationSession::ReplayState::Finished);
    QCOMPARE(m_session->latestScan(), scans);
    QVERIFY(m_session->replayFailures().empty());
}

// The latest kHistoryCapacity scans are kept, and no more. What keeping
// them costs is timed by the simulation frame benchmark, not here.
void TestSimulation::historyIsBounded()
{
    startOnDrillingCell(); // four nested GRAFCETs: the largest copies
    for (const char* name : {"DrillHigh", "Unclamped", "StartButton"})
        click(QString::fromLatin1(name));
    const std::int64_t scans = SimulationSession::kMaxSpeed;
    m_session->advance(scans);

    QCOMPARE(m_session->firstKeptScan(), scans - SimulationSession::kHistoryCapacity);
    m_session->showScan(0);
    QCOMPARE(m_session->viewedScan(), scans - SimulationSession::kHistoryCapacity);
    QVERIFY(!m_session->canStepBack());
    QCOMPARE(m_window->chartScene()->activeStep(), QStringLiteral("F1"));
    m_session->reset();
    QVERIFY(!m_session->isViewingHistory());
    QCOMPARE(m_session->firstKeptScan(), std::int64_t{0});
    QVERIFY(!m_session->canStepBack());
}

// A replay starts paused at scan 0: F10 plays one scan, Run the rest.
void TestSimulation::replayStartsPausedAtScanZero()
{
    startOnRealisticModel();
    const QString path = writeScenario("paused.scenario", "at 1: set HomePosition = TRUE, AirPressureOk = TRUE\n"
                                                          "at 1: expect step A1\n"
                                                          "at 4: expect step A1\n");
    QString error;
    QVERIFY2(m_session->startReplay(path, &error), qPrintable(error));
    QVERIFY(m_session->isReplaying());
    QVERIFY(!m_session->isRunning());
    QCOMPARE(m_session->simulator()->scanCount(), std::int64_t{0});
    QVERIFY2(m_dock->replayLabel()->text().contains(QStringLiteral("paused at scan 0 of 4")),
             qPrintable(m_dock->replayLabel()->text()));
    QVERIFY(m_dock->replayLabel()->text().contains(QStringLiteral("F10")));

    auto* singleScan = m_window->findChild<QAction*>(QStringLiteral("singleScanAction"));
    QCOMPARE(singleScan->shortcut(), QKeySequence(Qt::Key_F10));
    QTest::keyClick(m_window.get(), Qt::Key_F10);
    QCOMPARE(m_session->simulator()->scanCount(), std::int64_t{1});
    QCOMPARE(m_window->chartScene()->activeStep(), QStringLiteral("A1"));
    QVERIFY(m_session->isReplaying());
    QVERIFY2(m_dock->replayLabel()->text().contains(QStringLiteral("paused at scan 1 of 4")),
             qPrintable(m_dock->replayLabel()->text()));

    QTest::mouseClick(m_dock->findChild<QAbstractButton*>(QStringLiteral("runButton")), Qt::LeftButton);
    QVERIFY(m_session->isRunning());
    QTRY_COMPARE(m_session->replayState(), SimulationSession::ReplayState::Finished);
    QVERIFY(!m_session->isRunning());
    QCOMPARE(m_session->simulator()->scanCount(), std::int64_t{4});
    QVERIFY(m_session->replayFailures().empty());
}

// Re&play Scenario… opens the file dialog, then leaves the replay paused at scan 0.
void TestSimulation::replayFromTheDockStartsPaused()
{
    startOnRealisticModel();
    const QString path = writeScenario("dock.scenario", "at 1: set HomePosition = TRUE, AirPressureOk = TRUE\n"
                                                        "at 3: expect step A1\n");
    bool answered = false;
    QTimer::singleShot(0, this, [&] {
        auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
        if (!dialog)
            return;
        dialog->selectFile(path);
        static_cast<QDialog*>(dialog)->accept(); // public there
        answered = true;
    });
    QTest::mouseClick(m_dock->findChild<QPushButton*>(QStringLiteral("replayButton")), Qt::LeftButton);
    QVERIFY(answered);
    QVERIFY(m_session->isReplaying());
    QVERIFY(!m_session->isRunning());
    QCOMPARE(m_session->simulator()->scanCount(), std::int64_t{0});
    QVERIFY2(m_dock->replayLabel()->text().contains(QStringLiteral("paused at scan 0 of 3")),
             qPrintable(m_dock->replayLabel()->text()));
    QVERIFY(m_dock->replayLabel()->isVisible()); // the Scenario tab is in front
}

// Stepping back is allowed in a replay; playing again replays the scenario
// from the scan shown, each failure counted once.
void TestSimulation::steppingBackInAReplayReplaysFromThere()
{
    startOnRealisticModel();
    const QString path = writeScenario("back.scenario", "at 1: set HomePosition = TRUE\n"
                                                        "at 2: expect step A1\n"
                                                        "at 3: set AirPressureOk = TRUE\n"
                                                        "at 4: expect step A1\n");
    QString error;
    QVERIFY2(m_session->startReplay(path, &error), qPrintable(error));
    scan(4);
    QCOMPARE(m_session->replayState(), SimulationSession::ReplayState::Finished);
    QCOMPARE(m_session->replayFailures().size(), std::size_t{1}); // scan 2: A6 needs the air pressure
    QCOMPARE(m_dock->failureList()->count(), 1);

    clickButton("stepBackButton", 3);
    QCOMPARE(m_session->viewedScan(), std::int64_t{1});
    QCOMPARE(m_dock->toggleButton(QStringLiteral("AirPressureOk"))->text(), QStringLiteral("FALSE"));
    scan();
    QCOMPARE(m_session->replayState(), SimulationSession::ReplayState::Running);
    QCOMPARE(m_session->latestScan(), std::int64_t{2});
    QCOMPARE(m_session->replayFailures().size(), std::size_t{1});
    scan(2);
    QCOMPARE(m_session->replayState(), SimulationSession::ReplayState::Finished);
    QCOMPARE(m_session->latestScan(), std::int64_t{4});
    QCOMPARE(m_window->chartScene()->activeStep(), QStringLiteral("A1"));
    QCOMPARE(m_session->replayFailures().size(), std::size_t{1});
    QCOMPARE(m_dock->failureList()->count(), 1);

    // An input changed at a past scan ends the replay: the user plays on from there.
    clickButton("stepBackButton", 2);
    QVERIFY(m_dock->findChild<QWidget*>(QStringLiteral("inputsPanel"))->isEnabled());
    click(QStringLiteral("AirPressureOk"));
    QCOMPARE(m_session->replayState(), SimulationSession::ReplayState::None);
    QCOMPARE(m_session->latestScan(), std::int64_t{2});
    QVERIFY(m_dock->failureList()->isHidden());
    scan();
    QCOMPARE(m_session->latestScan(), std::int64_t{3});
    QCOMPARE(m_window->chartScene()->activeStep(), QStringLiteral("A1"));
    QCOMPARE(m_session->recording().changes.back().scan, std::int64_t{3});
}

// The failures list shows only when an expectation failed.
void TestSimulation::scenarioTabHasNoEmptyFailureBox()
{
    startOnRealisticModel();
    auto* tabs = m_dock->findChild<QTabWidget*>(QStringLiteral("simulationTabs"));
    tabs->setCurrentIndex(2);
    QVERIFY(m_dock->failureList()->isHidden());
    // The buttons and the text at the top, nothing stretched between them.
    QVERIFY(m_dock->replayLabel()->geometry().bottom() < tabs->currentWidget()->height() / 2);

    const QString path = writeScenario("fails.scenario", "at 1: set HomePosition = TRUE\n"
                                                         "at 2: expect step A1\n");
    QString error;
    QVERIFY2(m_session->startReplay(path, &error), qPrintable(error));
    QVERIFY(m_dock->failureList()->isHidden());
    m_session->run();
    QTRY_COMPARE(m_session->replayState(), SimulationSession::ReplayState::Finished);
    QVERIFY(!m_dock->failureList()->isHidden());
    QCOMPARE(m_dock->failureList()->count(), 1);
    m_session->reset();
    QVERIFY(m_dock->failureList()->isHidden());
}

QTEST_MAIN(TestSimulation)
#include "test_simulation.moc"
