// The mouse and clipboard conveniences of a GRAFCET tab on the shipped
// drilling cell: the rubber band, Cut, and Copy and Paste through the system
// clipboard between two documents, a damaged clipboard refused.

#include "editortestsupport.h"

#include "editor/app/languages.h"
#include "editor/document.h"
#include "editor/grafcet/grafcetactions.h"
#include "editor/grafcet/grafcetclipboard.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetstepitem.h"
#include "editor/grafcet/grafcettransitionitem.h"
#include "editor/grafcet/grafcetview.h"
#include "editor/mainwindow.h"

#include "core/formats/modelfiles.h"
#include "core/model/grafcetediting.h"

#include <QAction>
#include <QClipboard>
#include <QGuiApplication>
#include <QMimeData>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
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

// A GRAFCET tab of the document as MainWindow builds it, shown.
struct Tab {
    Tab(Document& document, const QString& stepId)
        : scene(new GrafcetScene(&document, stepId))
        , view(std::make_unique<GrafcetView>(scene))
        , actions(new GrafcetActions(document, *view))
    {
        scene->setParent(view.get());
        view->resize(900, 900);
        view->show();
    }

    QAction* action(const char* name) const { return view->findChild<QAction*>(QString::fromLatin1(name)); }
    QPoint at(QPointF scenePoint) const { return view->mapFromScene(scenePoint); }

    GrafcetScene* scene;
    std::unique_ptr<GrafcetView> view;
    GrafcetActions* actions;
};

QRectF squareOf(const GrafcetStepItem& step)
{
    const auto& box = step.layout().box;
    return step.mapRectToScene(QRectF(box.x, box.y, box.width, box.height));
}

// Whether a step or a transition is drawn at the point (not the wiring).
bool onElement(const Tab& tab, QPointF scenePoint)
{
    for (QGraphicsItem* item : tab.view->items(tab.at(scenePoint)))
        if (item->type() == GrafcetStepItem::Type || item->type() == GrafcetTransitionItem::Type)
            return true;
    return false;
}

// A left-button drag in the view's viewport, with `modifiers` held.
void drag(const Tab& tab, QPoint from, QPoint to, Qt::KeyboardModifiers modifiers = {})
{
    QWidget* viewport = tab.view->viewport();
    QTest::mousePress(viewport, Qt::LeftButton, modifiers, from);
    QTest::mouseMove(viewport, from + (to - from) / 2);
    QTest::mouseMove(viewport, to);
    QTest::mouseRelease(viewport, Qt::LeftButton, modifiers, to);
}

bool linked(const core::Grafcet& g, int from, int to)
{
    for (const core::GrafcetTransition& t : g.transitions())
        if (t.upstream == std::vector<int>{from} && t.downstream == std::vector<int>{to})
            return true;
    return false;
}

void setClipboard(const QByteArray& fragment)
{
    auto* data = new QMimeData;
    data->setData(GrafcetClipboard::kMimeType, fragment);
    QGuiApplication::clipboard()->setMimeData(data);
}

} // namespace

class TestGrafcetClipboard : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void rubberBandSelectsTheItemsInside();
    void rightClickKeepsTheSelection();
    void cutRemovesAndUndoRestores();
    void copyPasteBetweenTwoDocuments();
    void damagedClipboardIsRefused();

private:
    QTemporaryDir m_settingsDir;
};

void TestGrafcetClipboard::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    editortest::useTestSettings(m_settingsDir.path(), QStringLiteral("test_grafcetclipboard"));
}

// F1: 1 -T1- 2 -T2- (3 -T3- 4 || 5 -T4- 6) -T5- 7 ...; a band from the
// paper left of the drawing over steps 1 and 2 and T1 selects those three.
void TestGrafcetClipboard::rubberBandSelectsTheItemsInside()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F1"));
    QVERIFY(QTest::qWaitForWindowExposed(tab.view.get()));
    const QRectF paper = tab.scene->sceneRect();
    const QRectF step1 = squareOf(*tab.scene->stepItem(1));
    const QRectF step2 = squareOf(*tab.scene->stepItem(2));
    const QPointF start(paper.left() + 2, step1.top() - 4);
    const QPointF end(step2.right() + 4, step2.bottom() + 1);
    QVERIFY(!onElement(tab, start)); // the band starts on the paper
    tab.view->ensureVisible(QRectF(start, end));
    drag(tab, tab.at(start), tab.at(end));
    QCOMPARE(tab.actions->selectedSteps(), (std::vector<int>{1, 2}));
    QCOMPARE(tab.actions->selectedTransitions(), std::vector<int>{1});

    // Ctrl adds what a second band covers: step 7.
    const QRectF step7 = squareOf(*tab.scene->stepItem(7));
    const QPointF start7(paper.left() + 2, step7.top() - 1);
    const QPointF end7(step7.center().x(), step7.center().y());
    tab.view->ensureVisible(QRectF(start7, end7));
    QVERIFY(!onElement(tab, start7));
    drag(tab, tab.at(start7), tab.at(end7), Qt::ControlModifier);
    QCOMPARE(tab.actions->selectedSteps(), (std::vector<int>{1, 2, 7}));
    QCOMPARE(tab.actions->selectedTransitions(), std::vector<int>{1});

    // Without Ctrl a band replaces the selection; one on bare paper empties it.
    drag(tab, tab.at(start7), tab.at(end7));
    QCOMPARE(tab.actions->selectedSteps(), std::vector<int>{7});
    drag(tab, tab.at(start7), tab.at(start7 + QPointF(1, 3)));
    QVERIFY(tab.scene->selectedItems().isEmpty());

    // A click on an item still selects it, not a band.
    tab.view->ensureVisible(step2);
    QTest::mouseClick(tab.view->viewport(), Qt::LeftButton, {}, tab.at(step2.center()));
    QCOMPARE(tab.actions->selectedSteps(), std::vector<int>{2});
}

// The context menu acts on all the selected steps: the right button's press
// does not clear the selection first.
void TestGrafcetClipboard::rightClickKeepsTheSelection()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F1"));
    QVERIFY(QTest::qWaitForWindowExposed(tab.view.get()));
    tab.actions->select({1, 2}, {});
    const QRectF step2 = squareOf(*tab.scene->stepItem(2));
    tab.view->ensureVisible(step2);
    QTest::mousePress(tab.view->viewport(), Qt::RightButton, {}, tab.at(step2.center()));
    QTest::mouseRelease(tab.view->viewport(), Qt::RightButton, {}, tab.at(step2.center()));
    QCOMPARE(tab.actions->selectedSteps(), (std::vector<int>{1, 2}));
    QTest::mousePress(tab.view->viewport(), Qt::RightButton, {}, tab.at(tab.scene->sceneRect().topLeft() + QPointF(2, 2)));
    QCOMPARE(tab.actions->selectedSteps(), (std::vector<int>{1, 2}));
}

void TestGrafcetClipboard::cutRemovesAndUndoRestores()
{
    Document document(drillingCell());
    Tab tab(document, QStringLiteral("F1"));
    QVERIFY(QTest::qWaitForWindowExposed(tab.view.get()));
    const core::Grafcet before = *document.model().grafcet("F1");
    tab.view->activateWindow();
    tab.view->setFocus();
    tab.actions->select({3, 4}, {});
    QVERIFY(tab.action("grafcetCutAction")->isEnabled());
    QTest::keyClick(tab.view.get(), Qt::Key_X, Qt::ControlModifier);

    const core::Grafcet* after = document.model().grafcet("F1");
    QVERIFY(!after->step(3));
    QVERIFY(!after->step(4));
    core::Grafcet deleted = before; // repaired as Delete repairs
    QVERIFY(core::removeStepWithRepair(deleted, 3).ok);
    QVERIFY(core::removeStepWithRepair(deleted, 4).ok);
    QVERIFY(after->sameContent(deleted));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Cut 2 steps from F1"));
    const auto cut = GrafcetClipboard::fragment();
    QVERIFY(std::holds_alternative<core::GrafcetFragment>(cut));
    QCOMPARE(std::get<core::GrafcetFragment>(cut).steps.size(), std::size_t(2));
    QCOMPARE(std::get<core::GrafcetFragment>(cut).steps[0].actions, before.step(3)->actions);

    document.undoStack()->undo();
    QVERIFY(document.model().grafcet("F1")->sameContent(before));
    QVERIFY(tab.scene->stepItem(3));

    document.setReadOnly(true);
    QVERIFY(!tab.action("grafcetCutAction")->isEnabled());
}

// F2's steps 3 and 4 (T4 "10s/X3") copied in one document, pasted apart in
// another document's F1: the actions and the receptivity come along, the
// receptivity naming the pasted step.
void TestGrafcetClipboard::copyPasteBetweenTwoDocuments()
{
    QGuiApplication::clipboard()->clear();
    Document source(drillingCell());
    Document target(drillingCell());
    Tab copyTab(source, QStringLiteral("F2"));
    Tab pasteTab(target, QStringLiteral("F1"));
    QVERIFY(!pasteTab.action("grafcetPasteAction")->isEnabled()); // nothing to paste yet

    copyTab.actions->select({3, 4}, {});
    copyTab.action("grafcetCopyAction")->trigger();
    const QMimeData* data = QGuiApplication::clipboard()->mimeData();
    QVERIFY(data->hasFormat(GrafcetClipboard::kMimeType));
    QVERIFY2(data->text().contains(QStringLiteral("T4 (3 → 4): 10s/X3")), qPrintable(data->text()));

    QVERIFY(pasteTab.action("grafcetPasteAction")->isEnabled()); // followed the clipboard
    pasteTab.actions->select({}, {});
    pasteTab.action("grafcetPasteAction")->trigger();
    const core::Grafcet* g = target.model().grafcet("F1");
    const core::Grafcet* f2 = source.model().grafcet("F2");
    QCOMPARE(pasteTab.actions->selectedSteps(), (std::vector<int>{10, 11}));
    QCOMPARE(g->step(10)->actions, f2->step(3)->actions);
    QCOMPARE(g->step(11)->actions, f2->step(4)->actions);
    QCOMPARE(g->transition(9)->upstream, std::vector<int>{10});
    QCOMPARE(g->transition(9)->downstream, std::vector<int>{11});
    QCOMPARE(g->transition(9)->receptivity, std::string("10s/X10"));
    QVERIFY(source.model().grafcet("F2")->sameContent(*drillingCell().grafcet("F2"))); // the source untouched

    // Pasted into a selected step, the fragment follows it.
    pasteTab.actions->select({7}, {});
    pasteTab.action("grafcetPasteAction")->trigger();
    QCOMPARE(pasteTab.actions->selectedSteps(), (std::vector<int>{12, 13}));
    QVERIFY(linked(*g, 7, 12));
    QVERIFY(linked(*g, 12, 13));
    QVERIFY(linked(*g, 13, 8)); // what followed step 7
}

// In the window: whatever is on the clipboard under the fragment's type is
// read strictly; a damaged one leaves the model as it was and says why in
// the status bar.
void TestGrafcetClipboard::damagedClipboardIsRefused()
{
    Translators translators;
    translators.setLanguage(QStringLiteral("en"));
    const std::unique_ptr<MainWindow> window = editortest::showMainWindow(translators);
    QVERIFY(QTest::qWaitForWindowExposed(window.get()));
    window->findChild<QAction*>(QStringLiteral("example_0"))->trigger(); // the drilling cell
    QVERIFY(window->openNestedGrafcet(QStringLiteral("F3")));
    GrafcetView* view = window->grafcetView(QStringLiteral("F3"));
    QAction* paste = view->findChild<QAction*>(QStringLiteral("grafcetPasteAction"));
    Document* document = window->document();
    const core::Grafcet before = *document->model().grafcet("F3");
    const int commands = document->undoStack()->count();

    const QByteArray header = R"({"format": "ggstudio-grafcet-fragment", "version": "1.0", "grafcet": )";
    const struct {
        QByteArray data;
        const char* reason;
    } damaged[] = {
        {"{not json", "line 1"},
        {header + R"({"steps": [{"number": -1}]}})", "/grafcet/steps/0/number"},
        {header + R"({"steps": [{"number": 1e999}]}})", "number overflow"},
        {header + R"({"steps": [{"number": 1}], "transitions": [{"number": 1, "upstream": [1], "downstream": [2]}]}})",
         "/grafcet/transitions/0"},
        {header + R"({"steps": [{"number": 1, "comment": ")" + QByteArray(2 * 1024 * 1024, 'x') + "\"}]}}", "at most"},
    };
    for (const auto& [data, reason] : damaged) {
        setClipboard(data);
        QVERIFY(paste->isEnabled());
        window->statusBar()->clearMessage();
        paste->trigger();
        const QString message = window->statusBar()->currentMessage();
        QVERIFY2(message.contains(QStringLiteral("damaged")) && message.contains(QLatin1String(reason)),
                 qPrintable(message));
        QVERIFY(document->model().grafcet("F3")->sameContent(before));
        QCOMPARE(document->undoStack()->count(), commands);
    }

    // Other programs' text is no fragment: Paste is off.
    QGuiApplication::clipboard()->setText(QStringLiteral("Step 1"));
    QVERIFY(!paste->isEnabled());
}

QTEST_MAIN(TestGrafcetClipboard)
#include "test_grafcetclipboard.moc"
