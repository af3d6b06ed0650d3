// The GEMMA chart: items built from the template layout, kept in step with
// the Document and the Selection.

#include "editortestsupport.h"

#include "editor/chart/chartstyle.h"
#include "editor/chart/gemma/chartscene.h"
#include "editor/chart/gemma/chartview.h"
#include "editor/chart/gemma/frameitem.h"
#include "editor/chart/gemma/stepitem.h"
#include "editor/chart/gemma/transitionitem.h"
#include "editor/commands/addvariablecommand.h"
#include "editor/commands/setconditioncommand.h"
#include "editor/commands/setnegatedcommand.h"
#include "editor/commands/setstephiddencommand.h"
#include "editor/commands/setsteptypecommand.h"
#include "editor/document.h"
#include "editor/selection.h"
#include "editor/text/gemmastatenames.h"

#include "core/templates/gemma/gemmachartlayout.h"
#include "core/templates/gemma/gemmatemplate.h"

#include <QApplication>
#include <QFontMetricsF>
#include <QHelpEvent>
#include <QImage>
#include <QMouseEvent>
#include <QPainter>
#include <QScrollBar>
#include <QStyleOptionGraphicsItem>
#include <QTest>
#include <QToolTip>
#include <QTranslator>
#include <QWheelEvent>
#include <QUndoStack>

using namespace editor;
using editortest::countItems;

namespace {

core::Variable boolVariable(const char* name)
{
    core::Variable variable;
    variable.name = name;
    variable.type = core::IecType::Bool;
    return variable;
}


} // namespace

class TestChart : public QObject {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void buildsTheTemplate();
    void framesAreTitledInFamilyOrder();
    void officialNamesMatchTheTemplate();
    void hidingAStepHidesItsTransitions();
    void hiddenElementsFadeWhenShown();
    void prioritiesFollowVisibility();
    void sceneSelectionSetsTheSelection();
    void selectionSelectsTheItem();
    void selectionSurvivesHidingTheItem();
    void clickSelects();
    void dragPansFromTheFirstFrameOn();
    void tabWalksStepsThenTransitions();
    void tabSkipsHiddenElements();
    void labelShowsPriorityAndCondition();
    void labelWithoutChoiceHasNoPriority();
    void negatedPriorityIsOverlined();
    void negatedPriorityStandsOut();
    void selectionHaloStaysBelowTheMarks();
    void longConditionIsElided();
    void exportNoteEndsACutCondition();
    void undeclaredVariableMarksTheTransition();
    void hiddenInitialStepIsMarked();
    void stepTypeChangeRepaintsOnlyThatStep();
    void stepWithANestedGrafcetIsMarked();
    void activeStepIsMarked();
    void zoomSlots();
    void ctrlWheelZoomsAboutTheMouse();
    void tabLeavesPastTheLastElement();
    void replacedModelIsShown();
    void languageChangeRetranslatesTooltips();
    void hoverShowsTheTooltipOfTheItem();
    void marginsTileTheArea();
    void backgroundCoversEveryPixel();
    void bigStepIdsAreDrawnLarger();
    void labelWidthIsTheShownText();
    void shapeFollowsTheLabel();

private:
    Document* m_document = nullptr;
    Selection* m_selection = nullptr;
    ChartScene* m_scene = nullptr;
};

void TestChart::init()
{
    m_document = new Document;
    m_selection = new Selection;
    m_scene = new ChartScene(m_document, m_selection);
}

void TestChart::cleanup()
{
    delete m_scene;
    delete m_selection;
    delete m_document;
}

void TestChart::buildsTheTemplate()
{
    QCOMPARE(countItems<StepItem>(*m_scene), 16);
    QCOMPARE(countItems<TransitionItem>(*m_scene), 34);
    QCOMPARE(countItems<FrameItem>(*m_scene), 3);
    QCOMPARE(m_scene->steps().size(), 16);
    QCOMPARE(m_scene->transitions().size(), 34);
    QVERIFY(m_scene->stepItem("F1"));
    QVERIFY(m_scene->transitionItem("F->D1"));
    for (const QGraphicsItem* item : m_scene->items())
        QVERIFY(!(item->flags() & QGraphicsItem::ItemIsMovable));
    // Every template element is visible by default.
    for (const StepItem* item : m_scene->steps())
        QVERIFY2(item->isVisible(), qPrintable(item->id()));
    for (const TransitionItem* item : m_scene->transitions())
        QVERIFY2(item->isVisible(), qPrintable(item->id()));
}

void TestChart::framesAreTitledInFamilyOrder()
{
    QVERIFY(m_scene->frameItem(core::Family::A)->title().contains("Stop procedures"));
    QVERIFY(m_scene->frameItem(core::Family::F)->title().contains("Operation procedures"));
    QVERIFY(m_scene->frameItem(core::Family::D)->title().contains("Failure procedures"));
    QVERIFY(m_scene->frameItem(core::Family::D)->title().startsWith("D"));
}

void TestChart::officialNamesMatchTheTemplate()
{
    for (const core::TemplateState& state : core::templateStates()) {
        const QString id = QString::fromUtf8(state.id.data(), state.id.size());
        QCOMPARE(officialStateName(id), QString::fromUtf8(state.englishName.data(), state.englishName.size()));
    }
    QVERIFY(officialStateName("Z9").isEmpty());
    QVERIFY(m_scene->stepItem("F1")->toolTipText().contains("Normal production"));
}

void TestChart::hidingAStepHidesItsTransitions()
{
    m_document->push(new SetStepHiddenCommand(*m_document, "F2", true));
    QVERIFY(!m_scene->stepItem("F2")->isVisible());
    QVERIFY(!m_scene->transitionItem("A1->F2")->isVisible());
    QVERIFY(!m_scene->transitionItem("F2->F1")->isVisible());
    QVERIFY(m_scene->transitionItem("A1->F1")->isVisible());

    m_document->undoStack()->undo();
    QVERIFY(m_scene->stepItem("F2")->isVisible());
    QVERIFY(m_scene->transitionItem("A1->F2")->isVisible());
    QVERIFY(m_scene->transitionItem("F2->F1")->isVisible());
}

void TestChart::hiddenElementsFadeWhenShown()
{
    m_document->push(new SetStepHiddenCommand(*m_document, "F2", true));
    m_scene->setShowHidden(true);
    StepItem* step = m_scene->stepItem("F2");
    TransitionItem* transition = m_scene->transitionItem("F2->F1");
    QVERIFY(step->isVisible());
    QVERIFY(transition->isVisible());
    QVERIFY(step->opacity() < 0.5);
    QVERIFY(transition->opacity() < 0.5);
    QCOMPARE(m_scene->stepItem("F1")->opacity(), 1.0);

    m_scene->setShowHidden(false);
    QVERIFY(!step->isVisible());
    QVERIFY(!transition->isVisible());
}

void TestChart::prioritiesFollowVisibility()
{
    m_document->push(new SetConditionCommand(*m_document, "F1->A2", "Stop"));
    QCOMPARE(m_scene->transitionItem("F1->A2")->labelText(), QString("3: Stop"));
    // D3 is the target of F1's second transition: F1->A2 moves up.
    m_document->push(new SetStepHiddenCommand(*m_document, "D3", true));
    QCOMPARE(m_scene->transitionItem("F1->A2")->labelText(), QString("2: Stop"));
    m_document->undoStack()->undo();
    QCOMPARE(m_scene->transitionItem("F1->A2")->labelText(), QString("3: Stop"));
}

void TestChart::sceneSelectionSetsTheSelection()
{
    m_scene->stepItem("A3")->setSelected(true);
    QCOMPARE(m_selection->current(), ElementRef::step("A3"));
    m_scene->transitionItem("F1->A2")->setSelected(true);
    QCOMPARE(m_selection->current(), ElementRef::transition("F1->A2"));
    // Added to the selection (Ctrl+click, rubber band): both stay selected,
    // the docks show the one added last.
    QCOMPARE(m_scene->selectedItems().size(), 2);
    QCOMPARE(m_selection->elements().size(), 2);
    QVERIFY(m_selection->elements().contains(ElementRef::step("A3")));
    // Selecting one element programmatically selects it alone on the chart.
    m_selection->select(ElementRef::step("A4"));
    QCOMPARE(m_scene->selectedItems(), QList<QGraphicsItem*>{m_scene->stepItem("A4")});
    m_scene->clearSelection();
    QVERIFY(m_selection->current().isNull());
}

void TestChart::selectionSelectsTheItem()
{
    m_selection->select(ElementRef::step("D2"));
    QCOMPARE(m_scene->selectedItems(), QList<QGraphicsItem*>{m_scene->stepItem("D2")});
    m_selection->select(ElementRef::transition("A4->F1"));
    QCOMPARE(m_scene->selectedItems(), QList<QGraphicsItem*>{m_scene->transitionItem("A4->F1")});
    // A variable is not on the chart: nothing is selected there, and the
    // chart does not clear the variable selection.
    m_selection->select(ElementRef::variable("Start"));
    QVERIFY(m_scene->selectedItems().isEmpty());
    QCOMPARE(m_selection->current(), ElementRef::variable("Start"));
}

void TestChart::selectionSurvivesHidingTheItem()
{
    m_selection->select(ElementRef::step("F2"));
    m_document->push(new SetStepHiddenCommand(*m_document, "F2", true));
    QVERIFY(m_scene->selectedItems().isEmpty());
    QCOMPARE(m_selection->current(), ElementRef::step("F2"));
    m_scene->setShowHidden(true);
    QCOMPARE(m_scene->selectedItems(), QList<QGraphicsItem*>{m_scene->stepItem("F2")});
}

void TestChart::clickSelects()
{
    ChartView view(m_scene);
    view.resize(1000, 700);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const QPoint a4 = view.mapFromScene(m_scene->stepItem("A4")->sceneBoundingRect().center());
    QTest::mouseClick(view.viewport(), Qt::LeftButton, {}, a4);
    QCOMPARE(m_selection->current(), ElementRef::step("A4"));
    // A click on the empty sheet (inside the A frame) clears it.
    const QPoint empty = view.mapFromScene(QPointF(40, 300));
    QTest::mouseClick(view.viewport(), Qt::LeftButton, {}, empty);
    QVERIFY(m_selection->current().isNull());
}

void TestChart::dragPansFromTheFirstFrameOn()
{
    ChartView view(m_scene);
    // No cursor to load before the first frame.
    QCOMPARE(view.dragMode(), QGraphicsView::NoDrag);
    QVERIFY(!view.viewport()->testAttribute(Qt::WA_SetCursor));
    view.resize(1000, 700);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QTRY_COMPARE(view.dragMode(), QGraphicsView::ScrollHandDrag);
    QCOMPARE(view.viewport()->cursor().shape(), Qt::OpenHandCursor);

    // At 100 % the sheet is larger than the view: dragging the empty sheet
    // to the left scrolls it to the right.
    view.zoomToActualSize();
    QScrollBar* horizontal = view.horizontalScrollBar();
    horizontal->setValue(horizontal->minimum());
    const int before = horizontal->value();
    const QPoint from = view.mapFromScene(QPointF(40, 300));
    const QPoint to = from - QPoint(120, 0);
    QTest::mousePress(view.viewport(), Qt::LeftButton, {}, from);
    QMouseEvent move(QEvent::MouseMove, to, view.viewport()->mapToGlobal(to), Qt::NoButton, Qt::LeftButton, {});
    QApplication::sendEvent(view.viewport(), &move);
    QTest::mouseRelease(view.viewport(), Qt::LeftButton, {}, to);
    QCOMPARE(horizontal->value(), before + 120);
    QVERIFY(m_selection->current().isNull()); // panning selects nothing
}

void TestChart::tabWalksStepsThenTransitions()
{
    ChartView view(m_scene);
    QTest::keyClick(&view, Qt::Key_Tab);
    QCOMPARE(m_selection->current(), ElementRef::step("A1"));
    QTest::keyClick(&view, Qt::Key_Tab);
    QCOMPARE(m_selection->current(), ElementRef::step("A2"));
    QTest::keyClick(&view, Qt::Key_Tab, Qt::ShiftModifier);
    QCOMPARE(m_selection->current(), ElementRef::step("A1"));

    m_selection->select(ElementRef::step("D3")); // the last state
    QTest::keyClick(&view, Qt::Key_Tab);
    QCOMPARE(m_selection->current(), ElementRef::transition("F->D1")); // the first transition
    QTest::keyClick(&view, Qt::Key_Tab);
    QCOMPARE(m_selection->current(), ElementRef::transition("A1->F4"));
    QTest::keyClick(&view, Qt::Key_Backtab);
    QCOMPARE(m_selection->current(), ElementRef::transition("F->D1"));
    QTest::keyClick(&view, Qt::Key_Backtab);
    QCOMPARE(m_selection->current(), ElementRef::step("D3"));

    const QList<QGraphicsItem*> order = m_scene->tabOrder();
    QCOMPARE(order.size(), 16 + 34);
    QCOMPARE(order.first(), m_scene->stepItem("A1"));
    QCOMPARE(order.last(), m_scene->transitionItem("D3->D2"));
}

void TestChart::tabSkipsHiddenElements()
{
    m_document->push(new SetStepHiddenCommand(*m_document, "A2", true));
    ChartView view(m_scene);
    m_selection->select(ElementRef::step("A1"));
    QTest::keyClick(&view, Qt::Key_Tab);
    QCOMPARE(m_selection->current(), ElementRef::step("A3"));
    QVERIFY(!m_scene->tabOrder().contains(m_scene->transitionItem("A2->A1")));
}

void TestChart::labelShowsPriorityAndCondition()
{
    m_document->push(new SetConditionCommand(*m_document, "F1->A2", "NOT Stop"));
    const TransitionItem* item = m_scene->transitionItem("F1->A2");
    QCOMPARE(item->labelText(), QString("3: NOT Stop"));
    QVERIFY(item->priorityShown());
    QVERIFY(!item->priorityOverlined());
    QCOMPARE(item->displayedCondition(), QString("NOT Stop"));
    QVERIFY(item->toolTipText().contains("NOT Stop"));
}

void TestChart::labelWithoutChoiceHasNoPriority()
{
    m_document->push(new SetConditionCommand(*m_document, "A2->A1", "Start"));
    const TransitionItem* item = m_scene->transitionItem("A2->A1");
    QCOMPARE(item->labelText(), QString("Start"));
    QVERIFY(!item->priorityShown());
    // With one of its two transitions hidden, A5 has no choice left to show.
    m_document->push(new SetStepHiddenCommand(*m_document, "A7", true));
    m_document->push(new SetConditionCommand(*m_document, "A5->A6", "Reset"));
    QCOMPARE(m_scene->transitionItem("A5->A6")->labelText(), QString("Reset"));
}

void TestChart::negatedPriorityIsOverlined()
{
    QVERIFY(m_scene->transitionItem("F1->D1")->priorityOverlined()); // negated in the template
    TransitionItem* item = m_scene->transitionItem("F1->A2");
    QVERIFY(!item->priorityOverlined());
    m_document->push(new SetNegatedCommand(*m_document, "F1->A2", true));
    QVERIFY(item->priorityOverlined());
    m_document->undoStack()->undo();
    QVERIFY(!item->priorityOverlined());
}

namespace {
double darkShare(const TransitionItem* item, const QRectF& rect);
} // namespace

// At a glance: a negated transition's priority sits on a dark badge (most
// of its rectangle is ink), a plain priority is a digit on white.
void TestChart::negatedPriorityStandsOut()
{
    const TransitionItem* negated = m_scene->transitionItem("F1->D1");
    QVERIFY(darkShare(negated, negated->priorityRect()) > 0.5);
    TransitionItem* item = m_scene->transitionItem("F1->A2");
    QVERIFY(item->priorityShown());
    QVERIFY(darkShare(item, item->priorityRect()) < 0.35);
    m_document->push(new SetNegatedCommand(*m_document, "F1->A2", true));
    QVERIFY(darkShare(item, item->priorityRect()) > 0.5);
    // The condition keeps its place beside the badge, inside the label.
    QVERIFY(item->labelTextRect().contains(item->priorityRect().adjusted(0, 4, 0, -4)));
}

// A selected element's halo reaches past its outline; drawn below every
// other element, it never covers an arrowhead, a fired route or a token.
void TestChart::selectionHaloStaysBelowTheMarks()
{
    const core::TransitionLayout* layout = core::templateLayout().transition("A1->F2");
    QVERIFY(layout);
    // Inside the arrowhead, 2 units before its tip on F2's border: where the
    // step's halo reaches.
    const QPointF end(layout->route.back().x, layout->route.back().y);
    const QPointF before(layout->route[layout->route.size() - 2].x, layout->route[layout->route.size() - 2].y);
    const QPointF tip = end + (before - end) / QLineF(before, end).length() * 2;
    StepItem* step = m_scene->stepItem("F2");
    TransitionItem* transition = m_scene->transitionItem("A1->F2");
    // Painted last of the two where the halo reaches the arrowhead.
    const auto stepOnTop = [&] {
        const QList<QGraphicsItem*> items =
            m_scene->items(tip, Qt::IntersectsItemBoundingRect, Qt::DescendingOrder);
        return items.contains(step) && items.contains(transition)
            && items.indexOf(step) < items.indexOf(transition);
    };
    QVERIFY(stepOnTop());
    step->setSelected(true);
    QVERIFY(!stepOnTop());
    QVERIFY(m_scene->items(tip, Qt::IntersectsItemBoundingRect).contains(step));
    step->setSelected(false);
    QVERIFY(stepOnTop());
    // A selected transition goes below the transitions that cross it.
    transition->setSelected(true);
    QVERIFY(transition->zValue() < m_scene->transitionItem("A1->F1")->zValue());
    transition->setSelected(false);
    QCOMPARE(transition->zValue(), m_scene->transitionItem("A1->F1")->zValue());
}

void TestChart::longConditionIsElided()
{
    const QString condition = "Start AND NOT Stop AND Door_Closed AND Pressure_OK AND Air_OK AND Guard_Locked";
    m_document->push(new SetConditionCommand(*m_document, "F1->A2", condition));
    const TransitionItem* item = m_scene->transitionItem("F1->A2");
    QCOMPARE(item->labelText(), "3: " + condition);
    QVERIFY(item->displayedCondition().size() < condition.size());
    QVERIFY(item->displayedCondition().endsWith(QChar(0x2026)));
    QVERIFY(item->toolTipText().contains(condition));
}

void TestChart::exportNoteEndsACutCondition()
{
    const QString condition = "Start AND NOT Stop AND Door_Closed AND Pressure_OK AND Air_OK AND Guard_Locked";
    m_document->push(new SetConditionCommand(*m_document, "F1->A2", condition));
    m_document->push(new SetConditionCommand(*m_document, "F1->F4", "NOT Stop"));
    TransitionItem* cut = m_scene->transitionItem("F1->A2");
    TransitionItem* whole = m_scene->transitionItem("F1->F4");
    QVERIFY(cut->conditionCut());
    QVERIFY(!whole->conditionCut());
    QCOMPARE(cut->conditionText(), condition);
    const QString onScreen = cut->displayedCondition();
    const double width = cut->labelTextRect().width();

    // During an export: the start of the condition, then its note number, in the same room.
    cut->setNoteNumber(2);
    QVERIFY2(cut->displayedCondition().endsWith(QStringLiteral("\u2026[2]")), qPrintable(cut->displayedCondition()));
    QVERIFY(condition.startsWith(cut->displayedCondition().chopped(4)));
    QVERIFY(cut->labelTextRect().width() <= width + 0.01);
    QVERIFY(cut->conditionCut());
    QCOMPARE(cut->labelText(), "3: " + condition);
    // A condition that fits stays as it is.
    whole->setNoteNumber(1);
    QCOMPARE(whole->displayedCondition(), QString("NOT Stop"));

    // Back to the screen's label.
    cut->setNoteNumber(0);
    whole->setNoteNumber(0);
    QCOMPARE(cut->displayedCondition(), onScreen);
    QCOMPARE(cut->labelTextRect().width(), width);
}

void TestChart::undeclaredVariableMarksTheTransition()
{
    m_document->push(new AddVariableCommand(*m_document, boolVariable("Stop")));
    m_document->push(new SetConditionCommand(*m_document, "F1->A2", "NOT Stop"));
    QVERIFY(!m_scene->transitionItem("F1->A2")->hasProblemMark());
    m_document->push(new SetConditionCommand(*m_document, "F1->A2", "NOT Stop AND Ghost"));
    QVERIFY(m_scene->transitionItem("F1->A2")->hasProblemMark());
    QVERIFY(m_scene->transitionItem("A2->A1")->hasProblemMark()); // still empty
}

void TestChart::hiddenInitialStepIsMarked()
{
    QVERIFY(!m_scene->stepItem("A6")->hasProblemMark());
    // No edit hides it (the initial step is never hidden), but a file may.
    QVERIFY(!m_document->push(new SetStepHiddenCommand(*m_document, "A6", true)));
    QVERIFY(!m_scene->stepItem("A6")->hasProblemMark());
    core::Model hiding;
    QVERIFY(hiding.setStepHidden("A6", true));
    m_document->replaceModel(hiding, QString(), core::ModelFormat::Native);
    QVERIFY(m_scene->stepItem("A6")->hasProblemMark());
    m_document->push(new SetStepHiddenCommand(*m_document, "A6", false));
    QVERIFY(!m_scene->stepItem("A6")->hasProblemMark());
}

void TestChart::stepWithANestedGrafcetIsMarked()
{
    StepItem* f1 = m_scene->stepItem(QStringLiteral("F1")); // a macro-step of the template
    StepItem* f2 = m_scene->stepItem(QStringLiteral("F2"));
    QVERIFY(f1 && f2);
    QCOMPARE(f1->nestedMark(), std::nullopt);

    core::Model& model = m_document->modelForCommands();
    QVERIFY(model.addGrafcetStep("F1", core::GrafcetStep{1, true, {}, {}}).ok);
    QVERIFY(model.addGrafcetStep("F1", core::GrafcetStep{2, false, {}, {}}).ok);
    QCOMPARE(f1->nestedMark(), std::optional<int>(2));
    QVERIFY(f1->toolTipText().contains(QStringLiteral("Has a nested GRAFCET (2 steps)")));
    QCOMPARE(f2->nestedMark(), std::nullopt); // a macro-step without one
    QVERIFY(!f2->toolTipText().contains(QStringLiteral("nested GRAFCET")));

    // Drawn on the top-left corner, in its own colour.
    const QRectF corner = f1->mapRectToScene(QRectF(-4, -4, 4, 4));
    QImage image(40, 40, QImage::Format_ARGB32);
    const auto markPixels = [&]() {
        image.fill(Qt::transparent);
        QPainter painter(&image);
        m_scene->render(&painter, QRectF(0, 0, 40, 40), corner.adjusted(-8, -8, 8, 8));
        painter.end();
        int count = 0;
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x)
                count += QColor(image.pixel(x, y)) == chartstyle::nestedMarkColor() ? 1 : 0;
        }
        return count;
    };
    QVERIFY(markPixels() > 20);

    // A simple step runs no GRAFCET: no mark, until the type comes back.
    QVERIFY(m_document->push(new SetStepTypeCommand(*m_document, QStringLiteral("F1"), core::StepType::Simple)));
    QCOMPARE(f1->nestedMark(), std::nullopt);
    QCOMPARE(markPixels(), 0);
    m_document->undoStack()->undo();
    QCOMPARE(f1->nestedMark(), std::optional<int>(2));
    QVERIFY(markPixels() > 20);

    // The GRAFCET itself removed: the mark goes.
    QVERIFY(model.removeGrafcet("F1").ok);
    QCOMPARE(f1->nestedMark(), std::nullopt);
}

void TestChart::stepTypeChangeRepaintsOnlyThatStep()
{
    m_document->push(new SetStepTypeCommand(*m_document, "A4", core::StepType::Enclosing));
    QVERIFY(m_scene->stepItem("A4")->toolTipText().contains("Enclosing step"));
    QVERIFY(m_scene->stepItem("A3")->toolTipText().contains("Simple step"));
}

void TestChart::activeStepIsMarked()
{
    m_scene->setActiveStep("A6");
    QVERIFY(m_scene->stepItem("A6")->isActive());
    m_scene->setActiveStep("F1");
    QVERIFY(!m_scene->stepItem("A6")->isActive());
    QVERIFY(m_scene->stepItem("F1")->isActive());
    m_scene->setActiveStep(QString());
    QVERIFY(!m_scene->stepItem("F1")->isActive());
}

void TestChart::zoomSlots()
{
    ChartView view(m_scene);
    view.resize(700, 500);
    view.zoomToActualSize();
    QCOMPARE(view.zoom(), 1.0);
    view.zoomIn();
    QCOMPARE(view.zoom(), 1.25);
    view.zoomOut();
    QCOMPARE(view.zoom(), 1.0);
    view.zoomToFit();
    // The whole 1500 x 960 sheet fits into 700 x 500 pixels.
    QVERIFY(view.zoom() < 0.5);
    QVERIFY(view.zoom() > 0.3);
}

void TestChart::ctrlWheelZoomsAboutTheMouse()
{
    ChartView view(m_scene);
    view.resize(800, 600);
    view.zoomToActualSize();
    const QPoint mouse(300, 200);
    const QPointF underMouse = view.mapToScene(mouse);
    QWheelEvent wheel(mouse, view.viewport()->mapToGlobal(mouse), QPoint(), QPoint(0, 120), Qt::NoButton,
                      Qt::ControlModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(view.viewport(), &wheel);
    QVERIFY(view.zoom() > 1.1);
    const QPointF after = view.mapToScene(mouse);
    QVERIFY2(QLineF(after, underMouse).length() < 2, "the scene point under the mouse stays there");

    // Without Ctrl the wheel scrolls.
    const double zoom = view.zoom();
    QWheelEvent scroll(mouse, view.viewport()->mapToGlobal(mouse), QPoint(), QPoint(0, -120), Qt::NoButton,
                       Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(view.viewport(), &scroll);
    QCOMPARE(view.zoom(), zoom);
}

void TestChart::tabLeavesPastTheLastElement()
{
    ChartView view(m_scene);
    m_selection->select(ElementRef::transition("D3->D2"));
    QTest::keyClick(&view, Qt::Key_Tab);
    QCOMPARE(m_selection->current(), ElementRef::transition("D3->D2"));
    m_selection->select(ElementRef::step("A1"));
    QTest::keyClick(&view, Qt::Key_Backtab);
    QCOMPARE(m_selection->current(), ElementRef::step("A1"));
}

void TestChart::replacedModelIsShown()
{
    core::Model model;
    QVERIFY(model.setStepHidden("F3", true));
    QVERIFY(model.setCondition("A2->A1", "TRUE"));
    m_selection->select(ElementRef::step("F1"));
    m_document->replaceModel(model, QString(), core::ModelFormat::Native);
    QVERIFY(!m_scene->stepItem("F3")->isVisible());
    QVERIFY(!m_scene->transitionItem("F1->F3")->isVisible());
    QCOMPARE(m_scene->transitionItem("A2->A1")->labelText(), QString("TRUE"));
    QVERIFY(!m_scene->transitionItem("A2->A1")->hasProblemMark());
    QCOMPARE(m_scene->selectedItems(), QList<QGraphicsItem*>{m_scene->stepItem("F1")});
}

namespace {

// Answers every official state name with a marked text, as a real
// translation would answer with the French one.
class StateNameTranslator : public QTranslator {
public:
    QString translate(const char* context, const char* sourceText, const char*, int) const override
    {
        if (QByteArray(context) != "StateNames")
            return {};
        return QStringLiteral("[[%1]]").arg(QString::fromUtf8(sourceText));
    }
    bool isEmpty() const override { return false; }
};

} // namespace

// Tooltips are built when they show: a help event over an item shows
// that item's text, over the empty sheet none.
void TestChart::hoverShowsTheTooltipOfTheItem()
{
    ChartView view(m_scene);
    view.resize(1000, 700);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    // The text shown, empty when the event was not taken.
    auto hover = [&view](QPointF scenePos) {
        const QPoint at = view.mapFromScene(scenePos);
        QHelpEvent help(QEvent::ToolTip, at, view.viewport()->mapToGlobal(at));
        QApplication::sendEvent(view.viewport(), &help);
        return help.isAccepted() && QToolTip::isVisible() ? QToolTip::text() : QString();
    };
    const QString f1 = hover(m_scene->stepItem("F1")->sceneBoundingRect().center());
    QVERIFY2(f1.contains("Normal production"), qPrintable(f1));
    QCOMPARE(f1, m_scene->stepItem("F1")->toolTipText());
    m_document->push(new SetConditionCommand(*m_document, "A1->F1", "Start AND NOT Stop"));
    const TransitionItem* transition = m_scene->transitionItem("A1->F1");
    const QString text = hover(transition->mapToScene(transition->labelTextRect().center()));
    QVERIFY2(text.contains("Start AND NOT Stop"), qPrintable(text));
    QVERIFY(hover(QPointF(40, 300)).isEmpty());
    QToolTip::hideText();
}

void TestChart::languageChangeRetranslatesTooltips()
{
    ChartView view(m_scene);
    view.show();
    StateNameTranslator translator;
    QCoreApplication::installTranslator(&translator);
    QCoreApplication::processEvents();
    const QString translated = m_scene->stepItem("F1")->toolTipText();
    QCoreApplication::removeTranslator(&translator);
    QCoreApplication::processEvents();
    QVERIFY2(translated.contains("[[Normal production]]"), qPrintable(translated));
    QVERIFY(!m_scene->stepItem("F1")->toolTipText().contains("[["));

    // Family titles are elided once per language, not at every paint.
    const FrameItem* frame = m_scene->frameItem(core::Family::A);
    view.grab();
    QCOMPARE(frame->displayedTitle(), frame->title());
    QCoreApplication::installTranslator(&translator);
    QCoreApplication::processEvents();
    view.grab();
    QVERIFY2(frame->displayedTitle().contains("[[Stop procedures"), qPrintable(frame->displayedTitle()));
    QCoreApplication::removeTranslator(&translator);
    QCoreApplication::processEvents();
    view.grab();
    QCOMPARE(frame->displayedTitle(), frame->title());
}

namespace {

double area(const QRectF& rect)
{
    return rect.isEmpty() ? 0.0 : rect.width() * rect.height();
}

// The smallest rectangle around the pixels of `image` inside `within` that
// are darker than mid-grey (the ink of a step's id).
QRect inkBounds(const QImage& image, const QRect& within)
{
    QRect bounds;
    for (int y = within.top(); y <= within.bottom(); ++y) {
        for (int x = within.left(); x <= within.right(); ++x) {
            if (qGray(image.pixel(x, y)) < 128)
                bounds |= QRect(x, y, 1, 1);
        }
    }
    return bounds;
}

// The id of `step` as painted at 100 %, within its box less the outlines
// and the marks of its type.
QRect idInk(StepItem* step)
{
    const QRectF bounds = step->boundingRect();
    QImage image(bounds.size().toSize(), QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.translate(-bounds.topLeft());
    QStyleOptionGraphicsItem option;
    step->paint(&painter, &option, nullptr);
    painter.end();
    const int inset = qRound(-bounds.left()) + 10; // the item's box starts at (0, 0)
    return inkBounds(image, QRect(QPoint(0, 0), image.size()).adjusted(inset, inset, -inset, -inset));
}

// The share of the pixels of `rect` (scene units, painted at 100 %) darker
// than mid-grey when `item` alone is painted on white.
double darkShare(const TransitionItem* item, const QRectF& rect)
{
    const QRect area = rect.toAlignedRect();
    QImage image(area.size(), QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.translate(-area.topLeft());
    QStyleOptionGraphicsItem option;
    const_cast<TransitionItem*>(item)->paint(&painter, &option, nullptr);
    painter.end();
    int dark = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x)
            dark += qGray(image.pixel(x, y)) < 128 ? 1 : 0;
    }
    return static_cast<double>(dark) / (image.width() * image.height());
}

} // namespace

void TestChart::marginsTileTheArea()
{
    const QRectF area(0, 0, 100, 80);
    const QList<QRectF> inners{QRectF(20, 10, 50, 40), QRectF(-10, 30, 40, 100), QRectF(-5, -5, 200, 200),
                               QRectF(150, 150, 10, 10), QRectF(0, 0, 100, 40)};
    for (const QRectF& inner : inners) {
        const QList<QRectF> margins = ChartView::marginsAround(inner, area);
        double covered = ::area(inner & area);
        for (qsizetype i = 0; i < margins.size(); ++i) {
            QVERIFY(area.contains(margins[i]));
            QCOMPARE(::area(margins[i] & inner), 0.0);
            for (qsizetype j = i + 1; j < margins.size(); ++j)
                QCOMPARE(::area(margins[i] & margins[j]), 0.0);
            covered += ::area(margins[i]);
        }
        QCOMPARE(covered, ::area(area));
    }
}

void TestChart::backgroundCoversEveryPixel()
{
    // The viewport paints without a background fill of its own: every pixel
    // is the sheet, an item, or the window's colour around the sheet, at a
    // fractional zoom that leaves room on all four sides.
    ChartView view(m_scene);
    view.resize(900, 700);
    view.zoomToFit();
    view.zoomOut();
    view.zoomOut();
    QWidget* viewport = view.viewport();
    QVERIFY(viewport->testAttribute(Qt::WA_OpaquePaintEvent));
    QImage image(viewport->size(), QImage::Format_RGB32);
    const QColor unpainted(Qt::magenta);
    image.fill(unpainted);
    viewport->render(&image, QPoint(), QRegion(), QWidget::DrawChildren);

    const QRect sheet = view.mapFromScene(m_scene->sceneRect()).boundingRect();
    const QColor surround = view.palette().color(QPalette::Window);
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QColor pixel = image.pixelColor(x, y);
            QVERIFY2(pixel != unpainted, qPrintable(QString("unpainted pixel at %1, %2").arg(x).arg(y)));
            if (!sheet.adjusted(-1, -1, 1, 1).contains(x, y))
                QCOMPARE(pixel, surround);
        }
    }
    // The paper: white in the corner between the frames and the border.
    const QPoint corner = sheet.topLeft() + QPoint(3, 3);
    QCOMPARE(image.pixelColor(corner), QColor(Qt::white));
}

void TestChart::bigStepIdsAreDrawnLarger()
{
    // The hub step's id is the step font scaled up rather than a font of its
    // own: A1 (the hub, 60 units) against A2 (40), both simple steps.
    QCOMPARE(m_scene->stepItem("A1")->boundingRect().width() - m_scene->stepItem("A2")->boundingRect().width(), 20.0);
    const QRect big = idInk(m_scene->stepItem("A1"));
    const QRect normal = idInk(m_scene->stepItem("A2"));
    QVERIFY(!big.isEmpty());
    QVERIFY(!normal.isEmpty());
    const double ratio = double(big.height()) / normal.height();
    QVERIFY2(ratio > 1.3 && ratio < 1.65, qPrintable(QString::number(ratio)));
    QVERIFY(big.width() > normal.width());
}

void TestChart::labelWidthIsTheShownText()
{
    const QFontMetricsF metrics(chartstyle::font());
    // A priority alone, a priority and a condition, and an elided condition.
    m_document->push(new SetConditionCommand(*m_document, "F1->A2", "NOT Stop"));
    m_document->push(new SetConditionCommand(*m_document, "F1->F4",
                                             "Start AND NOT Stop AND Door_Closed AND Pressure_OK AND Air_OK"));
    for (const char* id : {"F1->D2", "F1->A2", "F1->F4"}) {
        const TransitionItem* item = m_scene->transitionItem(id);
        QVERIFY(item->priorityShown());
        const QString prefix = item->labelText().section(QLatin1Char(':'), 0, 0);
        QString shown = prefix;
        if (!item->displayedCondition().isEmpty())
            shown += QStringLiteral(": ") + item->displayedCondition();
        QCOMPARE(item->labelTextRect().width(), metrics.horizontalAdvance(shown));
    }
    // The short texts are remembered, each as itself.
    for (int pass = 0; pass < 2; ++pass) {
        for (const QString& text : {QStringLiteral("2"), QStringLiteral("2: "), QStringLiteral("12: "), QStringLiteral("2: Stop")})
            QCOMPARE(chartstyle::advance(text), metrics.horizontalAdvance(text));
    }
}

void TestChart::shapeFollowsTheLabel()
{
    // The shape is built when first asked for: after a change it covers the
    // label as it now is, not as it was.
    TransitionItem* item = m_scene->transitionItem("F1->A2");
    const QPointF shortLabel = item->labelTextRect().center();
    QVERIFY(item->shape().contains(shortLabel));
    m_document->push(new SetConditionCommand(*m_document, "F1->A2", "Start AND NOT Stop AND Door_Closed"));
    const QRectF longLabel = item->labelTextRect();
    QVERIFY(longLabel.width() > 60);
    // The end of the long label away from where the short one stands (labels
    // keep to their bar's side).
    const bool shortNearRight = std::abs(longLabel.right() - shortLabel.x()) < std::abs(longLabel.left() - shortLabel.x());
    const QPointF farEnd(shortNearRight ? longLabel.left() + 3 : longLabel.right() - 3, longLabel.center().y());
    QVERIFY(item->shape().contains(farEnd));
    m_document->undoStack()->undo();
    QVERIFY(!item->shape().contains(farEnd));
    QVERIFY(item->shape().contains(shortLabel));
}

QTEST_MAIN(TestChart)
#include "test_chart.moc"
