// Problems where the user looks (issue 33): a nested step, action or
// transition with a problem drawn red in its GRAFCET tab with the messages as
// tooltip, the GEMMA step that owns it red on the chart; the quick fix that
// declares an undeclared name with the kind and type its uses suggest; the
// nested messages in the UI language. On the shipped drilling cell, whose F1
// has nine steps and eight transitions and no problem.

#include "editortestsupport.h"

#include "editor/app/languages.h"
#include "editor/chart/chartstyle.h"
#include "editor/chart/gemma/chartscene.h"
#include "editor/chart/gemma/stepitem.h"
#include "editor/commands/setconditioncommand.h"
#include "editor/commands/setgrafcetactioncommand.h"
#include "editor/commands/setreceptivitycommand.h"
#include "editor/docks/diagnosticlist.h"
#include "editor/docks/grafcettransitiondock.h"
#include "editor/docks/problemsdock.h"
#include "editor/document.h"
#include "editor/grafcet/grafcetexport.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetstepitem.h"
#include "editor/grafcet/grafcettransitionitem.h"
#include "editor/grafcet/grafcetview.h"
#include "editor/mainwindow.h"
#include "editor/selection.h"
#include "editor/text/conditiontypeerrortext.h"
#include "editor/text/diagnostictext.h"

#include "core/condition/conditiontypeerror.h"
#include "core/model/model.h"

#include <QAction>
#include <QFile>
#include <QHelpEvent>
#include <QLabel>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QToolTip>
#include <QTranslator>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>
#include <QUndoStack>

#include <memory>

using namespace editor;

namespace {

const QString kF1 = QStringLiteral("F1");

// Marks every text of one translation context, to see that a message goes
// through tr() in that context whatever the .qm files hold.
class MarkingTranslator : public QTranslator {
public:
    explicit MarkingTranslator(const char* context)
        : m_context(context)
    {
    }
    bool isEmpty() const override { return false; }
    QString translate(const char* context, const char* sourceText, const char* = nullptr, int = -1) const override
    {
        return qstrcmp(context, m_context) == 0 ? QStringLiteral("[tr]") + QString::fromUtf8(sourceText) : QString();
    }

private:
    const char* m_context;
};

} // namespace

class TestNestedProblems : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();

    void nestedTransitionWithAProblemIsRedWithItsMessage();
    void nestedActionWithAProblemIsRedOnItsBox();
    void exportedDrawingIsClean();
    void quickFixDeclaresAnInputAndOneUndoRemovesIt();
    void quickFixGuessesOutputsAndNumbers();
    void quickFixUnderTheReceptivity();
    void quickFixOnAGemmaCondition();
    void nestedMessagesGoThroughTranslation();
    void everyNestedElementProblemIsWorded();
    void nestedTypeErrorReadsInFrench();

private:
    void openF1();
    Document& document() const { return *m_window->document(); }
    GrafcetScene* f1Scene() const { return m_window->grafcetView(kF1)->grafcetScene(); }
    StepItem* chartF1() const { return m_window->chartScene()->stepItem(kF1); }
    ProblemsDock* problemsDock() const { return m_window->findChild<ProblemsDock*>(QStringLiteral("problemsDock")); }
    void setReceptivity(int number, const QString& text)
    {
        QVERIFY(document().push(new SetReceptivityCommand(document(), kF1, number, text)));
    }
    // The first row of the Problems dock with this code, made current.
    QTreeWidgetItem* selectProblem(const QString& code) const;
    QPointF barCenter(int number) const;

    QTemporaryDir m_settingsDir;
    std::unique_ptr<Translators> m_translators;
    std::unique_ptr<MainWindow> m_window;
};

void TestNestedProblems::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    editortest::useTestSettings(m_settingsDir.path(), QStringLiteral("test_nestedproblems"));
}

void TestNestedProblems::init()
{
    m_window = editortest::showEnglishMainWindow(m_translators);
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
}

void TestNestedProblems::cleanup()
{
    m_window.reset();
    m_translators.reset();
}

void TestNestedProblems::openF1()
{
    QString error;
    QVERIFY2(document().load(QStringLiteral(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json"), &error),
             qPrintable(error));
    QVERIFY(m_window->openNestedGrafcet(kF1));
    QVERIFY(m_window->grafcetView(kF1));
}

QTreeWidgetItem* TestNestedProblems::selectProblem(const QString& code) const
{
    QTreeWidget* view = problemsDock()->view();
    for (QTreeWidgetItemIterator it(view); *it; ++it) {
        if ((*it)->text(ProblemsDock::CodeColumn) == code) {
            view->setCurrentItem(*it);
            return *it;
        }
    }
    return nullptr;
}

QPointF TestNestedProblems::barCenter(int number) const
{
    for (const core::GrafcetTransitionLayout& transition : f1Scene()->layout().transitions) {
        if (transition.number == number)
            return {transition.barCenter.x, transition.barCenter.y};
    }
    return {};
}

void TestNestedProblems::nestedTransitionWithAProblemIsRedWithItsMessage()
{
    openF1();
    QVERIFY(!f1Scene()->transitionItem(1)->hasProblemMark());
    QVERIFY(f1Scene()->toolTipAt(barCenter(1)).isEmpty());
    QVERIFY(!chartF1()->hasProblemMark());
    QVERIFY(!chartF1()->toolTipText().contains(QStringLiteral("problem")));

    setReceptivity(1, QStringLiteral("Go AND Unclamped"));
    QVERIFY(f1Scene()->transitionItem(1)->hasProblemMark());
    QVERIFY(!f1Scene()->transitionItem(2)->hasProblemMark());
    const QString tip = f1Scene()->toolTipAt(barCenter(1));
    QVERIFY2(tip.contains(QStringLiteral("&#x27;Go&#x27; is not a declared variable"))
                 || tip.contains(QStringLiteral("'Go' is not a declared variable")),
             qPrintable(tip));
    QVERIFY(chartF1()->hasProblemMark());
    QVERIFY2(chartF1()->toolTipText().contains(QStringLiteral("Its nested GRAFCET has 1 problem")),
             qPrintable(chartF1()->toolTipText()));
    // Hovering the bar in the tab shows it.
    GrafcetView* view = m_window->grafcetView(kF1);
    view->centerOn(barCenter(1));
    const QPoint at = view->mapFromScene(barCenter(1));
    QHelpEvent help(QEvent::ToolTip, at, view->viewport()->mapToGlobal(at));
    QCoreApplication::sendEvent(view->viewport(), &help);
    QTRY_VERIFY2(QToolTip::text().contains(QStringLiteral("'Go' is not a declared variable")),
                 qPrintable(QToolTip::text()));
    QToolTip::hideText();

    setReceptivity(1, QStringLiteral("PartPresent AND Unclamped"));
    QVERIFY(!f1Scene()->transitionItem(1)->hasProblemMark());
    QVERIFY(f1Scene()->toolTipAt(barCenter(1)).isEmpty());
    QVERIFY(!chartF1()->hasProblemMark());
}

void TestNestedProblems::nestedActionWithAProblemIsRedOnItsBox()
{
    openF1();
    QVERIFY(document().push(new SetGrafcetActionCommand(document(), kF1, 3, 1,
                                                        {core::ActionTiming::Continuous, "N Drill"})));
    GrafcetStepItem* step3 = f1Scene()->stepItem(3);
    QCOMPARE(step3->problemActions(), QList<int>{1});
    QVERIFY(!step3->hasProblemMark()); // the step's square is not at fault, its action is
    const core::GrafcetStepLayout& layout = step3->layout();
    const QPointF onSquare(layout.box.x + layout.box.width / 2, layout.box.y + layout.box.height / 2);
    QVERIFY(f1Scene()->toolTipAt(onSquare).contains(QStringLiteral("action 2 of step 3 of F1")));
    QVERIFY(chartF1()->hasProblemMark());

    document().undoStack()->undo();
    QVERIFY(f1Scene()->stepItem(3)->problemActions().isEmpty());
    QVERIFY(!chartF1()->hasProblemMark());

    // A step's own problem marks its square: without T6, step 7 has no way out.
    core::Model model = document().model();
    QVERIFY(model.removeGrafcetTransition("F1", 6).ok);
    document().replaceModel(model, QString(), core::ModelFormat::Native);
    QVERIFY(m_window->openNestedGrafcet(kF1));
    QVERIFY(f1Scene()->stepItem(7)->hasProblemMark());
    QVERIFY(f1Scene()->stepItem(7)->problemActions().isEmpty());
    const core::GrafcetStepLayout& seven = f1Scene()->stepItem(7)->layout();
    QVERIFY(f1Scene()->toolTipAt(QPointF(seven.box.x + 2, seven.box.y + 2)).contains(QStringLiteral("step 7 of F1"), Qt::CaseInsensitive));
}

void TestNestedProblems::exportedDrawingIsClean()
{
    openF1();
    setReceptivity(1, QStringLiteral("Go AND Unclamped"));
    QTemporaryDir dir;
    const QString red = chartstyle::problemColor().name();
    GrafcetExport picture(*f1Scene());
    QString error;
    const QString path = dir.filePath(QStringLiteral("f1.svg"));
    QVERIFY2(picture.writeSvg(path, &error), qPrintable(error));
    QFile svg(path);
    QVERIFY(svg.open(QIODevice::ReadOnly));
    QVERIFY(!QString::fromUtf8(svg.readAll()).contains(red, Qt::CaseInsensitive));
    // The tab keeps its marks.
    QVERIFY(f1Scene()->problemMarksShown());
    QVERIFY(f1Scene()->transitionItem(1)->hasProblemMark());
}

void TestNestedProblems::quickFixDeclaresAnInputAndOneUndoRemovesIt()
{
    openF1();
    setReceptivity(1, QStringLiteral("Go AND Unclamped"));
    QVERIFY(selectProblem(QStringLiteral("GG403")));
    QAction* declare = problemsDock()->declareAction();
    QVERIFY(problemsDock()->view()->actions().contains(declare)); // in the rows' context menu
    QVERIFY(declare->isVisible());
    QCOMPARE(declare->text(), QStringLiteral("Declare 'Go' as INPUT BOOL"));
    const int undoIndex = document().undoStack()->index();

    problemsDock()->view()->setFocus();
    QTest::keyClick(problemsDock()->view(), Qt::Key_Period, Qt::ControlModifier);
    const core::Variable* declared = document().model().variable("Go");
    QVERIFY(declared);
    QCOMPARE(declared->kind, core::VariableKind::Input);
    QCOMPARE(declared->type, core::IecType::Bool);
    QVERIFY(!selectProblem(QStringLiteral("GG403")));
    QVERIFY(!f1Scene()->transitionItem(1)->hasProblemMark());
    QVERIFY(!chartF1()->hasProblemMark());
    QCOMPARE(document().undoStack()->index(), undoIndex + 1);

    document().undoStack()->undo();
    QVERIFY(!document().model().variable("Go"));
    QVERIFY(selectProblem(QStringLiteral("GG403")));
    QVERIFY(f1Scene()->transitionItem(1)->hasProblemMark());
}

void TestNestedProblems::quickFixGuessesOutputsAndNumbers()
{
    openF1();
    QVERIFY(document().push(new SetGrafcetActionCommand(document(), kF1, 5, 0,
                                                        {core::ActionTiming::Continuous, "N Stamp"})));
    QVERIFY(selectProblem(QStringLiteral("GG405")));
    QCOMPARE(problemsDock()->declareAction()->text(), QStringLiteral("Declare 'Stamp' as OUTPUT BOOL"));
    problemsDock()->declareAction()->trigger();
    QCOMPARE(document().model().variable("Stamp")->kind, core::VariableKind::Output);

    setReceptivity(3, QStringLiteral("DrillLow AND Depth > 12"));
    QVERIFY(selectProblem(QStringLiteral("GG403")));
    QCOMPARE(problemsDock()->declareAction()->text(), QStringLiteral("Declare 'Depth' as INPUT INT"));
    problemsDock()->declareAction()->trigger();
    QCOMPARE(document().model().variable("Depth")->type, core::IecType::Int);
    QVERIFY(!selectProblem(QStringLiteral("GG403")));

    // A problem that is no undeclared name has no fix.
    setReceptivity(3, QStringLiteral("DrillLow AND"));
    QVERIFY(selectProblem(QStringLiteral("GG401")));
    QVERIFY(!problemsDock()->declareAction()->isVisible());
}

void TestNestedProblems::quickFixUnderTheReceptivity()
{
    openF1();
    setReceptivity(2, QStringLiteral("Clamped AND Ready"));
    m_window->selection()->select(ElementRef::grafcetTransition(kF1, 2));
    auto* dock = m_window->findChild<GrafcetTransitionDock*>();
    QVERIFY(dock);
    auto* button = dock->findChild<QToolButton*>(QStringLiteral("declareVariableButton"));
    QVERIFY(button);
    QCOMPARE(button->text(), QStringLiteral("Declare 'Ready' as INPUT BOOL"));
    dock->raise();
    QTRY_VERIFY(button->isVisible());
    QTest::mouseClick(button, Qt::LeftButton);
    QTRY_VERIFY(document().model().variable("Ready"));
    QVERIFY(!f1Scene()->transitionItem(2)->hasProblemMark());
    QVERIFY(!dock->findChild<QToolButton*>(QStringLiteral("declareVariableButton")));
    document().undoStack()->undo();
    QVERIFY(!document().model().variable("Ready"));
    QVERIFY(f1Scene()->transitionItem(2)->hasProblemMark());
}

void TestNestedProblems::quickFixOnAGemmaCondition()
{
    openF1();
    QVERIFY(document().push(new SetConditionCommand(document(), QStringLiteral("A2->A1"), QStringLiteral("Homed"))));
    QVERIFY(selectProblem(QStringLiteral("GG203")));
    QCOMPARE(problemsDock()->declareAction()->text(), QStringLiteral("Declare 'Homed' as INPUT BOOL"));
    problemsDock()->declareAction()->trigger();
    QVERIFY(document().model().variable("Homed"));
    QVERIFY(!selectProblem(QStringLiteral("GG203")));
}

void TestNestedProblems::nestedMessagesGoThroughTranslation()
{
    openF1();
    setReceptivity(1, QStringLiteral("Go AND Unclamped"));
    MarkingTranslator marking("NestedProblemText");
    QCoreApplication::installTranslator(&marking);
    QCoreApplication::processEvents();
    QTreeWidgetItem* row = selectProblem(QStringLiteral("GG403"));
    QVERIFY(row);
    const QString message = row->text(ProblemsDock::MessageColumn);
    QVERIFY2(message.startsWith(QStringLiteral("[tr]In [tr]the receptivity of T1 of F1")), qPrintable(message));
    QVERIFY(f1Scene()->toolTipAt(barCenter(1)).contains(QStringLiteral("[tr]")));
    // The Nested Transition dock's problem line.
    m_window->selection()->select(ElementRef::grafcetTransition(kF1, 1));
    auto* dock = m_window->findChild<GrafcetTransitionDock*>();
    QVERIFY(dock);
    bool found = false;
    for (QLabel* label : dock->findChildren<QLabel*>())
        found = found || label->text().startsWith(QStringLiteral("[tr]In [tr]the receptivity"));
    QVERIFY(found);
    QCoreApplication::removeTranslator(&marking);
}

// Every problem of a single receptivity or action is worded by the editor,
// none left in the core's English.
void TestNestedProblems::everyNestedElementProblemIsWorded()
{
    openF1();
    core::Model model = document().model();
    const auto receptivity = [&](int number, const char* text) { QVERIFY(model.setReceptivity("F1", number, text).ok); };
    const auto action = [&](int step, int index, core::ActionTiming timing, const char* text) {
        QVERIFY(model.setGrafcetAction("F1", step, index, {timing, text}).ok);
    };
    receptivity(1, "");                              // GG402
    receptivity(2, "Clamped AND");                   // GG401
    receptivity(3, "DrillLow AND X42");              // GG406
    receptivity(4, "RE BatchSize");                  // GG410
    receptivity(5, "DrillHigh AND BatchSize / 0 > 1"); // GG408
    receptivity(6, "25d/X7");                        // GG407
    receptivity(7, "Go AND BatchSize");              // GG403, twice
    action(2, 0, core::ActionTiming::Continuous, "N ClampOut IF BatchSize"); // GG405, a type error
    action(3, 0, core::ActionTiming::Continuous, "N PartCount");             // GG414
    action(3, 1, core::ActionTiming::Continuous, "S DrillDown");             // GG405, the wrong list
    action(4, 0, core::ActionTiming::Continuous, "N Stamp");                 // GG405, undeclared
    action(7, 1, core::ActionTiming::OnActivation, "PartCount := TRUE");     // GG405, a value that does not fit
    action(9, 0, core::ActionTiming::OnActivation, "S EmergencyOk");         // GG413
    action(5, 0, core::ActionTiming::Continuous, "N Marker IF RE DrillLow");  // GG411
    action(8, 0, core::ActionTiming::OnActivation, "S Spindle");             // GG415
    action(1, 0, core::ActionTiming::Continuous, "N Conveyor IF NOT PartPresent AND DrillUp"); // GG421
    document().replaceModel(model, QString(), core::ModelFormat::Native);

    MarkingTranslator marking("NestedProblemText");
    QCoreApplication::installTranslator(&marking);
    QSet<QString> worded;
    for (const core::Diagnostic& d : document().diagnostics()) {
        const bool element = d.target == core::Diagnostic::Target::GrafcetStep
                          || d.target == core::Diagnostic::Target::GrafcetTransition;
        const QString code = QString::fromStdString(d.code);
        const int number = code.mid(2).toInt();
        if (!element || number < 401 || number > 421 || number == 412 || (number >= 416 && number <= 419))
            continue; // the findings about the GRAFCET's structure have their own texts
        const QString text = diagnosticText(d);
        QVERIFY2(text.startsWith(QStringLiteral("[tr]")), qPrintable(code + QStringLiteral(": ") + text));
        // The place is worded again, not taken from the English arguments.
        const QString englishPlace = d.arguments.size() > 1 ? QString::fromStdString(d.arguments[1]) : QString();
        QVERIFY2(englishPlace.isEmpty() || text.count(englishPlace) == text.count(QStringLiteral("[tr]") + englishPlace),
                 qPrintable(text));
        worded << code;
    }
    QCoreApplication::removeTranslator(&marking);
    for (const char* code : {"GG401", "GG402", "GG403", "GG405", "GG406", "GG407", "GG408", "GG410", "GG411", "GG413",
                             "GG414", "GG415", "GG421"})
        QVERIFY2(worded.contains(QLatin1String(code)), code);
}

void TestNestedProblems::nestedTypeErrorReadsInFrench()
{
    openF1();
    setReceptivity(1, QStringLiteral("BatchSize AND Unclamped"));
    QTreeWidgetItem* row = selectProblem(QStringLiteral("GG403"));
    QVERIFY(row);
    const QString english = row->text(ProblemsDock::MessageColumn);
    const core::Diagnostic* diagnostic = nullptr;
    for (const core::Diagnostic& d : document().diagnostics()) {
        if (d.code == "GG403")
            diagnostic = &d;
    }
    QVERIFY(diagnostic);
    const std::optional<core::cond::TypeError> error = core::cond::typeErrorFromArguments(diagnostic->arguments, 4);
    QVERIFY(error); // the type error's data, for the editor to word it
    const QString englishDetail = conditionTypeErrorText(*error);
    QVERIFY(english.contains(englishDetail));

    QVERIFY(m_translators->setLanguage(QStringLiteral("fr")));
    QCoreApplication::processEvents();
    const QString frenchDetail = conditionTypeErrorText(*error);
    if (frenchDetail == englishDetail)
        QSKIP("The French translation of the type errors is not in the .qm files");
    row = selectProblem(QStringLiteral("GG403"));
    QVERIFY(row);
    QVERIFY2(row->text(ProblemsDock::MessageColumn).contains(frenchDetail),
             qPrintable(row->text(ProblemsDock::MessageColumn)));
}

QTEST_MAIN(TestNestedProblems)
#include "test_nestedproblems.moc"
