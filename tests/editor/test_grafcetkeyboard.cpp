// The keyboard in the GRAFCET tabs and their docks, on the shipped drilling
// cell (F1: 1, T1, 2, T2, then steps 3 and 5 in parallel, ...): Enter, F2
// and a double-click put the focus in the element's main field, Tab walks
// the drawing in its order, Esc clears the selection or comes back from a
// dock with the element still selected; the IF / value cell opens on a
// double-click; Create the usual shape leaves one element selected.

#include "editortestsupport.h"

#include "editor/app/languages.h"
#include "editor/docks/conditionedit.h"
#include "editor/docks/grafcetactionsmodel.h"
#include "editor/docks/grafcetstepdock.h"
#include "editor/docks/grafcettransitiondock.h"
#include "editor/document.h"
#include "editor/grafcet/grafcetactions.h"
#include "editor/grafcet/grafcetkeyboard.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetstepitem.h"
#include "editor/grafcet/grafcettransitionitem.h"
#include "editor/grafcet/grafcetview.h"
#include "editor/mainwindow.h"
#include "editor/selection.h"

#include "core/model/model.h"

#include <QAction>
#include <QApplication>
#include <QLineEdit>
#include <QMenu>
#include <QScrollBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QUndoStack>

#include <memory>
#include <tuple>

using namespace editor;

namespace {

const QString kF1 = QStringLiteral("F1");

// Where Tab places an element: its step box's or transition bar's centre.
QPointF placeOf(const GrafcetScene& scene, const ElementRef& element)
{
    if (element.kind == ElementRef::Kind::GrafcetStep) {
        const core::Rect& box = scene.layout().step(element.number)->box;
        return {box.x + box.width / 2, box.y + box.height / 2};
    }
    const core::Point& bar = scene.layout().transition(element.number)->barCenter;
    return {bar.x, bar.y};
}

QGraphicsItem* itemOf(const GrafcetScene& scene, const ElementRef& element)
{
    if (element.kind == ElementRef::Kind::GrafcetStep)
        return scene.stepItem(element.number);
    return scene.transitionItem(element.number);
}

QString focusName()
{
    return QApplication::focusWidget() ? QApplication::focusWidget()->objectName() : QString();
}

} // namespace

class TestGrafcetKeyboard : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();

    void enterOnATransitionSelectsItsReceptivity();
    void f2OnAStepOpensItsFirstAction();
    void enterOnAStepWithoutActionsFocusesAdd();
    void doubleClickFocusesTheMainField();
    void enterShowsAHiddenDock();
    void tabWalksTheDrawingInItsOrder();
    void escClearsTheSelection();
    void escInACellEditorCancelsAndComesBack();
    void conditionCellOpensOnDoubleClick();
    void usualShapeLeavesOneElementSelected();

private:
    GrafcetView* openF1();
    const core::Grafcet& f1() const { return *m_window->document()->model().grafcet("F1"); }
    Selection* selection() const { return m_window->selection(); }
    template <typename T>
    T* child(const char* name) const
    {
        return editortest::namedChild<T>(*m_window, name);
    }

    QTemporaryDir m_settingsDir;
    std::unique_ptr<Translators> m_translators;
    std::unique_ptr<MainWindow> m_window;
};

void TestGrafcetKeyboard::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    editortest::useTestSettings(m_settingsDir.path(), QStringLiteral("test_grafcetkeyboard"));
}

void TestGrafcetKeyboard::init()
{
    m_window = editortest::showEnglishMainWindow(m_translators);
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
}

void TestGrafcetKeyboard::cleanup()
{
    m_window.reset();
    m_translators.reset();
}

GrafcetView* TestGrafcetKeyboard::openF1()
{
    QString error;
    if (!m_window->document()->load(QStringLiteral(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json"), &error)) {
        qWarning("%s", qPrintable(error));
        return nullptr;
    }
    if (!m_window->openNestedGrafcet(kF1))
        return nullptr;
    GrafcetView* view = m_window->grafcetView(kF1);
    view->setFocus();
    return view;
}

// Enter on a transition: its whole receptivity selected in the Nested
// Transition dock, to type over; Esc comes back to the drawing, the
// transition still selected.
void TestGrafcetKeyboard::enterOnATransitionSelectsItsReceptivity()
{
    GrafcetView* view = openF1();
    QVERIFY(view);
    selection()->select(ElementRef::grafcetTransition(kF1, 3));
    QTest::keyClick(view, Qt::Key_Return);
    ConditionEdit* edit = child<GrafcetTransitionDock>("grafcetTransitionDock")->receptivityEdit();
    QCOMPARE(QApplication::focusWidget(), static_cast<QWidget*>(edit));
    QCOMPARE(edit->textCursor().selectedText(), QStringLiteral("DrillLow"));

    QTest::keyClicks(edit, "DrillHigh");
    QCOMPARE(QString::fromStdString(f1().transition(3)->receptivity), QStringLiteral("DrillHigh"));
    QTest::keyClick(edit, Qt::Key_Escape);
    QCOMPARE(QApplication::focusWidget(), static_cast<QWidget*>(view));
    QCOMPARE(selection()->current(), ElementRef::grafcetTransition(kF1, 3));
    QVERIFY(view->grafcetScene()->transitionItem(3)->isSelected());
}

// F2 on a step: its first action's variable open, its text selected.
void TestGrafcetKeyboard::f2OnAStepOpensItsFirstAction()
{
    GrafcetView* view = openF1();
    QVERIFY(view);
    selection()->select(ElementRef::grafcetStep(kF1, 3));
    QTest::keyClick(view, Qt::Key_F2);
    auto* editor = qobject_cast<QLineEdit*>(QApplication::focusWidget());
    QVERIFY2(editor, qPrintable(focusName()));
    QCOMPARE(editor->objectName(), QStringLiteral("actionVariableEdit"));
    QCOMPARE(editor->selectedText(), QStringLiteral("Spindle"));
    QTableView* table = child<GrafcetStepDock>("grafcetStepDock")->actionsView();
    QCOMPARE(table->currentIndex().row(), 0);
    QCOMPARE(table->currentIndex().column(), int(GrafcetActionsModel::VariableColumn));

    // Typed over and committed with Enter, the action changes as one command.
    QTest::keyClicks(editor, "Horn");
    QTest::keyClick(editor, Qt::Key_Return);
    QTRY_COMPARE(QString::fromStdString(f1().step(3)->actions.front().text), QStringLiteral("N Horn"));
    QCOMPARE(m_window->document()->undoStack()->undoText(), QStringLiteral("Set action 1 of F1 step 3"));
}

// A step without actions: the Add button, whose Space adds the first one.
void TestGrafcetKeyboard::enterOnAStepWithoutActionsFocusesAdd()
{
    GrafcetView* view = openF1();
    QVERIFY(view);
    QVERIFY(f1().step(6)->actions.empty());
    selection()->select(ElementRef::grafcetStep(kF1, 6));
    QTest::keyClick(view, Qt::Key_Enter, Qt::KeypadModifier);
    QCOMPARE(focusName(), QStringLiteral("addActionButton"));
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Space);
    QCOMPARE(f1().step(6)->actions.size(), std::size_t(1));
    QCOMPARE(focusName(), QStringLiteral("actionVariableEdit"));
}

// A double-click on a step or a transition selects it and focuses its main field.
void TestGrafcetKeyboard::doubleClickFocusesTheMainField()
{
    GrafcetView* view = openF1();
    QVERIFY(view);
    GrafcetScene* scene = view->grafcetScene();
    const ElementRef t1 = ElementRef::grafcetTransition(kF1, 1);
    view->ensureVisible(itemOf(*scene, t1));
    QTest::mouseDClick(view->viewport(), Qt::LeftButton, {}, view->mapFromScene(placeOf(*scene, t1)));
    QCOMPARE(selection()->current(), t1);
    ConditionEdit* edit = child<GrafcetTransitionDock>("grafcetTransitionDock")->receptivityEdit();
    QCOMPARE(QApplication::focusWidget(), static_cast<QWidget*>(edit));
    QCOMPARE(edit->textCursor().selectedText(), QStringLiteral("PartPresent AND Unclamped"));

    const ElementRef step2 = ElementRef::grafcetStep(kF1, 2);
    QTest::mouseDClick(view->viewport(), Qt::LeftButton, {}, view->mapFromScene(placeOf(*scene, step2)));
    QCOMPARE(selection()->current(), step2);
    QCOMPARE(focusName(), QStringLiteral("actionVariableEdit"));
    QCOMPARE(qobject_cast<QLineEdit*>(QApplication::focusWidget())->selectedText(), QStringLiteral("ClampOut"));

    // On the paper: nothing to edit.
    const QRectF paper = scene->sceneRect();
    view->setFocus();
    QTest::mouseDClick(view->viewport(), Qt::LeftButton, {}, view->mapFromScene(paper.left() + 2, paper.top() + 2));
    QCOMPARE(QApplication::focusWidget(), static_cast<QWidget*>(view));
}

// A closed dock opens again for Enter.
void TestGrafcetKeyboard::enterShowsAHiddenDock()
{
    GrafcetView* view = openF1();
    QVERIFY(view);
    auto* dock = child<GrafcetTransitionDock>("grafcetTransitionDock");
    dock->close();
    QVERIFY(!dock->isVisible());
    selection()->select(ElementRef::grafcetTransition(kF1, 2));
    view->setFocus();
    QTest::keyClick(view, Qt::Key_F2);
    QVERIFY(dock->isVisible());
    QTRY_VERIFY(!dock->visibleRegion().isEmpty());
    QCOMPARE(QApplication::focusWidget(), static_cast<QWidget*>(dock->receptivityEdit()));
}

// Tab selects each step and transition once, top to bottom and left to
// right, scrolled into view, and goes round without leaving the drawing;
// Shift+Tab goes back.
void TestGrafcetKeyboard::tabWalksTheDrawingInItsOrder()
{
    GrafcetView* view = openF1();
    QVERIFY(view);
    GrafcetScene* scene = view->grafcetScene();
    view->verticalScrollBar()->setValue(view->verticalScrollBar()->minimum());
    const int count = static_cast<int>(f1().steps().size() + f1().transitions().size());
    QList<ElementRef> walked;
    for (int i = 0; i < count; ++i) {
        QTest::keyClick(view, Qt::Key_Tab);
        QCOMPARE(QApplication::focusWidget(), static_cast<QWidget*>(view));
        const ElementRef current = selection()->current();
        QVERIFY(!walked.contains(current));
        walked << current;
        QVERIFY(itemOf(*scene, current)->isSelected());
        const QRectF shown = view->mapToScene(view->viewport()->rect()).boundingRect();
        QVERIFY2(shown.contains(itemOf(*scene, current)->sceneBoundingRect().center()),
                 qPrintable(QStringLiteral("%1 not shown").arg(current.number)));
    }
    for (int i = 1; i < count; ++i) {
        const QPointF before = placeOf(*scene, walked[i - 1]);
        const QPointF after = placeOf(*scene, walked[i]);
        QVERIFY(std::make_tuple(before.y(), before.x()) < std::make_tuple(after.y(), after.x()));
    }
    // 1, T1, 2, T2, then the parallel steps 3 and 5 side by side.
    const QList<ElementRef> start{ElementRef::grafcetStep(kF1, 1), ElementRef::grafcetTransition(kF1, 1),
                                  ElementRef::grafcetStep(kF1, 2), ElementRef::grafcetTransition(kF1, 2),
                                  ElementRef::grafcetStep(kF1, 3), ElementRef::grafcetStep(kF1, 5)};
    QCOMPARE(walked.mid(0, start.size()), start);
    QCOMPARE(view->findChild<GrafcetKeyboard*>()->drawingOrder(), walked);

    QTest::keyClick(view, Qt::Key_Tab); // round to the top
    QCOMPARE(selection()->current(), walked.first());
    QCOMPARE(QApplication::focusWidget(), static_cast<QWidget*>(view));
    QTest::keyClick(view, Qt::Key_Backtab, Qt::ShiftModifier);
    QCOMPARE(selection()->current(), walked.last());
    QTest::keyClick(view, Qt::Key_Backtab, Qt::ShiftModifier);
    QCOMPARE(selection()->current(), walked[count - 2]);
    QCOMPARE(QApplication::focusWidget(), static_cast<QWidget*>(view));
}

void TestGrafcetKeyboard::escClearsTheSelection()
{
    GrafcetView* view = openF1();
    QVERIFY(view);
    selection()->select(ElementRef::grafcetStep(kF1, 4));
    QVERIFY(view->grafcetScene()->stepItem(4)->isSelected());
    QTest::keyClick(view, Qt::Key_Escape);
    QVERIFY(selection()->current().isNull());
    QVERIFY(view->grafcetScene()->selectedItems().isEmpty());
}

// One Esc in an action cell being edited cancels the edit and comes back to
// the drawing, the step still selected.
void TestGrafcetKeyboard::escInACellEditorCancelsAndComesBack()
{
    GrafcetView* view = openF1();
    QVERIFY(view);
    selection()->select(ElementRef::grafcetStep(kF1, 2));
    QTest::keyClick(view, Qt::Key_Return);
    QCOMPARE(focusName(), QStringLiteral("actionVariableEdit"));
    const int undoIndex = m_window->document()->undoStack()->index();
    QTest::keyClicks(QApplication::focusWidget(), "Nothing");
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Escape);
    QCOMPARE(QApplication::focusWidget(), static_cast<QWidget*>(view));
    QCOMPARE(QString::fromStdString(f1().step(2)->actions.front().text), QStringLiteral("N ClampOut"));
    QCOMPARE(m_window->document()->undoStack()->index(), undoIndex);
    QCOMPARE(selection()->current(), ElementRef::grafcetStep(kF1, 2));

    // The comment field: Esc comes back too.
    QTest::keyClick(view, Qt::Key_Return);
    QWidget* comment = child<QWidget>("nestedCommentEdit");
    comment->setFocus();
    QTest::keyClick(comment, Qt::Key_Escape);
    QCOMPARE(QApplication::focusWidget(), static_cast<QWidget*>(view));
    QCOMPARE(selection()->current(), ElementRef::grafcetStep(kF1, 2));
}

// The IF / value cell opens on a double-click, as the Variable cell does,
// also when the press before it went elsewhere: after typing a variable,
// the first click only closes its completion list, so the view sees the
// double-click without the press on that cell (here: the double-click alone).
void TestGrafcetKeyboard::conditionCellOpensOnDoubleClick()
{
    QVERIFY(openF1());
    selection()->select(ElementRef::grafcetStep(kF1, 1));
    auto* dock = child<GrafcetStepDock>("grafcetStepDock");
    QTRY_VERIFY(!dock->visibleRegion().isEmpty());
    QTableView* table = dock->actionsView();
    const QModelIndex cell = dock->actionsModel()->index(0, GrafcetActionsModel::OperandColumn);
    QCOMPARE(cell.data().toString(), QStringLiteral("NOT PartPresent"));
    const QRect rect = table->visualRect(cell);
    QVERIFY2(table->viewport()->rect().contains(rect.center()), "the IF / value column is out of sight");
    QTest::mouseDClick(table->viewport(), Qt::LeftButton, {}, rect.center());
    auto* editor = qobject_cast<QLineEdit*>(table->indexWidget(cell));
    QVERIFY(editor);
    QCOMPARE(editor->objectName(), QStringLiteral("actionOperandEdit"));
    QCOMPARE(editor->text(), QStringLiteral("NOT PartPresent"));
    QCOMPARE(table->currentIndex(), cell);
    QCOMPARE(QApplication::focusWidget(), static_cast<QWidget*>(editor));
}

// After Create the usual shape, its first transition is selected: the menu
// inserts at once and the Nested Transition dock shows its TRUE.
void TestGrafcetKeyboard::usualShapeLeavesOneElementSelected()
{
    QVERIFY(openF1());
    const QString a7 = QStringLiteral("A7");
    QVERIFY(m_window->openNestedGrafcet(a7));
    GrafcetView* view = m_window->grafcetView(a7);
    view->findChild<QAction*>(QStringLiteral("grafcetCreateUsualAction"))->trigger();
    QCOMPARE(selection()->elements(), QList<ElementRef>{ElementRef::grafcetTransition(a7, 1)});
    QVERIFY(view->grafcetScene()->transitionItem(1)->isSelected());
    auto* dock = child<GrafcetTransitionDock>("grafcetTransitionDock");
    QTRY_VERIFY(!dock->visibleRegion().isEmpty());
    QCOMPARE(dock->receptivityEdit()->text(), QStringLiteral("TRUE"));

    QMenu menu;
    view->findChild<GrafcetActions*>()->populate(&menu);
    QAction* insert = view->findChild<QAction*>(QStringLiteral("grafcetInsertAfterAction"));
    QVERIFY(menu.actions().contains(insert));
    QVERIFY(insert->isEnabled());
    // Enter goes straight to the receptivity to write.
    view->setFocus();
    QTest::keyClick(view, Qt::Key_Return);
    QCOMPARE(QApplication::focusWidget(), static_cast<QWidget*>(dock->receptivityEdit()));
}

QTEST_MAIN(TestGrafcetKeyboard)
#include "test_grafcetkeyboard.moc"
