// The structured editing of a GRAFCET tab (GrafcetActions) on the shipped
// drilling cell: each entry through the view's actions, its command's text,
// the model and the scene after it, undo and redo.

#include "editortestsupport.h"

#include "editor/app/languages.h"
#include "editor/chart/gemma/chartcontextmenu.h"
#include "editor/commands/editgrafcetcommand.h"
#include "editor/commands/undohistorywording.h"
#include "editor/document.h"
#include "editor/elementref.h"
#include "editor/grafcet/connecttransitiondialog.h"
#include "editor/grafcet/grafcetactions.h"
#include "editor/grafcet/grafcetclipboard.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetstepitem.h"
#include "editor/grafcet/grafcettransitionitem.h"
#include "editor/grafcet/grafcetview.h"
#include "editor/grafcet/nestedgrafcetavailable.h"
#include "editor/mainwindow.h"

#include "core/formats/modelfiles.h"
#include "core/model/grafcetediting.h"

#include <QAction>
#include <QDialog>
#include <QDialogButtonBox>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QPushButton>
#include <QScrollBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTranslator>
#include <QUndoStack>

#include <memory>
#include <variant>

using namespace editor;

namespace {

core::Model drillingCell()
{
    core::LoadedModel loaded = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    return *loaded.model;
}

std::string join(const std::vector<int>& numbers)
{
    std::string text;
    for (int n : numbers)
        text += (text.empty() ? "" : ",") + std::to_string(n);
    return text;
}

// "T1 1>2, T2 2>3,4": every transition in list order.
QString links(const core::Grafcet* g)
{
    std::string text;
    for (const core::GrafcetTransition& t : g->transitions())
        text += (text.empty() ? "" : ", ") + ("T" + std::to_string(t.number)) + " " + join(t.upstream) + ">"
              + join(t.downstream);
    return QString::fromStdString(text);
}

int stepItems(const QGraphicsScene& scene)
{
    int count = 0;
    for (QGraphicsItem* item : scene.items())
        count += item->type() == GrafcetStepItem::Type ? 1 : 0;
    return count;
}

// A GRAFCET tab of the document as MainWindow builds it.
struct Tab {
    Tab(Document& document, const QString& stepId)
        : scene(new GrafcetScene(&document, stepId))
        , view(std::make_unique<GrafcetView>(scene))
        , actions(new GrafcetActions(document, *view))
    {
        scene->setParent(view.get());
    }

    QAction* action(const char* name) const { return view->findChild<QAction*>(QString::fromLatin1(name)); }

    GrafcetScene* scene;
    std::unique_ptr<GrafcetView> view;
    GrafcetActions* actions;
};

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

QStringList undoTexts(const QUndoStack& stack)
{
    QStringList texts;
    for (int i = 0; i < stack.count(); ++i)
        texts << stack.text(i);
    return texts;
}

} // namespace

class TestGrafcetEditing : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void insertAfterStepAndUndo();
    void insertWithTheKeyboard();
    void branches();
    void loopThroughTheStepMenu();
    void removeRepairsTheSequence();
    void copyPasteRenumbers();
    void renumberAndConnectDirectly();
    void createUsualShapeAndUndo();
    void readOnlyDisablesEditing();
    void windowOpensAnEmptyMacroStep();
    void branchEndingOnAStep();
    void deleteRemovesATransition();
    void moveBranchWithTheKeyboard();
    void connectDirectlySaysWhyOkIsDisabled();
    void aLongerReceptivityDoesNotShiftTheDrawing();
    void aWideDrawingOpensAtItsLeft();
    void everyEditIsWordedInTheCurrentLanguage();

private:
    QTemporaryDir m_settingsDir;
};

void TestGrafcetEditing::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    editortest::useTestSettings(m_settingsDir.path(), QStringLiteral("test_grafcetediting"));
}

void TestGrafcetEditing::insertAfterStepAndUndo()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F3"));
    const core::Grafcet before = *document.model().grafcet("F3");
    QCOMPARE(stepItems(*tab.scene), 2);

    tab.actions->select({1}, {});
    QVERIFY(tab.action("grafcetInsertAfterAction")->isEnabled());
    tab.action("grafcetInsertAfterAction")->trigger();
    const core::Grafcet* after = document.model().grafcet("F3");
    QCOMPARE(links(after), QStringLiteral("T1 3>2, T2 1>3")); // 1 -> T2 -> 3 -> T1 -> 2
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Add step 3 to F3"));
    QCOMPARE(stepItems(*tab.scene), 3);
    QVERIFY(tab.scene->stepItem(3));
    QVERIFY(tab.scene->transitionItem(2));
    // What was created is selected, ready for the next insertion.
    QCOMPARE(tab.actions->selectedSteps(), std::vector<int>{3});
    QCOMPARE(tab.actions->selectedTransitions(), std::vector<int>{2});
    QVERIFY(tab.scene->stepItem(3)->isSelected());

    document.undoStack()->undo();
    QVERIFY(document.model().grafcet("F3")->sameContent(before));
    QCOMPARE(stepItems(*tab.scene), 2);
    QVERIFY(!tab.scene->stepItem(3));
    document.undoStack()->redo();
    QCOMPARE(links(document.model().grafcet("F3")), QStringLiteral("T1 3>2, T2 1>3"));
    QCOMPARE(stepItems(*tab.scene), 3);
}

void TestGrafcetEditing::insertWithTheKeyboard()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F3"));
    tab.view->show();
    QVERIFY(QTest::qWaitForWindowExposed(tab.view.get()));
    tab.view->activateWindow();
    tab.view->setFocus();
    // A click selects the transition's bar.
    const QPoint bar = tab.view->mapFromScene(tab.scene->transitionItem(1)->boundingRect().center());
    QTest::mouseClick(tab.view->viewport(), Qt::LeftButton, {}, bar);
    QCOMPARE(tab.actions->selectedTransitions(), std::vector<int>{1});
    QTest::keyClick(tab.view.get(), Qt::Key_Insert);
    QCOMPARE(links(document.model().grafcet("F3")), QStringLiteral("T1 1>3, T2 3>2"));
    QCOMPARE(tab.actions->selectedSteps(), std::vector<int>{3});
    // Delete removes the selected step again, repairing the sequence.
    tab.actions->select({3}, {});
    QTest::keyClick(tab.view.get(), Qt::Key_Delete);
    QCOMPARE(links(document.model().grafcet("F3")), QStringLiteral("T1 1>2"));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Remove step 3 from F3"));
}

void TestGrafcetEditing::branches()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F3"));
    tab.actions->select({1}, {});
    tab.action("grafcetSelectionBranchAction")->trigger();
    QCOMPARE(links(document.model().grafcet("F3")), QStringLiteral("T1 1>2, T2 1>3, T3 3>2"));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Add selection branch to F3"));
    QCOMPARE(stepItems(*tab.scene), 3);
    QCOMPARE(tab.scene->layout().lines.size(), std::size_t(2)); // divergence and convergence

    tab.actions->select({}, {1});
    tab.action("grafcetParallelBranchAction")->trigger();
    QCOMPARE(links(document.model().grafcet("F3")), QStringLiteral("T1 1>2,4, T2 1>3, T3 3>2"));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Add parallel branch to F3"));
    QCOMPARE(tab.actions->selectedSteps(), std::vector<int>{4});

    // Remove Branch on the parallel step, then on the selection's second transition.
    QVERIFY(tab.action("grafcetRemoveBranchAction")->isEnabled());
    tab.action("grafcetRemoveBranchAction")->trigger();
    QCOMPARE(links(document.model().grafcet("F3")), QStringLiteral("T1 1>2, T2 1>3, T3 3>2"));
    tab.actions->select({}, {2});
    tab.action("grafcetRemoveBranchAction")->trigger();
    QCOMPARE(links(document.model().grafcet("F3")), QStringLiteral("T1 1>2"));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Remove branch from F3"));
    QCOMPARE(stepItems(*tab.scene), 2);

    for (int i = 0; i < 4; ++i)
        document.undoStack()->undo();
    QVERIFY(document.model().grafcet("F3")->sameContent(*drillingCell().grafcet("F3")));
    QCOMPARE(stepItems(*tab.scene), 2);
    QVERIFY(tab.scene->layout().lines.empty());
}

void TestGrafcetEditing::loopThroughTheStepMenu()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F3"));
    tab.actions->select({2}, {});
    QMenu menu;
    tab.actions->populate(&menu);
    auto* jumps = menu.findChild<QMenu*>(QStringLiteral("grafcetJumpMenu"));
    QVERIFY(jumps);
    QCOMPARE(jumps->actions().size(), 2); // steps 1 and 2
    jumps->findChild<QAction*>(QStringLiteral("grafcetJumpTo_1"))->trigger();
    QCOMPARE(links(document.model().grafcet("F3")), QStringLiteral("T1 1>2, T2 2>1"));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Add jump from step 2 to step 1 in F3"));
    QCOMPARE(tab.actions->selectedTransitions(), std::vector<int>{2});
    bool loop = false;
    for (const core::GrafcetLinkLayout& link : tab.scene->layout().links)
        loop |= link.transition == 2 && link.ending == core::GrafcetLinkLayout::Ending::Loop;
    QVERIFY(loop);

    // The background menu offers what needs no element.
    tab.actions->select({}, {});
    QMenu background;
    tab.actions->populate(&background);
    QVERIFY(background.actions().contains(tab.action("grafcetRenumberAction")));
    QVERIFY(!background.actions().contains(tab.action("grafcetInsertAfterAction")));
}

void TestGrafcetEditing::removeRepairsTheSequence()
{
    // F2: 1 -> T1 -> 2 -> T3 -> 3, 1 -> T2 -> 3, 3 -> T4 -> 4.
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F2"));
    tab.actions->select({3}, {});
    tab.action("grafcetRemoveAction")->trigger();
    QCOMPARE(links(document.model().grafcet("F2")), QStringLiteral("T1 1>2, T2 1>4, T3 2>4"));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Remove step 3 from F2"));
    QCOMPARE(stepItems(*tab.scene), 3);
    QVERIFY(!tab.scene->transitionItem(4));
    QVERIFY(document.model().grafcet("F2")->step(4)->actions.size() == 2); // step 4 kept its actions

    // Several steps at once: one command.
    tab.actions->select({2, 4}, {});
    tab.action("grafcetRemoveAction")->trigger();
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Remove 2 steps from F2"));
    QCOMPARE(stepItems(*tab.scene), 1);
    document.undoStack()->undo();
    document.undoStack()->undo();
    QVERIFY(document.model().grafcet("F2")->sameContent(*drillingCell().grafcet("F2")));
    QCOMPARE(stepItems(*tab.scene), 4);
}

void TestGrafcetEditing::copyPasteRenumbers()
{
    Document document(drillingCell());
    Tab f3(document, QStringLiteral("F3"));
    f3.actions->select({1, 2}, {});
    f3.action("grafcetCopyAction")->trigger();
    const auto copied = GrafcetClipboard::fragment();
    QVERIFY(std::holds_alternative<core::GrafcetFragment>(copied));
    QCOMPARE(std::get<core::GrafcetFragment>(copied).steps.size(), std::size_t(2));

    f3.actions->select({2}, {});
    QVERIFY(f3.action("grafcetPasteAction")->isEnabled());
    f3.action("grafcetPasteAction")->trigger();
    const core::Grafcet* g = document.model().grafcet("F3");
    QCOMPARE(links(g), QStringLiteral("T1 1>2, T2 3>4, T3 2>3"));
    QCOMPARE(g->transition(2)->receptivity, std::string("5s/X3 AND InfeedEmpty AND NOT PartPresent"));
    QCOMPARE(g->initialSteps(), std::vector<int>{1});
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Paste 2 steps into F3"));
    QCOMPARE(f3.actions->selectedSteps(), (std::vector<int>{3, 4}));
    QCOMPARE(stepItems(*f3.scene), 4);

    // Into another GRAFCET's tab, after its step 4: fresh numbers there.
    Tab f2(document, QStringLiteral("F2"));
    f2.actions->select({4}, {});
    f2.action("grafcetPasteAction")->trigger();
    QCOMPARE(links(document.model().grafcet("F2")), QStringLiteral("T1 1>2, T2 1>3, T3 2>3, T4 3>4, T5 5>6, T6 4>5"));
    QCOMPARE(document.model().grafcet("F2")->transition(5)->receptivity,
             std::string("5s/X5 AND InfeedEmpty AND NOT PartPresent"));

    document.undoStack()->undo();
    document.undoStack()->undo();
    QCOMPARE(stepItems(*f3.scene), 2);
    QCOMPARE(stepItems(*f2.scene), 4);
    QVERIFY(document.model().grafcet("F3")->sameContent(*drillingCell().grafcet("F3")));
}

void TestGrafcetEditing::renumberAndConnectDirectly()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F3"));
    tab.actions->select({1}, {});
    tab.action("grafcetInsertBeforeAction")->trigger(); // 3 (initial now) -> T2 -> 1 -> T1 -> 2
    QCOMPARE(links(document.model().grafcet("F3")), QStringLiteral("T1 1>2, T2 3>1"));
    tab.action("grafcetRenumberAction")->trigger();
    const core::Grafcet* g = document.model().grafcet("F3");
    // Top to bottom: 3 is 1, 1 is 2, 2 is 3; T2 at the top is T1. The lists keep their order.
    QCOMPARE(links(g), QStringLiteral("T2 2>3, T1 1>2"));
    QCOMPARE(g->initialSteps(), std::vector<int>{1});
    QCOMPARE(g->transition(2)->receptivity, std::string("5s/X2 AND InfeedEmpty AND NOT PartPresent"));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Renumber F3"));

    // Connect Directly: T2 from 2 to 3 and back to 1 at once.
    tab.actions->select({}, {2});
    tab.actions->setDialogRunner([](QDialog& dialog) {
        auto& connect = static_cast<ConnectTransitionDialog&>(dialog);
        QListWidget* down = connect.downstreamList();
        for (int row = 0; row < down->count(); ++row)
            if (down->item(row)->data(Qt::UserRole).toInt() == 1)
                down->item(row)->setCheckState(Qt::Checked);
        return int(QDialog::Accepted);
    });
    tab.action("grafcetConnectAction")->trigger();
    QCOMPARE(links(document.model().grafcet("F3")), QStringLiteral("T2 2>3,1, T1 1>2"));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Connect F3 T2"));
    tab.actions->setDialogRunner([](QDialog&) { return int(QDialog::Rejected); });
    tab.action("grafcetConnectAction")->trigger();
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Connect F3 T2")); // cancelled: nothing pushed
}

void TestGrafcetEditing::createUsualShapeAndUndo()
{
    Document document(drillingCell());
    const QString a7 = QStringLiteral("A7"); // a macro-step never drawn
    QVERIFY(!document.model().grafcet("A7"));
    QVERIFY(canOpenNestedGrafcet(document.model(), a7));
    QVERIFY(!canOpenNestedGrafcet(document.model(), QStringLiteral("A1"))); // simple, none
    Tab tab(document, a7);
    auto* link = tab.view->findChild<QLabel*>(QStringLiteral("grafcetEmptyLink"));
    QVERIFY(link);
    QVERIFY(link->isVisibleTo(tab.view.get()));
    QCOMPARE(stepItems(*tab.scene), 0);
    QMenu menu;
    tab.actions->populate(&menu);
    QVERIFY(menu.actions().contains(tab.action("grafcetCreateUsualAction")));

    emit link->linkActivated(QStringLiteral("create"));
    const core::Grafcet* g = document.model().grafcet("A7");
    QVERIFY(g);
    QVERIFY(g->sameContent(core::usualGrafcet()));
    QCOMPARE(g->step(3)->actions.front().text, std::string("S Complete"));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Create GRAFCET of A7"));
    QCOMPARE(stepItems(*tab.scene), 3);
    QVERIFY(!link->isVisibleTo(tab.view.get()));
    QVERIFY(!tab.action("grafcetCreateUsualAction")->isEnabled());

    document.undoStack()->undo();
    QVERIFY(!document.model().grafcet("A7"));
    QCOMPARE(stepItems(*tab.scene), 0);
    QVERIFY(link->isVisibleTo(tab.view.get()));
    document.undoStack()->redo();
    QCOMPARE(stepItems(*tab.scene), 3);
}

void TestGrafcetEditing::readOnlyDisablesEditing()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F3"));
    tab.actions->select({1}, {});
    QVERIFY(tab.action("grafcetInsertAfterAction")->isEnabled());
    document.setReadOnly(true);
    QVERIFY(!tab.action("grafcetInsertAfterAction")->isEnabled());
    QVERIFY(!tab.action("grafcetRemoveAction")->isEnabled());
    QVERIFY(tab.action("grafcetCopyAction")->isEnabled()); // copying changes nothing
}

// In the window: a macro-step without GRAFCET opens on an empty tab (from
// the chart's context menu too), which creates the usual shape.
void TestGrafcetEditing::windowOpensAnEmptyMacroStep()
{
    Translators translators;
    translators.setLanguage(QStringLiteral("en"));
    const std::unique_ptr<MainWindow> window = editortest::showMainWindow(translators);
    QVERIFY(QTest::qWaitForWindowExposed(window.get()));
    window->findChild<QAction*>(QStringLiteral("example_0"))->trigger(); // the drilling cell
    Document* document = window->document();
    QVERIFY(!window->openNestedGrafcet(QStringLiteral("A1"))); // a simple step
    QMenu chartMenu;
    window->findChild<ChartContextMenu*>()->populate(&chartMenu, ElementRef::step(QStringLiteral("A7")));
    QVERIFY(chartMenu.findChild<QAction*>(QStringLiteral("openGrafcetAction")));
    QVERIFY(window->openNestedGrafcet(QStringLiteral("A7")));
    GrafcetView* view = window->grafcetView(QStringLiteral("A7"));
    QVERIFY(view);
    QCOMPARE(window->centralTabs()->currentWidget(), static_cast<QWidget*>(view));
    QCOMPARE(editortest::countItems<GrafcetStepItem>(*view->grafcetScene()), 0);

    view->findChild<QAction*>(QStringLiteral("grafcetCreateUsualAction"))->trigger();
    QVERIFY(document->model().grafcet("A7"));
    QCOMPARE(editortest::countItems<GrafcetStepItem>(*view->grafcetScene()), 3);
    QCOMPARE(editortest::countItems<GrafcetTransitionItem>(*view->grafcetScene()), 2);
    document->undoStack()->undo();
    QVERIFY(!document->model().grafcet("A7"));
    QCOMPARE(window->grafcetView(QStringLiteral("A7")), view); // the tab stays, empty again
    QCOMPARE(editortest::countItems<GrafcetStepItem>(*view->grafcetScene()), 0);
}


void TestGrafcetEditing::branchEndingOnAStep()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F3")); // 1 -> T1 -> 2
    tab.actions->select({1}, {});
    QMenu menu;
    tab.actions->populate(&menu);
    QVERIFY(menu.actions().contains(tab.action("grafcetEndingBranchAction")));
    QVERIFY(tab.action("grafcetEndingBranchAction")->isEnabled());
    tab.action("grafcetEndingBranchAction")->trigger();
    const core::Grafcet* g = document.model().grafcet("F3");
    QCOMPARE(links(g), QStringLiteral("T1 1>2, T2 1>3"));
    QVERIFY(g->transitionsFrom(3).empty()); // an exit step, in one action
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Add branch ending on a step at step 1 in F3"));
    QCOMPARE(tab.actions->selectedSteps(), std::vector<int>{3});
    QCOMPARE(stepItems(*tab.scene), 3);
    document.undoStack()->undo();
    QVERIFY(document.model().grafcet("F3")->sameContent(*drillingCell().grafcet("F3")));
}

void TestGrafcetEditing::deleteRemovesATransition()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F3"));
    tab.view->show();
    QVERIFY(QTest::qWaitForWindowExposed(tab.view.get()));
    tab.view->activateWindow();
    tab.view->setFocus();
    const QPoint bar = tab.view->mapFromScene(tab.scene->transitionItem(1)->sceneBoundingRect().center());
    QTest::mouseClick(tab.view->viewport(), Qt::LeftButton, {}, bar);
    QCOMPARE(tab.actions->selectedTransitions(), std::vector<int>{1});
    QMenu menu;
    tab.actions->populate(&menu);
    QVERIFY(menu.actions().contains(tab.action("grafcetRemoveAction")));
    QTest::keyClick(tab.view.get(), Qt::Key_Delete);
    QVERIFY(document.model().grafcet("F3")->transitions().empty()); // the lone transition went
    QCOMPARE(document.model().grafcet("F3")->steps().size(), std::size_t(2)); // its steps stay
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Remove T1 from F3"));
    QVERIFY(!tab.scene->transitionItem(1));
    document.undoStack()->undo();
    QVERIFY(document.model().grafcet("F3")->sameContent(*drillingCell().grafcet("F3")));
}

void TestGrafcetEditing::moveBranchWithTheKeyboard()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F3"));
    tab.actions->select({1}, {});
    tab.action("grafcetEndingBranchAction")->trigger(); // T2 1>3, right of T1 1>2
    tab.view->show();
    QVERIFY(QTest::qWaitForWindowExposed(tab.view.get()));
    tab.view->activateWindow();
    tab.view->setFocus();
    const QPoint box = tab.view->mapFromScene(tab.scene->stepItem(3)->sceneBoundingRect().center());
    QTest::mouseClick(tab.view->viewport(), Qt::LeftButton, {}, box);
    QCOMPARE(tab.actions->selectedSteps(), std::vector<int>{3});
    QVERIFY(!tab.action("grafcetMoveBranchRightAction")->isEnabled()); // already the rightmost
    QVERIFY(tab.action("grafcetMoveBranchLeftAction")->isEnabled());
    const double before = tab.scene->stepItem(3)->sceneBoundingRect().center().x();
    QTest::keyClick(tab.view.get(), Qt::Key_Left, Qt::AltModifier);
    QCOMPARE(links(document.model().grafcet("F3")), QStringLiteral("T2 1>3, T1 1>2"));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Move branch left in F3"));
    QVERIFY(tab.scene->stepItem(3)->sceneBoundingRect().center().x() < before); // drawn at the left now
    QCOMPARE(tab.actions->selectedSteps(), std::vector<int>{3}); // still selected: Alt+Left again is possible
    QVERIFY(!tab.action("grafcetMoveBranchLeftAction")->isEnabled());
    {
        QMenu menu; // gone before the next key, as the context menu is after it closes
        tab.actions->populate(&menu);
        QVERIFY(menu.actions().contains(tab.action("grafcetMoveBranchRightAction")));
    }
    QVERIFY(tab.action("grafcetMoveBranchRightAction")->isEnabled());
    QTest::keyClick(tab.view.get(), Qt::Key_Right, Qt::AltModifier);
    QCOMPARE(links(document.model().grafcet("F3")), QStringLiteral("T1 1>2, T2 1>3"));
    document.undoStack()->undo();
    QCOMPARE(links(document.model().grafcet("F3")), QStringLiteral("T2 1>3, T1 1>2"));
    // On a transition: the selection branch it starts.
    tab.actions->select({}, {1});
    QVERIFY(!tab.action("grafcetMoveBranchRightAction")->isEnabled());
    QVERIFY(tab.action("grafcetMoveBranchLeftAction")->isEnabled());
    QTest::keyClick(tab.view.get(), Qt::Key_Left, Qt::AltModifier);
    QCOMPARE(links(document.model().grafcet("F3")), QStringLiteral("T1 1>2, T2 1>3"));
    QCOMPARE(tab.actions->selectedTransitions(), std::vector<int>{1});
}

void TestGrafcetEditing::connectDirectlySaysWhyOkIsDisabled()
{
    Document document(drillingCell());
    const core::Grafcet& g = *document.model().grafcet("F3"); // T1 1>2
    ConnectTransitionDialog dialog(g, 1, QStringLiteral("F3"));
    QPushButton* ok = dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
    QVERIFY(ok->isEnabled());
    QVERIFY(dialog.reasonLabel()->isHidden());
    dialog.downstreamList()->item(0)->setCheckState(Qt::Unchecked); // step 2
    QVERIFY(!ok->isEnabled());
    QVERIFY(!dialog.reasonLabel()->isHidden());
    QVERIFY(dialog.reasonLabel()->text().contains(QStringLiteral("downstream step")));
    QVERIFY(dialog.reasonLabel()->text().contains(QStringLiteral("Add Branch Ending on a Step")));
    dialog.upstreamList()->item(0)->setCheckState(Qt::Unchecked); // step 1
    QVERIFY(dialog.reasonLabel()->text().contains(QStringLiteral("upstream step")));
    dialog.upstreamList()->item(0)->setCheckState(Qt::Checked);
    dialog.downstreamList()->item(1)->setCheckState(Qt::Checked); // step 1: a loop on itself
    QVERIFY(ok->isEnabled());
    QVERIFY(dialog.reasonLabel()->isHidden());
}

void TestGrafcetEditing::aLongerReceptivityDoesNotShiftTheDrawing()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F3"));
    tab.view->resize(1000, 700); // wider than the drawing, which a centred view would move
    tab.view->show();
    QVERIFY(QTest::qWaitForWindowExposed(tab.view.get()));
    const auto stepOnScreen = [&tab] {
        return tab.view->mapFromScene(tab.scene->stepItem(1)->sceneBoundingRect().center());
    };
    const QPoint before = stepOnScreen();
    const double width = tab.scene->drawingRect().width();
    const auto setReceptivity = [&document](const std::string& text) {
        return document.push(new EditGrafcetCommand(
            document, QStringLiteral("F3"), [text](core::Grafcet& g) { return g.setReceptivity(1, text); },
            [] { return QStringLiteral("Set receptivity"); }));
    };
    QVERIFY(setReceptivity("PartPresent AND NOT DrillHigh AND NOT DrillLow AND ClampClosed AND SpindleReady"));
    QVERIFY(tab.scene->drawingRect().width() > width + 100); // the drawing grew at its right
    QCOMPARE(stepOnScreen(), before);
    QVERIFY(setReceptivity("a"));
    QCOMPARE(stepOnScreen(), before);
}

// A drawing wider than its tab opens at its top left, where the initial
// step and the way back are, not scrolled to its middle.
void TestGrafcetEditing::aWideDrawingOpensAtItsLeft()
{
    Document document(drillingCell());
    QVERIFY(document.push(new EditGrafcetCommand(
        document, QStringLiteral("F3"),
        [](core::Grafcet& g) {
            for (int branch = 0; branch < 6; ++branch)
                if (core::Status status = core::addBranchEndingOnStep(g, 1); !status)
                    return status;
            return core::Status::success();
        },
        [] { return QStringLiteral("Add branches"); })));
    Tab tab(document, QStringLiteral("F3"));
    tab.view->resize(300, 400);
    tab.view->show();
    QVERIFY(QTest::qWaitForWindowExposed(tab.view.get()));
    QScrollBar* bar = tab.view->horizontalScrollBar();
    QVERIFY(bar->maximum() > bar->minimum()); // wider than the tab
    QCOMPARE(bar->value(), bar->minimum());
    // The step's square (its token's place inside it); its actions may go on past the tab's edge.
    const QRect initialStep = tab.view->mapFromScene(tab.scene->stepItem(1)->tokenRect()).boundingRect();
    QVERIFY(tab.view->viewport()->rect().contains(initialStep));
}

// Every kind of entry the tab's actions make words its undo text again when
// the language changes (here a marking translator stands for it), and back.
void TestGrafcetEditing::everyEditIsWordedInTheCurrentLanguage()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F1"));
    const auto edit = [&](const char* action, const std::vector<int>& steps, const std::vector<int>& transitions) {
        const int before = document.undoStack()->count();
        tab.actions->select(steps, transitions);
        tab.action(action)->trigger();
        QVERIFY2(document.undoStack()->count() == before + 1, action);
    };
    // F1: T2 opens the parallel branches 3-4 and 5-6, closed by T5.
    edit("grafcetMoveBranchLeftAction", {5}, {});
    edit("grafcetInsertAfterAction", {1}, {});
    edit("grafcetSelectionBranchAction", {1}, {});
    edit("grafcetParallelBranchAction", {}, {2});
    edit("grafcetEndingBranchAction", {1}, {});
    edit("grafcetRemoveAction", {6}, {});
    edit("grafcetRenumberAction", {}, {});
    tab.actions->select({1}, {});
    tab.action("grafcetCopyAction")->trigger();
    edit("grafcetPasteAction", {1}, {});
    edit("grafcetCutAction", {2}, {});
    const QStringList english = undoTexts(*document.undoStack());
    QCOMPARE(english.first(), QStringLiteral("Move branch left in F1"));
    QCOMPARE(english.last(), QStringLiteral("Cut step 2 from F1"));

    {
        MarkingTranslator marking("editor::GrafcetActions");
        QCoreApplication::installTranslator(&marking);
        rewordUndoHistory(document.undoStack());
        QStringList marked;
        for (const QString& text : english)
            marked << QStringLiteral("[tr]") + text;
        QCOMPARE(undoTexts(*document.undoStack()), marked);
        QCOMPARE(document.undoStack()->undoText(), QStringLiteral("[tr]Cut step 2 from F1"));
    }
    rewordUndoHistory(document.undoStack());
    QCOMPARE(undoTexts(*document.undoStack()), english);
}

QTEST_MAIN(TestGrafcetEditing)
#include "test_grafcetediting.moc"
