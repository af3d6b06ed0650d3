// The GRAFCET tabs and their docks: the selection shared between a nested
// GRAFCET's drawing and the window, the Nested Step and Nested Transition
// docks and their commands (each one undo step, typing merged, undo
// restoring the model, the drawing and the docks), the Problems dock
// jumping into a GRAFCET, and the Structured Text dock following the tab
// in front. On the shipped drilling cell, whose F1 has nine steps and eight
// transitions.

#include "editortestsupport.h"

#include "editor/app/languages.h"
#include "editor/chart/chartstyle.h"
#include "editor/commands/addgrafcetactioncommand.h"
#include "editor/docks/conditionedit.h"
#include "editor/docks/grafcetactionparts.h"
#include "editor/docks/grafcetactionsmodel.h"
#include "editor/docks/grafcetstepdock.h"
#include "editor/docks/grafcettransitiondock.h"
#include "editor/docks/problemsdock.h"
#include "editor/docks/stpreviewdock.h"
#include "editor/docks/wrappinglabel.h"
#include "editor/document.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetstepitem.h"
#include "editor/grafcet/grafcettransitionitem.h"
#include "editor/grafcet/grafcetview.h"
#include "editor/grafcet/grafcetwiringitem.h"
#include "editor/mainwindow.h"
#include "editor/selection.h"

#include "core/layout/grafcetlayout.h"
#include "core/model/model.h"

#include <QCheckBox>
#include <QCompleter>
#include <QRegularExpression>
#include <QStringListModel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QScrollBar>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QToolButton>
#include <QTreeWidget>
#include <QUndoStack>

#include <memory>

using namespace editor;

namespace {

const QString kF1 = QStringLiteral("F1");

QString fromStd(const std::string& text)
{
    return QString::fromStdString(text);
}

// Where a transition's bar crosses its link, in scene coordinates.
QPointF barCenterOf(const GrafcetTransitionItem& item, const GrafcetScene& scene)
{
    for (const core::GrafcetTransitionLayout& transition : scene.layout().transitions) {
        if (transition.number == item.number())
            return {transition.barCenter.x, transition.barCenter.y};
    }
    return {};
}

} // namespace

class TestGrafcetDocks : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();

    void actionPartsSplitAndJoinTexts();
    void tabHasAnItemPerElement();
    void clickingAnItemSelectsItForTheDocks();
    void selectingElsewhereSelectsTheItemAndScrolls();
    void typedReceptivityIsOneUndoStep();
    void typingRelabelsTheDrawingInPlace();
    void receptivityProblemsAreUnderlined();
    void receptivityCompletesStepsAndVariables();
    void stepDockEditsInitialAndComment();
    void renumberingRefusesAUsedNumber();
    void actionCellEditIsOneCommand();
    void actionCellsEditTheirOwnPartInAnyOrder();
    void actionTypedWrongShowsTheError();
    void actionButtonsAddMoveAndRemove();
    void problemsDockSelectsTheNestedElement();
    void structuredTextFollowsTheTabInFront();

private:
    void loadExample(const QString& file = QStringLiteral("drilling-cell.ggstudio.json"));
    GrafcetView* openF1();
    QUndoStack* undoStack() const { return m_window->document()->undoStack(); }
    const core::Grafcet& f1() const { return *m_window->document()->model().grafcet("F1"); }
    GrafcetScene* f1Scene() const { return m_window->grafcetView(kF1)->grafcetScene(); }
    template <typename T>
    T* child(const char* name) const
    {
        return editortest::namedChild<T>(*m_window, name);
    }

    QTemporaryDir m_settingsDir;
    std::unique_ptr<Translators> m_translators;
    std::unique_ptr<MainWindow> m_window;
};

void TestGrafcetDocks::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    editortest::useTestSettings(m_settingsDir.path(), QStringLiteral("test_grafcetdocks"));
}

void TestGrafcetDocks::init()
{
    m_window = editortest::showEnglishMainWindow(m_translators);
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
}

void TestGrafcetDocks::cleanup()
{
    m_window.reset();
    m_translators.reset();
}

void TestGrafcetDocks::loadExample(const QString& file)
{
    QString error;
    QVERIFY2(m_window->document()->load(QStringLiteral(GGSTUDIO_EXAMPLES_DIR "/") + file, &error), qPrintable(error));
}

GrafcetView* TestGrafcetDocks::openF1()
{
    loadExample();
    if (!m_window->openNestedGrafcet(kF1))
        return nullptr;
    return m_window->grafcetView(kF1);
}

// The table's columns come from the action's text and go back to it without
// losing a character, whatever the user wrote.
void TestGrafcetDocks::actionPartsSplitAndJoinTexts()
{
    using Q = GrafcetActionParts::Qualifier;
    const GrafcetActionParts conditional = GrafcetActionParts::of({core::ActionTiming::Continuous, "N Valve IF Level < 10"});
    QCOMPARE(conditional.qualifier, Q::N);
    QCOMPARE(conditional.variable, QStringLiteral("Valve"));
    QCOMPARE(conditional.operand, QStringLiteral("Level < 10"));
    const GrafcetActionParts assign = GrafcetActionParts::of({core::ActionTiming::OnActivation, "Count := Count + 1"});
    QCOMPARE(assign.qualifier, Q::Assign);
    QCOMPARE(assign.variable, QStringLiteral("Count"));
    QCOMPARE(assign.operand, QStringLiteral("Count + 1"));
    for (const core::GrafcetAction& action : std::initializer_list<core::GrafcetAction>{
             {core::ActionTiming::Continuous, "N Valve IF Level < 10"},
             {core::ActionTiming::Continuous, "Complete"},
             {core::ActionTiming::OnActivation, "S Complete"},
             {core::ActionTiming::OnDeactivation, "R Lamp"},
             {core::ActionTiming::OnActivation, "Count := Count + 1"},
             {core::ActionTiming::Continuous, "Lamp IF X3"}})
        QCOMPARE(fromStd(GrafcetActionParts::of(action).action().text), fromStd(action.text));

    // N acts while the step is active, S, R and := when it changes: each choice keeps the other right.
    GrafcetActionParts parts = GrafcetActionParts::of({core::ActionTiming::Continuous, "N Lamp"});
    parts.setQualifier(Q::S);
    QCOMPARE(parts.timing, core::ActionTiming::OnActivation);
    QCOMPARE(fromStd(parts.action().text), QStringLiteral("S Lamp"));
    parts.setTiming(core::ActionTiming::Continuous);
    QCOMPARE(parts.qualifier, Q::N);
    QCOMPARE(fromStd(parts.action().text), QStringLiteral("N Lamp"));
}

// A GRAFCET's tab draws one item per step and per transition of the model.
void TestGrafcetDocks::tabHasAnItemPerElement()
{
    GrafcetView* view = openF1();
    QVERIFY(view);
    QCOMPARE(m_window->centralTabs()->currentWidget(), static_cast<QWidget*>(view));
    GrafcetScene* scene = view->grafcetScene();
    QCOMPARE(editortest::countItems<GrafcetStepItem>(*scene), static_cast<int>(f1().steps().size()));
    QCOMPARE(editortest::countItems<GrafcetTransitionItem>(*scene), static_cast<int>(f1().transitions().size()));
    for (const core::GrafcetStep& step : f1().steps()) {
        QVERIFY(scene->stepItem(step.number));
        QVERIFY(scene->stepItem(step.number)->flags() & QGraphicsItem::ItemIsSelectable);
    }
    for (const core::GrafcetTransition& transition : f1().transitions())
        QVERIFY(scene->transitionItem(transition.number));
}

// Clicking a transition's bar selects that nested transition: its dock shows
// its receptivity; clicking a step shows the Nested Step dock; clicking the
// empty paper selects nothing.
void TestGrafcetDocks::clickingAnItemSelectsItForTheDocks()
{
    GrafcetView* view = openF1();
    QVERIFY(view);
    GrafcetTransitionItem* t3 = f1Scene()->transitionItem(3);
    view->ensureVisible(t3);
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->mapFromScene(barCenterOf(*t3, *f1Scene())));
    QCOMPARE(m_window->selection()->current(), ElementRef::grafcetTransition(kF1, 3));
    QVERIFY(f1Scene()->transitionItem(3)->isSelected());
    auto* transitionDock = child<GrafcetTransitionDock>("grafcetTransitionDock");
    QVERIFY(transitionDock);
    QTRY_VERIFY(!transitionDock->visibleRegion().isEmpty()); // brought in front of the Step dock
    QCOMPARE(transitionDock->receptivityEdit()->text(), QStringLiteral("DrillLow"));
    QCOMPARE(child<QLabel>("upstreamSteps")->text().contains(QStringLiteral(">3<")), true);
    QCOMPARE(child<QLabel>("downstreamSteps")->text().contains(QStringLiteral(">4<")), true);

    GrafcetStepItem* step2 = f1Scene()->stepItem(2);
    view->ensureVisible(step2);
    const QRectF box(step2->layout().box.x, step2->layout().box.y, step2->layout().box.width, step2->layout().box.height);
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->mapFromScene(box.center()));
    QCOMPARE(m_window->selection()->current(), ElementRef::grafcetStep(kF1, 2));
    QVERIFY(step2->isSelected());
    QVERIFY(!f1Scene()->transitionItem(3)->isSelected());
    QCOMPARE(child<QSpinBox>("numberSpin")->value(), 2);
    QCOMPARE(child<QPlainTextEdit>("nestedCommentEdit")->toPlainText(), QStringLiteral("Clamp the part"));

    // The paper beside the drawing: nothing.
    const QRectF rect = f1Scene()->sceneRect();
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->mapFromScene(rect.left() + 2, rect.top() + 2));
    QVERIFY(m_window->selection()->current().isNull());
    QVERIFY(f1Scene()->selectedItems().isEmpty());
}

// The Selection choosing a nested element (a link, the Problems dock) selects
// its item, and the view scrolls to it; the selection survives the
// rebuilding of the drawing after an edit.
void TestGrafcetDocks::selectingElsewhereSelectsTheItemAndScrolls()
{
    GrafcetView* view = openF1();
    QVERIFY(view);
    view->verticalScrollBar()->setValue(0);
    m_window->selection()->select(ElementRef::grafcetStep(kF1, 9)); // at the bottom of the drawing
    QVERIFY(f1Scene()->stepItem(9)->isSelected());
    const QRectF shown = view->mapToScene(view->viewport()->rect()).boundingRect();
    QVERIFY(shown.intersects(f1Scene()->stepItem(9)->sceneBoundingRect()));

    // Back to the chart tab: a nested selection brings its GRAFCET's tab to the front.
    m_window->centralTabs()->setCurrentIndex(0);
    m_window->selection()->select(ElementRef::grafcetTransition(kF1, 7));
    QCOMPARE(m_window->centralTabs()->currentWidget(), static_cast<QWidget*>(view));
    QVERIFY(f1Scene()->transitionItem(7)->isSelected());
    QVERIFY(!f1Scene()->stepItem(9)->isSelected());

    // An edit lays the drawing out again with new items: the new one is selected.
    child<GrafcetTransitionDock>("grafcetTransitionDock")->receptivityEdit()->selectRange(0, 0);
    QTest::keyClicks(child<GrafcetTransitionDock>("grafcetTransitionDock")->receptivityEdit(), "(");
    QVERIFY(f1Scene()->transitionItem(7)->isSelected());
    QCOMPARE(m_window->selection()->current(), ElementRef::grafcetTransition(kF1, 7));
}

// Typing in the Nested Transition dock changes the model and the drawn
// label at each key, as one undo step named after the transition; undo
// restores the model, the label and the dock.
void TestGrafcetDocks::typedReceptivityIsOneUndoStep()
{
    QVERIFY(openF1());
    m_window->selection()->select(ElementRef::grafcetTransition(kF1, 3));
    ConditionEdit* edit = child<GrafcetTransitionDock>("grafcetTransitionDock")->receptivityEdit();
    QCOMPARE(edit->text(), QStringLiteral("DrillLow"));
    const int before = undoStack()->count();
    edit->selectRange(8, 8);
    QTest::keyClicks(edit, " OR 10s/X3");
    QCOMPARE(fromStd(f1().transition(3)->receptivity), QStringLiteral("DrillLow OR 10s/X3"));
    QCOMPARE(f1Scene()->transitionItem(3)->labelText(), QStringLiteral("DrillLow OR 10s/X3"));
    QCOMPARE(undoStack()->count(), before + 1);
    QCOMPARE(undoStack()->undoText(), QStringLiteral("Set receptivity of F1 T3"));
    QVERIFY2(edit->problems().isEmpty(), qPrintable(edit->problems().value(0).message));

    // Edges are drawn as IEC 60848 writes them.
    edit->selectRange(0, static_cast<int>(edit->text().size()));
    QTest::keyClicks(edit, "RE DrillLow");
    QCOMPARE(f1Scene()->transitionItem(3)->labelText(), QStringLiteral("↑DrillLow"));
    QCOMPARE(undoStack()->count(), before + 1); // still the same typing

    undoStack()->undo();
    QCOMPARE(fromStd(f1().transition(3)->receptivity), QStringLiteral("DrillLow"));
    QCOMPARE(f1Scene()->transitionItem(3)->labelText(), QStringLiteral("DrillLow"));
    QCOMPARE(edit->text(), QStringLiteral("DrillLow"));
    undoStack()->redo();
    QCOMPARE(f1Scene()->transitionItem(3)->labelText(), QStringLiteral("↑DrillLow"));
    QCOMPARE(edit->text(), QStringLiteral("RE DrillLow"));
}

// Typing in a receptivity most often changes only its label: the items stay
// (the selection with them), the layout is the one a new drawing would
// have. A label that moves the rest, or a change of structure (an initial
// step, drawn double), makes the items again.
void TestGrafcetDocks::typingRelabelsTheDrawingInPlace()
{
    QVERIFY(openF1());
    GrafcetScene* scene = f1Scene();
    m_window->selection()->select(ElementRef::grafcetTransition(kF1, 3));
    GrafcetStepItem* step = scene->stepItem(2);
    GrafcetTransitionItem* transition = scene->transitionItem(3);
    GrafcetWiringItem* wiring = scene->wiringItem();
    QVERIFY(step && transition && wiring && transition->isSelected());
    // Marked, so that an item made again at the same address is not taken for it.
    step->setData(0, QStringLiteral("kept"));
    transition->setData(0, QStringLiteral("kept"));
    wiring->setData(0, QStringLiteral("kept"));
    const auto kept = [](const QGraphicsItem* item) { return item && item->data(0).toString() == QLatin1String("kept"); };
    const QRectF drawing = scene->drawingRect();
    int rebuilt = 0;
    connect(scene, &GrafcetScene::rebuilt, this, [&rebuilt] { ++rebuilt; });

    ConditionEdit* edit = child<GrafcetTransitionDock>("grafcetTransitionDock")->receptivityEdit();
    edit->selectRange(8, 8);
    QTest::keyClicks(edit, " OR X4");
    QVERIFY(rebuilt >= 6); // its listeners (selection, simulation marks) still follow
    QVERIFY(kept(scene->stepItem(2)));
    QVERIFY(kept(scene->transitionItem(3)));
    QVERIFY(kept(scene->wiringItem())); // the drawing kept its width
    QVERIFY(transition->isSelected());
    QCOMPARE(transition->labelText(), QStringLiteral("DrillLow OR X4"));
    const core::GrafcetLayout fresh = core::layoutGrafcet(f1(), &GrafcetScene::textWidth);
    QVERIFY(fresh.transitions == scene->layout().transitions);
    QVERIFY(*fresh.transition(3) == transition->layout());
    QCOMPARE(scene->drawingRect(), drawing);

    // A label that moves the rest (the links routed around the widest)
    // makes the drawing again: the layout a new drawing has.
    QTest::keyClicks(edit, " OR DrillHigh AND ClampOut AND NOT Unclamped AND PartPresent AND SpindleOn");
    QVERIFY(!kept(scene->transitionItem(3)));
    QVERIFY(scene->drawingRect().width() > drawing.width());
    QCOMPARE(scene->sceneRect(), scene->drawingRect());
    const core::GrafcetLayout wider = core::layoutGrafcet(f1(), &GrafcetScene::textWidth);
    QVERIFY(wider.boundingRect == scene->layout().boundingRect);
    QVERIFY(wider.links == scene->layout().links);
    QVERIFY(*wider.transition(3) == scene->transitionItem(3)->layout());
    QVERIFY(scene->transitionItem(3)->isSelected());

    // Undone: the first label and width again.
    undoStack()->undo();
    QCOMPARE(scene->transitionItem(3)->labelText(), QStringLiteral("DrillLow"));
    QCOMPARE(scene->drawingRect(), drawing);
    step = scene->stepItem(2);
    step->setData(0, QStringLiteral("kept"));

    // Another structure: the items are made again.
    m_window->selection()->select(ElementRef::grafcetStep(kF1, 2));
    child<QCheckBox>("nestedInitialCheck")->click();
    QVERIFY(f1().step(2)->initial);
    QVERIFY(!kept(scene->stepItem(2)));
    QVERIFY(scene->stepItem(2)->layout().initial);
}

// The nested checks' problems are underlined where they are, with their messages.
void TestGrafcetDocks::receptivityProblemsAreUnderlined()
{
    QVERIFY(openF1());
    m_window->selection()->select(ElementRef::grafcetTransition(kF1, 3));
    ConditionEdit* edit = child<GrafcetTransitionDock>("grafcetTransitionDock")->receptivityEdit();
    edit->selectRange(0, static_cast<int>(edit->text().size()));
    QTest::keyClicks(edit, "DrillLow AND X42");
    QCOMPARE(edit->problems().size(), 1);
    const ConditionEdit::Problem& problem = edit->problems().front();
    QCOMPARE(edit->text().mid(problem.begin, problem.end - problem.begin), QStringLiteral("X42"));
    QVERIFY2(problem.message.contains(QStringLiteral("42")), qPrintable(problem.message));
    QVERIFY(problem.error);
    QVERIFY(!edit->extraSelections().isEmpty());

    edit->selectRange(0, static_cast<int>(edit->text().size()));
    QTest::keyClicks(edit, "DrillLow AND");
    QCOMPARE(edit->problems().size(), 1);
    QVERIFY(!edit->problems().front().message.isEmpty());
}

// Completion offers the declared variables, this GRAFCET's step activities and Complete.
void TestGrafcetDocks::receptivityCompletesStepsAndVariables()
{
    QVERIFY(openF1());
    m_window->selection()->select(ElementRef::grafcetTransition(kF1, 3));
    ConditionEdit* edit = child<GrafcetTransitionDock>("grafcetTransitionDock")->receptivityEdit();
    QCompleter* completer = edit->completer();
    const QStringList names = qobject_cast<QStringListModel*>(completer->model())
        ? qobject_cast<QStringListModel*>(completer->model())->stringList()
        : QStringList();
    for (const core::GrafcetStep& step : f1().steps())
        QVERIFY2(names.contains(QStringLiteral("X%1").arg(step.number)), qPrintable(names.join(u',')));
    QVERIFY(names.contains(QStringLiteral("DrillLow")));
    QVERIFY(names.contains(QStringLiteral("Complete")));
    QVERIFY(!names.contains(QStringLiteral("X10"))); // F1 has no step 10
}

void TestGrafcetDocks::stepDockEditsInitialAndComment()
{
    QVERIFY(openF1());
    m_window->selection()->select(ElementRef::grafcetStep(kF1, 2));
    auto* initial = child<QCheckBox>("nestedInitialCheck");
    QVERIFY(!initial->isChecked());
    initial->click();
    QVERIFY(f1().step(2)->initial);
    QCOMPARE(undoStack()->undoText(), QStringLiteral("Make F1 step 2 initial"));
    undoStack()->undo();
    QVERIFY(!f1().step(2)->initial);
    QVERIFY(!initial->isChecked());

    auto* comment = child<QPlainTextEdit>("nestedCommentEdit");
    const int before = undoStack()->index();
    comment->setFocus();
    comment->moveCursor(QTextCursor::End);
    QTest::keyClicks(comment, " firmly");
    QCOMPARE(fromStd(f1().step(2)->comment), QStringLiteral("Clamp the part firmly"));
    QCOMPARE(undoStack()->index(), before + 1); // one step for the whole typing
    QCOMPARE(undoStack()->undoText(), QStringLiteral("Edit comment of F1 step 2"));
    undoStack()->undo();
    QCOMPARE(comment->toPlainText(), QStringLiteral("Clamp the part"));
}

// A number in use is refused with a message; a free one renumbers the step
// (the drawing follows, the selection with it) as one undo step.
void TestGrafcetDocks::renumberingRefusesAUsedNumber()
{
    QVERIFY(openF1());
    m_window->selection()->select(ElementRef::grafcetStep(kF1, 2));
    auto* spin = child<QSpinBox>("numberSpin");
    auto* message = child<WrappingLabel>("numberMessage");
    const int before = undoStack()->count();
    spin->setValue(3);
    QVERIFY(message->isVisibleTo(message->window()));
    QVERIFY2(message->text().contains(QStringLiteral("3")), qPrintable(message->text()));
    QCOMPARE(spin->value(), 2);
    QCOMPARE(undoStack()->count(), before);
    QVERIFY(f1().step(2));

    spin->setValue(20);
    QVERIFY(!message->isVisibleTo(message->window()));
    QVERIFY(f1().step(20) && !f1().step(2));
    QCOMPARE(fromStd(f1().step(20)->comment), QStringLiteral("Clamp the part"));
    QCOMPARE(undoStack()->undoText(), QStringLiteral("Renumber F1 step 2 to 20"));
    QCOMPARE(m_window->selection()->current(), ElementRef::grafcetStep(kF1, 20));
    QVERIFY(f1Scene()->stepItem(20) && f1Scene()->stepItem(20)->isSelected());
    QVERIFY(!f1Scene()->stepItem(2));
    undoStack()->undo();
    QVERIFY(f1().step(2) && !f1().step(20));
    QVERIFY(f1Scene()->stepItem(2));
}

// Editing a cell of the actions table is one command for that action; undo restores it.
void TestGrafcetDocks::actionCellEditIsOneCommand()
{
    QVERIFY(openF1());
    m_window->selection()->select(ElementRef::grafcetStep(kF1, 3));
    auto* dock = child<GrafcetStepDock>("grafcetStepDock");
    GrafcetActionsModel* model = dock->actionsModel();
    QCOMPARE(model->rowCount(), 3);
    QCOMPARE(model->index(2, GrafcetActionsModel::QualifierColumn).data().toString(), QStringLiteral("N"));
    QCOMPARE(model->index(2, GrafcetActionsModel::VariableColumn).data().toString(), QStringLiteral("Coolant"));
    QCOMPARE(model->index(2, GrafcetActionsModel::OperandColumn).data().toString(), QStringLiteral("NOT DrillHigh"));

    QVERIFY(model->setData(model->index(2, GrafcetActionsModel::OperandColumn), QStringLiteral("X3 AND NOT DrillHigh")));
    QCOMPARE(fromStd(f1().step(3)->actions[2].text), QStringLiteral("N Coolant IF X3 AND NOT DrillHigh"));
    QCOMPARE(undoStack()->undoText(), QStringLiteral("Set action 3 of F1 step 3"));
    // The drawing shows the new condition under the action's box.
    bool drawn = false;
    for (const core::GrafcetActionLayout& action : f1Scene()->stepItem(3)->layout().actions)
        drawn = drawn || fromStd(action.condition).contains(QStringLiteral("X3 AND NOT DrillHigh"));
    QVERIFY(drawn);

    // Choosing S makes it a stored action on activation.
    QVERIFY(model->setData(model->index(0, GrafcetActionsModel::QualifierColumn), QStringLiteral("S")));
    QCOMPARE(f1().step(3)->actions[0].timing, core::ActionTiming::OnActivation);
    QCOMPARE(fromStd(f1().step(3)->actions[0].text), QStringLiteral("S Spindle"));
    QCOMPARE(model->index(0, GrafcetActionsModel::TimingColumn).data().toString(), QStringLiteral("On activation"));
    undoStack()->undo();
    QCOMPARE(f1().step(3)->actions[0].timing, core::ActionTiming::Continuous);
    undoStack()->undo();
    QCOMPARE(fromStd(f1().step(3)->actions[2].text), QStringLiteral("N Coolant IF NOT DrillHigh"));
    QCOMPARE(model->index(2, GrafcetActionsModel::OperandColumn).data().toString(), QStringLiteral("NOT DrillHigh"));
}

// Each cell of a new action edits its own part, whatever the order: a
// qualifier chosen before the variable is no variable called "S".
void TestGrafcetDocks::actionCellsEditTheirOwnPartInAnyOrder()
{
    QVERIFY(openF1());
    m_window->selection()->select(ElementRef::grafcetStep(kF1, 3));
    auto* dock = child<GrafcetStepDock>("grafcetStepDock");
    GrafcetActionsModel* model = dock->actionsModel();
    const auto addAction = [&] {
        const int row = int(f1().step(3)->actions.size());
        Document* document = m_window->document();
        const core::GrafcetAction empty{core::ActionTiming::Continuous, ""};
        return document->push(new AddGrafcetActionCommand(*document, kF1, 3, row, empty)) ? row : -1;
    };
    const auto set = [&](int row, int column, const QString& value) {
        return model->setData(model->index(row, column), value);
    };
    const auto cell = [&](int row, int column) { return model->index(row, column).data().toString(); };
    using M = GrafcetActionsModel;

    // The qualifier first, then the variable.
    const int first = addAction();
    QVERIFY(set(first, M::QualifierColumn, QStringLiteral("S")));
    QCOMPARE(cell(first, M::QualifierColumn), QStringLiteral("S"));
    QVERIFY(cell(first, M::VariableColumn).isEmpty());
    QCOMPARE(f1().step(3)->actions[std::size_t(first)].timing, core::ActionTiming::OnActivation);
    QVERIFY(set(first, M::VariableColumn, QStringLiteral("Marker")));
    QCOMPARE(fromStd(f1().step(3)->actions[std::size_t(first)].text), QStringLiteral("S Marker"));
    QCOMPARE(cell(first, M::QualifierColumn), QStringLiteral("S"));
    QCOMPARE(cell(first, M::VariableColumn), QStringLiteral("Marker"));

    // R, which the timing alone cannot tell from S, and the other order on the next rows.
    const int reset = addAction();
    QVERIFY(set(reset, M::QualifierColumn, QStringLiteral("R")));
    QCOMPARE(cell(reset, M::QualifierColumn), QStringLiteral("R"));
    QVERIFY(set(reset, M::VariableColumn, QStringLiteral("Marker")));
    QCOMPARE(fromStd(f1().step(3)->actions[std::size_t(reset)].text), QStringLiteral("R Marker"));

    const int second = addAction();
    QVERIFY(set(second, M::VariableColumn, QStringLiteral("Marker")));
    QVERIFY(set(second, M::QualifierColumn, QStringLiteral("S")));
    QCOMPARE(fromStd(f1().step(3)->actions[std::size_t(second)].text), QStringLiteral("S Marker"));
    QCOMPARE(f1().step(3)->actions[std::size_t(second)].timing, core::ActionTiming::OnActivation);

    // The condition before the variable: no variable called "IF ...".
    const int conditional = addAction();
    QVERIFY(set(conditional, M::OperandColumn, QStringLiteral("NOT DrillHigh")));
    QVERIFY(cell(conditional, M::VariableColumn).isEmpty());
    QCOMPARE(cell(conditional, M::OperandColumn), QStringLiteral("NOT DrillHigh"));
    QVERIFY(set(conditional, M::VariableColumn, QStringLiteral("Marker")));
    QCOMPARE(fromStd(f1().step(3)->actions[std::size_t(conditional)].text),
             QStringLiteral("N Marker IF NOT DrillHigh"));

    // An assignment's value before its variable.
    const int assigned = addAction();
    QVERIFY(set(assigned, M::QualifierColumn, QStringLiteral(":=")));
    QVERIFY(set(assigned, M::OperandColumn, QStringLiteral("TRUE")));
    QVERIFY(set(assigned, M::VariableColumn, QStringLiteral("Marker")));
    QCOMPARE(fromStd(f1().step(3)->actions[std::size_t(assigned)].text), QStringLiteral("Marker := TRUE"));

    // Texts of a file are read as the action parser reads them: a lone
    // qualifier letter before IF or := is the variable.
    for (const char* text : {"N IF Level < 10", "S := 1"}) {
        const GrafcetActionParts parts = GrafcetActionParts::of({core::ActionTiming::Continuous, text});
        QCOMPARE(parts.variable, QString(QLatin1Char(text[0])));
        QCOMPARE(fromStd(parts.action().text), QString::fromLatin1(text));
    }
}

// A cell typed wrong says why at once, before anything is committed; a
// committed wrong action is red with the checks' message.
void TestGrafcetDocks::actionTypedWrongShowsTheError()
{
    QVERIFY(openF1());
    m_window->selection()->select(ElementRef::grafcetStep(kF1, 3));
    auto* dock = child<GrafcetStepDock>("grafcetStepDock");
    QTRY_VERIFY(!dock->visibleRegion().isEmpty());
    GrafcetActionsModel* model = dock->actionsModel();
    QTableView* view = dock->actionsView();
    const QModelIndex cell = model->index(2, GrafcetActionsModel::OperandColumn);
    view->setCurrentIndex(cell);
    view->edit(cell);
    auto* editor = view->findChild<QLineEdit*>(QStringLiteral("actionOperandEdit"));
    QVERIFY(editor);
    editor->selectAll();
    QTest::keyClicks(editor, "NOT AND");
    auto* message = child<WrappingLabel>("actionMessage");
    QVERIFY(message->isVisibleTo(message->window()));
    QVERIFY(!message->text().isEmpty());
    QCOMPARE(editor->toolTip(), message->text());
    QCOMPARE(editor->palette().color(QPalette::Text), chartstyle::problemColor());
    QCOMPARE(fromStd(f1().step(3)->actions[2].text), QStringLiteral("N Coolant IF NOT DrillHigh")); // not yet
    editor->selectAll();
    QTest::keyClicks(editor, "NOT DrillLow");
    QVERIFY(editor->toolTip().isEmpty());

    // Committed wrong (an input written by an action): the row turns red with the checks' message.
    QVERIFY(model->setData(model->index(1, GrafcetActionsModel::VariableColumn), QStringLiteral("DrillLow")));
    QCOMPARE(model->index(1, GrafcetActionsModel::VariableColumn).data(Qt::ForegroundRole).value<QColor>(),
             chartstyle::problemColor());
    QVERIFY(!model->problemText(1).isEmpty());
    view->setCurrentIndex(model->index(1, GrafcetActionsModel::VariableColumn));
    QCOMPARE(message->text(), model->problemText(1));
}

void TestGrafcetDocks::actionButtonsAddMoveAndRemove()
{
    QVERIFY(openF1());
    m_window->selection()->select(ElementRef::grafcetStep(kF1, 3));
    auto* dock = child<GrafcetStepDock>("grafcetStepDock");
    GrafcetActionsModel* model = dock->actionsModel();
    QTableView* view = dock->actionsView();
    view->setCurrentIndex(model->index(0, GrafcetActionsModel::VariableColumn));
    child<QToolButton>("addActionButton")->click();
    QCOMPARE(f1().step(3)->actions.size(), std::size_t(4));
    QCOMPARE(undoStack()->undoText(), QStringLiteral("Add action 2 to F1 step 3"));
    QCOMPARE(view->currentIndex().row(), 1);
    auto* editor = view->findChild<QLineEdit*>(QStringLiteral("actionVariableEdit"));
    QVERIFY(editor); // the new action's variable is being typed
    QTest::keyClicks(editor, "Marker");
    QTest::keyClick(editor, Qt::Key_Return); // the view commits after the editor had the key
    QTRY_COMPARE(fromStd(f1().step(3)->actions[1].text), QStringLiteral("N Marker"));

    view->setCurrentIndex(model->index(1, GrafcetActionsModel::VariableColumn));
    child<QToolButton>("moveActionDownButton")->click();
    QCOMPARE(fromStd(f1().step(3)->actions[2].text), QStringLiteral("N Marker"));
    QCOMPARE(undoStack()->undoText(), QStringLiteral("Move action 2 of F1 step 3 down"));
    QCOMPARE(view->currentIndex().row(), 2);
    child<QToolButton>("moveActionUpButton")->click();
    QCOMPARE(fromStd(f1().step(3)->actions[1].text), QStringLiteral("N Marker"));
    child<QToolButton>("removeActionButton")->click();
    QCOMPARE(f1().step(3)->actions.size(), std::size_t(3));
    QCOMPARE(undoStack()->undoText(), QStringLiteral("Remove action 2 of F1 step 3"));
    undoStack()->undo();
    QCOMPARE(fromStd(f1().step(3)->actions[1].text), QStringLiteral("N Marker"));
    QCOMPARE(model->rowCount(), 4);
}

// Double-clicking a nested problem opens its GRAFCET's tab, selects the
// element there and focuses the field at fault.
void TestGrafcetDocks::problemsDockSelectsTheNestedElement()
{
    loadExample(QStringLiteral("drilling-cell-faulty.ggstudio.json"));
    auto* problems = child<ProblemsDock>("problemsDock");
    QVERIFY(problems);
    QTreeWidgetItem* receptivityProblem = nullptr;
    for (QTreeWidgetItemIterator it(problems->view()); *it && !receptivityProblem; ++it) {
        if ((*it)->text(ProblemsDock::ElementColumn).contains(QRegularExpression(QStringLiteral("^[A-Z]\\d+ T\\d+$"))))
            receptivityProblem = *it;
    }
    QVERIFY(receptivityProblem);
    const QString label = receptivityProblem->text(ProblemsDock::ElementColumn); // "F1 T2"
    const QString stepId = label.section(u' ', 0, 0);
    const int number = label.section(u' ', 1).mid(1).toInt();
    emit problems->view()->itemActivated(receptivityProblem, 0);
    QCOMPARE(m_window->selection()->current(), ElementRef::grafcetTransition(stepId, number));
    GrafcetView* view = m_window->grafcetView(stepId);
    QVERIFY(view);
    QCOMPARE(m_window->centralTabs()->currentWidget(), static_cast<QWidget*>(view));
    QVERIFY(view->grafcetScene()->transitionItem(number)->isSelected());
    auto* dock = child<GrafcetTransitionDock>("grafcetTransitionDock");
    QTRY_VERIFY(dock->receptivityEdit()->hasFocus());
}

// With a GRAFCET's tab in front the Structured Text dock shows its function
// block and the code of the selected nested element; with the chart in
// front, the GEMMA program again.
void TestGrafcetDocks::structuredTextFollowsTheTabInFront()
{
    auto* preview = child<StPreviewDock>("stPreviewDock");
    QVERIFY(preview);
    preview->raise();
    QVERIFY(openF1());
    QCOMPARE(preview->grafcetInFront(), kF1);
    preview->updatePreview();
    QVERIFY(preview->editor()->toPlainText().contains(QStringLiteral("\nFUNCTION_BLOCK F1_FB\n")));
    QVERIFY(!preview->editor()->toPlainText().contains(QStringLiteral("PROGRAM GEMMA")));
    m_window->selection()->select(ElementRef::grafcetTransition(kF1, 4));
    QVERIFY(!preview->highlightedRanges().empty());
    const core::LineRange& range = preview->highlightedRanges().front();
    QString highlighted;
    for (int line = range.first; line <= range.last; ++line)
        highlighted += preview->editor()->document()->findBlockByNumber(line - 1).text();
    QVERIFY2(highlighted.contains(QStringLiteral("GG_Fire4")), qPrintable(highlighted));
    QVERIFY(!preview->editor()->extraSelections().isEmpty());

    m_window->centralTabs()->setCurrentIndex(0);
    QVERIFY(preview->grafcetInFront().isEmpty());
    preview->updatePreview();
    QVERIFY(preview->editor()->toPlainText().contains(QStringLiteral("PROGRAM GEMMA")));
    QVERIFY(!preview->editor()->toPlainText().contains(QStringLiteral("FUNCTION_BLOCK")));
    QVERIFY(preview->highlightedRanges().empty()); // a nested element has no lines in the GEMMA program
}

QTEST_MAIN(TestGrafcetDocks)
#include "test_grafcetdocks.moc"
