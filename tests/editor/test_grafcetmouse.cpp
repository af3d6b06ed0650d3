// Editing a GRAFCET tab with the mouse on the shipped drilling cell, with
// QTest mouse events on the view's viewport: a drag from a connection
// handle links (each direction's meaning, the refusals with their reason,
// one undoable command each), a drag from a step's body moves its branch,
// and clicks still select.

#include "editortestsupport.h"

#include "editor/chart/layoutconversion.h"
#include "editor/commands/undohistorywording.h"
#include "editor/document.h"
#include "editor/grafcet/branchdrag.h"
#include "editor/grafcet/grafcetactions.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetstepitem.h"
#include "editor/grafcet/grafcettransitionitem.h"
#include "editor/grafcet/grafcetview.h"
#include "editor/grafcet/linkdrag.h"

#include "core/formats/modelfiles.h"
#include "core/model/grafcetediting.h"

#include <QApplication>
#include <QHelpEvent>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QToolTip>
#include <QTranslator>
#include <QUndoStack>

#include <memory>

using namespace editor;

namespace {

core::Model drillingCell()
{
    core::LoadedModel loaded = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    return *loaded.model;
}

std::vector<int> steps(const std::vector<int>& numbers)
{
    return numbers;
}

// A GRAFCET tab of the document as MainWindow builds it, shown.
struct Tab {
    Tab(Document& document, const QString& stepId)
        : scene(new GrafcetScene(&document, stepId))
        , view(std::make_unique<GrafcetView>(scene))
        , actions(new GrafcetActions(document, *view))
        , links(view->findChild<LinkDrag*>())
        , branches(view->findChild<BranchDrag*>())
    {
        scene->setParent(view.get());
        view->resize(700, 700);
        view->show();
    }

    QWidget* viewport() const { return view->viewport(); }
    QPoint at(const QPointF& scenePos) const { return view->mapFromScene(scenePos); }
    QPoint stepHandle(int number) const { return at(LinkDrag::handlePosition(*scene->stepItem(number))); }
    QPoint transitionHandle(int number) const { return at(LinkDrag::handlePosition(*scene->transitionItem(number))); }
    QPoint stepBox(int number) const { return at(toQRectF(scene->stepItem(number)->layout().box).center()); }
    QPoint transitionBar(int number) const { return at(toQPointF(scene->transitionItem(number)->layout().barCenter)); }

    // Press, move in two stretches, release: the drag the user makes.
    void drag(QPoint from, QPoint to) const
    {
        QTest::mousePress(viewport(), Qt::LeftButton, {}, from);
        QTest::mouseMove(viewport(), (from + to) / 2);
        QTest::mouseMove(viewport(), to);
        QTest::mouseRelease(viewport(), Qt::LeftButton, {}, to);
    }

    GrafcetScene* scene;
    std::unique_ptr<GrafcetView> view;
    GrafcetActions* actions;
    LinkDrag* links;
    BranchDrag* branches;
};

// The numbers of the transitions leaving `step`, in branch order.
std::vector<int> leaving(const Document& document, const char* stepId, int step)
{
    std::vector<int> numbers;
    for (const core::GrafcetTransition* t : document.model().grafcet(stepId)->transitionsFrom(step))
        numbers.push_back(t->number);
    return numbers;
}

const core::GrafcetTransition& transition(const Document& document, const char* stepId, int number)
{
    const core::GrafcetTransition* t = document.model().grafcet(stepId)->transition(number);
    Q_ASSERT(t);
    return *t;
}

// Marks every text of one translation context: a language in which the
// undo history shows which entries are worded again.
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

class TestGrafcetMouse : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void stepOntoTransitionJoinsItsUpstreamSteps();
    void transitionOntoStepJoinsItsDownstreamSteps();
    void stepOntoStepAddsATransition();
    void dragHighlightsTheTarget();
    void refusedLinksSayWhy();
    void undoAndRedoALink();
    void stepDraggedSidewaysMovesItsParallelBranch();
    void stepDraggedSidewaysMovesItsSelectionBranch();
    void stepOnNoBranchSaysSo();
    void clicksStillSelect();
    void noLinkWhileReadOnly();
    void linkAndBranchUndoTextsFollowTheLanguage();

private:
    QTemporaryDir m_settingsDir;
};

void TestGrafcetMouse::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    editortest::useTestSettings(m_settingsDir.path(), QStringLiteral("test_grafcetmouse"));
}

void TestGrafcetMouse::stepOntoTransitionJoinsItsUpstreamSteps()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F2"));
    QVERIFY(QTest::qWaitForWindowExposed(tab.view.get()));
    QVERIFY(tab.links);
    // F2: 1 -> T1 -> 2 -> T3 -> 3, 1 -> T2 -> 3, 3 -> T4 -> 4.
    tab.drag(tab.stepHandle(4), tab.transitionBar(3));
    QCOMPARE(transition(document, "F2", 3).upstream, steps({2, 4}));
    QCOMPARE(transition(document, "F2", 3).downstream, steps({3}));
    QCOMPARE(document.undoStack()->count(), 1);
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Link step 4 to T3 in F2"));
    QCOMPARE(tab.actions->selectedTransitions(), std::vector<int>{3});
    QVERIFY(!tab.links->isDragging());
}

void TestGrafcetMouse::transitionOntoStepJoinsItsDownstreamSteps()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F2"));
    QVERIFY(QTest::qWaitForWindowExposed(tab.view.get()));
    tab.drag(tab.transitionHandle(2), tab.stepBox(4));
    QCOMPARE(transition(document, "F2", 2).upstream, steps({1}));
    QCOMPARE(transition(document, "F2", 2).downstream, steps({3, 4}));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Link T2 to step 4 in F2"));
    QCOMPARE(tab.actions->selectedTransitions(), std::vector<int>{2});
}

void TestGrafcetMouse::stepOntoStepAddsATransition()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F3"));
    QVERIFY(QTest::qWaitForWindowExposed(tab.view.get()));
    // F3: 1 -> T1 -> 2; from 2 back to 1, drawn as a loop.
    tab.drag(tab.stepHandle(2), tab.stepBox(1));
    const core::GrafcetTransition& loop = transition(document, "F3", 2);
    QCOMPARE(loop.upstream, steps({2}));
    QCOMPARE(loop.downstream, steps({1}));
    QCOMPARE(loop.receptivity, std::string(core::kNewTransitionReceptivity));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Link step 2 to step 1 in F3"));
    QVERIFY(tab.scene->transitionItem(2));
    // The new transition is selected, ready for its receptivity.
    QCOMPARE(tab.actions->selectedTransitions(), std::vector<int>{2});
}

void TestGrafcetMouse::dragHighlightsTheTarget()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F2"));
    QVERIFY(QTest::qWaitForWindowExposed(tab.view.get()));
    // Hovering a step shows its handle.
    QTest::mouseMove(tab.viewport(), tab.stepBox(4));
    QCOMPARE(tab.links->handleShown(), core::GrafcetLinkEnd::step(4));
    const QPoint from = tab.stepHandle(4);
    // The handle's tooltip says what it does (shown here without activating
    // the window, whose deactivation when the tip shows would hide it).
    tab.view->setAttribute(Qt::WA_AlwaysShowToolTips);
    QToolTip::hideText();
    QTRY_VERIFY(!QToolTip::isVisible());
    QHelpEvent help(QEvent::ToolTip, from, tab.viewport()->mapToGlobal(from));
    QApplication::sendEvent(tab.viewport(), &help);
    QCOMPARE(QToolTip::text(), QStringLiteral("Drag onto a step or a transition to link them"));
    QTest::mousePress(tab.viewport(), Qt::LeftButton, {}, from);
    QTest::mouseMove(tab.viewport(), from + QPoint(20, 0));
    QVERIFY(tab.links->isDragging());
    QTest::mouseMove(tab.viewport(), tab.transitionBar(3));
    QCOMPARE(tab.links->dropTarget(), core::GrafcetLinkEnd::transition(3));
    QVERIFY(tab.links->isDropValid());
    // Over T4, which step 4 follows: highlighted as refused.
    QTest::mouseMove(tab.viewport(), tab.transitionBar(4));
    QCOMPARE(tab.links->dropTarget(), core::GrafcetLinkEnd::transition(4));
    QVERIFY(!tab.links->isDropValid());
    // Dropped on the background: nothing happens.
    const QPoint background = tab.at(tab.scene->drawingRect().bottomRight()) - QPoint(3, 3);
    QTest::mouseMove(tab.viewport(), background);
    QVERIFY(!tab.links->dropTarget());
    QTest::mouseRelease(tab.viewport(), Qt::LeftButton, {}, background);
    QVERIFY(!tab.links->isDragging());
    QCOMPARE(document.undoStack()->count(), 0);
}

void TestGrafcetMouse::refusedLinksSayWhy()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F2"));
    QVERIFY(QTest::qWaitForWindowExposed(tab.view.get()));
    const core::Grafcet before = *document.model().grafcet("F2");
    QSignalSpy refusals(&document, &Document::editFailed);

    const auto refused = [&](QPoint from, QPoint to, const QString& reason) {
        refusals.clear();
        tab.drag(from, to);
        QCOMPARE(refusals.count(), 1);
        QCOMPARE(refusals.front().front().toString(), reason);
        QCOMPARE(QToolTip::text(), reason);
        QVERIFY(document.model().grafcet("F2")->sameContent(before));
        QCOMPARE(document.undoStack()->count(), 0);
    };
    refused(tab.transitionHandle(1), tab.transitionBar(4),
            QStringLiteral("A transition cannot be linked to a transition: steps and transitions alternate"));
    refused(tab.stepHandle(1), tab.transitionBar(2), QStringLiteral("Step 1 already precedes T2"));
    refused(tab.transitionHandle(3), tab.stepBox(3), QStringLiteral("Step 3 already follows T3"));
    refused(tab.stepHandle(1), tab.stepBox(2), QStringLiteral("Step 1 already leads to step 2"));
    refused(tab.stepHandle(4), tab.transitionBar(4), QStringLiteral("Step 4 would be linked to itself through T4"));
    refused(tab.stepHandle(3), tab.stepBox(3),
            QStringLiteral("Step 3 cannot be linked to itself through one transition"));
}

void TestGrafcetMouse::undoAndRedoALink()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F2"));
    QVERIFY(QTest::qWaitForWindowExposed(tab.view.get()));
    const core::Grafcet before = *document.model().grafcet("F2");
    tab.drag(tab.stepHandle(4), tab.stepBox(1));
    const core::Grafcet after = *document.model().grafcet("F2");
    QCOMPARE(after.transitions().size(), before.transitions().size() + 1);
    QCOMPARE(document.undoStack()->count(), 1);

    document.undoStack()->undo();
    QVERIFY(document.model().grafcet("F2")->sameContent(before));
    QVERIFY(!tab.scene->transitionItem(5));
    document.undoStack()->redo();
    QVERIFY(document.model().grafcet("F2")->sameContent(after));
    QVERIFY(tab.scene->transitionItem(5));
    // The redone link can be linked from again: the handles follow the new drawing.
    tab.drag(tab.transitionHandle(5), tab.stepBox(2));
    QCOMPARE(transition(document, "F2", 5).downstream, steps({1, 2}));
    QCOMPARE(document.undoStack()->count(), 2);
}

void TestGrafcetMouse::stepDraggedSidewaysMovesItsParallelBranch()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F1"));
    QVERIFY(QTest::qWaitForWindowExposed(tab.view.get()));
    QVERIFY(tab.branches);
    // F1: T2 opens the parallel branches 3-4 and 5-6, closed by T5.
    QCOMPARE(transition(document, "F1", 2).downstream, steps({3, 5}));
    const QPoint from = tab.stepBox(5);
    const QPoint onto = tab.stepBox(3);
    QTest::mousePress(tab.viewport(), Qt::LeftButton, {}, from);
    QTest::mouseMove(tab.viewport(), (from + onto) / 2);
    QTest::mouseMove(tab.viewport(), onto);
    QVERIFY(tab.branches->isDragging());
    QCOMPARE(tab.branches->dropOffset(), -1);
    QVERIFY(!tab.links->isDragging());
    QTest::mouseRelease(tab.viewport(), Qt::LeftButton, {}, onto);
    QCOMPARE(transition(document, "F1", 2).downstream, steps({5, 3}));
    QCOMPARE(transition(document, "F1", 5).upstream, steps({6, 4}));
    QCOMPARE(document.undoStack()->count(), 1);
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Move the branch of step 5 left in F1"));
    QCOMPARE(tab.actions->selectedSteps(), std::vector<int>{5});
    // Drawn in the new order: step 5 now left of step 3.
    QVERIFY(tab.stepBox(5).x() < tab.stepBox(3).x());
    document.undoStack()->undo();
    QCOMPARE(transition(document, "F1", 2).downstream, steps({3, 5}));
}

void TestGrafcetMouse::stepDraggedSidewaysMovesItsSelectionBranch()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F2"));
    QVERIFY(QTest::qWaitForWindowExposed(tab.view.get()));
    // F2: step 1 chooses between T1 (to step 2) and T2 (straight to step 3).
    QCOMPARE(leaving(document, "F2", 1), steps({1, 2}));
    const QPoint from = tab.stepBox(2);
    const QPoint onto(tab.transitionBar(2).x(), from.y());
    tab.drag(from, onto);
    QCOMPARE(leaving(document, "F2", 1), steps({2, 1}));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Move the branch of step 2 right in F2"));
    // Dropped back where it stands: nothing moves.
    tab.drag(tab.stepBox(2), tab.stepBox(2) + QPoint(12, 0));
    QCOMPARE(leaving(document, "F2", 1), steps({2, 1}));
    QCOMPARE(document.undoStack()->count(), 1);
}

void TestGrafcetMouse::stepOnNoBranchSaysSo()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F3"));
    QVERIFY(QTest::qWaitForWindowExposed(tab.view.get()));
    const core::Grafcet before = *document.model().grafcet("F3");
    QSignalSpy refusals(&document, &Document::editFailed);
    tab.drag(tab.stepBox(2), tab.stepBox(2) + QPoint(60, 0));
    QCOMPARE(refusals.count(), 1);
    QCOMPARE(refusals.front().front().toString(),
             QStringLiteral("Step 2 is on no branch of a divergence: there is no branch to move"));
    QVERIFY(document.model().grafcet("F3")->sameContent(before));
    QCOMPARE(document.undoStack()->count(), 0);
}

void TestGrafcetMouse::clicksStillSelect()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F2"));
    QVERIFY(QTest::qWaitForWindowExposed(tab.view.get()));
    QTest::mouseClick(tab.viewport(), Qt::LeftButton, {}, tab.stepBox(2));
    QCOMPARE(tab.actions->selectedSteps(), std::vector<int>{2});
    QTest::mouseClick(tab.viewport(), Qt::LeftButton, {}, tab.transitionBar(4));
    QCOMPARE(tab.actions->selectedTransitions(), std::vector<int>{4});
    QVERIFY(tab.actions->selectedSteps().empty());
    // A click on a handle selects its element, and links nothing.
    QTest::mouseClick(tab.viewport(), Qt::LeftButton, {}, tab.stepHandle(3));
    QCOMPARE(tab.actions->selectedSteps(), std::vector<int>{3});
    QVERIFY(tab.actions->selectedTransitions().empty());
    // Ctrl+click on a handle adds its element to the selection, as on the element.
    QTest::mouseClick(tab.viewport(), Qt::LeftButton, Qt::ControlModifier, tab.transitionHandle(1));
    QCOMPARE(tab.actions->selectedSteps(), std::vector<int>{3});
    QCOMPARE(tab.actions->selectedTransitions(), std::vector<int>{1});
    QCOMPARE(document.undoStack()->count(), 0);
}

void TestGrafcetMouse::noLinkWhileReadOnly()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F2"));
    QVERIFY(QTest::qWaitForWindowExposed(tab.view.get()));
    document.setReadOnly(true);
    QTest::mouseMove(tab.viewport(), tab.stepBox(4));
    QVERIFY(!tab.links->handleShown());
    tab.drag(tab.stepHandle(4), tab.transitionBar(3));
    QVERIFY(!tab.links->isDragging());
    QCOMPARE(transition(document, "F2", 3).upstream, steps({2}));
}


// A link and a branch move made with the mouse word their undo texts again
// when the language changes (a marking translator stands for it), and back.
void TestGrafcetMouse::linkAndBranchUndoTextsFollowTheLanguage()
{
    Document document(drillingCell());
    Tab f2(document, QStringLiteral("F2"));
    QVERIFY(QTest::qWaitForWindowExposed(f2.view.get()));
    f2.drag(f2.stepHandle(4), f2.transitionBar(3));
    Tab f1(document, QStringLiteral("F1"));
    QVERIFY(QTest::qWaitForWindowExposed(f1.view.get()));
    f1.drag(f1.stepBox(5), f1.stepBox(3));
    QCOMPARE(document.undoStack()->count(), 2);
    QCOMPARE(document.undoStack()->text(0), QStringLiteral("Link step 4 to T3 in F2"));
    QCOMPARE(document.undoStack()->text(1), QStringLiteral("Move the branch of step 5 left in F1"));

    {
        MarkingTranslator links("editor::LinkDrag");
        MarkingTranslator branches("editor::BranchDrag");
        QCoreApplication::installTranslator(&links);
        QCoreApplication::installTranslator(&branches);
        rewordUndoHistory(document.undoStack());
        QCOMPARE(document.undoStack()->text(0), QStringLiteral("[tr]Link step 4 to T3 in F2"));
        QCOMPARE(document.undoStack()->text(1), QStringLiteral("[tr]Move the branch of step 5 left in F1"));
    }
    rewordUndoHistory(document.undoStack());
    QCOMPARE(document.undoStack()->text(0), QStringLiteral("Link step 4 to T3 in F2"));
    QCOMPARE(document.undoStack()->text(1), QStringLiteral("Move the branch of step 5 left in F1"));
}

QTEST_MAIN(TestGrafcetMouse)
#include "test_grafcetmouse.moc"
