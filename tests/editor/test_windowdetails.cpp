// The window at 1366 x 768 and the docks' details (issue 33): the undo
// history in the UI language, one name for a GEMMA transition, the
// Variables table's Insert key and header rows, the step-number box's
// refusals, Ctrl+Z after a committed field, and what the docks show at
// the smallest screen the window is laid out for. On the shipped drilling cell.

#include "editortestsupport.h"

#include "editor/app/languages.h"
#include "editor/commands/setconditioncommand.h"
#include "editor/commands/setprioritycommand.h"
#include "editor/docks/grafcetstepdock.h"
#include "editor/docks/variablesdock.h"
#include "editor/docks/variablestablemodel.h"
#include "editor/docks/wrappinglabel.h"
#include "editor/document.h"
#include "editor/grafcet/grafcetactions.h"
#include "editor/grafcet/grafcetview.h"
#include "editor/mainwindow.h"
#include "editor/selection.h"

#include "core/model/grafcet.h"
#include "core/model/model.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QHeaderView>
#include <QLabel>
#include <QTabWidget>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>
#include <QSpinBox>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <memory>

using namespace editor;

class TestWindowDetails : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();

    void transitionsAreNamedWithAnArrow();
    void undoTextsFollowTheLanguage();
    void grafcetUndoTextsFollowTheLanguage();
    void insertKeyAddsAVariable();
    void pasteReadsAHeaderRow();
    void stepNumberZeroIsRefusedWithTheReason();
    void ctrlZAfterCommitUndoesTheModel();
    void grafcetTabLeavesTheDockColumnAsItWas_data();
    void grafcetTabLeavesTheDockColumnAsItWas();
    void simulationReadsAt1366x768();
    void scanStatusDoesNotCrowdTheSpeedBox();
    void problemsCodeColumnShowsWholeCodes();

private:
    void loadExample(const QString& file = QStringLiteral("drilling-cell.ggstudio.json"));
    void useDefaultLayout();
    void simulate(int scans);
    QDockWidget* dock(const char* name) const { return child<QDockWidget>(name); }
    QUndoStack* undoStack() const { return m_window->document()->undoStack(); }
    Document& document() const { return *m_window->document(); }
    template <typename T>
    T* child(const char* name) const
    {
        return editortest::namedChild<T>(*m_window, name);
    }
    // In the GEMMA Simulation dock: the PackML one has widgets of the same names.
    template <typename T>
    T* simulationChild(const char* name) const
    {
        return editortest::namedChild<T>(*dock("simulationDock"), name);
    }

    QTemporaryDir m_settingsDir;
    std::unique_ptr<Translators> m_translators;
    std::unique_ptr<MainWindow> m_window;
};

void TestWindowDetails::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    editortest::useTestSettings(m_settingsDir.path(), QStringLiteral("test_windowdetails"));
}

void TestWindowDetails::init()
{
    m_window = editortest::showEnglishMainWindow(m_translators);
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    loadExample();
}

void TestWindowDetails::cleanup()
{
    m_window.reset();
    m_translators.reset();
}

void TestWindowDetails::loadExample(const QString& file)
{
    QString error;
    QVERIFY2(document().load(QStringLiteral(GGSTUDIO_EXAMPLES_DIR "/") + file, &error), qPrintable(error));
}

// The window inside a 1366 x 768 screen (less the window manager's frame), in the default layout.
void TestWindowDetails::useDefaultLayout()
{
    m_window->resize(1366 - 16, 768 - 48);
    child<QAction>("resetLayoutAction")->trigger();
    QApplication::processEvents();
}

void TestWindowDetails::simulate(int scans)
{
    child<QAction>("simulateAction")->setChecked(true);
    QApplication::processEvents();
    for (int i = 0; i < scans; ++i)
        child<QAction>("singleScanAction")->trigger();
    QApplication::processEvents();
}

// A GEMMA transition reads "A1 → F2" in the undo history as on the chart and in the docks.
void TestWindowDetails::transitionsAreNamedWithAnArrow()
{
    QVERIFY(document().push(new SetConditionCommand(document(), QStringLiteral("A1->F2"), QStringLiteral("TRUE"))));
    QCOMPARE(undoStack()->undoText(), QStringLiteral("Edit condition of A1 → F2"));
    QVERIFY(document().push(new SetPriorityCommand(document(), QStringLiteral("F1->F3"), 1)));
    QCOMPARE(undoStack()->undoText(), QStringLiteral("Set priority of F1 → F3 to 1"));
    QVERIFY(!child<QAction>("undoAction")->text().contains(QLatin1String("->")));
}

// An entry made in English reads in French once the user switches, in the Edit menu too.
void TestWindowDetails::undoTextsFollowTheLanguage()
{
    QVERIFY(document().push(new SetConditionCommand(document(), QStringLiteral("A1->F2"), QStringLiteral("TRUE"))));
    auto* variables = child<VariablesDock>("variablesDock");
    variables->pasteVariables(QStringLiteral("Lamp1\tBOOL\nLamp2\tBOOL\n"));
    QVERIFY(variables->findChild<QTableView*>("variablesView")->selectionModel());
    // Two variables removed as one entry: a macro.
    variables->findChild<QTableView*>("variablesView")->selectRow(document().model().variableIndex("Lamp1"));
    variables->findChild<QTableView*>("variablesView")
        ->selectionModel()
        ->select(variables->findChild<QTableView*>("variablesView")->model()->index(
                     document().model().variableIndex("Lamp2"), 0),
                 QItemSelectionModel::Select | QItemSelectionModel::Rows);
    QAction* remove = nullptr;
    for (QAction* action : variables->findChild<QTableView*>("variablesView")->actions()) {
        if (action->text() == QLatin1String("Remove"))
            remove = action;
    }
    QVERIFY(remove);
    remove->trigger();
    QCOMPARE(undoStack()->undoText(), QStringLiteral("Remove 2 variables"));

    QVERIFY(m_translators->setLanguage(QStringLiteral("fr")));
    QCoreApplication::processEvents();
    QCOMPARE(undoStack()->undoText(), QCoreApplication::translate("editor::VariablesDock", "Remove %n variables",
                                                                   nullptr, 2));
    QVERIFY(undoStack()->undoText() != QLatin1String("Remove 2 variables"));
    QVERIFY2(child<QAction>("undoAction")->text().contains(undoStack()->undoText()),
             qPrintable(child<QAction>("undoAction")->text()));
    const QString condition = undoStack()->text(undoStack()->count() - 3);
    QCOMPARE(condition, QStringLiteral("Modifier la réceptivité de A1 → F2"));
    QVERIFY2(condition != QLatin1String("Edit condition of A1 → F2"), qPrintable(condition));

    QVERIFY(m_translators->setLanguage(QStringLiteral("en")));
    QCoreApplication::processEvents();
    QCOMPARE(undoStack()->undoText(), QStringLiteral("Remove 2 variables"));
    QCOMPARE(undoStack()->text(undoStack()->count() - 3), QStringLiteral("Edit condition of A1 → F2"));
}

// A GRAFCET edit made in English (a step inserted, steps pasted from the
// tab's menu actions) reads in French in the undo history once the user
// switches, and in English again on the way back.
void TestWindowDetails::grafcetUndoTextsFollowTheLanguage()
{
    QVERIFY(m_window->openNestedGrafcet(QStringLiteral("F1")));
    GrafcetView* view = m_window->grafcetView(QStringLiteral("F1"));
    QVERIFY(view);
    auto* actions = view->findChild<GrafcetActions*>(QStringLiteral("grafcetActions"));
    QVERIFY(actions);
    const auto trigger = [view](const char* name) {
        auto* action = view->findChild<QAction*>(QLatin1String(name));
        QVERIFY2(action, name);
        action->trigger();
    };
    const int added = document().model().grafcet("F1")->nextStepNumber();
    actions->select({1}, {});
    trigger("grafcetInsertAfterAction");
    const QString insertText = QStringLiteral("Add step %1 to F1").arg(added);
    QCOMPARE(undoStack()->undoText(), insertText);
    actions->select({1}, {});
    trigger("grafcetCopyAction");
    trigger("grafcetPasteAction");
    QCOMPARE(undoStack()->undoText(), QStringLiteral("Paste 1 step into F1"));
    QCOMPARE(undoStack()->count(), 2);

    QVERIFY(m_translators->setLanguage(QStringLiteral("fr")));
    QCoreApplication::processEvents();
    QCOMPARE(undoStack()->undoText(), QStringLiteral("Coller 1 étape dans F1"));
    QCOMPARE(undoStack()->text(0), QStringLiteral("Ajouter l’étape %1 à F1").arg(added));
    QVERIFY2(child<QAction>("undoAction")->text().contains(undoStack()->undoText()),
             qPrintable(child<QAction>("undoAction")->text()));

    QVERIFY(m_translators->setLanguage(QStringLiteral("en")));
    QCoreApplication::processEvents();
    QCOMPARE(undoStack()->undoText(), QStringLiteral("Paste 1 step into F1"));
    QCOMPARE(undoStack()->text(0), insertText);
}

// Insert in the table adds a row after the current one, as the Add button does.
void TestWindowDetails::insertKeyAddsAVariable()
{
    auto* view = child<QTableView>("variablesView");
    child<VariablesDock>("variablesDock")->raise();
    const int before = static_cast<int>(document().model().variables().size());
    view->setFocus();
    view->setCurrentIndex(view->model()->index(0, VariablesTableModel::NameColumn));
    QTest::keyClick(view, Qt::Key_Insert);
    QCOMPARE(static_cast<int>(document().model().variables().size()), before + 1);
    QCOMPARE(undoStack()->undoText(), QStringLiteral("Add variable Variable1"));
    QCOMPARE(document().model().variableIndex("Variable1"), 1);
}

// A first row of column titles, in any language of the editor, is not a
// variable: it gives the order of the columns.
void TestWindowDetails::pasteReadsAHeaderRow()
{
    auto* dock = child<VariablesDock>("variablesDock");
    // The table's own order, with its English titles.
    QVERIFY(dock->pasteVariables(QStringLiteral("Name\tType\tKind\tDefault\tComment\n"
                                                "Lamp\tBOOL\tOutput\tTRUE\tPanel lamp\n")));
    const core::Variable* lamp = document().model().variable("Lamp");
    QVERIFY(lamp);
    QVERIFY(!document().model().variable("Name"));
    QCOMPARE(lamp->kind, core::VariableKind::Output);
    QCOMPARE(QString::fromStdString(lamp->defaultValue), QStringLiteral("TRUE"));
    QCOMPARE(QString::fromStdString(lamp->comment), QStringLiteral("Panel lamp"));

    // Titles of the French editor, pasted into the English one.
    const QString nameFr = QStringLiteral("Nom");
    QVERIFY(m_translators->setLanguage(QStringLiteral("fr")));
    const QString header = QCoreApplication::translate("editor::VariablesTableModel", "Name") + QLatin1Char('\t')
        + QCoreApplication::translate("editor::VariablesTableModel", "Comment") + QLatin1Char('\t')
        + QCoreApplication::translate("editor::VariablesTableModel", "Type");
    QVERIFY(m_translators->setLanguage(QStringLiteral("en")));
    QVERIFY2(header.startsWith(nameFr), qPrintable(header));
    QVERIFY(dock->pasteVariables(header + QStringLiteral("\nCounter\tParts made\tINT\n")));
    const core::Variable* counter = document().model().variable("Counter");
    QVERIFY(counter);
    QCOMPARE(counter->type, core::IecType::Int);
    QCOMPARE(QString::fromStdString(counter->comment), QStringLiteral("Parts made"));

    // Without titles the order is name, type, default, comment, kind.
    QVERIFY(dock->pasteVariables(QStringLiteral("Speed\tINT\t5\tmm/s\tinput\n")));
    const core::Variable* speed = document().model().variable("Speed");
    QVERIFY(speed);
    QCOMPARE(QString::fromStdString(speed->defaultValue), QStringLiteral("5"));
    QCOMPARE(speed->kind, core::VariableKind::Input);
}

// 0 is not put back to 1 without a word: the box says why it refuses it.
void TestWindowDetails::stepNumberZeroIsRefusedWithTheReason()
{
    QVERIFY(m_window->openNestedGrafcet(QStringLiteral("F1")));
    m_window->selection()->select(ElementRef::grafcetStep(QStringLiteral("F1"), 2));
    auto* spin = child<QSpinBox>("numberSpin");
    auto* message = child<WrappingLabel>("numberMessage");
    const int before = undoStack()->count();
    spin->setFocus();
    spin->selectAll();
    QTest::keyClicks(spin, QStringLiteral("0"));
    QTest::keyClick(spin, Qt::Key_Return);
    QVERIFY(message->isVisibleTo(message->window()));
    QCOMPARE(message->text(), QStringLiteral("Step numbers start at 1: 0 is not a step number."));
    QCOMPARE(spin->value(), 2);
    QCOMPARE(undoStack()->count(), before);
    QVERIFY(document().model().grafcet("F1")->step(2));
}

// Ctrl+Z in a spin box whose number is committed undoes the model, not the typing.
void TestWindowDetails::ctrlZAfterCommitUndoesTheModel()
{
    QVERIFY(m_window->openNestedGrafcet(QStringLiteral("F1")));
    m_window->selection()->select(ElementRef::grafcetStep(QStringLiteral("F1"), 2));
    auto* spin = child<QSpinBox>("numberSpin");
    spin->setFocus();
    spin->selectAll();
    QTest::keyClicks(spin, QStringLiteral("20"));
    QTest::keyClick(spin, Qt::Key_Return);
    QVERIFY(document().model().grafcet("F1")->step(20));
    QCOMPARE(undoStack()->undoText(), QStringLiteral("Renumber F1 step 2 to 20"));
    spin = child<QSpinBox>("numberSpin");
    QVERIFY(spin->hasFocus());
    QTest::keyClick(spin, Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(document().model().grafcet("F1")->step(2));
    QVERIFY(!document().model().grafcet("F1")->step(20));

    // Typing not yet committed is undone in the box, the model left alone.
    m_window->selection()->select(ElementRef::grafcetStep(QStringLiteral("F1"), 2));
    spin->setFocus();
    spin->selectAll();
    const int index = undoStack()->index();
    QTest::keyClicks(spin, QStringLiteral("3"));
    QTest::keyClick(spin, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(undoStack()->index(), index);
}

void TestWindowDetails::grafcetTabLeavesTheDockColumnAsItWas_data()
{
    QTest::addColumn<QString>("language");
    for (const char* language : {"en", "fr", "de", "es", "it"})
        QTest::newRow(language) << QString::fromLatin1(language);
}

// Opening a GRAFCET tab and selecting its step, then its transition, does
// not widen the dock column at 1366 x 768, in any language.
void TestWindowDetails::grafcetTabLeavesTheDockColumnAsItWas()
{
    QFETCH(QString, language);
    QVERIFY(m_translators->setLanguage(language));
    useDefaultLayout();
    const int before = dock("stepDock")->width();
    // The nested docks and Simulation fit the column the GEMMA sheet leaves at 1366 x 768
    // (370 px in English), whatever the language: they do not set its width.
    for (const char* name : {"grafcetStepDock", "grafcetTransitionDock", "simulationDock"}) {
        QVERIFY2(dock(name)->minimumSizeHint().width() <= 370,
                 qPrintable(QStringLiteral("%1: %2 px").arg(QLatin1String(name)).arg(dock(name)->minimumSizeHint().width())));
    }
    QVERIFY(m_window->openNestedGrafcet(QStringLiteral("F1")));
    m_window->selection()->select(ElementRef::grafcetStep(QStringLiteral("F1"), 7)); // the widest actions
    QApplication::processEvents();
    QVERIFY(dock("grafcetStepDock")->isVisible());
    QVERIFY2(dock("grafcetStepDock")->width() <= before + 2,
             qPrintable(QStringLiteral("%1 px, was %2").arg(dock("grafcetStepDock")->width()).arg(before)));
    m_window->selection()->select(ElementRef::grafcetTransition(QStringLiteral("F1"), 2));
    QApplication::processEvents();
    QVERIFY(dock("grafcetTransitionDock")->isVisible());
    QVERIFY2(dock("grafcetTransitionDock")->width() <= before + 2,
             qPrintable(QStringLiteral("%1 px, was %2").arg(dock("grafcetTransitionDock")->width()).arg(before)));
}

// While simulating, the greyed Variables and Problems docks (and Structured
// Text, in their group) give their room up: the inputs and outputs, the
// explanation and the trace each show rows enough to work with; they come
// back when the simulation ends.
void TestWindowDetails::simulationReadsAt1366x768()
{
    useDefaultLayout();
    const int variablesBefore = dock("variablesDock")->height();
    simulate(3);
    QVERIFY(dock("simulationDock")->isVisible());
    QVERIFY(!dock("variablesDock")->isVisible());
    QVERIFY(!dock("problemsDock")->isVisible());
    QVERIFY(!dock("stPreviewDock")->isVisible());
    // The whole column, nearly as high as the drawing beside it (three quarters of it before).
    QVERIFY2(dock("simulationDock")->height() >= m_window->centralWidget()->height() * 9 / 10,
             qPrintable(QStringLiteral("%1 px beside %2").arg(dock("simulationDock")->height())
                            .arg(m_window->centralWidget()->height())));
    const int line = m_window->fontMetrics().lineSpacing();
    auto* inputs = simulationChild<QWidget>("inputsArea");
    QVERIFY2(inputs->height() >= 12 * line, qPrintable(QStringLiteral("inputs: %1 px").arg(inputs->height())));
    auto* explanation = simulationChild<QAbstractItemView>("explanationView");
    QVERIFY2(explanation->viewport()->height() >= 4 * line,
             qPrintable(QStringLiteral("explanation: %1 px").arg(explanation->viewport()->height())));
    simulationChild<QTabWidget>("simulationTabs")->setCurrentIndex(1);
    QApplication::processEvents();
    auto* trace = simulationChild<QTableView>("traceView");
    QVERIFY2(trace->viewport()->height() >= 4 * trace->verticalHeader()->defaultSectionSize(),
             qPrintable(QStringLiteral("trace: %1 px").arg(trace->viewport()->height())));

    child<QAction>("simulateAction")->setChecked(false);
    QApplication::processEvents();
    QVERIFY(dock("variablesDock")->isVisible());
    QVERIFY(dock("problemsDock")->toggleViewAction()->isChecked());
    QVERIFY2(qAbs(dock("variablesDock")->height() - variablesBefore) <= 2,
             qPrintable(QStringLiteral("%1, was %2").arg(dock("variablesDock")->height()).arg(variablesBefore)));
}

// "Scan 10 of 12 (history)" has a line of its own, whole, clear of the speed box.
void TestWindowDetails::scanStatusDoesNotCrowdTheSpeedBox()
{
    useDefaultLayout();
    simulate(12);
    child<QAction>("stepBackAction")->trigger();
    child<QAction>("stepBackAction")->trigger();
    QApplication::processEvents();
    auto* status = simulationChild<QLabel>("statusLabel");
    auto* speed = simulationChild<QSpinBox>("speedSpin");
    QVERIFY2(status->text().contains(QLatin1String("(history)")), qPrintable(status->text()));
    const QRect statusRect(status->mapTo(m_window.get(), QPoint()), status->size());
    const QRect speedRect(speed->mapTo(m_window.get(), QPoint()), speed->size());
    QVERIFY(!statusRect.adjusted(-6, 0, 6, 0).intersects(speedRect));
    QVERIFY2(status->contentsRect().width() >= status->fontMetrics().horizontalAdvance(status->text()),
             qPrintable(QStringLiteral("%1 px for %2").arg(status->contentsRect().width()).arg(status->text())));
}

// The Problems dock's code column is as wide as its widest code, icon and
// indentation under a GRAFCET's row included: no "GG…".
void TestWindowDetails::problemsCodeColumnShowsWholeCodes()
{
    loadExample(QStringLiteral("drilling-cell-faulty.ggstudio.json"));
    useDefaultLayout();
    dock("problemsDock")->raise();
    QApplication::processEvents();
    auto* view = child<QTreeWidget>("problemsView");
    QVERIFY(view->topLevelItemCount() > 0);
    view->expandAll();
    QApplication::processEvents();
    for (QTreeWidgetItemIterator it(view); *it; ++it) {
        const QString code = (*it)->text(0);
        if (code.isEmpty())
            continue;
        const int right = view->header()->sectionViewportPosition(0) + view->header()->sectionSize(0);
        const int needed = view->visualRect(view->indexFromItem(*it, 0)).left() + view->iconSize().width() + 8
            + view->fontMetrics().horizontalAdvance(code);
        QVERIFY2(needed <= right, qPrintable(QStringLiteral("%1 needs %2 px, has %3").arg(code).arg(needed).arg(right)));
    }
}

QTEST_MAIN(TestWindowDetails)
#include "test_windowdetails.moc"
