// The PackML Commands panel (PackmlCommandsDock) on a Document holding a PackML
// model: one row per command, typing pushes merged commands, live errors,
// the selection both ways, its page on a GEMMA model.

#include "packmldocktestsupport.h"

#include "editor/commands/packml/packmlcommandtextcommands.h"
#include "editor/commands/packml/packmlsettingscommands.h"
#include "editor/docks/diagnosticlist.h"
#include "editor/docks/packml/packmlcommandsdock.h"
#include "editor/selection.h"

#include "core/templates/packml/packmlmodel.h"

#include <QFrame>
#include <QLabel>
#include <QLineEdit>
#include <QStackedWidget>
#include <QTest>
#include <QUndoStack>

using namespace editor;
using namespace packmldocktest;
using core::packml::Command;
using core::packml::Edition;
using core::packml::State;

class TestPackmlCommandsDock : public QObject {
    Q_OBJECT

private slots:
    void commandsDockHasOneRowPerCommandOfTheEdition();
    void commandsDockTypingPushesMergedCommands();
    void commandsDockShowsLiveErrors();
    void commandsDockSelectionBothWays();
    void commandsDockOnGemmaModel();
};

void TestPackmlCommandsDock::commandsDockHasOneRowPerCommandOfTheEdition()
{
    Document document(core::packml::newModel(Edition::Y2015));
    Selection selection;
    PackmlCommandsDock dock(&document, &selection);
    QCOMPARE(dock.objectName(), QStringLiteral("packmlCommandsDock"));
    for (const char* name : {"Reset", "Start", "Stop", "Hold", "Unhold", "Suspend", "Unsuspend", "Abort", "Clear"})
        QVERIFY(dock.findChild<QFrame*>(QStringLiteral("row_") + QLatin1String(name)));
    QVERIFY(!dock.findChild<QFrame*>(QStringLiteral("row_Complete")));
    QCOMPARE(child<ConditionEdit>(dock, "condition_Hold")->text(), QStringLiteral("Cmd_Hold"));

    // Moving to 2022 brings Complete's row; undo takes it away again.
    QVERIFY(document.push(new SetPackmlOptionsCommand(document, core::packml::defaultOptions(Edition::Y2022))));
    QVERIFY(dock.findChild<QFrame*>(QStringLiteral("row_Complete")));
    QCOMPARE(child<ConditionEdit>(dock, "condition_Complete")->text(), QStringLiteral("Cmd_Complete"));
    document.undoStack()->undo();
    QVERIFY(!dock.findChild<QFrame*>(QStringLiteral("row_Complete")));
}

void TestPackmlCommandsDock::commandsDockTypingPushesMergedCommands()
{
    Document document(core::packml::newModel(Edition::Y2015));
    Selection selection;
    PackmlCommandsDock dock(&document, &selection);
    dock.show();
    ConditionEdit* condition = child<ConditionEdit>(dock, "condition_Abort");
    condition->setFocus();
    condition->moveCursor(QTextCursor::End);
    QTest::keyClicks(condition, " OR NOT EStopOK");
    QCOMPARE(config(document).command(Command::Abort).condition, std::string("Cmd_Abort OR NOT EStopOK"));
    QCOMPARE(document.undoStack()->count(), 1);

    QLineEdit* comment = child<QLineEdit>(dock, "comment_Abort");
    QTest::keyClicks(comment, "E-stop");
    QCOMPARE(config(document).command(Command::Abort).comment, std::string("E-stop"));
    QCOMPARE(document.undoStack()->count(), 2);

    document.undoStack()->undo();
    document.undoStack()->undo();
    QCOMPARE(condition->text(), QStringLiteral("Cmd_Abort"));
    QCOMPARE(comment->text(), QString());
}

void TestPackmlCommandsDock::commandsDockShowsLiveErrors()
{
    Document document(core::packml::newModel(Edition::Y2015));
    Selection selection;
    PackmlCommandsDock dock(&document, &selection);
    ConditionEdit* condition = child<ConditionEdit>(dock, "condition_Hold");
    DiagnosticList* problems = child<DiagnosticList>(dock, "problems_Hold");
    QVERIFY(condition->problems().isEmpty());
    QCOMPARE(problems->count(), 0);

    condition->setFocus();
    condition->selectAll();
    QTest::keyClicks(condition, "Cmd_Hold OR Jammed");
    QVERIFY(mentions(condition->problems(), "Jammed")); // GG203, undeclared, underlined at its name
    QVERIFY(problems->count() > 0);
    // The other rows are clean.
    QVERIFY(child<ConditionEdit>(dock, "condition_Stop")->problems().isEmpty());

    condition->selectAll();
    QTest::keyClicks(condition, "Cmd_Hold AND");
    QVERIFY(!condition->problems().isEmpty()); // GG201, syntax
    QVERIFY(condition->problems().front().error);
    document.undoStack()->undo();
    QVERIFY(condition->problems().isEmpty());
    QCOMPARE(problems->count(), 0);
}

void TestPackmlCommandsDock::commandsDockSelectionBothWays()
{
    Document document(core::packml::newModel(Edition::Y2015));
    Selection selection;
    PackmlCommandsDock dock(&document, &selection);
    dock.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dock));
    QVERIFY(dock.currentCommand().isEmpty());

    // The chart's Stop arrow selects the command: its row becomes current.
    selection.select(ElementRef::packmlCommand(QStringLiteral("Stop")));
    QCOMPARE(dock.currentCommand(), QStringLiteral("Stop"));
    QCOMPARE(child<QFrame>(dock, "row_Stop")->frameShadow(), QFrame::Raised);
    QCOMPARE(child<QFrame>(dock, "row_Hold")->frameShadow(), QFrame::Plain);

    // A transition fired by a command brings the command's row; one fired by SC leaves it.
    selection.select(ElementRef::packmlTransition(QStringLiteral("Execute"), QStringLiteral("Holding"), 1));
    QCOMPARE(dock.currentCommand(), QStringLiteral("Hold"));
    selection.select(ElementRef::packmlTransition(QStringLiteral("Starting"), QStringLiteral("Execute"), 1));
    QCOMPARE(dock.currentCommand(), QStringLiteral("Hold"));

    // Working in a row selects its command.
    QTest::mouseClick(child<QLineEdit>(dock, "comment_Clear"), Qt::LeftButton);
    QCOMPARE(selection.current(), ElementRef::packmlCommand(QStringLiteral("Clear")));
    QCOMPARE(dock.currentCommand(), QStringLiteral("Clear"));

    // Problems asks for the condition: the cursor goes to its first problem.
    QVERIFY(document.push(new SetCommandConditionCommand(document, QStringLiteral("Reset"), QStringLiteral("Cmd_Reset OR Nope"))));
    selection.select(ElementRef::packmlCommand(QStringLiteral("Reset")), QStringLiteral("condition"));
    ConditionEdit* condition = child<ConditionEdit>(dock, "condition_Reset");
    QCOMPARE(dock.currentCommand(), QStringLiteral("Reset"));
    QCOMPARE(condition->textCursor().selectedText(), QStringLiteral("Nope"));
}

void TestPackmlCommandsDock::commandsDockOnGemmaModel()
{
    Document document;
    Selection selection;
    PackmlCommandsDock dock(&document, &selection);
    auto* pages = dock.findChild<QStackedWidget*>();
    QCOMPARE(pages->currentWidget(), static_cast<QWidget*>(child<QLabel>(dock, "notPackml")));
    QVERIFY(!dock.findChild<ConditionEdit*>());

    // Replacing the model with a PackML one shows the rows.
    document.replaceModel(core::packml::newModel(Edition::Y2022), QString(), core::ModelFormat::Native);
    QVERIFY(pages->currentWidget() != static_cast<QWidget*>(child<QLabel>(dock, "notPackml")));
    QVERIFY(dock.findChild<QFrame*>(QStringLiteral("row_Complete")));
}

QTEST_MAIN(TestPackmlCommandsDock)
#include "test_packmlcommandsdock.moc"
